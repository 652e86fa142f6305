"""The wing task shared by the single and the vector environments: B copies of a scene stepped by one compiled
kernel, with actions, observations, rewards, terminations and wind disturbances composed around it.

A single environment is the task with B = 1, so single and vector environments run the same code and agree
bit for bit (tests/test_envs.py checks it).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from laddermill_gym.atmosphere.disturbances import grid_geometry, sample_wind_field
from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.envs import kernel_warmup
from laddermill_gym.envs.actions import ActionMap, clip_actions, resolve_groups
from laddermill_gym.envs.copy_threads import CopyThreads
from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_INDEX, observation_bounds, wing_lateral_offsets
from laddermill_gym.envs.physics_step import jacobian_settings, physics_scene_options, stable_physics_step
from laddermill_gym.envs.start_cache import WING_SOURCES, cached_start
from laddermill_gym.envs.task_base import (
    TaskCore,
    check_copies,
    default_parallel,
    env_disturbances,
    episode_periods,
    positive,
    substeps_per_period,
)

# the settings dataclasses live in task_settings.py; imported here, where every env has always found them
from laddermill_gym.envs.task_settings import (  # noqa: F401
    RewardConfig,
    TerminationConfig,
    check_nonnegative_fields,
    check_reference_power,
    config_from,
)
from laddermill_gym.envs.wing_failures import aero_range_text, shared_failure_text, status_texts
from laddermill_gym.kernels.contract import B3_POS, B3_SIZE, OK
from laddermill_gym.kernels.rigid.observe import (
    AUX_GROUND_END,
    AUX_GROUND_START,
    AUX_MAX_TENSION,
    AUX_MIN_ALTITUDE,
    N_AUX,
    launch_step_observe,
    observe_state,
    step_observe_serial,
)
from laddermill_gym.kernels.task_rewards import (
    ARG_EFFORT,
    ARG_LATERAL,
    ARG_RATES,
    N_ARGS,
    N_TERMS,
    SEQUENTIAL_SUM,
    TERM_KEYS,
    shaped_terms,
    wing_readout,
)
from laddermill_gym.ladder.scene import Scene, load_scene, options_key, options_kwargs
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.model.packing import make_workspace
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.breakpoints import W_METHODS
from laddermill_gym.sim.stable_step import UnstableStepWarning
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["RewardConfig", "TerminationConfig", "WingTask", "FAILURES", "scene_trim"]

#: Termination causes (code -> name); code 0 means the copy is still flying.
FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state, speed or rate limit, singular mass)",
                            2: "ground contact", 3: "cable over its breaking load", 4: "aerodynamic range exceeded"}
_STATUS_TEXT = status_texts("speed or rate limit")
#: what the kernel warm-up's second process calls with the task's arguments (envs/task_warmup.py)
WARMUP_TARGET = "laddermill_gym.envs.task_warmup:compile_wing"
#: the third process's, beside it: the step kernel's callees from the other end (envs/task_warmup.py)
WARMUP_TAIL_TARGET = "laddermill_gym.envs.task_warmup:compile_wing_tail"


@input_cache(maxsize=16)
def scene_trim(scene: str, options: tuple) -> tuple[Scene, np.ndarray, np.ndarray]:
    """(scene, x_trim, u_trim) of a scene name or path with ``load_scene`` overrides ``options`` (a sorted
    tuple of (key, value) pairs); cached, because every copy of a sync vector env would otherwise trim
    the same scene again, and on disk for the next process (``envs/start_cache.py``)."""
    sc = load_scene(scene, **options_kwargs(options))
    if not isinstance(sc, Scene):  # fidelity 'pointmass': no tails, the attitude is the action
        raise ValueError(f"scene {scene!r} is at the point-mass fidelity: use laddermill_gym.envs.pointmass.env."
                         "PointMassEnv, whose actions command the kites' attitude")
    x, u = cached_start("wing_start", sc.name, (sc,), WING_SOURCES, sc.initial_state, skip=("file",))
    x.setflags(write=False)
    u.setflags(write=False)
    return sc, x, u


def _stable_step_scene(name: str, options: dict, trimmed, control_dt: float, disturbances, episode_time: float,
                       wind_dt: float):
    """(scene, x_trim, u_trim, note): ``trimmed`` = (scene, x, u) unchanged (note '') unless its RK4 step is past
    the stable step in the strongest wind of ``disturbances``; then the scene at the finer step that
    :func:`~laddermill_gym.envs.physics_step.stable_physics_step` chooses, with an UnstableStepWarning."""
    sc, x, u = trimmed
    dt, note = stable_physics_step(sc, x, u, control_dt, disturbances, episode_time, wind_dt)
    if not note:
        return sc, x, u, ""
    warnings.warn(f"scene {sc.name}: {note}", UnstableStepWarning, stacklevel=user_stacklevel())
    return (*scene_trim(name, options_key(dict(options, dt=dt))), note)


class WingTask(TaskCore):
    """B copies of a wing scene as an RL task.

    Parameters
    ----------
    n_copies : int
        B.
    scene : str
        Scene name (configs/scenes/NAME.yaml) or path; 3D scenes only.
    scene_options : dict, optional
        Overrides passed to :func:`laddermill_gym.ladder.scene.load_scene` (e.g. ``elements_per_piece``), including
        ``overrides``: a nested mapping of the scene file's fields, e.g. ``{"overrides": {"wind": {"v0": 10.0}}}``
        (parameters as data, checked like the file).
    control_dt : float
        Control period [s]; the action is held over it.
    physics_dt : float, optional
        Integrator step [s] (default: the scene's); must divide ``control_dt``. With RK4, a step past the stable
        step in the strongest wind of the disturbances is replaced by a finer one, with an UnstableStepWarning
        (:mod:`laddermill_gym.envs.physics_step`; the note in ``physics_step_note``).
    action_mode : "tail" or "alpha"
        See :mod:`laddermill_gym.envs.actions`.
    groups : "per_wing", "all", "halves" or a list of wing index lists
        Wings sharing one command.
    alpha_servo_tau : float
        First-order servo time constant [s] of the alpha mode (0 = ideal).
    episode_time : float
        Episode length [s]; ``truncated`` when it is reached.
    disturbances : Disturbance, mapping, a sequence of them, or YAML text
        Wind disturbances composed per episode (default: the paper's 0.01 rad direction step at 1 s); mappings
        as :mod:`laddermill_gym.atmosphere.disturbance_spec` reads them.
    wind_dt : float
        Spacing [s] of the sampled wind modulation.
    reward, termination : dict or RewardConfig / TerminationConfig
    jacobian_every : int
        Physics steps per iteration matrix of a W-method step (default 1: built every step); k > 1 keeps it for k
        steps (``kernels/rigid/rosenbrock.py`` ``with_jacobian_reuse``: same order, other last bits; an opt-in
        speed option, docs/benchmarks.md).
    parallel : bool, optional
        Step the copies on threads (default: from 32 copies on, from 2 for a scene of 500 states or
        more: ``task_base.default_parallel``); small batches of a small model run faster on one thread.
    """

    env_name = "the wing env"
    #: failure code -> name (the SB3 adapter and the evaluation harness read it)
    failure_names = FAILURES

    def __init__(self, n_copies: int = 1, scene: str = "tethered_wing", scene_options: dict | None = None,
                 control_dt: float = 0.05, physics_dt: float | None = None, action_mode: str = "tail",
                 groups="per_wing", alpha_servo_tau: float = 0.0, episode_time: float = 300.0,
                 disturbances=None, wind_dt: float = 0.1, reward=None, termination=None,
                 parallel: bool | None = None, physics_step: str | None = None, jacobian_every: int = 1):
        task_kwargs = {k: v for k, v in locals().items() if k not in ("self", "__class__")}
        control_dt, episode_time, wind_dt = (positive(name, v, "s") for name, v in (
            ("control_dt", control_dt), ("episode_time", episode_time), ("wind_dt", wind_dt)))
        self.n_steps_max = episode_periods(float(episode_time), float(control_dt))  # before any warm-up starts
        options = physics_scene_options(scene_options, physics_step, physics_dt, control_dt)
        # the step kernel compiled in a second process while the trim is solved (envs/kernel_warmup.py); a third
        # shares the W method's callees (an RK4 step has none worth a process: task_warmup.step_callees)
        kernels = (step_observe_serial,)
        targets = (WARMUP_TARGET, WARMUP_TAIL_TARGET) if options.get("method") in W_METHODS else (WARMUP_TARGET,)
        two = len(targets) > 1  # they print when their callees are done (the trim may wait for that)
        warmups = [kernel_warmup.start(target, task_kwargs, kernels, True, two) for target in targets]
        with kernel_warmup.stopped_on_error(warmups):  # a failed construction leaves no warm-up running
            kernel_warmup.await_callees(warmups)  # on two cores: the trim's compile beside the step kernel's
            sc, x_trim, u_trim = scene_trim(str(scene), options_key(options))
            asm = sc.assembly
            if asm.dim != 3:
                raise ValueError(f"scene {sc.name}: the environments need a 3D scene (dimension = {asm.dim})")
            substeps_per_period(sc.name, sc.settings, control_dt)
            self.disturbances = env_disturbances(disturbances, float(episode_time), wind_dt)
            self.scene, x_trim, u_trim, self.physics_step_note = _stable_step_scene(
                str(scene), options, (sc, x_trim, u_trim), control_dt, self.disturbances, episode_time, wind_dt)
            sc, asm = self.scene, self.scene.assembly
            self._check_turbulence_cover(asm, x_trim)
            settings = (sc.settings if type(jacobian_every) is int and jacobian_every == 1  # True, 1.0: refused below
                        else jacobian_settings(sc.settings, jacobian_every))
            self.n_substeps = int(round(control_dt / sc.settings.dt))
            self.control_dt, self.episode_time, self.wind_dt = float(control_dt), float(episode_time), float(wind_dt)
            geom = grid_geometry(self.disturbances, self.episode_time)  # a spatial disturbance's gust grid
            self.reward_config = config_from(reward, RewardConfig, "reward")
            self.termination_config = config_from(termination, TerminationConfig, "termination")
            self.x_trim, self.u_trim = x_trim, u_trim
            nw = asm.n_wings
            self.n_wings = nw
            self.n_copies = check_copies(n_copies)
            self.parallel = default_parallel(self.n_copies, asm.state_size, parallel)
            self._kernel = CopyThreads(step_observe_serial, self.n_copies, self.parallel, launch_step_observe)
            n_mod = int(math.ceil(self.episode_time / self.wind_dt - 1e-9)) + 1
            self.batch = BatchSimulator(asm, self.n_copies, settings, n_modulation=max(2, n_mod),
                                        n_grid=0 if geom is None else geom.floats)
            B = self.n_copies
            self.nominal = np.ascontiguousarray(x_trim[: B3_SIZE * nw].reshape(nw, B3_SIZE)[:, B3_POS: B3_POS + 3])
            lay = sc.layout
            self.below = np.array([lay.piece_elements[k][-1] for k in range(nw)], dtype=np.int64)
            two_ended = sc.end is not None
            self.ground = np.array([lay.piece_elements[0][0], lay.piece_elements[-1][-1] if two_ended else -1],
                                   dtype=np.int64)
            self.obs_dim = N_OBS_PER_WING * nw
            self.obs = np.zeros((B, self.obs_dim))
            self.aux = np.zeros((B, N_AUX))
            self._dx = np.zeros((B, asm.state_size))
            self._nsteps = np.zeros(B, dtype=np.int64)
            self.steps = np.zeros(B, dtype=np.int64)
            self.obs_low, self.obs_high = observation_bounds(sc)
        kernel_warmup.wait_all(warmups)  # before the first kernel call: load what they compiled from numba's cache
        # trim observation: nominal alpha per wing and the reference power
        one = WingTask._observe_state(self, x_trim, u_trim)
        alpha_trim = one[0].reshape(nw, N_OBS_PER_WING)[:, OBS_INDEX["alpha"]]
        self.alpha_trim = alpha_trim
        rc = self.reward_config
        self.v_reel = rc.reel_speed_fraction * asm.wind.v0
        self.p_ref = float((one[1][AUX_GROUND_START] - one[1][AUX_GROUND_END]) * self.v_reel)
        if rc.reference_power_W is not None:
            self.p_ref = float(rc.reference_power_W)
        if not self.p_ref > 0:
            raise ValueError(f"scene {sc.name}: the trim gives no positive reference power ({self.p_ref:.4g} W)")
        self._wing_limits(sc, min(w.span for w in asm.wing_types))
        self.actions = ActionMap(asm, resolve_groups(groups, nw, two_ended), action_mode, u_trim, alpha_trim,
                                 self.control_dt, alpha_servo_tau)
        self.actions.reset(B)
        self.n_actions = self.actions.n_actions
        self.last_action = np.tile(self.actions.nominal_action, (B, 1))
        self._reward_constants()

    # ------------------------------------------------------------------ kernels
    def _run(self, nsteps: np.ndarray) -> None:
        self._wing_kernel_pass(nsteps, self.nominal, self.obs)

    def _observe_state(self, x: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(obs row (obs_dim,), aux row (N_AUX,)) of one state x at t = 0 in the undisturbed wind (speed factor
        1, no direction offset); raises ValueError if the mass matrix is singular there.

        Without a gust grid it is the step kernel's own observation (no step) of copy 0 set to (x, u) in that
        wind, so a cold start compiles no separate observation kernel (issue 32: about 4 s of CPU); this runs in
        the constructor, before the first reset sets every copy. With a grid (whose copies add the grid's
        terms) it is ``observe_state`` on a model without one."""
        b = self.batch
        if b.n_grid == 0:
            b.set_wind(0, WindField())  # undisturbed: factor 1, no offset
            b.states[0], b.controls[0], b.t[0] = x, u, 0.0
            self._nsteps[:] = -1
            self._nsteps[0] = 0
            self._wing_kernel_pass(self._nsteps, self.nominal, self.obs)
            if b.status[0] != OK:
                raise ValueError(f"scene {self.scene.name}: singular mass matrix at the state observed")
            return self.obs[0].copy(), self.aux[0].copy()
        tmod, ms, md, gp, gv = pack_wind_field(WindField())  # undisturbed: factor 1, no offset, no gust grid
        model = b.model._replace(tmod=tmod, ms=ms, md=md, gp=gp, gv=gv)
        obs, aux = np.zeros(self.obs_dim), np.zeros(N_AUX)
        status = observe_state(0.0, np.array(x, dtype=float), np.array(u, dtype=float), model,
                               make_workspace(self.scene.assembly), self.nominal, self.below, self.ground, obs, aux)
        if status != OK:
            raise ValueError(f"scene {self.scene.name}: singular mass matrix at the state observed")
        return obs, aux

    # ------------------------------------------------------------------ episodes
    def reset(self, mask: np.ndarray, rngs) -> None:
        """Start new episodes in the copies selected by the boolean ``mask`` (B,): trim state and controls,
        t = 0, a fresh wind disturbance drawn with ``rngs[b]`` (a numpy Generator per copy), and observe them.
        Other copies are untouched."""
        b = self.batch
        idx = np.flatnonzero(mask)
        for i in idx:
            b.set_wind(int(i), sample_wind_field(self.disturbances, self.episode_time, self.wind_dt, rngs[i]))
        b.states[idx] = self.x_trim
        b.controls[idx] = self.u_trim
        b.t[idx] = 0.0
        self.actions.reset(self.n_copies, mask)
        self.last_action[idx] = self.actions.nominal_action
        self._start_copies(idx)

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """Apply normalised actions (B, n_actions) for one control period to the copies in ``mask`` (default
        all) and evaluate them.

        Returns
        -------
        reward : (B,) float64;  terminated, truncated : (B,) bool;  info : dict of (B,) arrays (reward terms,
        power [W], largest tension [N], lowest altitude [m], time [s], clipped action entries, failure code
        (see :data:`FAILURES`)). Rows of copies outside ``mask`` are meaningless.
        """
        a, n_clipped = clip_actions(action, self.n_copies, self.n_actions)
        b = self.batch
        sel = np.ones(self.n_copies, bool) if mask is None else np.asarray(mask, bool)
        servo = None if self.actions.alpha_servo is None else self.actions.alpha_servo.copy()
        self.actions.apply(a, sel, b.controls, self.last_action)
        if servo is not None and mask is not None:  # copies outside the mask keep their servo state
            self.actions.alpha_servo[~sel] = servo[~sel]
        self._advance_copies(sel)
        return self._evaluate(a, n_clipped)

    def _evaluate(self, a: np.ndarray, n_clipped: np.ndarray):
        """(reward, terminated, truncated, info) of every copy at its observed state: two compiled passes over the
        copies (``kernels/task_rewards.py``: the reward's arguments and failure codes, then the terms and their
        sum) around numpy's expm1 of the saturating terms (bit for bit the numpy arithmetic of before; from 8 wings
        or actions on, the means in numpy: :meth:`_means`)."""
        B = self.n_copies
        power, p_term, failure = np.empty(B), np.empty(B), np.empty(B, dtype=np.int64)
        neg_args = np.empty((N_ARGS, B))
        if self._numpy_means:
            self._means(a, neg_args)
        wing_readout(self.obs, self.aux, self.batch.status, a, self._nominal_action, self.n_wings, self.v_reel,
                     self._reward_scalars[0], self.p_ref, self.lateral_scale, self._reward_scalars[1],
                     self._limits, self._numpy_means, power, p_term, neg_args, failure)
        terms = np.empty((N_TERMS, B))
        reward, terminated, truncated = np.empty(B), np.empty(B, dtype=bool), np.empty(B, dtype=bool)
        shaped_terms(p_term, np.expm1(neg_args), failure, self.steps, self._weights, self.n_steps_max, terms, reward,
                     terminated, truncated)
        info = dict(zip(TERM_KEYS, terms, strict=True))
        info.update(power_W=power, max_tension_N=self.aux[:, AUX_MAX_TENSION].copy(),
                    min_altitude_m=self.aux[:, AUX_MIN_ALTITUDE].copy(), t=self.batch.t.copy(),
                    n_clipped=n_clipped, failure=failure)
        return reward, terminated, truncated, info

    def _reward_constants(self) -> None:
        """The compiled read-out's constants: limits (alpha_lo, alpha_hi, beta_max [rad], breaking tension [N],
        min altitude [m]), weights (w_y, w_w, w_u, failure penalty), (power weight, rate_scale^2 [rad^2/s^2]),
        the nominal action as float64 and a scratch row."""
        rc = self.reward_config
        self._limits = np.array([self.alpha_lo, self.alpha_hi, self.beta_max, self.breaking_tension,
                                 self.min_altitude], dtype=float)
        self._weights = np.array([rc.lateral_weight, rc.rate_weight, rc.effort_weight, rc.failure_penalty], float)
        self._reward_scalars = (float(rc.power_weight), float(rc.rate_scale) ** 2)
        self._nominal_action = np.asarray(self.actions.nominal_action, dtype=float)
        self._numpy_means = max(self.n_wings, self.n_actions) >= SEQUENTIAL_SUM

    def _means(self, a: np.ndarray, neg_args: np.ndarray) -> None:
        """The negated means of the saturating terms (``kernels/task_rewards.py``'s rows) with numpy's pairwise
        sums, for a scene of :data:`SEQUENTIAL_SUM` wings or actions or more (the chain)."""
        o = self.obs.reshape(self.n_copies, self.n_wings, N_OBS_PER_WING)
        lat = np.mean((o[:, :, OBS_INDEX["dy"]] / self.lateral_scale) ** 2, axis=1)
        rates = np.mean((o[:, :, OBS_INDEX["p"]] ** 2 + o[:, :, OBS_INDEX["r"]] ** 2) / self._reward_scalars[1], axis=1)
        neg_args[ARG_LATERAL], neg_args[ARG_RATES] = -lat, -rates
        neg_args[ARG_EFFORT] = -np.mean((a - self._nominal_action) ** 2, axis=1)

    def reset_info(self) -> dict:
        """The single env's reset info beside ``t``: the reference power [W]."""
        return {"reference_power_W": self.p_ref}

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m] (B, n_wings) of observations (B, obs_dim)."""
        return wing_lateral_offsets(obs, self.n_wings)

    def snapshot(self) -> dict:
        """:meth:`TaskCore.snapshot` and the alpha servo's state."""
        servo = self.actions.alpha_servo
        return dict(super().snapshot(), servo=None if servo is None else servo.copy())

    def restore(self, snap: dict) -> None:
        super().restore(snap)
        if snap["servo"] is not None:
            self.actions.alpha_servo = snap["servo"]

    def renderer(self, interactive: bool = False):
        """A 3D renderer of the copies (``envs/render.py``): wings, cable and ground points."""
        from laddermill_gym.envs.render import SceneRenderer

        return SceneRenderer(self, interactive)

    def failure_text(self, b: int, code: int) -> str:
        """A sentence on why copy ``b`` terminated (time, and the quantity)."""
        text = shared_failure_text(self, b, code, _STATUS_TEXT)
        if text is not None:
            return text
        o = self.obs[b].reshape(self.n_wings, N_OBS_PER_WING)
        if code == 2:
            k = int(np.argmin(-(o[:, OBS_INDEX['dz']] + self.nominal[:, 2])))
            return (f"t = {self.batch.t[b]:.2f} s: ground contact, wing {k} CG at {self.aux[b, AUX_MIN_ALTITUDE]:.2f} "
                    f"m altitude (< termination's min_altitude {self.min_altitude:.3g} m)")
        return aero_range_text(self, b, o, "wing")
