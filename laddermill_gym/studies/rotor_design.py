"""Steady-state design study of Roberts' twin 35 m rotorcraft at 15,000 ft and 30,000 ft (Roberts sec. 6, Table 1).

Run ``python -m laddermill_gym.studies.rotor_design [--out runs/rotor_design]`` (about 8 s).

For each craft config (``configs/rotorcraft/roberts_35m_15kft.yaml``, ``..._30kft.yaml``) and each wind speed V
at the craft, the craft incidence alpha_c and the collective theta0 are chosen to maximise the electrical
power 2 (-Q Omega) 0.95 subject to

* the blade-incidence limit: retreating-tip incidence <= 13 deg (``laddermill_gym.rotorcraft.rotor``);
* lift: the three tethers of the config length, heavy inextensible catenaries each loaded at the craft end by
  a third of the craft's net force (rotor forces and frame drag less the weight), must reach the design
  altitude and must leave their anchors upwards: the craft carries its own weight and all of the tethers';
* tether stress: the top tension (the largest along a hanging cable) <= ``SAFE_FRACTION`` x breaking load.

The density is the ISA troposphere at the design altitude; the rotor speed is the config's. The command prints
the craft estimate, the power table, the peak power at each altitude beside Roberts' 3.13 MW, what reproduces
3.13 MW and a sensitivity table, and writes ``design_study.csv`` and ``power_curves.png``. Method, sources and
choices: ``laddermill_gym/docs/rotorcraft_design.md``.

Units: SI (m, s, kg, N, W, Pa); angles in radians unless a name ends in ``_deg``.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit
from scipy.optimize import minimize_scalar

from laddermill_gym.model.configio import CONFIG_DIR, config_path, read_yaml
from laddermill_gym.rotorcraft import rotor_kernels as _k
from laddermill_gym.rotorcraft.rotor import (
    INFLOW_MAX_ITER,
    INFLOW_TOL,
    RotorParams,
    RotorSolveError,
    collective_at_limit,
    ideal_power_coefficient,
    load_rotor_config,
)
from laddermill_gym.studies.design_physics import (
    FOOT,
    HUB_SPACING,
    TIP_SPEEDS,
    Catenary,
    _number,
    catenary,
    craft_estimate,
    isa_density,
    isa_temperature,
    speed_of_sound,
)

__all__ = [
    "FOOT", "ROBERTS_PEAK_POWER", "ALTITUDES_FT", "CRAFT_CONFIGS", "SAFE_FRACTION", "KEVLAR_DENSITY",
    "KEVLAR_MASS_FRACTION", "DEFAULT_WINDS", "DEFAULT_OUT", "isa_temperature", "isa_density", "speed_of_sound",
    "Catenary", "catenary", "RotorcraftDesign", "load_design", "OperatingPoint", "evaluate_point",
    "best_operating_point", "wind_for_power", "AltitudeStudy", "study_altitude", "power_for_cp", "cp_for_power",
    "craft_estimate", "sensitivity", "tip_speed_scan", "write_csv", "plot_power_curves", "main",
]

#: Roberts' Table 1: peak electrical power output, the same at both altitudes [W].
ROBERTS_PEAK_POWER = 3.13e6
#: The two altitudes of Roberts' sec. 6 [ft].
ALTITUDES_FT: tuple[int, ...] = (15000, 30000)
#: Craft config of each altitude [ft].
CRAFT_CONFIGS: dict[int, Path] = {
    15000: CONFIG_DIR / "rotorcraft" / "roberts_35m_15kft.yaml",
    30000: CONFIG_DIR / "rotorcraft" / "roberts_35m_30kft.yaml",
}
#: Allowed top tension over the rope breaking load [-]; chosen: design factor 2 (rotorcraft_design.md).
SAFE_FRACTION = 0.5
#: Kevlar 49 density [kg/m^3] (DuPont, Kevlar aramid fiber technical guide).
KEVLAR_DENSITY = 1440.0
#: Share of the cable mass in the Kevlar tensile member [-] (Roberts sec. 6: "half of this figure").
KEVLAR_MASS_FRACTION = 0.5
#: Wind speeds at the craft of the study [m/s].
DEFAULT_WINDS = np.arange(5.0, 45.5, 1.0)
DEFAULT_OUT = Path("runs/rotor_design")

# optimiser: incidence grid [deg]; collective span below the tip-limit collective [deg] and its points
_ALPHA_GRID_DEG = np.arange(1.0, 89.0, 1.0)
_THETA_SPAN_DEG, _THETA_POINTS = 30.0, 61
_ACTIVE_TOL = 2e-3  # a constraint within this relative distance of its bound is reported as binding [-]
_SLACK = 1e-10      # tolerance of the feasibility tests (relative margins) [-]
_PENALTY = 1e30     # objective of an infeasible point in the 1-D searches [-W]


# ------------------------------------------------------------------------------------------ design data
@dataclass(frozen=True)
class RotorcraftDesign:
    """What the steady study needs of a craft config (:func:`load_design`).

    Attributes
    ----------
    name : str
    rotor : RotorParams
        Blade data of each rotor.
    blade_limit : float
        Retreating-tip incidence limit [rad].
    radius, rotor_speed : float
        Rotor radius R [m]; rotor speed Omega [rad/s], held by the generators.
    mass, gravity : float
        Craft mass without tethers [kg]; [m/s^2].
    drag_area : float
        Frame C_D A [m^2] (drag 1/2 rho V^2 C_D A, horizontal).
    efficiency : float
        Electrical efficiency from shaft to grid [-].
    tether_length, tether_elevation : float
        Length of each tether [m]; design cable angle beta [rad]. Design altitude = length sin(beta).
    cable_mass_per_length, breaking_load : float
        [kg/m]; rope breaking load of one tether [N].
    n_rotors, n_tethers : int
        2 rotors; 3 tethers sharing the net force equally.
    """

    name: str
    rotor: RotorParams
    blade_limit: float
    radius: float
    rotor_speed: float
    mass: float
    gravity: float
    drag_area: float
    efficiency: float
    tether_length: float
    tether_elevation: float
    cable_mass_per_length: float
    breaking_load: float
    n_rotors: int = 2
    n_tethers: int = 3

    @property
    def altitude(self) -> float:
        """Design altitude above the anchors [m]."""
        return self.tether_length * math.sin(self.tether_elevation)

    @property
    def tip_speed(self) -> float:
        """Omega R [m/s]."""
        return self.rotor_speed * self.radius

    @property
    def disk_area(self) -> float:
        """pi R^2 of one rotor [m^2]."""
        return math.pi * self.radius ** 2

    @property
    def kevlar_area(self) -> float:
        """Cross-section of one tether's Kevlar member [m^2]: its mass share over the Kevlar density."""
        return KEVLAR_MASS_FRACTION * self.cable_mass_per_length / KEVLAR_DENSITY

    def with_altitude_elevation(self, elevation: float) -> RotorcraftDesign:
        """The same craft at the same altitude on tethers at another design elevation [rad]."""
        return dataclasses.replace(self, tether_elevation=elevation, tether_length=self.altitude / math.sin(elevation))


def load_design(path: Path | str) -> RotorcraftDesign:
    """Read the study's numbers from a craft YAML (the schema of ``configs/rotorcraft/roberts_flying_model.yaml``)
    and the rotor and cable files it names. Only the fields used here are read (the full loader is
    ``laddermill_gym.rotorcraft.config``); errors name the file, the field and the value (ConfigError)."""
    path = Path(path)
    s = read_yaml(path)
    rotor_cfg = load_rotor_config(config_path("rotors", s.text("rotor"), path.parent))
    t = s.section("tethers")
    c = read_yaml(config_path("cables", t.text("cable"), path.parent))
    elevation_deg = t.number("elevation_deg", positive=True)
    if not elevation_deg < 90.0:
        raise t.error("elevation_deg", elevation_deg, "must be < 90")
    efficiency = s.number("electrical_efficiency", positive=True)
    if efficiency > 1.0:
        raise s.error("electrical_efficiency", efficiency, "must be <= 1")
    return RotorcraftDesign(
        name=s.text("name"), rotor=rotor_cfg.params, blade_limit=rotor_cfg.blade_incidence_limit,
        radius=s.number("rotor_radius", positive=True), rotor_speed=s.number("rotor_speed", positive=True),
        mass=s.number("mass", positive=True), gravity=s.number("gravity", positive=True),
        drag_area=s.number("drag_area", nonneg=True), efficiency=efficiency,
        tether_length=t.number("length", positive=True), tether_elevation=math.radians(elevation_deg),
        cable_mass_per_length=c.number("mass_per_length", positive=True),
        breaking_load=c.number("breaking_load", positive=True))


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


@njit(cache=True)
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


def _check_design(design) -> RotorcraftDesign:
    if not isinstance(design, RotorcraftDesign):
        raise ValueError(f"argument 'design' = {design!r}: must be a RotorcraftDesign")
    return design


def evaluate_point(design: RotorcraftDesign, wind: float, alpha_c: float, theta0: float,
                   safe_fraction: float = SAFE_FRACTION) -> OperatingPoint:
    """The craft at wind speed [m/s], incidence alpha_c [rad] and collective theta0 [rad], not optimised.

    Raises ValueError on a bad argument (also when the advance ratio leaves (0, 1)) and RotorSolveError when the
    inflow does not converge.
    """
    ev = _Evaluator(_check_design(design), _number("wind", wind, 0.0, lo_open=True),
                    _number("safe_fraction", safe_fraction, 0.0, 1.0, lo_open=True))
    alpha_c = _number("alpha_c", alpha_c, 0.0, 0.5 * math.pi, lo_open=True)
    theta0 = _number("theta0", theta0, -0.5 * math.pi, 0.5 * math.pi)
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
    design = _check_design(design)
    ev = _Evaluator(design, _number("wind", wind, 0.0, lo_open=True),
                    _number("safe_fraction", safe_fraction, 0.0, 1.0, lo_open=True))
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
    design = _check_design(design)
    power = _number("power", power)

    def best(v):
        p = best_operating_point(design, v, safe_fraction)
        return p.power if p is not None else -math.inf

    v = min(max(float(round(_number("guess", guess, lo, hi))), lo), hi)
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


# ------------------------------------------------------------------------------------------ the study
@dataclass(frozen=True)
class AltitudeStudy:
    """Power curve and summary of one craft config.

    Attributes
    ----------
    altitude_ft : int
        Nominal altitude [ft].
    design : RotorcraftDesign
    winds : np.ndarray
        Wind speeds [m/s], shape (n,).
    points : list
        Best :class:`OperatingPoint` at each wind speed, None where none is feasible; length n.
    peak : OperatingPoint
        The largest power over the wind range.
    stress_onset : OperatingPoint | None
        The first point at which the tether stress limit binds (None if it never does).
    wind_for_roberts : float
        Wind speed [m/s] at which the best power first reaches 3.13 MW (:func:`wind_for_power`; nan if never).
    roberts_point : OperatingPoint | None
        The best point at that wind speed.
    cut_in : float
        Lowest wind speed [m/s] with positive power (nan if none).
    """

    altitude_ft: int
    design: RotorcraftDesign
    winds: np.ndarray
    points: list
    peak: OperatingPoint
    stress_onset: OperatingPoint | None
    wind_for_roberts: float
    roberts_point: OperatingPoint | None
    cut_in: float


def study_altitude(design: RotorcraftDesign, altitude_ft: int, winds=DEFAULT_WINDS,
                   safe_fraction: float = SAFE_FRACTION) -> AltitudeStudy:
    """Best operating point at each wind speed [m/s] (increasing 1-D array) and the summary."""
    design = _check_design(design)
    winds = np.asarray(winds, dtype=float)
    if winds.ndim != 1 or winds.size < 2 or not np.all(np.isfinite(winds)) or np.any(winds <= 0.0) \
            or np.any(np.diff(winds) <= 0.0):
        raise ValueError(f"argument 'winds' = {winds!r}: must be two or more increasing positive speeds")
    points = [best_operating_point(design, float(v), safe_fraction) for v in winds]
    ok = [p for p in points if p is not None]
    if not ok:
        raise RotorSolveError(f"{design.name}: no feasible operating point for winds {winds[0]}..{winds[-1]} m/s")
    power = np.array([p.power if p is not None else -np.inf for p in points])
    above = np.flatnonzero(power >= ROBERTS_PEAK_POWER)
    v_r = wind_for_power(design, ROBERTS_PEAK_POWER, float(winds[above[0]]), safe_fraction) if above.size else math.nan
    return AltitudeStudy(
        altitude_ft=altitude_ft, design=design, winds=winds, points=points, peak=max(ok, key=lambda p: p.power),
        stress_onset=next((p for p in ok if "stress" in p.binding), None), wind_for_roberts=v_r,
        roberts_point=best_operating_point(design, v_r, safe_fraction) if math.isfinite(v_r) else None,
        cut_in=next((p.wind for p in ok if p.power > 0.0), math.nan))


# ------------------------------------------------------------------------------------------ sensitivity
def sensitivity(design: RotorcraftDesign, wind: float, safe_fraction: float = SAFE_FRACTION
                ) -> list[tuple[str, float, float]]:
    """Best power [W] at wind [m/s] and the wind [m/s] that gives 3.13 MW for one-at-a-time design changes.

    Returns (label, power [W] or nan if infeasible, wind for 3.13 MW [m/s] or nan) for: the baseline, solidity
    0.075 (rotor.md's other reading of Roberts' 22.5 deg), no profile drag, tip speed -/+ 20 m/s, tether
    elevation 20 and 40 deg at the same altitude, craft mass x0.7 and x1.3, weightless tethers, and no tether
    stress limit.
    """
    d = _check_design(design)
    cases = [
        ("baseline", d, safe_fraction),
        ("solidity 0.075", dataclasses.replace(d, rotor=d.rotor.with_solidity(0.075)), safe_fraction),
        ("no profile drag (delta = 0)", dataclasses.replace(d, rotor=d.rotor.ideal()), safe_fraction),
        ("tip speed -20 m/s", dataclasses.replace(d, rotor_speed=(d.tip_speed - 20.0) / d.radius), safe_fraction),
        ("tip speed +20 m/s", dataclasses.replace(d, rotor_speed=(d.tip_speed + 20.0) / d.radius), safe_fraction),
        ("tether elevation 20 deg", d.with_altitude_elevation(math.radians(20.0)), safe_fraction),
        ("tether elevation 40 deg", d.with_altitude_elevation(math.radians(40.0)), safe_fraction),
        ("craft mass x0.7", dataclasses.replace(d, mass=0.7 * d.mass), safe_fraction),
        ("craft mass x1.3", dataclasses.replace(d, mass=1.3 * d.mass), safe_fraction),
        ("weightless tethers", dataclasses.replace(d, cable_mass_per_length=1e-9), safe_fraction),
        ("no tether stress limit", dataclasses.replace(d, breaking_load=math.inf), safe_fraction),
    ]
    out = []
    for label, dd, sf in cases:
        p = best_operating_point(dd, wind, sf)
        out.append((label, p.power if p is not None else math.nan,
                    wind_for_power(dd, ROBERTS_PEAK_POWER, wind, sf)))
    return out


def tip_speed_scan(design: RotorcraftDesign, wind: float, tip_speeds=TIP_SPEEDS,
                   n_blades: int = 4, safe_fraction: float = SAFE_FRACTION) -> list[tuple[float, float, float]]:
    """Best power [W] at wind [m/s] for other tip speeds [m/s], the craft mass re-estimated by
    :func:`craft_estimate` for each (drive rated at Roberts' 3.13 MW). Returns (tip speed, mass [kg], power [W]
    or nan if infeasible)."""
    d = _check_design(design)
    out = []
    for vt in tip_speeds:
        m = craft_estimate(d.radius, vt, d.rotor.sigma, n_blades, ROBERTS_PEAK_POWER / d.efficiency / d.n_rotors,
                           HUB_SPACING)["mass"]
        p = best_operating_point(dataclasses.replace(d, rotor_speed=vt / d.radius, mass=m), wind, safe_fraction)
        out.append((vt, m, p.power if p is not None else math.nan))
    return out


# ------------------------------------------------------------------------------------------ output
_CSV_HEAD = ["altitude_ft", "wind_m_s", "feasible", "power_MW", "cp", "alpha_c_deg", "theta0_deg", "mu",
             "tip_aoa_deg", "thrust_kN", "h_force_kN", "tension_kN", "stress_MPa", "utilisation",
             "anchor_angle_deg", "top_angle_deg", "chord_angle_deg", "tether_height_m", "binding"]


def write_csv(path: Path, studies: list[AltitudeStudy]) -> None:
    """One row per altitude and wind speed (columns ``_CSV_HEAD``; empty where no point is feasible)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(_CSV_HEAD)
        for st in studies:
            for v, p in zip(st.winds, st.points, strict=True):
                if p is None:
                    w.writerow([st.altitude_ft, f"{v:g}", 0] + [""] * (len(_CSV_HEAD) - 3))
                    continue
                t = p.tether
                vals = [p.power / 1e6, p.cp, math.degrees(p.alpha_c), math.degrees(p.theta0), p.mu,
                        math.degrees(p.tip_aoa), p.thrust / 1e3, p.h_force / 1e3, t.top_tension / 1e3,
                        p.stress / 1e6, p.utilisation, math.degrees(t.anchor_angle), math.degrees(t.top_angle),
                        math.degrees(t.chord_angle), t.height]
                w.writerow([st.altitude_ft, f"{v:g}", 1] + [f"{x:.6g}" for x in vals] + [p.binding or "none"])


def plot_power_curves(path: Path, studies: list[AltitudeStudy]) -> None:
    """Electrical power against wind speed at both altitudes with Roberts' 3.13 MW and the stress-limit onset."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from laddermill_gym.plotting import save_figure

    fig, ax = plt.subplots(figsize=(8.0, 5.2))
    for st in studies:
        power = np.array([p.power / 1e6 if p is not None else np.nan for p in st.points])
        line, = ax.plot(st.winds, power, "-o", ms=3, lw=1.5, label=f"{st.altitude_ft:,} ft")
        if st.stress_onset is not None:
            ax.plot(st.stress_onset.wind, st.stress_onset.power / 1e6, "s", ms=8, mfc="none",
                    color=line.get_color(), label=f"{st.altitude_ft:,} ft: tether stress limit reached")
        if math.isfinite(st.wind_for_roberts):
            ax.axvline(st.wind_for_roberts, color=line.get_color(), ls=":", lw=1.0)
    ax.axhline(ROBERTS_PEAK_POWER / 1e6, color="k", ls="--", lw=1.0)
    ax.text(studies[0].winds[0], ROBERTS_PEAK_POWER / 1e6 + 0.15, "Roberts, Table 1: 3.13 MW peak", fontsize=9)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("wind speed at the craft V [m/s]")
    ax.set_ylabel("electrical power 2 (-Q Omega) 0.95 [MW]")
    ax.set_title("Twin 35 m rotorcraft: best steady power within the blade limit, lift and tether stress\n"
                 "(dotted: wind at which 3.13 MW is reached; below zero the craft draws power to stay up)",
                 fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)
    save_figure(fig, path)


def _print_design(st: AltitudeStudy) -> None:
    d = st.design
    allowed = SAFE_FRACTION * d.breaking_load
    print(f"{st.altitude_ft:,} ft ({d.name}): altitude {d.altitude:.0f} m, ISA density {isa_density(d.altitude):.4f} "
          f"kg/m^3, speed of sound {speed_of_sound(d.altitude):.1f} m/s; R {d.radius} m, Omega R {d.tip_speed:.1f} "
          f"m/s; craft {d.mass:.0f} kg; 3 tethers {d.tether_length:.0f} m at {math.degrees(d.tether_elevation):g} "
          f"deg, {d.cable_mass_per_length * d.tether_length:.0f} kg each; allowed tension {allowed / 1e3:.1f} kN "
          f"({allowed / d.kevlar_area / 1e6:.0f} MPa in the Kevlar)")


def _print_table(studies: list[AltitudeStudy]) -> None:
    head = " P [MW]    C_p  a_c  th0     mu  T [kN] util binding     "
    print("   V |" + "|".join(f" {st.altitude_ft:,} ft:".ljust(len(head)) for st in studies))
    print("m/s  |" + "|".join(head for _ in studies))
    for i, v in enumerate(studies[0].winds):
        cells = []
        for st in studies:
            p = st.points[i]
            cells.append(" landed: cannot hold the altitude".ljust(len(head)) if p is None else
                         f"{p.power / 1e6:7.3f} {p.cp:6.3f} {math.degrees(p.alpha_c):4.1f} "
                         f"{math.degrees(p.theta0):4.1f} {p.mu:6.3f} {p.tether.top_tension / 1e3:7.1f} "
                         f"{p.utilisation:4.2f} {p.binding or '-':<12}")
        print(f"{v:4.0f} |" + "|".join(cells))


def main(argv: list[str] | None = None) -> list[AltitudeStudy]:
    """Command line: run the study at both altitudes, print the results, write the CSV and the PNG."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(DEFAULT_OUT), help="output folder (design_study.csv, power_curves.png)")
    out = Path(ap.parse_args(argv).out)
    t0 = time.perf_counter()
    studies = [study_altitude(load_design(CRAFT_CONFIGS[a]), a) for a in ALTITUDES_FT]

    print(f"Craft estimate (drive rated 3.13 MW / 0.95 / 2 per rotor, 4 blades, hub spacing {HUB_SPACING:g} m):")
    for st in studies:
        d = st.design
        e = craft_estimate(d.radius, d.tip_speed, d.rotor.sigma, 4, ROBERTS_PEAK_POWER / 0.95 / 2, HUB_SPACING)
        print(f"  Omega R {d.tip_speed:.0f} m/s: per rotor blades {e['blades']:.0f}, hub {e['hub']:.0f}, drive "
              f"{e['drive']:.0f}, generator {e['generator']:.0f} kg; frame {e['frame']:.0f} kg; craft {e['mass']:.0f}"
              f" kg; hubs {e['hub_height']:.2f} m above and {e['hub_x']:.2f} m ahead of the CG; J = "
              f"[{e['Jxx']:.3g}, {e['Jyy']:.3g}, {e['Jzz']:.3g}, {e['Jxz']:.3g}] kg m^2")
    print()
    for st in studies:
        _print_design(st)
    print()
    _print_table(studies)
    print()
    for st in studies:
        pk, d, rp, onset = st.peak, st.design, st.roberts_point, st.stress_onset
        rho = isa_density(d.altitude)
        top = ", the top of the range" if pk.wind == st.winds[-1] else ""
        print(f"{st.altitude_ft:,} ft: cut-in {st.cut_in:g} m/s; peak over {st.winds[0]:g}-{st.winds[-1]:g} m/s "
              f"{pk.power / 1e6:.2f} MW at {pk.wind:g} m/s{top} (binding: {pk.binding or 'none'}); tether stress limit "
              + (f"first binds at {onset.wind:g} m/s ({onset.power / 1e6:.2f} MW)." if onset else "never binds."))
        if rp is not None:
            cp_ideal = float(ideal_power_coefficient(rp.alpha_c))
            unit = power_for_cp(cp_ideal, 1.0, rho, d.radius, d.n_rotors, d.efficiency)
            v_ideal = (ROBERTS_PEAK_POWER / unit) ** (1.0 / 3.0)
            print(f"    3.13 MW at {st.wind_for_roberts:.1f} m/s: C_p {rp.cp:.3f}, alpha_c "
                  f"{math.degrees(rp.alpha_c):.1f} deg, theta0 {math.degrees(rp.theta0):.2f} deg, mu {rp.mu:.3f}, tip "
                  f"{math.degrees(rp.tip_aoa):.2f} deg, tension {rp.tether.top_tension / 1e3:.1f} kN = "
                  f"{rp.stress / 1e6:.0f} MPa (utilisation {rp.utilisation:.2f}), chord "
                  f"{math.degrees(rp.tether.chord_angle):.1f} deg, binding: {rp.binding or 'none'}.")
            print(f"    ideal C_p at that incidence {cp_ideal:.3f} would give 3.13 MW at {v_ideal:.1f} m/s.")
        cps = ", ".join(f"{v:g} m/s {cp_for_power(ROBERTS_PEAK_POWER, v, rho, d.radius):.3f}"
                        for v in (15.0, 20.0, 25.0, 30.0, 35.0))
        print(f"    C_p that gives 3.13 MW at {cps} (Betz 16/27 = 0.593).")
    for st in studies:
        v_ref = float(math.ceil(st.wind_for_roberts)) if math.isfinite(st.wind_for_roberts) else float(st.peak.wind)
        print(f"\nSensitivity at {st.altitude_ft:,} ft: best power at {v_ref:g} m/s, and the wind that gives 3.13 MW")
        scan = ", ".join(f"{vt:g}: {p / 1e6:.2f}" if math.isfinite(p) else f"{vt:g}: -"
                         for vt, _, p in tip_speed_scan(st.design, v_ref))
        print(f"    tip speed [m/s]: power [MW] (craft mass re-estimated; -: cannot hold the altitude): {scan}")
        for label, p, v in sensitivity(st.design, v_ref):
            reach = f"{v:6.1f} m/s" if math.isfinite(v) else "not reached below 60 m/s"
            print(f"    {label:<30} {p / 1e6:7.2f} MW   {reach}")
    write_csv(out / "design_study.csv", studies)
    plot_power_curves(out / "power_curves.png", studies)
    print(f"\nwrote {out / 'design_study.csv'} and {out / 'power_curves.png'} ({time.perf_counter() - t0:.1f} s)")
    return studies


if __name__ == "__main__":
    main()
