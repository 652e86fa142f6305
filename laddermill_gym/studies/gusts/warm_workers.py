"""``laddermill workers warm``: prepare a node for ``--workers`` / ``--ray`` by compiling (or loading from numba's
cache) the kernels of every gusts-v1 environment in this process, and print the time. Run once per node after
installing (docs/scale_out.md).

    laddermill workers warm
    python -m laddermill_gym.studies.gusts.warm_workers warm

The command of the executor (:mod:`laddermill_gym.studies.parallel`, whose description its help shows), kept here
beside the gust benchmark whose warm-up tasks it runs: the executor itself knows no study.
"""

from __future__ import annotations

import argparse
import os
import time

from tqdm import tqdm

from laddermill_gym.studies import parallel
from laddermill_gym.studies.commands import Command
from laddermill_gym.studies.gusts.gust_bench import warmup_tasks
from laddermill_gym.studies.gusts.gust_suite import load_suite


def _warm_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("action", choices=["warm"], help="warm: compile (or load from the cache) the kernels of every "
                   "gusts-v1 environment in this process and print the time; run once per node after installing")


def _warm(args) -> int:
    t0 = time.perf_counter()
    for fn, kw in tqdm(warmup_tasks(load_suite("gusts-v1"), [], ["open_loop"]), desc="warm", unit="env"):
        fn(**kw)
    print(f"warm: {time.perf_counter() - t0:.1f} s; numba cache: {os.environ.get('NUMBA_CACHE_DIR') or '__pycache__'}")
    return 0


#: ``laddermill workers``; its help shows the executor's own description
COMMAND = Command("workers", "prepare a node for --workers / --ray (fill numba's cache)",
                  parallel.__doc__.split("\n\n")[0], _warm_arguments, _warm)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
