"""Forces of the point-mass fidelity (Podgaets & Ockels 2007, eqs. 2-22), one node or element at a time.

Frame: x along the nominal wind's origin ("north", the wind blows towards -x), y east, z down (Meijaard et al.
1999), gravity (0, 0, +g). Every function reads the flat state ``x`` (6 n,) through the node layout
``N3_POS``/``N3_VEL`` and the packed ``PMModel``; none allocates.

* Element e (node e - 1 to node e): tension only, Voigt: T = EA (l - l0)/l0 + DA l'/l0 for l > l0, else 0,
  clipped at 0 (eq. 13 with damping; the paper's eq. 16 without it). l0 is ``PP_L0`` but for the first element
  (``PP_L_FIRST``) and the element to the end anchor (``PP_L_LAST``), whose lengths the moving cable changes at
  the rates ``PP_RATE_FIRST``/``PP_RATE_LAST``; the damping then acts on the material strain rate,
  l0 d(eps)/dt = l' - (l/l0) dl0/dt (as the rigid moving cable, docs/moving_cable.md).
* Kite (eqs. 3-15): lift L = 1/2 rho S C_L(alpha) |V| (d x V), drag D = -1/2 rho S C_D(alpha) |V| V, with V the
  kite's velocity relative to the air, d the span (body y) axis of the commanded attitude and alpha the angle
  of V in the body x-z plane. (The paper writes V x d with its own sign of V; d x V points "up" for a kite
  flying nose into the wind, z down. |d x V| = |V| cos(beta), so sideslip reduces lift as in eq. 14.)
* Cable drag (Meijaard et al. 1999, eqs. 23-24, the cross-flow form): -1/2 rho d l (C_N0 |V_n| V_n +
  C_T0 |V| V) on the cable length a node carries, V_n the part of V normal to the local tangent.
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (
    KT_ALPHA0,
    KT_AREA,
    KT_DALPHA,
    KT_MASS,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    PP_ANCHOR,
    PP_CN0,
    PP_CT0,
    PP_DA,
    PP_DIAM,
    PP_EA,
    PP_END,
    PP_END_FIXED,
    PP_GRAVITY,
    PP_L0,
    PP_L_FIRST,
    PP_L_LAST,
    PP_MU,
    PP_N,
    PP_RATE_FIRST,
    PP_RATE_LAST,
    PU_PITCH,
    PU_ROLL,
    PU_SIZE,
    PU_YAW,
)
from laddermill_gym.kernels.wind import density, wind_point

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def node_pos(x, j, par):
    """Position [m] of free node j, or of the start anchor (j = -1) or the end anchor (j = n)."""
    if j < 0:
        return par[PP_ANCHOR], par[PP_ANCHOR + 1], par[PP_ANCHOR + 2]
    if j >= int(par[PP_N]):
        return par[PP_END], par[PP_END + 1], par[PP_END + 2]
    o = N3_SIZE * j + N3_POS
    return x[o], x[o + 1], x[o + 2]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def node_vel(x, j, par):
    """Velocity [m/s] of free node j; the anchors (j = -1, j = n) stand still."""
    if j < 0 or j >= int(par[PP_N]):
        return 0.0, 0.0, 0.0
    o = N3_SIZE * j + N3_VEL
    return x[o], x[o + 1], x[o + 2]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def n_elements(par):
    """Number of elements: one below every free node, plus one to the end anchor when the end is fixed."""
    return int(par[PP_N]) + (1 if par[PP_END_FIXED] != 0.0 else 0)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def rest_length(e, par):
    """Unstretched length [m] of element e: ``PP_L_FIRST`` for the first, ``PP_L_LAST`` for the element to the end
    anchor (e = n), else ``PP_L0``."""
    if e == 0:
        return par[PP_L_FIRST]
    if e == int(par[PP_N]):
        return par[PP_L_LAST]
    return par[PP_L0]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def rest_rate(e, par):
    """Rate of the unstretched length [m/s] of element e (non-zero only at the moving cable's two ends)."""
    if e == 0:
        return par[PP_RATE_FIRST]
    if e == int(par[PP_N]):
        return par[PP_RATE_LAST]
    return 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def element_geometry(x, e, par):
    """Unit vector (node e - 1 -> node e) and length l [m] of element e."""
    ax, ay, az = node_pos(x, e - 1, par)
    bx, by, bz = node_pos(x, e, par)
    dx, dy, dz = bx - ax, by - ay, bz - az
    ln = math.sqrt(dx * dx + dy * dy + dz * dz)
    inv = 1.0 / ln if ln > 0.0 else 0.0
    return dx * inv, dy * inv, dz * inv, ln


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def element_tension(x, e, par, damped):
    """Tension [N] of element e: elastic, plus Voigt damping on the material strain rate when ``damped``; zero
    when slack."""
    tx, ty, tz, ln = element_geometry(x, e, par)
    l0 = rest_length(e, par)
    if ln <= l0:
        return 0.0
    ten = par[PP_EA] * (ln - l0) / l0
    if damped:
        ax, ay, az = node_vel(x, e - 1, par)
        bx, by, bz = node_vel(x, e, par)
        ld = (bx - ax) * tx + (by - ay) * ty + (bz - az) * tz - ln / l0 * rest_rate(e, par)
        ten += par[PP_DA] * ld / l0
    return ten if ten > 0.0 else 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def has_upper(j, par):
    """Whether free node j has an element above it (to node j + 1 or to the end anchor)."""
    return j < int(par[PP_N]) - 1 or par[PP_END_FIXED] != 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def kite_index(j, knode):
    """Index k of the kite on node j (knode ascending; the caller knows there is one)."""
    lo, hi = 0, knode.size - 1
    while lo < hi:
        mid = (lo + hi) // 2
        if knode[mid] < j:
            lo = mid + 1
        else:
            hi = mid
    return lo


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def cable_length_at(j, par):
    """Cable length [m] lumped at free node j: half of each element it touches."""
    if has_upper(j, par):
        return 0.5 * (rest_length(j, par) + rest_length(j + 1, par))
    return 0.5 * rest_length(j, par)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def node_mass(j, M):
    """Lumped mass [kg] of free node j: its cable share plus the kite it carries."""
    m = M.par[PP_MU] * cable_length_at(j, M.par)
    if M.kflag[j] != 0:
        m += M.kt[KT_MASS]
    return m


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def kite_coefficients(alpha, M):
    """C_L, C_D at alpha [rad] by linear interpolation on the kite's uniform grid (periodic in 2 pi)."""
    if not (abs(alpha) < math.inf):  # NaN or infinite alpha: no table index, NaN coefficients (issue 13)
        return math.nan, math.nan
    a0, da = M.kt[KT_ALPHA0], M.kt[KT_DALPHA]
    a = alpha - a0
    a -= 2.0 * math.pi * math.floor(a / (2.0 * math.pi))
    u = a / da
    n = M.kcl.size
    i = min(max(int(u), 0), n - 2)
    f = u - i
    return M.kcl[i] + f * (M.kcl[i + 1] - M.kcl[i]), M.kcd[i] + f * (M.kcd[i + 1] - M.kcd[i])


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def kite_force(k, vx, vy, vz, rho, u, M):
    """Aerodynamic force [N] on kite k with air-relative velocity (vx, vy, vz) [m/s] at density rho
    [kg/m^3], attitude from the controls u (roll, pitch, yaw)."""
    phi, th, psi = u[k * PU_SIZE + PU_ROLL], u[k * PU_SIZE + PU_PITCH], u[k * PU_SIZE + PU_YAW]
    cf, sf, ct, st, cp, sp = math.cos(phi), math.sin(phi), math.cos(th), math.sin(th), math.cos(psi), math.sin(psi)
    # columns of the body-to-global rotation Rz(psi) Ry(theta) Rx(phi): body x (nose), y (span), z (down)
    xbx, xby, xbz = ct * cp, ct * sp, -st
    dx, dy, dz = cp * st * sf - sp * cf, sp * st * sf + cp * cf, ct * sf
    zbx, zby, zbz = cp * st * cf + sp * sf, sp * st * cf - cp * sf, ct * cf
    alpha = math.atan2(vx * zbx + vy * zby + vz * zbz, vx * xbx + vy * xby + vz * xbz)
    cl, cd = kite_coefficients(alpha, M)
    vv = math.sqrt(vx * vx + vy * vy + vz * vz)
    q = 0.5 * rho * M.kt[KT_AREA] * vv
    lx, ly, lz = dy * vz - dz * vy, dz * vx - dx * vz, dx * vy - dy * vx
    return q * (cl * lx - cd * vx), q * (cl * ly - cd * vy), q * (cl * lz - cd * vz)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def external_force(t, x, j, u, M, s, d):
    """Gravity, cable drag and (on a kite node) kite aerodynamics on free node j [N]; wind modulation s, d."""
    par = M.par
    px, py, pz = node_pos(x, j, par)
    vx, vy, vz = node_vel(x, j, par)
    wx, wy, wz = wind_point(px, py, pz, t, M.wf, s, d, M.gp, M.gv)
    ax, ay, az = vx - wx, vy - wy, vz - wz
    rho = density(-pz, M.wf)
    m = node_mass(j, M)
    fx, fy, fz = 0.0, 0.0, m * par[PP_GRAVITY]
    # cable drag on the length this node carries, about the local tangent
    lo = node_pos(x, j - 1, par)
    hi = node_pos(x, j + 1, par) if has_upper(j, par) else (px, py, pz)
    tx, ty, tz = hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]
    tn = math.sqrt(tx * tx + ty * ty + tz * tz)
    if tn > 0.0:
        tx, ty, tz = tx / tn, ty / tn, tz / tn
    va = ax * tx + ay * ty + az * tz
    nx, ny, nz = ax - va * tx, ay - va * ty, az - va * tz
    vn = math.sqrt(nx * nx + ny * ny + nz * nz)
    vm = math.sqrt(ax * ax + ay * ay + az * az)
    qc = 0.5 * rho * par[PP_DIAM] * cable_length_at(j, par)
    cn, ctg = qc * par[PP_CN0] * vn, qc * par[PP_CT0] * vm
    fx -= cn * nx + ctg * ax
    fy -= cn * ny + ctg * ay
    fz -= cn * nz + ctg * az
    if M.kflag[j] != 0:
        kx, ky, kz = kite_force(kite_index(j, M.knode), ax, ay, az, rho, u, M)
        fx, fy, fz = fx + kx, fy + ky, fz + kz
    return fx, fy, fz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def string_force(x, j, tension, par):
    """Net force [N] of the two elements on free node j from the stored tensions (n_e,) [N]."""
    tx, ty, tz, _ = element_geometry(x, j, par)
    t0 = tension[j]
    fx, fy, fz = -t0 * tx, -t0 * ty, -t0 * tz
    if has_upper(j, par):
        ux, uy, uz, _ = element_geometry(x, j + 1, par)
        t1 = tension[j + 1]
        fx, fy, fz = fx + t1 * ux, fy + t1 * uy, fz + t1 * uz
    return fx, fy, fz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def node_force(t, x, j, u, M, tension, s, d):
    """Total force [N] on free node j: :func:`external_force` (wind modulation s, d) plus :func:`string_force` of
    the stored tensions (n_e,) [N]; what the explicit kick, the accelerations and the implicit assembly step on."""
    fx, fy, fz = external_force(t, x, j, u, M, s, d)
    gx, gy, gz = string_force(x, j, tension, M.par)
    return fx + gx, fy + gy, fz + gz
