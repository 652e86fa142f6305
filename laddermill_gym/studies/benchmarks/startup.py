"""Start-up time of the environments (``laddermill bench --startup``, issue 32 point 1): a fresh Python process that
imports gymnasium and the package, makes an env, resets it and takes one step, timed with empty caches
(cold: every kernel compiled and LadderMill's operating point computed; ``NUMBA_CACHE_DIR`` and
``LADDERMILL_CACHE_DIR`` in a new temporary folder) and again with the caches that run left (warm: every kernel
and operating point loaded from them).

Each measurement is its own subprocess (``python -c`` :data:`CHILD`), timed three ways: from its launch to its first
step done (the wall clock the child reads after the step against the one read before the launch: the interpreter's
start, the imports, make, reset and step; what the targets judge), the whole process (its interpreter's shutdown
too, which in a warm start is about a quarter of a second of CPython collecting the objects numba's typing registries
made) and from the inside (the imports to the first step); the child
also counts the functions numba compiled (``numba.core.event``), so a warm start that compiles anything shows it.
``--profile`` (``python -m laddermill_gym.studies.benchmarks.startup --profile --envs ID``) takes one cold start
with every compile timed (:data:`PROFILE_CHILD`) and prints where the seconds go, phase by phase (make, which
computes the mill's operating point, reset, step) and function by function, then a timeline of what each process
compiled when: the process itself and its kernel warm-up processes (``envs/compile_trace.py``).
Machines are shared and noisy: the warm start is the median of a few runs; ``--cold-runs N`` takes N cold starts,
each from empty caches, and prints their median and range; compare cold starts taken in the same period. The
targets are issue 32's: TetheredWing-v0 and Rotorcraft-v0 at most 20 s cold and 1 s warm, LadderMill-v0 (its
operating point included) at most 60 s cold.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from laddermill_gym.envs import compile_trace
from laddermill_gym.envs.laddermill.op_cache import CACHE_VARIABLE

#: env id -> (cold target [s], warm target [s] or None): issue 32, point 1
TARGETS: dict[str, tuple[float, float | None]] = {
    "laddermill_gym/TetheredWing-v0": (20.0, 1.0),
    "laddermill_gym/Rotorcraft-v0": (20.0, 1.0),
    "laddermill_gym/LadderMill-v0": (60.0, None),
}
#: the envs with a warm-start target: ``--quick`` times these warm only
QUICK_ENVS = ("laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0")
#: warm starts per env (median)
WARM_REPEATS = 3


#: what the fresh process runs (``python -c``), its clock started before any import: make (``{make}``: the single
#: env, or the native vector env of ``--copies``, :func:`make_call`) + reset (seed 0) + one step with the zero
#: action; prints the seconds, the process's CPU time (user + system: less sensitive than the wall time to other
#: work on a shared machine), the number of functions numba compiled and the cache it used
CHILD = """import time
t0 = time.perf_counter()
import json
from numba.core import event
compiled = []
class Count(event.Listener):
    def on_start(self, ev):
        compiled.append(1)
    def on_end(self, ev):
        pass
event.register("numba:compile", Count())
import gymnasium
import numpy as np
import laddermill_gym
env = {make}
env.reset(seed=0)
env.step(np.zeros(env.action_space.shape, dtype=env.action_space.dtype))
stepped = time.time()
seconds = time.perf_counter() - t0
import resource
use = resource.getrusage(resource.RUSAGE_SELF)
kids = resource.getrusage(resource.RUSAGE_CHILDREN)
env.close()
from numba.core.config import CACHE_DIR
print(json.dumps({{"inside_s": seconds, "cpu_s": use.ru_utime + use.ru_stime, "compiled": len(compiled),
                  "cpu_children_s": kids.ru_utime + kids.ru_stime, "cache_dir": CACHE_DIR, "stepped": stepped}}))
"""


#: ``--profile``: the fresh process times every function numba compiles (``numba:compile`` events, nested: a
#: kernel's compile includes its callees'), so each row has its own seconds (self: the total less the callees
#: compiled inside it, i.e. its typing, lowering and the LLVM optimisation and code generation of its library,
#: into which numba links every callee's code again), in wall and in CPU seconds of the process (the compile runs
#: on one thread: CPU seconds are what a loaded machine does not inflate), and the phase (make, reset, step)
PROFILE_CHILD = """import time
t0 = time.perf_counter()
epoch0 = time.time()
import json
from numba.core import event
stack, rows, phase = [], [], ["import"]
class Tree(event.Listener):
    def on_start(self, ev):
        f = ev.data["dispatcher"].py_func
        row = {{"name": f.__module__ + "." + f.__qualname__, "depth": len(stack), "phase": phase[0],
               "start": time.perf_counter(), "inner": 0.0, "cpu_start": time.process_time(), "cpu_inner": 0.0}}
        row["at"] = time.time()
        rows.append(row)
        stack.append(row)
    def on_end(self, ev):
        row = stack.pop()
        row["total_s"] = time.perf_counter() - row.pop("start")
        row["self_s"] = row["total_s"] - row.pop("inner")
        row["total_cpu_s"] = time.process_time() - row.pop("cpu_start")
        row["self_cpu_s"] = row["total_cpu_s"] - row.pop("cpu_inner")
        if stack:
            stack[-1]["inner"] += row["total_s"]
            stack[-1]["cpu_inner"] += row["total_cpu_s"]
event.register("numba:compile", Tree())
import gymnasium
import numpy as np
import laddermill_gym
phases = {{}}
def mark(name):
    phases[phase[0]] = time.process_time() - phases.get("_at", 0.0)
    phases["_at"] = time.process_time()
    phase[0] = name
mark("make")
env = gymnasium.make({env_id!r})
mark("reset")
env.reset(seed=0)
mark("step")
env.step(np.zeros(env.action_space.shape, dtype=env.action_space.dtype))
mark("end")
del phases["_at"]
seconds = time.perf_counter() - t0
import resource
use = resource.getrusage(resource.RUSAGE_SELF)
kids = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({{"inside_s": seconds, "cpu_s": use.ru_utime + use.ru_stime, "rows": rows, "phases": phases,
                  "cpu_children_s": kids.ru_utime + kids.ru_stime, "epoch0": epoch0}}))
"""


def profile(env_id: str, top: int = 25, echo=print) -> dict:
    """One cold start of ``env_id`` (new, empty numba and operating-point caches) with every compile timed: prints
    the functions with the most seconds of their own and the seconds per phase; returns the child's figures."""
    with tempfile.TemporaryDirectory(prefix="laddermill_numba_") as tmp:
        trace = os.path.join(tmp, "compile_trace")
        os.makedirs(trace)
        res = run_child(env_id, tmp, PROFILE_CHILD, {compile_trace.VARIABLE: trace})
        res["warmups"] = compile_trace.read(trace)
    rows = res["rows"]
    cpu = res["phases"]
    echo(f"== compile profile {env_id}: cold start {res['wall_s']:.1f} s (inside {res['inside_s']:.1f} s, CPU "
         f"{res['cpu_s']:.1f} s{_children(res)}), {len(rows)} functions compiled")
    for ph in ("import", "make", "reset", "step"):
        sel = [r for r in rows if r["phase"] == ph]
        if sel or ph in cpu:
            echo(f"  {ph:6s} {cpu.get(ph, 0.0):7.1f} s CPU, of which {sum(r['self_cpu_s'] for r in sel):.1f} s "
                 f"compiling ({len(sel)} functions; {sum(r['self_s'] for r in sel):.1f} s wall)")
    echo(f"  {'self CPU [s]':>12s} {'total CPU [s]':>13s} {'self wall [s]':>13s}  phase  function (nesting depth)")
    for r in sorted(rows, key=lambda r: -r["self_cpu_s"])[:top]:
        echo(f"  {r['self_cpu_s']:12.2f} {r['total_cpu_s']:13.2f} {r['self_s']:13.2f}  {r['phase']:5s}  {r['name']} "
             f"({r['depth']})")
    timeline(res, echo)
    return res


def timeline(res: dict, echo=print) -> None:
    """Print when each process of a profiled cold start compiled its top-level functions (their callees inside),
    in seconds from the start-up's first line: the process itself (its rows of nesting depth 0) and each kernel
    warm-up process (``envs/compile_trace.py``), so the seconds a core waits show."""
    t0 = res["epoch0"]
    procs = [("this process", [{"name": r["name"], "start": r["at"], "end": r["at"] + r["total_s"]}
                               for r in res["rows"] if r["depth"] == 0])]
    procs += [(f"warm-up {t['label'].rpartition(':')[2]} (pid {t['pid']})", t["rows"]) for t in res["warmups"]]
    echo("  timeline [s from the start]: top-level compiles of each process (callees inside)")
    for label, rows in procs:
        if not rows:
            continue
        busy = sum(r["end"] - r["start"] for r in rows)
        echo(f"    {label}: {rows[0]['start'] - t0:.1f} to {rows[-1]['end'] - t0:.1f}, compiling {busy:.1f} s")
        for r in rows:
            if r["end"] - r["start"] >= 0.5:
                echo(f"      {r['start'] - t0:6.1f} -> {r['end'] - t0:6.1f}  {r['name']}")


def make_call(env_id: str, copies: int | None = None) -> str:
    """The Python expression that makes ``env_id``: ``gymnasium.make``, or with ``copies`` its native vector env of
    that many copies (``gymnasium.make_vec``, ``vector_entry_point``: the one an RL run steps)."""
    if copies is None:
        return f"gymnasium.make({env_id!r})"
    if isinstance(copies, bool) or not isinstance(copies, int) or copies < 1:
        raise ValueError(f"copies = {copies!r}: must be a whole number >= 1")
    return f"gymnasium.make_vec({env_id!r}, {copies}, vectorization_mode='vector_entry_point')"


def run_child(env_id: str, cache_dir: str | None, child: str = CHILD, extra_env: dict | None = None,
              copies: int | None = None) -> dict:
    """One start-up of ``env_id`` (with ``copies``: its native vector env, :func:`make_call`) in a fresh subprocess
    with ``NUMBA_CACHE_DIR`` = ``cache_dir`` and the mill's operating-point cache (``LADDERMILL_CACHE_DIR``,
    ``envs/laddermill/op_cache.py``) in its ``laddermill`` sub-folder (None: this process's environment as it is),
    and ``extra_env`` set: the child's figures plus ``wall_s``, the subprocess's wall time [s]."""
    env = dict(os.environ, **(extra_env or {}))
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = cache_dir
        env[CACHE_VARIABLE] = os.path.join(cache_dir, "laddermill")
    cmd = [sys.executable, "-c", child.format(env_id=env_id, make=make_call(env_id, copies))]
    launched = time.time()
    t0 = time.perf_counter()
    r = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        raise RuntimeError(f"start-up of {env_id} failed (exit {r.returncode}):\n{r.stderr[-2000:]}")
    out = json.loads(r.stdout.strip().splitlines()[-1])
    out["wall_s"] = wall
    if "stepped" in out:  # the wall clock every process shares: the child's first step done, from its launch
        out["first_step_s"] = out.pop("stepped") - launched
    return out


def measure(env_id: str, cold: bool = True, warm_repeats: int = WARM_REPEATS, copies: int | None = None,
            cold_runs: int = 1) -> dict:
    """Cold starts (each with new, empty numba and operating-point caches; ``cold_runs`` of them, summarised by
    :func:`summarise`) and the median of ``warm_repeats`` warm starts from the caches the last one left; with ``cold``
    False, warm starts only, from the caches this process's environment names; ``copies``: of the native vector env
    (:func:`make_call`)."""
    res: dict = {"env": env_id, "copies": copies}
    n = cold_runs if cold else 1
    colds, runs = [], []
    for i in range(n):
        with tempfile.TemporaryDirectory(prefix="laddermill_numba_") as tmp:
            cache = tmp if cold else None
            if cold:
                colds.append(run_child(env_id, cache, copies=copies))
            if i == n - 1:  # the warm starts read the caches the last cold start left
                runs = [run_child(env_id, cache, copies=copies) for _ in range(warm_repeats)]
    if colds:
        res["cold"] = summarise(colds)
    res["warm"] = summarise(runs)
    return res


def summarise(runs: list[dict]) -> dict:
    """One row for several starts: the median of each clock and CPU figure (``cpu_children_s`` where the runs
    report it), the most functions any compiled, how many runs, the launch-to-step seconds of each (``all_s``) and
    the first run's cache folder."""
    out = {k: statistics.median(r.get(k, 0.0) for r in runs)
           for k in ("first_step_s", "wall_s", "inside_s", "cpu_s", "cpu_children_s")}
    out.update(compiled=max(r["compiled"] for r in runs), runs=len(runs), all_s=[r["first_step_s"] for r in runs],
               cache_dir=runs[0]["cache_dir"])
    return out


def _children(res: dict) -> str:
    """The CPU seconds of the start's own subprocesses (LadderMill's kernel warm-up,
    ``envs/laddermill/kernel_warmup.py``), when it had any."""
    kids = res.get("cpu_children_s", 0.0)
    return f" + {kids:.1f} s in a second process" if kids > 0.05 else ""


def _verdict(seconds: float, target: float | None) -> str:
    if target is None:
        return ""
    return f"(target {target:g} s: {'met' if seconds <= target else 'NOT met'})"


def report(res: dict, echo=print) -> None:
    """Print one env's figures: the seconds from the process's launch to its first step done (what the targets
    judge), then the whole process's (its interpreter's shutdown included), the imports-to-step seconds the process
    counted itself and its CPU seconds."""
    cold_t, warm_t = TARGETS.get(res["env"], (None, None))
    copies = res.get("copies")
    made = "make" if copies is None else f"make_vec ({copies} copies)"
    echo(f"== start-up {res['env']}: {made} + reset + one step in a fresh process, from its launch to the step done")
    if "cold" in res:
        c = res["cold"]
        several = f", median of {c['runs']}: {min(c['all_s']):.1f}-{max(c['all_s']):.1f} s" if c["runs"] > 1 else ""
        echo(f"  cold (empty caches)       {c['first_step_s']:7.1f} s  (process {c['wall_s']:.1f} s, inside "
             f"{c['inside_s']:.1f} s, CPU {c['cpu_s']:.1f} s{_children(c)}, {c['compiled']} functions compiled"
             f"{several}) {_verdict(c['first_step_s'], cold_t)}")
    w = res["warm"]
    echo(f"  warm (caches filled)      {w['first_step_s']:7.2f} s  (process {w['wall_s']:.2f} s, inside "
         f"{w['inside_s']:.2f} s, CPU {w['cpu_s']:.2f} s, {w['compiled']} functions compiled, median of {w['runs']}) "
         f"{_verdict(w['first_step_s'], warm_t)}")


def run_startup(quick: bool = False, envs=None, echo=print, copies: int | None = None, cold_runs: int = 1) -> dict:
    """``laddermill bench --startup``: cold and warm start of each of ``envs`` (default: the three of
    :data:`TARGETS`); ``quick``: warm starts only, once each, of :data:`QUICK_ENVS`, from the current cache;
    ``copies``: of the native vector envs of that many copies instead of the single envs; ``cold_runs``: cold
    starts per env, each from empty caches, their median printed with their range (a shared machine's cold starts
    scatter by seconds)."""
    make_call("", copies)  # a bad count is refused before any run
    if isinstance(cold_runs, bool) or not isinstance(cold_runs, int) or cold_runs < 1:
        raise ValueError(f"cold_runs={cold_runs!r}: a whole number of cold starts, at least 1")
    envs = list(envs or (QUICK_ENVS if quick else TARGETS))
    out = {}
    for env_id in envs:
        echo(f"timing the start-up of {env_id} {'(warm only)' if quick else '(cold, then warm)'} ...")
        sys.stdout.flush()
        out[env_id] = measure(env_id, cold=not quick, warm_repeats=1 if quick else WARM_REPEATS, copies=copies,
                              cold_runs=cold_runs)
        report(out[env_id], echo)
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.benchmarks.startup")
    p.add_argument("--quick", action="store_true", help="warm starts only, from the current numba cache")
    p.add_argument("--envs", nargs="*", default=None, help="env ids (default: the three with targets)")
    p.add_argument("--profile", action="store_true",
                   help="one cold start per env with the seconds numba spends compiling each function and a "
                        "timeline of what each process (the kernel warm-ups too) compiled when")
    p.add_argument("--copies", type=int, default=None,
                   help="time the native vector env of this many copies (gymnasium.make_vec) instead of the single env")
    p.add_argument("--cold-runs", type=int, default=1,
                   help="cold starts per env, each from empty caches: their median and range are printed")
    args = p.parse_args(argv)
    if args.copies is not None and args.copies < 1:
        p.error(f"--copies {args.copies}: must be at least 1")
    if args.cold_runs < 1:
        p.error(f"--cold-runs {args.cold_runs}: must be at least 1")
    if args.profile:
        for env_id in args.envs or QUICK_ENVS:
            profile(env_id)
        return 0
    run_startup(args.quick, args.envs, copies=args.copies, cold_runs=args.cold_runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
