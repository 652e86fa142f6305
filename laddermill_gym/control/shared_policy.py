"""A parameter-shared per-wing policy of the mill (issue 31 point 2) and its controller for the single-agent env.

The policy is one set of weights for every slot: each slot's agent sees its local observation
(:mod:`laddermill_gym.multiagent.agents`: own wing, k neighbours on each side, its position i / (n - 1) along the
loop, the station's entries) and commands its own three surfaces. Its actor is a *gain-scheduled linear* map
(:class:`GainScheduledExtractor` + SB3's linear action head): the lateral deviations of the 2k + 1 wings it sees
from the operating point's orbit (dy, vy, phi - phi_op, wrap(psi - psi_op), p, r, divided by the LQR config's
Bryson scales), and a constant, multiplied by hat functions of the position (``n_basis`` nodes over [0, 1]):
a = sum_b h_b(i / (n - 1)) (W_b z_local + c_b). The weights W_b, c_b are learnt (behaviour cloning of the LQR,
then PPO on the reward: ``harness/shared_train.py``); the orbit's attitude (phi_op, psi_op per slot) is the env's
operating point, which every slot's agent is given, as it is given its position.

:class:`SharedPolicyController` runs a trained policy on the single-agent env (``laddermill evaluate``): the
single-agent observation -> every slot's local observation (``WingAgents.local_observations``, the multi-agent
env's own mapping) -> the policy -> the joint action in slot order.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import torch as th
import yaml
from stable_baselines3.common.torch_layers import BaseFeaturesExtractor

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.multiagent.agents import AGENT_KINDS, WingAgents, build_task

__all__ = ["LATERAL_FIELDS", "GainScheduledExtractor", "SharedPolicyController", "SHARED_POLICY_FILE",
           "hat_basis"]

#: The lateral entries of a wing block the actor uses, in the order of ``control.linearize.WING_LATERAL``.
LATERAL_FIELDS = ("dy", "vy", "phi", "psi", "p", "r")
#: The run folder's description of a shared policy (env id, k, agents, observation size, env arguments).
SHARED_POLICY_FILE = "shared_policy.yaml"


def hat_basis(position: th.Tensor, n_basis: int) -> th.Tensor:
    """(N, n_basis) piecewise-linear hat functions of ``position`` (N,) in [0, 1] on ``n_basis`` equally spaced
    nodes (a partition of unity; one node: the constant 1)."""
    if n_basis == 1:
        return th.ones(position.shape[0], 1, dtype=position.dtype)
    nodes = th.linspace(0.0, 1.0, n_basis, dtype=position.dtype)
    return th.clamp(1.0 - th.abs(position[:, None] - nodes[None, :]) * (n_basis - 1), min=0.0)


class GainScheduledExtractor(BaseFeaturesExtractor):
    """Features (N, n_basis (6 (2k + 1) + 1)) of local observations (N, d): h(position) (outer) [z_local, 1].

    Parameters: ``n_agents`` n, ``k``, ``block`` (entries per wing, 15), ``n_basis``, ``trim`` (n, 2) the
    operating point's (phi, psi) of every slot [rad], ``scales`` (6,) Bryson scales of (dy, vy, phi, psi, p, r)
    [m, m/s, rad, rad, rad/s, rad/s]. Absent neighbours (past a ground station) contribute zeros.
    """

    def __init__(self, observation_space, n_agents: int, k: int, block: int, n_basis: int, trim, scales):
        n_lat = len(LATERAL_FIELDS) * (2 * k + 1) + 1
        super().__init__(observation_space, n_basis * n_lat)
        self.n, self.k, self.block, self.n_basis = int(n_agents), int(k), int(block), int(n_basis)
        offsets = [0] + [d for d in range(-k, k + 1) if d != 0]  # own block, then the neighbours' order
        self.register_buffer("offsets", th.tensor(offsets, dtype=th.long))
        cols = [j * block + OBS_INDEX[f] for j in range(2 * k + 1) for f in LATERAL_FIELDS]
        self.register_buffer("cols", th.tensor(cols, dtype=th.long))
        self.register_buffer("trim", th.as_tensor(np.asarray(trim, dtype=np.float32).reshape(self.n, 2)))
        self.register_buffer("scales", th.as_tensor(np.asarray(scales, dtype=np.float32).reshape(6)))
        self.flag0 = block * (2 * k + 1)  # first presence flag
        self.pos = self.flag0 + 2 * k  # the position entry

    def forward(self, obs: th.Tensor) -> th.Tensor:
        z, pos = self.local_features(obs)
        h = hat_basis(pos, self.n_basis)
        return (h[:, :, None] * z[:, None, :]).reshape(obs.shape[0], -1)

    def local_features(self, obs: th.Tensor) -> tuple[th.Tensor, th.Tensor]:
        """(N, 6 (2k + 1) + 1) scaled lateral deviations and a constant, and (N,) positions i / (n - 1): the
        features before the position's hat functions multiply them."""
        N, k = obs.shape[0], self.k
        pos = obs[:, self.pos]
        slot = th.round(pos * max(self.n - 1, 1)).long()
        lat = obs[:, self.cols].reshape(N, 2 * k + 1, len(LATERAL_FIELDS))
        present = th.ones(N, 2 * k + 1, dtype=obs.dtype)
        if k:
            present[:, 1:] = obs[:, self.flag0: self.flag0 + 2 * k]
        who = th.clamp(slot[:, None] + self.offsets[None, :], 0, self.n - 1)
        trim = self.trim[who]  # (N, 2k + 1, 2)
        dphi = lat[..., 2] - trim[..., 0]
        dpsi = th.remainder(lat[..., 3] - trim[..., 1] + math.pi, 2 * math.pi) - math.pi
        z = th.stack([lat[..., 0], lat[..., 1], dphi, dpsi, lat[..., 4], lat[..., 5]], dim=-1) / self.scales
        z = (z * present[..., None]).reshape(N, -1)
        return th.cat([z, th.ones(N, 1, dtype=obs.dtype)], dim=1), pos


def _read_meta(path: Path) -> dict[str, Any]:
    try:
        meta = yaml.safe_load(path.read_text())
    except yaml.YAMLError as err:
        raise ValueError(f"{path}: not readable YAML ({err})") from None
    need = ("env", "k", "n_agents", "obs_dim", "algorithm")
    missing = [f for f in need if not isinstance(meta, dict) or f not in meta]
    if missing:
        raise ValueError(f"{path}: missing {', '.join(missing)} (not a shared-policy run written by laddermill "
                         "train)")
    return meta


class SharedPolicyController:
    """``predict`` of a trained shared per-wing policy on the single-agent env's observations (B, D) or (D,):
    every slot's local observation -> the policy (deterministic) -> the joint action (B, n m_a) in [-1, 1].

    Build with :meth:`load` (a run folder holding ``shared_policy.yaml`` and ``model.zip``, or that model file).
    ``check_env(env_id, env_kwargs)`` refuses another env, another number of agents or another observation size,
    naming the file."""

    def __init__(self, model, view: WingAgents, source: Path, meta: dict):
        self.model, self.view, self.source, self.meta = model, view, source, meta
        self.trained_env = str(meta["env"])
        self.obs_dim = view.task.obs_dim
        self.act_dim = view.n_agents * view.act_dim

    @staticmethod
    def is_shared_run(path: str | Path) -> bool:
        """Whether ``path`` is a shared-policy run folder or a model file in one."""
        path = Path(path)
        folder = path if path.is_dir() else path.parent
        return (folder / SHARED_POLICY_FILE).is_file()

    @classmethod
    def load(cls, path: str | Path, env_id: str | None = None, env_kwargs: dict | None = None
             ) -> SharedPolicyController:
        """Load the run folder (its ``model.zip``) or a model file ``path``; with ``env_id`` the policy is checked
        against that env (and ``env_kwargs``: the agents and observation size) before anything runs."""
        import stable_baselines3 as sb3

        path = Path(path)
        folder = path if path.is_dir() else path.parent
        meta_file = folder / SHARED_POLICY_FILE
        meta = _read_meta(meta_file)
        model_file = folder / "model.zip" if path.is_dir() else path
        if not model_file.is_file():
            raise FileNotFoundError(f"{model_file}: no such model file (the run folder {folder} has "
                                    f"{SHARED_POLICY_FILE} but no model.zip)")
        algo = str(meta["algorithm"])
        if not hasattr(sb3, algo):
            raise ValueError(f"{meta_file}: algorithm = {algo!r} is not a Stable-Baselines3 algorithm")
        env = env_id or str(meta["env"])
        if env != meta["env"]:
            raise ValueError(f"{model_file}: trained on {meta['env']}, not {env}; evaluate it on {meta['env']} or "
                             f"train one for {env}")
        if env not in AGENT_KINDS:
            raise ValueError(f"{meta_file}: env = {env!r} has no per-wing interface ({sorted(AGENT_KINDS)})")
        kw = dict(meta.get("env_kwargs") or {}) if env_kwargs is None else dict(env_kwargs)
        kw.pop("disturbances", None)
        kw.pop("parallel", None)
        view = WingAgents(build_task(env, 1, kw), env, int(meta["k"]))
        ctrl = cls(getattr(sb3, algo).load(model_file, device="cpu"), view, model_file, meta)
        ctrl.check_env(env)
        return ctrl

    def check_env(self, env_id: str) -> None:
        """Refuse an env id, agent count or local observation size other than the training's (ValueError naming
        the model file and what does not match)."""
        m, v = self.meta, self.view
        if env_id != m["env"]:
            raise ValueError(f"{self.source}: trained on {m['env']}, not {env_id}; evaluate it on {m['env']} or "
                             f"train one for {env_id}")
        if v.n_agents != int(m["n_agents"]):
            raise ValueError(f"{self.source}: trained with {m['n_agents']} agents (slots), the env has "
                             f"{v.n_agents} (n_wings or scene differ)")
        shape = self.model.observation_space.shape
        if shape != (v.obs_dim,) or int(m["obs_dim"]) != v.obs_dim:
            raise ValueError(f"{self.source}: local observations of {shape} entries (k = {m['k']}), the env gives "
                             f"{v.obs_dim}")

    def local(self, observation: np.ndarray) -> tuple[np.ndarray, bool]:
        obs = np.asarray(observation, dtype=np.float64)
        single = obs.ndim == 1
        obs = obs[None] if single else obs
        if obs.ndim != 2 or obs.shape[1] != self.obs_dim:
            raise ValueError(f"{self.source}: expects observations of {self.obs_dim} entries ({self.view.n_agents} "
                             f"slots, {self.trained_env}), got shape {np.shape(observation)}")
        return self.view.local_observations(obs), single

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = True) -> tuple[np.ndarray, Any]:
        """Joint actions (B, n m_a) float32 (or (n m_a,)) of single-agent observations; always deterministic
        (the policy's mean)."""
        local, single = self.local(observation)
        B = local.shape[0]
        a, _ = self.model.predict(local.reshape(B * self.view.n_agents, -1), deterministic=True)
        joint = np.clip(a, -1.0, 1.0).reshape(B, self.act_dim).astype(np.float32)
        return (joint[0] if single else joint), state
