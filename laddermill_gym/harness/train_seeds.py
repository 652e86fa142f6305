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
``--out-root`` a path on a file system every node shares. Every worker reads the config in the caller's working
directory (where it exists on the worker's node), so a relative path inside the config (``init_from:
lqr:configs/agents/...``) names the caller's file there too. Prints one line per seed as it completes; a failed
seed stops the start of others, lets the running ones finish, and is named with its run folder (exit status 1).
Ctrl-C saves the running seeds' models, starts no other seed and exits with 130, serially as with ``--workers`` or
``--ray`` (there the workers ignore the terminal's Ctrl-C and the caller passes it on: ``studies/pool_workers``); a
second Ctrl-C aborts without saving.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import sys
import warnings
from pathlib import Path

from tqdm import tqdm

from laddermill_gym.studies.commands import Command, UsageError, writable_folder
from laddermill_gym.studies.parallel import Pool, TasksFailed, TasksInterrupted, add_arguments, check_arguments

__all__ = ["train_task", "warm_envs", "train_seeds", "TrainingInterrupted", "in_callers_folder", "add_parser", "main"]

PROG = "laddermill train-seeds"


def _config(config: str, overrides: dict):
    """The config with the overrides (RLConfig fields), checked as ``laddermill train`` checks its options
    (:func:`~laddermill_gym.harness.train.apply_overrides`: UsageError naming the option)."""
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import apply_overrides

    return apply_overrides(load_rl_config(config), overrides)


class TrainingInterrupted(Exception):
    """A seed's training stopped by Ctrl-C (its model saved): the batch stops, the command exits with 130."""


def in_callers_folder(cwd: str | None) -> None:
    """Change to the caller's working directory ``cwd`` (a Ray actor starts wherever ``ray start`` ran), where the
    config's relative paths mean the caller's files; a RuntimeWarning where this node has no such folder."""
    if cwd is None or os.getcwd() == cwd:
        return
    if Path(cwd).is_dir():
        os.chdir(cwd)
    else:
        warnings.warn(f"the caller's working directory {cwd} is not on this node: relative paths in the config are "
                      f"read from {os.getcwd()}", RuntimeWarning, stacklevel=2)


def warm_envs(config: str, cwd: str | None = None) -> None:
    """The per-worker warm-up: build the config's training and evaluation envs and step each once (compiles
    or loads their kernels), in the caller's working directory ``cwd``."""
    import numpy as np

    in_callers_folder(cwd)

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


def train_task(config: str, seed: int, out: str, overrides: dict, command: list[str] | None = None,
               cwd: str | None = None) -> dict:
    """A picklable task: train ``config`` with ``seed`` and ``overrides`` (RLConfig fields) into ``out``, recording
    ``command`` (the caller's command line; default this process's ``sys.argv``) in its ``run.yaml``, in the caller's
    working directory ``cwd``; returns :func:`~laddermill_gym.harness.train.train`'s summary with the seed and
    folder. TrainingInterrupted when Ctrl-C stopped it (the model saved)."""
    from laddermill_gym.harness.train import train

    in_callers_folder(cwd)
    summary = train(_config(config, dict(overrides, seed=int(seed))), Path(out), command=command)
    if summary.get("interrupted"):
        raise TrainingInterrupted(f"stopped by Ctrl-C after {summary['steps']} steps, its model saved in {out}")
    return dict(summary, seed=int(seed), out=str(out))


def train_seeds(config: str, seeds, out_root: Path, overrides: dict, workers: int = 0,
                ray: str | None = None, on_result=None) -> list[dict]:
    """Train ``config`` once per seed (tasks in seed order; each run folder's ``run.yaml`` records this process's
    command line, not the worker's); the summaries in that order; ``on_result(summary)`` as each seed completes."""
    stem = Path(config).stem
    if Path(config).exists():  # Ray workers do not share the caller's working directory
        config = str(Path(config).resolve())
    cwd = os.getcwd()
    outs = [str((out_root / f"{stem}_seed{s}").resolve()) for s in seeds]
    tasks = [(train_task, dict(config=config, seed=int(s), out=o, overrides=dict(overrides), command=list(sys.argv),
                               cwd=cwd)) for s, o in zip(seeds, outs, strict=True)]
    labels = [f"seed {s} (run folder {o})" for s, o in zip(seeds, outs, strict=True)]
    with Pool(min(workers, len(tasks)), ray, warmup=[(warm_envs, {"config": config, "cwd": cwd})],
              cap=len(tasks)) as pool:
        return pool.run(tasks, desc=f"train {stem}", unit="seed", labels=labels,
                        on_result=None if on_result is None else lambda i, summary: on_result(summary))


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
    from laddermill_gym.harness.validation import check_held_out
    from laddermill_gym.model.configio import ConfigError

    try:  # laddermill train's checks (a NaN time limit, --n-envs above 4096, a minibatch beyond the rollout, a
        check_held_out(_config(args.config, over))  # validation on a benchmark's episodes ...): before any worker
    except (UsageError, ConfigError) as err:
        _fail(prog, str(err))
    from laddermill_gym.harness.train import RUN_FILES

    folders = [args.out_root / f"{Path(args.config).stem}_seed{s}" for s in args.seeds]
    held = [str(f) for f in folders if any((f / name).exists() for name in RUN_FILES)]
    if held:  # laddermill train refuses a folder holding a run; here before any seed trains
        _fail(prog, f"--out-root {str(args.out_root)!r}: the run folders {held} exist already")
    try:
        writable_folder(args.out_root, "--out-root")
    except UsageError as err:
        _fail(prog, str(err))

    def line(s: dict) -> None:
        tqdm.write(f"seed {s['seed']}: {s['steps']} steps in {s['minutes']} min; evaluation return best "
                   f"{s['best_eval_return']:.2f}, last {s['last_eval_return']:.2f}; run folder {s['out']}")

    try:
        train_seeds(args.config, args.seeds, args.out_root, over, args.workers, args.ray, on_result=line)
    except ConnectionError as err:  # Ray's cluster not reached (ray.init): no seed has trained
        _fail(prog, f"--ray {args.ray!r}: {err}")
    except TasksInterrupted as err:  # Ctrl-C on workers: each running seed saved its model (or completed)
        print(f"{prog}: interrupted: {err}", file=sys.stderr)
        return 130
    except TasksFailed as err:  # the seeds that completed have had their line
        if isinstance(err.__cause__, TrainingInterrupted):
            print(f"{prog}: interrupted: {err}", file=sys.stderr)
            return 130
        print(f"{prog}: {err}", file=sys.stderr)
        return 1
    return 0


#: ``laddermill train-seeds`` (its own parser's name is :data:`PROG`)
COMMAND = Command("train-seeds", "train one config with several seeds (locally parallel or on Ray)",
                  __doc__.split("\n\n")[0], _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("train-seeds", main))
