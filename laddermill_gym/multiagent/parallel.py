"""A PettingZoo ``ParallelEnv`` with one agent per wing (per slot of the mill) over the single-agent env's task with
one copy: :func:`parallel_env` (needs the ``multiagent`` extra, PettingZoo). The agents, their observations,
actions and rewards: :mod:`laddermill_gym.multiagent.agents`."""

from __future__ import annotations

import warnings
from typing import Any

import gymnasium as gym
import numpy as np
from pettingzoo import ParallelEnv

from laddermill_gym.envs.actions import ActionError, action_array
from laddermill_gym.multiagent.agents import WingAgents, build_task, check_k

__all__ = ["WingParallelEnv", "parallel_env"]


class WingParallelEnv(ParallelEnv):
    """One agent per wing of ``env_id`` (LadderMill-v0: slots, LadderChain-v0: wings, PointMassChain-v0: kites),
    stepping the single-agent env's task with one copy: the same kernel, seeding and arithmetic, so the joint step
    of the agents' actions equals ``gymnasium.make(env_id, **env_kwargs)``'s step of the concatenated action, seed
    for seed, bit for bit.

    Parameters: ``env_id``, ``k`` (neighbours seen on each side, >= 0), ``render_mode`` (None only: PettingZoo's
    ``env_fn(render_mode=...)`` convention; the per-wing env does not render) and the env's arguments (its registered
    defaults merged with them; the actions must stay per wing). ``step(actions)`` takes a dict with exactly the live
    agents as keys, each a finite real array (m_a,) (entries outside [-1, 1] clipped); anything else raises
    ValueError naming the agent. All agents end together when the task's episode ends (``terminations`` on a
    failure, ``truncations`` at ``episode_time``); ``infos[agent]`` holds its four reward terms and the task's
    info entries (``power_W``, ``failure``, ``failure_name``, ``t`` ...). ``state()`` is the single-agent
    observation (a centralised critic's input).
    """

    metadata = {"name": "laddermill_wings_v0", "render_modes": [], "is_parallelizable": True}

    def __init__(self, env_id: str, k: int = 1, render_mode: str | None = None, **env_kwargs):
        if render_mode is not None:  # PettingZoo builds envs as env_fn(render_mode=...)
            raise ValueError(f"render_mode = {render_mode!r}: the per-wing env does not render (render_modes: []); "
                             f"render the single-agent env gymnasium.make({env_id!r}, render_mode='rgb_array')")
        self.env_id, k = env_id, check_k(k)
        self.view = view = WingAgents(build_task(env_id, 1, dict(env_kwargs)), env_id, k)
        self.task = view.task
        self.render_mode = None
        self.possible_agents = list(view.names)
        self.agents: list[str] = []
        self._index = {a: i for i, a in enumerate(self.possible_agents)}
        low, high = view.obs_low.astype(np.float32), view.obs_high.astype(np.float32)
        self.observation_spaces = {a: gym.spaces.Box(low, high, dtype=np.float32) for a in self.possible_agents}
        self.action_spaces = {a: gym.spaces.Box(-1.0, 1.0, shape=(view.act_dim,), dtype=np.float32)
                              for a in self.possible_agents}
        self.state_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                          self.task.obs_high.astype(np.float32), dtype=np.float32)
        self._rng: np.random.Generator | None = None

    def observation_space(self, agent: str) -> gym.spaces.Box:
        """Box (d,) float32 of ``agent``'s local observation (the same object at every call)."""
        return self.observation_spaces[agent]

    def action_space(self, agent: str) -> gym.spaces.Box:
        """Box [-1, 1]^(m_a) float32 of ``agent``'s commands (the same object at every call)."""
        return self.action_spaces[agent]

    def state(self) -> np.ndarray:
        """The single-agent observation (obs_dim,) float32 of the copy: every wing and the station."""
        return self.task.obs[0].astype(np.float32)

    def _observations(self) -> dict[str, np.ndarray]:
        obs = self.view.observations()[0]
        return {a: obs[i] for i, a in enumerate(self.possible_agents)}

    def reset(self, seed: int | None = None, options: dict | None = None):
        """A new episode (``seed``: a new generator, the one ``gymnasium.make(env_id).reset(seed=seed)`` builds;
        None: keep drawing from the last). Returns (observations, infos) of every agent; the infos hold ``t`` = 0
        and the task's reset info (reference power [W] ...). ``options``: none taken; a non-empty mapping is named in
        a UserWarning and ignored (PettingZoo's API test resets with ``{"options": 1}`` and expects no error)."""
        if options:
            warnings.warn(f"options = {options!r}: parallel_env({self.env_id!r}) takes no reset options and ignores "
                          "them (set disturbances, episode_time and the like with parallel_env's arguments)",
                          UserWarning, stacklevel=2)
        if seed is not None or self._rng is None:
            self._rng = gym.utils.seeding.np_random(seed)[0]
        self.task.reset(np.ones(1, bool), [self._rng])
        self.agents = list(self.possible_agents)
        info = {"t": 0.0, **self.task.reset_info()}
        return self._observations(), {a: dict(info) for a in self.agents}

    def per_agent_actions(self, actions) -> np.ndarray:
        """The actions (n, m_a) float64 of a dict {agent: (m_a,) array} holding every live agent; ValueError (an
        :class:`~laddermill_gym.envs.actions.ActionError`) naming missing or unknown agents or the agent whose
        action is not a finite real array of that shape; RuntimeError before a reset or after the episode's end."""
        if not self.agents:
            raise RuntimeError("step() called before reset() or after the episode ended; call reset()")
        if not isinstance(actions, dict):
            raise ActionError(f"actions = {type(actions).__name__}: must be a dict {{agent: action}} over "
                              f"{len(self.agents)} agents ({self.agents[0]} .. {self.agents[-1]})")
        missing, unknown = set(self.agents) - set(actions), set(actions) - set(self.agents)
        if missing or unknown:
            raise ActionError(f"actions: keys must be the live agents; missing {sorted(missing, key=str)[:5]}, "
                              f"unknown {sorted(map(str, unknown))[:5]}")
        out = np.empty((self.view.n_agents, self.view.act_dim))
        for a, act in actions.items():
            try:
                out[self._index[a]] = action_array(act, (self.view.act_dim,))
            except ActionError as err:
                raise ActionError(f"agent {a}: {err}") from None
        return out

    def step(self, actions):
        """One control period of the copy with every agent's action; returns (observations, rewards,
        terminations, truncations, infos), dicts over the agents that were live."""
        a = self.per_agent_actions(actions)
        _, terminated, truncated, info = self.task.step(self.view.joint_action(a[None]))
        terms = self.view.reward_terms(a[None], info)
        reward = sum(terms.values())[0]
        code = int(info["failure"][0])
        common: dict[str, Any] = {key: (v[0].item() if v.ndim == 1 else v[0].copy()) for key, v in info.items()}
        common["failure_name"] = self.task.failure_names[code]
        common["failure_reason"] = self.task.failure_text(0, code)
        obs = self._observations()
        live = self.agents
        infos = {ag: dict(common, **{t: float(v[0, self._index[ag]]) for t, v in terms.items()}) for ag in live}
        rewards = {ag: float(reward[self._index[ag]]) for ag in live}
        terminations = dict.fromkeys(live, bool(terminated[0]))
        truncations = dict.fromkeys(live, bool(truncated[0]))
        if terminated[0] or truncated[0]:
            self.agents = []
        return {ag: obs[ag] for ag in live}, rewards, terminations, truncations, infos

    def render(self):
        """Nothing: the per-wing env does not render (``render_modes`` is empty; the single-agent env does)."""
        return None

    def close(self) -> None:
        pass


def parallel_env(env_id: str, k: int = 1, render_mode: str | None = None, **env_kwargs) -> WingParallelEnv:
    """The per-wing PettingZoo ``ParallelEnv`` of ``env_id`` (LadderMill-v0, LadderChain-v0, PointMassChain-v0),
    each agent seeing ``k`` neighbours on each side; ``env_kwargs`` as ``gymnasium.make(env_id, **env_kwargs)``
    takes them. ValueError names an unknown id, a negative ``k``, an argument the env does not take or actions
    that are not per wing, and a ``render_mode`` other than None (the per-wing env does not render)."""
    return WingParallelEnv(env_id, k, render_mode, **env_kwargs)
