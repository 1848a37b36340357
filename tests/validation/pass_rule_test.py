#!/usr/bin/python3
"""The cross-check's pass rule for statistics (validation/measures.py): Welch's t with the
Welch-Satterthwaite degrees of freedom, against Student's t at the false-alarm rate of a normal
|z| of z_max, and the combination of several seeds' estimates. Against closed forms, to 1e-9
relative (what scipy's quantiles and the float sums give), and a rule that must fail where two
values differ by many errors.

Usage: pass_rule_test.py"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "validation"))
from measures import combined, t_bound, welch  # noqa: E402


def near(a, b, what):
    if not math.isclose(a, b, rel_tol=1e-9):
        sys.exit(f"{what}: {a!r}, expected {b!r}")
    print(f"ok: {what}: {a:.6g}")


# with infinite degrees of freedom Student's t is the normal: the bound is z_max itself
near(t_bound(3.0, math.inf), 3.0, "bound at infinite degrees of freedom")
# one degree of freedom is Cauchy's distribution: P(|t| > x) = 1 - 2 atan(x) / pi, so the |t|
# exceeded as rarely as |z| = 3 (2 x 0.00134990) is 1 / tan(pi x 0.00134990)
tail = 0.5 * math.erfc(3.0 / math.sqrt(2.0))
near(t_bound(3.0, 1.0), 1.0 / math.tan(math.pi * tail), "bound at one degree of freedom")
# two degrees of freedom: P(|t| > x) = 1 - x / sqrt(2 + x^2), so x = sqrt(2 / (1 - q^2) - 2)
# with q = 1 - 2 tail
q = 1.0 - 2.0 * tail
near(t_bound(3.0, 2.0), math.sqrt(2.0 / (1.0 - q * q) - 2.0), "bound at two degrees of freedom")

# Welch: equal errors and degrees of freedom n add to 2n; an exact value adds none
t, dof = welch((1.0, 0.3, 4.0), (0.0, 0.3, 4.0))
near(t, 1.0 / math.hypot(0.3, 0.3), "Welch's t")
near(dof, 8.0, "Welch-Satterthwaite degrees of freedom, equal errors")
t, dof = welch((1.0, 0.3, 4.0), (0.0, 0.0, math.inf))
near(dof, 4.0, "degrees of freedom beside an exact value")
# unequal: (a^2 + b^2)^2 / (a^4 / 3 + b^4 / 9)
t, dof = welch((0.0, 0.2, 3.0), (0.0, 0.5, 9.0))
near(dof, (0.04 + 0.25) ** 2 / (0.2 ** 4 / 3.0 + 0.5 ** 4 / 9.0), "unequal errors")

# seeds: the scatter is the larger error here, with seeds - 1 degrees of freedom
value, error, dof = combined([(1.0, 0.1, 2.0), (3.0, 0.1, 2.0)])
near(value, 2.0, "seeds' mean")
near(error, 1.0, "seeds' scatter as the error")
near(dof, 1.0, "seeds' scatter's degrees of freedom")
# and the seeds' own errors where they are the larger: sqrt(sum e^2) / n, and their
# Welch-Satterthwaite degrees of freedom
value, error, dof = combined([(1.0, 0.4, 3.0), (1.1, 0.4, 3.0)])
near(error, math.sqrt(0.32) / 2.0, "seeds' own errors combined")
near(dof, 6.0, "their degrees of freedom")

# the rule fails where it should: two values 7 errors apart on 20 degrees of freedom, and a
# difference that z = 3 would fail but Student's t at 2 degrees of freedom cannot tell
t, dof = welch((0.0, 0.1, 10.0), (1.0, 0.1, 10.0))
if t <= t_bound(3.0, dof):
    sys.exit(f"t = {t:.3g} on {dof:g} degrees of freedom passed; the rule cannot fail")
print(f"ok: t = {t:.3g} on {dof:g} degrees of freedom fails (bound {t_bound(3.0, dof):.3g})")
t, dof = welch((0.0, 0.1, 1.0), (0.5, 0.1, 1.0))
if not 3.0 < t <= t_bound(3.0, dof):
    sys.exit(f"t = {t:.3g} on {dof:g} degrees of freedom: expected above 3, within the bound")
print(f"ok: t = {t:.3g} on {dof:g} degrees of freedom is within Student's bound "
      f"{t_bound(3.0, dof):.3g}: two seeds of one block cannot tell it")
