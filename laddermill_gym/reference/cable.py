"""Cable elements of the reference model: element kinematics, distributed loads (weight and aerodynamics,
(M23)-(M24)), the sag correction (M18)-(M22) and the tension.

The air density for a cable load is evaluated at the height of that end's attachment point.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from laddermill_gym.model.params import Assembly
from laddermill_gym.reference.state import check_dim, end_kinematics
from laddermill_gym.reference.wind import air_density, wind_velocity

#: Element length below which the element direction is taken as 0 [m].
LENGTH_EPS = 1e-9

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
    x_r, xd_r, _ = end_kinematics(asm, e, 0, x)
    x_s, xd_s, _ = end_kinematics(asm, e, 1, x)
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
    check_dim(asm)
    return np.array([tension(asm, e, x, t) for e in range(asm.elements.count)], dtype=float)
