"""The native vector environment: all copies of a wing scene stepped by one compiled kernel, parallel over
copies (registered as the ``vector_entry_point`` of the wing envs; ``gymnasium.make_vec(id, n,
vectorization_mode="vector_entry_point")``)."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from laddermill_gym.envs.task import WingTask


class WingVectorEnv(VectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.wing_env.WingEnv` in one batch.

    Copy i behaves exactly like a single env seeded with ``seed + i`` (bit for bit: same kernel, same
    arithmetic). Autoreset: ``autoreset_mode`` "NextStep" (Gymnasium's default: the step after an episode
    ends resets that copy and ignores its action) or "SameStep" (the reset observation is returned at once;
    the final observation and info are in ``info["final_obs"]``, ``info["final_info"]``).

    ``info`` holds (num_envs,) arrays of every reward term, power [W], largest tension [N], lowest wing
    altitude [m], time [s], clipped action entries and the failure code (0 flying; see
    :data:`laddermill_gym.envs.task.FAILURES`), each with its ``_name`` mask.

    Parameters: ``num_envs``, ``autoreset_mode``, ``parallel`` (numba thread pool; default from 32 copies
    on) and the :class:`~laddermill_gym.envs.task.WingTask` arguments.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 20, "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        if int(num_envs) != num_envs or num_envs < 1:
            raise ValueError(f"num_envs = {num_envs!r}: must be a positive integer")
        mode = AutoresetMode(autoreset_mode)
        if mode == AutoresetMode.DISABLED:
            raise ValueError("autoreset_mode = 'Disabled' is not supported: use 'NextStep' or 'SameStep'")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode = {render_mode!r}: the vector env renders 'rgb_array' only")
        task_kwargs.pop("max_episode_steps", None)
        self.task = WingTask(int(num_envs), **task_kwargs)
        self.num_envs = int(num_envs)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, autoreset_mode=mode, render_fps=int(round(1.0 / self.task.control_dt)))
        self.autoreset_mode = mode
        self.single_observation_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                                       self.task.obs_high.astype(np.float32), dtype=np.float32)
        self.single_action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
        self._autoreset = np.zeros(self.num_envs, dtype=bool)
        self._renderer = None

    def _seed(self, seed) -> None:
        if seed is None:
            self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
            return
        seeds = [seed + i for i in range(self.num_envs)] if isinstance(seed, int) else list(seed)
        if len(seeds) != self.num_envs:
            raise ValueError(f"seed: expected an int or {self.num_envs} seeds, got {len(seeds)}")
        # the same generator a single env builds in Env.reset(seed=s)
        self._rngs = [gym.utils.seeding.np_random(s)[0] for s in seeds]

    def reset(self, *, seed: int | list[int] | None = None, options: dict[str, Any] | None = None):
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
            for k in ("failure", "n_clipped", "reward_power", "reward_lateral", "reward_rates", "reward_effort",
                      "reward_failure"):
                info[k][resetting] = 0
        else:
            reward, terminated, truncated, info = self.task.step(a)
        done = terminated | truncated
        obs = self.task.obs.astype(np.float32)
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
        from laddermill_gym.envs.render import SceneRenderer

        if self._renderer is None:
            self._renderer = SceneRenderer(self.task)
        return self._renderer.draw(0)

    def close_extras(self, **kwargs):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
