"""Wind profile, direction, density, time modulation (Meijaard et al. 1999 eqs. 1-3) and the frozen gust
grid that makes the wind vary in space.

Packed wind parameters ``wf``: slots ``WF_*`` of ``kernels/contract.py`` (v0 [m/s], h0 [m], v1 [1/s],
exponent [-], phi_inf [rad], h_s [m], rho0 [kg/m^3], density model, H_b [m]). Modulation samples ``ms`` (speed
factor) and ``md`` (direction offset, rad) on the grid ``t0 + k dt`` (``tmod[TM_T0]``, ``tmod[TM_DT]``).
Gust grid: header ``gp`` (slots ``GP_*``) and samples ``gv`` (``atmosphere/field.py`` builds both; None and None
when there is none).

The wind at a point p = (x, y, z) [m] and time t [s] is (:func:`wind_point`)

    w(p, t) = -s(t) V(h) (cos a, sin a, 0) + g(xi, h),   h = -z,  a = phi_s(h) + delta(t),
    xi = p . e - U t,

with s, delta the modulation, V, phi_s the profile and direction (eqs. 1-2), e the grid's downwind unit vector,
U its advection speed (Taylor's frozen turbulence) and g the bilinear interpolation of the grid samples
(held at the grid's edges outside it), rotated from (u downwind, v right, w up) to global axes.
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (
    DENSITY_BAROMETRIC,
    GP_ADVECTION,
    GP_DH,
    GP_DXI,
    GP_EX,
    GP_EY,
    GP_FADE,
    GP_H0,
    GP_NH,
    GP_NXI,
    GP_XI0,
    GV_SIZE,
    GV_U,
    GV_V,
    GV_W,
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


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def modulation(t, t0, dt, ms, md):
    """Speed factor, direction offset and their time derivatives at time t (linear interpolation,
    held constant outside the sample grid). Returns (s, delta, s_dot, delta_dot)."""
    n = ms.size
    if n == 1:
        return ms[0], md[0], 0.0, 0.0
    u = (t - t0) / dt
    if u != u:  # a NaN time indexes nothing: NaN out, for the caller's finiteness checks (issue 13)
        return u, u, u, u
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


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def profile(h, wf):
    """Wind speed V_w(h) [m/s] and its height derivative [1/s] (eq. 1)."""
    v0, h0, v1, ex = wf[WF_V0], wf[WF_H0], wf[WF_V1], wf[WF_EXPONENT]
    if h <= 0.0:
        return 0.0, 0.0
    if h < h0:
        r = h / h0
        return v0 * r ** ex, v0 * ex * r ** (ex - 1.0) / h0
    return v0 + v1 * (h - h0), v1


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def direction(h, wf):
    """Wind direction phi_s(h) [rad] and its height derivative [rad/m] (eq. 2)."""
    pinf, hs = wf[WF_DIR_INF], wf[WF_DIR_HEIGHT]
    if pinf == 0.0 or h <= 0.0:
        return 0.0, 0.0
    ex = math.exp(-h / hs)
    return pinf * (1.0 - ex), pinf * ex / hs


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def density(h, wf):
    """Air density [kg/m^3] at altitude h [m] (eq. 3 or ISA troposphere)."""
    if wf[WF_DENSITY_MODEL] == DENSITY_BAROMETRIC:
        return wf[WF_RHO0] * math.exp(-h / wf[WF_SCALE_HEIGHT])
    base = 1.0 - 2.2558e-5 * h
    if base <= 0.0:
        return 0.0
    return wf[WF_RHO0] * base ** 4.2559


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def wind_at(z, wf, s, d):
    """Wind velocity (global, m/s) at height h = -z with speed factor s and direction offset d."""
    h = -z
    v, _ = profile(h, wf)
    ph, _ = direction(h, wf)
    a = ph + d
    return -s * v * math.cos(a), -s * v * math.sin(a), 0.0


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
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


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _cell(u, n):
    """Cell index k, fraction f in it and whether u lies inside the grid (0 <= u <= n - 1); held at the edges.
    A NaN u (a non-finite state) gives cell 0, never a NaN index."""
    if n < 2 or not u > 0.0:
        return 0, 0.0, False
    if u >= n - 1:
        return n - 2, 1.0, False
    k = int(math.floor(u))
    return k, u - k, True


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _grid_cell(xi, h, gp):
    """The cell of (xi, h) [m]: flat offsets of its four corners' first component (k00, k10, k01, k11), the
    fractions (a along xi, b along h) and whether xi and h lie inside the grid (else held at the edge). A grid
    of one row or column is constant along that axis. Computed once for all three components."""
    nx, nh = int(gp[GP_NXI]), int(gp[GP_NH])
    i, a, in_x = _cell((xi - gp[GP_XI0]) / gp[GP_DXI], nx)
    j, b, in_h = _cell((h - gp[GP_H0]) / gp[GP_DH], nh)
    i1 = i + 1 if nx > 1 else i
    j1 = j + 1 if nh > 1 else j
    return ((i * nh + j) * GV_SIZE, (i1 * nh + j) * GV_SIZE, (i * nh + j1) * GV_SIZE, (i1 * nh + j1) * GV_SIZE,
            a, b, in_x, in_h)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, c):
    """Component c of the gust grid in the cell of :func:`_grid_cell` by bilinear interpolation, and its
    derivatives along xi and h [1/s] (zero across a held edge)."""
    f00 = gv[k00 + c]
    f10 = gv[k10 + c]
    f01 = gv[k01 + c]
    f11 = gv[k11 + c]
    f = (1.0 - a) * ((1.0 - b) * f00 + b * f01) + a * ((1.0 - b) * f10 + b * f11)
    dfx = ((1.0 - b) * (f10 - f00) + b * (f11 - f01)) / gp[GP_DXI] if in_x else 0.0
    dfh = ((1.0 - a) * (f01 - f00) + a * (f11 - f10)) / gp[GP_DH] if in_h else 0.0
    return f, dfx, dfh


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _fade(t, tf):
    """The grid's fade-in factor r(t) = 0.5 (1 - cos(pi t / T_f)) on 0 <= t < T_f (0 before, 1 after; 1 for
    T_f = 0) and its time derivative [1/s]."""
    if tf <= 0.0 or t >= tf:
        return 1.0, 0.0
    if not t > 0.0:
        return 0.0, 0.0
    c = math.pi / tf
    return 0.5 * (1.0 - math.cos(c * t)), 0.5 * c * math.sin(c * t)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def gust_at(x, y, z, t, gp, gv):
    """Gust velocity (global, m/s) of the frozen grid at the point (x, y, z) [m] and time t [s] (times the
    fade-in factor)."""
    if gp[GP_NXI] == 0.0:  # a batch row without a grid
        return 0.0, 0.0, 0.0
    ex, ey = gp[GP_EX], gp[GP_EY]
    xi = x * ex + y * ey - gp[GP_ADVECTION] * t
    k00, k10, k01, k11, a, b, in_x, in_h = _grid_cell(xi, -z, gp)
    u, _, _ = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_U)
    v, _, _ = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_V)
    w, _, _ = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_W)
    r, _ = _fade(t, gp[GP_FADE])
    return r * (u * ex - v * ey), r * (u * ey + v * ex), -r * w


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def gust_rate(x, y, z, vx, vy, vz, t, gp, gv):
    """Time derivative (global, m/s^2) of the gust seen by a point at (x, y, z) [m] moving with the global
    velocity (vx, vy, vz) [m/s]: r (dg/dxi (v . e - U) + dg/dh (-vz)) + r' g, r the fade-in factor."""
    if gp[GP_NXI] == 0.0:  # a batch row without a grid
        return 0.0, 0.0, 0.0
    ex, ey = gp[GP_EX], gp[GP_EY]
    xi = x * ex + y * ey - gp[GP_ADVECTION] * t
    xid = vx * ex + vy * ey - gp[GP_ADVECTION]
    hd = -vz
    k00, k10, k01, k11, a, b, in_x, in_h = _grid_cell(xi, -z, gp)
    u, ux, uh = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_U)
    v, vx_, vh = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_V)
    w, wx, wh = _grid_sample(k00, k10, k01, k11, a, b, in_x, in_h, gp, gv, GV_W)
    r, rd = _fade(t, gp[GP_FADE])
    du = r * (ux * xid + uh * hd) + rd * u
    dv = r * (vx_ * xid + vh * hd) + rd * v
    dw = r * (wx * xid + wh * hd) + rd * w
    return du * ex - dv * ey, du * ey + dv * ex, -dw


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def wind_point(x, y, z, t, wf, s, d, gp, gv):
    """Wind velocity (global, m/s) at the point (x, y, z) [m] and time t [s]: the profile with speed factor s
    and direction offset d (:func:`wind_at`) plus the frozen gust grid (``gp``, ``gv``; both None for none: the
    test is then resolved when numba compiles, so the kernels are the profile-only code, bit for bit)."""
    if gv is None:
        return wind_at(z, wf, s, d)
    wx, wy, wz = wind_at(z, wf, s, d)
    gx, gy, gz = gust_at(x, y, z, t, gp, gv)
    return wx + gx, wy + gy, wz + gz


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def wind_point_rate(x, y, z, vx, vy, vz, t, wf, s, d, sdot, ddot, gp, gv):
    """Time derivative (global, m/s^2) of the wind seen by a point at (x, y, z) [m] moving with the global
    velocity (vx, vy, vz) [m/s] (:func:`wind_rate` plus :func:`gust_rate`); the alpha-rate term uses it."""
    if gv is None:
        return wind_rate(z, vz, wf, s, d, sdot, ddot)
    wx, wy, wz = wind_rate(z, vz, wf, s, d, sdot, ddot)
    gx, gy, gz = gust_rate(x, y, z, vx, vy, vz, t, gp, gv)
    return wx + gx, wy + gy, wz + gz
