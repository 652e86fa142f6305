"""Rotor coefficients at an operating point (advance ratio, incidence, collective): the Glauert inflow, the
thrust, H-force, torque, flapping and power coefficients, and Roberts' eqs. 2-4 (incidence, cable angle,
power coefficient) over the numba kernels of ``rotor_kernels``."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.rotorcraft import rotor_kernels as _k
from laddermill_gym.rotorcraft.rotor_params import (
    INFLOW_MAX_ITER,
    INFLOW_TOL,
    RotorParams,
    check_alpha,
    check_mu,
    check_number,
    check_params,
    check_theta,
)


# ------------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class InflowSolution:
    """Glauert inflow consistent with C_T (rotorcraft.rotor_kernels.solve_inflow).

    Attributes: lam (inflow ratio, > 0 up through the disk) [-], nu (induced-velocity ratio) [-], ct [-],
    iterations (residual evaluations), status (rotorcraft.rotor_kernels.STATUS_*), converged (status == STATUS_OK).
    """

    lam: float
    nu: float
    ct: float
    iterations: int
    status: int

    @property
    def converged(self) -> bool:
        return self.status == _k.STATUS_OK


@dataclass(frozen=True)
class RotorState:
    """Rotor at (mu, alpha_c, theta0) with its consistent inflow (rotorcraft.rotor_kernels.rotor_state).

    Attributes
    ----------
    mu, alpha_c, theta0 : float
        Advance ratio [-], craft incidence [rad], collective pitch [rad] (the inputs).
    lam, nu : float
        Inflow ratio (up through the disk > 0) and induced-velocity ratio [-].
    ct, ch, cq : float
        Thrust, H-force and torque coefficients [-] (C_Q < 0: power generated).
    a0, a1, b1 : float
        Coning, longitudinal and lateral flapping [rad].
    tip_aoa : float
        Angle of attack of the retreating blade tip (x = 1, psi = 270 deg) [rad].
    cp : float
        Windmill power coefficient P / (rho pi R^2 V^3 / 2) [-] (Roberts eq. 4).
    iterations, status : int
        Inflow-solver evaluations and status; every coefficient is nan unless ``converged``.
    """

    mu: float
    alpha_c: float
    theta0: float
    lam: float
    nu: float
    ct: float
    ch: float
    cq: float
    a0: float
    a1: float
    b1: float
    tip_aoa: float
    cp: float
    iterations: int
    status: int

    @property
    def converged(self) -> bool:
        return self.status == _k.STATUS_OK


def state_from_kernel(p: np.ndarray, mu: float, alpha_c: float, theta0: float, out: np.ndarray) -> RotorState:
    _k.rotor_state(p, mu, alpha_c, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
    v = [float(x) for x in out]
    return RotorState(mu=mu, alpha_c=alpha_c, theta0=theta0, lam=v[_k.O_LAMBDA], nu=v[_k.O_NU], ct=v[_k.O_CT],
                      ch=v[_k.O_CH], cq=v[_k.O_CQ], a0=v[_k.O_A0], a1=v[_k.O_A1], b1=v[_k.O_B1],
                      tip_aoa=v[_k.O_TIP_AOA], cp=v[_k.O_CP], iterations=int(v[_k.O_ITER]),
                      status=int(v[_k.O_STATUS]))


# ------------------------------------------------------------------------------------------- public API
def solve_inflow(params: RotorParams, mu: float, alpha_c: float, theta0: float) -> InflowSolution:
    """Inflow ratio lam = mu tan(alpha_c) - nu with Glauert's nu = C_T / (2 sqrt(mu^2 + lam^2)).

    Parameters
    ----------
    params : RotorParams
    mu : float
        Advance ratio V cos(alpha_c) / (Omega R) [-], in (0, 1).
    alpha_c : float
        Craft (disk) incidence to the wind [rad], in (-pi/2, pi/2).
    theta0 : float
        Collective pitch [rad].
    """
    p = check_params(params).packed()
    mu, alpha_c, theta0 = check_mu(mu), check_alpha(alpha_c), check_theta(theta0)
    out = np.empty(_k.N_OUT)
    _k.solve_inflow(p, mu, mu * math.tan(alpha_c), theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
    return InflowSolution(lam=float(out[_k.O_LAMBDA]), nu=float(out[_k.O_NU]), ct=float(out[_k.O_CT]),
                          iterations=int(out[_k.O_ITER]), status=int(out[_k.O_STATUS]))


def rotor_coefficients(params: RotorParams, mu: float, alpha_c: float, theta0: float) -> RotorState:
    """All rotor coefficients at advance ratio mu [-], incidence alpha_c [rad] and collective theta0 [rad].

    See :class:`RotorState`. Check ``converged`` before using the numbers.
    """
    p = check_params(params).packed()
    mu, alpha_c, theta0 = check_mu(mu), check_alpha(alpha_c), check_theta(theta0)
    return state_from_kernel(p, mu, alpha_c, theta0, np.empty(_k.N_OUT))


def power_coefficient(cq: float, mu: float, alpha_c: float) -> float:
    """Roberts eq. 4 from the torque coefficient: C_p = -2 C_Q (cos(alpha_c)/mu)^3 [-]."""
    return _k.power_coefficient(check_number("cq", cq), check_mu(mu), check_alpha(alpha_c))


def craft_incidence(mu: float, lam: float, ct: float) -> float:
    """Roberts eq. 2: alpha_c = atan(lam/mu + C_T / (2 mu sqrt(mu^2 + lam^2))) [rad]."""
    return _k.craft_incidence(check_mu(mu), check_number("lam", lam), check_number("ct", ct))


def cable_angle(thrust: float, h_force: float, weight: float, alpha_c: float, n_rotors: int = 2) -> float:
    """Roberts eq. 3: equilibrium angle [rad] of the (massless) cables above the horizontal.

    Parameters
    ----------
    thrust, h_force : float
        Thrust and H-force of ONE rotor [N].
    weight : float
        Craft weight m g [N], > 0.
    alpha_c : float
        Craft incidence [rad].
    n_rotors : int
        Number of rotors (2 for Roberts' craft, whose eq. 3 reads 2T/mg and 2H/mg).
    """
    weight = check_number("weight", weight, 0.0, lo_open=True)
    if isinstance(n_rotors, bool) or not isinstance(n_rotors, (int, np.integer)) or n_rotors < 1:
        raise ValueError(f"argument 'n_rotors' = {n_rotors!r}: must be an integer >= 1")
    t = check_number("thrust", thrust) * n_rotors / weight
    h = check_number("h_force", h_force) * n_rotors / weight
    return _k.cable_angle(t, h, check_alpha(alpha_c))


def ideal_power_coefficient(alpha_c):
    """Ideal power coefficient [-] at incidence alpha_c [rad] (scalar or array; any shape).

    Actuator disk with Glauert inflow and no profile drag, best induced velocity: 16/27 at alpha_c = pi/2,
    0 at alpha_c = 0 (rotorcraft.rotor_kernels.ideal_power_coefficient).
    """
    arr = np.asarray(alpha_c, dtype=float)
    if not np.all(np.isfinite(arr)) or np.any(np.abs(arr) > 0.5 * math.pi + 1e-12):
        raise ValueError(f"argument 'alpha_c' = {alpha_c!r}: must be finite and within [-pi/2, pi/2]")
    flat = arr.ravel()
    res = np.array([_k.ideal_power_coefficient(float(x)) for x in flat]).reshape(arr.shape)
    return float(res) if res.ndim == 0 else res
