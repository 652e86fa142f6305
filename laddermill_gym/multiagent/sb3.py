"""Parameter sharing for Stable-Baselines3: every agent of B copies of a per-wing env as one env of an SB3
``VecEnv`` (num_envs = B n), as SuperSuit's ``pettingzoo_env_to_vec_env_v1`` + ``concat_vec_envs_v1`` make of a
PettingZoo env, but over the single-agent env's task with B copies, stepped by its one batched kernel call per
control period instead of B ParallelEnvs stepped one after another (needs the ``rl`` extra, not PettingZoo).

Env j = b n + i is agent i of copy b (:mod:`laddermill_gym.multiagent.agents`: its local observation, action and
reward). A copy's agents end together; the copy is then reset in the same step (SB3's convention: the last
observation in ``infos[j]["terminal_observation"]``, ``infos[j]["TimeLimit.truncated"]``). Copy b seeded with
``seed + b`` (``venv.seed(seed)`` before ``reset()``) runs as the ParallelEnv and the single-agent env seeded so.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np
from stable_baselines3.common.vec_env import VecEnv

from laddermill_gym.envs.actions import action_array
from laddermill_gym.envs.task_base import refuse_reset_options
from laddermill_gym.multiagent.agents import WingAgents, build_task, check_k

__all__ = ["SharedPolicyVecEnv", "shared_policy_vec_env"]


class SharedPolicyVecEnv(VecEnv):
    """The n agents of each of the B copies of ``view.task`` as an SB3 VecEnv of B n envs (see the module doc).

    Observations (B n, d) float32, actions (B n, m_a) in [-1, 1] (a finite real array of that shape, else
    :class:`~laddermill_gym.envs.actions.ActionError`, a ValueError, before anything moves), rewards (B n,)
    float32, dones (B n,) bool; ``infos[j]`` holds agent j's reward terms, the copy's ``power_W`` [W], ``failure``
    (code), ``t`` [s], ``n_clipped`` (the copy's action entries clipped to [-1, 1] this step, as the ParallelEnv's
    and the single-agent env's ``info["n_clipped"]``) and ``TimeLimit.truncated``.
    """

    def __init__(self, view: WingAgents):
        self.view, self.task = view, view.task
        self.n_copies, self.n_agents = int(view.task.n_copies), view.n_agents
        self.render_mode = None
        obs_space = gym.spaces.Box(view.obs_low.astype(np.float32), view.obs_high.astype(np.float32),
                                   dtype=np.float32)
        act_space = gym.spaces.Box(-1.0, 1.0, shape=(view.act_dim,), dtype=np.float32)
        super().__init__(self.n_copies * self.n_agents, obs_space, act_space)
        self._rngs = [np.random.default_rng() for _ in range(self.n_copies)]
        self._copy_seeds: list[int] | None = None
        self._actions = np.zeros((self.num_envs, view.act_dim))

    def seed(self, seed: int | None = None) -> list[int]:
        """Copy b's generator from ``seed + b`` at the next ``reset()`` (every agent of the copy shares it);
        returns the B n seeds SB3 expects (agent i of copy b: ``seed + b``)."""
        if seed is None:
            seed = int(np.random.randint(0, 2 ** 32 - 1, dtype=np.uint32))
        elif isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise ValueError(f"seed = {seed!r}: must be an integer >= 0 (copy b draws from seed + b)")
        self._copy_seeds = [int(seed) + b for b in range(self.n_copies)]
        return [s for s in self._copy_seeds for _ in range(self.n_agents)]

    def set_options(self, options: list[dict] | dict | None = None) -> None:
        """Refuses any non-empty options (ValueError naming them): the copies take no reset options, and SB3's
        ``reset`` would otherwise drop them without a word."""
        for opt in (options if isinstance(options, list) else [options]):
            refuse_reset_options(opt, "the shared-policy vector env", "shared_policy_vec_env's arguments")
        super().set_options(options)

    def _observations(self) -> np.ndarray:
        return self.view.observations().reshape(self.num_envs, self.view.obs_dim)

    def reset(self) -> np.ndarray:
        """Reset every copy (with the seeds of the last ``seed()``, once); observations (B n, d) float32."""
        if self._copy_seeds is not None:
            self._rngs = [gym.utils.seeding.np_random(s)[0] for s in self._copy_seeds]
            self._copy_seeds = None
        self.task.reset(np.ones(self.n_copies, bool), self._rngs)
        return self._observations()

    def step_async(self, actions: np.ndarray) -> None:
        self._actions = action_array(actions, (self.num_envs, self.view.act_dim))

    def step_wait(self):
        B, n = self.n_copies, self.n_agents
        per_agent = self._actions.reshape(B, n, self.view.act_dim)
        _, terminated, truncated, info = self.task.step(self.view.joint_action(per_agent))
        terms = self.view.reward_terms(per_agent, info)
        reward = sum(terms.values()).reshape(-1)
        done_copy = terminated | truncated
        dones = np.repeat(done_copy, n)
        obs = self._observations()
        infos = self._infos(terms, info, terminated, truncated)
        for j in np.flatnonzero(dones):
            infos[j]["terminal_observation"] = obs[j].copy()
        if done_copy.any():
            self.task.reset(done_copy, self._rngs)
            obs = self._observations()
        return obs, reward.astype(np.float32), dones, infos

    def _infos(self, terms: dict[str, np.ndarray], info: dict, terminated: np.ndarray, truncated: np.ndarray
               ) -> list[dict[str, Any]]:
        """The B n info dicts of a step (see the class doc): the copy's entries, then the agent's four reward terms
        (``WingAgents.reward_terms``' names and order), as Python numbers converted by one ``tolist`` per array,
        each dict built as one literal (B n dicts a step: built one numpy scalar at a time they cost a quarter of
        the native vector env's step)."""
        k0, k1, k2, k3 = terms  # a fifth term fails here, loudly, rather than going missing
        c0, c1, c2, c3 = (terms[key].reshape(-1).tolist() for key in (k0, k1, k2, k3))  # (B n,) each
        power, failure, t = info["power_W"].tolist(), info["failure"].tolist(), info["t"].tolist()
        clipped = info["n_clipped"].tolist()
        time_limit = np.logical_and(truncated, np.logical_not(terminated)).tolist()
        infos: list[dict[str, Any]] = []
        n = self.n_agents
        for b in range(self.n_copies):
            p, f, tb, c, tl = float(power[b]), int(failure[b]), float(t[b]), int(clipped[b]), bool(time_limit[b])
            j = slice(b * n, (b + 1) * n)
            infos += [{"power_W": p, "failure": f, "t": tb, "n_clipped": c, "TimeLimit.truncated": tl, k0: r0, k1: r1,
                       k2: r2, k3: r3} for r0, r1, r2, r3 in zip(c0[j], c1[j], c2[j], c3[j], strict=True)]
        return infos

    def close(self) -> None:
        self.task.close_threads()  # the copies' threads, as the native vector env's close

    def get_attr(self, attr_name: str, indices=None) -> list[Any]:
        """``render_mode`` (None) or an attribute of the shared task (the same for every env)."""
        value = self.render_mode if attr_name == "render_mode" else getattr(self.task, attr_name)
        return [value for _ in self._get_indices(indices)]

    def set_attr(self, attr_name: str, value: Any, indices=None) -> None:
        """Refused: the envs share one task (AttributeError)."""
        raise AttributeError(f"set_attr({attr_name!r}): the agents share one task; set it on venv.task")

    def env_method(self, method_name: str, *method_args, indices=None, **method_kwargs) -> list[Any]:
        fn = getattr(self.task, method_name)
        return [fn(*method_args, **method_kwargs) for _ in self._get_indices(indices)]

    def env_is_wrapped(self, wrapper_class, indices=None) -> list[bool]:
        return [False for _ in self._get_indices(indices)]


def shared_policy_vec_env(env_id: str, n_copies: int = 1, k: int = 1, seed: int | None = None,
                          **env_kwargs) -> SharedPolicyVecEnv:
    """The SB3 VecEnv of every agent of ``n_copies`` copies of the per-wing env ``env_id`` (``k`` neighbours on
    each side; ``env_kwargs`` as ``gymnasium.make`` takes them), copy b seeded ``seed + b``. ValueError as
    :func:`~laddermill_gym.multiagent.parallel.parallel_env` and for ``n_copies`` < 1."""
    if isinstance(n_copies, bool) or not isinstance(n_copies, (int, np.integer)) or n_copies < 1:
        raise ValueError(f"n_copies = {n_copies!r}: must be an integer >= 1")
    k = check_k(k)
    venv = SharedPolicyVecEnv(WingAgents(build_task(env_id, int(n_copies), dict(env_kwargs)), env_id, k))
    if seed is not None:
        venv.seed(seed)
    return venv
