"""Lansdorp, Ruiterkamp, Williams & Ockels (2008), "Long-term laddermill modeling for site selection", eqs. 1-15:
the quasi-steady power of a pumping kite, vectorised over wind states.

Every function takes numpy arrays that broadcast together (shape ``(n,)`` for n wind states, or scalars) in SI
units, angles in radians. The cable angle ``theta`` is measured from the vertical, as in the paper; the kite
flies straight down-wind of the ground station at altitude ``h`` on a straight cable of length
``L = h / cos(theta)``.

The cable angle enters as the paper says (after eq. 9): the horizontal wind ``w`` is rotated into the kite frame,
so only its component along the cable, ``w sin(theta)``, drives the kite, and reeling out at ``v_out`` lowers it
further: the effective wind of eqs. 1, 8 and 9 is ``w_e = w sin(theta) - v_out``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np


@dataclass(frozen=True)
class PumpingParams:
    """Fixed parameters of the pumping system (SI units). Defaults: Lansdorp et al. (2008), section V."""

    rho: float = 1.225                 # [kg/m^3] air density
    eta: float = 0.92                  # [-] mechanical efficiency, eq. 13
    cable_cd: float = 1.2              # [-] cable drag coefficient C_Dc, eq. 5
    sigma_ut: float = 1.6e9            # [Pa] cable ultimate strength, eq. 15
    safety_factor: float = 2.5         # [-] F_s, eq. 15
    reel_length: float = 200.0         # [m] Delta L, cable reeled per cycle, eq. 12
    reel_in_speed: float = 16.7        # [m/s] reel-in speed L_r dot, eq. 11
    reel_in_tension_ratio: float = 1.0 / 50.0  # [-] T_r / T: "1/50 of the tension during power generation"
    min_length_ratio: float = 2.5      # [-] gamma of eq. 18 (40 % of the cable reeled at most)
    cable_density: float = 970.0       # [kg/m^3] Dyneema SK75 fibre density (DSM fact sheet); cable mass, eq. 20

    def __post_init__(self):
        for name in ("rho", "eta", "sigma_ut", "safety_factor", "reel_length", "min_length_ratio",
                     "cable_density"):
            v = getattr(self, name)
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"PumpingParams.{name} = {v!r}: must be a finite number > 0")
        for name in ("cable_cd", "reel_in_speed", "reel_in_tension_ratio"):
            v = getattr(self, name)
            if not v >= 0:
                raise ValueError(f"PumpingParams.{name} = {v!r}: must be >= 0")
        if self.eta > 1:
            raise ValueError(f"PumpingParams.eta = {self.eta!r}: an efficiency must be <= 1")


class CycleResult(NamedTuple):
    """One pumping cycle per wind state (arrays of shape (n,)): the common output of the quasi-steady models."""

    tension_out: np.ndarray    # [N] cable tension while reeling out (eq. 9)
    tension_in: np.ndarray     # [N] cable tension while reeling in
    speed_out: np.ndarray      # [m/s] reel-out speed
    power_out: np.ndarray      # [W] mechanical power while reeling out (eq. 10)
    power_in: np.ndarray       # [W] mechanical power spent reeling in (eq. 11)
    time_cycle: np.ndarray     # [s] cycle time (eq. 12, plus any transition time)
    energy: np.ndarray         # [J] net energy per cycle after the efficiency (eq. 13)
    power: np.ndarray          # [W] useful mean power of the cycle (eq. 14)
    kite_speed: np.ndarray     # [m/s] kite speed across the wind during reel-out (eq. 8)


def cable_length(h, theta):
    """Straight cable from the ground to altitude ``h`` [m] at ``theta`` [rad] from the vertical: L [m]."""
    return np.asarray(h, dtype=float) / np.cos(theta)


def cable_drag_share(d, L, S, cable_cd):
    """Cable drag lumped at the kite as a kite drag coefficient [-]: the 1/4 rule of eq. 6 divided by
    (1/2 rho S |w_e|^2): ``d L C_Dc / (4 S)``."""
    return np.asarray(d, dtype=float) * L * cable_cd / (4.0 * np.asarray(S, dtype=float))


def glide_ratio(cl, cd, d, L, S, cable_cd):
    """System glide ratio G [-] of kite and cable, eq. 7."""
    return np.asarray(cl, dtype=float) / (cd + cable_drag_share(d, L, S, cable_cd))


def effective_wind(w, theta, v_out):
    """Effective wind [m/s] driving the kite, eq. 1 in the kite frame: the wind component along the cable,
    ``w sin(theta)``, less the reel-out speed; never below zero (the kite cannot be driven by a wind it outruns)."""
    return np.maximum(np.asarray(w, dtype=float) * np.sin(theta) - v_out, 0.0)


def kite_speed(G, w_e):
    """Kite speed across the wind [m/s], eq. 8."""
    return G * w_e


def tension(rho, cl, S, G, w_e):
    """Cable tension [N] at constant cable speed, eq. 9: ``T = 1/2 rho C_L S G^2 (1 + 1/G^2)^(3/2) |w_e|^2``
    (G > 0; ``tension_from_coefficients`` is the same for any C_L >= 0)."""
    G = np.asarray(G, dtype=float)
    return 0.5 * rho * np.asarray(cl, dtype=float) * S * G * G * (1.0 + 1.0 / (G * G)) ** 1.5 * \
        np.asarray(w_e, dtype=float) ** 2


def tension_from_coefficients(rho, cl, cd_total, S, w_e):
    """Eq. 9 written with the system drag coefficient ``cd_total = C_D + d L C_Dc / (4 S)`` (= C_L / G):
    ``T = 1/2 rho S (C_L^2 + C_Dt^2)^(3/2) / C_Dt^2 |w_e|^2`` [N], finite at C_L = 0 (drag alone)."""
    cl = np.asarray(cl, dtype=float)
    return 0.5 * rho * S * (cl * cl + cd_total * cd_total) ** 1.5 / (cd_total * cd_total) * \
        np.asarray(w_e, dtype=float) ** 2


def max_cable_force(d, params: PumpingParams):
    """Largest allowed cable tension [N], eq. 15."""
    return params.sigma_ut / params.safety_factor * np.pi * np.asarray(d, dtype=float) ** 2 / 4.0


def speed_per_tension(v_out, params: PumpingParams, time_extra=0.0):
    """Useful cycle power per unit reel-out tension [W/N = m/s] when the reel-in tension is the fixed fraction
    ``params.reel_in_tension_ratio`` of it (eqs. 10-14 divided by T): P_useful = T * k(v_out). ``time_extra`` [s]
    is added to the cycle time (transitions); ``v_out = 0`` gives 0."""
    v_out = np.asarray(v_out, dtype=float)
    dl, v_in, r, eta = params.reel_length, params.reel_in_speed, params.reel_in_tension_ratio, params.eta
    with np.errstate(divide="ignore", invalid="ignore"):
        t_out = np.where(v_out > 0, dl / np.where(v_out > 0, v_out, 1.0), np.inf)
        t_in = dl / v_in if v_in > 0 else np.inf
        energy = eta * dl - r * dl / eta          # per newton of reel-out tension: eq. 13 / T
        k = np.where(np.isfinite(t_out) & np.isfinite(t_in), energy / (t_out + t_in + time_extra), 0.0)
    return k


def cycle(tension_out, v_out, params: PumpingParams, tension_in=None, time_extra=0.0):
    """Eqs. 10-14 for given reel-out tension [N] and speed [m/s]. ``tension_in`` [N] defaults to the paper's
    fraction of the reel-out tension. A reel-in speed of 0 never completes the cycle (power 0); ``inf`` makes
    reel-in instantaneous (the energy it costs, T_r Delta L / eta, stays). ``time_extra`` [s] (scalar or
    per state) is added to the cycle time (the transitions of the Schmehl model)."""
    T = np.asarray(tension_out, dtype=float)
    v_out = np.broadcast_to(np.asarray(v_out, dtype=float), T.shape)
    T_in = T * params.reel_in_tension_ratio if tension_in is None else np.asarray(tension_in, dtype=float)
    dl, v_in, eta = params.reel_length, params.reel_in_speed, params.eta
    p_out = T * v_out                                   # eq. 10
    p_in = T_in * v_in if np.isfinite(v_in) else np.full_like(T, np.inf)  # eq. 11
    with np.errstate(divide="ignore", invalid="ignore"):
        t_out = np.where(v_out > 0, dl / np.where(v_out > 0, v_out, 1.0), np.inf)
        t_in = dl / v_in if v_in > 0 else np.inf
        t_c = t_out + t_in + time_extra                 # eq. 12
        e_in = T_in * dl / eta                          # P_r / eta * Delta L / L_r dot, finite for any v_in > 0
        energy = eta * T * dl - e_in                    # eq. 13 (eta P Delta L / L dot = eta T Delta L)
        power = np.where(np.isfinite(t_c), energy / t_c, 0.0)  # eq. 14
    energy = np.where(np.isfinite(t_c), energy, 0.0)
    return p_out, p_in, t_c, energy, power


def cycle_power(w, h, theta, d, S, cl, cd, params: PumpingParams | None = None, reel_out_factor=1.0 / 3.0,
                reel_out_rule: str = "wind") -> CycleResult:
    """Lansdorp's quasi-steady pumping cycle for wind speeds ``w`` [m/s] (shape (n,)) at the kite altitude.

    Parameters
    ----------
    w : wind speed at altitude ``h`` [m/s], shape (n,)
    h, theta : kite altitude [m] and cable angle from the vertical [rad]
    d, S : cable diameter [m] and kite area [m^2]
    cl, cd : kite lift and drag coefficients [-], scalars or shape (n,)
    reel_out_factor : reel-out speed as a fraction of the wind speed [-] (the paper fixes 1/3)
    reel_out_rule : ``"wind"``: v_out = f w (the paper: "1/3 of the wind speed"); ``"radial"``: v_out =
        f w sin(theta) (a fraction of the wind along the cable; 1/3 of it is Loyd's optimum)

    Returns
    -------
    CycleResult with arrays of shape (n,). The tension is not capped here: the site optimisation keeps it
    below eq. 15 by choosing C_L (``site_problem``).
    """
    if reel_out_rule not in ("wind", "radial"):
        raise ValueError(f"reel_out_rule = {reel_out_rule!r}: must be 'wind' or 'radial'")
    params = PumpingParams() if params is None else params
    w = np.asarray(w, dtype=float)
    L = cable_length(h, theta)
    cd_total = cd + cable_drag_share(d, L, S, params.cable_cd)
    G = np.asarray(cl, dtype=float) / cd_total
    v_out = reel_out_factor * w * (np.sin(theta) if reel_out_rule == "radial" else 1.0)
    w_e = effective_wind(w, theta, v_out)
    T = np.broadcast_to(tension_from_coefficients(params.rho, cl, cd_total, S, w_e), w.shape)
    p_out, p_in, t_c, energy, power = cycle(T, v_out, params)
    T_in = T * params.reel_in_tension_ratio
    return CycleResult(T, T_in, np.broadcast_to(v_out, w.shape), p_out, p_in, np.broadcast_to(t_c, w.shape),
                       energy, power, np.broadcast_to(kite_speed(G, w_e), w.shape))
