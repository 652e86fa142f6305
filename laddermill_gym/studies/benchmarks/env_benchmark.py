"""Environment throughput benchmark: env steps per second of the native batched vector env against
Gymnasium's ``SyncVectorEnv`` over single envs, measured in the same run (``laddermill bench-envs``).

Every copy steps with the trim action of the open-loop controller (the work per step does not depend on the
action); copies whose episode ends are reset by the vector envs' autoreset, as in training. Times are medians over
repeats. The native env is the registered ``vector_entry_point`` (``gymnasium.make_vec``), the single envs the
registered entry point, so every environment is measured the same way.
"""

from __future__ import annotations

import json
import os
import time

import gymnasium as gym
import numpy as np

from laddermill_gym.envs import ENTRY_POINTS, ENV_IDS


def thread_cpu_seconds() -> dict[str, float]:
    """CPU seconds (user + system) of each thread of this process by thread id, from Linux's ``/proc/self/task``
    (a clock of its own per thread, not slowed by other work on the machine); empty where there is none."""
    out: dict[str, float] = {}
    tick = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100
    try:
        tasks = os.listdir("/proc/self/task")
    except OSError:
        return out
    for tid in tasks:
        try:
            with open(f"/proc/self/task/{tid}/stat") as fh:
                f = fh.read().rsplit(")", 1)[1].split()
        except OSError:  # a thread that ended meanwhile
            continue
        out[tid] = (int(f[11]) + int(f[12])) / tick  # utime, stime (fields 14, 15 of proc(5))
    return out


def threads_working(before: dict, after: dict) -> float | None:
    """The threads' worth of work between two :func:`thread_cpu_seconds` readings: their CPU seconds over the
    busiest thread's (1.0: one thread did everything; 2.0: two shared it evenly); None without readings. Unlike
    the CPU share it does not fall when other work loads the machine. OpenMP's workers spin briefly after each
    parallel region, which counts a little here."""
    used = [after[k] - before.get(k, 0.0) for k in after]
    top = max(used, default=0.0)
    return sum(used) / top if top > 0 else None


def _steps_per_second(env, action: np.ndarray, n_steps: int, repeats: int) -> tuple[float, float, float | None]:
    """(median env steps per wall second, median CPU seconds of this process per wall second over the repeats:
    about the threads kept busy; well below them on a machine loaded by other work, and
    :func:`threads_working` over all repeats: how many threads shared the work, whatever the load)."""
    env.reset(seed=0)
    env.step(action)  # warm-up
    rates, shares = [], []
    th0 = thread_cpu_seconds()
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        for _ in range(n_steps):
            env.step(action)
        wall = time.perf_counter() - t0
        rates.append(n_steps * env.num_envs / wall)
        shares.append((time.process_time() - c0) / wall)
    return float(np.median(rates)), float(np.median(shares)), threads_working(th0, thread_cpu_seconds())


def bench_vector(env_id: str, counts=(1, 8, 64, 512), quick: bool = False, echo=print,
                 budget: float = 1e6, variants: dict | None = None) -> list[dict]:
    """Steps/s of the native vector env and of SyncVectorEnv for each number of copies. ``budget``: ten times the
    copy-steps of one repeat of the native env at the full setting (a fifth of it with ``quick``; each of the 3 or 5
    repeats runs budget / 10 copy-steps, at least 5 steps); the SyncVectorEnv runs 1 % of it (at least 3 steps).
    ``variants``: label -> env arguments of further native envs measured in the same run (e.g. the registered step
    on one thread, the step ``physics_step="ros34pw2"``), each with its ratio. Each rate comes with its CPU share
    ("cpu": this process's CPU seconds per wall second, about the threads kept busy; on a loaded machine well below
    them, so the wall rates are then the machine's share, not its speed) and each native rate with the threads that
    shared its work ("threads": :func:`threads_working`, whatever the load)."""
    from laddermill_gym.control.factory import make_controller

    kwargs = ENV_IDS[env_id]
    single = gym.envs.registration.load_env_creator(ENTRY_POINTS[env_id][0])
    per_repeat = budget / 5 if quick else budget  # copy-steps per repeat for the native env
    rows = []
    for n in counts:
        rates, shares, threads = {}, {}, {}
        for label, extra in {"native": {}, **(variants or {})}.items():
            native = gym.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **extra)
            obs, _ = native.reset(seed=0)
            act = np.asarray(make_controller("open_loop", env_id).predict(obs)[0], dtype=np.float32)
            n_steps = max(5, int(per_repeat / n) // 10)
            rates[label], shares[label], threads[label] = _steps_per_second(native, act, n_steps, 3 if quick else 5)
            native.close()
        sync = gym.vector.SyncVectorEnv([lambda: single(**kwargs) for _ in range(n)])
        sync_rate, sync_share, _ = _steps_per_second(sync, act, max(3, int(budget / 100 / (5 if quick else 1) / n)), 3)
        sync.close()
        native_rate = rates.pop("native")
        row = {"env": env_id, "copies": n, "native_steps_per_s": native_rate, "sync_steps_per_s": sync_rate,
               "ratio": native_rate / sync_rate, "native_cpu_share": shares.pop("native"), "sync_cpu_share": sync_share,
               "native_threads": threads.pop("native")}
        if rates:
            row["variants"] = {k: {"steps_per_s": v, "ratio": v / sync_rate, "cpu_share": shares[k],
                                   "threads": threads[k]} for k, v in rates.items()}
        extra_text = "".join(f"   {k} {v:10,.0f} ({v / sync_rate:.1f}x; cpu {shares[k]:.2f}{_th(threads[k])})"
                             for k, v in rates.items())
        echo(f"  {n:5d} copies: native {native_rate:12,.0f} steps/s (cpu {row['native_cpu_share']:.2f}"
             f"{_th(row['native_threads'])}){extra_text}   "
             f"SyncVectorEnv {sync_rate:10,.0f} steps/s (cpu {sync_share:.2f})   ratio {row['ratio']:7.1f}x")
        rows.append(row)
    return rows


def _th(threads: float | None) -> str:
    return "" if threads is None else f", threads {threads:.2f}"


#: the further native envs of the 101-wing envs' rows (issue 32 point 3): the registered step on one thread (the
#: default at 8 copies before the 101-wing models stepped on the thread pool from 2 copies), one ROS34PW2 step
#: per control period (``physics_step``, ``envs/physics_step.py``) and one ROS2 step per period with its iteration
#: matrix kept for 4 steps (``jacobian_every``: the fastest step within 1e-3 of the extent that runs the whole
#: short episode on the chain and on LadderMill-v2, docs/benchmarks.md), all measured in the same run
FAST_101 = {"one-thread": {"parallel": False}, "ros34pw2": {"physics_step": "ros34pw2"},
            "ros2": {"physics_step": "ros2"}, "ros2:4": {"physics_step": "ros2", "jacobian_every": 4}}
#: the 101-wing envs' options: copy-steps per repeat (about a second of native stepping at 8 copies) and the variants
_OPTS_101 = {"quick": True, "budget": 5e4, "variants": FAST_101}
#: the ids that register a faster step (LadderMill-v3: ROS2, LadderChain-v1: RK4 at 1/60 s): their registered step
#: on one thread too
_OPTS_FAST = {"quick": True, "budget": 5e4, "variants": {"one-thread": {"parallel": False}}}


#: the envs of the benchmark: short name -> (env id, what it is, copy counts, SyncVectorEnv-budget options)
ENVS: dict[str, tuple] = {
    "TetheredWing-v0": ("laddermill_gym/TetheredWing-v0", "20 Hz control", (1, 8, 64, 512), {}),
    "TetheredWing-v1": ("laddermill_gym/TetheredWing-v1",
                        "TetheredWing-v0 with two RK4 steps of 25 ms per 20 Hz period", (1, 8, 64, 512), {}),
    "LadderChain-v0": ("laddermill_gym/LadderChain-v0", "101 wings, four RK4 steps of 12.5 ms per 20 Hz period", (1, 8),
                       _OPTS_101),
    "LadderChain-v1": ("laddermill_gym/LadderChain-v1",
                       "LadderChain-v0 with three RK4 steps of 1/60 s per 20 Hz period", (1, 8), _OPTS_FAST),
    "Rotorcraft-v0": ("laddermill_gym/Rotorcraft-v0", "one ROS34PW2 step of 50 ms per 20 Hz control period",
                      (1, 16, 64), {"budget": 5e4}),
    "LadderMill-v0": ("laddermill_gym/LadderMill-v0", "101 wings on the moving cable, 20 Hz control", (1, 8),
                      {"quick": True, "budget": 2e4}),
    "LadderMill-v1": ("laddermill_gym/LadderMill-v1",
                      "101 v1 wings on the moving cable (ppo_mill's env), five RK4 steps of 10 ms per 20 Hz period",
                      (1, 8), _OPTS_101),
    "LadderMill-v2": ("laddermill_gym/LadderMill-v2",
                      "101 v2 wings on the moving cable, five RK4 steps of 10 ms per 20 Hz period", (1, 8), _OPTS_101),
    "LadderMill-v3": ("laddermill_gym/LadderMill-v3", "LadderMill-v2 with one ROS2 step per 20 Hz period", (1, 8),
                      _OPTS_FAST),
    "PointMassChain-v0": ("laddermill_gym/PointMassChain-v0",
                          "101 point-mass kites, 2 implicit steps of 25 ms per 20 Hz period", (1, 8, 64),
                          {"budget": 5e4}),
}
#: the envs whose task steps its copies without numba's copy threads (``envs/copy_threads.py``): no --threads
THREADLESS = ("PointMassChain-v0",)
#: the result keys of the JSON file (as before the options came)
_KEYS = {"TetheredWing-v0": "tethered_wing", "LadderChain-v0": "ladder_chain", "Rotorcraft-v0": "rotorcraft",
         "LadderMill-v0": "laddermill", "PointMassChain-v0": "pointmass_chain", "LadderMill-v2": "laddermill_v2",
         "LadderMill-v1": "laddermill_v1", "LadderMill-v3": "laddermill_v3", "LadderChain-v1": "ladder_chain_v1",
         "TetheredWing-v1": "tethered_wing_v1"}


def run_env_benchmark(quick: bool = False, json_path: str | None = None, echo=print, envs=None,
                      copies=None) -> dict:
    """The env benchmark: every env of :data:`ENVS` (or those named in ``envs``) at its copy counts (``copies``:
    these counts for every env instead); the LadderMill ids compute their operating points (30-140 s) once, or read
    them from the on-disk cache (``envs/laddermill/op_cache.py``)."""
    threads = os.environ.get("NUMBA_NUM_THREADS", "default")
    echo(f"Environment throughput (medians; numba threads: {threads}; cpus: {os.cpu_count()})")
    res = {"cpus": os.cpu_count(), "numba_threads": threads}
    for name in envs or ENVS:
        env_id, what, counts, opts = ENVS[name]
        echo(f"{env_id} ({what}):")
        opts = dict(opts, quick=opts.get("quick", False) or quick)
        res[_KEYS[name]] = bench_vector(env_id, counts=tuple(copies or counts), echo=echo, **opts)
    if json_path:
        with open(json_path, "w") as fh:
            json.dump(res, fh, indent=2)
        echo(f"figures written to {json_path}")
    return res


def bench_envs_command(args) -> int:
    """``laddermill bench-envs``: :func:`run_env_benchmark`, or :func:`thread_scaling` with ``--threads`` (at the
    largest ``--copies``, default 512); UsageError for an env name not in :data:`ENVS` or a count below 1."""
    from pathlib import Path

    from laddermill_gym.studies.commands import UsageError

    for name in ("copies", "threads"):
        bad = [v for v in getattr(args, name) or [] if v < 1]
        if bad:
            raise UsageError(f"--{name} = {bad[0]}: must be a positive integer")
    unknown = [e for e in args.envs or [] if e not in ENVS]
    if unknown:
        raise UsageError(f"--envs = {unknown[0]!r}: not one of {', '.join(ENVS)}")
    unthreaded = [e for e in args.envs or [] if e in THREADLESS]
    if args.threads and unthreaded:
        raise UsageError(f"--threads with --envs {unthreaded[0]}: its task has no copies on numba's threads to "
                         "scale (the point-mass string's threads are its solve's: docs/pointmass.md)")
    if not args.threads:
        try:
            run_env_benchmark(quick=args.quick, json_path=args.json, envs=args.envs, copies=args.copies)
        except ValueError as err:  # the batch's memory check (sim/batch.py) on a --copies count: no traceback
            if not str(err).startswith("n_copies = "):
                raise
            raise UsageError(f"--copies {args.copies}: {err}") from None
        return 0
    import numba

    if min(args.threads) > numba.config.NUMBA_NUM_THREADS:  # every count left out: nothing would be measured
        raise UsageError(f"--threads {args.threads}: every count is above the pool's "
                         f"{numba.config.NUMBA_NUM_THREADS} threads (NUMBA_NUM_THREADS or the cpu count)")
    res = thread_scaling(args.threads, envs=args.envs, copies=max(args.copies or [512]), quick=args.quick)
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2))
        print(f"wrote {args.json}")
    return 0


def serial_share(env, action: np.ndarray, n_steps: int) -> float:
    """The share of a native vector step's CPU time spent outside the task's compiled step kernel (``task._kernel``:
    physics and observation, parallel over copies), measured over ``n_steps`` steps on the current numba thread
    count (one thread: Amdahl's serial part s; the speed-up on p threads is then at most 1 / (s + (1 - s) / p))."""
    task = env.task
    inner, spent = task._kernel, [0.0]

    def timed(*args):
        c = time.process_time()
        inner(*args)
        spent[0] += time.process_time() - c

    task._kernel = timed
    try:
        c0 = time.process_time()
        for _ in range(n_steps):
            env.step(action)
        total = time.process_time() - c0
    finally:
        task._kernel = inner
    return 1.0 - spent[0] / total if total > 0 else 0.0


def thread_scaling(thread_counts, envs=None, copies: int = 512, quick: bool = False, echo=print) -> dict:
    """Steps/s of the native vector env of each env in ``envs`` (default TetheredWing-v0 and Rotorcraft-v0) at
    ``copies`` copies for each numba thread count of ``thread_counts`` (``numba.set_num_threads`` in this process;
    a count above the pool's size, NUMBA_NUM_THREADS or the cpu count, is left out with a note), and the speed-up
    over the first count; on two threads or more also the same env with its copies on Python threads instead of
    numba's (``envs/copy_threads.py``: what a process forked after GNU OpenMP runs; the vector envs' only way until
    2026-12-04), measured right after it; then the serial share of a step on one thread (:func:`serial_share`) and
    Amdahl's bound it puts on the speed-up at 16 threads (the issue's many-core target; a machine's memory
    bandwidth and the copies' imbalance lower it further)."""
    import numba

    pool = numba.config.NUMBA_NUM_THREADS
    counts = [k for k in thread_counts if 1 <= k <= pool]
    if len(counts) < len(thread_counts):
        echo(f"note: thread counts above the pool's {pool} threads (NUMBA_NUM_THREADS or the cpu count) left out")
    res = {"cpus": os.cpu_count(), "pool": pool, "copies": copies}
    names = list(envs or ("TetheredWing-v0", "Rotorcraft-v0"))
    natives = {name: gym.make_vec(ENVS[name][0], num_envs=copies, vectorization_mode="vector_entry_point")
               for name in names}
    serial = [ENVS[n][0] for n in names if not getattr(natives[n].task, "parallel", False)]
    if max(counts) > 1 and serial:  # one thread whatever numba's count: refused before any env is measured
        from laddermill_gym.studies.commands import UsageError

        for native in natives.values():
            native.close()
        raise UsageError(f"--threads at --copies {copies}: {', '.join(serial)} steps so few copies on one thread (its "
                         "task takes several threads from envs/task_base.PARALLEL_COPIES copies, or 2 for a model of "
                         "PARALLEL_STATE_SIZE states), so no thread count would change it")
    for name in names:
        env_id, native = ENVS[name][0], natives[name]
        obs, _ = native.reset(seed=0)
        from laddermill_gym.control.factory import make_controller

        act = np.asarray(make_controller("open_loop", env_id).predict(obs)[0], dtype=np.float32)
        runner = native.task._kernel
        launcher = getattr(runner, "launcher", None)
        echo(f"{env_id} at {copies} copies:")
        rows = []
        n_steps = max(5, int((2e5 if quick else 1e6) / copies) // 10)  # the bench_vector budget per repeat
        for k in counts:
            numba.set_num_threads(k)
            rate, _, _ = _steps_per_second(native, act, n_steps, 3 if quick else 5)
            row = {"threads": k, "steps_per_s": rate, "speedup": rate / rows[0]["steps_per_s"] if rows else 1.0}
            text = f"  {k:3d} threads: {rate:12,.0f} steps/s   speed-up {row['speedup']:5.2f}x"
            if launcher is not None and k > 1:
                runner.launcher = None  # the copies on Python threads
                try:
                    py_rate, _, _ = _steps_per_second(native, act, n_steps, 3 if quick else 5)
                finally:
                    runner.launcher = launcher
                row["python_threads_steps_per_s"] = py_rate
                row["python_threads_speedup"] = py_rate / rows[0]["steps_per_s"]
                text += f"   (Python threads {py_rate:12,.0f}, {row['python_threads_speedup']:5.2f}x)"
            rows.append(row)
            echo(text)
        numba.set_num_threads(1)
        share = serial_share(native, act, n_steps)
        bound = 1.0 / (share + (1.0 - share) / 16)
        echo(f"  serial share on one thread {share:.1%} (CPU outside the compiled step kernel): Amdahl's bound at 16 "
             f"threads {bound:.1f}x")
        native.close()
        numba.set_num_threads(pool)
        res[_KEYS[name]] = rows
        res[_KEYS[name] + "_serial_share"] = share
    return res
