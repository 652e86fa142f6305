"""Operating points of the 35 m rotorcraft study: the power and constraint margins of a design at one wind
speed (blade-incidence limit, lift, tether stress), the best point over incidence and collective, the wind
that gives a power, and Roberts' eq. 4 between power and power coefficient.

Units: SI (m, s, kg, N, W, Pa); angles in radians unless a name ends in ``_deg``."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.optimize import minimize_scalar

from laddermill_gym.rotorcraft import rotor_kernels as _k
from laddermill_gym.rotorcraft.rotor import INFLOW_MAX_ITER, INFLOW_TOL, RotorSolveError, collective_at_limit
from laddermill_gym.studies.rotorcraft.design_physics import Catenary, catenary, isa_density, number
from laddermill_gym.studies.rotorcraft.rotor_design_data import SAFE_FRACTION, RotorcraftDesign, check_design

# optimiser: incidence grid [deg]; collective span below the tip-limit collective [deg] and its points
_ALPHA_GRID_DEG = np.arange(1.0, 89.0, 1.0)
_THETA_SPAN_DEG, _THETA_POINTS = 30.0, 61
_ACTIVE_TOL = 2e-3  # a constraint within this relative distance of its bound is reported as binding [-]
_SLACK = 1e-10      # tolerance of the feasibility tests (relative margins) [-]
_PENALTY = 1e30     # objective of an infeasible point in the 1-D searches [-W]


# ------------------------------------------------------------------------------------------ operating points
@dataclass(frozen=True)
class OperatingPoint:
    """A steady operating point (forces in the vertical plane of the wind).

    Attributes
    ----------
    wind, altitude, density : float
        Wind speed at the craft [m/s], design altitude [m], ISA density there [kg/m^3].
    alpha_c, theta0 : float
        Craft (disk) incidence and collective [rad].
    mu, ct, ch, cq, cp, tip_aoa : float
        Advance ratio, thrust, H-force and torque coefficients, power coefficient (Roberts eq. 4) [-];
        retreating-tip incidence [rad] (as ``laddermill_gym.rotorcraft.rotor.RotorState``).
    thrust, h_force : float
        Thrust and H-force of one rotor [N].
    power : float
        Electrical power n_rotors (-Q Omega) efficiency [W] (< 0: the craft draws power from the ground).
    force_x, force_z : float
        Net force of the craft on its tethers, downwind and up [N] (rotors and frame drag, less the weight).
    tether : Catenary
        One tether, loaded by force / n_tethers.
    stress : float
        Kevlar stress at the craft end [Pa] (top tension / Kevlar area).
    utilisation : float
        Top tension over the allowed tension (safe fraction x breaking load) [-].
    feasible : bool
        Blade limit, lift (altitude reached, anchors pulled up) and stress all met.
    binding : str
        Constraints at their bounds, "+"-joined from "blade", "lift", "stress"; "" when none.
    """

    wind: float
    altitude: float
    density: float
    alpha_c: float
    theta0: float
    mu: float
    ct: float
    ch: float
    cq: float
    cp: float
    tip_aoa: float
    thrust: float
    h_force: float
    power: float
    force_x: float
    force_z: float
    tether: Catenary
    stress: float
    utilisation: float
    feasible: bool
    binding: str


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def _scan(p, mu, alpha, thetas, c, res):
    """Power and constraint margins over collectives thetas [rad] at advance ratio mu and incidence alpha [rad].

    c: force unit q = rho pi R^2 (Omega R)^2 [N], R [m], Omega [rad/s], efficiency, n_rotors, n_tethers, craft
    weight [N], frame drag [N], tether weight per length [N/m], tether length [m], altitude [m], allowed tension
    [N], blade limit [rad]. res[i] = (power [W], lift margin, stress margin, blade margin) [-]: lift
    min((z - h)/h, V_a/T_top), stress 1 - T_top/allowed, blade (limit - tip)/limit; nan if the inflow failed.
    """
    q, rad, om, eff, nr, nt, weight, drag, w, length, h, allowed, limit = (c[0], c[1], c[2], c[3], c[4], c[5],
                                                                          c[6], c[7], c[8], c[9], c[10], c[11],
                                                                          c[12])
    out = np.empty(_k.N_OUT)
    ca, sa = math.cos(alpha), math.sin(alpha)
    for i in range(thetas.size):
        _k.rotor_state(p, mu, alpha, thetas[i], INFLOW_TOL, INFLOW_MAX_ITER, out)
        if out[_k.O_STATUS] != _k.STATUS_OK:
            res[i, :] = np.nan
            continue
        thrust, hforce = out[_k.O_CT] * q, out[_k.O_CH] * q
        ht = (nr * (thrust * sa + hforce * ca) + drag) / nt
        vt = (nr * (thrust * ca - hforce * sa) - weight) / nt
        va = vt - w * length
        tension = math.hypot(ht, vt)
        lift = -1.0
        if ht > 0.0:
            lift = min((tension - math.hypot(ht, va)) / w / h - 1.0, va / tension)
        res[i, 0] = -nr * out[_k.O_CQ] * q * rad * om * eff
        res[i, 1] = lift
        res[i, 2] = 1.0 - tension / allowed
        res[i, 3] = (limit - out[_k.O_TIP_AOA]) / limit


class _Evaluator:
    """Power and constraints of one design at one wind speed and stress allowance."""

    def __init__(self, d: RotorcraftDesign, wind: float, safe_fraction: float):
        self.d, self.wind, self.h = d, wind, d.altitude
        self.rho = isa_density(self.h)
        self.q = self.rho * d.disk_area * d.tip_speed ** 2  # force unit rho pi R^2 (Omega R)^2 [N]
        self.drag = 0.5 * self.rho * wind ** 2 * d.drag_area
        self.w = d.cable_mass_per_length * d.gravity
        self.allowed = safe_fraction * d.breaking_load
        self.p = d.rotor.packed()
        self.c = np.array([self.q, d.radius, d.rotor_speed, d.efficiency, d.n_rotors, d.n_tethers,
                           d.mass * d.gravity, self.drag, self.w, d.tether_length, self.h, self.allowed,
                           d.blade_limit])
        self._one = np.empty((1, 4))

    def mu(self, alpha: float) -> float:
        return self.wind * math.cos(alpha) / self.d.tip_speed

    def scan(self, alpha: float, thetas: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Power [W] and the smallest constraint margin [-] (>= 0: feasible) over collectives [rad]."""
        res = np.empty((thetas.size, 4))
        _scan(self.p, self.mu(alpha), alpha, thetas, self.c, res)
        return res[:, 0], np.min(res[:, 1:], axis=1)

    def one(self, alpha: float, theta: float) -> tuple[float, float]:
        _scan(self.p, self.mu(alpha), alpha, np.array([theta]), self.c, self._one)
        r = self._one[0]
        return float(r[0]), float(min(r[1], r[2], r[3]))

    def best_at_alpha(self, alpha: float) -> tuple[float, float]:
        """Best feasible (power [W], collective [rad]) at incidence alpha [rad]; (-inf, nan) if none.

        61 collectives over the 30 deg below the tip-limit collective; the edges of the feasible set are refined
        by bisection on the smallest margin (40 halvings, keeping the feasible end), an interior maximum by
        bounded Brent (1e-9 rad).
        """
        mu = self.mu(alpha)
        if not 0.0 < mu < 1.0:
            return -math.inf, math.nan
        try:
            th_lim = collective_at_limit(self.d.rotor, mu, alpha, self.d.blade_limit)
        except RotorSolveError:
            return -math.inf, math.nan
        thetas = np.linspace(max(th_lim - math.radians(_THETA_SPAN_DEG), math.radians(-60.0)), th_lim, _THETA_POINTS)
        power, margin = self.scan(alpha, thetas)
        ok = margin >= -_SLACK
        if not ok.any():
            return -math.inf, math.nan
        cands = [(float(power[i]), float(thetas[i])) for i in np.flatnonzero(ok)]
        for i in range(thetas.size - 1):
            if ok[i] != ok[i + 1] and np.isfinite(margin[i]) and np.isfinite(margin[i + 1]):
                good, bad = (thetas[i], thetas[i + 1]) if ok[i] else (thetas[i + 1], thetas[i])
                for _ in range(40):
                    mid = 0.5 * (good + bad)
                    if self.one(alpha, mid)[1] >= -_SLACK:
                        good = mid
                    else:
                        bad = mid
                cands.append((self.one(alpha, good)[0], float(good)))
        i = int(np.argmax(np.where(ok, power, -np.inf)))
        if 0 < i < thetas.size - 1 and ok[i - 1] and ok[i + 1]:
            def neg(th):
                pw, m = self.one(alpha, th)
                return -pw if m >= -_SLACK and math.isfinite(pw) else _PENALTY
            r = minimize_scalar(neg, bounds=(thetas[i - 1], thetas[i + 1]), method="bounded",
                                options={"xatol": 1e-9})
            if r.fun < _PENALTY:
                cands.append((-float(r.fun), float(r.x)))
        return max(cands)

    def point(self, alpha: float, theta0: float) -> OperatingPoint:
        d = self.d
        mu = self.mu(alpha)
        out = np.empty(_k.N_OUT)
        _k.rotor_state(self.p, mu, alpha, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
        thrust, hforce = out[_k.O_CT] * self.q, out[_k.O_CH] * self.q
        ca, sa = math.cos(alpha), math.sin(alpha)
        fx = d.n_rotors * (thrust * sa + hforce * ca) + self.drag
        fz = d.n_rotors * (thrust * ca - hforce * sa) - d.mass * d.gravity
        tether = catenary(max(fx, 0.0) / d.n_tethers, fz / d.n_tethers, self.w, d.tether_length)
        tension = tether.top_tension
        binding = []
        if out[_k.O_TIP_AOA] >= d.blade_limit * (1.0 - _ACTIVE_TOL):
            binding.append("blade")
        if tether.height <= self.h * (1.0 + _ACTIVE_TOL) or tether.anchor_vertical <= _ACTIVE_TOL * tension:
            binding.append("lift")
        if tension >= self.allowed * (1.0 - _ACTIVE_TOL):
            binding.append("stress")
        power, margin = self.one(alpha, theta0)
        return OperatingPoint(
            wind=self.wind, altitude=self.h, density=self.rho, alpha_c=alpha, theta0=theta0, mu=mu,
            ct=float(out[_k.O_CT]), ch=float(out[_k.O_CH]), cq=float(out[_k.O_CQ]), cp=float(out[_k.O_CP]),
            tip_aoa=float(out[_k.O_TIP_AOA]), thrust=float(thrust), h_force=float(hforce), power=power,
            force_x=float(fx), force_z=float(fz), tether=tether, stress=tension / d.kevlar_area,
            utilisation=tension / self.allowed, feasible=bool(margin >= -_SLACK), binding="+".join(binding))


def evaluate_point(design: RotorcraftDesign, wind: float, alpha_c: float, theta0: float,
                   safe_fraction: float = SAFE_FRACTION) -> OperatingPoint:
    """The craft at wind speed [m/s], incidence alpha_c [rad] and collective theta0 [rad], not optimised.

    Raises ValueError on a bad argument (also when the advance ratio leaves (0, 1)) and RotorSolveError when the
    inflow does not converge.
    """
    ev = _Evaluator(check_design(design), number("wind", wind, 0.0, lo_open=True),
                    number("safe_fraction", safe_fraction, 0.0, 1.0, lo_open=True))
    alpha_c = number("alpha_c", alpha_c, 0.0, 0.5 * math.pi, lo_open=True)
    theta0 = number("theta0", theta0, -0.5 * math.pi, 0.5 * math.pi)
    if not 0.0 < ev.mu(alpha_c) < 1.0:
        raise ValueError(f"argument 'wind' = {wind!r}: advance ratio {ev.mu(alpha_c)!r} outside (0, 1)")
    pt = ev.point(alpha_c, theta0)
    if not math.isfinite(pt.ct):
        raise RotorSolveError(f"inflow not converged at wind {wind} m/s, alpha_c {alpha_c} rad, theta0 {theta0} rad")
    return pt


def best_operating_point(design: RotorcraftDesign, wind: float,
                         safe_fraction: float = SAFE_FRACTION) -> OperatingPoint | None:
    """Largest electrical power at wind speed [m/s] within the blade limit, lift and tether stress.

    At each incidence the best feasible collective is found (61 collectives over the 30 deg below the one that
    puts the retreating tip at the limit, ``laddermill_gym.rotorcraft.rotor.collective_at_limit``; edges of the
    feasible set by bisection, interior maxima by Brent). The incidence is scanned over 1..88 deg in 1 deg steps
    and the two best local maxima refined by bounded Brent (1e-7 rad). Returns None when no point is feasible: the craft
    cannot stay at its altitude.
    """
    design = check_design(design)
    ev = _Evaluator(design, number("wind", wind, 0.0, lo_open=True),
                    number("safe_fraction", safe_fraction, 0.0, 1.0, lo_open=True))
    alphas = np.radians(_ALPHA_GRID_DEG)
    rows = [ev.best_at_alpha(float(a)) for a in alphas]
    power = np.array([r[0] for r in rows])
    if not np.isfinite(power).any():
        return None
    best = max((r[0], float(a), r[1]) for r, a in zip(rows, alphas, strict=True))
    step = alphas[1] - alphas[0]
    peaks = [i for i in range(power.size) if np.isfinite(power[i])
             and power[i] >= (power[i - 1] if i > 0 else -np.inf) and power[i] >= (power[i + 1] if i + 1 < power.size
                                                                                   else -np.inf)]
    for i in sorted(peaks, key=lambda j: -power[j])[:2]:
        def neg(a):
            pw = ev.best_at_alpha(a)[0]
            return -pw if math.isfinite(pw) else _PENALTY
        r = minimize_scalar(neg, bounds=(alphas[i] - step, alphas[i] + step), method="bounded",
                            options={"xatol": 1e-7})
        pw, th = ev.best_at_alpha(float(r.x))
        if pw > best[0]:
            best = (pw, float(r.x), th)
    return ev.point(best[1], best[2])


def wind_for_power(design: RotorcraftDesign, power: float, guess: float = 25.0,
                   safe_fraction: float = SAFE_FRACTION, lo: float = 5.0, hi: float = 60.0) -> float:
    """Lowest wind speed [m/s] in [lo, hi] at which the best power reaches ``power`` [W], nan if none.

    Steps of 1 m/s from ``guess`` [m/s] find a bracket (a wind without a feasible point counts as not
    reaching), then three regula-falsi steps on the best power (about 0.01 m/s).
    """
    design = check_design(design)
    power = number("power", power)

    def best(v):
        p = best_operating_point(design, v, safe_fraction)
        return p.power if p is not None else -math.inf

    v = min(max(float(round(number("guess", guess, lo, hi))), lo), hi)
    pv = best(v)
    step = -1.0 if pv >= power else 1.0
    while True:
        v2 = v + step
        if not lo <= v2 <= hi:
            return v if pv >= power and step < 0 else math.nan
        p2 = best(v2)
        if (p2 >= power) != (pv >= power):
            break
        v, pv = v2, p2
    (a, pa), (b, pb) = sorted([(v, pv), (v2, p2)])
    for _ in range(3):
        if not (math.isfinite(pa) and math.isfinite(pb)):
            break
        m = a + (power - pa) * (b - a) / (pb - pa)
        pm = best(m)
        if pm >= power:
            b, pb = m, pm
        else:
            a, pa = m, pm
    if not math.isfinite(pa) or not math.isfinite(pb):
        return b
    return a + (power - pa) * (b - a) / (pb - pa)


def power_for_cp(cp: float, wind: float, density: float, radius: float, n_rotors: int = 2,
                 efficiency: float = 0.95) -> float:
    """Electrical power [W] = efficiency n_rotors C_p 1/2 rho pi R^2 V^3 (Roberts eq. 4)."""
    return efficiency * n_rotors * cp * 0.5 * density * math.pi * radius ** 2 * wind ** 3


def cp_for_power(power: float, wind: float, density: float, radius: float, n_rotors: int = 2,
                 efficiency: float = 0.95) -> float:
    """Power coefficient [-] that gives electrical power [W] at wind [m/s] (inverse of :func:`power_for_cp`)."""
    return power / power_for_cp(1.0, wind, density, radius, n_rotors, efficiency)
