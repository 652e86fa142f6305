"""The work-precision study's closed-loop forcings (``laddermill work-precision SCENE --controller lqr``): the
same forcing with the wings held by the package's lateral LQR, sampled at the environments' control period and
held in between (zero-order hold), so that the errors are those of what a controlled system does.

Open loop, the chain's and the mill's slow lateral modes after the direction step are unstable (growth up to
6.4 1/s, ``whip_spectrum.py``): any integrator's local error is amplified. The closed loop stabilises them, so the
same error measures (``controller_errors.py``) judge the integrators on a system whose errors do not grow by
themselves. This adds a measure: the open-loop rows stay (``--controller none``, the default).

The design is the package's own for each scene (``LQR_CONFIGS``): ``control.lqr.design_tethered_wing`` for the
single wing, ``control.lqr.design_ladder_chain`` with a centralised config for the chain and for the mill's scene
(the mill's weights, ``configs/agents/lqr_laddermill.yaml``; linearised at the study's start, the static
equilibrium at rest, not at LadderMill-v0's moving operating point). The feedback reads the lateral coordinates
(y, vy, phi, psi, p, r per wing: ``control.linearize``) from the state, u = u_trim - K (z - z_trim) on rudder and
aileron, clipped to the control limits as the environments clip their actions; elevators keep their trim.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.control.base import actions_from_controls, control_ranges, controls_from_actions
from laddermill_gym.control.linearize import LATERAL_INPUTS, lateral_indices, minimal_from_full
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.model.params import N_CONTROLS
from laddermill_gym.sim.simulator import ADAPTIVE_METHODS

#: the controllers of ``--controller``: ``none`` the open loop (controls held at the start's), ``lqr`` the LQR
CONTROLLERS = ("none", "lqr")
_AGENTS = CONFIG_DIR / "agents"  # the shipped configs, in a checkout and in an installed wheel alike
#: the LQR config of each scene the closed loop runs on (the scene's file stem)
LQR_CONFIGS = {"tethered_wing": _AGENTS / "lqr_tethered_wing.yaml",
               "ladder_chain": _AGENTS / "lqr_ladder_chain_central.yaml",
               "laddermill": _AGENTS / "lqr_laddermill.yaml"}


def check_controller(name: str) -> str:
    """``name`` if it is one of :data:`CONTROLLERS`, else ValueError naming it."""
    if name not in CONTROLLERS:
        raise ValueError(f"controller = {name!r}: must be one of {', '.join(CONTROLLERS)}")
    return name


@dataclass(frozen=True)
class Feedback:
    """A lateral state feedback held over each control period.

    gain (2 n_wings, 6 n_wings) [rad per unit lateral state]; lateral (6 n_wings,) indices of the wings' lateral
    coordinates among the minimal ones; z_trim (6 n_wings,) their trim values; u_trim (3 n_wings,) [rad]; mid,
    half (3 n_wings,) the control ranges' centres and half widths [rad]; period [s] the control period;
    design_s [s] the design's wall time; config the LQR config's path."""

    gain: np.ndarray
    lateral: np.ndarray
    z_trim: np.ndarray
    u_trim: np.ndarray
    mid: np.ndarray
    half: np.ndarray
    period: float
    design_s: float
    config: str

    def controls(self, asm, x: np.ndarray) -> np.ndarray:
        """Controls (3 n_wings,) [rad] for state ``x`` of assembly ``asm``: trim less K dz on rudder and aileron
        (the yaw difference wrapped into [-pi, pi)), clipped to the limits."""
        dz = minimal_from_full(asm, x)[self.lateral] - self.z_trim
        nw = self.u_trim.size // N_CONTROLS
        dz.reshape(nw, 6)[:, 3] = (dz.reshape(nw, 6)[:, 3] + np.pi) % (2 * np.pi) - np.pi
        u = self.u_trim.reshape(nw, N_CONTROLS).copy()
        u[:, list(LATERAL_INPUTS)] -= (self.gain @ dz).reshape(nw, len(LATERAL_INPUTS))
        return controls_from_actions(actions_from_controls(u.reshape(-1), self.mid, self.half), self.mid, self.half)


def design_feedback(scene: str, sim, controller: str) -> Feedback | None:
    """The feedback of ``controller`` for ``scene`` (a name or YAML path: its stem picks the config of
    :data:`LQR_CONFIGS`), designed at ``sim``'s initial state and controls; None for ``none``. ValueError naming
    the controller, or the scene when it has no LQR config."""
    from laddermill_gym.control.lqr import design_ladder_chain, design_tethered_wing, full_gain, load_lqr_config
    from laddermill_gym.ladder.scene import load_scene

    if check_controller(controller) == "none":
        return None
    stem = Path(scene).stem
    if stem not in LQR_CONFIGS:
        raise ValueError(f"scene {scene!r}: no LQR design for the closed loop (--controller lqr runs on "
                         f"{', '.join(LQR_CONFIGS)})")
    t0 = time.perf_counter()
    cfg = load_lqr_config(LQR_CONFIGS[stem])
    sc = load_scene(scene)  # the study's scene as it runs it (build_simulator), whatever the config's division
    x, u = sim.initial_state.copy(), sim.initial_controls.copy()
    if sc.assembly.n_wings == 1:
        gains = design_tethered_wing(cfg, sc, trim=(x, u)).lqr.K[None]
    else:
        gains = design_ladder_chain(cfg, sc, trim=(x, u)).gains
    asm = sim.assembly
    lat = lateral_indices(asm.n_wings, 0)
    mid, half = control_ranges(asm)
    return Feedback(gain=full_gain(gains), lateral=lat, z_trim=minimal_from_full(asm, x)[lat], u_trim=u, mid=mid,
                    half=half, period=cfg.control_period, design_s=time.perf_counter() - t0, config=str(cfg.file))


def periods_per_sample(times: np.ndarray, period: float) -> int:
    """Control periods between the equally spaced output ``times`` [s]; ValueError unless a whole number."""
    m = int(round((times[1] - times[0]) / period))
    if m < 1 or abs(m * period - (times[1] - times[0])) > 1e-9:
        raise ValueError(f"the output spacing {times[1] - times[0]:g} s is not a multiple of the control period "
                         f"{period:g} s: choose --samples so that --time / --samples is one")
    return m


def closed_loop_trajectory(sim, times: np.ndarray, method: str, value: float, fb: Feedback, positions,
                           clock: dict | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Run ``sim`` under the feedback ``fb`` through ``times`` [s] (fixed-step methods: steps of ``value`` [s],
    which must divide the control period; error-controlled ones: tolerance ``value``, stopping on every control
    time); (states (n, n_state), ``positions(sim)`` (n, ...)) at the times. SimulationError when it breaks
    down. ``clock``: a dict whose "wall" and "cpu" [s] are set to the time spent in the feedback (the same for
    every method: the controller's, not the integrator's); the controls, within their limits by construction,
    are set without the simulator's per-wing check."""
    per = periods_per_sample(times, fb.period)
    adaptive = method in ADAPTIVE_METHODS
    n_sub = 0 if adaptive else int(round(fb.period / value))
    if not adaptive and (n_sub < 1 or abs(n_sub * value - fb.period) > 1e-9):
        raise ValueError(f"{method} step {value} s does not divide the control period {fb.period} s")
    xs, ps = [sim.state.copy()], [positions(sim)]
    asm = sim.assembly
    wall = cpu = 0.0
    for k in range(per * (len(times) - 1)):
        t0, c0 = time.perf_counter(), time.process_time()
        sim.controls = fb.controls(asm, sim.state)
        wall, cpu = wall + time.perf_counter() - t0, cpu + time.process_time() - c0
        if adaptive:
            sim.advance_to((k + 1) * fb.period, rtol=value, atol=value)
        else:
            sim.step(None, n_sub)
        if (k + 1) % per == 0:
            xs.append(sim.state.copy())
            ps.append(positions(sim))
    if clock is not None:
        clock.update(wall=wall, cpu=cpu)
    return np.array(xs), np.array(ps)


def closed_loop_reference(sim, times: np.ndarray, fb: Feedback, method: str, tol: float) -> np.ndarray:
    """States at ``times`` of the closed loop integrated by scipy's ``method`` at rtol = atol = ``tol`` on
    ``sim.rhs`` (an implementation independent of the simulator's steppers), one control period at a time with
    its held controls, piece by piece between the wind's kinks (``precision.piecewise_reference``)."""
    from laddermill_gym.studies.numerics.precision import piecewise_reference

    per = periods_per_sample(times, fb.period)
    x = sim.state.copy()
    out = [x.copy()]
    kinks = sim.breakpoint_times
    for k in range(per * (len(times) - 1)):
        u = fb.controls(sim.assembly, x)
        span = np.array([k * fb.period, (k + 1) * fb.period])
        x = piecewise_reference(lambda t, y, u=u: sim.rhs(t, y, u), x, span, kinks, method, tol)[-1]
        if (k + 1) % per == 0:
            out.append(x.copy())
    return np.array(out)
