"""The one native vector environment of every env family: all copies of a task stepped by one compiled kernel,
parallel over copies (registered as the ``vector_entry_point`` of every env; ``gymnasium.make_vec(id, n,
vectorization_mode="vector_entry_point")``). A family's vector env is a subclass that names its task
(``task_class``) and says what its info holds; the checks, seeding, autoreset, info keys and rendering are here."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from laddermill_gym.envs.task_env import check_render_mode, check_task_arguments

#: info entries of copies reset in a NextStep autoreset step (reported as 0)
ZEROED_ON_RESET: tuple[str, ...] = ("failure", "n_clipped", "reward_power", "reward_lateral", "reward_rates",
                                    "reward_effort", "reward_failure")


def check_vector_arguments(num_envs, render_mode, autoreset_mode, task_class) -> AutoresetMode:
    """Validate the vector-env arguments every task shares; returns the autoreset mode. Raises ValueError
    naming the argument and its value."""
    if isinstance(num_envs, bool) or int(num_envs) != num_envs or num_envs < 1:
        raise ValueError(f"num_envs = {num_envs!r}: must be a positive integer")
    mode = AutoresetMode(autoreset_mode)
    if mode == AutoresetMode.DISABLED:
        raise ValueError("autoreset_mode = 'Disabled' is not supported: use 'NextStep' or 'SameStep'")
    if not task_class.render_modes:
        check_render_mode(render_mode, (), task_class.env_name)
    if render_mode not in (None, "rgb_array"):
        raise ValueError(f"render_mode = {render_mode!r}: the vector env renders 'rgb_array' only")
    return mode


class TaskVectorEnv(VectorEnv):
    """The Gymnasium vector env of a task of B copies (the protocol of ``envs/task_base.py``); subclasses set
    ``task_class``.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: copy 0; None only where the task does not render),
    ``autoreset_mode``, ``parallel`` (numba thread pool; default from 32 copies on) and the task's arguments;
    others raise ValueError naming them. ``info`` holds the task's info arrays, each with its ``_name`` mask, and
    ``failure_name`` / ``failure_reason`` per copy.

    Copy i behaves exactly like the task's single env seeded with ``seed + i`` (bit for bit: same kernel, same
    arithmetic). Autoreset: ``autoreset_mode`` "NextStep" (Gymnasium's default: the step after an episode ends
    resets that copy, ignores its action and reports reward 0 and failure 0) or "SameStep" (the reset
    observation is returned at once; the final observation and info are in ``info["final_obs"]``,
    ``info["final_info"]``). ``task.renderer()`` draws copy 0.
    """

    task_class: type
    metadata = {"render_modes": ["rgb_array"], "render_fps": 20, "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode, self.task_class)
        task_kwargs.pop("max_episode_steps", None)
        check_task_arguments(self.task_class, task_kwargs, vector=True)
        self.task = task = self.task_class(int(num_envs), **task_kwargs)
        self.failure_names = dict(task.failure_names)
        self.num_envs = int(task.n_copies)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, autoreset_mode=mode, render_fps=int(round(1.0 / task.control_dt)))
        self.autoreset_mode = mode
        self.single_observation_space = gym.spaces.Box(task.obs_low.astype(np.float32),
                                                       task.obs_high.astype(np.float32), dtype=np.float32)
        self.single_action_space = gym.spaces.Box(-1.0, 1.0, shape=(task.n_actions,), dtype=np.float32)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
        self._autoreset = np.zeros(self.num_envs, dtype=bool)
        self._renderer = None
        if not task.render_modes:
            self.metadata = dict(self.metadata, render_modes=[])

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral offsets [m] (num_envs, m) of batched observations (the evaluation harness's and the gust
        benchmark's lateral read-out; the task says which offsets)."""
        return self.task.lateral_offsets(obs)

    def _seed(self, seed) -> None:
        if seed is None:
            self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
            return
        seeds = ([int(seed) + i for i in range(self.num_envs)] if isinstance(seed, (int, np.integer))
                 else list(seed))
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed: expected an int or {self.num_envs} seeds, got {len(seeds)}")
        # the same generator a single env builds in Env.reset(seed=s)
        self._rngs = [gym.utils.seeding.np_random(s)[0] for s in seeds]

    def reset(self, *, seed: int | list[int] | None = None, options: dict[str, Any] | None = None):
        """Reset every copy; ``seed`` an int (copy i gets seed + i), a list of num_envs seeds or None (the copies
        keep drawing from their generators)."""
        if seed is not None:
            self._seed(seed)
        self.task.reset(np.ones(self.num_envs, bool), self._rngs)
        self._autoreset[:] = False
        info = {"t": self.task.batch.t.copy(), "_t": np.ones(self.num_envs, bool)}
        return self.task.obs.astype(np.float32), info

    def step(self, actions):
        a = np.asarray(actions, dtype=float).reshape(self.num_envs, self.task.n_actions)
        n = self.num_envs
        if self.autoreset_mode == AutoresetMode.NEXT_STEP and self._autoreset.any():
            resetting = self._autoreset.copy()
            self.task.reset(resetting, self._rngs)
            reward, terminated, truncated, info = self.task.step(a, mask=~resetting)
            reward[resetting] = 0.0
            terminated[resetting] = False
            truncated[resetting] = False
            for k in ZEROED_ON_RESET:  # the terms a task reports (PumpingKite-v0 has no reward_effort)
                if k in info:
                    info[k][resetting] = 0
        else:
            reward, terminated, truncated, info = self.task.step(a)
        done = terminated | truncated
        obs = self.task.obs.astype(np.float32)
        # the single env's failure name and reason too, so native and sync vector envs give the same info keys
        names = self.failure_names
        codes = [int(c) for c in info["failure"]]
        info["failure_name"] = np.array([names[c] for c in codes], dtype=object)
        info["failure_reason"] = np.array([self.task.failure_text(i, c) if c else "" for i, c in enumerate(codes)],
                                          dtype=object)
        out: dict[str, Any] = {}
        for k, v in info.items():
            out[k] = v
            out["_" + k] = np.ones(n, bool)
        if self.autoreset_mode == AutoresetMode.SAME_STEP and done.any():
            final_info = {k: v.copy() for k, v in out.items()}
            final_obs = np.empty(n, dtype=object)
            for i in np.flatnonzero(done):
                final_obs[i] = obs[i].copy()
            self.task.reset(done, self._rngs)
            obs = self.task.obs.astype(np.float32)
            out["final_obs"], out["_final_obs"] = final_obs, done.copy()
            out["final_info"], out["_final_info"] = final_info, done.copy()
        self._autoreset = done
        return obs, reward, terminated, truncated, out

    def render(self):
        if self.render_mode != "rgb_array":
            return None
        if self._renderer is None:
            self._renderer = self.task.renderer()
        return self._renderer.draw(0)

    def close_extras(self, **kwargs):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

