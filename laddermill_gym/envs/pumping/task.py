"""The pumping-kite task shared by the single and the vector environments: B copies of one wing on a winch tether
(``kernels/winch.py``) stepped by the wings' step-and-observe kernel (``kernels/rigid/observe.py``, which runs on
the winch kinds unchanged: the winch block follows the bodies), with tail and winch actions, the wing and winch
observation, net-electrical-power rewards, terminations and wind disturbances around it.

A single environment is the task with B = 1, so single and vector environments run the same code.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.actions import clip_actions
from laddermill_gym.envs.observation import wing_lateral_offsets
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
from laddermill_gym.envs.task_base import TaskCore, clip_observations, substeps_per_period
from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, N_CONTROLS, SX_ENERGY, SX_MOVED, SX_SPEED, TM_DT, TM_T0
from laddermill_gym.kernels.rigid.observe import (
    AUX_GROUND_START,
    N_AUX,
    launch_step_observe,
    step_observe_serial,
)
from laddermill_gym.kernels.wind import modulation, wind_point
from laddermill_gym.ladder.scene import options_key, options_kwargs
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.model.states import rotations_from_quaternions

__all__ = ["PumpingTask", "pumping_start"]


@input_cache(maxsize=8)
def pumping_start(config: str, options: tuple) -> tuple[PumpingScene, np.ndarray, np.ndarray]:
    """(pumping scene, initial state, initial controls) of a pumping config with ``load_scene`` overrides
    ``options`` (``ladder.scene.options_key``: sorted pairs, nested mappings as JSON), memoised per process (the
    trim takes seconds). Read-only arrays."""
    ps = load_pumping(config, **options_kwargs(options))
    x, u = ps.initial_state()
    x.setflags(write=False)
    u.setflags(write=False)
    return ps, x, u


class PumpingTask(TaskCore):
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
    env_name = "PumpingKite"
    reward_class, termination_class, noise_class = PumpingRewardConfig, TerminationConfig, InitialNoise

    def __init__(self, n_copies: int = 1, config: str = "pumping_kite", scene_options: dict | None = None,
                 control_dt: float = 0.05, episode_time: float = 400.0, initial_noise=None, disturbances=None,
                 wind_dt: float = 0.1, reward=None, termination=None, parallel: bool | None = None):
        B = self._common_arguments(n_copies, control_dt, episode_time, wind_dt, disturbances, reward, termination,
                                   initial_noise)
        options = dict(scene_options or {})
        if options.get("dimension", 3) != 3:
            raise ValueError(f"scene_options: dimension = {options['dimension']!r}; PumpingKite is 3D")
        self.pumping, x0, u0 = pumping_start(str(config), options_key(options))
        self.scene = sc = self.pumping.scene
        self.n_substeps = substeps_per_period(sc.name, sc.settings, self.control_dt, control_dt)
        self.x_trim, self.u_trim = x0, u0
        asm = self.pumping.assembly
        self._check_turbulence_cover(asm, x0)
        self.winch = asm.station
        self.n_wings = 1
        self._make_batch(B, asm, sc.settings, parallel, step_observe_serial, launch_step_observe)
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
        self.energy_start = np.zeros(B)
        self.last_action = np.zeros((B, self.n_actions))
        self.obs_low, self.obs_high = pumping_observation_bounds(sc, self.pumping.cycle.reel_length)
        cyc = self.pumping.cycle
        #: drum capacity [m]: a commanded winch pays out no further than Delta L + 2 depower overruns
        self.max_paid_out = cyc.reel_length + 2.0 * cyc.depower_overrun
        self._wing_limits(sc, asm.wing(0).span)
        start = -float(x0[B3_POS + 2])  # [m] the start's CG altitude
        if self.min_altitude >= start:
            raise ValueError(f"termination.min_altitude = {self.min_altitude:g} m: at or above the start's CG altitude "
                             f"{start:.2f} m, so every episode would end on its first step")
        self._rotation0 = rotations_from_quaternions(x0[B3_QUAT: B3_QUAT + 4].reshape(1, 4))
        self.batch.states[:] = x0
        self.batch.controls[:] = u0

    # ------------------------------------------------------------------ kernel
    def _run(self, nsteps: np.ndarray) -> None:
        """Advance copy b by nsteps[b] RK4 steps (0: observe only, < 0: skip), then compose the observations."""
        self._wing_kernel_pass(nsteps, self.nominal, self.wing_obs)
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
        clip_observations(ro, self.obs_low, self.obs_high, self.obs)

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by ``mask`` (B,): the trim at the start of reel-out (plus the
        initial noise), its controls, t = 0, a fresh wind disturbance, drawn with ``rngs[b]`` (first the
        disturbances, then the noise), and observe them. Other copies are untouched."""
        self._reset_copies(mask, rngs, self.x_trim, self.u_trim, self._rotation0, 0.0)

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
        self._advance_copies(sel)
        de = b.states[:, self.xoff + SX_ENERGY] - self.energy_start
        self.electrical_energy[:] = electrical_energy(de, self.winch.efficiency)
        return evaluate_copies(self, a, n_clipped)

    # ------------------------------------------------------------------ read-outs
    def simulator(self, b: int = 0) -> WinchSimulator:
        """A :class:`~laddermill_gym.envs.pumping.winch_scene.WinchSimulator` of copy ``b`` (a snapshot of its state,
        time [s], controls and air)."""
        return self._snapshot_simulator(WinchSimulator, b, check=False)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m] (B, 1) of observations (B, 20)."""
        return wing_lateral_offsets(obs, 1)

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
        return failure_text(self, b, code)

    def renderer(self, interactive: bool = False):
        """The wing envs' side and top views (``envs/render.py``)."""
        from laddermill_gym.envs.render import SceneRenderer

        return SceneRenderer(self, interactive)
