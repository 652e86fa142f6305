"""Copies of :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` stepped one after another behind the
batched interface of :class:`~laddermill_gym.envs.vector.WingVectorEnv` that the controller harness uses
(``agents.evaluate.run_episodes``, the evaluations of ``agents.train``), and the training VecEnv of
Stable-Baselines3 for the craft. The craft has no batched kernel, so both are plain loops over single envs.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass
from typing import Any

import numpy as np

from laddermill_gym.envs import ENV_IDS
from laddermill_gym.envs.rotorcraft.env import CRAFT_FAILURES, OBS_Y, RotorcraftEnv

__all__ = ["CraftTaskInfo", "RotorcraftVectorEnv", "is_craft_env", "craft_sb3_vec_env", "CRAFT_ENV_KWARGS"]

#: Arguments of :class:`RotorcraftEnv` (the ones a config or a scenario may set)
CRAFT_ENV_KWARGS: tuple[str, ...] = tuple(inspect.signature(RotorcraftEnv).parameters)
#: Scalar ``info`` entries batched into (num_envs,) arrays by :class:`RotorcraftVectorEnv`
INFO_KEYS: tuple[str, ...] = ("t", "power_W", "altitude_m", "max_tip_incidence_rad", "n_clipped", "failure",
                              "reward_power", "reward_lateral", "reward_rates", "reward_effort", "reward_failure")


def is_craft_env(env_id: str) -> bool:
    """Whether the registered environment ``env_id`` is the rotorcraft (not a wing scene)."""
    if env_id not in ENV_IDS:
        raise ValueError(f"env_id = {env_id!r}: must be one of {sorted(ENV_IDS)}")
    return "craft" in ENV_IDS[env_id]


@dataclass(frozen=True)
class CraftTaskInfo:
    """What the harness reads from ``env.task``: n_wings [-] (1: one lateral offset per copy), n_actions [-],
    n_steps_max [-] control periods per episode, control_dt [s]."""

    n_wings: int
    n_actions: int
    n_steps_max: int
    control_dt: float


class RotorcraftVectorEnv:
    """``num_envs`` copies of :class:`RotorcraftEnv` with the batched API of
    :class:`~laddermill_gym.envs.vector.WingVectorEnv` (autoreset "NextStep": the step after a copy's episode
    ended resets that copy, ignores its action and reports reward 0 and failure 0).

    Parameters
    ----------
    num_envs : int
        Copies; copy i seeded with ``seed + i`` (or ``seed[i]``) behaves exactly like a single env.
    **env_kwargs
        Arguments of :class:`RotorcraftEnv` (craft, wind_speed [m/s], control_dt [s], episode_time [s],
        disturbances, ...).

    ``step`` returns observations (num_envs, 19) float32, rewards, terminated and truncated (num_envs,) and an
    info dict of (num_envs,) arrays of :data:`INFO_KEYS` (t [s], power_W [W], failure code, ...).
    """

    def __init__(self, num_envs: int, **env_kwargs):
        if isinstance(num_envs, bool) or int(num_envs) != num_envs or num_envs < 1:
            raise ValueError(f"num_envs = {num_envs!r}: must be a positive integer")
        unknown = sorted(set(env_kwargs) - set(CRAFT_ENV_KWARGS))
        if unknown:
            raise ValueError(f"env_kwargs {unknown}: not arguments of RotorcraftEnv (known: {CRAFT_ENV_KWARGS})")
        self.num_envs = int(num_envs)
        self.envs = [RotorcraftEnv(**env_kwargs) for _ in range(self.num_envs)]
        e = self.envs[0]
        self.single_observation_space, self.single_action_space = e.observation_space, e.action_space
        self.task = CraftTaskInfo(n_wings=1, n_actions=int(e.action_space.shape[0]), n_steps_max=e.n_steps_max,
                                  control_dt=e.control_dt)
        self.failure_names = dict(CRAFT_FAILURES)
        self._autoreset = np.zeros(self.num_envs, bool)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m], shape (num_envs, 1), of batched observations (num_envs, 19)."""
        return np.asarray(obs, dtype=float)[:, OBS_Y:OBS_Y + 1]

    def reset(self, *, seed: int | list[int] | None = None, options: dict[str, Any] | None = None):
        """Reset every copy; ``seed`` an int (copy i gets seed + i), a list of num_envs seeds or None."""
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)):
            seeds = [int(seed) + i for i in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed: expected an int or {self.num_envs} seeds, got {len(seeds)}")
        obs = np.stack([env.reset(seed=s, options=options)[0] for env, s in zip(self.envs, seeds, strict=True)])
        self._autoreset[:] = False
        return obs, {"t": np.zeros(self.num_envs), "_t": np.ones(self.num_envs, bool)}

    def step(self, actions):
        a = np.asarray(actions, dtype=np.float32).reshape(self.num_envs, self.task.n_actions)
        n = self.num_envs
        obs = np.empty((n,) + self.single_observation_space.shape, np.float32)
        reward, term, trunc = np.zeros(n), np.zeros(n, bool), np.zeros(n, bool)
        info = {k: np.zeros(n, dtype=int if k in ("n_clipped", "failure") else float) for k in INFO_KEYS}
        for i, env in enumerate(self.envs):
            if self._autoreset[i]:
                obs[i] = env.reset()[0]
                continue
            obs[i], reward[i], term[i], trunc[i], inf = env.step(a[i])
            for k in INFO_KEYS:
                info[k][i] = inf[k]
        self._autoreset = term | trunc
        info.update({"_" + k: np.ones(n, bool) for k in INFO_KEYS})
        return obs, reward, term, trunc, info

    def close(self) -> None:
        for env in self.envs:
            env.close()


def craft_sb3_vec_env(num_envs: int, seed: int | None = None, **env_kwargs):
    """SB3 ``DummyVecEnv`` of ``num_envs`` :class:`RotorcraftEnv` copies (copy i seeded with ``seed + i`` at
    its first reset); needs the ``rl`` extra."""
    from stable_baselines3.common.vec_env import DummyVecEnv

    unknown = sorted(set(env_kwargs) - set(CRAFT_ENV_KWARGS))
    if unknown:
        raise ValueError(f"env_kwargs {unknown}: not arguments of RotorcraftEnv (known: {CRAFT_ENV_KWARGS})")
    venv = DummyVecEnv([lambda: RotorcraftEnv(**env_kwargs) for _ in range(int(num_envs))])
    if seed is not None:
        venv.seed(seed)
    return venv
