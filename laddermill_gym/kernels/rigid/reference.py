"""Plain-numpy reference implementation of the laddermill model's right-hand side (3D only).

This module is the *oracle* the numba kernels are tested against. It is written directly from
``laddermill_gym/docs/model.md`` with readability as the only goal: it assembles the dense global mass
matrix ``M`` (``n_dof x n_dof``) and the dense generalised force vector ``F`` of eq. (M25),
``M v' = f + h - D^T sigma``, and solves with :func:`numpy.linalg.solve`. Nothing here is fast.

Conventions (see docs/model.md):

* SI units and radians; global frame x north, y east, z down; altitude ``h = -z``.
* Generalised velocities: per wing ``(v, omega)`` in body axes (6 dof, wing ``k`` at dof ``6 k``),
  then per free node its global velocity (3 dof, node ``j`` at dof ``6 n_w + 3 j``).
* State: per wing ``[x(3), q(4), v(3), omega(3)]`` (13 floats at ``13 k``), then per node
  ``[position(3), velocity(3)]`` (6 floats at ``13 n_w + 6 j``).

Choices made where the specification leaves room (the kernels must make the same ones):

* Wind modulation: the sample interval is ``k = floor((t - t0) / dt)``; for ``0 <= k <= n-2`` the value
  is the linear interpolation on ``[k, k+1]`` and the time slope is ``(s[k+1] - s[k]) / dt``; for ``k < 0``
  the value is ``s[0]`` and for ``k >= n-1`` it is ``s[n-1]``, with slope 0 in both cases. At an exact
  sample time ``t0 + k dt`` the slope is that of the interval starting there.
* Wind profile at exactly ``h = h0`` uses the upper branch (value ``V0``, slope ``V1``); for ``h <= 0`` the
  speed and its slope are 0. With ``direction_inf == 0`` the direction is identically 0 (no division by
  ``direction_height``).
* ISA density: the base ``1 - 2.2558e-5 h`` is clipped at 0 (density 0 above ~44.3 km).
* Air density for a cable load is evaluated at the height of that end's attachment point.
* ``g = (-w_a, 0, u_a) / (u_a^2 + w_a^2)`` is set to 0 when ``u_a^2 + w_a^2 == 0`` (pure sideslip).
* Gravity also acts on a node's lumped ``node_mass`` (``node_mass * (0, 0, gravity)``).
* Controls are used as given (no clipping to ``control_limits``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.interpolate import CubicSpline

from laddermill_gym.model.params import (
    AERO_COLUMNS,
    END_FIXED,
    END_NODE,
    END_WING,
    N_CONTROLS,
    AeroTable,
    Assembly,
    WindParams,
    WingType,
)

__all__ = [
    "ElementState",
    "aero_coefficients",
    "air_density",
    "cable_aero_load",
    "element_loads_per_length",
    "element_state",
    "element_tensions",
    "end_transformation",
    "euler_321",
    "inertia_matrix",
    "mass_matrix_and_forces",
    "quaternion_product",
    "reference_rhs",
    "rotation",
    "sag_elongation",
    "sag_tension",
    "skew",
    "tension",
    "wind_direction_profile",
    "wind_modulation",
    "wind_rate",
    "wind_speed_profile",
    "wind_velocity",
    "wing_aero",
]

#: Airspeed below which a wing gets no aerodynamic load [m/s].
AIRSPEED_EPS = 1e-9
#: Element length below which the element direction is taken as 0 [m].
LENGTH_EPS = 1e-9


# --------------------------------------------------------------------------------------------------
# Wind and air
# --------------------------------------------------------------------------------------------------


def wind_speed_profile(wind: WindParams, h: float) -> tuple[float, float]:
    """Wind speed V_w(h) of eq. (M1) and its height derivative.

    Parameters
    ----------
    wind : WindParams
    h : float
        Altitude [m] (``h = -z``).

    Returns
    -------
    V : float
        Speed [m/s]: 0 for ``h <= 0``, ``V0 (h/h0)^n`` for ``0 < h < h0``, ``V0 + V1 (h - h0)`` for ``h >= h0``.
    dV_dh : float
        dV_w/dh [1/s] (0 for ``h <= 0``).
    """
    if h <= 0.0:
        return 0.0, 0.0
    if h < wind.h0:
        V = wind.v0 * (h / wind.h0) ** wind.exponent
        dV = wind.exponent * wind.v0 / wind.h0 * (h / wind.h0) ** (wind.exponent - 1.0)
        return V, dV
    return wind.v0 + wind.v1 * (h - wind.h0), wind.v1


def wind_direction_profile(wind: WindParams, h: float) -> tuple[float, float]:
    """Wind direction phi_s(h) = phi_inf (1 - exp(-h/h_s)) of eq. (M2) and its height derivative.

    Returns
    -------
    phi : float
        Direction [rad].
    dphi_dh : float
        d phi_s / dh [rad/m].
    """
    if wind.direction_inf == 0.0:
        return 0.0, 0.0
    decay = np.exp(-h / wind.direction_height)
    return wind.direction_inf * (1.0 - decay), wind.direction_inf / wind.direction_height * decay


def _interp_with_slope(samples: np.ndarray, t0: float, dt: float, t: float) -> tuple[float, float]:
    """Linear interpolation of uniform samples, held constant outside; returns (value, d value/dt).

    The interval is ``k = floor((t - t0)/dt)`` (so an exact sample time belongs to the interval that
    starts there); outside ``0 <= k <= n - 2`` the end value is held and the slope is 0.
    """
    n = samples.size
    tau = (t - t0) / dt
    k = int(np.floor(tau))
    if k < 0:
        return float(samples[0]), 0.0
    if k >= n - 1:
        return float(samples[n - 1]), 0.0
    frac = tau - k
    value = samples[k] + (samples[k + 1] - samples[k]) * frac
    slope = (samples[k + 1] - samples[k]) / dt
    return float(value), float(slope)


def wind_modulation(wind: WindParams, t: float) -> tuple[float, float, float, float]:
    """Time modulation of the wind.

    Returns
    -------
    s, ds_dt : float
        Speed factor [-] and its time derivative [1/s].
    delta, ddelta_dt : float
        Direction offset [rad] and its time derivative [rad/s].
    """
    s, ds = _interp_with_slope(np.asarray(wind.mod_speed, dtype=float), wind.mod_t0, wind.mod_dt, t)
    d, dd = _interp_with_slope(np.asarray(wind.mod_direction, dtype=float), wind.mod_t0, wind.mod_dt, t)
    return s, ds, d, dd


def wind_velocity(wind: WindParams, position: np.ndarray, t: float) -> np.ndarray:
    """Wind velocity w(p, t) = -s(t) V_w(h) (cos(phi_s(h) + delta(t)), sin(phi_s(h) + delta(t)), 0).

    Parameters
    ----------
    wind : WindParams
    position : ndarray, shape (3,)
        Global position [m] (z down).
    t : float
        Time [s].

    Returns
    -------
    ndarray, shape (3,)
        Wind velocity in global components [m/s].
    """
    h = -float(position[2])
    V, _ = wind_speed_profile(wind, h)
    phi, _ = wind_direction_profile(wind, h)
    s, _, delta, _ = wind_modulation(wind, t)
    angle = phi + delta
    return -s * V * np.array([np.cos(angle), np.sin(angle), 0.0])


def wind_rate(wind: WindParams, position: np.ndarray, velocity: np.ndarray, t: float) -> np.ndarray:
    """Rate of change of the wind seen by a point moving with global velocity ``velocity``.

    ``dw/dt = (partial w / partial h) h' + partial w / partial t`` with ``h' = -velocity[2]``; the time
    part uses the slopes of the modulation (see :func:`wind_modulation`).

    Parameters
    ----------
    wind : WindParams
    position : ndarray, shape (3,)
        Global position [m].
    velocity : ndarray, shape (3,)
        Global velocity of the point [m/s].
    t : float
        Time [s].

    Returns
    -------
    ndarray, shape (3,)
        dw/dt in global components [m/s^2].
    """
    h = -float(position[2])
    h_dot = -float(velocity[2])
    V, dV_dh = wind_speed_profile(wind, h)
    phi, dphi_dh = wind_direction_profile(wind, h)
    s, ds_dt, delta, ddelta_dt = wind_modulation(wind, t)
    angle = phi + delta
    along = np.array([np.cos(angle), np.sin(angle), 0.0])  # unit vector of the direction
    turn = np.array([-np.sin(angle), np.cos(angle), 0.0])  # its derivative with respect to the angle
    # w = -s V along(angle)
    dw_dh = -s * (dV_dh * along + V * dphi_dh * turn)
    dw_dt = -(ds_dt * V * along + s * V * ddelta_dt * turn)
    return dw_dh * h_dot + dw_dt


def air_density(wind: WindParams, h: float) -> float:
    """Air density [kg/m^3] at altitude ``h`` [m] (eq. M3 "barometric", or ISA troposphere "isa")."""
    if wind.density_model == "barometric":
        return float(wind.rho0 * np.exp(-h / wind.scale_height))
    if wind.density_model == "isa":
        base = max(1.0 - 2.2558e-5 * h, 0.0)
        return float(wind.rho0 * base**4.2559)
    raise ValueError(f"wind.density_model must be 'barometric' or 'isa', got {wind.density_model!r}")


# --------------------------------------------------------------------------------------------------
# Rotations
# --------------------------------------------------------------------------------------------------


def skew(a: np.ndarray) -> np.ndarray:
    """The 3x3 antisymmetric matrix ``a~`` with ``a~ b = a x b``."""
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


def rotation(q: np.ndarray) -> np.ndarray:
    """Rotation matrix (body -> global components) of a quaternion, normalised first.

    Parameters
    ----------
    q : ndarray, shape (4,)
        Quaternion (q0, q1, q2, q3), scalar first; need not be unit.

    Returns
    -------
    ndarray, shape (3, 3)
    """
    q = np.asarray(q, dtype=float)
    q0, q1, q2, q3 = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
            [2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1)],
            [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)],
        ]
    )


def quaternion_product(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product ``a (x) b`` of two quaternions (scalar first), shape (4,)."""
    a0, av = a[0], np.asarray(a[1:], dtype=float)
    b0, bv = b[0], np.asarray(b[1:], dtype=float)
    return np.concatenate([[a0 * b0 - av @ bv], a0 * bv + b0 * av + np.cross(av, bv)])


def euler_321(R: np.ndarray) -> tuple[float, float, float]:
    """3-2-1 Euler angles of ``R = Rz(psi) Ry(theta) Rx(phi)``.

    Returns
    -------
    (phi, theta, psi) : tuple of float
        Roll, pitch, yaw [rad]: ``phi = atan2(R32, R33)``, ``theta = -asin(R31)``, ``psi = atan2(R21, R11)``.
    """
    phi = float(np.arctan2(R[2, 1], R[2, 2]))
    theta = float(-np.arcsin(np.clip(R[2, 0], -1.0, 1.0)))
    psi = float(np.arctan2(R[1, 0], R[0, 0]))
    return phi, theta, psi


# --------------------------------------------------------------------------------------------------
# Wing aerodynamics
# --------------------------------------------------------------------------------------------------

_SPLINES: dict[int, tuple[AeroTable, CubicSpline]] = {}


def _spline(table: AeroTable) -> CubicSpline:
    """Periodic cubic spline of all table columns (cached per table object)."""
    entry = _SPLINES.get(id(table))
    if entry is None or entry[0] is not table:
        spline = CubicSpline(table.alpha, table.values, bc_type="periodic", axis=0)
        entry = (table, spline)
        _SPLINES[id(table)] = entry
    return entry[1]


def aero_coefficients(table: AeroTable, alpha: float) -> dict[str, float]:
    """All table columns at angle of attack ``alpha`` [rad] (wrapped into [-pi, pi)).

    Returns
    -------
    dict
        ``{name: value}`` for every name in :data:`~laddermill_gym.model.params.AERO_COLUMNS`.
    """
    a = (alpha + np.pi) % (2.0 * np.pi) - np.pi
    values = _spline(table)(a)
    return {name: float(values[i]) for i, name in enumerate(AERO_COLUMNS)}


def wing_aero(
    wing_type: WingType,
    x_cg: np.ndarray,
    R: np.ndarray,
    v: np.ndarray,
    omega: np.ndarray,
    controls: np.ndarray,
    wind: WindParams,
    t: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
    """Quasi-steady aerodynamic load on one wing, split into the alpha-rate part and the rest.

    The full generalised aerodynamic force (body axes, force then moment about the CG) is
    ``(force, moment) + k * alpha'`` with ``alpha' = g . v' + adot0``.

    Parameters
    ----------
    wing_type : WingType
    x_cg : ndarray, shape (3,)
        Global CG position [m].
    R : ndarray, shape (3, 3)
        Rotation body -> global.
    v : ndarray, shape (3,)
        Body-frame CG velocity [m/s].
    omega : ndarray, shape (3,)
        Body-frame angular velocity (p, q, r) [rad/s].
    controls : ndarray, shape (3,)
        Elevator, rudder, aileron [rad].
    wind : WindParams
    t : float
        Time [s].

    Returns
    -------
    force_body : ndarray, shape (3,)
        Aerodynamic force without the alpha-rate term, body axes [N].
    moment_body : ndarray, shape (3,)
        Aerodynamic moment about the CG without the alpha-rate term, body axes [N m].
    k : ndarray, shape (6,)
        Generalised force per unit alpha' [N s, N m s].
    g : ndarray, shape (3,)
        d alpha / d v_a [s/m].
    adot0 : float
        Part of alpha' not proportional to v' [rad/s].
    """
    zero3 = np.zeros(3)
    wind_global = wind_velocity(wind, x_cg, t)
    v_air = v - R.T @ wind_global
    u_a, v_a, w_a = v_air
    V = float(np.linalg.norm(v_air))
    if V < AIRSPEED_EPS:
        return zero3, zero3.copy(), np.zeros(6), zero3.copy(), 0.0

    alpha = float(np.arctan2(w_a, u_a))
    beta = float(np.arcsin(np.clip(v_a / V, -1.0, 1.0)))
    h = -float(x_cg[2])
    qbar = 0.5 * air_density(wind, h) * V * V
    S, b, c = wing_type.area, wing_type.span, wing_type.chord
    p, q, r = omega
    phat = p * b / (2.0 * V)
    qhat = q * c / (2.0 * V)
    rhat = r * b / (2.0 * V)
    d_e, d_r, d_a = controls
    C = aero_coefficients(wing_type.aero, alpha)

    # Coefficients without the alpha-rate terms (adhat = 0).
    C_L = C["CL"] + C["CLq"] * qhat + C["CLde"] * d_e
    C_D = C["CD"]
    C_m = C["Cm"] + C["Cmq"] * qhat + C["Cmde"] * d_e
    C_Y = C["CYb"] * beta + C["CYp"] * phat + C["CYr"] * rhat + C["CYdr"] * d_r
    C_l = C["Clb"] * beta + C["Clp"] * phat + C["Clr"] * rhat + C["Clda"] * d_a + C["Cldr"] * d_r
    C_n = C["Cnb"] * beta + C["Cnp"] * phat + C["Cnr"] * rhat + C["Cnda"] * d_a + C["Cndr"] * d_r

    sa, ca = np.sin(alpha), np.cos(alpha)
    force = qbar * S * np.array([C_L * sa - C_D * ca, C_Y, -C_L * ca - C_D * sa])
    moment_ref = qbar * S * np.array([b * C_l, c * C_m, b * C_n])
    r_ref = np.asarray(wing_type.r_ref, dtype=float)
    moment_cg = moment_ref + np.cross(r_ref, force)

    # Alpha-rate pieces.
    lift_dir = np.array([sa, 0.0, -ca])
    k_force = C["CLad"] * lift_dir
    k_moment = np.cross(r_ref, k_force) + np.array([0.0, c * C["Cmad"], 0.0])
    k = qbar * S * c / (2.0 * V) * np.concatenate([k_force, k_moment])

    denom = u_a * u_a + w_a * w_a
    g = np.array([-w_a, 0.0, u_a]) / denom if denom > 0.0 else np.zeros(3)
    w_dot = wind_rate(wind, x_cg, R @ v, t)
    adot0 = float(g @ (np.cross(omega, R.T @ wind_global) - R.T @ w_dot))
    return force, moment_cg, k, g, adot0


def inertia_matrix(wing_type: WingType) -> np.ndarray:
    """Body-axes inertia tensor J = [[Jxx, 0, -Jxz], [0, Jyy, 0], [-Jxz, 0, Jzz]] [kg m^2]."""
    Jxx, Jyy, Jzz, Jxz = wing_type.inertia
    return np.array([[Jxx, 0.0, -Jxz], [0.0, Jyy, 0.0], [-Jxz, 0.0, Jzz]])


# --------------------------------------------------------------------------------------------------
# State access
# --------------------------------------------------------------------------------------------------


def _check_dim(asm: Assembly) -> None:
    if asm.dim != 3:
        raise ValueError(f"reference implementation supports only Assembly.dim == 3, got dim={asm.dim}")


def _wing_state(asm: Assembly, x: np.ndarray, k: int):
    """(position, q, v, omega) of wing ``k`` (views into the state)."""
    o = 13 * k
    return x[o : o + 3], x[o + 3 : o + 7], x[o + 7 : o + 10], x[o + 10 : o + 13]


def _node_state(asm: Assembly, x: np.ndarray, j: int):
    """(position, velocity) of free node ``j``."""
    o = 13 * asm.n_wings + 6 * j
    return x[o : o + 3], x[o + 3 : o + 6]


def _n_dof(asm: Assembly) -> int:
    return 6 * asm.n_wings + 3 * asm.n_nodes


def _wing_dof(k: int) -> int:
    return 6 * k


def _node_dof(asm: Assembly, j: int) -> int:
    return 6 * asm.n_wings + 3 * j


def _end_kinematics(asm: Assembly, e: int, end: int, x: np.ndarray):
    """Position, velocity and the quadratic acceleration term of one element end (global).

    Returns
    -------
    position, velocity, accel_quadratic : ndarray, shape (3,)
        ``accel_quadratic`` is ``R [w x (v + w x a)]`` for a wing end and 0 otherwise.
    """
    el = asm.elements
    kind = int(el.end_kind[e, end])
    idx = int(el.end_index[e, end])
    if kind == END_WING:
        pos, q, v, w = _wing_state(asm, x, idx)
        R = rotation(q)
        a = np.asarray(el.attach[e, end], dtype=float)
        position = pos + R @ a
        velocity = R @ (v + np.cross(w, a))
        accel_quadratic = R @ np.cross(w, v + np.cross(w, a))
        return position, velocity, accel_quadratic
    if kind == END_NODE:
        pos, vel = _node_state(asm, x, idx)
        return pos.copy(), vel.copy(), np.zeros(3)
    if kind == END_FIXED:
        return np.asarray(asm.fixed_points[idx], dtype=float).copy(), np.zeros(3), np.zeros(3)
    raise ValueError(f"elements.end_kind[{e}, {end}] = {kind} is not END_WING, END_NODE or END_FIXED")


def end_transformation(asm: Assembly, e: int, end: int, x: np.ndarray) -> np.ndarray:
    """Matrix ``T_end`` (3 x n_dof) mapping generalised velocities to the end's global velocity.

    A wing end has ``(R, -R a~)`` in the wing's (v, omega) columns, a node end the identity in the
    node's columns, a fixed end is all zeros.
    """
    el = asm.elements
    kind = int(el.end_kind[e, end])
    idx = int(el.end_index[e, end])
    T = np.zeros((3, _n_dof(asm)))
    if kind == END_WING:
        _, q, _, _ = _wing_state(asm, x, idx)
        R = rotation(q)
        a = np.asarray(el.attach[e, end], dtype=float)
        d = _wing_dof(idx)
        T[:, d : d + 3] = R
        T[:, d + 3 : d + 6] = -R @ skew(a)
    elif kind == END_NODE:
        d = _node_dof(asm, idx)
        T[:, d : d + 3] = np.eye(3)
    elif kind != END_FIXED:
        raise ValueError(f"elements.end_kind[{e}, {end}] = {kind} is not END_WING, END_NODE or END_FIXED")
    return T


# --------------------------------------------------------------------------------------------------
# Cable elements
# --------------------------------------------------------------------------------------------------


class ElementState(NamedTuple):
    """Kinematics of one cable element (global components).

    x_r, x_s : attachment points [m]; xd_r, xd_s : their velocities [m/s];
    l_vec : x_s - x_r [m]; length : |l_vec| [m]; e : unit vector (0 if length < 1e-9);
    eps : length - l0 [m]; eps_dot : e . (xd_s - xd_r) [m/s].
    """

    x_r: np.ndarray
    x_s: np.ndarray
    xd_r: np.ndarray
    xd_s: np.ndarray
    l_vec: np.ndarray
    length: float
    e: np.ndarray
    eps: float
    eps_dot: float


def element_state(asm: Assembly, e: int, x: np.ndarray) -> ElementState:
    """Attachment points, velocities, length, direction, elongation and its rate of element ``e``.

    Parameters
    ----------
    asm : Assembly
    e : int
        Element index.
    x : ndarray, shape (state_size,)
        State vector.

    Returns
    -------
    ElementState
    """
    x_r, xd_r, _ = _end_kinematics(asm, e, 0, x)
    x_s, xd_s, _ = _end_kinematics(asm, e, 1, x)
    l_vec = x_s - x_r
    length = float(np.linalg.norm(l_vec))
    unit = l_vec / length if length >= LENGTH_EPS else np.zeros(3)
    eps = length - float(asm.elements.l0[e])
    eps_dot = float(unit @ (xd_s - xd_r))
    return ElementState(x_r, x_s, xd_r, xd_s, l_vec, length, unit, eps, eps_dot)


def cable_aero_load(
    rho: float, diameter: float, cn0: float, ct0: float, u: np.ndarray, e: np.ndarray
) -> np.ndarray:
    """Aerodynamic load per unit length on a cable (M23)-(M24).

    ``f = rho d / 2 (C_N0 |u_n| u_n + C_T0 |u| u)`` with ``u_n = u - (u . e) e``.

    Parameters
    ----------
    rho : float
        Air density [kg/m^3].
    diameter : float
        Cable diameter [m].
    cn0, ct0 : float
        Normal and tangential force constants [-].
    u : ndarray, shape (3,)
        Air velocity relative to the cable (wind minus cable velocity) [m/s].
    e : ndarray, shape (3,)
        Unit tangent of the cable (or 0).

    Returns
    -------
    ndarray, shape (3,)
        Load per unit length [N/m], global.
    """
    u_n = u - (u @ e) * e
    return 0.5 * rho * diameter * (cn0 * np.linalg.norm(u_n) * u_n + ct0 * np.linalg.norm(u) * u)


def element_loads_per_length(
    asm: Assembly, e: int, x: np.ndarray, t: float, state: ElementState | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distributed loads per unit length at the two ends of element ``e``.

    Returns
    -------
    gravity : ndarray, shape (3,)
        ``mu g (0, 0, 1)`` [N/m] (same at both ends).
    f_aero_r, f_aero_s : ndarray, shape (3,)
        Aerodynamic load per length at end r and end s [N/m] (0 if ``asm.cable_aero`` is off); the air
        density is taken at each end's height and ``u`` is the wind there minus the end's velocity.
    """
    st = element_state(asm, e, x) if state is None else state
    el = asm.elements
    gravity = float(el.mu[e]) * asm.gravity * np.array([0.0, 0.0, 1.0])
    f_r = np.zeros(3)
    f_s = np.zeros(3)
    if asm.cable_aero:
        for end_pos, end_vel, out in ((st.x_r, st.xd_r, f_r), (st.x_s, st.xd_s, f_s)):
            u = wind_velocity(asm.wind, end_pos, t) - end_vel
            rho = air_density(asm.wind, -float(end_pos[2]))
            out[:] = cable_aero_load(rho, float(el.diameter[e]), asm.cable_cn0, asm.cable_ct0, u, st.e)
    return gravity, f_r, f_s


def sag_elongation(length: float, p_r: np.ndarray, p_s: np.ndarray) -> float:
    """eps_p of eq. (M18): ``l^3 ((|p_r|^2 + |p_s|^2)/90 + 7/360 p_r . p_s)`` [N^2 m].

    ``p_r``, ``p_s`` are the lateral loads per unit length at the ends [N/m].
    """
    return length**3 * ((p_r @ p_r + p_s @ p_s) / 90.0 + 7.0 / 360.0 * (p_r @ p_s))


def sag_tension(sigma0: float, EA: float, l0: float, eps_p: float, length: float) -> float:
    """Tension with the sag correction (M19)-(M22).

    Solves ``f(s) = s^3 - sigma0 s^2 - c = 0`` with ``c = EA eps_p / l0`` by Newton's method from
    ``max(sigma0, c^(1/3))``, stopping after the first step with ``|step| < 1e-13 |s_new|`` or after 60
    steps. If ``c <= 1e-300`` or ``length < 1e-9`` the result is ``max(sigma0, 0)``.

    Parameters
    ----------
    sigma0 : float
        ``(EA eps + DA eps') / l0`` [N].
    EA : float
        Axial stiffness [N].
    l0 : float
        Unstretched length [m].
    eps_p : float
        Sag term of eq. (M18) [N^2 m].
    length : float
        Current length l [m].

    Returns
    -------
    float
        Tension sigma [N].
    """
    c = EA * eps_p / l0
    if c <= 1e-300 or length < LENGTH_EPS:
        return max(sigma0, 0.0)
    s = max(sigma0, c ** (1.0 / 3.0))
    for _ in range(60):
        f = s**3 - sigma0 * s**2 - c
        df = 3.0 * s**2 - 2.0 * sigma0 * s
        step = f / df
        s = s - step
        if abs(step) < 1e-13 * abs(s):
            break
    return s


def tension(asm: Assembly, e: int, x: np.ndarray, t: float) -> float:
    """Tension sigma [N] of element ``e`` (with or without the sag correction per ``asm.sag``).

    Parameters
    ----------
    asm : Assembly
    e : int
        Element index.
    x : ndarray, shape (state_size,)
        State.
    t : float
        Time [s] (the wind, hence the cable aerodynamic load, depends on it).
    """
    el = asm.elements
    st = element_state(asm, e, x)
    l0 = float(el.l0[e])
    EA = float(el.EA[e])
    sigma0 = (EA * st.eps + float(el.DA[e]) * st.eps_dot) / l0
    if not asm.sag:
        return max(sigma0, 0.0) if st.eps > 0.0 else 0.0
    gravity, f_r, f_s = element_loads_per_length(asm, e, x, t, st)
    load_r = gravity + f_r
    load_s = gravity + f_s
    p_r = load_r - (load_r @ st.e) * st.e
    p_s = load_s - (load_s @ st.e) * st.e
    eps_p = sag_elongation(st.length, p_r, p_s)
    return sag_tension(sigma0, EA, l0, eps_p, st.length)


def element_tensions(asm: Assembly, t: float, x: np.ndarray) -> np.ndarray:
    """Tensions of all elements, shape (n_e,) [N]."""
    _check_dim(asm)
    return np.array([tension(asm, e, x, t) for e in range(asm.elements.count)], dtype=float)


# --------------------------------------------------------------------------------------------------
# Assembly of M and F
# --------------------------------------------------------------------------------------------------


def mass_matrix_and_forces(asm: Assembly, t: float, x: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Dense global mass matrix and generalised force vector of eq. (M25).

    Parameters
    ----------
    asm : Assembly
        Must have ``dim == 3``.
    t : float
        Time [s].
    x : ndarray, shape (state_size,)
        State.
    u : ndarray, shape (3 n_w,)
        Controls, (elevator, rudder, aileron) per wing [rad].

    Returns
    -------
    M : ndarray, shape (n_dof, n_dof)
        Mass matrix including the alpha-rate apparent mass ``-k g^T`` (not symmetric then).
    F : ndarray, shape (n_dof,)
        Everything on the right side: gravity, gyroscopic and quadratic velocity terms, aerodynamics
        (with ``k adot0``), cable loads and tensions.
    """
    _check_dim(asm)
    x = np.asarray(x, dtype=float)
    u = np.asarray(u, dtype=float)
    if x.shape != (asm.state_size,):
        raise ValueError(f"state x must have shape ({asm.state_size},), got {x.shape}")
    if u.shape != (N_CONTROLS * asm.n_wings,):
        raise ValueError(f"controls u must have shape ({N_CONTROLS * asm.n_wings},), got {u.shape}")
    n = _n_dof(asm)
    M = np.zeros((n, n))
    F = np.zeros(n)
    gravity_global = np.array([0.0, 0.0, asm.gravity])

    # Wings: rigid-body mass, gravity, gyroscopic terms, aerodynamics (M4).
    for k in range(asm.n_wings):
        wt = asm.wing(k)
        pos, q, v, w = _wing_state(asm, x, k)
        R = rotation(q)
        J = inertia_matrix(wt)
        d = _wing_dof(k)
        M[d : d + 3, d : d + 3] += wt.mass * np.eye(3)
        M[d + 3 : d + 6, d + 3 : d + 6] += J
        F[d : d + 3] += R.T @ (wt.mass * gravity_global)
        F[d : d + 3] += -wt.mass * np.cross(w, v)
        F[d + 3 : d + 6] += -np.cross(w, J @ w)
        controls = u[N_CONTROLS * k : N_CONTROLS * (k + 1)]
        force, moment, kvec, gvec, adot0 = wing_aero(wt, pos, R, v, w, controls, asm.wind, t)
        F[d : d + 3] += force
        F[d + 3 : d + 6] += moment
        F[d : d + 6] += kvec * adot0
        M[d : d + 6, d : d + 3] -= np.outer(kvec, gvec)

    # Nodes: lumped mass and its weight.
    for j in range(asm.n_nodes):
        d = _node_dof(asm, j)
        m_node = float(asm.node_mass[j])
        M[d : d + 3, d : d + 3] += m_node * np.eye(3)
        F[d : d + 3] += m_node * gravity_global

    # Cable elements (M7)-(M25).
    el = asm.elements
    for e in range(el.count):
        st = element_state(asm, e, x)
        T_r = end_transformation(asm, e, 0, x)
        T_s = end_transformation(asm, e, 1, x)
        T = np.vstack([T_r, T_s])  # 6 x n_dof
        m_e = float(el.mu[e]) * float(el.l0[e])
        M0e = m_e / 6.0 * np.block([[2 * np.eye(3), np.eye(3)], [np.eye(3), 2 * np.eye(3)]])
        M += T.T @ M0e @ T

        # Quadratic velocity terms (M15).
        _, _, c_r = _end_kinematics(asm, e, 0, x)
        _, _, c_s = _end_kinematics(asm, e, 1, x)
        F += -T.T @ M0e @ np.concatenate([c_r, c_s])

        # Distributed loads as nodal forces.
        _, f_r, f_s = element_loads_per_length(asm, e, x, t, st)
        weight_half = 0.5 * m_e * gravity_global
        F_r = weight_half + st.length * (2.0 * f_r + f_s) / 6.0
        F_s = weight_half + st.length * (f_r + 2.0 * f_s) / 6.0
        F += T_r.T @ F_r + T_s.T @ F_s

        # Tension: -D^T sigma.
        sigma = tension(asm, e, x, t)
        F += sigma * (T_r.T @ st.e) - sigma * (T_s.T @ st.e)
    return M, F


def reference_rhs(t: float, x: np.ndarray, u: np.ndarray, asm: Assembly) -> np.ndarray:
    """State derivative dx/dt of the 3D model.

    Parameters
    ----------
    t : float
        Time [s].
    x : ndarray, shape (state_size,)
        State: per wing [x(3), q(4), v(3), omega(3)], then per node [position(3), velocity(3)].
    u : ndarray, shape (3 n_w,)
        Controls (elevator, rudder, aileron) per wing [rad].
    asm : Assembly
        Must have ``dim == 3``.

    Returns
    -------
    ndarray, shape (state_size,)
        Same layout as ``x``: per wing [R v, 1/2 q (x) (0, omega), v', omega'], per node [velocity, acceleration].
        ``q`` is the stored (unnormalised) quaternion in the kinematic equation; ``R`` uses the normalised one.
    """
    _check_dim(asm)
    x = np.asarray(x, dtype=float)
    M, F = mass_matrix_and_forces(asm, t, x, u)
    accel = np.linalg.solve(M, F)
    dx = np.zeros_like(x)
    for k in range(asm.n_wings):
        _, q, v, w = _wing_state(asm, x, k)
        o = 13 * k
        d = _wing_dof(k)
        dx[o : o + 3] = rotation(q) @ v
        dx[o + 3 : o + 7] = 0.5 * quaternion_product(q, np.concatenate([[0.0], w]))
        dx[o + 7 : o + 13] = accel[d : d + 6]
    for j in range(asm.n_nodes):
        _, vel = _node_state(asm, x, j)
        o = 13 * asm.n_wings + 6 * j
        d = _node_dof(asm, j)
        dx[o : o + 3] = vel
        dx[o + 3 : o + 6] = accel[d : d + 3]
    return dx
