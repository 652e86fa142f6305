"""The ideal actuator disk at an incidence (Roberts' ideal curve in Fig. 3): its best through-flow and power
coefficient with Glauert's inflow, no profile drag, no H-force. Non-dimensional as ``rotor_kernels``; angles in
radians. Read through :mod:`laddermill_gym.rotorcraft.rotor_kernels`, which the rotor's API imports.
"""

import math

from numba import njit


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def _ideal_cubic(w, s, c2):
    """g(w) = 3 w^3 - 2 s w^2 + 2 c^2 w - s c^2 (zero where d C_p/dw = 0 for the actuator disk)."""
    return ((3.0 * w - 2.0 * s) * w + 2.0 * c2) * w - s * c2


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def ideal_through_flow(alpha_c):
    """Normal through-flow w = (V sin(alpha_c) - v)/V [-] of the best actuator disk at incidence alpha_c [rad].

    The disk (no profile drag, no H-force) extracts C_p = 4 u w sqrt(cos^2 alpha_c + w^2) with the induced
    velocity u = sin(alpha_c) - w (Glauert: T = 2 rho A v sqrt((V cos)^2 + (V sin - v)^2)). dC_p/dw = 0 gives
    g(w) = 3 w^3 - 2 s w^2 + 2 c^2 w - s c^2 = 0 with g(0) = -s c^2 <= 0 < g(s) = s; solved by bisection on
    [0, s] (one root there for 0 < alpha_c <= pi/2, checked on a 1e-4 rad grid in tests). Returns 0 for
    alpha_c <= 0 and 2/3 at alpha_c = pi/2 (Betz: u = 1/3).
    """
    s = math.sin(alpha_c)
    if s <= 0.0:
        return 0.0
    c = math.cos(alpha_c)
    c2 = c * c
    lo, hi = 0.0, s
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _ideal_cubic(mid, s, c2) < 0.0:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * s:
            break
    return 0.5 * (lo + hi)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def ideal_power_coefficient(alpha_c):
    """Ideal (no profile drag) windmill C_p [-] of an actuator disk at incidence alpha_c [rad], Glauert inflow.

    Maximum over the induced velocity of 4 u w sqrt(cos^2 alpha_c + w^2) (see :func:`ideal_through_flow`):
    16/27 (Betz) at alpha_c = pi/2, tending to 0 as alpha_c -> 0.
    """
    w = ideal_through_flow(alpha_c)
    s = math.sin(alpha_c)
    if s <= 0.0:
        return 0.0
    c = math.cos(alpha_c)
    return 4.0 * (s - w) * w * math.sqrt(c * c + w * w)
