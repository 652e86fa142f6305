"""The laddermill task shared by the single and the vector environments: B copies of the moving-cable mill stepped
by one compiled kernel (the wings' ``kernels/rigid/observe.py`` step-and-observe kernel, which runs on the
moving-cable kinds unchanged), with slot actions, slot observations, generator-power rewards, terminations and
wind disturbances around it.

A single environment is the task with B = 1, so single and vector environments run the same code (same kernel,
same arithmetic per copy).
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np

from laddermill_gym.envs.actions import clip_actions
from laddermill_gym.envs.laddermill import kernel_warmup
from laddermill_gym.envs.laddermill.actions import SlotActionMap, check_authority, check_surfaces, resolve_slot_groups
from laddermill_gym.envs.laddermill.evaluate import evaluate_copies, failure_text
from laddermill_gym.envs.laddermill.gust_extent import LoopExtent, check_turbulence_cover, extent, loop_points
from laddermill_gym.envs.laddermill.observation import (
    N_OBS_PER_SLOT,
    N_STATION_OBS,
    OBS_INDEX,
    STATION_OBS_INDEX,
    mill_observation_bounds,
)
from laddermill_gym.envs.laddermill.operating_point import (
    SEARCH_HOOK,
    OperatingPoint,
    SettleConfig,
    mill_scene,
    nominal_positions,
    operating_point,
    operating_point_pending,
    scene_digest,
)
from laddermill_gym.envs.laddermill.settings import (
    MILL_FAILURES,
    DrumConfig,
    InitialNoise,
    MillRewardConfig,
    SpeedCommandConfig,
    TerminationConfig,
)
from laddermill_gym.envs.observation import wing_lateral_offsets
from laddermill_gym.envs.physics_step import env_physics_settings, jacobian_settings, stable_rk4_step
from laddermill_gym.envs.task import config_from
from laddermill_gym.envs.task_base import TaskCore, clip_observations, substeps_per_period
from laddermill_gym.kernels.contract import B3_QUAT, B3_SIZE, N_CONTROLS, SX_ENERGY, SX_MOVED, SX_SPEED
from laddermill_gym.kernels.rigid.observe import (
    AUX_GROUND_END,
    AUX_GROUND_START,
    N_AUX,
    launch_step_observe,
    step_observe_serial,
)
from laddermill_gym.ladder.scene import options_key
from laddermill_gym.model.params import CONTROL_NAMES
from laddermill_gym.model.states import rotations_from_quaternions
from laddermill_gym.model.station import electrical_power
from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.sim.stable_step import UnstableStepWarning
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["MillTask"]


def _scene_options(scene_options) -> tuple:
    """Sorted (key, value) ``load_scene`` overrides; the env is 3D (a ``dimension`` other than 3 is refused)."""
    options = dict(scene_options or {})
    if options.pop("dimension", 3) != 3:
        raise ValueError(f"scene_options: dimension = {scene_options['dimension']!r}; LadderMill is 3D (the "
                         "operating point is found in plane and mapped to 3D)")
    return options_key(options)


class MillTask(TaskCore):
    """B copies of the moving-cable laddermill as an RL task (arguments: :class:`LadderMillEnv
    <laddermill_gym.envs.laddermill.env.LadderMillEnv>`; ``n_copies`` = B, ``parallel``: threads,
    default from 2 copies on for the mill's thousand-odd states, ``task_base.default_parallel``; ``physics_step``,
    ``physics_dt``: the physics' fixed-step method and step instead of the scene's, ``envs/physics_step.py``; an RK4
    ``physics_dt`` past the step's stability estimate at the operating point is refined, with an UnstableStepWarning;
    ``jacobian_every``: physics steps per iteration matrix of a W-method step, default 1 = every step; k > 1 keeps
    it for k steps, fresh on each episode's first step: same order, other last bits, an opt-in speed option,
    ``envs/physics_step.py`` ``jacobian_settings``).

    Attributes (shapes with B copies, n slots): ``obs`` (B, 15 n + 4) clipped observations, ``raw_obs`` the same
    unclipped, ``aux`` (B, N_AUX) kernel read-outs, ``power`` (B,) electrical generator power [W], ``op`` the
    :class:`~laddermill_gym.envs.laddermill.operating_point.OperatingPoint`, ``p_ref`` [W], ``u_op``
    (n_controls,) operating-point controls, ``energy_start`` (B,) generator energy at the start of the last control
    period [J], ``batch`` the :class:`~laddermill_gym.sim.batch.BatchSimulator`, ``loop_points`` (m, 3) the points
    the loop passes through over a transfer period [m] (wings over the orbit, cable nodes, ground stations:
    :mod:`~laddermill_gym.envs.laddermill.gust_extent`), which a turbulence grid must cover (a RuntimeWarning at
    construction names a grid that does not; :meth:`loop_extent` gives the ranges).
    """

    #: failure code -> name (the SB3 adapter and the evaluation harness read it)
    failure_names = MILL_FAILURES
    env_name = "LadderMill"
    reward_class, termination_class, noise_class = MillRewardConfig, TerminationConfig, InitialNoise

    def __init__(self, n_copies: int = 1, scene: str = "laddermill", scene_options: dict | None = None,
                 control_dt: float = 0.05, episode_time: float = 120.0, groups="per_slot", n_bands: int = 4,
                 surfaces=CONTROL_NAMES, generator_torque: bool = False, drum=None,
                 cable_speed_command: bool = False, speed=None,
                 operating_point: OperatingPoint | None = None, settle=None, initial_noise=None,
                 disturbances=None, wind_dt: float = 0.1, reward=None, termination=None,
                 parallel: bool | None = None, authority: float = 1.0, physics_step: str | None = None,
                 physics_dt: float | None = None, jacobian_every: int = 1):
        task_kwargs = {k: v for k, v in locals().items() if k not in ("self", "operating_point", "__class__")}
        B = self._common_arguments(n_copies, control_dt, episode_time, wind_dt, disturbances, reward, termination,
                                   initial_noise)
        self.settle = config_from(settle, SettleConfig, "settle")
        self.drum = config_from(drum, DrumConfig, "drum")
        self.speed = config_from(speed, SpeedCommandConfig, "speed")
        for name, flag, its in (("generator_torque", generator_torque, ("drum", drum)),
                                ("cable_speed_command", cable_speed_command, ("speed", speed))):
            if not isinstance(flag, (bool, np.bool_)):  # 'no' was truthy: a torque action nobody asked for
                raise ValueError(f"{name} = {flag!r}: must be True or False")
            if its[1] is not None and not flag:
                raise ValueError(f"{its[0]} = {its[1]!r}: its settings apply only with {name}=True, which is off")
        if generator_torque and cable_speed_command:
            raise ValueError("generator_torque and cable_speed_command: choose one station action")
        options = _scene_options(scene_options)
        self.scene = sc = mill_scene(str(scene), options, 3)
        # the action settings are checked before the operating point's search (30-100 s for 101 wings)
        slot_groups = resolve_slot_groups(groups, sc.assembly.n_wings, n_bands)
        surfaces, authority = check_surfaces(surfaces), check_authority(authority)
        dt = sc.settings.dt  # the observation bounds' (the id's spaces whatever the physics step)
        # the physics step: the scene's, or physics_step / physics_dt (the operating point is the scene's either way)
        settings = env_physics_settings(sc.settings, physics_step, physics_dt, self.control_dt)
        settings = jacobian_settings(settings, jacobian_every)  # 1: equal to the settings above (same bits)
        self.n_substeps = substeps_per_period(sc.name, settings, self.control_dt, control_dt)
        self.op, warmup = self._operating_point_warmup(operating_point, str(scene), options, task_kwargs)
        with kernel_warmup.stopped_on_error((warmup,)):  # a failed construction leaves no warm-up running
            rp = self.reward_config.reference_power_W
            self.p_ref = self.op.reference_power_W if rp is None else float(rp)
            self.generator_torque = bool(generator_torque)
            self.cable_speed_command = bool(cable_speed_command)
            asm = self._assembly()
            self.n_wings = n = asm.n_wings
            settings = self._stable_step(asm, settings, physics_dt, control_dt)
            self._make_batch(B, asm, settings, parallel, step_observe_serial, launch_step_observe)
            self.loop_points = loop_points(self.op, asm)
            check_turbulence_cover(self.disturbances, self.loop_points)
            self.xoff = asm.body_state_size
            lay = sc.layout
            self.below = np.array([lay.piece_elements[k][-1] for k in range(n)], dtype=np.int64)
            self.ground = np.array([lay.piece_elements[0][0], lay.piece_elements[-1][-1]], dtype=np.int64)
            self._zero_nominal = np.zeros((n, 3))  # the kernel writes absolute positions; offsets: _compose
            self.actions = SlotActionMap(asm, slot_groups, surfaces, self.u_op, self.station_half_range, authority)
            self.n_actions = self.actions.n_actions
            self.obs_dim = N_OBS_PER_SLOT * n + N_STATION_OBS
            self.slot_obs = np.zeros((B, N_OBS_PER_SLOT * n))
            self.raw_obs = np.zeros((B, self.obs_dim))
            self.obs = np.zeros((B, self.obs_dim))
            self.aux = np.zeros((B, N_AUX))
            self.power = np.zeros(B)
            self.mechanical_power = np.zeros(B)
            self.cable_speed = np.zeros(B)
            self.energy_start = np.zeros(B)
            self.last_action = np.zeros((B, self.n_actions))
            max_speed = asm.station.piece_length / dt
            self.obs_low, self.obs_high = mill_observation_bounds(sc, max_speed)
            self._limits()
            self._rotation_op = rotations_from_quaternions(
                self.op.state[: B3_SIZE * n].reshape(n, B3_SIZE)[:, B3_QUAT: B3_QUAT + 4])
            self.batch.states[:] = self.op.state
            self.batch.controls[:] = self.u_op
        kernel_warmup.wait_all((warmup,))  # before the first kernel call: load what it compiled from numba's cache

    # ------------------------------------------------------------------ construction
    def _operating_point_warmup(self, given, scene: str, options: tuple, task_kwargs: dict):
        """(:meth:`_operating_point`, the kernel warm-up or None): when the operating point is to be computed, a
        second process compiles kernels meanwhile (``envs/laddermill/kernel_warmup.py``): the static equilibrium's
        while this one compiles the search's (``SEARCH_HOOK``), then this task's 3D step kernels."""
        warmup = None
        if given is None and operating_point_pending(scene, options, self.settle):
            warmup = kernel_warmup.start(task_kwargs, (step_observe_serial,))
        if warmup is None:
            return self._operating_point(given, scene, options), None
        SEARCH_HOOK[0] = lambda sc, opts: kernel_warmup.before_search(warmup, sc, opts)
        try:
            return self._operating_point(given, scene, options), warmup
        except BaseException:
            warmup.stop()  # the search failed: nothing will wait for the kernels
            raise
        finally:
            SEARCH_HOOK[0] = None

    def _operating_point(self, given, scene: str, options: tuple) -> OperatingPoint:
        """The given operating point (checked against the scene: its shapes, and its :func:`scene_digest` where
        both have one) or the memoised one of (scene, options, settle)."""
        sc = self.scene
        if given is None:
            return operating_point(scene, options, self.settle)
        if not isinstance(given, OperatingPoint):
            raise ValueError(f"operating_point = {given!r}: must be an OperatingPoint (envs.laddermill) or None")
        n, size = sc.assembly.n_wings, sc.assembly.state_size
        if given.state.shape != (size,) or given.controls.shape != (N_CONTROLS * n,) or given.n_wings != n:
            raise ValueError(f"operating_point: state {given.state.shape} / controls {given.controls.shape} do not "
                             f"fit scene {sc.name} with {n} wings (state ({size},), controls ({N_CONTROLS * n},))")
        digest = scene_digest(sc)
        if digest and given.scene_digest and given.scene_digest != digest:
            raise ValueError(f"operating_point: found for another scene, wing, wind or station than this env's "
                             f"{sc.name!r} ({n} wings, wind v0 = {sc.assembly.wind.v0:g} m/s, options "
                             f"{dict(options)}); the point's note: {given.note}")
        return given

    def _stable_step(self, asm, settings, physics_dt, control_dt):
        """``settings``, or for an RK4 ``physics_dt`` the caller chose past ``ENV_STEP_MARGIN`` of RK4's estimated
        stable step at the operating point (in the strongest wind of the disturbances) the finer step of
        ``envs/physics_step.stable_rk4_step``, with an UnstableStepWarning (the note in ``physics_step_note``), as
        the wing envs do; a blow-up of a step past it read as a wing's failure. The registered steps are kept."""
        self.physics_step_note = ""
        if physics_dt is None or settings.method != "rk4":
            return settings
        probe = Simulator(asm, self.op.state, settings, self.u_op)
        dt, self.physics_step_note = stable_rk4_step(probe, settings.dt, self.control_dt, self.disturbances,
                                                     self.episode_time, self.wind_dt)
        if not self.physics_step_note:
            return settings
        warnings.warn(f"{self.env_name}: {self.physics_step_note}", UnstableStepWarning, stacklevel=user_stacklevel())
        settings = dataclasses.replace(settings, dt=dt)
        self.n_substeps = substeps_per_period(self.scene.name, settings, self.control_dt, control_dt)
        return settings

    def _assembly(self):
        """The scene's assembly with the station at the operating point's constant cable speed: a prescribed
        schedule held at V_c, or (``generator_torque``) a drum starting at V_c whose torque is the last control.
        With ``cable_speed_command`` the station follows a commanded speed (mode 'commanded', V_c at a = 0).
        Sets ``u_op``, ``torque_op`` [N m], ``torque_half_range`` [N m] and ``station_half_range`` (the station
        action's unit, None without one)."""
        sc, op, d = self.scene, self.op, self.drum
        st = sc.assembly.station
        v = op.cable_speed
        self.torque_op = d.radius * op.mechanical_power_W / v  # the drum's torque that balances the mean pull
        self.torque_half_range = (d.torque_half_range if d.torque_half_range is not None
                                  else d.radius * op.reference_power_W / (st.efficiency * v))
        if self.generator_torque:
            q_lo, q_hi = self.torque_op - self.torque_half_range, self.torque_op + self.torque_half_range
            station = dataclasses.replace(st, mode="drum", speed_times=(0.0,), speed_values=(v,),
                                          drum_radius=d.radius, drum_inertia=d.inertia, torque_limits=(q_lo, q_hi))
            self.u_op = np.concatenate([op.controls, [self.torque_op]])
            self.station_half_range = self.torque_half_range
        elif self.cable_speed_command:
            h = self.speed.half_range if self.speed.half_range is not None else v
            station = dataclasses.replace(st, mode="commanded", speed_times=(0.0,), speed_values=(v,),
                                          speed_time_constant=self.speed.time_constant, speed_limits=(v - h, v + h))
            self.u_op = np.concatenate([op.controls, [v]])
            self.station_half_range = h
        else:
            station = dataclasses.replace(st, mode="prescribed", speed_times=(0.0,), speed_values=(v,))
            self.u_op = np.array(op.controls, dtype=float)
            self.station_half_range = None
        self.u_op.setflags(write=False)
        return dataclasses.replace(sc.assembly, station=station)

    def _limits(self) -> None:
        self._wing_limits(self.scene, min(w.span for w in self.scene.assembly.wing_types))

    # ------------------------------------------------------------------ kernel
    def _run(self, nsteps: np.ndarray) -> None:
        """Advance copy b by nsteps[b] RK4 steps (0: observe only, < 0: skip), then compose the observations."""
        self._wing_kernel_pass(nsteps, self._zero_nominal, self.slot_obs)
        self._compose()

    def _compose(self) -> None:
        """raw_obs from the kernel's slot rows (offsets taken from the reference orbit at each copy's cable phase)
        and the station read-outs; power [W]; obs = raw_obs clipped to the bounds (non-finite: the bound)."""
        B, n, st = self.n_copies, self.n_wings, self.batch.assembly.station
        x = self.batch.states
        moved = x[:, self.xoff + SX_MOVED]
        slots = self.raw_obs[:, : N_OBS_PER_SLOT * n].reshape(B, n, N_OBS_PER_SLOT)
        slots[:] = self.slot_obs.reshape(B, n, N_OBS_PER_SLOT)
        i = OBS_INDEX["dx"]
        slots[:, :, i: i + 3] -= nominal_positions(self.op, moved)
        self.cable_speed[:] = x[:, self.xoff + SX_SPEED] if st.mode != "prescribed" else self.op.cable_speed
        dten = self.aux[:, AUX_GROUND_START] - self.aux[:, AUX_GROUND_END]
        if st.mode == "drum":
            self.mechanical_power[:] = self.batch.controls[:, -1] / st.drum_radius * self.cable_speed
        else:
            self.mechanical_power[:] = dten * self.cable_speed
        self.power[:] = electrical_power(self.mechanical_power, st.efficiency)
        station = self.raw_obs[:, N_OBS_PER_SLOT * n:]
        station[:, STATION_OBS_INDEX["cable_speed"]] = self.cable_speed
        station[:, STATION_OBS_INDEX["cable_phase"]] = moved / st.piece_length
        station[:, STATION_OBS_INDEX["tension_difference"]] = dten
        # over the operating point's reference power, whatever the reward's normalisation
        station[:, STATION_OBS_INDEX["power_ratio"]] = self.power / self.op.reference_power_W
        clip_observations(self.raw_obs, self.obs_low, self.obs_high, self.obs)

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by the boolean ``mask`` (B,): the operating point (plus the
        initial noise, per wing) and its controls, t = 0, a fresh wind disturbance, drawn with ``rngs[b]`` (a numpy
        Generator per copy: first the disturbances, then the noise), and observe them. Other copies are untouched."""
        self._reset_copies(mask, rngs, self.op.state, self.u_op, self._rotation_op, 0.0)

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """Apply normalised actions (B, n_actions) for one control period to the copies in ``mask`` (default all)
        and evaluate them.

        Returns
        -------
        reward : (B,) float64;  terminated, truncated : (B,) bool;  info : dict of (B,) arrays (reward terms,
        powers [W], cable speed [m/s], tension difference and largest tension [N], lowest altitude [m], transfers,
        time [s], clipped action entries, wings outside the attached-flow band, failure code). Rows of copies
        outside ``mask`` are meaningless.
        """
        a, n_clipped = clip_actions(action, self.n_copies, self.n_actions)
        b = self.batch
        sel = np.ones(self.n_copies, bool) if mask is None else np.asarray(mask, bool)
        b.controls[sel] = self.actions.controls(a)[sel]
        self.last_action[sel] = a[sel]
        self.energy_start[:] = b.states[:, self.xoff + SX_ENERGY]
        self._advance_copies(sel)
        return evaluate_copies(self, a, n_clipped)

    # ------------------------------------------------------------------ read-outs
    def loop_extent(self, heading: float = 0.0) -> LoopExtent:
        """Height and along-wind (p . e) ranges [m] of ``loop_points`` for a gust grid of ``heading`` [rad] (0: the
        undisturbed wind, e = (-1, 0, 0)): the least ``heights`` and ``along_wind`` of a turbulence over the mill."""
        return extent(self.loop_points, heading)

    def simulator(self, b: int = 0) -> Simulator:
        """A :class:`~laddermill_gym.sim.simulator.Simulator` of copy ``b`` (its state, time [s], controls and wind;
        a snapshot: stepping it does not step the copy). ``generator_power()``, ``slot_wings()`` etc. read it out."""
        return self._snapshot_simulator(Simulator, b, check=False)

    def reset_info(self) -> dict:
        """The single env's reset info beside ``t``: the reference power [W] and whether the operating point
        converged (with its note)."""
        return {"reference_power_W": self.p_ref, "operating_point_converged": self.op.converged,
                "operating_point_note": self.op.note}

    def env_kwargs(self, kwargs: dict) -> dict:
        """The arguments with the operating point, so that an unpickled env does not compute it again."""
        return dict(kwargs, operating_point=self.op)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m] (B, n) per slot of observations (B, 15 n + 4)."""
        return wing_lateral_offsets(obs, self.n_wings)

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
        return failure_text(self, b, code)

    def renderer(self, interactive: bool = False):
        """Side and top views of the loop (``envs/laddermill/render.py``)."""
        from laddermill_gym.envs.laddermill.render import MillRenderer

        return MillRenderer(self, interactive)
