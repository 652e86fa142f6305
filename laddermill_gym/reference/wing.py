"""Wing aerodynamics of the reference model: the periodic spline of the aerodynamic table, the quasi-steady load
on one wing (split into the alpha-rate part and the rest) and the inertia tensor.

``g = (-w_a, 0, u_a) / (u_a^2 + w_a^2)`` is set to 0 when ``u_a^2 + w_a^2 == 0`` (pure sideslip); controls are
used as given (no clipping to ``control_limits``).
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np
from scipy.interpolate import CubicSpline

from laddermill_gym.model.params import AERO_COLUMNS, AeroTable, WindParams, WingType
from laddermill_gym.reference.wind import air_density, wind_rate, wind_velocity

#: Airspeed below which a wing gets no aerodynamic load [m/s].
AIRSPEED_EPS = 1e-9

_SPLINES: OrderedDict[int, tuple[AeroTable, CubicSpline]] = OrderedDict()
_KEPT = 16  # the tables used last (each entry keeps its table, so an id is not reused while it is here)


def _spline(table: AeroTable) -> CubicSpline:
    """Periodic cubic spline of all table columns (cached per table object, the 16 used last)."""
    entry = _SPLINES.get(id(table))
    if entry is None or entry[0] is not table:
        spline = CubicSpline(table.alpha, table.values, bc_type="periodic", axis=0)
        entry = (table, spline)
        _SPLINES[id(table)] = entry
    _SPLINES.move_to_end(id(table))
    while len(_SPLINES) > _KEPT:
        _SPLINES.popitem(last=False)
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
    C = aero_coefficients(wing_type.aero, alpha)
    force, moment_cg = _load_without_alpha_rate(wing_type, C, alpha, beta, V, qbar, omega, controls)
    k = _load_per_alpha_rate(wing_type, C, alpha, V, qbar)

    denom = u_a * u_a + w_a * w_a
    g = np.array([-w_a, 0.0, u_a]) / denom if denom > 0.0 else np.zeros(3)
    w_dot = wind_rate(wind, x_cg, R @ v, t)
    adot0 = float(g @ (np.cross(omega, R.T @ wind_global) - R.T @ w_dot))
    return force, moment_cg, k, g, adot0


def _load_without_alpha_rate(wing_type: WingType, C: dict[str, float], alpha: float, beta: float, V: float,
                             qbar: float, omega: np.ndarray, controls: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Aerodynamic force [N] and moment about the CG [N m], body axes, with the coefficients taken without
    their alpha-rate terms (adhat = 0); ``C`` holds the table columns at ``alpha``."""
    S, b, c = wing_type.area, wing_type.span, wing_type.chord
    p, q, r = omega
    phat = p * b / (2.0 * V)
    qhat = q * c / (2.0 * V)
    rhat = r * b / (2.0 * V)
    d_e, d_r, d_a = controls

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
    return force, moment_ref + np.cross(r_ref, force)


def _load_per_alpha_rate(wing_type: WingType, C: dict[str, float], alpha: float, V: float,
                         qbar: float) -> np.ndarray:
    """Generalised force (force, moment about the CG) per unit alpha' [N s, N m s] of the CLad and Cmad terms."""
    S, c = wing_type.area, wing_type.chord
    sa, ca = np.sin(alpha), np.cos(alpha)
    r_ref = np.asarray(wing_type.r_ref, dtype=float)
    lift_dir = np.array([sa, 0.0, -ca])
    k_force = C["CLad"] * lift_dir
    k_moment = np.cross(r_ref, k_force) + np.array([0.0, c * C["Cmad"], 0.0])
    return qbar * S * c / (2.0 * V) * np.concatenate([k_force, k_moment])


def inertia_matrix(wing_type: WingType) -> np.ndarray:
    """Body-axes inertia tensor J = [[Jxx, 0, -Jxz], [0, Jyy, 0], [-Jxz, 0, Jzz]] [kg m^2]."""
    Jxx, Jyy, Jzz, Jxz = wing_type.inertia
    return np.array([[Jxx, 0.0, -Jxz], [0.0, Jyy, 0.0], [-Jxz, 0.0, Jzz]])
