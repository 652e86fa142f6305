"""What every env family's task shares (the task is the family's one concern; the single env, the native vector
env and the SB3 adapter around it are generic: ``envs/task_env.py``, ``envs/vector.py``, ``envs/sb3.py``).

A task holds B copies of one system and answers the protocol those three use:

* ``reset(mask, rngs)``, ``step(actions, mask=None) -> (reward, terminated, truncated, info)`` with (B,) arrays;
* ``obs`` (B, obs_dim), ``obs_low`` / ``obs_high`` (obs_dim,), ``n_actions``, ``n_copies``, ``control_dt`` [s],
  ``steps`` (B,), ``last_action`` (B, n_actions), ``batch`` (with ``t`` (B,) [s]);
* ``failure_names`` (code -> name), ``failure_text(b, code)``, ``lateral_offsets(obs)`` (B, m) [m];
* ``render_modes`` (empty: the family does not render) and ``renderer(interactive)``;
* ``snapshot()`` / ``restore(snapshot)`` / ``observe()`` (pickling), ``reset_info()`` (the single env's reset
  info beside ``t``), ``env_kwargs(kwargs)`` (the arguments a pickled env is rebuilt from).

:class:`TaskCore` implements the parts that are the same for every family over a
:class:`~laddermill_gym.sim.batch.BatchSimulator`; the checks of the constructor arguments are functions here.
"""

from __future__ import annotations

import math
import numbers
import warnings
from functools import reduce
from operator import add

import numpy as np

from laddermill_gym.atmosphere.disturbance_spec import parse_disturbances
from laddermill_gym.atmosphere.disturbances import DirectionStep, grid_geometry, sample_wind_field
from laddermill_gym.envs.copy_threads import CopyThreads
from laddermill_gym.envs.task_settings import config_from
from laddermill_gym.kernels.contract import B3_RATE, B3_SIZE, B3_VEL
from laddermill_gym.model.configio import load_yaml_text
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["TaskCore", "positive", "check_copies", "substeps_per_period", "clip_observations", "add_wing_noise",
           "default_parallel", "refuse_reset_options"]

#: copies from which a task steps on several threads by default [-]: below it starting the pool costs more than
#: it saves for a small model (TetheredWing-v0 at 8 copies: 43,500 steps/s on one thread, docs/benchmarks.md)
PARALLEL_COPIES = 32
#: state size [-] from which a task steps on several threads from 2 copies on: a copy of the 101-wing chain
#: (1313 states) or mill costs about a millisecond per control period, a thousand times the pool's start
#: (issue 32 point 3, docs/benchmarks.md); the single-wing models (under 100 states) keep PARALLEL_COPIES
PARALLEL_STATE_SIZE = 500


def positive(name: str, v, unit: str) -> float:
    """``v`` as a float; ValueError naming ``name``, the value and the ``unit`` unless it is a finite real number > 0
    (Python's or numpy's: ``np.int64(300)`` from ``np.arange`` and ``np.float32`` pass; a bool does not). A numpy
    float narrower than float64 is read as the shortest decimal that gives it (``np.float32(0.05)`` as 0.05, not
    0.0500000007: a control period read from a float32 array divides an episode as the number written does)."""
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, numbers.Real):
        raise ValueError(f"{name} = {v!r}: must be a number (a finite number > 0 {unit}), not {type(v).__name__}")
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {v!r}: must be a finite number > 0 {unit}")
    if isinstance(v, np.floating) and np.dtype(type(v)).itemsize < 8:
        return float(str(v))
    return float(v)


class CoarseWindWarning(UserWarning):
    """An env's wind is sampled (``wind_dt``) more coarsely than its episode is long: its disturbances barely act."""


def warn_coarse_wind(disturbances, wind_dt: float, episode_time: float) -> None:
    """A :class:`CoarseWindWarning` when ``disturbances`` act on a wind sampled every ``wind_dt`` [s] longer than
    the episode (``episode_time`` [s]): ``wind_dt = 1000`` all but removed the paper's direction step, silently."""
    if disturbances and wind_dt > episode_time:
        warnings.warn(f"wind_dt = {wind_dt:g} s is longer than the episode (episode_time = {episode_time:g} s): the "
                      "wind modulation is sampled every wind_dt, so a disturbance is smeared over wind_dt and barely "
                      "acts", CoarseWindWarning, stacklevel=user_stacklevel())


class LateDisturbanceWarning(UserWarning):
    """A disturbance of an env starts at or after the end of its episode: it never acts (:func:`env_disturbances`)."""


def env_disturbances(value, episode_time: float | None = None, wind_dt: float | None = None) -> tuple:
    """An env's ``disturbances=`` argument as disturbances (``atmosphere.disturbance_spec.parse_disturbances``; None:
    the paper's direction step), YAML text read with the package's loader (YAML 1.2 floats such as ``1e-2`` as
    numbers, a key given twice refused; ConfigError naming ``disturbances``). With ``episode_time`` [s], a
    :class:`LateDisturbanceWarning` names each one whose onset ``time`` (its earliest, for a drawn range) is at or
    after the episode's end: it never acts; with ``wind_dt`` [s] too, :func:`warn_coarse_wind`."""
    if isinstance(value, str):
        value = load_yaml_text(value, "disturbances")
        if value is None:
            raise ValueError("disturbances = '': empty YAML text; give None for the default direction step")
    out = parse_disturbances(value, (DirectionStep(),))
    for i, d in enumerate(out if episode_time is not None else ()):
        onset = getattr(d, "time", None)
        first = min(onset) if isinstance(onset, (tuple, list)) else onset
        if first is not None and first >= episode_time:
            warnings.warn(f"disturbances[{i}] ({type(d).__name__}, time = {onset!r} s) starts at or after the "
                          f"episode's end (episode_time = {episode_time!r} s): it never acts",
                          LateDisturbanceWarning, stacklevel=user_stacklevel())
    if wind_dt is not None and episode_time is not None:
        warn_coarse_wind(out, wind_dt, episode_time)
    return out


def check_copies(n_copies, name: str = "n_copies") -> int:
    """The number of copies B as an int; ValueError naming ``name`` and the value unless it is a positive integer
    (an int, or a float of integral value; not a bool, a string or None)."""
    if (isinstance(n_copies, bool) or not isinstance(n_copies, numbers.Real) or not math.isfinite(n_copies)
            or int(n_copies) != n_copies or n_copies < 1):
        raise ValueError(f"{name} = {n_copies!r}: must be a positive integer")
    return int(n_copies)


def refuse_reset_options(options, name: str, where: str = "gymnasium.make") -> None:
    """ValueError naming ``options`` and the env ``name`` unless ``options`` is None or empty: the envs take their
    disturbances, episode length and the like as arguments (of ``where``), and one that ignored an option would
    reset with its own settings without a word."""
    if options:
        raise ValueError(f"options = {options!r}: {name} takes no reset options (set disturbances, episode_time and "
                         f"the like with {where})")


def substeps_per_period(scene_name: str, settings, control_dt: float, control_dt_given=None) -> int:
    """Physics steps per control period of a scene's fixed-step integrator ``settings``; ValueError if the method
    is error-controlled or ``control_dt`` [s] is not a whole multiple of its step (``control_dt_given`` is the value
    named in that message, default ``control_dt``)."""
    if settings.method not in FIXED_STEP_METHODS:
        raise ValueError(f"scene {scene_name}: integrator.method = {settings.method!r}; environments step with a "
                         f"fixed-step method, one of {FIXED_STEP_METHODS}")
    return whole_multiple(control_dt, settings.dt, control_dt if control_dt_given is None else control_dt_given)


def episode_periods(episode_time: float, control_dt: float) -> int:
    """Control periods in an episode of ``episode_time`` [s] at ``control_dt`` [s]; ValueError naming both unless it
    is a whole number, at least 1, to 1e-9 (before, the fraction was rounded away: an episode of 0.07 s at a 50 ms
    period ended after 0.05 s)."""
    n = int(round(episode_time / control_dt))
    if n < 1 or abs(n * control_dt - episode_time) > 1e-9 * episode_time:
        raise ValueError(f"episode_time = {episode_time!r} s is not a whole number of control periods (control_dt = "
                         f"{control_dt!r} s: {episode_time / control_dt:.6g} periods)")
    return n


def whole_multiple(control_dt: float, dt: float, shown) -> int:
    """round(control_dt / dt); ValueError naming ``shown`` unless control_dt [s] is a whole multiple of dt [s]."""
    n = int(round(control_dt / dt))
    if n < 1 or abs(n * dt - control_dt) > 1e-9 * control_dt:
        raise ValueError(f"control_dt = {shown!r} s is not a whole multiple of the physics step {dt!r} s")
    return n


def clip_observations(raw: np.ndarray, low: np.ndarray, high: np.ndarray, out: np.ndarray) -> None:
    """``out`` = ``raw`` clipped to [low, high], a non-finite entry replaced by the bound on its side (nan: the
    upper bound)."""
    np.clip(np.where(np.isfinite(raw), raw, np.where(raw < 0, low, high)), low, high, out=out)


def add_wing_noise(x: np.ndarray, rotations: np.ndarray, noise, rng: np.random.Generator) -> None:
    """Add random start velocities to the first n wings of the state ``x`` in place: per wing a lateral velocity
    (along the start's body y axis, ``rotations`` (n, 3, 3) body to world) [m/s] and roll and yaw rates [rad/s],
    normal with the standard deviations of ``noise`` (``lateral_velocity``, ``roll_rate``, ``yaw_rate``), drawn
    from ``rng`` as one (n, 3) sample; nothing is drawn when all three are 0."""
    scale = np.array([noise.lateral_velocity, noise.roll_rate, noise.yaw_rate])
    if not np.any(scale > 0):
        return
    n = len(rotations)
    d = rng.normal(size=(n, 3)) * scale  # (global lateral velocity, roll rate, yaw rate) per wing
    w = x[: B3_SIZE * n].reshape(n, B3_SIZE)
    w[:, B3_VEL: B3_VEL + 3] += rotations[:, 1, :] * d[:, :1]  # R^T (0, dvy, 0)
    w[:, B3_RATE] += d[:, 1]
    w[:, B3_RATE + 2] += d[:, 2]


def default_parallel(n_copies: int, state_size: int, parallel) -> bool:
    """Whether B = ``n_copies`` copies of a model of ``state_size`` states step on threads:
    ``parallel`` when given, else from :data:`PARALLEL_COPIES` copies on, or from 2 for a model of at least
    :data:`PARALLEL_STATE_SIZE` states. Each copy's arithmetic is the same either way (bit for bit)."""
    if parallel is not None:
        return bool(parallel)
    return n_copies >= PARALLEL_COPIES or (n_copies >= 2 and state_size >= PARALLEL_STATE_SIZE)


class TaskCore:
    """The shared part of the tasks over a :class:`~laddermill_gym.sim.batch.BatchSimulator` (``batch``), with the
    step counters ``steps`` (B,), ``_nsteps`` (B,) int64 and ``last_action`` (B, n_actions) and a ``_run(nsteps)``
    that advances copy b by nsteps[b] physics steps (0: observe only, < 0: skip) and observes."""

    #: the render modes of the family's single env ("rgb_array" also for its vector env); empty: no rendering
    render_modes: tuple[str, ...] = ("rgb_array", "human")
    #: the name used in the envs' error messages
    env_name: str = "the env"
    #: the settings dataclasses of the ``reward``, ``termination`` and ``initial_noise`` arguments
    reward_class: type | None = None
    termination_class: type | None = None
    noise_class: type | None = None

    # ------------------------------------------------------------------ construction
    def _common_arguments(self, n_copies, control_dt, episode_time, wind_dt, disturbances, reward, termination,
                          initial_noise) -> int:
        """Check the arguments every family takes and return B (``n_copies``): sets ``control_dt``,
        ``episode_time``, ``wind_dt`` [s] (:meth:`_episode_times`), ``disturbances`` (objects, mappings or YAML
        text; None: the paper's 0.01 rad direction step at 1 s), and ``reward_config``, ``termination_config``,
        ``initial_noise`` from their arguments (``config_from`` the family's ``reward_class``,
        ``termination_class``, ``noise_class``: None, an instance or a dict of its fields)."""
        B = check_copies(n_copies)
        self._episode_times(control_dt, episode_time, wind_dt)
        self.disturbances = env_disturbances(disturbances, self.episode_time, self.wind_dt)
        self.reward_config = config_from(reward, self.reward_class, "reward")
        self.termination_config = config_from(termination, self.termination_class, "termination")
        self.initial_noise = config_from(initial_noise, self.noise_class, "initial_noise")
        return B

    def _episode_times(self, control_dt, episode_time, wind_dt) -> None:
        """control_dt, episode_time and wind_dt [s], each checked to be a finite number > 0, episode_time a whole
        number of control periods (``n_steps_max``, :func:`episode_periods`)."""
        self.control_dt = positive("control_dt", control_dt, "s")
        self.episode_time = positive("episode_time", episode_time, "s")
        self.wind_dt = positive("wind_dt", wind_dt, "s")
        self.n_steps_max = episode_periods(self.episode_time, self.control_dt)

    def _wing_limits(self, scene, span: float) -> None:
        """The reward's lateral scale [m] and the termination limits of a wing scene: lowest CG altitude [m]
        (default half of the smallest ``span`` [m]), tension [N], alpha range and |beta| [rad]."""
        rc, tc = self.reward_config, self.termination_config
        self.lateral_scale = rc.lateral_scale if rc.lateral_scale is not None else 0.05 * scene.piece_length
        self.min_altitude = tc.min_altitude if tc.min_altitude is not None else 0.5 * span
        self.breaking_tension = tc.breaking_factor * scene.cable.breaking_load
        self.alpha_lo, self.alpha_hi = np.radians(tc.alpha_range_deg)
        self.beta_max = math.radians(tc.max_abs_beta_deg)

    def close_threads(self) -> None:
        """Shut the copies' thread pool, where the step kernel runs on one (envs/copy_threads.py); the envs and the
        SB3 adapters call it when they close."""
        kernel = getattr(self, "_kernel", None)
        if hasattr(kernel, "close"):
            kernel.close()

    def _check_turbulence_cover(self, assembly, state) -> None:
        """Warn (RuntimeWarning, naming the field and the range needed) for each turbulence disturbance whose grid
        does not cover the start ``state``'s bodies, cable nodes and anchors: outside it the kernels hold the grid's
        edge values, silently (an episode moves the points further; LadderMill checks its whole loop)."""
        from laddermill_gym.envs.gust_cover import START, check_turbulence_cover, start_points

        check_turbulence_cover(self.disturbances, start_points(assembly, state), what=START)

    def _make_batch(self, n_copies: int, assembly, settings, parallel, kernel, launcher, **batch_kwargs) -> None:
        """``n_copies`` (B), ``parallel`` (several threads; None: :func:`default_parallel`), ``_kernel`` (the step
        ``kernel`` on the copies, on numba's thread count when parallel: :class:`~.copy_threads.CopyThreads` with the
        kernel's ``launcher``), the :class:`~laddermill_gym.sim.batch.BatchSimulator` ``batch`` of ``assembly`` with
        a wind modulation sampled every ``wind_dt`` over ``episode_time`` and room for the gust grid of a spatial
        disturbance (turbulence) of ``disturbances`` (``batch_kwargs``: a vehicle's), and the step scratch ``_dx``,
        ``_nsteps``, ``steps``."""
        B = self.n_copies = n_copies
        self.parallel = default_parallel(B, assembly.state_size, parallel)
        self._kernel = CopyThreads(kernel, B, self.parallel, launcher)
        n_mod = int(math.ceil(self.episode_time / self.wind_dt - 1e-9)) + 1
        geom = grid_geometry(self.disturbances, self.episode_time)
        self.batch = BatchSimulator(assembly, B, settings, n_modulation=max(2, n_mod),
                                    n_grid=0 if geom is None else geom.floats, **batch_kwargs)
        self._dx = np.zeros((B, assembly.state_size))
        self._nsteps = np.zeros(B, dtype=np.int64)
        self.steps = np.zeros(B, dtype=np.int64)

    # ------------------------------------------------------------------ stepping
    def _wing_kernel_pass(self, nsteps: np.ndarray, nominal: np.ndarray, obs: np.ndarray) -> None:
        """Advance the copies by nsteps[b] steps with the wing step-and-observe kernel (``self._kernel``), writing
        the wing observations relative to ``nominal`` (n, 3) [m] into ``obs`` and the read-outs into ``aux``."""
        b = self.batch
        b.advance(nsteps, lambda dt, ns: self._kernel(
            *b.kernel_head(dt, ns, self._dx), nominal, self.below, self.ground, obs, self.aux, b.status, b.done))

    def _start_copies(self, idx: np.ndarray) -> None:
        """Zero the step counters of the copies ``idx`` and observe them without stepping (the end of a reset)."""
        self.steps[idx] = 0
        self._nsteps[:] = -1
        self._nsteps[idx] = 0
        self._run(self._nsteps)

    def _advance_copies(self, sel: np.ndarray) -> None:
        """One control period (``n_substeps`` physics steps) of the copies in the boolean mask ``sel`` (B,)."""
        self._nsteps[:] = -1
        self._nsteps[sel] = self.n_substeps
        self._run(self._nsteps)
        self.steps[sel] += 1

    def _reset_copies(self, mask: np.ndarray, rngs, state: np.ndarray, controls: np.ndarray, rotations: np.ndarray,
                      action, body: int = 0) -> None:
        """Start new episodes in the copies selected by the boolean ``mask`` (B,): a fresh wind disturbance and
        the ``initial_noise`` (:func:`add_wing_noise` on the bodies from ``body`` on, whose start rotations are
        ``rotations``) drawn in that order with ``rngs[b]`` (a numpy Generator per copy), added to ``state``;
        ``controls``, t = 0, ``last_action`` = ``action``; then observe them. Other copies are untouched."""
        b = self.batch
        idx = np.flatnonzero(mask)
        for i in idx:
            rng = rngs[i]
            b.set_wind(int(i), sample_wind_field(self.disturbances, self.episode_time, self.wind_dt, rng))
            x = np.array(state)
            add_wing_noise(x[B3_SIZE * body:], rotations, self.initial_noise, rng)
            b.states[i] = x
        b.controls[idx] = controls
        b.t[idx] = 0.0
        self.last_action[idx] = action
        self._start_copies(idx)

    def shaped_reward(self, power: np.ndarray, p_ref: float, lateral: np.ndarray, rates: np.ndarray, effort, failure):
        """(reward (B,), terminated (B,), truncated (B,), info with the reward terms) of the reward the families
        share: w_P P / P_ref - w_y S(lateral) - w_w S(rates) [- w_u S(effort)] - failure_penalty [terminated],
        S(x) = 1 - exp(-x) (a nan x: 1), with the weights of ``reward_config``; ``power`` [W], ``p_ref`` [W],
        ``effort`` None where the family has no effort term; ``failure`` the codes (B,), 0: flying; truncated at
        ``n_steps_max`` control periods."""
        rc = self.reward_config
        terminated = failure != 0
        terms = {"reward_power": rc.power_weight * power / p_ref,
                 "reward_lateral": -rc.lateral_weight * -np.expm1(-np.nan_to_num(lateral, nan=np.inf)),
                 "reward_rates": -rc.rate_weight * -np.expm1(-np.nan_to_num(rates, nan=np.inf))}
        if effort is not None:
            terms["reward_effort"] = -rc.effort_weight * -np.expm1(-effort)
        terms["reward_failure"] = -rc.failure_penalty * terminated
        reward = reduce(add, terms.values())
        truncated = (self.steps >= self.n_steps_max) & ~terminated
        return reward, terminated, truncated, terms

    def observe(self) -> None:
        """Observe every copy at its current state without stepping (after restoring states by hand)."""
        self._nsteps[:] = 0
        self._run(self._nsteps)

    # ------------------------------------------------------------------ the envs' hooks
    def reset_info(self) -> dict:
        """Entries of a single env's reset info beside ``t`` (none by default)."""
        return {}

    def env_kwargs(self, kwargs: dict) -> dict:
        """The arguments a pickled single env is rebuilt from (by default those it was made with)."""
        return dict(kwargs)

    def snapshot(self) -> dict:
        """Copies of everything an episode in progress depends on: the batch's states, controls, times and air,
        the step counters and last actions (the pickled env's state), and the kernels' workspace where a W-method
        keeps its iteration matrix over steps (``jacobian_every`` > 1: the next steps solve with the held one)."""
        b = self.batch
        held = getattr(b.settings, "jacobian_every", 1) > 1
        return {"arrays": (b.states.copy(), b.controls.copy(), b.t.copy(), self.steps.copy(), self.last_action.copy()),
                "air": tuple(None if a is None else a.copy() for a in b.air),
                "work": tuple(a.copy() for a in b.work) if held else None}

    def restore(self, snap: dict) -> None:
        """Put a :meth:`snapshot` back (the caller observes afterwards)."""
        b = self.batch
        b.states[:], b.controls[:], b.t[:], self.steps[:], self.last_action[:] = snap["arrays"]
        for mine, saved in zip(b.air, snap["air"], strict=True):
            if mine is not None:
                mine[:] = saved
        for mine, saved in zip(b.work, snap.get("work") or (), strict=False):
            mine[:] = saved

    def _snapshot_simulator(self, make, b: int, **reset_kwargs):
        """``make(assembly, state, settings, controls)`` at copy ``b``'s state, time [s], controls and air: a
        single simulator for read-outs (stepping it does not step the copy)."""
        bt = self.batch
        sim = make(bt.assembly, bt.states[b], bt.settings, bt.controls[b])
        air = {f: a[b].copy() for f, a in zip(bt.air._fields, bt.air, strict=True) if a is not None}
        sim.model = sim.model._replace(**air)
        sim.reset(state=bt.states[b], t=float(bt.t[b]), controls=bt.controls[b], **reset_kwargs)
        return sim
