"""Training time against torch's thread count: the figure behind ``laddermill train``'s one-thread default.

    python -m laddermill_gym.studies.benchmarks.torch_threads [configs/agents/ppo_tethered_wing.yaml] [--threads 1 2]
        [--rollouts 2] [--repeats 5] [--json out.json]

Builds the model of a training config exactly as ``laddermill train`` does (its batched training env,
VecNormalize, hyperparameters and network), lets it learn once to compile the kernels (and, for SAC, past
``learning_starts``), then times
``model.learn`` over ``--rollouts`` rollouts (PPO: n_envs x n_steps env steps each; SAC: n_envs x 256) for each
thread count in turn, ``--repeats`` times, interleaved so that the machine's load affects every count alike.
Prints the median wall time per 1000 env steps and its ratio to one thread. The default thread counts are 1 and
torch's own default on this machine (one per core).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.control.rl_config import load_rl_config
from laddermill_gym.model.configio import CONFIG_DIR

DEFAULT_CONFIG = CONFIG_DIR / "agents" / "ppo_tethered_wing.yaml"


def build_model(config: Path):
    """The SB3 model of ``laddermill train`` for ``config`` (no callbacks, no logging), the env steps of one
    rollout and of the warm-up (compilation; SAC's ``learning_starts``)."""
    import stable_baselines3 as sb3
    from stable_baselines3.common.vec_env import VecMonitor, VecNormalize

    from laddermill_gym.envs.sb3 import sb3_vec_env

    cfg = load_rl_config(config)
    # the training env of ``laddermill train`` (harness.train.training_env; the harness sits above the studies)
    venv = VecMonitor(sb3_vec_env(cfg.env_id, cfg.n_envs, seed=cfg.seed, **cfg.train_env_kwargs()))
    if cfg.normalize_observations:
        venv = VecNormalize(venv, norm_obs=True, norm_reward=False, clip_obs=10.0)
    algo = getattr(sb3, cfg.algorithm)
    model = algo("MlpPolicy", venv, seed=cfg.seed, policy_kwargs=cfg.policy_kwargs or None, verbose=0,
                 device="cpu", **cfg.hyperparameters)
    per_rollout = cfg.n_envs * (cfg.hyperparameters.get("n_steps", 2048) if cfg.algorithm == "PPO" else 256)
    warm_up = per_rollout + int(cfg.hyperparameters.get("learning_starts", 0))  # SAC: past its random start
    return model, per_rollout, warm_up


def measure(config: Path, threads: list[int], rollouts: int, repeats: int) -> dict:
    """Wall seconds per 1000 env steps of ``model.learn`` for every thread count (``repeats`` interleaved runs of
    ``rollouts`` rollouts each): {"steps": n, "seconds_per_1000": {threads: [..]}, "median": {...}}."""
    import torch

    model, per_rollout, warm_up = build_model(config)
    steps = rollouts * per_rollout
    model.learn(total_timesteps=warm_up)  # compile the kernels, allocate the buffers, fill SAC's first samples
    times: dict[int, list[float]] = {t: [] for t in threads}
    with tqdm(total=repeats * len(threads), unit="run", desc="torch threads") as bar:
        for _ in range(repeats):
            for t in threads:
                torch.set_num_threads(t)
                t0 = time.perf_counter()
                model.learn(total_timesteps=steps, reset_num_timesteps=False)
                times[t].append(1000.0 * (time.perf_counter() - t0) / steps)
                bar.update(1)
    return {"config": str(config), "steps": steps, "seconds_per_1000": times,
            "median": {t: float(np.median(v)) for t, v in times.items()}}


def main(argv: list[str] | None = None) -> int:
    import torch

    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.benchmarks.torch_threads",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("config", nargs="?", type=Path, default=DEFAULT_CONFIG, help="a configs/agents/ppo_*.yaml or "
                   "sac_*.yaml (default: ppo_tethered_wing.yaml)")
    p.add_argument("--threads", type=int, nargs="+", help="thread counts (default: 1 and torch's default, "
                   f"{torch.get_num_threads()} here)")
    p.add_argument("--rollouts", type=int, default=2, help="rollouts per timed run")
    p.add_argument("--repeats", type=int, default=5, help="timed runs per thread count (the median is reported)")
    p.add_argument("--json", type=Path, help="also write the times to this JSON file")
    args = p.parse_args(argv)
    threads = args.threads or sorted({1, torch.get_num_threads()})
    for name, value in (("--rollouts", args.rollouts), ("--repeats", args.repeats), *(("--threads", t)
                                                                                      for t in threads)):
        if value < 1:
            p.error(f"{name} = {value}: must be >= 1")
    res = measure(args.config, threads, args.rollouts, args.repeats)
    base = res["median"][threads[0]]
    print(f"{args.config.name}: {res['steps']} env steps per run, median of {args.repeats}")
    print(f"{'threads':>8} {'s / 1000 steps':>15} {'ratio to ' + str(threads[0]):>12}")
    for t in threads:
        print(f"{t:>8} {res['median'][t]:15.3f} {res['median'][t] / base:12.2f}")
    if args.json:
        args.json.write_text(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
