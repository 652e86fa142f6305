"""Wind profile, direction, density and time modulation (Meijaard et al. 1999 eqs. 1-3).

Packed wind parameters ``wf``: slots ``WF_*`` of ``kernels/contract.py`` (v0 [m/s], h0 [m], v1 [1/s],
exponent [-], phi_inf [rad], h_s [m], rho0 [kg/m^3], density model, H_b [m]). Modulation samples ``ms`` (speed
factor) and ``md`` (direction offset, rad) on the grid ``t0 + k dt`` (``tmod[TM_T0]``, ``tmod[TM_DT]``).
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (
    DENSITY_BAROMETRIC,
    WF_DENSITY_MODEL,
    WF_DIR_HEIGHT,
    WF_DIR_INF,
    WF_EXPONENT,
    WF_H0,
    WF_RHO0,
    WF_SCALE_HEIGHT,
    WF_V0,
    WF_V1,
)


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def modulation(t, t0, dt, ms, md):
    """Speed factor, direction offset and their time derivatives at time t (linear interpolation,
    held constant outside the sample grid). Returns (s, delta, s_dot, delta_dot)."""
    n = ms.size
    if n == 1:
        return ms[0], md[0], 0.0, 0.0
    u = (t - t0) / dt
    if u <= 0.0:
        if u == 0.0:
            return ms[0], md[0], (ms[1] - ms[0]) / dt, (md[1] - md[0]) / dt
        return ms[0], md[0], 0.0, 0.0
    if u >= n - 1:
        return ms[n - 1], md[n - 1], 0.0, 0.0
    k = int(math.floor(u))
    f = u - k
    s = ms[k] + f * (ms[k + 1] - ms[k])
    d = md[k] + f * (md[k + 1] - md[k])
    return s, d, (ms[k + 1] - ms[k]) / dt, (md[k + 1] - md[k]) / dt


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def profile(h, wf):
    """Wind speed V_w(h) [m/s] and its height derivative [1/s] (eq. 1)."""
    v0, h0, v1, ex = wf[WF_V0], wf[WF_H0], wf[WF_V1], wf[WF_EXPONENT]
    if h <= 0.0:
        return 0.0, 0.0
    if h < h0:
        r = h / h0
        return v0 * r ** ex, v0 * ex * r ** (ex - 1.0) / h0
    return v0 + v1 * (h - h0), v1


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def direction(h, wf):
    """Wind direction phi_s(h) [rad] and its height derivative [rad/m] (eq. 2)."""
    pinf, hs = wf[WF_DIR_INF], wf[WF_DIR_HEIGHT]
    if pinf == 0.0 or h <= 0.0:
        return 0.0, 0.0
    ex = math.exp(-h / hs)
    return pinf * (1.0 - ex), pinf * ex / hs


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def density(h, wf):
    """Air density [kg/m^3] at altitude h [m] (eq. 3 or ISA troposphere)."""
    if wf[WF_DENSITY_MODEL] == DENSITY_BAROMETRIC:
        return wf[WF_RHO0] * math.exp(-h / wf[WF_SCALE_HEIGHT])
    base = 1.0 - 2.2558e-5 * h
    if base <= 0.0:
        return 0.0
    return wf[WF_RHO0] * base ** 4.2559


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def wind_at(z, wf, s, d):
    """Wind velocity (global, m/s) at height h = -z with speed factor s and direction offset d."""
    h = -z
    v, _ = profile(h, wf)
    ph, _ = direction(h, wf)
    a = ph + d
    return -s * v * math.cos(a), -s * v * math.sin(a), 0.0


@njit(cache=True, error_model="numpy", fastmath={"contract", "reassoc", "nsz", "arcp"})
def wind_rate(z, zdot, wf, s, d, sdot, ddot):
    """Time derivative of the wind (global) seen by a point at height -z moving with vertical rate zdot."""
    h = -z
    v, dv = profile(h, wf)
    ph, dph = direction(h, wf)
    a = ph + d
    ca, sa = math.cos(a), math.sin(a)
    hdot = -zdot
    # d/dt of -s v (cos a, sin a): s, v and a vary
    dvdt = dv * hdot
    dadt = dph * hdot + ddot
    wx = -(sdot * v + s * dvdt) * ca + s * v * sa * dadt
    wy = -(sdot * v + s * dvdt) * sa - s * v * ca * dadt
    return wx, wy, 0.0
