"""Scenarios from files, built-in names, TOML text and dicts, with the loader's checks."""
import pytest

import talus
from conftest import REPO, SMALL


def test_a_builtin_by_name_with_changes():
    s = talus.scenario("hourglass", set={"particles.count": 120, "simulation.duration": 0.3})
    assert s.name == "hourglass"
    assert s.duration == 0.3
    assert "count = 120" in s.to_toml()


def test_a_file_and_the_same_text_give_the_same_scenario():
    path = REPO / "inputs" / "collisions" / "scenario.toml"
    a = talus.Scenario.from_file(path)
    b = talus.Scenario.from_toml(path.read_text())
    assert a.to_toml() == b.to_toml()


def test_a_dict_is_checked_as_a_file_is():
    s = talus.scenario(SMALL)
    assert s.name == "small_box"
    bad = dict(SMALL, materials=[dict(SMALL["materials"][0], friction=-1.0)])
    with pytest.raises(talus.ScenarioError, match=r"materials\.0\.friction.*allowed"):
        talus.scenario(bad)


def test_errors_name_the_key_and_the_allowed_values():
    with pytest.raises(talus.ScenarioError, match=r"particles\.count.*allowed"):
        talus.scenario("hourglass", set={"particles.count": -5})
    with pytest.raises(ValueError, match=r"did you mean 'hourglass'"):
        talus.scenario("hourglas")
    with pytest.raises(TypeError, match="a scenario value is"):
        talus.scenario("hourglass", set={"particles.count": object()})


def test_with_changes_keeps_the_earlier_ones():
    s = talus.scenario(SMALL).with_changes({"particles.count": 30})
    t = s.with_changes({"simulation.duration": 0.2})
    assert "count = 30" in t.to_toml() and t.duration == 0.2


def test_builtins_and_changeable_keys_are_listed():
    assert "tilted_box" in talus.builtin_scenarios()
    assert "simulation.gravity" in talus.changeable_keys()
