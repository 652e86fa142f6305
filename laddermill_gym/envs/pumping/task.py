"""The pumping-kite task shared by the single and the vector environments: B copies of one wing on a winch tether
(``kernels/winch.py``) stepped by the wings' step-and-observe kernel (``kernels/rigid/observe.py``, which runs on
the winch kinds unchanged: the winch block follows the bodies), with tail and winch actions, the wing and winch
observation, net-electrical-power rewards, terminations and wind disturbances around it.

A single environment is the task with B = 1, so single and vector environments run the same code.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from laddermill_gym.atmosphere.disturbance_spec import parse_disturbances
from laddermill_gym.atmosphere.disturbances import (
    DirectionStep,
    grid_geometry,
    sample_wind_field,
)
from laddermill_gym.envs.actions import clip_actions
from laddermill_gym.envs.pumping.actions import PumpingActionMap
from laddermill_gym.envs.pumping.evaluate import evaluate_copies, failure_text
from laddermill_gym.envs.pumping.observation import N_OBS, WINCH_OBS_INDEX, pumping_observation_bounds
from laddermill_gym.envs.pumping.settings import (
    PUMPING_FAILURES,
    InitialNoise,
    PumpingRewardConfig,
    TerminationConfig,
)
from laddermill_gym.envs.pumping.winch_scene import PumpingScene, WinchSimulator, electrical_energy, load_pumping
from laddermill_gym.envs.task import config_from
from laddermill_gym.kernels.contract import (
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_VEL,
    N_CONTROLS,
    SX_ENERGY,
    SX_MOVED,
    SX_SPEED,
    TM_DT,
    TM_T0,
)
from laddermill_gym.kernels.rigid.observe import (
    AUX_GROUND_START,
    N_AUX,
    step_observe_batch,
    step_observe_serial,
)
from laddermill_gym.kernels.wind import modulation, wind_point
from laddermill_gym.model.states import rotations_from_quaternions
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.simulator import FIXED_STEP_METHODS

__all__ = ["PumpingTask", "pumping_start"]


def _positive(name: str, v, unit: str) -> float:
    if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {v!r}: must be a finite number > 0 {unit}")
    return float(v)


@functools.lru_cache(maxsize=8)
def pumping_start(config: str, options: tuple) -> tuple[PumpingScene, np.ndarray, np.ndarray]:
    """(pumping scene, initial state, initial controls) of a pumping config with ``load_scene`` overrides
    ``options`` (sorted (key, value) pairs), memoised per process (the trim takes seconds). Read-only arrays."""
    ps = load_pumping(config, **dict(options))
    x, u = ps.initial_state()
    x.setflags(write=False)
    u.setflags(write=False)
    return ps, x, u


class PumpingTask:
    """B copies of the pumping kite as an RL task (arguments: :class:`PumpingKiteEnv
    <laddermill_gym.envs.pumping.env.PumpingKiteEnv>`; ``n_copies`` = B, ``parallel``: numba's thread pool, default
    from 32 copies on).

    Attributes (B copies): ``obs`` (B, 20) clipped observations, ``raw_obs`` unclipped, ``aux`` (B, N_AUX) kernel
    read-outs, ``pumping`` the :class:`~laddermill_gym.envs.pumping.winch_scene.PumpingScene`, ``scene`` its plain
    scene, ``x_trim`` / ``u_trim`` the start state and controls, ``nominal`` (1, 3) the start CG position [m],
    ``energy_start`` (B,) drum energy at the start of the last control period [J], ``batch`` the
    :class:`~laddermill_gym.sim.batch.BatchSimulator`.
    """

    failure_names = PUMPING_FAILURES

    def __init__(self, n_copies: int = 1, config: str = "pumping_kite", scene_options: dict | None = None,
                 control_dt: float = 0.05, episode_time: float = 400.0, initial_noise=None, disturbances=None,
                 wind_dt: float = 0.1, reward=None, termination=None, parallel: bool | None = None):
        if isinstance(n_copies, bool) or int(n_copies) != n_copies or n_copies < 1:
            raise ValueError(f"n_copies = {n_copies!r}: must be a positive integer")
        self.control_dt = _positive("control_dt", control_dt, "s")
        self.episode_time = _positive("episode_time", episode_time, "s")
        self.wind_dt = _positive("wind_dt", wind_dt, "s")
        self.disturbances = parse_disturbances(disturbances, (DirectionStep(),))
        self.reward_config = config_from(reward, PumpingRewardConfig, "reward")
        self.termination_config = config_from(termination, TerminationConfig, "termination")
        self.initial_noise = config_from(initial_noise, InitialNoise, "initial_noise")
        options = dict(scene_options or {})
        if options.get("dimension", 3) != 3:
            raise ValueError(f"scene_options: dimension = {options['dimension']!r}; PumpingKite is 3D")
        self.pumping, x0, u0 = pumping_start(str(config), tuple(sorted(options.items())))
        self.scene = sc = self.pumping.scene
        if sc.settings.method not in FIXED_STEP_METHODS:
            raise ValueError(f"scene {sc.name}: integrator.method = {sc.settings.method!r}; environments step with a "
                             f"fixed-step method, one of {FIXED_STEP_METHODS}")
        dt = sc.settings.dt
        self.n_substeps = int(round(self.control_dt / dt))
        if self.n_substeps < 1 or abs(self.n_substeps * dt - self.control_dt) > 1e-9 * self.control_dt:
            raise ValueError(f"control_dt = {control_dt!r} s is not a whole multiple of the physics step {dt!r} s")
        self.n_steps_max = int(round(self.episode_time / self.control_dt))
        self.x_trim, self.u_trim = x0, u0
        asm = self.pumping.assembly
        self.winch = asm.station
        self.n_wings = 1
        self.n_copies = B = int(n_copies)
        self.parallel = B >= 32 if parallel is None else bool(parallel)
        self._kernel = step_observe_batch if self.parallel else step_observe_serial
        n_mod = int(math.ceil(self.episode_time / self.wind_dt - 1e-9)) + 1
        geom = grid_geometry(self.disturbances, self.episode_time)  # a spatial disturbance's gust grid (turbulence)
        self.batch = BatchSimulator(asm, B, sc.settings, n_modulation=max(2, n_mod),
                                    n_grid=0 if geom is None else geom.floats)
        self.xoff = asm.body_state_size
        self.nominal = np.array(x0[B3_POS: B3_POS + 3], dtype=float).reshape(1, 3)
        self.below = np.array([sc.layout.piece_elements[0][-1]], dtype=np.int64)
        self.ground = np.array([0, -1], dtype=np.int64)
        self.actions = PumpingActionMap(asm.wing(0).control_limits, u0[:N_CONTROLS], self.winch)
        self.n_actions = self.actions.n_actions
        self.obs_dim = N_OBS
        self.wing_obs = np.zeros((B, N_OBS - len(WINCH_OBS_INDEX)))
        self.raw_obs = np.zeros((B, N_OBS))
        self.obs = np.zeros((B, N_OBS))
        self.aux = np.zeros((B, N_AUX))
        self.electrical_energy = np.zeros(B)
        self._dx = np.zeros((B, asm.state_size))
        self._nsteps = np.zeros(B, dtype=np.int64)
        self.energy_start = np.zeros(B)
        self.steps = np.zeros(B, dtype=np.int64)
        self.last_action = np.zeros((B, self.n_actions))
        self.obs_low, self.obs_high = pumping_observation_bounds(sc, self.pumping.cycle.reel_length)
        cyc = self.pumping.cycle
        #: drum capacity [m]: a commanded winch pays out no further than Delta L + 2 depower overruns
        self.max_paid_out = cyc.reel_length + 2.0 * cyc.depower_overrun
        rc, tc = self.reward_config, self.termination_config
        self.lateral_scale = rc.lateral_scale if rc.lateral_scale is not None else 0.05 * sc.piece_length
        self.min_altitude = tc.min_altitude if tc.min_altitude is not None else 0.5 * asm.wing(0).span
        self.breaking_tension = tc.breaking_factor * sc.cable.breaking_load
        self.alpha_lo, self.alpha_hi = np.radians(tc.alpha_range_deg)
        self.beta_max = math.radians(tc.max_abs_beta_deg)
        self._rotation0 = rotations_from_quaternions(x0[B3_QUAT: B3_QUAT + 4].reshape(1, 4))[0]
        self.batch.states[:] = x0
        self.batch.controls[:] = u0

    # ------------------------------------------------------------------ kernel
    def _run(self, nsteps: np.ndarray) -> None:
        """Advance copy b by nsteps[b] RK4 steps (0: observe only, < 0: skip), then compose the observations."""
        b = self.batch
        b.advance(nsteps, lambda dt, ns: self._kernel(
            b.t, b.states, b.controls, dt, ns, *b.detached, b.work, b.air, b.limits, b.tableau, b.breaks,
            self._dx, self.nominal, self.below, self.ground, self.wing_obs, self.aux, b.status, b.done))
        self._compose()

    def _wind(self, i: int) -> tuple[float, float]:
        """(along-tether wind [m/s], wind speed [m/s]) at copy i's wing CG now (its own air)."""
        b, m = self.batch, self.batch.model
        x, t = b.states[i], float(b.t[i])
        a = b.air
        s, d, _, _ = modulation(t, a.tmod[i, TM_T0], a.tmod[i, TM_DT], a.ms[i], a.md[i])
        gp = None if a.gp is None else a.gp[i]
        gv = None if a.gv is None else a.gv[i]
        p = x[B3_POS: B3_POS + 3]  # the wing's CG, body 0
        w = np.array(wind_point(p[0], p[1], p[2], t, m.wf, s, d, gp, gv))
        r = p - b.assembly.fixed_points[0]
        return float(w @ r / max(np.linalg.norm(r), 1e-9)), float(np.linalg.norm(w))

    def _compose(self) -> None:
        """raw_obs from the kernel's wing row and the winch read-outs; obs = raw_obs clipped to the bounds
        (non-finite: the bound)."""
        x = self.batch.states
        ro, i = self.raw_obs, WINCH_OBS_INDEX
        ro[:, : self.wing_obs.shape[1]] = self.wing_obs
        ro[:, i["winch_speed"]] = x[:, self.xoff + SX_SPEED]
        ro[:, i["paid_out"]] = x[:, self.xoff + SX_MOVED]
        ro[:, i["drum_tension"]] = self.aux[:, AUX_GROUND_START]
        for c in range(self.n_copies):
            ro[c, i["radial_wind"]], ro[c, i["wind_speed"]] = self._wind(c)
        lo, hi = self.obs_low, self.obs_high
        np.clip(np.where(np.isfinite(ro), ro, np.where(ro < 0, lo, hi)), lo, hi, out=self.obs)

    def observe(self) -> None:
        """Observe every copy at its current state without stepping (after restoring states by hand)."""
        self._nsteps[:] = 0
        self._run(self._nsteps)

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by ``mask`` (B,): the trim at the start of reel-out (plus the
        initial noise), its controls, t = 0, a fresh wind disturbance, drawn with ``rngs[b]`` (first the
        disturbances, then the noise), and observe them. Other copies are untouched."""
        b, noise = self.batch, self.initial_noise
        idx = np.flatnonzero(mask)
        scale = np.array([noise.lateral_velocity, noise.roll_rate, noise.yaw_rate])
        for i in idx:
            rng = rngs[i]
            b.set_wind(int(i), sample_wind_field(self.disturbances, self.episode_time, self.wind_dt, rng))
            x = np.array(self.x_trim)
            if np.any(scale > 0):
                d = rng.normal(size=3) * scale  # (global lateral velocity, roll rate, yaw rate)
                x[B3_VEL: B3_VEL + 3] += self._rotation0[1, :] * d[0]  # R^T (0, dvy, 0)
                x[B3_RATE] += d[1]
                x[B3_RATE + 2] += d[2]
            b.states[i] = x
        b.controls[idx] = self.u_trim
        b.t[idx] = 0.0
        self.steps[idx] = 0
        self.last_action[idx] = 0.0
        self._nsteps[:] = -1
        self._nsteps[idx] = 0
        self._run(self._nsteps)

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """Apply normalised actions (B, 4) for one control period to the copies in ``mask`` (default all) and
        evaluate them: (reward (B,), terminated (B,), truncated (B,), info dict of (B,) arrays)
        (:func:`~laddermill_gym.envs.pumping.evaluate.evaluate_copies`)."""
        a, n_clipped = clip_actions(action, self.n_copies, self.n_actions)
        b = self.batch
        sel = np.ones(self.n_copies, bool) if mask is None else np.asarray(mask, bool)
        u = self.actions.controls(a)
        if self.winch.mode == "commanded":  # a full drum pays out no more (the cycle's Delta L + 2 overruns)
            full = b.states[:, self.xoff + SX_MOVED] >= self.max_paid_out
            u[full, -1] = np.minimum(u[full, -1], 0.0)
        b.controls[sel] = u[sel]
        self.last_action[sel] = a[sel]
        self.energy_start[:] = b.states[:, self.xoff + SX_ENERGY]
        self._nsteps[:] = -1
        self._nsteps[sel] = self.n_substeps
        self._run(self._nsteps)
        de = b.states[:, self.xoff + SX_ENERGY] - self.energy_start
        self.electrical_energy[:] = electrical_energy(de, self.winch.efficiency)
        self.steps[sel] += 1
        return evaluate_copies(self, a, n_clipped)

    # ------------------------------------------------------------------ read-outs
    def simulator(self, b: int = 0) -> WinchSimulator:
        """A :class:`~laddermill_gym.envs.pumping.winch_scene.WinchSimulator` of copy ``b`` (a snapshot of its state,
        time [s], controls and air)."""
        bt = self.batch
        sim = WinchSimulator(bt.assembly, bt.states[b], bt.settings, bt.controls[b])
        air = {f: a[b].copy() for f, a in zip(bt.air._fields, bt.air, strict=True) if a is not None}
        sim.model = sim.model._replace(**air)
        sim.reset(state=bt.states[b], t=float(bt.t[b]), controls=bt.controls[b])
        return sim

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
        return failure_text(self, b, code)

    def renderer(self, interactive: bool = False):
        """The wing envs' side and top views (``envs/render.py``)."""
        from laddermill_gym.envs.render import SceneRenderer

        return SceneRenderer(self, interactive)
