"""Can the shared policy's class hold the mill (or the fixed chain)? The LQR's gain projected onto it, flown:

    python -m laddermill_gym.harness.shared_fit [--env ID] [--teacher LQR_CONFIG] [--n-basis 101] [--k 4]
        [--episode-time 300] [--out DIR]

The actor of :mod:`laddermill_gym.control.shared_policy` is a = sum_b h_b(i / (n - 1)) (W_b z_i + c_b): slot i's
rudder and aileron are a linear map of the lateral deviations z_i of its wing and its k neighbours each side
(over the LQR config's Bryson scales). The LQR (``make_controller("lqr", env)`` or ``--teacher``'s design, as one
linear law: ``harness.shared_teacher``, gain K, 2n x 6n, and the trim action as the constant's weight) cut to
that band (``gain_locality.banded(K, k)``) is, slot by slot, such a map w_i; this command fits the W_b to the w_i
by least squares over the slots (min_W sum_i |sum_b h_b(i) W_b - w_i|^2: with one node per slot,
``n_basis = n``, the fit is exact), writes the result as a shared-policy run folder (``model.zip``,
``shared_policy.yaml``) and flies it on the single-agent env's registered scenario (the paper's 0.01 rad step at
1 s), seeds 0-4, beside the LQR. No data and no reward: it checks the *class*, not a learner.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import yaml

from laddermill_gym.studies.commands import Parser

__all__ = ["band_weights", "bryson_scales", "project_weights", "main"]

_NLAT = 6  # lateral entries per slot (shared_policy.LATERAL_FIELDS)


def bryson_scales(env_id: str, lqr_config: Path | None = None) -> np.ndarray:
    """(dy, vy, phi, psi, p, r) scales [m, m/s, rad, rad, rad/s, rad/s]: the max_state of the LQR config
    ``lqr_config`` (None: the env's default design's)."""
    from laddermill_gym.control.factory import DEFAULT_LQR_CONFIGS
    from laddermill_gym.control.lqr_config import load_lqr_config

    path = DEFAULT_LQR_CONFIGS[env_id] if lqr_config is None else lqr_config
    return np.asarray(load_lqr_config(path).max_state, dtype=float)


def band_weights(K: np.ndarray, half: np.ndarray, scales: np.ndarray, k: int) -> np.ndarray:
    """(n, 6 (2k + 1), 2) per-slot weights of the LQR's actions a = -K dz / half (rudder, aileron) on the actor's
    local features z_i = (own block, then neighbours at offsets -k..-1, 1..k) / scales; neighbours past a ground
    station (outside 0..n-1) get zero weight (their features are zero)."""
    n = K.shape[0] // 2
    Kb = K.reshape(n, 2, n, _NLAT)
    offsets = [0] + [d for d in range(-k, k + 1) if d != 0]
    w = np.zeros((n, len(offsets), _NLAT, 2))
    for i in range(n):
        for j, d in enumerate(offsets):
            if 0 <= i + d < n:
                w[i, j] = (-Kb[i, :, i + d, :] * np.asarray(scales)[None, :] / np.asarray(half)[i][:, None]).T
    return w.reshape(n, len(offsets) * _NLAT, 2)


def project_weights(w: np.ndarray, n_basis: int, column: np.ndarray, n_act: int,
                    offset: np.ndarray | None = None) -> tuple[np.ndarray, float]:
    """The actor's linear head (n_act, n_basis (f + 1)) fitting the per-slot weights ``w`` (n, f, 2) by least
    squares over the slots (hat functions of i / (n - 1)), and the relative gain error |H W - w| / |w| (0 when
    ``n_basis`` = n). The constant feature's weights c_b fit ``offset`` (n, n_act), every slot's action at zero
    deviation, the same way (None: 0)."""
    import torch as th

    from laddermill_gym.control.shared_policy import hat_basis

    n, f, _ = w.shape
    H = hat_basis(th.arange(n, dtype=th.float64) / max(n - 1, 1), n_basis).numpy()  # (n, nb)
    W = np.linalg.lstsq(H, w.reshape(n, -1), rcond=None)[0].reshape(n_basis, f, 2)
    err = float(np.linalg.norm(np.einsum("ib,bfa->ifa", H, W) - w) / np.linalg.norm(w))
    head = np.zeros((n_act, n_basis, f + 1))
    for c in range(2):
        head[column[c], :, :f] = W[:, :, c]
    if offset is not None:
        head[:, :, f] = np.linalg.lstsq(H, np.asarray(offset, dtype=float).reshape(n, n_act), rcond=None)[0].T
    return head.reshape(n_act, -1), err


def fitted_model(env_id: str, k: int, n_basis: int, teacher, scales: np.ndarray, out: Path, seed: int = 0):
    """A PPO model with the shared actor whose head is the projection of the LQR's band-k gain (and its trim
    action); saved in ``out`` as a run folder. Returns (model, relative gain error, meta)."""
    import torch as th
    from stable_baselines3 import PPO

    from laddermill_gym.harness.gain_locality import banded
    from laddermill_gym.harness.shared_teacher import linear_teacher
    from laddermill_gym.multiagent.sb3 import shared_policy_vec_env

    venv = shared_policy_vec_env(env_id, 1, k=k, seed=seed)
    view = venv.view
    from laddermill_gym.control.shared_policy import GainScheduledExtractor

    pk = dict(features_extractor_class=GainScheduledExtractor,
              features_extractor_kwargs=dict(n_agents=view.n_agents, k=k, block=view.block, n_basis=n_basis,
                                             trim=np.asarray(teacher.trim_attitude).tolist(),
                                             scales=np.asarray(scales).tolist()),
              net_arch=dict(pi=[], vf=[8]), log_std_init=-3.0, ortho_init=False)
    model = PPO("MlpPolicy", venv, seed=seed, policy_kwargs=pk, device="cpu", verbose=0)
    lin = linear_teacher(teacher)
    w = band_weights(banded(lin.K, k), lin.half, scales, k)
    head, err = project_weights(w, n_basis, lin.column, view.act_dim, lin.offset)
    net = model.policy.action_net
    with th.no_grad():
        net.weight.copy_(th.as_tensor(head, dtype=net.weight.dtype))
        net.bias.zero_()
    meta = dict(env=env_id, k=k, n_agents=view.n_agents, obs_dim=view.obs_dim, algorithm="PPO", env_kwargs={},
                config=f"harness.shared_fit --n-basis {n_basis} --k {k}", seed=seed)
    out.mkdir(parents=True, exist_ok=True)
    (out / "shared_policy.yaml").write_text(yaml.safe_dump(meta, sort_keys=False))
    model.save(out / "model.zip")
    return model, err, meta


def main(argv: list[str] | None = None) -> int:
    import gymnasium as gym

    from laddermill_gym.control.shared_policy import SharedPolicyController
    from laddermill_gym.harness.evaluate import run_episodes
    from laddermill_gym.harness.shared_teacher import make_teacher
    from laddermill_gym.model.configio import find_config

    p = Parser(prog="python -m laddermill_gym.harness.shared_fit", description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/LadderMill-v1",
                   choices=[f"laddermill_gym/LadderMill-v{v}" for v in (1, 2, 3)]
                   + [f"laddermill_gym/LadderChain-v{v}" for v in (0, 1)])
    p.add_argument("--teacher", help="the LQR config (file or shipped name; default: the env's default design)")
    p.add_argument("--n-basis", type=int, default=101, help="hat functions of the position (101: one per slot)")
    p.add_argument("--k", type=int, default=4, help="neighbours each side")
    p.add_argument("--episode-time", type=float, default=300.0, help="[s]")
    p.add_argument("--episodes", type=int, default=5)
    p.add_argument("--out", type=Path, default=Path("runs/shared_fit"))
    p.add_argument("--no-lqr", action="store_true", help="fly the fitted policy only, not the LQR beside it")
    a = p.parse_args(argv)
    if a.n_basis < 1 or not 0 <= a.k <= 10:
        p.error(f"--n-basis {a.n_basis} / --k {a.k}: need n_basis >= 1 and 0 <= k <= 10")
    lqr_config = None if a.teacher is None else find_config("agents", a.teacher, "--teacher")
    teacher = make_teacher(a.env, lqr_config)
    model, err, _ = fitted_model(a.env, a.k, a.n_basis, teacher, bryson_scales(a.env, lqr_config), a.out)
    print(f"n_basis {a.n_basis}, k {a.k}: relative gain error of the projection {err:.4f}; run folder {a.out}")
    env = gym.make_vec(a.env, num_envs=a.episodes, vectorization_mode="vector_entry_point",
                       episode_time=a.episode_time)
    ctrl = SharedPolicyController.load(a.out, a.env)
    runs = [("shared policy (LQR band projected)", ctrl)] + ([] if a.no_lqr else [("LQR", teacher)])
    for name, c in runs:
        r = run_episodes(c, env, record=False, progress=True)
        held = int(np.sum(r.lengths_s >= a.episode_time - 1e-6))
        print(f"{name}: held {held} of {a.episodes}, length {np.round(r.lengths_s, 2)} s, max |dy| "
              f"{r.max_lateral_m.max():.4f} m, mean power {r.mean_power_W.mean() / 1e3:.2f} kW")
    return 0


if __name__ == "__main__":
    sys.exit(main())
