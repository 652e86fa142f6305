"""The quasi-steady pumping model of Schmehl, Noom & van der Vlugt (2013, "Traction power generation with tethered
wings", in Airborne Wind Energy, Springer, ch. 2) and van der Vlugt, Bley, Noom & Schmehl (2019, "Quasi-steady
model of a pumping kite power system", Renewable Energy 131), written here from their equations, with the same
interface as ``lansdorp.cycle_power`` so the two can be compared wind state by wind state.

What it adds to Lansdorp's model: the kite's position on the wind window (elevation beta, azimuth phi) and its
flight direction (course angle chi), the kinematic ratio kappa = v_a,tau / v_a,r (= the glide ratio only for a
massless kite), gravity of the kite and of the lumped tether mass, and three phases: traction (reel-out at
``f = v_out / v_w``), retraction (reel-in at a fixed elevation, the kite depowered to the C_L that holds it there),
and the transition between their elevations at constant tether length (time, no energy).

Frame (our derivation): wind along x, z up; e_r along the tether, e_beta towards higher elevation, e_phi = e_z x
e_r / |.|; the course chi is measured from e_beta (chi = 90 deg: flying horizontally across the wind).
Tangential kinematics (Schmehl et al. 2013 eq. 2.42): lambda = v_k,tau / v_w = a + sqrt(a^2 + b^2 - 1 +
kappa^2 (b - f)^2), a = -sin(beta) cos(phi) cos(chi) - sin(phi) sin(chi), b = cos(beta) cos(phi); apparent wind
v_a = v_w (b - f) sqrt(1 + kappa^2).
Tangential force balance along the course with the weight m g (our derivation of the same balance):
(E - kappa) sqrt(1 + kappa^2) = m g cos(beta) cos(chi) / (1/2 rho S C_D v_w^2 (b - f)^2); kappa = E when m = 0.
The weight's component across the course is taken by rolling the lift (its magnitude change neglected, as in the
references). Tether force F_t = D (E kappa + 1) / sqrt(1 + kappa^2) - m g sin(beta).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laddermill_gym.quasisteady.lansdorp import CycleResult, PumpingParams, cable_drag_share, cable_length, cycle

GRAVITY = 9.81  # [m/s^2]


@dataclass(frozen=True)
class SchmehlParams:
    """Choices of the Schmehl / van der Vlugt model that Lansdorp's model does not have (SI units, radians)."""

    #: [kg/m^2] our assumption: the order of a leading-edge-inflatable kite with its control unit
    kite_mass_per_area: float = 0.6
    #: [-] share of the tether mass lumped at the kite (half: a straight tether hinged at the ground)
    tether_mass_share: float = 0.5
    azimuth: float = 0.0                # [rad] phi of the traction pattern's centre
    n_course: int = 8                   # [-] course angles chi of the loop (even in chi), time-weighted
    #: [rad] elevation during reel-in (our choice; the transition raises the kite from beta_out to it)
    retraction_elevation: float = np.radians(60.0)
    cl_max: float = 1.2                 # [-] largest C_L while reeling in (Lansdorp et al. 2008, section V)
    #: [-] polar C_D = cd0 + cd2 C_L^2 of the depowered kite (Lansdorp et al. 2008, the polar of Table 2)
    cd0: float = 0.03
    cd2: float = 0.04                   # [-]

    def __post_init__(self):
        if self.n_course < 1 or self.kite_mass_per_area < 0 or not 0 <= self.tether_mass_share <= 1:
            raise ValueError(f"SchmehlParams: invalid {self!r}")


def _solve_kappa(E, R):
    """kappa >= the local maximum of (E - k) sqrt(1 + k^2) with (E - k) sqrt(1 + k^2) = R (vectorised bisection).
    NaN where the weight is too large for the kite to fly that course (R above the maximum)."""
    E, R = np.broadcast_arrays(np.asarray(E, dtype=float), np.asarray(R, dtype=float))
    disc = E * E - 8.0
    k_lo = np.where(disc > 0, (E + np.sqrt(np.maximum(disc, 0.0))) / 4.0, 0.0)
    g_lo = (E - k_lo) * np.sqrt(1.0 + k_lo * k_lo)
    k_hi = E + np.sqrt(np.abs(R)) + 1.0
    lo, hi = k_lo.copy(), k_hi.copy()
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        above = (E - mid) * np.sqrt(1.0 + mid * mid) > R
        lo = np.where(above, mid, lo)
        hi = np.where(above, hi, mid)
    return np.where(R <= g_lo, 0.5 * (lo + hi), np.nan)


def traction(w, beta, f, S, cl, cd_total, mass, rho, azimuth, chi):
    """Traction phase at one course angle: (tether force [N], tangential speed ratio lambda [-]), arrays (n,).
    Both are NaN where the kite cannot fly that course: the weight exceeds what the apparent wind can carry, the
    tether would go slack (force <= 0) or the kite would not move along it (lambda <= 0)."""
    E = cl / cd_total
    b = np.cos(beta) * np.cos(azimuth)
    a = -np.sin(beta) * np.cos(azimuth) * np.cos(chi) - np.sin(azimuth) * np.sin(chi)
    q_r = 0.5 * rho * (w * np.maximum(b - f, 0.0)) ** 2          # dynamic pressure of the radial apparent wind
    with np.errstate(divide="ignore", invalid="ignore"):
        R = mass * GRAVITY * np.cos(beta) * np.cos(chi) / (q_r * S * cd_total)
    kappa = _solve_kappa(E, np.where(q_r > 0, R, np.inf))
    drag = q_r * (1.0 + kappa * kappa) * S * cd_total
    force = drag * (E * kappa + 1.0) / np.sqrt(1.0 + kappa * kappa) - mass * GRAVITY * np.sin(beta)
    lam = a + np.sqrt(np.maximum(a * a + b * b - 1.0 + kappa * kappa * (b - f) ** 2, 0.0))
    ok = np.isfinite(kappa) & (force > 0) & (lam > 0)
    return np.where(ok, force, np.nan), np.where(ok, lam, np.nan)


def pattern_mean(force, lam):
    """Time mean of the tether force [N] and of lambda [-] over a loop of courses ``force``, ``lam`` (shape
    (n_course, n)) spaced evenly in course angle: the loop's arc length is even in chi, so the time on each course
    is proportional to 1 / lambda (our derivation; lambda's mean is the harmonic one). Where any course cannot be
    flown (NaN) the loop cannot be closed: both are 0 and the third result, ``flyable`` (bool, (n,)), is False."""
    flyable = np.all(np.isfinite(force) & np.isfinite(lam), axis=0)
    dwell = np.where(flyable, 1.0 / np.where(flyable, lam, 1.0), 0.0)     # time per unit arc length x v_w
    total = np.sum(dwell, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        f_mean = np.where(flyable, np.sum(np.where(flyable, force, 0.0) * dwell, axis=0) / total, 0.0)
        lam_mean = np.where(flyable, force.shape[0] / total, 0.0)
    return f_mean, lam_mean, flyable


def retraction(w, beta, v_in, S, cd_extra, mass, rho, qs: SchmehlParams):
    """Reel-in at fixed elevation ``beta``: the C_L that balances the weight across the tether (bisection over
    [0, cl_max] on the polar) and the tether force [N]; arrays (n,). Returns (force, cl, glide ratio)."""
    v_r = w * np.cos(beta) + v_in                  # radial apparent wind: the wind along the tether plus reel-in
    v_b = -w * np.sin(beta)                        # the wind across the tether (towards lower elevation)
    va = np.hypot(v_r, v_b)
    ar, ab = v_r / va, v_b / va                    # unit apparent wind; lift along (-ab, ar), towards higher beta
    q = 0.5 * rho * va * va * S
    need = mass * GRAVITY * np.cos(beta)

    def across(cl):
        return q * ((qs.cd0 + qs.cd2 * cl * cl + cd_extra) * ab + cl * ar) - need

    lo, hi = np.zeros_like(va), np.full_like(va, qs.cl_max)
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        pos = across(mid) > 0
        hi = np.where(pos, mid, hi)
        lo = np.where(pos, lo, mid)
    cl = np.where(across(np.zeros_like(va)) >= 0, 0.0, 0.5 * (lo + hi))
    cdt = qs.cd0 + qs.cd2 * cl * cl + cd_extra
    force = q * (cdt * ar - cl * ab) - mass * GRAVITY * np.sin(beta)
    return np.maximum(force, 0.0), cl, cl / cdt


def cycle_power(w, h, theta, d, S, cl, cd, params: PumpingParams | None = None, reel_out_factor=1.0 / 3.0,
                reel_out_rule: str = "wind", qs: SchmehlParams | None = None) -> CycleResult:
    """Schmehl / van der Vlugt pumping cycle, same arguments and result as ``lansdorp.cycle_power`` (the cable
    angle ``theta`` from the vertical sets the traction elevation beta = 90 deg - theta and the tether length
    L = h / cos(theta)); the wind ``w`` [m/s] (shape (n,)) is taken at the kite for all three phases. The
    traction tension and kite speed are time means over the loop of ``qs.n_course`` courses (``pattern_mean``);
    where a course of the loop cannot be flown the cycle never completes: power and energy 0, cycle time inf,
    tension and kite speed 0 (as ``lansdorp.cycle`` treats a reel-in speed of 0)."""
    params = PumpingParams() if params is None else params
    qs = SchmehlParams() if qs is None else qs
    w = np.asarray(w, dtype=float)
    beta = 0.5 * np.pi - theta
    L = cable_length(h, theta)
    share = cable_drag_share(d, L, S, params.cable_cd)
    cd_total = np.broadcast_to(np.asarray(cd, dtype=float) + share, w.shape)
    cl = np.broadcast_to(np.asarray(cl, dtype=float), w.shape)
    mass = qs.kite_mass_per_area * S + qs.tether_mass_share * params.cable_density * np.pi * d * d / 4.0 * L
    f = reel_out_factor * (np.sin(theta) if reel_out_rule == "radial" else 1.0)
    chis = 2.0 * np.pi * (np.arange(qs.n_course) + 0.5) / qs.n_course if qs.n_course > 1 else np.array([0.5 * np.pi])
    per_course = [traction(w, beta, f, S, cl, cd_total, mass, params.rho, qs.azimuth, c) for c in chis]
    T_out, lam, flyable = pattern_mean(np.array([fc[0] for fc in per_course]), np.array([fc[1] for fc in per_course]))
    v_out = f * w
    beta_in = max(float(qs.retraction_elevation), float(beta))
    T_in, _, _ = retraction(w, beta_in, params.reel_in_speed, S, share, mass, params.rho, qs)
    # transition at constant length from beta to beta_in, flying up (chi = 0) still powered (kappa = the traction
    # glide ratio; a depowered kite could not climb against the wind), no reeling and no energy
    bm = 0.5 * (beta + beta_in)
    a, b = -np.sin(bm) * np.cos(qs.azimuth), np.cos(bm) * np.cos(qs.azimuth)
    E_t = cl / cd_total
    lam_t = a + np.sqrt(np.maximum(a * a + b * b - 1.0 + E_t * E_t * b * b, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        t_trans = np.where((lam_t * w > 0) & flyable, L * (beta_in - beta) / (lam_t * w), np.inf)
    p_out, p_in, t_c, energy, power = cycle(T_out, v_out, params, tension_in=T_in, time_extra=t_trans)
    return CycleResult(T_out, T_in, np.broadcast_to(v_out, w.shape), p_out, p_in, t_c, energy, power, lam * w)
