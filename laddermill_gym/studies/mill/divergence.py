"""The open-loop 3D mill after the paper's 0.01 rad wind-direction step, followed to its physical end (Meijaard et
al. 1999, Fig. 8; issue 30 point 7).

From the 3D periodic state the wind direction steps by 0.01 rad; the mill diverges sideways (no controller). The
run is followed with an integrator that resolves the motion (RK4 at a step below the scene's, and ROS34PW2 with
error control) and ends at the first **physical** criterion (:class:`EndCriteria`, judged on samples every
``sample_s``):

* ``aerodynamic range``: a wing's angle of attack or sideslip outside the band where its data are accurate
  (``sim.recording.ALPHA_RANGE_DEG``, ``MAX_ABS_BETA_DEG``) for ``aero_hold_s`` seconds without a break (the
  model's loads are then guesses: the flat-plate post-stall table);
* ``wing below height``: a wing CG below ``min_height_m`` (default half the span: a wing tip at the ground, the
  LadderMill env's ``min_altitude``);
* ``cable overload``: an element's tension above ``breaking_fraction`` times the cable's breaking load
  (``sim/overload.py``).

A numerical breakdown (the integrator's speed / rate guards, a non-finite state, a stalled step size) before any
of these is a separate, named outcome (``numerical breakdown``), never read as physics. The report names the
criterion, the time after the step and the wings (or elements).
"""

from __future__ import annotations

import math
import numbers
import time
from dataclasses import dataclass, field

import numpy as np
from tqdm import tqdm

from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.sim.overload import BREAKING_FRACTION, tension_limits
from laddermill_gym.sim.recording import ALPHA_RANGE_DEG, MAX_ABS_BETA_DEG
from laddermill_gym.sim.simulator import SimulationError, Simulator

STEP_RAD = 0.01  # [rad] the paper's wind-direction change
STEP_LEAD_S = 1.0  # [s] the step comes this long after the periodic state (so the record starts undisturbed)
#: Outcomes of a followed run: the three physical criteria, the integrator's breakdown, and neither in time.
AERO, HEIGHT, OVERLOAD = "aerodynamic range", "wing below height", "cable overload"
BREAKDOWN, TIME_LIMIT, WALL_LIMIT = "numerical breakdown", "time limit", "wall-clock limit"
SAMPLE_KEYS = ("t_after_step_s", "roll_deg", "pitch_deg", "yaw_deg", "p_rad_s", "q_rad_s", "r_rad_s", "alpha_deg",
               "beta_deg", "alpha_min_deg", "alpha_max_deg", "abs_beta_max_deg")


@dataclass(frozen=True)
class EndCriteria:
    """When a diverging run ends physically. alpha_range_deg [deg], max_abs_beta_deg [deg]: the band of accurate
    aerodynamic data; aero_hold_s [s]: how long a wing must stay outside it without a break (chosen: 2 s, five
    times the longest spell outside it in the undisturbed periodic motion at 2 m/s, 0.40 s, the wing just
    inserted, which ``meijaard`` prints: :func:`undisturbed_spell`); min_height_m [m]: the lowest wing CG height
    (None: half the smallest span); breaking_fraction [-]: share of the breaking load that ends the run (1: the
    cable breaks); aero_wings: which wing slots are judged on their aerodynamic range (None: all)."""

    alpha_range_deg: tuple[float, float] = ALPHA_RANGE_DEG
    max_abs_beta_deg: float = MAX_ABS_BETA_DEG
    aero_hold_s: float = 2.0
    min_height_m: float | None = None
    breaking_fraction: float = BREAKING_FRACTION
    aero_wings: tuple[int, ...] | None = None

    def __post_init__(self):
        lo, hi = self.alpha_range_deg
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ValueError(f"EndCriteria.alpha_range_deg = {self.alpha_range_deg!r}: need finite low < high [deg]")
        for name in ("max_abs_beta_deg", "aero_hold_s", "breaking_fraction"):
            v = getattr(self, name)
            if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
                raise ValueError(f"EndCriteria.{name} = {v!r}: must be a finite number > 0")


#: The study's end criteria (the defaults of :class:`EndCriteria`).
DEFAULT_END = EndCriteria()


@dataclass
class End:
    """How a followed run ended: ``outcome`` (one of the criteria, ``BREAKDOWN``, ``TIME_LIMIT`` or
    ``WALL_LIMIT``), the time after the step [s], the wings (or elements) concerned and a sentence."""

    outcome: str
    t_after_step_s: float
    bodies: list[int] = field(default_factory=list)
    text: str = ""

    @property
    def physical(self) -> bool:
        return self.outcome in (AERO, HEIGHT, OVERLOAD)


class Judge:
    """The end criteria applied to samples in time order (:meth:`see`): each wing's aerodynamic range with the
    time it left it, the lowest CG height and the tensions. ``t_step`` [s] is the time of the disturbance (times
    are reported after it); ``min_height_m`` [m] and ``limits`` (n_e,) [N] are resolved by the caller."""

    def __init__(self, criteria: EndCriteria, n_wings: int, min_height_m: float, limits: np.ndarray,
                 t_step: float = 0.0):
        self.c, self.t_step, self.min_height, self.limits = criteria, t_step, float(min_height_m), limits
        judged = np.zeros(n_wings, dtype=bool)
        judged[list(range(n_wings)) if criteria.aero_wings is None else list(criteria.aero_wings)] = True
        self.judged = judged
        self.out_since = np.full(n_wings, np.nan)  # time [s] each wing left the band (nan: inside)
        #: over the samples seen: the lowest wing CG height [m] and the largest tension over its limit [-]
        self.lowest, self.peak_ratio = math.inf, 0.0

    def see(self, t: float, alpha_deg: np.ndarray, beta_deg: np.ndarray, heights: np.ndarray,
            tensions: np.ndarray) -> End | None:
        """One sample: time [s], alpha and beta per wing [deg], CG heights [m], tensions (n_e,) [N]. Returns the
        :class:`End` when a criterion holds (checked in the order overload, height, aerodynamic range), else None."""
        c, ts = self.c, t - self.t_step
        self.lowest = min(self.lowest, float(np.min(heights)))
        self.peak_ratio = max(self.peak_ratio, float(np.max(tensions / self.limits)))
        over = np.flatnonzero(tensions > self.limits)
        if over.size:
            e = int(over[np.argmax(tensions[over] / self.limits[over])])
            return End(OVERLOAD, ts, over.tolist(), f"element {e} tension {tensions[e] / 1e3:.4g} kN over "
                       f"{self.limits[e] / 1e3:.4g} kN ({c.breaking_fraction:g} x its breaking load)")
        low = np.flatnonzero(heights < self.min_height)
        if low.size:
            k = int(low[np.argmin(heights[low])])
            return End(HEIGHT, ts, low.tolist(), f"wing {k} CG at {heights[k]:.3g} m, below {self.min_height:.3g} m")
        lo, hi = c.alpha_range_deg
        out = self.judged & ((alpha_deg < lo) | (alpha_deg > hi) | (np.abs(beta_deg) > c.max_abs_beta_deg))
        self.out_since[~out] = np.nan
        self.out_since[out & np.isnan(self.out_since)] = t
        held = np.flatnonzero(out & (t - self.out_since >= c.aero_hold_s - 1e-9))
        if held.size:
            k = int(held[np.argmin(self.out_since[held])])
            return End(AERO, ts, held.tolist(), f"wing {k} outside the aerodynamic data (alpha {alpha_deg[k]:.1f} "
                       f"deg, beta {beta_deg[k]:.1f} deg; band {lo:g}..{hi:g} deg, |beta| <= {c.max_abs_beta_deg:g} "
                       f"deg) since {self.out_since[k] - self.t_step:.2f} s after the step, for {c.aero_hold_s:g} s")
        return None


def min_height(sim: Simulator, criteria: EndCriteria) -> float:
    """The criteria's lowest CG height [m], or half the smallest wing span of the scene."""
    if criteria.min_height_m is not None:
        return float(criteria.min_height_m)
    return 0.5 * min(w.span for w in sim.assembly.wing_types)


def judge_state(judge: Judge, sim: Simulator) -> End | None:
    """Apply ``judge`` to the simulator's current state (alpha, beta, heights, tensions: one right-hand side)."""
    ab = np.degrees(sim.wing_alpha_beta())
    return judge.see(sim.t, ab[:, 0], ab[:, 1], sim.body_heights()[0], sim.tensions())


def sample(sim: Simulator, t_step: float, slot: int) -> dict:
    """The slot's Euler angles [deg], rates [rad/s], alpha and beta [deg]; extremes over slots 1..n-2 [deg]."""
    e, w, ab = np.degrees(sim.wing_euler()[slot]), sim.wing_rates()[slot], np.degrees(sim.wing_alpha_beta())
    return dict(zip(SAMPLE_KEYS, (sim.t - t_step, *e, *w, *ab[slot], ab[1:-1, 0].min(), ab[1:-1, 0].max(),
                                  np.abs(ab[1:-1, 1]).max()), strict=True))


def range_exit(rows: list[dict], alpha_ok_deg=(-16.0, 18.0), beta_ok_deg: float = 21.0) -> dict:
    """First times after the step [s] (nan: never) at which alpha or |beta| of the followed slot, and of any wing in
    slots 1..n-2, leave ``alpha_ok_deg`` / ``beta_ok_deg`` [deg] (rows: samples of :func:`sample`)."""
    c = {k: np.array([r[k] for r in rows]) for k in SAMPLE_KEYS}
    lo, hi = alpha_ok_deg
    masks = {"alpha_exit_slot_s": (c["alpha_deg"] < lo) | (c["alpha_deg"] > hi),
             "beta_exit_slot_s": np.abs(c["beta_deg"]) > beta_ok_deg,
             "alpha_exit_any_s": (c["alpha_min_deg"] < lo) | (c["alpha_max_deg"] > hi),
             "beta_exit_any_s": c["abs_beta_max_deg"] > beta_ok_deg}
    return {k: float(c["t_after_step_s"][np.argmax(m)]) if m.any() else math.nan for k, m in masks.items()}


def undisturbed_spell(sim: Simulator, criteria: EndCriteria, seconds: float, sample_s: float = 0.1) -> dict:
    """Run ``sim`` undisturbed for ``seconds`` [s] (a copy: ``sim`` is not advanced) and judge it every
    ``sample_s`` [s]: the longest spell a wing spends outside the aerodynamic band [s] and that wing, the lowest
    wing CG [m], the peak tension over its limit [-], and the end if a criterion held (it should not: the undisturbed
    motion is the reference the criteria are set against)."""
    s = Simulator(sim.assembly, sim.state, sim.settings, sim.controls)
    s.reset(sim.state, t=sim.t, controls=sim.controls)
    s.set_wind(sim.wind_field)
    judge = Judge(criteria, s.assembly.n_wings, min_height(s, criteria),
                  tension_limits(s.assembly, criteria.breaking_fraction), s.t)
    n = max(1, int(round(sample_s / s.settings.dt)))
    longest, wing, end = 0.0, -1, None
    for _ in range(int(round(seconds / (n * s.settings.dt)))):
        s.step(n_steps=n)
        end = end or judge_state(judge, s)
        spell = s.t - judge.out_since
        if np.any(np.isfinite(spell)) and np.nanmax(spell) > longest:
            longest, wing = float(np.nanmax(spell)), int(np.nanargmax(spell))
    return {"longest_out_s": longest, "wing": wing, "lowest_wing_m": judge.lowest,
            "peak_tension_ratio": judge.peak_ratio, "end": end}


def set_direction_step(sim: Simulator) -> float:
    """Put the paper's 0.01 rad direction step ``STEP_LEAD_S`` after the simulator's time; returns its time [s]."""
    t_step = sim.t + STEP_LEAD_S
    sim.set_wind(WindField(t0=t_step - 1e-3, dt=1e-3, speed=np.ones(2), direction=np.array([0.0, STEP_RAD])))
    return t_step


def follow(sim: Simulator, label: str, slot: int, after_step: float, sample_s: float = 0.1,
           criteria: EndCriteria | None = DEFAULT_END, wall_limit: float = math.inf,
           progress: bool = True) -> dict:
    """From ``sim``'s state (3D), step the wind direction by 0.01 rad ``STEP_LEAD_S`` later and run with the
    simulator's integrator (``sim.settings``; an error-controlled method steps each sample span with its error
    control) until an :class:`EndCriteria` holds (judged after the step on every sample), a
    :class:`SimulationError` (the ``BREAKDOWN`` outcome), ``after_step`` [s] after the step or ``wall_limit`` [s]
    of wall time. ``criteria`` None: judge nothing (run to a breakdown or the end). Returns the samples of
    ``slot`` (:func:`sample`), the :class:`End`, the time reached after the step [s], the wall time [s] and the
    range exits (:func:`range_exit`)."""
    dt, wall0 = sim.settings.dt, time.perf_counter()
    t_step = set_direction_step(sim)
    judge = None if criteria is None else Judge(criteria, sim.assembly.n_wings, min_height(sim, criteria),
                                                tension_limits(sim.assembly, criteria.breaking_fraction), t_step)
    rows, end = [sample(sim, t_step, slot)], None
    n, n_total, done = max(1, int(round(sample_s / dt))), int(round((STEP_LEAD_S + after_step) / dt)), 0
    with tqdm(total=round(after_step + STEP_LEAD_S, 1), desc=f"direction step, {label}", unit="s", leave=False,
              disable=not progress) as bar:
        while done < n_total and end is None:
            k = min(n, n_total - done)
            try:
                sim.step(n_steps=k)
            except SimulationError as err:
                end = End(BREAKDOWN, sim.t - t_step, [], str(err))
            done += k
            rows.append(sample(sim, t_step, slot))
            if end is None and judge is not None and sim.t > t_step + 0.5 * dt:  # after the step, not on it
                end = judge_state(judge, sim)
            if end is None and time.perf_counter() - wall0 > wall_limit:
                end = End(WALL_LIMIT, sim.t - t_step, [], f"stopped after {wall_limit:g} s of wall time")
            bar.update(round(rows[-1]["t_after_step_s"] + STEP_LEAD_S, 1) - bar.n)
    end = end or End(TIME_LIMIT, sim.t - t_step, [], f"no end criterion within {after_step:g} s after the step")
    return {"label": label, "slot": slot, "rows": rows, "end": end, "t_reached_s": sim.t - t_step,
            "wall_s": time.perf_counter() - wall0, "steps": list(sim.adaptive_steps),
            "lowest_wing_m": judge.lowest if judge else math.nan, "peak_tension_ratio": judge.peak_ratio if judge
            else math.nan, **range_exit(rows[1:])}


def describe(run: dict) -> str:
    """The printed line of one followed run."""
    end = run["end"]
    kind = "physical end" if end.physical else "no physical end"
    wings = ""
    if end.bodies:
        what = "elements" if end.outcome == OVERLOAD else "wings"
        wings = f" ({what} {', '.join(str(b) for b in end.bodies[:8])}{' ...' if len(end.bodies) > 8 else ''})"
    return (f"{run['label']}: {kind}, {end.outcome} at {end.t_after_step_s:.2f} s after the step{wings}: {end.text}; "
            f"slot {run['slot']} leaves the data's alpha / beta range at {run['alpha_exit_slot_s']:.1f} / "
            f"{run['beta_exit_slot_s']:.1f} s, any wing at {run['alpha_exit_any_s']:.1f} / "
            f"{run['beta_exit_any_s']:.1f} s; lowest wing CG {run['lowest_wing_m']:.1f} m, peak tension "
            f"{run['peak_tension_ratio']:.3g} x the breaking load (judged samples); {run['wall_s']:.0f} s wall")
