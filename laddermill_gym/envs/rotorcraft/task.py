"""The rotorcraft task shared by the single and the vector environments: B copies of Roberts' craft on one
:class:`~laddermill_gym.sim.batch.BatchSimulator`, stepped by one compiled kernel per control period
(:mod:`laddermill_gym.rotorcraft.craft_observe`), with actions, observations, rewards, terminations and wind
disturbances composed around it.

A single environment is the task with B = 1, so single and vector environments run the same code and agree
bit for bit (tests/test_rotorcraft_vector.py checks it), as the wing environments do with
:class:`~laddermill_gym.envs.task.WingTask`.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections import namedtuple

import numpy as np

from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.envs import kernel_warmup
from laddermill_gym.envs.actions import clip_actions
from laddermill_gym.envs.physics_step import env_physics_settings, jacobian_settings, stable_rk4_step
from laddermill_gym.envs.rotorcraft.observation import OBS_Y, craft_observation_bounds
from laddermill_gym.envs.rotorcraft.settings import (
    InitialNoise,
    RotorcraftRewardConfig,
    RotorcraftTerminationConfig,
)
from laddermill_gym.envs.rotorcraft.trim import check_trim_incidence, control_ranges, craft_trim
from laddermill_gym.envs.step_callees import compile_ahead, w_loop_call
from laddermill_gym.envs.task_base import TaskCore, positive, whole_multiple
from laddermill_gym.kernels.action_pass import affine_controls
from laddermill_gym.kernels.contract import (
    B3_POS,
    B3_SIZE,
    CA_ALTITUDE,
    CA_MAX_ELEMENT,
    CA_MAX_TENSION,
    CA_POWER,
    CA_TENSION,
    CA_THRUST,
    CO_EULER,
    GROUND,
    LIMIT,
    N_CRAFT_AUX,
    N_CRAFT_OBS,
    NONFINITE,
    OK,
    REF_POSITION,
    REF_SIZE,
    REF_TENSION,
    REF_THRUST,
    SINGULAR,
)
from laddermill_gym.kernels.task_rewards import N_ARGS, N_TERMS, TERM_KEYS, clip_rows, craft_readout, shaped_terms
from laddermill_gym.rotorcraft.config import DEFAULT_CRAFT
from laddermill_gym.rotorcraft.craft import TETHER_NAMES, CraftSimulator
from laddermill_gym.rotorcraft.craft_observe import (
    CRAFT_BODY,
    craft_step_observe_serial,
    launch_craft_step_observe,
)
from laddermill_gym.sim.reports import ground_stop_text
from laddermill_gym.sim.stable_step import UnstableStepWarning
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["CraftTask", "CRAFT_FAILURES", "CraftScene"]

#: Termination causes (code -> name); 0: still flying.
CRAFT_FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state, speed or rate limit)",
                                  2: "rotor inflow failed", 3: "ground contact", 4: "tether over its breaking load",
                                  5: "attitude out of range", 6: "blade incidence past its limit"}
#: what the kernel warm-up's second process calls with the task's arguments (envs/task_warmup.py)
WARMUP_TARGET = "laddermill_gym.envs.task_warmup:compile_craft"
_STATUS_TEXT = {SINGULAR: "singular mass matrix", NONFINITE: "non-finite state", LIMIT: "speed or rate limit exceeded"}
#: What the scene renderer reads of a task's scene: the built assembly and a name.
CraftScene = namedtuple("CraftScene", ["assembly", "name"])


class CraftTask(TaskCore):
    """B copies of Roberts' tethered twin-rotor craft as an RL task.

    Parameters (those of :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv`, which documents the task)
    ----------
    n_copies : int
        B.
    craft : str
        Craft name in configs/rotorcraft/ or a YAML path.
    wind_speed : float, optional
        Wind speed v0 at h0 [m/s] (default: the config's).
    collective : float, optional
        Trim collective [rad] (default: the config's).
    control_dt : float
        Control period [s]; the action is held over it; a whole multiple of the physics step.
    physics_dt : float, optional
        Physics step [s] (default: the config's; with ``physics_step`` a W-method, the control period).
    episode_time : float
        Episode length [s]; ``truncated`` when it is reached.
    disturbances : sequence of Disturbance or their config dicts
        Wind disturbances composed per episode (default: a 0.01 rad direction step at 1 s).
    wind_dt : float
        Spacing [s] of the sampled wind modulation.
    initial_noise, reward, termination : dict or InitialNoise / RotorcraftRewardConfig / RotorcraftTerminationConfig
    parallel : bool, optional
        Step the copies on numba's thread pool (default: when B >= 32).
    physics_step : str, optional
        The integrator (``"ros1"``, ``"ros2"``, ``"ros2t"``, ``"ros34pw2"``, ``"rk4"``; ``envs/physics_step.py``)
        instead of the config's (None, the default: ROS34PW2 at 50 ms for ``roberts_flying_model``). ``"rk4"`` needs
        ``physics_dt``: the craft's RK4 is stable below about 6.2 ms (``laddermill stable-step
        roberts_flying_model``); a ``physics_dt`` past ``ENV_STEP_MARGIN`` of its stable step estimated at the trim in
        the strongest wind of the disturbances is replaced by the largest whole fraction of the control period below
        it, with an UnstableStepWarning (``envs/physics_step.py``; the note in ``physics_step_note``), as in the wing
        envs.
    jacobian_every : int
        Physics steps per iteration matrix of the W step (default 1: every step, the registered bits; k > 1 keeps
        it k steps, ``kernels/rigid/rosenbrock.py`` ``with_jacobian_reuse``: same order, other last bits).

    Attributes
    ----------
    obs : (B, 19) float64, the clipped observations;  raw_obs : (B, 19) float64, as the kernel wrote them;
    aux : (B, N_CRAFT_AUX) float64 (``craft_observe.CA_*``);  steps : (B,) control periods since the reset;
    batch : the BatchSimulator (states, controls, t, wind modulation, status).
    """

    #: One lateral offset per copy (the harness's lateral read-out) and the craft's failure names.
    n_wings = 1
    failure_names = CRAFT_FAILURES
    env_name = "the rotorcraft env"
    reward_class, termination_class = RotorcraftRewardConfig, RotorcraftTerminationConfig
    noise_class = InitialNoise
    #: Read-only attributes the single env shows as its own (units and shapes above and in the code)
    env_attributes: tuple[str, ...] = (
        "craft", "x_trim", "u_trim", "trim_action", "control_dt", "episode_time", "wind_dt", "n_substeps",
        "n_steps_max", "disturbances", "reward_config", "termination_config", "initial_noise", "nominal_position",
        "thrust_trim", "tension_trim", "p_ref", "lateral_scale", "min_altitude", "breaking_tension")

    def __init__(self, n_copies: int = 1, craft: str = DEFAULT_CRAFT, wind_speed: float | None = None,
                 collective: float | None = None, control_dt: float = 0.05, physics_dt: float | None = None,
                 episode_time: float = 120.0, disturbances=None, wind_dt: float = 0.1, initial_noise=None,
                 reward=None, termination=None, parallel: bool | None = None, physics_step: str | None = None,
                 jacobian_every: int = 1):
        task_kwargs = {k: v for k, v in locals().items() if k not in ("self", "__class__")}
        # the step kernel compiled in a second process while the trim is solved (envs/kernel_warmup.py)
        warmup = kernel_warmup.start(WARMUP_TARGET, task_kwargs,
                                     (craft_step_observe_serial,), True, True)
        with kernel_warmup.stopped_on_error((warmup,)):  # a failed construction leaves no warm-up running
            B = self._common_arguments(n_copies, control_dt, episode_time, wind_dt, disturbances, reward, termination,
                                       initial_noise)
            if wind_speed is not None:
                wind_speed = positive("wind_speed", wind_speed, "m/s")
            if physics_dt is not None:
                physics_dt = positive("physics_dt", physics_dt, "s")
            if physics_step == "rk4" and physics_dt is None:
                raise ValueError("physics_step = 'rk4' needs physics_dt: the craft's RK4 is stable below about "
                                 "6.2 ms (laddermill stable-step roberts_flying_model), not at the config's 50 ms "
                                 "step (configs/rotorcraft/)")
            self.craft, self.x_trim, self.u_trim = craft_trim(str(craft), wind_speed, collective, physics_dt)
            cfg = self.craft.config
            # physics_step: another integrator, one step per control period for a W-method (None: the config's)
            settings = env_physics_settings(cfg.settings, physics_step, physics_dt, self.control_dt)
            self.physics_step_note = ""
            self.n_substeps = whole_multiple(self.control_dt, settings.dt, control_dt)  # the step asked for divides
            if settings.method == "rk4":  # past RK4's stable step (about 6 ms): finer, with a warning, as the wings
                probe = CraftSimulator(cfg, self.craft.assembly, self.craft.layout, self.x_trim, self.u_trim)
                dt, self.physics_step_note = stable_rk4_step(probe, settings.dt, self.control_dt, self.disturbances,
                                                             self.episode_time, self.wind_dt)
                if self.physics_step_note:
                    warnings.warn(f"{self.env_name}: {self.physics_step_note}", UnstableStepWarning,
                                  stacklevel=user_stacklevel())
                    settings = dataclasses.replace(settings, dt=dt)
            self.n_substeps = whole_multiple(self.control_dt, settings.dt, control_dt)
            # the W step's iteration matrix kept for jacobian_every physics steps (1: every step, the registered bits)
            self._settings = (settings if type(jacobian_every) is int and jacobian_every == 1  # True, 1.0: refused
                              else jacobian_settings(settings, jacobian_every))
            self._build_batch(B, parallel)
            if isinstance(warmup, kernel_warmup.Warmup) and warmup.wait_for(kernel_warmup.CALLEES_DONE):
                # the W method's loop compiled here, beside the warm-up's step kernel (envs/step_callees.py)
                compile_ahead(w_loop_call(self.batch, self._dx))
        kernel_warmup.wait_all((warmup,))  # before the first kernel call: load what it compiled from numba's cache
        self._references()
        rc, tc = self.reward_config, self.termination_config
        self.lateral_scale = rc.lateral_scale if rc.lateral_scale is not None else 0.05 * cfg.tethers.length
        span = cfg.hub_spacing + 2.0 * cfg.rotor_radius
        self.min_altitude = tc.min_altitude if tc.min_altitude is not None else 0.5 * span
        self.breaking_tension = tc.breaking_factor * cfg.tethers.cable.breaking_load
        # the trim's larger retreating-tip incidence [rad], checked against the rotor model's blade-incidence limit
        self.trim_tip_incidence = check_trim_incidence(self.craft, self.sim, self.x_trim, tc.blade_stall,
                                                       f"{craft} at wind_speed = {cfg.wind.v0!r} m/s, collective = "
                                                       f"{float(self.u_trim[0])!r} rad")
        self.obs_low, self.obs_high = craft_observation_bounds(cfg, self.craft.layout.lengths, self.tension_trim)
        self.mid, self.half = control_ranges(cfg)
        self.trim_action = ((self.u_trim - self.mid) / self.half).astype(np.float32)
        self.n_actions = 2
        self.last_action = np.tile(self.trim_action.astype(float), (self.n_copies, 1))
        self._reward_constants()
        self._clip_obs()

    # ------------------------------------------------------------------ construction
    def _build_batch(self, B: int, parallel: bool | None) -> None:
        """The batch of B copies at the trim, its kernel and scratch, and a single simulator of the craft for
        read-outs (linearisation, diagnosis)."""
        c = self.craft
        self.sim = CraftSimulator(c.config, c.assembly, c.layout, self.x_trim, self.u_trim)
        self.scene = CraftScene(c.assembly, c.config.name)
        self._make_batch(B, c.assembly, self._settings, parallel,
                         craft_step_observe_serial, launch_craft_step_observe, vehicle=self.sim.make_vehicle(),
                         n_controls=self.sim.n_controls, vehicle_sizes=self.sim.vehicle_sizes())
        self.batch.states[:] = self.x_trim
        self.batch.controls[:] = self.u_trim
        self._check_turbulence_cover(c.assembly, self.x_trim)
        self.tether_end = np.array([els[-1] for els in c.layout.tether_elements], dtype=np.int64)
        self.raw_obs = np.zeros((B, N_CRAFT_OBS))
        self.obs = np.zeros((B, N_CRAFT_OBS))
        self.aux = np.zeros((B, N_CRAFT_AUX))

    def _references(self) -> None:
        """Trim read-outs (every copy sits at the trim in the undisturbed air: speed factor 1, no direction offset,
        no gust grid): the nominal CG position [m], the rotor thrusts [N] and tether tensions [N] the observation's
        ratios refer to, and the reference power [W]."""
        for i in range(self.n_copies):
            self.batch.set_wind(i, WindField())
        o = B3_SIZE * CRAFT_BODY
        self.nominal_position = np.array(self.x_trim[o + B3_POS: o + B3_POS + 3])
        self.nominal = self.nominal_position[None]  # (1, 3): what the scene renderer reads
        self._rotation_trim = self.sim.wing_rotations()[0]
        self.ref = np.ones(REF_SIZE)
        self.ref[REF_POSITION: REF_POSITION + 3] = self.nominal_position
        self._nsteps[:] = 0
        self._kernel_pass(self._nsteps)
        aux = self.aux[0]
        self.thrust_trim = aux[CA_THRUST: CA_THRUST + 2].copy()
        self.tension_trim = aux[CA_TENSION: CA_TENSION + 3].copy()
        self.p_ref = float(aux[CA_POWER])
        cfg = self.craft.config
        if not (np.all(self.thrust_trim > 0) and np.all(self.tension_trim > 0)):  # the observation's ratios' references
            raise ValueError(f"craft {cfg.name} at wind_speed = {cfg.wind.v0!r} m/s: the trim gives no positive thrust "
                             f"{self.thrust_trim} N or tensions {self.tension_trim} N")
        if self.reward_config.reference_power_W is not None:  # a fixed reference: the trim may take power (a hover)
            self.p_ref = float(self.reward_config.reference_power_W)
        elif not self.p_ref > 0:  # the power reward's scale
            raise ValueError(f"craft {cfg.name} at wind_speed = {cfg.wind.v0!r} m/s, collective = "
                             f"{float(self.u_trim[0])!r} rad: the trim gives no positive power ({self.p_ref:.4g} W), "
                             "which the reward takes as its reference; pass reward={'reference_power_W': P}")
        self.ref[REF_THRUST: REF_THRUST + 2] = self.thrust_trim
        self.ref[REF_TENSION: REF_TENSION + 3] = self.tension_trim
        self._kernel_pass(self._nsteps)

    # ------------------------------------------------------------------ kernel
    def _kernel_pass(self, nsteps: np.ndarray) -> None:
        """Advance copy b by nsteps[b] physics steps (the env's method: ROS34PW2 by default; 0: observe only, < 0: skip)
        and write raw_obs and aux."""
        b = self.batch
        b.advance(nsteps, lambda dt, ns: self._kernel(
            *b.kernel_head(dt, ns, self._dx), self.ref, self.tether_end, self.raw_obs, self.aux, b.status, b.done))

    def _run(self, nsteps: np.ndarray) -> None:
        """:meth:`_kernel_pass`, then the clipped observations."""
        self._kernel_pass(nsteps)
        self._clip_obs()

    def _clip_obs(self) -> None:
        """obs: raw_obs with non-finite entries replaced by the bound on their side (nan: the upper) and clipped
        to [obs_low, obs_high]."""
        clip_rows(self.raw_obs, self.obs_low, self.obs_high, self.obs)

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by the boolean ``mask`` (B,): the trim state (plus the
        initial noise) and controls, t = 0, a fresh wind disturbance, drawn with ``rngs[b]`` (a numpy Generator
        per copy: first the disturbances, then the noise), and observe them. Other copies are untouched."""
        self._reset_copies(mask, rngs, self.x_trim, self.u_trim, self._rotation_trim[None], self.trim_action,
                           CRAFT_BODY)

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """Apply normalised actions (B, 2) for one control period to the copies in ``mask`` (default all) and
        evaluate them.

        Returns
        -------
        reward : (B,) float64;  terminated, truncated : (B,) bool;  info : dict of arrays, one row per copy:
        the reward terms, t [s], power_W [W], thrust_N (B, 2) [N], tether_tension_N (B, 3) [N], altitude_m [m],
        max_tip_incidence_rad [rad], n_clipped (action entries outside [-1, 1]) and failure (code of
        :data:`CRAFT_FAILURES`). Rows of copies outside ``mask`` are meaningless.
        """
        a, n_clipped = clip_actions(action, self.n_copies, self.n_actions)
        sel = np.ones(self.n_copies, bool) if mask is None else np.asarray(mask, bool)
        affine_controls(a, self.mid, self.half, sel, self.batch.controls, self.last_action)  # mid + a half, compiled
        self._advance_copies(sel)
        return self._evaluate(a, n_clipped)

    def _evaluate(self, a: np.ndarray, n_clipped: np.ndarray):
        """(reward, terminated, truncated, info) of every copy at its observed state: two compiled passes over the
        copies (``kernels/task_rewards.py``: the reward's arguments and the failure codes of
        :data:`CRAFT_FAILURES`, where several apply the one listed first; then the terms and their sum) around
        numpy's expm1 of the saturating terms (bit for bit the numpy arithmetic of ``TaskCore.shaped_reward``)."""
        B, aux = self.n_copies, self.aux
        power, p_term, failure, tip = np.empty(B), np.empty(B), np.empty(B, dtype=np.int64), np.empty(B)
        neg_args = np.empty((N_ARGS, B))
        craft_readout(self.raw_obs, aux, self.batch.status, a, self._trim_action64, self._v_ref, self._limits, power,
                      p_term, neg_args, failure, tip)
        self.tip_incidence = tip
        terms = np.empty((N_TERMS, B))
        reward, terminated, truncated = np.empty(B), np.empty(B, dtype=bool), np.empty(B, dtype=bool)
        shaped_terms(p_term, np.expm1(neg_args), failure, self.steps, self._weights, self.n_steps_max, terms, reward,
                     terminated, truncated)
        info = dict(zip(TERM_KEYS, terms, strict=True))
        info.update(t=self.batch.t.copy(), power_W=power, thrust_N=aux[:, CA_THRUST: CA_THRUST + 2].copy(),
                    tether_tension_N=aux[:, CA_TENSION: CA_TENSION + 3].copy(), altitude_m=aux[:, CA_ALTITUDE].copy(),
                    max_tip_incidence_rad=tip, n_clipped=n_clipped, failure=failure)
        return reward, terminated, truncated, info

    def _reward_constants(self) -> None:
        """The compiled read-out's constants: (power weight, p_ref [W], lateral scale [m], rate_scale^2
        [rad^2/s^2]), limits (max |roll|, pitch range, max |yaw| [deg], breaking tension [N], min altitude [m],
        blade-incidence limit [rad]: inf without ``termination.blade_stall``),
        weights (w_y, w_w, w_u, failure penalty) and the trim action as float64."""
        rc, tc = self.reward_config, self.termination_config
        self._v_ref = np.array([rc.power_weight, self.p_ref, self.lateral_scale, rc.rate_scale ** 2], dtype=float)
        self._limits = np.array([tc.max_abs_roll_deg, *tc.pitch_range_deg, tc.max_abs_yaw_deg, self.breaking_tension,
                                 self.min_altitude,
                                 self.craft.config.blade_incidence_limit if tc.blade_stall else np.inf], dtype=float)
        self._weights = np.array([rc.lateral_weight, rc.rate_weight, rc.effort_weight, rc.failure_penalty], float)
        self._trim_action64 = self.trim_action.astype(float)

    # ------------------------------------------------------------------ read-outs
    def simulator(self, b: int = 0) -> CraftSimulator:
        """The task's :class:`CraftSimulator` set to copy ``b``: its state, time [s], controls [rad] and wind
        modulation (a snapshot: stepping it does not step the copy, and the next call resets it)."""
        bt, sim = self.batch, self.sim
        air = {f: a[b].copy() for f, a in zip(bt.air._fields, bt.air, strict=True) if a is not None}
        sim.model = sim.model._replace(**air)
        sim.reset(state=bt.states[b], t=float(bt.t[b]), controls=bt.controls[b], check=False)
        return sim

    def _diagnosis(self, b: int) -> str:
        """What copy ``b``'s failed step broke (``envs.wing_failures.failed_step_culprits``) and the simulator's
        diagnosis of its last good state; for a state that is not finite (the simulator refuses one) its first
        non-finite entry."""
        from laddermill_gym.envs.wing_failures import failed_step_culprits

        x = self.batch.states[b]
        bad = np.flatnonzero(~np.isfinite(x))
        if bad.size:
            return f"state[{int(bad[0])}] = {x[bad[0]]} is not finite ({bad.size} entries)"
        sim = self.simulator(b)
        return failed_step_culprits(sim, int(self.batch.status[b])) + sim.diagnose()

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
        t = float(self.batch.t[b])
        if code in (1, 2) and self.batch.status[b] != OK:
            kind = _STATUS_TEXT.get(int(self.batch.status[b]), f"status {int(self.batch.status[b])}")
            error = f"integration failed at t = {t:.6g} s ({kind}); {self._diagnosis(b)}"
            if code == 2:
                return f"t = {t:.2f} s: a rotor's Glauert inflow did not converge ({error})"
            return f"t = {t:.2f} s: {error}"
        if code == 2:
            return f"t = {t:.2f} s: a rotor's Glauert inflow did not converge"
        if code == 3 and self.batch.status[b] == GROUND:
            bt = self.batch
            return f"t = {t:.2f} s: {ground_stop_text(self.craft.assembly, bt.states[b], bt.settings.ground_height)}"
        if code == 3:
            altitude = self.aux[b, CA_ALTITUDE]
            return f"t = {t:.2f} s: ground contact, CG at {altitude:.2f} m altitude (< {self.min_altitude:.3g} m)"
        if code == 4:
            e = int(self.aux[b, CA_MAX_ELEMENT])
            which = next(TETHER_NAMES[i] for i, els in enumerate(self.craft.layout.tether_elements) if e in els)
            return (f"t = {t:.2f} s: {which} tether tension {self.aux[b, CA_MAX_TENSION]:.4g} N over "
                    f"{self.breaking_tension:.4g} N")
        if code == 6:
            limit = np.degrees(self.craft.config.blade_incidence_limit)
            return (f"t = {t:.2f} s: a retreating blade tip at {np.degrees(self.tip_incidence[b]):.2f} deg incidence, "
                    f"past the rotor model's {limit:.3g} deg blade-incidence limit (its lift is linear, without stall)")
        if code == 5:
            tc = self.termination_config
            phi, theta, psi = np.degrees(self.raw_obs[b, CO_EULER: CO_EULER + 3])
            return (f"t = {t:.2f} s: attitude roll {phi:.1f}, pitch {theta:.1f}, yaw {psi:.1f} deg outside "
                    f"|roll| <= {tc.max_abs_roll_deg:g}, pitch in {list(tc.pitch_range_deg)}, "
                    f"|yaw| <= {tc.max_abs_yaw_deg:g} deg")
        return ""

    def reset_info(self) -> dict:
        """The single env's reset info beside ``t``: the reference power [W]."""
        return {"reference_power_W": self.p_ref}

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offset dy [m] (B, 1) of observations (B, 19)."""
        return np.asarray(obs, dtype=float)[:, OBS_Y:OBS_Y + 1]

    def renderer(self, interactive: bool = False):
        """A scene renderer of the copies that draws the craft as its frame and rotor disks."""
        from laddermill_gym.envs.rotorcraft.render import craft_renderer

        return craft_renderer(self, interactive)
