"""Running a trained shared per-wing policy on the single-agent env, without torch where its actor is linear.

A shared per-wing policy (``laddermill train ppo_mill_v1``; the shipped ``ppo_mill``) is one set of weights for
every slot (:mod:`laddermill_gym.control.shared_policy`). Its run folder holds ``shared_policy.yaml`` (env id, k,
agents, local observation size, algorithm), the SB3 ``model.zip`` and, since the actor is a linear map of fixed
features, ``linear_actor.npz``: that map's arrays exported from ``model.zip`` (``export_linear_actor`` in
``shared_policy.py``, called when training ends), with the SHA-256 of the ``model.zip`` it came from.

:class:`SharedController` is what both evaluators share: the single-agent observation (B, D) -> every slot's local
observation (``WingAgents.local_observations``, the multi-agent env's own mapping) -> the actor -> the joint action
(B, n m_a) in slot order, and the checks that refuse another env, agent count or observation size (naming the
file). :class:`LinearActorController` evaluates the exported actor in numpy (the features in float32, as SB3 does;
their product with the weights in float64, summed in a fixed order by
:func:`~laddermill_gym.control.exact_actor.affine_fixed_order`, so the actions have the same bits on every CPU): no
torch, so the README's first command (installed without the ``rl`` extra) flies the shipped policy;
``SharedPolicyController`` (``shared_policy.py``) runs the SB3 model itself. tests/test_linear_actor.py checks that
both give the same actions (to float32 rounding) and the features against loops written from the formula.

Why our own evaluator rather than ONNX or TorchScript: the actor is one matrix product of features that need the
slot's trim and a hat function of its position; a 60-line numpy evaluator has no dependency at all, where an ONNX
runtime would be a new one for the base install.
"""

from __future__ import annotations

import hashlib
from abc import ABC, abstractmethod
from pathlib import Path
from typing import Any

import numpy as np

from laddermill_gym.control.exact_actor import affine_fixed_order
from laddermill_gym.envs import same_task
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.model.configio import load_yaml_text
from laddermill_gym.multiagent.agents import AGENT_KINDS, WingAgents, build_task

__all__ = ["SHARED_POLICY_FILE", "LINEAR_ACTOR_FILE", "LATERAL_FIELDS", "LINEAR_ACTOR_KEYS", "SharedController",
           "LinearActor", "LinearActorController", "read_shared_meta", "is_shared_run", "file_digest", "build_view",
           "lateral_columns"]

#: The run folder's description of a shared policy (env id, k, agents, observation size, env arguments).
SHARED_POLICY_FILE = "shared_policy.yaml"
#: The linear actor's arrays, exported from model.zip (no torch needed to run it).
LINEAR_ACTOR_FILE = "linear_actor.npz"
#: The lateral entries of a wing block the actor uses, in the order of ``control.linearize.WING_LATERAL``.
LATERAL_FIELDS = ("dy", "vy", "phi", "psi", "p", "r")
#: The arrays of ``linear_actor.npz``: weight (m_a, n_basis n_lat), bias (m_a,), trim (n, 2) [rad], scales (6,),
#: offsets (2k + 1,), cols (6 (2k + 1),), n_agents, k, block, n_basis and model_sha256 (of the source model.zip).
LINEAR_ACTOR_KEYS = ("weight", "bias", "trim", "scales", "offsets", "cols", "n_agents", "k", "block", "n_basis",
                     "model_sha256")


def file_digest(path: Path) -> str:
    """SHA-256 (hex) of a file's bytes."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def read_shared_meta(path: Path) -> dict[str, Any]:
    """``shared_policy.yaml``'s fields; ValueError naming the file when it is not YAML or lacks a field."""
    meta = load_yaml_text(Path(path).read_text(), str(path))  # YAML 1.2 (5e-2 a number), ConfigError naming the file
    need = ("env", "k", "n_agents", "obs_dim", "algorithm")
    missing = [f for f in need if not isinstance(meta, dict) or f not in meta]
    if missing:
        raise ValueError(f"{path}: missing {', '.join(missing)} (not a shared-policy run written by laddermill "
                         "train)")
    return meta


def is_shared_run(path: str | Path) -> bool:
    """Whether ``path`` is a shared-policy run folder or a model file in one (a checkpoint in its
    ``checkpoints/`` included)."""
    from laddermill_gym.control.sb3_policy import run_folder

    path = Path(path)
    folder = path if path.is_dir() else run_folder(path)
    return (folder / SHARED_POLICY_FILE).is_file()


def build_view(meta: dict, source: Path, env_id: str | None, env_kwargs: dict | None) -> WingAgents:
    """The agents of the env the policy runs on (``env_id``, default the training's, with ``env_kwargs``, default
    the training's); ValueError naming ``source`` for another env or one without a per-wing interface."""
    env = env_id or str(meta["env"])
    if not same_task(env, str(meta["env"])):
        raise ValueError(f"{source}: trained on {meta['env']}, not {env}; evaluate it on {meta['env']} or "
                         f"train one for {env}")
    if env not in AGENT_KINDS:
        raise ValueError(f"{source}: env = {env!r} has no per-wing interface ({sorted(AGENT_KINDS)})")
    kw = dict(meta.get("env_kwargs") or {}) if env_kwargs is None else dict(env_kwargs)
    kw.pop("disturbances", None)
    kw.pop("parallel", None)
    return WingAgents(build_task(env, 1, kw), env, int(meta["k"]))


class SharedController(ABC):
    """``predict`` of a shared per-wing policy on the single-agent env's observations (B, D) or (D,): every slot's
    local observation -> :meth:`actions` (subclasses) -> the joint action (B, n m_a) float32 in [-1, 1]."""

    def __init__(self, view: WingAgents, source: Path, meta: dict):
        self.view, self.source, self.meta = view, source, meta
        self.trained_env = str(meta["env"])
        self.obs_dim = view.task.obs_dim
        self.act_dim = view.n_agents * view.act_dim

    @abstractmethod
    def actions(self, local: np.ndarray) -> np.ndarray:
        """(N, m_a) actions of local observations (N, d) float32, before the clip to [-1, 1]."""

    def local_obs_dim(self) -> int:
        """The local observation size the actor takes."""
        return int(self.meta["obs_dim"])

    @abstractmethod
    def actions_per_agent(self) -> int:
        """The commands the actor gives each agent (its output size)."""

    def check_env(self, env_id: str) -> None:
        """Refuse an env id, agent count, local observation size or commands per agent other than the training's
        (ValueError naming the model file and what does not match)."""
        m, v = self.meta, self.view
        if not same_task(env_id, str(m["env"])):
            raise ValueError(f"{self.source}: trained on {m['env']}, not {env_id}; evaluate it on {m['env']} or "
                             f"train one for {env_id}")
        if v.n_agents != int(m["n_agents"]):
            raise ValueError(f"{self.source}: trained with {m['n_agents']} agents (slots), the env has "
                             f"{v.n_agents} (n_wings or scene differ)")
        if int(m["obs_dim"]) != self.local_obs_dim():  # the model's own size against what its run folder says
            raise ValueError(f"{self.source}: takes local observations of {self.local_obs_dim()} entries, but its "
                             f"{SHARED_POLICY_FILE} says obs_dim = {m['obs_dim']!r} (k = {m['k']})")
        if self.local_obs_dim() != v.obs_dim:
            raise ValueError(f"{self.source}: local observations of ({self.local_obs_dim()},) entries (k = "
                             f"{m['k']}), the env gives {v.obs_dim}")
        if self.actions_per_agent() != v.act_dim:
            raise ValueError(f"{self.source}: commands {self.actions_per_agent()} surfaces per agent, the env's "
                             f"agents take {v.act_dim} (surfaces differ: {m.get('env_kwargs') or {}} in training)")

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
        a = self.actions(local.reshape(B * self.view.n_agents, -1))
        joint = np.clip(a, -1.0, 1.0).reshape(B, self.act_dim).astype(np.float32)
        return (joint[0] if single else joint), state


class LinearActor:
    """The exported linear actor: mean action = W (h(position) (outer) [z, 1]) + b on local observations, z the
    scaled lateral deviations of the 2k + 1 wings seen (``GainScheduledExtractor``'s arithmetic, in float32); the
    product W features + b in float64, fixed order (the same bits on every CPU)."""

    def __init__(self, arrays: dict[str, np.ndarray], source: Path):
        self.source = source
        self.weight = np.asarray(arrays["weight"], dtype=np.float32)
        self.bias = np.asarray(arrays["bias"], dtype=np.float32)
        self.trim = np.asarray(arrays["trim"], dtype=np.float32)
        self.scales = np.asarray(arrays["scales"], dtype=np.float32)
        self.offsets = np.asarray(arrays["offsets"], dtype=np.int64)
        self.cols = np.asarray(arrays["cols"], dtype=np.int64)
        self.n, self.k, self.block, self.n_basis = (int(arrays[f]) for f in ("n_agents", "k", "block", "n_basis"))
        n_lat = len(LATERAL_FIELDS) * (2 * self.k + 1) + 1
        if self.weight.ndim != 2 or self.weight.shape[1] != self.n_basis * n_lat or self.bias.shape != (
                self.weight.shape[0],) or self.trim.shape != (self.n, 2) or self.cols.shape != (n_lat - 1,):
            raise ValueError(f"{source}: weight {self.weight.shape}, bias {self.bias.shape}, trim {self.trim.shape}, "
                             f"cols {self.cols.shape} do not fit n_agents {self.n}, k {self.k}, n_basis "
                             f"{self.n_basis}")
        self.flag0 = self.block * (2 * self.k + 1)
        self.pos = self.flag0 + 2 * self.k

    @classmethod
    def load(cls, path: Path, model_file: Path | None = None) -> LinearActor:
        """Read ``path``; with ``model_file``, refuse an npz exported from another model.zip (ValueError naming both:
        re-export it with ``export_linear_actor``)."""
        with np.load(path, allow_pickle=False) as f:
            missing = [key for key in LINEAR_ACTOR_KEYS if key not in f.files]
            if missing:
                raise ValueError(f"{path}: missing {', '.join(missing)} (not written by export_linear_actor)")
            arrays = {key: f[key] for key in LINEAR_ACTOR_KEYS}
        if model_file is not None and model_file.is_file() and str(arrays["model_sha256"]) != file_digest(model_file):
            raise ValueError(f"{path}: exported from another model than {model_file} (SHA-256 differs); re-export "
                             "it: python -m laddermill_gym.control.shared_policy --export " + str(model_file))
        return cls(arrays, path)

    def features(self, obs: np.ndarray) -> np.ndarray:
        """(N, n_basis n_lat) float32 features of local observations (N, d)."""
        obs = np.asarray(obs, dtype=np.float32)
        N, k = obs.shape[0], self.k
        pos = obs[:, self.pos]
        slot = np.round(pos * np.float32(max(self.n - 1, 1))).astype(np.int64)
        lat = obs[:, self.cols].reshape(N, 2 * k + 1, len(LATERAL_FIELDS))
        present = np.ones((N, 2 * k + 1), dtype=np.float32)
        if k:
            present[:, 1:] = obs[:, self.flag0: self.flag0 + 2 * k]
        trim = self.trim[np.clip(slot[:, None] + self.offsets[None, :], 0, self.n - 1)]
        two_pi, pi = np.float32(2 * np.pi), np.float32(np.pi)
        dpsi = np.remainder(lat[..., 3] - trim[..., 1] + pi, two_pi) - pi
        z = np.stack([lat[..., 0], lat[..., 1], lat[..., 2] - trim[..., 0], dpsi, lat[..., 4], lat[..., 5]],
                     axis=-1) / self.scales
        z = np.concatenate([(z * present[..., None]).reshape(N, -1), np.ones((N, 1), dtype=np.float32)], axis=1)
        if self.n_basis == 1:
            h = np.ones((N, 1), dtype=np.float32)
        else:
            nodes = np.linspace(0.0, 1.0, self.n_basis, dtype=np.float32)
            h = np.maximum(np.float32(1.0) - np.abs(pos[:, None] - nodes[None, :]) * np.float32(self.n_basis - 1),
                           np.float32(0.0))
        return (h[:, :, None] * z[:, None, :]).reshape(N, -1)

    def mean(self, obs: np.ndarray) -> np.ndarray:
        """(N, m_a) float64 mean actions of local observations (N, d) (before any clip)."""
        return affine_fixed_order(self.features(obs), self.weight, self.bias)


class LinearActorController(SharedController):
    """A shared per-wing policy evaluated from its ``linear_actor.npz`` (numpy only). Build with :meth:`load`."""

    def __init__(self, actor: LinearActor, view: WingAgents, source: Path, meta: dict):
        super().__init__(view, source, meta)
        self.actor = actor

    def actions(self, local: np.ndarray) -> np.ndarray:
        return self.actor.mean(local)

    def actions_per_agent(self) -> int:
        return int(self.actor.weight.shape[0])

    @staticmethod
    def available(path: str | Path) -> bool:
        """Whether ``path``, a run folder or its ``model.zip``, has an exported linear actor. The actor is
        ``model.zip``'s: another model file of the folder (``last_model.zip``, ``bc_model.zip``) has none."""
        path = Path(path)
        if not (path.is_dir() or path.name == "model.zip"):
            return False
        return ((path if path.is_dir() else path.parent) / LINEAR_ACTOR_FILE).is_file()

    @classmethod
    def load(cls, path: str | Path, env_id: str | None = None, env_kwargs: dict | None = None
             ) -> LinearActorController:
        """The run folder ``path`` (or a file in it) with its ``shared_policy.yaml`` and ``linear_actor.npz``,
        checked against ``env_id`` / ``env_kwargs`` (default: the training's) before anything runs."""
        path = Path(path)
        folder = path if path.is_dir() else path.parent
        npz = folder / LINEAR_ACTOR_FILE
        if not (path.is_dir() or path.name == "model.zip"):
            raise ValueError(f"{path}: {npz} is the actor of {folder / 'model.zip'}, not of this file; run this "
                             "one with SharedPolicyController (torch)")
        meta = read_shared_meta(folder / SHARED_POLICY_FILE)
        if not npz.is_file():
            raise FileNotFoundError(f"{npz}: no such file (export it from {folder / 'model.zip'}: python -m "
                                    "laddermill_gym.control.shared_policy --export <model.zip>)")
        actor = LinearActor.load(npz, folder / "model.zip")
        if actor.n != int(meta["n_agents"]) or actor.k != int(meta["k"]):
            raise ValueError(f"{npz}: n_agents {actor.n}, k {actor.k}; {folder / SHARED_POLICY_FILE} says "
                             f"{meta['n_agents']}, {meta['k']}")
        ctrl = cls(actor, build_view(meta, npz, env_id, env_kwargs), npz, meta)
        ctrl.check_env(env_id or str(meta["env"]))
        return ctrl


def lateral_columns(k: int, block: int) -> list[int]:
    """Columns of a local observation holding the lateral entries of the 2k + 1 wings it sees (own block first)."""
    return [j * block + OBS_INDEX[f] for j in range(2 * k + 1) for f in LATERAL_FIELDS]
