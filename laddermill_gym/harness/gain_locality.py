"""How local is the mill's centralised LQR? The locality study behind the shared per-wing policy's ``k``
(laddermill_gym/docs/learned_mill.md):

    python -m laddermill_gym.harness.gain_locality [--env laddermill_gym/LadderMill-v1]

Designs the env's default lateral LQR (``make_controller("lqr", env)``: 2n inputs x 6n states), makes its gain
dimensionless with the config's Bryson scales (K_s = diag(1 / max_input) K diag(max_state)), and prints

1. the Frobenius norm of the 2 x 6 block that maps slot j's lateral state to slot i's commands, by slot distance
   |i - j| (mean, largest, share of the whole gain);
2. the gain cut to a band |i - j| <= k (k = 0, 1, 2, 3, 4, 6, 8, all) and the spectral radius of the design model's
   ZOH closed loop Ad - Bd K_k (the model the gain was designed on; below 1: that band still stabilises it);
3. the own-slot block's norm along the loop (every 5th slot): how much a shared policy's gains must vary with
   the position.
"""

from __future__ import annotations

import sys

import numpy as np

from laddermill_gym.studies.commands import Parser

__all__ = ["block_norms", "banded", "main"]

_NLAT, _NIN = 6, 2  # lateral states and inputs per slot (control.linearize.WING_LATERAL, LATERAL_INPUTS)


def block_norms(K: np.ndarray) -> np.ndarray:
    """(n, n) Frobenius norms of the (2, 6) blocks of a slot-ordered gain K (2n, 6n)."""
    n = K.shape[0] // _NIN
    return np.linalg.norm(K.reshape(n, _NIN, n, _NLAT), axis=(1, 3))


def banded(K: np.ndarray, k: int) -> np.ndarray:
    """K with every block of slot distance above ``k`` set to zero."""
    n = K.shape[0] // _NIN
    dist = np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])
    return K * np.kron((dist <= k).astype(float), np.ones((_NIN, _NLAT)))


def main(argv: list[str] | None = None) -> int:
    import control

    from laddermill_gym.control.factory import DEFAULT_LQR_CONFIGS
    from laddermill_gym.control.lqr_config import load_lqr_config
    from laddermill_gym.control.mill_lqr import design_mill_lqr
    from laddermill_gym.envs import registered_arguments
    from laddermill_gym.envs.laddermill.task import MillTask

    p = Parser(prog="python -m laddermill_gym.harness.gain_locality", description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/LadderMill-v1",
                   choices=["laddermill_gym/LadderMill-v0", "laddermill_gym/LadderMill-v1"])
    args = p.parse_args(argv)
    kw = registered_arguments(args.env, {})
    task = MillTask(1, **{k: v for k, v in kw.items() if k != "parallel"})
    cfg = load_lqr_config(DEFAULT_LQR_CONFIGS[args.env])
    d = design_mill_lqr(cfg, task, progress=print)
    print(d.summary())
    K = np.asarray(d.gains)  # centralised (the shipped configs'): (2n, 6n)
    if K.ndim != 2:
        raise SystemExit(f"{cfg.file}: structure = {cfg.structure!r}; the study needs the centralised gain")
    n = K.shape[0] // _NIN
    Ks = K * np.tile(cfg.max_state, n)[None, :] / np.tile(cfg.max_input, n)[:, None]
    W = block_norms(Ks)
    dist = np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])
    print("slot distance | mean block norm | largest | share of the gain")
    for dd in range(11):
        m = W[dist == dd]
        print(f"{dd:13d} | {m.mean():15.4f} | {m.max():7.4f} | {m.sum() / W.sum():.3f}")
    print(f"beyond 10: share {W[dist > 10].sum() / W.sum():.4f}")
    sysd = control.c2d(control.ss(d.A, d.B, np.eye(d.A.shape[0]), np.zeros(d.B.shape)), cfg.control_period, "zoh")
    Ad, Bd = np.asarray(sysd.A), np.asarray(sysd.B)
    for k in (0, 1, 2, 3, 4, 6, 8, n):
        r = np.max(np.abs(np.linalg.eigvals(Ad - Bd @ banded(K, k))))
        print(f"band |i - j| <= {k}: spectral radius of the design model's closed loop {r:.5f}")
    own = np.diag(W)
    print("own-slot block norm, slots 0, 5, ..:", " ".join(f"{v:.2f}" for v in own[::5]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
