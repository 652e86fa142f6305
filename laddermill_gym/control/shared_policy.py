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

import numpy as np
import torch as th
from stable_baselines3.common.torch_layers import BaseFeaturesExtractor

from laddermill_gym.control.sb3_policy import algorithm_class, load_as, run_folder
from laddermill_gym.control.shared_controller import (
    LATERAL_FIELDS,
    LINEAR_ACTOR_FILE,
    SHARED_POLICY_FILE,
    SharedController,
    build_view,
    file_digest,
    lateral_columns,
    read_shared_meta,
)
from laddermill_gym.multiagent.agents import WingAgents

__all__ = ["LATERAL_FIELDS", "GainScheduledExtractor", "SharedPolicyController", "SHARED_POLICY_FILE",
           "hat_basis", "export_linear_actor", "is_linear_actor"]


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
        self.register_buffer("cols", th.tensor(lateral_columns(k, block), dtype=th.long))
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


class SharedPolicyController(SharedController):
    """``predict`` of a trained shared per-wing policy's SB3 model (``rl`` extra) on the single-agent env's
    observations (B, D) or (D,): every slot's local observation -> the policy (deterministic) -> the joint action
    (B, n m_a) in [-1, 1] (:class:`~laddermill_gym.control.shared_controller.SharedController`).

    Build with :meth:`load` (a run folder holding ``shared_policy.yaml`` and ``model.zip``, or that model file).
    ``check_env(env_id)`` refuses another env, another number of agents or another observation size, naming the
    file; :meth:`check_extractor` a model whose actor was built for other slots or another k than its folder says.
    The shipped policies run torch-free from their exported ``linear_actor.npz`` (``LinearActorController``)."""

    def __init__(self, model, view: WingAgents, source: Path, meta: dict):
        super().__init__(view, source, meta)
        self.model = model

    def actions(self, local: np.ndarray) -> np.ndarray:
        return self.model.predict(local, deterministic=True)[0]

    def local_obs_dim(self) -> int:
        return int(self.model.observation_space.shape[0])

    def actions_per_agent(self) -> int:
        return int(self.model.action_space.shape[0])

    @classmethod
    def load(cls, path: str | Path, env_id: str | None = None, env_kwargs: dict | None = None
             ) -> SharedPolicyController:
        """Load the run folder (its ``model.zip``) or a model file ``path``; with ``env_id`` the policy is checked
        against that env (and ``env_kwargs``: the agents and observation size) before anything runs."""
        path = Path(path)
        folder = path if path.is_dir() else run_folder(path)  # a checkpoint's: the run folder above
        meta_file = folder / SHARED_POLICY_FILE
        meta = read_shared_meta(meta_file)
        model_file = folder / "model.zip" if path.is_dir() else path
        if not model_file.is_file():
            raise FileNotFoundError(f"{model_file}: no such model file (the run folder {folder} has "
                                    f"{SHARED_POLICY_FILE} but no model.zip)")
        algo = algorithm_class(str(meta["algorithm"]), meta_file)
        view = build_view(meta, model_file, env_id, env_kwargs)
        ctrl = cls(load_as(algo, model_file, meta_file), view, model_file, meta)
        ctrl.check_env(env_id or str(meta["env"]))
        ctrl.check_extractor()
        return ctrl

    def check_extractor(self) -> None:
        """Refuse a model whose actor's :class:`GainScheduledExtractor` was built for another number of slots than
        the env's agents or another ``k`` than its ``shared_policy.yaml`` says (ValueError naming the model file and
        both values): its slot index round(position (n - 1)) would give the env's agents other slots' operating
        point (trim) and gains, without a word. Another features extractor has no slot count to check."""
        policy = self.model.policy
        ext = getattr(policy, "pi_features_extractor", policy.features_extractor)
        if not isinstance(ext, GainScheduledExtractor):
            return
        if ext.n != self.view.n_agents:
            raise ValueError(f"{self.source}: its GainScheduledExtractor has n_agents = {ext.n} slots, the env has "
                             f"{self.view.n_agents} agents (the model was trained for {ext.n} slots; its "
                             f"{SHARED_POLICY_FILE} says {self.meta['n_agents']})")
        if ext.k != int(self.meta["k"]):
            raise ValueError(f"{self.source}: its GainScheduledExtractor has k = {ext.k}, its {SHARED_POLICY_FILE} "
                             f"says k = {self.meta['k']}")


def is_linear_actor(policy) -> bool:
    """Whether an SB3 actor-critic ``policy``'s mean action is linear in GainScheduledExtractor's features (no
    hidden actor layers), so that ``linear_actor.npz`` can hold it."""
    ext = getattr(policy, "pi_features_extractor", policy.features_extractor)
    return isinstance(ext, GainScheduledExtractor) and len(policy.mlp_extractor.policy_net) == 0


def export_linear_actor(model_file: str | Path) -> Path:
    """Write the linear actor of the shared policy ``model_file`` (a ``model.zip`` beside its
    ``shared_policy.yaml``) to ``linear_actor.npz`` in the same folder and return its path; ValueError naming the
    file when the actor is not linear (hidden layers, another features extractor)."""
    import stable_baselines3 as sb3

    model_file = Path(model_file)
    meta = read_shared_meta(model_file.parent / SHARED_POLICY_FILE)
    policy = getattr(sb3, str(meta["algorithm"])).load(model_file, device="cpu").policy
    ext = getattr(policy, "pi_features_extractor", policy.features_extractor)
    if not is_linear_actor(policy):
        raise ValueError(f"{model_file}: the actor is not linear in GainScheduledExtractor's features (extractor "
                         f"{type(ext).__name__}, {len(policy.mlp_extractor.policy_net)} hidden layers); it needs "
                         "torch (SharedPolicyController)")
    out = model_file.parent / LINEAR_ACTOR_FILE
    arrays = dict(weight=policy.action_net.weight, bias=policy.action_net.bias, trim=ext.trim, scales=ext.scales,
                  offsets=ext.offsets, cols=ext.cols)
    with open(out, "wb") as f:
        np.savez(f, **{key: val.detach().cpu().numpy() for key, val in arrays.items()}, n_agents=ext.n, k=ext.k,
                 block=ext.block, n_basis=ext.n_basis, model_sha256=file_digest(model_file))
    return out


def main(argv: list[str] | None = None) -> int:
    """``python -m laddermill_gym.control.shared_policy --export RUN/model.zip``: write its linear_actor.npz."""
    import argparse

    p = argparse.ArgumentParser(description=main.__doc__)
    p.add_argument("--export", nargs="+", required=True, metavar="MODEL_ZIP", help="shared-policy model files")
    # the package's module, not __main__: the saved model's extractor class is the package's
    from laddermill_gym.control import shared_policy

    for model_file in p.parse_args(argv).export:
        print(shared_policy.export_linear_actor(model_file))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
