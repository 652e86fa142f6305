"""Run a simulator for a time span and record its named views; save as npz and CSV."""

from __future__ import annotations

import csv
from contextlib import ExitStack, nullcontext
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

import numpy as np

from laddermill_gym.sim.interrupt import stop_requests
from laddermill_gym.sim.overload import BREAKING_FRACTION, Overload, overload_events, tension_limits
from laddermill_gym.sim.simulator import SimulationError, Simulator

#: The band of angle of attack [deg] where the shipped wing data (configs/wings/meijaard_wing.yaml) are accurate:
#: attached flow on every surface. laddermill_gym/docs/wing_data.md: the main wing stalls at alpha_s = -16 / +18
#: deg ("Surface coefficient curves") and the tail plane from about -14 and 18 deg of the aircraft's alpha ("Key
#: numbers"); beyond, the table holds flat-plate estimates "good for keeping a simulation going, not for
#: predicting post-stall manoeuvres" ("Limitations").
ALPHA_RANGE_DEG: tuple[float, float] = (-14.0, 18.0)
#: Largest sideslip [deg] where the wing data are accurate: the lateral coefficients are linear in beta (docs/
#: model.md) and the fins, which carry them, stall at +-21 deg (wing_data.md, "Surface coefficient curves").
MAX_ABS_BETA_DEG: float = 21.0


class GroundContact(NamedTuple):
    """A body found at or below the ground in a recorded sample (``ground_contact: flag``): the time [s] of the
    first sample of that contact, the body ("wing 3", "node 7") and its height there [m]."""

    t: float
    body: str
    height: float


@dataclass
class Recording:
    """Time histories: ``t`` (n,) [s] and ``views[name]`` (n, ...) with units in the names; ``error`` holds
    the SimulationError message if the run broke down (the record stops at the last good state);
    ``ground_contacts`` the contacts flagged in the samples (each body's first sample at or below the ground
    after one above it, in time order); ``overloads`` the cable elements over their tension limit in the samples
    (``sim/overload.py``: each element's first sample of a spell over it, in time order)."""

    t: np.ndarray
    views: dict[str, np.ndarray]
    error: str | None = None
    ground_contacts: list[GroundContact] = field(default_factory=list)
    overloads: list[Overload] = field(default_factory=list)
    #: the run was stopped by Ctrl-C (:func:`record` with ``interruptible``): the record ends at its last sample,
    #: the state where it stopped
    interrupted: bool = False

    def save_npz(self, path: Path) -> Path:
        np.savez_compressed(path, t_s=self.t, error=np.array(self.error or ""), **self.views)
        return path

    def save_csv(self, path: Path) -> Path:
        """One row per sample: time and every scalar of every view (columns named ``view[i][j]``)."""
        cols, data = ["t_s"], [self.t[:, None]]
        for name, arr in self.views.items():
            flat = arr.reshape(len(self.t), -1)
            shape = arr.shape[1:]
            for idx in np.ndindex(*shape):
                cols.append(name + "".join(f"[{i}]" for i in idx))
            data.append(flat)
        table = np.hstack(data)
        with open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(cols)
            w.writerows(table.tolist())
        return path


def record(sim: Simulator, duration: float, sample_dt: float, progress: bool = True,
           alpha_range_deg: tuple[float, float] = ALPHA_RANGE_DEG, max_abs_beta_deg: float = MAX_ABS_BETA_DEG,
           interruptible: bool = False, breaking_fraction: float = BREAKING_FRACTION) -> Recording:
    """Advance ``sim`` by ``duration`` [s] with its current controls, sampling the views every
    ``sample_dt`` [s] (rounded to whole integrator steps). A breakdown or a ground contact in "stop" mode ends
    the record early with the last good state (its last sample, between two regular ones) and the report in
    ``Recording.error``. With ``interruptible`` (in the main thread) a first Ctrl-C stops the run after the
    current chunk of at most :data:`CHUNK_STEPS` steps (one compiled call), with that state as the last sample and
    ``Recording.interrupted`` set (``sim/interrupt.py``); the progress bar counts simulated seconds, updated after
    each chunk. ValueError when the run would take more than :data:`MAX_STEPS` steps (:func:`check_step_count`).

    Besides :meth:`Simulator.views <laddermill_gym.sim.simulator.Simulator.views>` the record holds the boolean
    views ``aero_out_of_range`` (n, n_wings): the wing's angle of attack outside ``alpha_range_deg`` [deg] or its
    |sideslip| above ``max_abs_beta_deg`` [deg], the band where its aerodynamic data are accurate (defaults:
    the shipped wing's, :data:`ALPHA_RANGE_DEG` and :data:`MAX_ABS_BETA_DEG`; never for a body without a table,
    the rotorcraft); and, unless ``settings.ground_contact`` is "off", ``wing_ground_contact`` (n, n_wings) and
    ``node_ground_contact`` (n, n_nodes): the wing CG or free node at or below ``settings.ground_height``; and
    ``element_overload`` (n, n_elements): the element's tension above ``breaking_fraction`` [-] times its
    breaking load (``Recording.overloads``; checked on the samples, so a peak between two samples is not seen)."""
    limits = tension_limits(sim.assembly, breaking_fraction)
    if not duration > 0 or not sample_dt > 0:
        raise ValueError(f"duration ({duration}) and sample_dt ({sample_dt}) must be > 0")
    lo, hi = alpha_range_deg
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi and max_abs_beta_deg > 0):
        raise ValueError(f"alpha_range_deg = {alpha_range_deg!r} (need finite low < high) and max_abs_beta_deg = "
                         f"{max_abs_beta_deg!r} (need > 0)")
    dt = sim.settings.dt
    per = max(1, int(round(sample_dt / dt)))
    n = int(round(duration / (per * dt)))
    check_step_count(dt, n * per * dt)
    times, frames = [sim.t], [sim.views()]
    error, stopped = None, False
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=round(n * per * dt, 9), desc=f"simulating {duration:g} s", unit="s", leave=False,
                   bar_format="{l_bar}{bar}| {n:.4g}/{total:.4g} s [{elapsed}<{remaining}]")
    with ExitStack() as stack:
        request = stack.enter_context(stop_requests("Ctrl-C: stopping after the current chunk of steps and writing "
                                                    "what was recorded (Ctrl-C again to abort)")
                                      if interruptible else nullcontext(None))
        if bar:
            stack.callback(bar.close)
        for _ in range(n):
            error, stopped = _advance_sample(sim, per, bar, request)
            if error or stopped:
                _add_last_good(sim, times, frames)
                break
            times.append(sim.t)
            frames.append(sim.views())
    views = {k: np.array([f[k] for f in frames]) for k in frames[0]}
    views["aero_out_of_range"] = _aero_flags(sim, views, alpha_range_deg, max_abs_beta_deg)
    t = np.array(times)
    contacts = []
    if sim.settings.ground_contact != "off":
        contacts = _ground_flags(sim.settings.ground_height, t, views)
    views["element_overload"], overloads = overload_events(t, views["element_tension_N"], limits)
    return Recording(t, views, error, contacts, overloads, interrupted=stopped)


#: The most steps of one compiled call of :func:`record` [-]: a sample of more steps is run in chunks, so that a
#: Ctrl-C stops the run within one chunk and the progress bar moves (1000 steps: 10 ms to 10 s, by model size).
CHUNK_STEPS = 1000
#: The most steps a recorded run may take [-]: 1e9 steps are hours of compute for the smallest scene (several
#: microseconds a step) and days for the mill.
MAX_STEPS = 1e9
#: Step counts above which the run is warned about (``check_step_count``): minutes to hours of compute.
WARN_STEPS = 1e7


def check_step_count(dt: float, duration: float, where: str = "integrator.dt") -> str | None:
    """ValueError when ``duration`` [s] at the step ``dt`` [s] (named ``where``) takes more than :data:`MAX_STEPS`
    steps; the warning text (None: none) when more than :data:`WARN_STEPS`."""
    steps = duration / dt
    if steps > MAX_STEPS:
        raise ValueError(f"{where} = {dt!r} s: {duration:g} s of simulation would take {steps:.3g} steps, more than "
                         f"{MAX_STEPS:.0e} (hours to days of compute): use a larger step or a shorter time")
    if steps > WARN_STEPS:
        return (f"{duration:g} s at {where} = {dt!r} s are {steps:.3g} steps: minutes to hours of compute "
                "(the progress bar shows the simulated time; Ctrl-C stops and writes what was recorded)")
    return None


def _advance_sample(sim: Simulator, per: int, bar, request) -> tuple[str | None, bool]:
    """Advance ``sim`` by ``per`` steps in chunks of at most :data:`CHUNK_STEPS`; (the breakdown report or None,
    whether a stop was requested), after the chunk in which either happened."""
    left = per
    while left > 0:
        k = min(left, CHUNK_STEPS)
        try:
            sim.step(n_steps=k)
        except SimulationError as err:
            return str(err), False
        left -= k
        if bar:
            bar.update(k * sim.settings.dt)
        if request is not None and request.requested:
            return None, True
    return None, False


def _add_last_good(sim: Simulator, times: list, frames: list) -> None:
    """Append the simulator's state after a breakdown (the last good one) or a stop (Ctrl-C), between two samples,
    to the record."""
    if sim.t > times[-1]:
        try:
            frame = sim.views()
        except SimulationError:  # a singular mass matrix right there: the last sample stays the last
            return
        times.append(sim.t)
        frames.append(frame)


def _aero_flags(sim: Simulator, views: dict, alpha_range_deg, max_abs_beta_deg) -> np.ndarray:
    """(n, n_wings) True where a wing with an aerodynamic table is outside the accurate alpha / beta band."""
    alpha, beta = np.degrees(views["wing_alpha_rad"]), np.degrees(views["wing_beta_rad"])
    has_table = np.array([sim.assembly.wing(k).aero is not None for k in range(alpha.shape[1])], dtype=bool)
    out = (alpha < alpha_range_deg[0]) | (alpha > alpha_range_deg[1]) | (np.abs(beta) > max_abs_beta_deg)
    return out & has_table


def _ground_flags(ground_height: float, t: np.ndarray, views: dict) -> list[GroundContact]:
    """Add the views ``wing_ground_contact`` and ``node_ground_contact`` (height -z <= ground_height [m]) and
    return the contacts: each body's first sample at or below the ground (and each new one after leaving it)."""
    contacts = []
    for kind, name in (("wing", "wing_position_m"), ("node", "node_position_m")):
        h = -views[name][..., 2]
        below = h <= ground_height
        views[f"{kind}_ground_contact"] = below
        starts = below & ~np.vstack([np.zeros((1, below.shape[1]), dtype=bool), below[:-1]])
        contacts += [GroundContact(float(t[i]), f"{kind} {k}", float(h[i, k])) for i, k in np.argwhere(starts)]
    return sorted(contacts)
