"""Stable-Baselines3 ``VecEnv`` adapter over the batched tasks (needs the ``rl`` extra).

SB3 resets finished copies in the same step and puts the last observation of an episode into
``infos[i]["terminal_observation"]`` and ``infos[i]["TimeLimit.truncated"]``; this adapter does exactly that
on top of a task with B copies (:class:`~laddermill_gym.envs.task.WingTask`,
:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`, the mill's ``MillTask``), so SB3 algorithms train on the
compiled batch without Gymnasium's per-copy Python loop. Every step's ``infos[i]`` holds the single env's ``info``
keys (reward terms, power, failure code, name and reason ...), as ``DummyVecEnv`` over ``gymnasium.make`` gives.

One line for SB3 users: ``venv = sb3_vec_env("laddermill_gym/TetheredWing-v0", 8, seed=0)`` builds the same model
as ``gymnasium.make`` (the registered defaults, then your overrides), bit for bit.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env import VecEnv

from laddermill_gym.envs import ENV_IDS, env_arguments, registered_arguments, task_class
from laddermill_gym.envs.actions import action_array
from laddermill_gym.envs.task import FAILURES, WingTask
from laddermill_gym.envs.task_base import check_copies, refuse_reset_options

__all__ = ["TaskSB3VecEnv", "WingSB3VecEnv", "sb3_vec_env"]


class TaskSB3VecEnv(VecEnv):
    """The copies of a batched ``task`` (``WingTask`` or ``CraftTask``: ``reset(mask, rngs)``, ``step(actions)``,
    ``obs`` (B, n_obs), ``obs_low``, ``obs_high``, ``n_actions``, ``n_copies``) as an SB3 VecEnv. Copy i seeded
    with ``seed + i`` (``venv.seed(seed)`` before the reset) draws the disturbances of a single env seeded so.
    ``reset_infos`` holds each copy's reset info (``t`` and the task's ``reset_info()``) as ``DummyVecEnv`` fills
    it; the envs take no reset options (``set_options`` with any is refused at the next reset); a step before the
    first reset raises ``gymnasium.error.ResetNeeded``."""

    def __init__(self, task, env_id: str | None = None, env_kwargs: dict | None = None,
                 render_mode: str | None = None):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode = {render_mode!r}: None or 'rgb_array'")
        self.task = task
        self.render_mode = render_mode  # before VecEnv.__init__, which asks get_attr("render_mode")
        self.env_id = env_id
        self.env_kwargs = dict(env_kwargs or {})
        obs_space = gym.spaces.Box(self.task.obs_low.astype(np.float32), self.task.obs_high.astype(np.float32),
                                   dtype=np.float32)
        act_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        super().__init__(check_copies(task.n_copies, "num_envs"), obs_space, act_space)
        self.metadata = dict(self.metadata, render_fps=1.0 / task.control_dt)  # VecVideoRecorder's rate (30 without)
        self.failure_names = dict(getattr(task, "failure_names", FAILURES))
        self._renderer = None
        self._was_reset = False
        self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
        self._actions = np.zeros((self.num_envs, self.task.n_actions))
        self.render_mode = render_mode

    def reset(self) -> np.ndarray:
        for options in self._options:
            refuse_reset_options(options, self.env_id or type(self.task).__name__, "the env's arguments")
        self._reset_options()
        if self._seeds is not None and any(s is not None for s in self._seeds):
            self._rngs = [gym.utils.seeding.np_random(s)[0] for s in self._seeds]
            self._reset_seeds()
        self.task.reset(np.ones(self.num_envs, bool), self._rngs)
        self._was_reset = True
        self.reset_infos = [self._reset_info() for _ in range(self.num_envs)]
        return self.task.obs.astype(np.float32)

    def _reset_info(self) -> dict[str, Any]:
        return {"t": 0.0, **self.task.reset_info()}

    def step_async(self, actions: np.ndarray) -> None:
        """Take the actions (num_envs, n_actions); :class:`~laddermill_gym.envs.actions.ActionError` (nothing
        stepped) unless they are a finite real array of that shape."""
        if not self._was_reset:  # the copies hold no state yet (DummyVecEnv's envs raise the same)
            raise gym.error.ResetNeeded("step() before reset(): call reset() first")
        self._actions = action_array(actions, (self.num_envs, self.task.n_actions))

    def step_wait(self):
        reward, terminated, truncated, info = self.task.step(self._actions)
        done = terminated | truncated
        obs = self.task.obs.astype(np.float32)
        infos: list[dict[str, Any]] = []
        for i in range(self.num_envs):
            d = {k: (v[i].item() if v.ndim == 1 else v[i].copy()) for k, v in info.items()}
            code = int(info["failure"][i])
            d["failure_name"] = self.failure_names[code]
            d["failure_reason"] = self.task.failure_text(i, code) if code else ""
            d["TimeLimit.truncated"] = bool(truncated[i] and not terminated[i])  # every step, as DummyVecEnv
            infos.append(d)
        for i in np.flatnonzero(done):
            infos[i]["terminal_observation"] = obs[i].copy()
        if done.any():
            self.task.reset(done, self._rngs)
            obs = self.task.obs.astype(np.float32)
            for i in np.flatnonzero(done):
                self.reset_infos[i] = self._reset_info()
        return obs, reward.astype(np.float32), done, infos

    def close(self) -> None:
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        self.task.close_threads()

    def get_attr(self, attr_name: str, indices=None) -> list[Any]:
        """``spec`` (the registered EnvSpec with this env's arguments), ``render_mode``, the single env's spaces and
        ``metadata``, each copy's ``np_random``, or an attribute of the shared task (the same for every copy)."""
        if attr_name == "np_random":
            return [self._rngs[i] for i in self._get_indices(indices)]
        if attr_name in ("render_mode", "observation_space", "action_space", "metadata"):
            value = getattr(self, attr_name)
        elif attr_name == "spec":
            import dataclasses

            value = (dataclasses.replace(gym.spec(self.env_id), kwargs=dict(self.env_kwargs))
                     if self.env_id is not None else None)
        else:
            value = getattr(self.task, attr_name)
        return [value for _ in self._get_indices(indices)]

    def set_attr(self, attr_name: str, value: Any, indices=None) -> None:
        """Set an attribute of the task the copies share: only for all copies at once (AttributeError otherwise,
        and for an attribute the task does not have)."""
        if len(list(self._get_indices(indices))) != self.num_envs:
            raise AttributeError(f"set_attr({attr_name!r}, indices={indices!r}): the copies share one task, so an "
                                 "attribute can only be set for all of them")
        if not hasattr(self.task, attr_name):
            raise AttributeError(f"set_attr({attr_name!r}): the task {type(self.task).__name__} has no such "
                                 "attribute")
        setattr(self.task, attr_name, value)

    def env_method(self, method_name: str, *method_args, indices=None, **method_kwargs) -> list[Any]:
        """A method of the task the copies share, called once for all of them (its result repeated per copy);
        AttributeError for a subset of the copies, and for ``reset`` and ``step`` (the VecEnv's own)."""
        if method_name in ("reset", "step"):
            raise AttributeError(f"env_method({method_name!r}): the copies share one task; call the VecEnv's "
                                 f"{method_name}()")
        idx = list(self._get_indices(indices))
        if len(idx) != self.num_envs:
            raise AttributeError(f"env_method({method_name!r}, indices={indices!r}): the copies share one task, so a "
                                 "method runs for all of them")
        result = getattr(self.task, method_name)(*method_args, **method_kwargs)
        return [result for _ in idx]

    def env_is_wrapped(self, wrapper_class, indices=None) -> list[bool]:
        return [False for _ in self._get_indices(indices)]

    def get_images(self):
        """One RGB frame (H, W, 3) uint8 per copy (one figure, kept until :meth:`close`); ResetNeeded before the
        first reset (the copies hold no state yet)."""
        if not self._was_reset:
            raise gym.error.ResetNeeded("get_images() before reset(): call reset() first")
        if self._renderer is None:
            self._renderer = self.task.renderer()
        return [self._renderer.draw(i) for i in range(self.num_envs)]


class WingSB3VecEnv(TaskSB3VecEnv):
    """``num_envs`` copies of a wing env as an SB3 VecEnv (same arguments as
    :class:`~laddermill_gym.envs.wing_env.WingVectorEnv`)."""

    def __init__(self, num_envs: int, env_id: str = "laddermill_gym/TetheredWing-v0", render_mode=None,
                 **task_kwargs):
        kw = registered_arguments(env_id, task_kwargs)  # the registered defaults, as gymnasium.make(env_id) uses
        super().__init__(WingTask(check_copies(num_envs, "num_envs"), **kw), env_id, kw, render_mode)


def sb3_vec_env(env_id: str, num_envs: int, seed: int | None = None, render_mode: str | None = None,
                **env_kwargs) -> TaskSB3VecEnv:
    """SB3 VecEnv of ``num_envs`` copies of the registered environment ``env_id``: its registered defaults merged
    with ``env_kwargs`` (``envs.registered_arguments``: the model ``gymnasium.make(env_id, **env_kwargs)`` builds,
    dict-valued arguments such as ``scene_options`` merged key by key), copy i seeded with
    ``seed + i`` at its first reset; ``render_mode="rgb_array"`` for ``VecVideoRecorder``. ValueError names an
    argument the environment does not take."""
    if env_id not in ENV_IDS:
        raise ValueError(f"env_id = {env_id!r}: must be one of {sorted(ENV_IDS)}")
    known = env_arguments(env_id)
    unknown = sorted(set(env_kwargs) - set(known))
    if unknown:
        raise ValueError(f"{', '.join(f'{k} = {env_kwargs[k]!r}' for k in unknown)}: {env_id} takes no such "
                         f"argument (known: {', '.join(known)})")
    kw = registered_arguments(env_id, env_kwargs)
    venv = TaskSB3VecEnv(task_class(env_id)(check_copies(num_envs, "num_envs"), **kw), env_id, kw, render_mode)
    if seed is not None:
        venv.seed(seed)
    return venv
