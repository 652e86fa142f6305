"""The per-wing view of a task with B copies: which agents there are, each agent's local observation, its slice of
the joint action and its reward terms, computed from the task's public arrays after the task's own reset or step
(no physics of its own). The PettingZoo env (``parallel.py``, B = 1) and the SB3 adapter (``sb3.py``, B copies)
both read the task through it.

Agents: LadderMill-v0's *slots* (``slot_0`` .. ``slot_{n-1}``: a slot's command stays with the position along the
loop while wings travel through it, as the single-agent env's per-slot actions do); LadderChain-v0's *wings*
(``wing_0`` ..); PointMassChain-v0's *kites* (``kite_0`` ..). Neighbours are the agents within ``k`` positions in
that order; the ends have none beyond them (the mill's slots 0 and n - 1, at the two ground stations, are not
neighbours).

Local observation of agent i (float32, length ``m (1 + 2k) + 2k + 1 + g``; m = 15 rigid wing entries of
``envs.observation.OBS_FIELDS`` or 7 point-mass kite entries of ``envs.pointmass.task.OBS_PER_KITE``):

1. its own block of the single-agent observation (m entries);
2. the blocks of the neighbours i - k .. i - 1, i + 1 .. i + k, in that order (zeros where there is none);
3. 2k presence flags in the same order (1: the neighbour exists, 0: past an end);
4. the position i / (n - 1) in [0, 1] (0 with one agent);
5. g shared entries: the mill's cable phase s / l0 [-], cable speed [m/s] and generator power ratio P / P_ref [-]
   (its station observation); the chains' power ratio P / P_ref [-] (g = 1), P the ground power the task's
   ``reward_power`` uses.

Action of agent i: entries i m_a .. (i + 1) m_a - 1 of the single-agent action in its per-wing mode (m_a = the
number of surfaces: 3 for the rigid wings, pitch and roll for the kites), in [-1, 1].

Reward of agent i: ``reward_shared`` (the task's ``reward_power`` + ``reward_failure``, the same for every agent)
plus its local ``reward_lateral`` = -w_y S((dy_i / lateral_scale)^2), ``reward_rates`` = -w_w S((p_i^2 + r_i^2) /
rate_scale^2) (0 for the kites, whose task has no rates term) and ``reward_effort`` = -w_u S(mean over its entries of
(a - a_nominal)^2), S(x) = 1 - exp(-x), with the task's weights and scales; every agent terminates (truncates) when
the task's copy does.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs import env_arguments, registered_arguments, task_class
from laddermill_gym.envs.laddermill.observation import N_STATION_OBS, STATION_OBS_INDEX
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.task_base import clip_observations
from laddermill_gym.kernels.contract import PKO_SIZE
from laddermill_gym.kernels.rigid.observe import AUX_GROUND_END, AUX_GROUND_START

__all__ = ["MULTIAGENT_IDS", "AGENT_KINDS", "WingAgents", "build_task"]

LM, LC, PMC = "laddermill_gym/LadderMill-v0", "laddermill_gym/LadderChain-v0", "laddermill_gym/PointMassChain-v0"
LM1 = "laddermill_gym/LadderMill-v1"  # v0's task and layout with the v1 wing and authority 0.2
LM2 = "laddermill_gym/LadderMill-v2"  # v0's task and layout with the v2 wing and authority 0.2
LM3 = "laddermill_gym/LadderMill-v3"  # v2's task and layout with one ROS2 step per control period
LC1 = "laddermill_gym/LadderChain-v1"  # v0's task and layout with three RK4 steps of 1/60 s per control period
#: The ids with a per-wing interface and what their agents are.
AGENT_KINDS: dict[str, str] = {LM: "slot", LM1: "slot", LM2: "slot", LM3: "slot", LC: "wing", LC1: "wing",
                                PMC: "kite"}
MULTIAGENT_IDS: tuple[str, ...] = tuple(AGENT_KINDS)
#: The single-agent argument that selects the per-wing actions, and its per-wing value, per id.
_PER_WING_GROUPS = {LM: "per_slot", LM1: "per_slot", LM2: "per_slot", LM3: "per_slot", LC: "per_wing",
                    LC1: "per_wing", PMC: "per_kite"}
#: Bound of the chains' power ratio entry [-] (the mill's comes from its observation bounds: the same 1e3).
POWER_RATIO_BOUND = 1e3
#: The mill's station entries an agent sees, in order.
_MILL_SHARED = tuple(STATION_OBS_INDEX[f] for f in ("cable_phase", "cable_speed", "power_ratio"))


def check_k(k) -> int:
    """``k`` as an int >= 0; ValueError naming it otherwise."""
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
        raise ValueError(f"k = {k!r}: the neighbours seen on each side must be an integer >= 0")
    return int(k)


def build_task(env_id: str, n_copies: int, env_kwargs: dict):
    """The single-agent env's task with ``n_copies`` copies: the registered defaults of ``env_id`` merged with
    ``env_kwargs`` (as ``gymnasium.make`` builds them), one thread below 32 copies. ValueError names an unknown id,
    an argument the env does not take, or actions that are not per wing."""
    if env_id not in AGENT_KINDS:
        raise ValueError(f"env_id = {env_id!r}: the per-wing interface exists for {list(MULTIAGENT_IDS)}")
    known = env_arguments(env_id)
    unknown = sorted(set(env_kwargs) - set(known))
    if unknown:
        raise ValueError(f"{', '.join(f'{a} = {env_kwargs[a]!r}' for a in unknown)}: {env_id} takes no such "
                         f"argument (known: {', '.join(known)})")
    kw = registered_arguments(env_id, env_kwargs)
    groups = kw.get("groups", _PER_WING_GROUPS[env_id])
    if groups != _PER_WING_GROUPS[env_id]:
        raise ValueError(f"groups = {groups!r}: the per-wing interface needs {env_id}'s per-wing actions, "
                         f"groups = {_PER_WING_GROUPS[env_id]!r}")
    for station in ("generator_torque", "cable_speed_command"):
        if kw.get(station):
            raise ValueError(f"{station} = True: the station's command belongs to no wing; the per-wing interface "
                             "runs the mill at its prescribed cable speed")
    return task_class(env_id)(int(n_copies), **kw)


class WingAgents:
    """The agents of ``task`` (B copies of the env ``env_id``, from :func:`build_task`) seeing ``k`` neighbours on
    each side (see the module doc for the layout).

    Attributes: ``names`` the n agent names, ``n_agents`` n, ``obs_dim`` d, ``act_dim`` m_a, ``obs_low`` /
    ``obs_high`` (d,) float64 bounds, ``nominal`` (n, m_a) the actions the effort term is measured from.
    """

    def __init__(self, task, env_id: str, k: int = 1):
        self.task, self.env_id, self.k = task, env_id, check_k(k)
        self.kind = AGENT_KINDS[env_id]
        n = self.n_agents = int(task.n_wings)
        self.names = tuple(f"{self.kind}_{i}" for i in range(n))
        if task.n_actions % n:
            raise ValueError(f"{env_id}: {task.n_actions} action entries do not split over {n} agents")
        self.act_dim = task.n_actions // n
        self.block = PKO_SIZE if self.kind == "kite" else len(OBS_INDEX)  # entries per wing: 7 or 15
        self.n_shared = 3 if self.kind == "slot" else 1
        self.obs_dim = self.block * (1 + 2 * k) + 2 * k + 1 + self.n_shared
        nominal = task.trim_action if self.kind == "kite" else task.actions.nominal_action
        self.nominal = np.asarray(nominal, dtype=float).reshape(n, self.act_dim)
        self.offsets = np.array([d for d in range(-k, k + 1) if d != 0], dtype=np.int64)
        self.obs_low, self.obs_high = self._bounds()
        # agent i's blocks (own, then the neighbours') are rows k + i + d, d in _seen, of the wing blocks padded
        # with k zero blocks at each end; its flags and position are fixed
        idx = np.arange(n)
        self._seen = (0, *(int(d) for d in self.offsets))
        present = (idx[:, None] + self.offsets[None, :] >= 0) & (idx[:, None] + self.offsets[None, :] < n)
        static = np.concatenate([present.astype(float), (idx / max(n - 1, 1))[:, None]], axis=1)
        nb = self.block * (1 + 2 * k)
        self._static = np.empty((n, 2 * k + 1), dtype=np.float32)
        clip_observations(static, self.obs_low[nb: nb + 2 * k + 1], self.obs_high[nb: nb + 2 * k + 1], self._static)
        self._padded: np.ndarray | None = None

    def _bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(low, high) (d,) float64 of the local observation: the task's bounds of wing 0's block (every wing's are
        the same), 0 and 1 for flags and position, the mill's station bounds or +-1e3 for the power ratio."""
        t, m, k = self.task, self.block, self.k
        lo_w, hi_w = t.obs_low[:m], t.obs_high[:m]
        if not (np.all(lo_w <= 0.0) and np.all(hi_w >= 0.0)):
            raise ValueError(f"{self.env_id}: an absent neighbour's zeros lie outside the observation bounds")
        if self.kind == "slot":
            g_lo = t.obs_low[-N_STATION_OBS:][list(_MILL_SHARED)]
            g_hi = t.obs_high[-N_STATION_OBS:][list(_MILL_SHARED)]
        else:
            g_lo, g_hi = np.array([-POWER_RATIO_BOUND]), np.array([POWER_RATIO_BOUND])
        low = np.concatenate([np.tile(lo_w, 1 + 2 * k), np.zeros(2 * k + 1), g_lo])
        high = np.concatenate([np.tile(hi_w, 1 + 2 * k), np.ones(2 * k + 1), g_hi])
        return low, high

    # ------------------------------------------------------------------ observations
    def shared(self) -> np.ndarray:
        """The shared entries (B, g): mill: cable phase [-], cable speed [m/s], power ratio [-] from the task's
        station observation; chains: the ground power over P_ref [-] (P as the task's ``reward_power`` has it)."""
        t = self.task
        if self.kind == "slot":
            return t.obs[:, -N_STATION_OBS:][:, list(_MILL_SHARED)]
        if self.kind == "wing":
            power = (t.aux[:, AUX_GROUND_START] - t.aux[:, AUX_GROUND_END]) * t.v_reel
        else:
            tension = t.batch.tension
            speed = t.batch.cable_speed if t.mill is not None else t.v_reel  # a point-mass mill: its V_c
            power = (tension[:, 0] - (tension[:, -1] if t.string.end is not None else 0.0)) * speed
        return (power / t.p_ref)[:, None]

    def observations(self) -> np.ndarray:
        """Local observations (B, n, d) float32 of every agent of every copy at the task's current observation,
        clipped to the bounds (a non-finite entry: the bound)."""
        return self.local_observations(self.task.obs, self.shared())

    def local_observations(self, obs: np.ndarray, shared: np.ndarray | None = None) -> np.ndarray:
        """Local observations (B, n, d) float32 of single-agent observations ``obs`` (B, D) (the task's layout: n
        wing blocks first) with shared entries ``shared`` (B, g); None: the mill's station entries of ``obs``; for
        the chains, whose ground power is not in the single-agent observation (it needs the task's state), None
        gives that entry 0 (no power seen: a controller on the single-agent env cannot know it; the
        gain-scheduled actor of ``control.shared_policy`` does not read it). A trained shared policy maps the
        single-agent env's observation to its agents with it, by the same arithmetic as :meth:`observations`."""
        n, m, k = self.n_agents, self.block, self.k
        obs = np.asarray(obs)
        if obs.ndim != 2 or obs.shape[1] != self.task.obs_dim:
            raise ValueError(f"{self.env_id}: observations of shape {obs.shape}, expected (B, {self.task.obs_dim})")
        if shared is None:
            shared = (obs[:, -N_STATION_OBS:][:, list(_MILL_SHARED)] if self.kind == "slot"
                      else np.zeros((obs.shape[0], self.n_shared)))
        B, g, nb = obs.shape[0], self.n_shared, m * (1 + 2 * k)
        # clipping is entry by entry with the blocks' bounds (every block's are wing 0's), so the wing blocks are
        # clipped once (n m entries per copy, not n (2k + 1) m) into the padded buffer, then gathered
        padded = self._padded_blocks(B)
        clip_observations(obs[:, : n * m].reshape(B, n, m), self.obs_low[:m], self.obs_high[:m], padded[:, k: k + n])
        out = np.empty((B, n, self.obs_dim), dtype=np.float32)
        for j, d in enumerate(self._seen):  # every agent's j-th block seen: the padded rows k + d .. k + d + n - 1
            out[:, :, j * m: (j + 1) * m] = padded[:, k + d: k + d + n]
        out[:, :, nb: nb + 2 * k + 1] = self._static
        clip_observations(np.asarray(shared, dtype=float).reshape(B, 1, g), self.obs_low[-g:], self.obs_high[-g:],
                          out[:, :, nb + 2 * k + 1:])
        return out

    def _padded_blocks(self, B: int) -> np.ndarray:
        """The reused (B, n + 2k, m) float32 buffer of the clipped wing blocks, k zero blocks at each end (the
        absent neighbours); one per batch size B."""
        if self._padded is None or self._padded.shape[0] != B:
            self._padded = np.zeros((B, self.n_agents + 2 * self.k, self.block), dtype=np.float32)
        return self._padded

    # ------------------------------------------------------------------ actions and rewards
    def joint_action(self, per_agent: np.ndarray) -> np.ndarray:
        """The single-agent actions (B, n_actions) of per-agent actions (B, n, m_a) (agent i's entries at
        i m_a .. (i + 1) m_a - 1)."""
        return np.asarray(per_agent, dtype=float).reshape(self.task.n_copies, self.n_agents * self.act_dim)

    def reward_terms(self, per_agent: np.ndarray, info: dict) -> dict[str, np.ndarray]:
        """Per-agent reward terms (B, n) after the task's step with the per-agent actions ``per_agent`` (B, n, m_a)
        and the task's ``info``: ``reward_shared``, ``reward_lateral``, ``reward_rates``, ``reward_effort`` (their
        sum is the reward; see the module doc)."""
        t, rc = self.task, self.task.reward_config
        B, n = t.n_copies, self.n_agents
        shared = np.broadcast_to((info["reward_power"] + info["reward_failure"])[:, None], (B, n))
        dy = t.lateral_offsets(t.obs if self.kind == "wing" else t.raw_obs)
        # a non-finite observed state costs the full penalty, as in the task's own reward (``shaped_reward``)
        lateral = -rc.lateral_weight * -np.expm1(-np.nan_to_num((dy / t.lateral_scale) ** 2, nan=np.inf))
        if self.kind == "kite":
            rates = np.zeros((B, n))
        else:
            o = (t.obs if self.kind == "wing" else t.raw_obs)[:, : n * self.block].reshape(B, n, self.block)
            w2 = o[:, :, OBS_INDEX["p"]] ** 2 + o[:, :, OBS_INDEX["r"]] ** 2
            rates = -rc.rate_weight * -np.expm1(-np.nan_to_num(w2 / rc.rate_scale ** 2, nan=np.inf))
        a = np.clip(np.asarray(per_agent, dtype=float).reshape(B, n, self.act_dim), -1.0, 1.0)
        effort = -rc.effort_weight * -np.expm1(-np.mean((a - self.nominal) ** 2, axis=2))
        return {"reward_shared": np.array(shared), "reward_lateral": lateral, "reward_rates": rates,
                "reward_effort": effort}

