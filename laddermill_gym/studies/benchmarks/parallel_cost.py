"""What a worker pays for numba, and what workers gain: cold compile vs cache load vs warm task, and the speed-up.

    python -m laddermill_gym.studies.benchmarks.parallel_cost [--env laddermill_gym/TetheredWing-v0] [--repeats 3]
        [--duration 120] [--controller lqr] [--workers 2] [--part all|cost|speed]
        [--out results/parallel_cost.json]

One task is one gust-benchmark episode set (:func:`laddermill_gym.studies.gusts.gust_bench.episodes_task`: the
open-loop controller, two seeds, a 1 - cos gust, ``--duration`` seconds). Each measurement starts fresh
worker processes (``spawn``) through :func:`laddermill_gym.studies.parallel.run_tasks`, one worker running
two tasks in a row:

* ``cold``: an empty numba cache (a new ``NUMBA_CACHE_DIR``) and no warm-up: the first task compiles every
  kernel it reaches (what every task would pay if each ran in a new process on a node without a cache);
* ``cache``: the cache that run filled, no warm-up: the first task loads the kernels from disk (median of
  ``--repeats`` fresh processes);
* ``warm``: the same cache with the benchmark's per-worker warm-up: its time, then the tasks' times.

Then the end-to-end wall time of the gusts-v1 benchmark on ``--env`` with ``--controller`` serially and with
``--workers`` local workers (pool start, warm-up and all), with the machine's load average before each, and
the pool's fixed cost. Prints a table and writes JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import tempfile
import time
from pathlib import Path

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.parallel import run_tasks, worker_report

GUST = ({"type": "OneMinusCosineGust", "amplitude": 0.3, "duration": 4.0, "time": 1.0,
         "direction_amplitude": 0.05},)  # [-], [s], [s], [rad]: the gusts-v1 short gust


def timed(fn, kwargs: dict) -> dict:
    """A task: run ``fn(**kwargs)`` and return its wall time [s] with :func:`worker_report`."""
    t0 = time.perf_counter()
    fn(**kwargs)
    return dict(worker_report(), task_s=time.perf_counter() - t0)


def _episode(env_id: str, duration: float) -> tuple:
    return (gb.episodes_task, dict(env_id=env_id, env_kwargs={}, spec="open_loop", seeds=(0, 1),
                                   duration=duration, disturbances=GUST))


def _warmup(env_id: str) -> list:
    return [(gb.forget_controllers, {}), (gb.episodes_task, dict(env_id=env_id, env_kwargs={}, spec="open_loop",
                                                                 seeds=(0,), duration=gb.WARMUP_S, disturbances=()))]


def fresh_worker(task, cache: str, warm: list) -> list[dict]:
    """Two timed tasks in one fresh worker process whose caches are under ``cache``: numba's
    (``NUMBA_CACHE_DIR``) and the package's start cache (``LADDERMILL_CACHE_DIR``: trims, splines, operating
    points), so that the first run in a new folder pays what a node without either pays."""
    names = {"NUMBA_CACHE_DIR": cache, "LADDERMILL_CACHE_DIR": os.path.join(cache, "laddermill")}
    old = {k: os.environ.get(k) for k in names}
    os.environ.update(names)
    try:
        return run_tasks([(timed, dict(fn=task[0], kwargs=task[1]))] * 2, workers=1, warmup=warm, progress=False)
    finally:
        for k, v in old.items():
            if v is None:
                del os.environ[k]
            else:
                os.environ[k] = v


def per_worker_cost(env_id: str, duration: float, repeats: int) -> dict:
    """First and second task times [s] with a cold cache, a filled cache and after the warm-up (medians)."""
    task = _episode(env_id, duration)
    with tempfile.TemporaryDirectory(prefix="numba_cold_") as cache:
        cold = fresh_worker(task, cache, [])
        loads = [fresh_worker(task, cache, []) for _ in range(repeats)]
        warms = [fresh_worker(task, cache, _warmup(env_id)) for _ in range(repeats)]
    med = statistics.median
    return {"cold_first_task_s": cold[0]["task_s"], "cold_second_task_s": cold[1]["task_s"],
            "cache_first_task_s": med(r[0]["task_s"] for r in loads),
            "cache_second_task_s": med(r[1]["task_s"] for r in loads),
            "warmup_s": med(r[0]["warmup_s"] for r in warms), "warm_first_task_s": med(r[0]["task_s"] for r in warms),
            "warm_second_task_s": med(r[1]["task_s"] for r in warms)}


def speed_up(env_id: str, controller: str, workers: int, repeats: int) -> dict:
    """End-to-end wall time [s] of gusts-v1 on ``env_id`` with ``controller`` serially and on ``workers``
    local processes (pool start, warm-up and all; medians over ``repeats``, interleaved), the one-minute load
    average before each run, and the fixed cost of a pool: its start with the benchmark's warm-up (wall time
    of one trivial task per worker) and the warm-up alone (median over the workers)."""
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    suite = load_suite("gusts-v1")
    walls: dict[str, list[float]] = {"serial": [], "workers": []}
    loads, start, warm = [], [], []
    for _ in range(repeats):
        for key, n in (("serial", 0), ("workers", workers)):
            loads.append(os.getloadavg()[0])
            t0 = time.perf_counter()
            gb.run_suite(suite, [env_id], [controller], progress=False, workers=n)
            walls[key].append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        reports = run_tasks([(worker_report, {})] * workers, workers=workers,
                            warmup=gb.warmup_tasks(suite, [env_id], [controller]), progress=False)
        start.append(time.perf_counter() - t0)
        warm += [r["warmup_s"] for r in reports]
    s, w = statistics.median(walls["serial"]), statistics.median(walls["workers"])
    return {"suite": "gusts-v1", "controller": controller, "workers": workers, "serial_s": s, "workers_s": w,
            "speed_up": s / w, "pool_start_with_warmup_s": statistics.median(start),
            "warmup_s": statistics.median(warm), "load_avg_1min": loads, "cores": os.cpu_count()}


def main(argv=None) -> dict:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.benchmarks.parallel_cost",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0")
    p.add_argument("--duration", type=float, default=120.0, help="episode length [s]")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--controller", default="lqr", help="controller of the speed-up run")
    p.add_argument("--part", choices=["all", "cost", "speed"], default="all",
                   help="cost: the per-worker compile / load / warm figures; speed: the speed-up; all: both")
    p.add_argument("--out", type=Path, default=Path("results/parallel_cost.json"))
    a = p.parse_args(argv)
    for name in ("duration", "repeats", "workers"):
        if getattr(a, name) <= 0:
            p.error(f"--{name.replace('_', '-')} {getattr(a, name)}: must be > 0")
    res: dict = {"env": a.env, "duration_s": a.duration}
    if a.part in ("all", "cost"):
        res.update(per_worker_cost(a.env, a.duration, a.repeats))
    if a.part in ("all", "speed"):
        res["speed_up"] = speed_up(a.env, a.controller, a.workers, a.repeats)
    for k, v in res.items():
        print(f"{k:>22}: {v:.3f}" if isinstance(v, float) else f"{k:>22}: {v}")
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(json.dumps(res, indent=1))
    print(f"wrote {a.out}")
    return res


if __name__ == "__main__":
    main()
