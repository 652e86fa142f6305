"""Closed-loop runs of a controller directly on the simulator (no environment): the paper's disturbance, a
step in wind direction, with the controller sampled at its control period and its output held (ZOH)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from laddermill_gym.control.base import Controller, control_ranges, controls_from_actions, elements_below_wings, observe
from laddermill_gym.ladder.scene import Scene
from laddermill_gym.sim.simulator import SimulationError

__all__ = ["Rollout", "with_direction_step", "run_direction_step"]


@dataclass(frozen=True)
class Rollout:
    """Sampled history of a closed-loop run (one row per control period).

    t : (n,) [s];  positions : (n, n_wings, 3) [m];  euler : (n, n_wings, 3) [rad] (phi, theta, psi);
    actions : (n, 3 n_wings) normalised actions applied from t on;  clipped_fraction : share of action
    entries the controller clipped (if it counts them, else nan);  error : why the run stopped early ('' if
    it did not).
    """

    t: np.ndarray
    positions: np.ndarray
    euler: np.ndarray
    actions: np.ndarray
    clipped_fraction: float
    error: str

    @property
    def completed(self) -> bool:
        return not self.error


def with_direction_step(scene: Scene, step: float, step_time: float = 1.0) -> Scene:
    """The scene with a wind-direction step of ``step`` [rad] at ``step_time`` [s] (a 1 ms ramp, as
    ``laddermill simulate --direction-step``)."""
    asm = scene.assembly
    wind = asm.wind.with_modulation(step_time - 1e-3, 1e-3, np.ones(2), np.array([0.0, step]))
    return scene.replace(assembly=dataclasses.replace(asm, wind=wind))


def run_direction_step(scene: Scene, x_trim: np.ndarray, u_trim: np.ndarray, controller: Controller,
                       t_end: float, control_period: float = 0.05, step: float = 0.01,
                       step_time: float = 1.0) -> Rollout:
    """Start at the trim, apply the wind-direction step, and run ``controller`` at ``control_period`` [s] until
    ``t_end`` [s] or until the integration breaks down (then ``error`` says why).

    Observations come from the environments' observation kernel on the simulator's state
    (:func:`~laddermill_gym.control.base.observe`), so a 3D scene is needed; the scene's integrator step must
    divide the period.
    """
    sc = with_direction_step(scene, step, step_time)
    sim = sc.simulator(x_trim, u_trim)
    n_sub = int(round(control_period / sc.settings.dt))
    if n_sub < 1 or abs(n_sub * sc.settings.dt - control_period) > 1e-9:
        raise ValueError(f"control period {control_period} s is not a multiple of the integrator step "
                         f"{sc.settings.dt} s")
    nominal = sim.wing_positions()
    below = elements_below_wings(sc.layout, sc.assembly.n_wings)
    mid, half = control_ranges(sc.assembly)
    if hasattr(controller, "reset_clip_count"):
        controller.reset_clip_count()
    ts, pos, eul, acts = [], [], [], []
    error = ""
    n_steps = int(round(t_end / control_period))
    for _ in range(n_steps + 1):
        ts.append(sim.t)
        pos.append(sim.wing_positions())
        eul.append(sim.wing_euler())
        a, _ = controller.predict(observe(sim, nominal, below), deterministic=True)
        acts.append(np.asarray(a, dtype=float))
        if len(ts) > n_steps:
            break
        try:
            sim.step(controls_from_actions(a, mid, half), n_sub)
        except SimulationError as err:
            error = str(err)
            break
    clipped = (controller.n_clipped / controller.n_actions
               if getattr(controller, "n_actions", 0) else float("nan"))
    return Rollout(t=np.array(ts), positions=np.array(pos), euler=np.array(eul), actions=np.array(acts),
                   clipped_fraction=float(clipped), error=error)
