"""Train one config with several seeds: serially, in local worker processes or on a Ray cluster.

    laddermill train-seeds configs/agents/ppo_tethered_wing.yaml --seeds 0 1 2   (or python -m
        laddermill_gym.harness.train_seeds)
        [--out-root runs] [--timesteps N] [--minutes M] [--n-envs N] [--workers N] [--ray auto|local|ADDRESS]

Every seed is one task of :mod:`laddermill_gym.studies.parallel` that calls
:func:`laddermill_gym.harness.train.train` into ``<out-root>/<config name>_seed<seed>`` (the folder
``laddermill train --seed S`` uses); each worker first builds the config's training and evaluation envs once
(the numba warm-up). A run with a step budget (no ``--minutes``, or a limit it does not reach) gives the same
run folder contents whichever way it ran; a time limit ends training at a step count that depends on the
machine's speed. On a cluster the run folders are written on the node that trained the seed: give
``--out-root`` a path on a file system every node shares. Prints one line per seed.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path

from laddermill_gym.studies.commands import Command, UsageError
from laddermill_gym.studies.parallel import Pool, add_arguments, check_arguments

__all__ = ["train_task", "warm_envs", "train_seeds", "add_parser", "main"]

PROG = "laddermill train-seeds"


def _config(config: str, overrides: dict):
    """The config with the overrides (RLConfig fields), checked as ``laddermill train`` checks its options
    (:func:`~laddermill_gym.harness.train.apply_overrides`: UsageError naming the option)."""
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import apply_overrides

    return apply_overrides(load_rl_config(config), overrides)


def warm_envs(config: str) -> None:
    """The per-worker warm-up: build the config's training and evaluation envs and step each once (compiles
    or loads their kernels)."""
    import numpy as np

    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import evaluation_env, training_env

    cfg = dataclasses.replace(load_rl_config(config), n_envs=1)  # not a run: the rollout limits do not apply
    venv = training_env(cfg)
    venv.reset()
    venv.step(np.zeros((1, *venv.action_space.shape), dtype=np.float32))
    venv.close()
    env = evaluation_env(cfg)
    env.reset(seed=0)
    env.step(np.zeros(env.action_space.shape, dtype=np.float32))
    env.close()


def train_task(config: str, seed: int, out: str, overrides: dict, command: list[str] | None = None) -> dict:
    """A picklable task: train ``config`` with ``seed`` and ``overrides`` (RLConfig fields) into ``out``, recording
    ``command`` (the caller's command line; default this process's ``sys.argv``) in its ``run.yaml``; returns
    :func:`~laddermill_gym.harness.train.train`'s summary with the seed and folder."""
    from laddermill_gym.harness.train import train

    summary = train(_config(config, dict(overrides, seed=int(seed))), Path(out), command=command)
    return dict(summary, seed=int(seed), out=str(out))


def train_seeds(config: str, seeds, out_root: Path, overrides: dict, workers: int = 0,
                ray: str | None = None) -> list[dict]:
    """Train ``config`` once per seed (tasks in seed order; each run folder's ``run.yaml`` records this process's
    command line, not the worker's); the summaries in that order."""
    stem = Path(config).stem
    if Path(config).exists():  # Ray workers do not share the caller's working directory
        config = str(Path(config).resolve())
    tasks = [(train_task, dict(config=config, seed=int(s), out=str((out_root / f"{stem}_seed{s}").resolve()),
                               overrides=dict(overrides), command=list(sys.argv))) for s in seeds]
    with Pool(min(workers, len(tasks)), ray, warmup=[(warm_envs, {"config": config})]) as pool:
        return pool.run(tasks, desc=f"train {stem}", unit="seed")


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("config", help="configs/agents/ppo_*.yaml or sac_*.yaml")
    p.add_argument("--seeds", type=int, nargs="+", required=True, help="training seeds (one run each)")
    p.add_argument("--out-root", type=Path, default=Path("runs"), help="parent of the run folders (default runs)")
    p.add_argument("--timesteps", type=int, help="override total_timesteps")
    p.add_argument("--minutes", type=float, help="override time_limit_minutes")
    p.add_argument("--n-envs", type=int, help="override n_envs")
    add_arguments(p)


def _fail(prog: str, msg: str) -> None:
    sys.stderr.write(f"{prog}: error: {msg}\n")
    raise SystemExit(2)


def _run(args, prog: str = PROG) -> int:
    check_arguments(args, prog)
    if len(set(args.seeds)) != len(args.seeds) or min(args.seeds) < 0 or max(args.seeds) > 2 ** 32 - 1:
        _fail(prog, f"--seeds {args.seeds}: must be distinct whole numbers 0 .. 2**32 - 1")  # numpy's seed range
    given = (("timesteps", "total_timesteps", args.timesteps), ("minutes", "time_limit_minutes", args.minutes),
             ("n-envs", "n_envs", args.n_envs))
    over = {field: v for _, field, v in given if v is not None}
    from laddermill_gym.harness.shared_config import is_shared_config

    if is_shared_config(args.config):
        _fail(prog, f"config {args.config!r}: a shared per-wing policy's config; train-seeds runs laddermill train's "
                    "configs (train it with laddermill train CONFIG --seed S)")
    try:  # laddermill train's checks (a NaN time limit, --n-envs above 4096, a minibatch beyond the rollout ...)
        _config(args.config, over)  # a bad config fails here, before any worker starts
    except UsageError as err:
        _fail(prog, str(err))
    from laddermill_gym.harness.train import RUN_FILES

    folders = [args.out_root / f"{Path(args.config).stem}_seed{s}" for s in args.seeds]
    held = [str(f) for f in folders if any((f / name).exists() for name in RUN_FILES)]
    if held:  # laddermill train refuses a folder holding a run; here before any seed trains
        _fail(prog, f"--out-root {str(args.out_root)!r}: the run folders {held} exist already")
    for s in train_seeds(args.config, args.seeds, args.out_root, over, args.workers, args.ray):
        print(f"seed {s['seed']}: {s['steps']} steps in {s['minutes']} min; evaluation return best "
              f"{s['best_eval_return']:.2f}, last {s['last_eval_return']:.2f}; run folder {s['out']}")
    return 0


#: ``laddermill train-seeds`` (its own parser's name is :data:`PROG`)
COMMAND = Command("train-seeds", "train one config with several seeds (locally parallel or on Ray)",
                  __doc__.split("\n\n")[0], _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
