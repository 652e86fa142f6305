"""The native vector environment of the rotorcraft: all copies of Roberts' craft stepped by one compiled kernel,
parallel over copies (registered as the ``vector_entry_point`` of ``laddermill_gym/Rotorcraft-v0``:
``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``), like
:class:`~laddermill_gym.envs.vector.WingVectorEnv` for the wing scenes.
"""

from __future__ import annotations

import inspect
from typing import Any

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from laddermill_gym.envs.rotorcraft.observation import OBS_Y
from laddermill_gym.envs.rotorcraft.task import CRAFT_FAILURES, CraftTask

__all__ = ["RotorcraftVectorEnv"]

#: The CraftTask arguments the vector env passes on (all but the number of copies)
_TASK_ARGUMENTS: tuple[str, ...] = tuple(p for p in inspect.signature(CraftTask).parameters if p != "n_copies")
#: info entries of copies that were reset in a NextStep autoreset step (reported as 0)
_ZEROED_ON_RESET: tuple[str, ...] = ("failure", "n_clipped", "reward_power", "reward_lateral", "reward_rates",
                                     "reward_effort", "reward_failure")


class RotorcraftVectorEnv(VectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` in one batch.

    Copy i behaves exactly like a single env seeded with ``seed + i`` (bit for bit: same kernel, same
    arithmetic). Autoreset: ``autoreset_mode`` "NextStep" (Gymnasium's default: the step after an episode
    ends resets that copy, ignores its action and reports reward 0 and failure 0) or "SameStep" (the reset
    observation is returned at once; the final observation and info are in ``info["final_obs"]``,
    ``info["final_info"]``).

    Observations (num_envs, 19) float32 (clipped to the bounds, as the single env's); ``info`` holds
    (num_envs,) arrays of every reward term, t [s], power_W [W], altitude_m [m], max_tip_incidence_rad [rad],
    n_clipped and failure (code of :data:`~laddermill_gym.envs.rotorcraft.task.CRAFT_FAILURES`), and
    thrust_N (num_envs, 2) [N] and tether_tension_N (num_envs, 3) [N], each with its ``_name`` mask.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: copy 0), ``autoreset_mode``, ``parallel``
    (numba thread pool; default from 32 copies on) and the arguments of
    :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` (craft, wind_speed [m/s], control_dt [s],
    episode_time [s], disturbances, ...); others raise ValueError naming them.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 20, "autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        if isinstance(num_envs, bool) or int(num_envs) != num_envs or num_envs < 1:
            raise ValueError(f"num_envs = {num_envs!r}: must be a positive integer")
        mode = AutoresetMode(autoreset_mode)
        if mode == AutoresetMode.DISABLED:
            raise ValueError("autoreset_mode = 'Disabled' is not supported: use 'NextStep' or 'SameStep'")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode = {render_mode!r}: the vector env renders 'rgb_array' only")
        task_kwargs.pop("max_episode_steps", None)
        unknown = sorted(set(task_kwargs) - set(_TASK_ARGUMENTS))
        if unknown:
            raise ValueError(f"{', '.join(f'{k} = {task_kwargs[k]!r}' for k in unknown)}: not arguments of the "
                             f"rotorcraft env (known: {', '.join(_TASK_ARGUMENTS)})")
        self.task = CraftTask(int(num_envs), **task_kwargs)
        self.num_envs = int(num_envs)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, autoreset_mode=mode, render_fps=int(round(1.0 / self.task.control_dt)))
        self.autoreset_mode = mode
        self.failure_names = dict(CRAFT_FAILURES)
        self.single_observation_space = gym.spaces.Box(self.task.obs_low, self.task.obs_high, dtype=np.float32)
        self.single_action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self._rngs = [np.random.default_rng() for _ in range(self.num_envs)]
        self._autoreset = np.zeros(self.num_envs, dtype=bool)
        self._renderer = None

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m], shape (num_envs, 1), of batched observations (num_envs, 19)."""
        return np.asarray(obs, dtype=float)[:, OBS_Y:OBS_Y + 1]

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
            for k in _ZEROED_ON_RESET:
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
        if self._renderer is None:
            self._renderer = self.task.renderer()
        return self._renderer.draw(0)

    def close_extras(self, **kwargs):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
