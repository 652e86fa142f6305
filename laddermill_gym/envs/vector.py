"""The one native vector environment of every env family: all copies of a task stepped by one compiled kernel,
parallel over copies (registered as the ``vector_entry_point`` of every env; ``gymnasium.make_vec(id, n,
vectorization_mode="vector_entry_point")``). A family's vector env is a subclass that names its task
(``task_class``) and says what its info holds; the checks, seeding, autoreset, info keys and rendering are here.

It follows Gymnasium's ``SyncVectorEnv`` over the family's single envs (copy i seeded seed + i) in everything a
caller sees: observations, rewards, the three autoreset modes (NextStep, SameStep, Disabled with
``reset(options={"reset_mask": mask})``), the info dict (each key with its ``_key`` mask: a copy reset in this call
holds its reset info, ``t`` = 0 and the task's ``reset_info()``, and none of the step's keys, whose entries are then
0 or None) and ``render()`` (one frame per copy)."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from laddermill_gym.envs import registered_arguments
from laddermill_gym.envs.actions import action_array
from laddermill_gym.envs.task_base import check_copies
from laddermill_gym.envs.task_env import check_render_mode, check_task_arguments


def check_vector_arguments(num_envs, render_mode, autoreset_mode, task_class) -> AutoresetMode:
    """Validate the vector-env arguments every task shares; returns the autoreset mode. Raises ValueError
    naming the argument and its value."""
    check_copies(num_envs, "num_envs")
    try:
        mode = AutoresetMode(autoreset_mode)
    except ValueError:
        raise ValueError(f"autoreset_mode = {autoreset_mode!r}: must be one of "
                         f"{[m.value for m in AutoresetMode]}") from None
    if not task_class.render_modes:
        check_render_mode(render_mode, (), task_class.env_name)
    if render_mode not in (None, "rgb_array"):
        raise ValueError(f"render_mode = {render_mode!r}: the vector env renders 'rgb_array' only")
    return mode


class TaskVectorEnv(VectorEnv):
    """The Gymnasium vector env of a task of B copies (the protocol of ``envs/task_base.py``); subclasses set
    ``task_class``.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: ``render()`` returns one frame per copy; None only
    where the task does not render), ``autoreset_mode``, ``parallel`` (threads; default from 32 copies on, from 2
    for a model of 500 states or more: ``task_base.default_parallel``) and the task's arguments; others raise
    ValueError naming them; ``max_episode_steps`` (Gymnasium's, which ``make_vec`` passes on) truncates an episode
    at that many control periods if it comes before ``episode_time``. ``info`` holds the task's info arrays, each
    with its ``_name`` mask, and ``failure_name`` / ``failure_reason`` per copy; a copy reset in the call holds its
    reset info instead (``t`` = 0 and the task's ``reset_info()``, e.g. ``reference_power_W``), as SyncVectorEnv
    gives.

    Copy i behaves exactly like the task's single env seeded with ``seed + i`` (bit for bit: same kernel, same
    arithmetic). Autoreset: ``autoreset_mode`` "NextStep" (Gymnasium's default: the step after an episode ends
    resets that copy, ignores its action and reports reward 0), "SameStep" (the reset observation is returned at
    once; the final observation and info are in ``info["final_obs"]``, ``info["final_info"]``) or "Disabled" (the
    caller resets ended copies with ``reset(options={"reset_mask": mask})``; stepping one before raises
    RuntimeError). A step before every copy's first reset raises ``gymnasium.error.ResetNeeded``. Actions: a finite
    real array (num_envs, n_actions); anything else raises :class:`~laddermill_gym.envs.actions.ActionError` before
    any copy moves.
    """

    task_class: type
    #: as the single env's (``envs/task_env.TaskEnv.registered_id``)
    registered_id: str | None = None
    metadata = {"render_modes": ["rgb_array"], "render_fps": 20, "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode, self.task_class)
        max_steps = task_kwargs.pop("max_episode_steps", None)
        if self.registered_id is not None:
            task_kwargs = registered_arguments(self.registered_id, task_kwargs)
        check_task_arguments(self.task_class, task_kwargs, vector=True)
        self.task = task = self.task_class(int(num_envs), **task_kwargs)
        if max_steps is not None:  # Gymnasium's step limit (the single env's TimeLimit wrapper), if shorter
            task.n_steps_max = min(task.n_steps_max, check_copies(max_steps, "max_episode_steps"))
        self.failure_names = dict(task.failure_names)
        self.num_envs = int(task.n_copies)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, autoreset_mode=mode, render_fps=1.0 / task.control_dt)  # as the single env
        self.autoreset_mode = mode
        self._ever_reset = np.zeros(int(num_envs), dtype=bool)
        self.single_observation_space = gym.spaces.Box(task.obs_low.astype(np.float32),
                                                       task.obs_high.astype(np.float32), dtype=np.float32)
        self.single_action_space = gym.spaces.Box(-1.0, 1.0, shape=(task.n_actions,), dtype=np.float32)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        # each copy's generator and its seed, as a single env draws them on first use (np_random_seed)
        drawn = [gym.utils.seeding.np_random() for _ in range(self.num_envs)]
        self._rngs, self._seeds = [g for g, _ in drawn], [s for _, s in drawn]
        self._autoreset = np.zeros(self.num_envs, dtype=bool)
        self._renderer = None
        self._no_failure = None
        if not task.render_modes:
            self.metadata = dict(self.metadata, render_modes=[])

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral offsets [m] (num_envs, m) of batched observations (the evaluation harness's and the gust
        benchmark's lateral read-out; the task says which offsets)."""
        return self.task.lateral_offsets(obs)

    # ------------------------------------------------------------------ resets
    def _reset_mask(self, options: dict | None) -> np.ndarray:
        """``options["reset_mask"]`` checked as SyncVectorEnv checks it (a (num_envs,) bool numpy array with a True
        entry; TypeError or ValueError otherwise), or every copy. Any other option is refused by name (the single
        envs take none: ``task_env.py``)."""
        other = sorted(set(options or {}) - {"reset_mask"})
        if other:
            raise ValueError(f"options {other}: the vector env takes only 'reset_mask' (set disturbances, "
                             "episode_time and the like with gymnasium.make_vec)")
        if not options or "reset_mask" not in options:
            return np.ones(self.num_envs, bool)
        mask = options["reset_mask"]
        if not isinstance(mask, np.ndarray):
            raise TypeError(f"options['reset_mask'] must be a numpy array, got {type(mask)}")
        if mask.shape != (self.num_envs,):
            raise ValueError(f"options['reset_mask'] must have shape ({self.num_envs},), got {mask.shape}")
        if mask.dtype != np.bool_:
            raise TypeError(f"options['reset_mask'] must have dtype bool, got {mask.dtype}")
        if not mask.any():
            raise ValueError(f"options['reset_mask'] must hold at least one True entry, got {mask}")
        return mask.copy()

    def _seed(self, seed, mask: np.ndarray) -> None:
        """New generators for the copies in ``mask`` whose seed is not None: ``seed`` an int (copy i: seed + i) or
        num_envs seeds; the same generator a single env builds in ``Env.reset(seed=s)``."""
        if seed is None:
            return
        if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        elif isinstance(seed, (list, tuple, np.ndarray)):
            seeds = list(seed)
        else:
            raise ValueError(f"seed = {seed!r}: an int (copy i: seed + i), {self.num_envs} seeds or None")
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed: expected an int or {self.num_envs} seeds, got {len(seeds)}")
        for i in np.flatnonzero(mask):
            if seeds[i] is not None:
                self._rngs[i], self._seeds[i] = gym.utils.seeding.np_random(seeds[i])

    @property
    def np_random_seed(self) -> tuple[int, ...]:
        """The seed of each copy's generator (as ``SyncVectorEnv`` gives its envs' ``np_random_seed``)."""
        return tuple(self._seeds)

    def reset(self, *, seed: int | list[int | None] | None = None, options: dict[str, Any] | None = None):
        """Reset the copies of ``options["reset_mask"]`` (default: every copy); ``seed`` an int (copy i gets
        seed + i), a list of num_envs seeds (None: that copy keeps drawing from its generator) or None. The info
        holds the reset copies' reset info (``t`` and the task's ``reset_info()``), each key with its mask."""
        mask = self._reset_mask(options)
        self._seed(seed, mask)
        self.task.reset(mask, self._rngs)
        self._autoreset[mask] = False
        self._ever_reset |= mask
        return self.task.obs.astype(np.float32), self._info(None, np.zeros(self.num_envs, bool), mask)

    # ------------------------------------------------------------------ steps
    def step(self, actions):
        """One control period of every copy (the autoreset mode says what a copy whose episode ended does)."""
        n = self.num_envs
        if not self._ever_reset.all():  # those copies hold no state yet (SyncVectorEnv raises the same)
            raise gym.error.ResetNeeded(f"step() before reset(): copies {np.flatnonzero(~self._ever_reset).tolist()} "
                                        "were never reset; call reset() first")
        a = action_array(actions, (n, self.task.n_actions))
        mode = self.autoreset_mode
        if mode == AutoresetMode.DISABLED and self._autoreset.any():
            raise RuntimeError(f"copies {np.flatnonzero(self._autoreset).tolist()} ended in the last step: with "
                               "autoreset_mode Disabled, reset them with reset(options={'reset_mask': mask}) first")
        resetting = self._autoreset.copy() if mode == AutoresetMode.NEXT_STEP else np.zeros(n, bool)
        if resetting.any():
            self.task.reset(resetting, self._rngs)
            reward, terminated, truncated, info = self.task.step(a, mask=~resetting)
            reward[resetting] = 0.0
            terminated[resetting] = False
            truncated[resetting] = False
        else:
            reward, terminated, truncated, info = self.task.step(a)
        done = terminated | truncated
        self._failure_text(info)
        if mode == AutoresetMode.SAME_STEP and done.any():
            final_obs = np.full(n, None, dtype=object)
            for i in np.flatnonzero(done):
                final_obs[i] = self.task.obs[i].astype(np.float32)
            final_info = self._info(info, done, np.zeros(n, bool))
            self.task.reset(done, self._rngs)
            out = self._info(info, ~done, done)
            out["final_obs"], out["_final_obs"] = final_obs, done.copy()
            out["final_info"], out["_final_info"] = final_info, done.copy()
        else:
            out = self._info(info, ~resetting, resetting)
        self._autoreset = done
        return self.task.obs.astype(np.float32), reward, terminated, truncated, out

    def _failure_text(self, info: dict) -> None:
        """The single env's ``failure_name`` and ``failure_reason`` per copy into ``info``."""
        codes = np.asarray(info["failure"])
        failed = np.flatnonzero(codes)
        if self._no_failure is None:  # (names, reasons) of copies flying: code 0's name, no reason
            self._no_failure = (np.full(codes.shape[0], self.failure_names[0], dtype=object),
                                np.full(codes.shape[0], "", dtype=object))
        names, reasons = self._no_failure[0].copy(), self._no_failure[1].copy()  # a copy: a third of np.full's time
        for i in failed:  # the few copies that failed in this step
            names[i], reasons[i] = self.failure_names[int(codes[i])], self.task.failure_text(int(i), int(codes[i]))
        info["failure_name"], info["failure_reason"] = names, reasons

    def _info(self, step_info: dict | None, stepped: np.ndarray, reset: np.ndarray) -> dict[str, Any]:
        """The vector info as SyncVectorEnv builds it from its single envs' infos: the task's step info arrays
        (B, ...) for the copies ``stepped`` and the reset info for the copies ``reset``, each key with its mask;
        a copy without a key holds 0 (None in an object array) there; a key no copy holds is left out."""
        out: dict[str, Any] = {}
        every = bool(stepped.all())
        for k, v in (step_info if step_info is not None and stepped.any() else {}).items():
            dtype = _single_dtype(v)
            if every and v.dtype == dtype:  # the task's fresh array of this step, as it is (no copy)
                arr = v
            else:
                arr = np.array(v, dtype=dtype)
                arr[~stepped] = None if arr.dtype == object else 0
            out[k], out["_" + k] = arr, stepped.copy()
        if reset.any():
            for k, value in {"t": 0.0, **self.task.reset_info()}.items():
                if k not in out:
                    out[k], out["_" + k] = _empty_like(value, self.num_envs), np.zeros(self.num_envs, bool)
                out[k][reset] = value
                out["_" + k] = out["_" + k] | reset
        return out

    # ------------------------------------------------------------------ rendering
    def render(self) -> tuple | None:
        """One RGB frame (H, W, 3) uint8 per copy, as SyncVectorEnv's tuple of its single envs' frames; None (with
        a warning) without a render mode."""
        if self.render_mode != "rgb_array":
            gym.logger.warn("render() called without a render_mode; pass render_mode='rgb_array'")
            return None
        if not self._ever_reset.all():  # copies hold no state yet (as gym.make's order check for the single env)
            raise gym.error.ResetNeeded("render() before reset(): call reset() first")
        if self._renderer is None:
            self._renderer = self.task.renderer()
        return tuple(self._renderer.draw(i) for i in range(self.num_envs))

    def close_extras(self, **kwargs):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        self.task.close_threads()


def _single_dtype(v: np.ndarray):
    """The dtype SyncVectorEnv's info array gets from the single env's entry: v[0].item() (a Python float, int or
    bool: float64, int64, bool) for a (B,) numeric array, the array's own dtype otherwise."""
    if v.ndim == 1 and v.dtype.kind in "fiub":
        return {"f": np.float64, "i": np.int64, "u": np.int64, "b": np.bool_}[v.dtype.kind]
    return v.dtype


def _empty_like(value, n: int) -> np.ndarray:
    """The array SyncVectorEnv starts for an info key first met with ``value``: zeros of its type for a number,
    zeros of its shape and dtype for an array, None entries otherwise."""
    if type(value) in (int, float, bool) or isinstance(value, np.number):
        return np.zeros(n, dtype=type(value))
    if isinstance(value, np.ndarray):
        return np.zeros((n, *value.shape), dtype=value.dtype)
    return np.full(n, None, dtype=object)
