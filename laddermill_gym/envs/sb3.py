"""Stable-Baselines3 ``VecEnv`` adapter over the batched tasks (needs the ``rl`` extra).

SB3 resets finished copies in the same step and puts the last observation of an episode into
``infos[i]["terminal_observation"]`` and ``infos[i]["TimeLimit.truncated"]``; this adapter does exactly that
on top of a task with B copies (:class:`~laddermill_gym.envs.task.WingTask`,
:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`), so SB3 algorithms train on the compiled batch without
Gymnasium's per-copy Python loop. :func:`sb3_vec_env` builds it for any registered environment.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env import VecEnv

from laddermill_gym.envs import env_arguments, task_class
from laddermill_gym.envs.task import FAILURES, WingTask

__all__ = ["TaskSB3VecEnv", "WingSB3VecEnv", "sb3_vec_env"]


class TaskSB3VecEnv(VecEnv):
    """The copies of a batched ``task`` (``WingTask`` or ``CraftTask``: ``reset(mask, rngs)``, ``step(actions)``,
    ``obs`` (B, n_obs), ``obs_low``, ``obs_high``, ``n_actions``, ``n_copies``) as an SB3 VecEnv. Copy i seeded
    with ``seed + i`` (``venv.seed(seed)`` before the reset) draws the disturbances of a single env seeded so."""

    def __init__(self, task):
        self.task = task
        obs_space = gym.spaces.Box(self.task.obs_low.astype(np.float32), self.task.obs_high.astype(np.float32),
                                   dtype=np.float32)
        act_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        super().__init__(int(task.n_copies), obs_space, act_space)
        self.failure_names = dict(getattr(task, "failure_names", FAILURES))
        self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
        self._actions = np.zeros((self.num_envs, self.task.n_actions))
        self.render_mode = None

    def reset(self) -> np.ndarray:
        if self._seeds is not None and any(s is not None for s in self._seeds):
            self._rngs = [gym.utils.seeding.np_random(s)[0] for s in self._seeds]
            self._reset_seeds()
        self.task.reset(np.ones(self.num_envs, bool), self._rngs)
        return self.task.obs.astype(np.float32)

    def step_async(self, actions: np.ndarray) -> None:
        self._actions = np.asarray(actions, dtype=float).reshape(self.num_envs, self.task.n_actions)

    def step_wait(self):
        reward, terminated, truncated, info = self.task.step(self._actions)
        done = terminated | truncated
        obs = self.task.obs.astype(np.float32)
        infos: list[dict[str, Any]] = [{} for _ in range(self.num_envs)]
        for i in np.flatnonzero(done):
            infos[i] = {k: (v[i].item() if v.ndim == 1 else v[i].copy()) for k, v in info.items()}
            infos[i]["terminal_observation"] = obs[i].copy()
            infos[i]["TimeLimit.truncated"] = bool(truncated[i] and not terminated[i])
            infos[i]["failure_name"] = self.failure_names[int(info["failure"][i])]
        if done.any():
            self.task.reset(done, self._rngs)
            obs = self.task.obs.astype(np.float32)
        return obs, reward.astype(np.float32), done, infos

    def close(self) -> None:
        pass

    def get_attr(self, attr_name: str, indices=None) -> list[Any]:
        if attr_name == "render_mode":  # the copies are drawn by get_images, not by a per-env render mode
            return [None for _ in self._get_indices(indices)]
        return [getattr(self.task, attr_name) for _ in self._get_indices(indices)]

    def set_attr(self, attr_name: str, value: Any, indices=None) -> None:
        raise AttributeError(f"set_attr({attr_name!r}): the copies share one task; build a new env instead")

    def env_method(self, method_name: str, *method_args, indices=None, **method_kwargs) -> list[Any]:
        fn = getattr(self.task, method_name)
        return [fn(*method_args, **method_kwargs) for _ in self._get_indices(indices)]

    def env_is_wrapped(self, wrapper_class, indices=None) -> list[bool]:
        return [False for _ in self._get_indices(indices)]

    def get_images(self):
        r = self.task.renderer()
        return [r.draw(i) for i in range(self.num_envs)]


class WingSB3VecEnv(TaskSB3VecEnv):
    """``num_envs`` copies of a wing env as an SB3 VecEnv (same arguments as
    :class:`~laddermill_gym.envs.vector.WingVectorEnv`)."""

    def __init__(self, num_envs: int, **task_kwargs):
        super().__init__(WingTask(int(num_envs), **task_kwargs))


def sb3_vec_env(env_id: str, num_envs: int, seed: int | None = None, **env_kwargs) -> TaskSB3VecEnv:
    """SB3 VecEnv of ``num_envs`` copies of the registered environment ``env_id`` with the arguments ``env_kwargs``
    (the registered defaults are not added: pass them), copy i seeded with ``seed + i`` at its first reset.
    ValueError names an argument the environment does not take."""
    known = env_arguments(env_id)
    unknown = sorted(set(env_kwargs) - set(known))
    if unknown:
        raise ValueError(f"{', '.join(f'{k} = {env_kwargs[k]!r}' for k in unknown)}: {env_id} takes no such "
                         f"argument (known: {', '.join(known)})")
    venv = TaskSB3VecEnv(task_class(env_id)(int(num_envs), **env_kwargs))
    if seed is not None:
        venv.seed(seed)
    return venv
