"""Python values as TOML text, the form the scenario loader reads (and --set takes)."""
import json
import math
import re

import numpy as np

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f"scenario keys are strings, not {type(k).__name__} ({k!r})")
    return k if _BARE_KEY.match(k) else json.dumps(k)


def value(v):
    """One value: bool, number, string, list (or numpy array) or dict (an inline table)."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # the shortest text that reads back to the same double
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"a scenario value is a bool, number, string, list or dict, not "
                    f"{type(v).__name__} ({v!r})")


def document(d):
    """A whole scenario from a dict of its sections (each a dict, or a list of dicts)."""
    if not isinstance(d, dict):
        raise TypeError(f"a scenario is a dict of its sections, not {type(d).__name__}")
    return "".join(f"{_key(k)} = {value(v)}\n" for k, v in d.items())


def assignments(changes):
    """'key=value' strings from a dict {"dotted.key": value} or a list of such strings."""
    if changes is None:
        return []
    if isinstance(changes, dict):
        out = []
        for k, v in changes.items():
            if not isinstance(k, str):
                raise TypeError(f"a change's key is a dotted string, not {k!r}")
            out.append(f"{k}={value(v)}")
        return out
    if isinstance(changes, str):
        return [changes]
    return [str(x) for x in changes]
