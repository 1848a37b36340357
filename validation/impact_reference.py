"""The reference of the work-precision impacts: two equal disks meeting head-on at 2 SPEED, and
their normal contact's ODE solved accurately (RK4), with the laws of src/talus/normal_laws.hpp
written out again so that nothing is taken from the engine.
"""
import functools
import math

RADIUS, DENSITY, YOUNG, POISSON, SPEED = 0.001, 2650.0, 1.0e8, 0.3, 0.5
MASS = DENSITY * math.pi * RADIUS**2  # a disk, 1 m thick (docs/model.md)
HERTZ_A = 2.0e-6                      # s: the viscoelastic Hertz damping
LINEAR_K, LINEAR_E = 1.0e4, 0.5       # N/m, the asked restitution
OFFSET = 0.8 * RADIUS                 # the oblique impact's offset across the approach


def normal_force(law, xi, rate, m_eff, r_eff):
    """The never-attractive normal force of src/talus/normal_laws.hpp, written out again."""
    if law == "hertz":
        e_star = YOUNG / (2.0 * (1.0 - POISSON**2))
        rho = 4.0 / 3.0 * e_star * math.sqrt(r_eff)
        f = rho * math.sqrt(max(xi, 0.0)) * (xi + 1.5 * HERTZ_A * rate)
    else:
        zeta = linear_damping_ratio(LINEAR_E)
        f = LINEAR_K * xi + 2.0 * zeta * math.sqrt(LINEAR_K * m_eff) * rate
    return max(f, 0.0)


@functools.lru_cache(maxsize=None)
def linear_damping_ratio(e):
    """zeta of the never-attractive dashpot that reaches restitution e (closed_forms.hpp's
    inverse), found by bisection on the ODE itself so that nothing is taken from the engine."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        got = contact_ode("linear_zeta", mid)[0]
        lo, hi = (mid, hi) if got > e else (lo, mid)
    return 0.5 * (lo + hi)


def contact_ode(law, zeta=None, steps=200000):
    """(restitution, peak force, duration) of the head-on impact, by RK4 on xi'' = -F / m_eff
    from xi = 0, xi' = 2 SPEED, the exit placed by linear interpolation of xi between steps."""
    m_eff, r_eff, v = 0.5 * MASS, 0.5 * RADIUS, 2.0 * SPEED
    if law == "linear_zeta":  # the bisection's inner solve: a linear law of this zeta
        force = lambda xi, rate: max(  # noqa: E731
            LINEAR_K * xi + 2.0 * zeta * math.sqrt(LINEAR_K * m_eff) * rate, 0.0)
        t_c = math.pi * math.sqrt(m_eff / LINEAR_K)
        steps = 20000
    else:
        force = lambda xi, rate: normal_force(law, xi, rate, m_eff, r_eff)  # noqa: E731
        t_c = collision_time(law)
    h = 2.0 * t_c / steps
    xi, rate, t, peak = 0.0, v, 0.0, 0.0
    deriv = lambda x, u: (u, -force(x, u) / m_eff)  # noqa: E731
    while True:
        k1 = deriv(xi, rate)
        k2 = deriv(xi + 0.5 * h * k1[0], rate + 0.5 * h * k1[1])
        k3 = deriv(xi + 0.5 * h * k2[0], rate + 0.5 * h * k2[1])
        k4 = deriv(xi + h * k3[0], rate + h * k3[1])
        nxi = xi + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        nrate = rate + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        if nxi <= 0.0 and t > 0.0:
            f = xi / (xi - nxi)
            exit_rate = rate + f * (nrate - rate)
            return -exit_rate / v, peak, t + f * h
        xi, rate, t = nxi, nrate, t + h
        peak = max(peak, force(xi, rate))


def collision_time(law):
    """The elastic collision time at 2 SPEED, the scale of the timesteps (as the engine's
    automatic timestep: collision time / factor)."""
    m_eff, r_eff = 0.5 * MASS, 0.5 * RADIUS
    if law == "hertz":
        rho = 4.0 / 3.0 * YOUNG / (2.0 * (1.0 - POISSON**2)) * math.sqrt(r_eff)
        c = 2.0 * 1.25**0.4 * math.sqrt(math.pi) * math.gamma(1.4) / math.gamma(0.9)
        return c * (m_eff / rho) ** 0.4 * (2.0 * SPEED) ** -0.2
    return math.pi * math.sqrt(m_eff / LINEAR_K)
