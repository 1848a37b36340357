"""Scenarios: from a file, a built-in name, TOML text or a dict, checked as `talus run` checks
them (a ScenarioError names the key and the allowed values)."""
import os

from . import _talus, toml_text


class Scenario:
    """A checked scenario with every default filled in."""

    def __init__(self, native, source, changes=()):
        self._native = native
        self._source = source  # how to make it again: ("file", what) or ("text", text, name)
        self._changes = list(changes)

    @classmethod
    def from_file(cls, what, set=None):
        """A scenario file (.toml, or a thesis .in file) or a built-in scenario's name."""
        changes = toml_text.assignments(set)
        what = os.fspath(what)
        return cls(_talus.resolve_scenario(what, changes), ("file", what), changes)

    @classmethod
    def from_toml(cls, text, set=None, name="<toml text>"):
        changes = toml_text.assignments(set)
        return cls(_talus.load_scenario(text, name, changes), ("text", text, name), changes)

    @classmethod
    def from_dict(cls, sections, set=None):
        """A scenario from a dict of its sections: {"simulation": {"duration": 0.5}, "materials":
        [{"name": "sand", ...}], ...}, the same keys as a scenario file."""
        return cls.from_toml(toml_text.document(sections), set, "<dict>")

    def with_changes(self, set):
        """The same scenario with "key=value" changes (a dict or a list of strings)."""
        changes = self._changes + toml_text.assignments(set)
        if self._source[0] == "file":
            return Scenario(_talus.resolve_scenario(self._source[1], changes), self._source, changes)
        return Scenario(_talus.load_scenario(self._source[1], self._source[2], changes),
                        self._source, changes)

    @property
    def name(self):
        return self._native.name

    @property
    def duration(self):
        """s: the run's length."""
        return self._native.duration

    def to_toml(self):
        """The resolved scenario as TOML: every key with its value."""
        return self._native.to_toml()

    def __repr__(self):
        return f"<talus.Scenario {self.name!r}, {self.duration:g} s>"


def scenario(what, set=None):
    """A Scenario from a file name, a built-in name, a dict, or a Scenario (with `set`)."""
    if isinstance(what, Scenario):
        return what.with_changes(set) if set else what
    if isinstance(what, dict):
        return Scenario.from_dict(what, set)
    return Scenario.from_file(what, set)


def builtin_scenarios():
    """The names of the built-in scenarios."""
    return list(_talus.builtin_names())


def changeable_keys():
    """The keys that may change during a run (Simulation.change, a stage's set)."""
    return _talus.changeable_keys()
