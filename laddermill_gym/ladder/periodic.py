"""The laddermill's periodic stationary motion: run a moving-cable simulator period by period until it repeats.

With a constant cable speed V_c the mill's motion, once the transients have died out, repeats with the period
l0 / V_c: every transfer shifts the wings one slot and the state returns to the same shape, slot by slot
(Meijaard et al. 1999: "the resulting motion is periodic"). :func:`run_to_periodic` steps the simulator one
period at a time, starting at a transfer, so that successive samples are at the same phase, and stops when

* the shape repeats: the largest change of any wing's CG position between two successive periods, over the
  piece length, is below ``shape_tol``, and
* the power repeats: the mean generator power of a period (energy delivered in it / period) differs from the
  previous period's by less than ``power_tol`` relative,

for ``confirm`` periods in a row; or gives up after ``max_time`` seconds and says so (``converged`` False, with
the history, never silently).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.model.station import electrical_power
from laddermill_gym.sim.overload import BREAKING_FRACTION, Overload, OverloadWatch, tension_limits
from laddermill_gym.sim.simulator import SimulationError, Simulator


@dataclass
class PeriodicResult:
    """What :func:`run_to_periodic` found.

    converged : both criteria held for ``confirm`` successive periods.
    period_s : l0 / V_c [s].  t_s : simulated time at the end [s].
    mean_power_W : mean mechanical generator power over the last period [W].
    mean_electrical_power_W : the same through the station's efficiency (``model/station.electrical_power``) [W].
    tension_mean_N, tension_min_N, tension_max_N : per element over the last period (n_elements,) [N].
    shape_m : wing CG positions at the last transfer (n_wings, 3) [m], slot order (slot 0 on the veered side).
    history : per period: time [s], mean power [W], shape change [-], power change [-].
    breakdown : the simulator's report when the integration broke down during the search (the motion is then not
    periodic; power and tensions are those of the last, possibly partial, period), else None.
    overload : the first sample of the search at which an element's tension exceeded ``breaking_fraction`` times its
    breaking load (``sim/overload.py``; time [s], element, tension, limit [N]), else None; the search goes on.
    peak_tension_ratio : the largest tension over that limit in any step of the search [-].
    """

    converged: bool
    period_s: float
    t_s: float
    mean_power_W: float
    mean_electrical_power_W: float
    tension_mean_N: np.ndarray
    tension_min_N: np.ndarray
    tension_max_N: np.ndarray
    shape_m: np.ndarray
    history: list[dict] = field(default_factory=list)
    breakdown: str | None = None
    overload: Overload | None = None
    peak_tension_ratio: float = 0.0

    def summary(self) -> str:
        state = "converged" if self.converged else ("NOT converged (broke down: " + self.breakdown + ")"
                                                     if self.breakdown else "NOT converged")
        last = self.history[-1] if self.history else {}
        return (f"periodic motion {state} at t = {self.t_s:.1f} s (period {self.period_s:.2f} s): mean generator "
                f"power {self.mean_power_W / 1e3:.1f} kW; last shape change {last.get('shape_change', np.nan):.2e} "
                f"l0, power change {last.get('power_change', np.nan):.2e}; " + self.overload_text())

    def overload_text(self) -> str:
        """The cable's strength over the search: the first overload, or the peak tension's share of the limit."""
        if self.overload is not None:
            return f"CABLE OVERLOAD at {self.overload.text()} (peak {self.peak_tension_ratio:.3g} x the limit)"
        return f"no cable overload (peak tension {self.peak_tension_ratio:.3g} x the limit)"


def advance_to_transfer(sim: Simulator, max_steps: int) -> None:
    """Step until the transfer count changes (the state is then just after a transfer); RuntimeError naming the
    time and the cable speed when none comes within ``max_steps``, ValueError for a scene without a station."""
    n0 = sim.transfers()
    for _ in range(max_steps):
        sim.step()
        if sim.transfers() != n0:
            return
    raise RuntimeError(f"t = {sim.t:.3f} s: no wing transfer within {max_steps} steps; is the cable moving "
                       f"(V_c = {sim.cable_speed():.4g} m/s)?")


def _tensions_at(sim: Simulator, samples: list, watch: OverloadWatch) -> list[np.ndarray]:
    """The element tensions [N] of ``sim``'s model at each recorded (time [s], state) of ``samples`` (its
    controls), each shown to ``watch``."""
    out = []
    for t, x in samples:
        sim.rhs(t, x)
        out.append(sim.work.tension[: sim.assembly.elements.count].copy())
        watch.see(t, out[-1])
    return out


def _one_period(sim: Simulator, per_steps: int, period: float, watch: OverloadWatch | None) -> tuple[list, str | None]:
    """Step ``sim`` to the next transfer (at most ``per_steps`` steps): (per step its tensions, shown to ``watch``,
    or, with ``watch`` None, its (time, state copy); the simulator's report if the integration broke down, else
    None). RuntimeError when no transfer comes within the steps (two periods of ``period`` [s])."""
    n0 = sim.transfers()
    samples = []
    for _ in range(per_steps):
        try:
            sim.step()
        except SimulationError as err:  # a motion that diverges is reported, not periodic
            return samples, str(err)
        if watch is not None:
            samples.append(sim.tensions())
            watch.see(sim.t, samples[-1])
        else:
            samples.append((sim.t, sim.state.copy()))
        if sim.transfers() != n0:
            return samples, None
    raise RuntimeError(f"t = {sim.t:.3f} s: no transfer within two periods ({2 * period:.1f} s)")


def run_to_periodic(sim: Simulator, shape_tol: float = 1e-2, power_tol: float = 1e-2, confirm: int = 2,
                    max_time: float = 3000.0, progress: bool = True,
                    breaking_fraction: float = BREAKING_FRACTION, watch_every_period: bool = True) -> PeriodicResult:
    """Run ``sim`` (a moving cable with a prescribed speed that is constant from now on, or a drum held at a
    constant speed by its torque) to its periodic stationary motion; see the module docstring for the criteria.
    The period is l0 / V_c with the speed at the start of the search. Tensions are sampled every step and checked
    against ``breaking_fraction`` [-] times the cable's breaking load (``PeriodicResult.overload``).

    ``watch_every_period`` False: the tensions (one right-hand side each, a quarter of an RK4 step) are evaluated
    only for the steps of the last period, from their recorded (time, state), after the search: the same bits of
    ``tension_*_N`` (the right-hand side is a function of t, x, u alone), but ``overload`` and
    ``peak_tension_ratio`` then cover the last period only (the operating point's use: it reads neither)."""
    st = sim.assembly.station
    if st is None:
        raise ValueError("run_to_periodic needs a moving cable (a scene with a station)")
    if st.mode == "prescribed" and sim.t < st.speed_times[-1]:  # to the end of the schedule's ramp
        sim.step(n_steps=int(np.ceil((st.speed_times[-1] - sim.t) / sim.settings.dt)))
    v = sim.cable_speed()
    if not v > 0:
        raise ValueError(f"cable speed V_c = {v!r} m/s at t = {sim.t} s: the periodic motion needs V_c > 0")
    period = st.piece_length / v
    per_steps = int(np.ceil(2 * period / sim.settings.dt))
    advance_to_transfer(sim, per_steps)
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=int(max_time), desc="periodic motion", unit="s", leave=False)
    t_start = sim.t
    shape, energy, t_prev = sim.wing_positions(), sim.generator_energy(), sim.t
    history: list[dict] = []
    hits, p_prev = 0, np.nan
    ten, breakdown = None, None
    watch = OverloadWatch(tension_limits(sim.assembly, breaking_fraction))
    try:
        while sim.t - t_start < max_time:
            tens, breakdown = _one_period(sim, per_steps, period, watch if watch_every_period else None)
            if tens or ten is None:  # (a breakdown in the first step of a period keeps the last period's tensions)
                now = sim.tensions() if watch_every_period else (sim.t, sim.state.copy())
                ten = tens or [now]
            if breakdown is not None:
                if sim.t > t_prev:
                    p = (sim.generator_energy() - energy) / (sim.t - t_prev)
                    history.append({"t_s": sim.t, "mean_power_W": p, "shape_change": np.nan, "power_change": np.nan})
                shape = sim.wing_positions()
                break
            new_shape, e = sim.wing_positions(), sim.generator_energy()
            p = (e - energy) / (sim.t - t_prev)
            d_shape = float(np.max(np.linalg.norm(new_shape - shape, axis=1)) / st.piece_length)
            d_power = abs(p - p_prev) / max(abs(p), 1e-12)
            history.append({"t_s": sim.t, "mean_power_W": p, "shape_change": d_shape, "power_change": d_power})
            hits = hits + 1 if (d_shape < shape_tol and d_power < power_tol) else 0
            shape, energy, t_prev, p_prev = new_shape, e, sim.t, p
            if bar is not None:
                bar.update(int(sim.t - t_start) - bar.n)
            if hits >= confirm:
                break
    finally:
        if bar is not None:
            bar.close()
    if ten is not None:
        ten = np.array(ten if watch_every_period else _tensions_at(sim, ten, watch))
    p = history[-1]["mean_power_W"] if history else float("nan")
    return PeriodicResult(converged=breakdown is None and hits >= confirm, period_s=period, t_s=sim.t, mean_power_W=p,
                          mean_electrical_power_W=electrical_power(p, st.efficiency), tension_mean_N=ten.mean(axis=0),
                          tension_min_N=ten.min(axis=0), tension_max_N=ten.max(axis=0), shape_m=shape,
                          history=history, breakdown=breakdown, overload=watch.first,
                          peak_tension_ratio=watch.peak_ratio)


def periodic_start(scene, progress: bool = True, shape_tol: float = 1e-3, power_tol: float = 1e-3,
                   max_time: float = 3000.0):
    """The operating point of a moving-cable scene: its in-plane model run to the periodic motion
    (:func:`run_to_periodic`), in the scene's own dimension (a 3D scene gets the in-plane state embedded, which
    the 3D model continues in plane to round-off). Returns (state, controls, time [s], PeriodicResult); the time
    matters because the cable-speed schedule is a function of it. Raises ValueError for a turning wind."""
    import dataclasses

    from laddermill_gym.model.states import planar_to_3d

    a = scene.assembly
    if a.wind.direction_inf != 0.0:
        raise ValueError(f"{scene.file}: the periodic start solves the in-plane mill; wind.direction_inf_rad = "
                         f"{a.wind.direction_inf} must be 0")
    s2 = scene.replace(assembly=dataclasses.replace(a, dim=2)) if a.dim == 3 else scene
    sim = s2.simulator()
    res = run_to_periodic(sim, shape_tol=shape_tol, power_tol=power_tol, max_time=max_time, progress=progress)
    x = sim.state.copy()
    if a.dim == 3:
        nb = s2.assembly.body_state_size
        x = np.concatenate([planar_to_3d(x[:nb], a.n_wings, a.n_nodes), x[nb:]])
    return x, sim.controls.copy(), sim.t, res
