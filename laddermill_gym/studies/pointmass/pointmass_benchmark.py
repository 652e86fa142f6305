"""Benchmark of the point-mass fidelity (``podgaets_5km``): held memory and peak resident memory, cost per step
and per element of the explicit and the implicit method at 10,000, 100,000 and 500,000 elements on 1 and on all
threads, simulated seconds per wall second, and the implicit method's error against the explicit one over a
short run. ``python -m laddermill_gym.studies.pointmass.pointmass_benchmark [--quick] [--json FILE]``.

Timings are medians of repeated runs from the same state, both methods and thread counts timed in turn within
every repeat (a shared, noisy machine then slows all of them alike); compilation is excluded (warm-up run).
"""

from __future__ import annotations

import argparse
import json
import resource
import statistics
import subprocess
import sys
import time

import numpy as np
from tqdm import tqdm

from laddermill_gym.ladder.pointmass_scene import load_pointmass_scene
from laddermill_gym.model.pointmass import held_bytes, make_work
from laddermill_gym.sim.pointmass import PointMassSimulator, explicit_stable_dt
from laddermill_gym.studies.commands import run_subcommand

SCENE = "podgaets_5km"
#: Element lengths [m] giving 10,000, 100,000 and 500,000 elements on the scene's 5 km.
ELEMENT_LENGTHS = (0.5, 0.05, 0.01)
#: Target of the issue: the implicit method at least this many simulated seconds per wall second at 500,000.
TARGET_REAL_TIME = 0.1
#: Fraction of the explicit method's stability limit used as its step.
EXPLICIT_SAFETY = 0.9


def _step_cost(sims: dict, steps: dict, repeats: int) -> dict:
    """Median wall time of one step [s] of each simulator (state restored every repeat), timed in turn."""
    start = {k: s.x.copy() for k, s in sims.items()}
    times: dict = {k: [] for k in sims}
    for k, s in sims.items():  # warm-up: compile or load the cache
        s.step(1)
        s.x[:] = start[k]
    for _ in range(repeats):
        for k, s in sims.items():
            s.x[:], s.t = start[k], 0.0
            t0 = time.perf_counter()
            s.step(steps[k])
            times[k].append((time.perf_counter() - t0) / steps[k])
    return {k: statistics.median(v) for k, v in times.items()}


def measure_costs(quick: bool, threads_all: int) -> list[dict]:
    """Cost per step and per element of both methods at every size and thread count."""
    rows = []
    for el in tqdm(ELEMENT_LENGTHS, desc="sizes", unit="size"):
        sc = load_pointmass_scene(SCENE, element_length=el)
        x0, _ = sc.initial_state()
        dt_exp = EXPLICIT_SAFETY * explicit_stable_dt(sc.string)
        sims, steps = {}, {}
        for th in sorted({1, threads_all}):
            sims[("implicit", th)] = PointMassSimulator(sc.string, x0, sc.controls, sc.dt, "implicit", threads=th)
            sims[("explicit", th)] = PointMassSimulator(sc.string, x0, sc.controls, dt_exp, "explicit", threads=th)
            n_run = max(2, int(2e6 / sc.string.n_nodes)) if not quick else 2
            steps[("implicit", th)] = steps[("explicit", th)] = n_run
        cost = _step_cost(sims, steps, 3 if quick else 5)
        held = sims[("implicit", 1)].held_bytes()["total"]
        for (meth, th), c in cost.items():
            dt = sc.dt if meth == "implicit" else dt_exp
            rows.append({"elements": sc.string.n_elements, "element_length_m": el, "method": meth, "threads": th,
                         "dt_s": dt, "step_s": c, "ns_per_element": 1e9 * c / sc.string.n_elements,
                         "real_time_factor": dt / c, "held_MB": held / 1e6})
    return rows


def thread_scaling(threads: tuple[int, ...], element_length: float = 0.01, repeats: int = 5) -> list[dict]:
    """Step time of both methods at ``element_length`` on each thread count (speed-up against one thread)."""
    sc = load_pointmass_scene(SCENE, element_length=element_length)
    x0, _ = sc.initial_state()
    dt_exp = EXPLICIT_SAFETY * explicit_stable_dt(sc.string)
    sims = {}
    for th in threads:
        sims[("implicit", th)] = PointMassSimulator(sc.string, x0, sc.controls, sc.dt, "implicit", threads=th)
        sims[("explicit", th)] = PointMassSimulator(sc.string, x0, sc.controls, dt_exp, "explicit", threads=th)
    n_run = max(2, int(2e6 / sc.string.n_nodes))
    cost = _step_cost(sims, {k: n_run for k in sims}, repeats)
    rows = []
    for (meth, th), c in cost.items():
        rows.append({"elements": sc.string.n_elements, "method": meth, "threads": th, "step_s": c,
                     "speedup": cost[(meth, threads[0])] / c,
                     "real_time_factor": (sc.dt if meth == "implicit" else dt_exp) / c})
        print(f"{sc.string.n_elements:9d} {meth:>9} {th:4d} threads: step {1e3 * c:9.3f} ms, speed-up "
              f"{rows[-1]['speedup']:5.2f}, {rows[-1]['real_time_factor']:.3g} x real time", flush=True)
    return rows


def implicit_error(quick: bool, element_length: float = 0.5) -> list[dict]:
    """The implicit method at several steps against the explicit one (its stable step) over a short run from
    the quasi-static start: largest kite-position difference [m] at the end, and the kites' largest travel."""
    sc = load_pointmass_scene(SCENE, element_length=element_length)
    x0, _ = sc.initial_state()
    duration = 0.05 if quick else 0.2
    ref = PointMassSimulator(sc.string, x0, sc.controls, EXPLICIT_SAFETY * explicit_stable_dt(sc.string), "explicit",
                             threads=1)  # one thread: on a loaded machine 10,000 nodes run faster without a pool
    ref.advance(duration, chunk=1000, progress=True)
    kn = sc.string.kite_nodes
    travel = float(np.max(np.linalg.norm(ref.positions[kn] - x0.reshape(-1, 6)[kn, :3], axis=1)))
    out = []
    for dt in (0.01, 0.001, 0.0001):
        sim = PointMassSimulator(sc.string, x0, sc.controls, dt, "implicit")
        sim.advance(duration, chunk=1000)
        err = float(np.max(np.linalg.norm(sim.positions[kn] - ref.positions[kn], axis=1)))
        node_err = float(np.max(np.linalg.norm(sim.positions - ref.positions, axis=1)))
        out.append({"elements": sc.string.n_elements, "duration_s": duration, "dt_s": dt, "explicit_dt_s": ref.dt,
                    "kite_error_m": err, "node_error_m": node_err, "kite_travel_m": travel})
    return out


def rss_probe(steps: int = 20) -> float:
    """Peak resident memory [MB] of this process after loading ``podgaets_5km``, building its quasi-static start
    and running ``steps`` implicit steps (run in a fresh process by :func:`peak_rss_of_scene`)."""
    sc = load_pointmass_scene(SCENE)
    sim = sc.simulator()
    sim.step(steps)
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: KiB


def peak_rss_of_scene() -> float:
    """Peak resident memory [MB] of a fresh Python process that runs the scene (:func:`rss_probe`)."""
    code = "from laddermill_gym.studies.pointmass.pointmass_benchmark import rss_probe; print(rss_probe())"
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True)
    return float(out.stdout.strip().splitlines()[-1])


def run_pointmass_benchmark(quick: bool = False, json_path: str | None = None) -> dict:
    """Measure and print; returns the results (also written to ``json_path`` when given)."""
    import numba

    threads = numba.config.NUMBA_NUM_THREADS
    rows = measure_costs(quick, threads)
    errs = implicit_error(quick)
    peak = peak_rss_of_scene()
    big = [r for r in rows if r["elements"] == 500_000]
    sc = load_pointmass_scene(SCENE)
    sim = PointMassSimulator(sc.string, np.zeros(sc.string.state_size), sc.controls, sc.dt, "implicit")
    held = sim.held_bytes()
    print(f"\npoint-mass fidelity, scene {SCENE}: {sc.string.n_elements} elements, {sc.string.n_kites} kites")
    print("held arrays [MB]: " + ", ".join(f"{k} {v / 1e6:.2f}" for k, v in held.items())
          + "   (budget 40 MB; Podgaets & Ockels: 82 MB for the whole program)")
    room = {p: held_bytes(sim.M, make_work(sc.string, parts=p), sim.x, sim.u)["total"] / 1e6 for p in (16, 128)}
    print("held in all with a workspace for 16 / 128 chunks [MB]: " + " / ".join(f"{v:.2f}" for v in room.values()))
    print(f"peak resident memory of a process that runs the scene: {peak:.0f} MB (Python, numpy, scipy, numba with "
          "its compiled code, the quasi-static start's temporaries)")
    print(f"\n{'elements':>9} {'method':>9} {'thr':>4} {'dt [s]':>10} {'step [ms]':>10} {'ns/elem':>8} "
          f"{'x real time':>12}")
    for r in rows:
        print(f"{r['elements']:9d} {r['method']:>9} {r['threads']:4d} {r['dt_s']:10.3g} {1e3 * r['step_s']:10.3f} "
              f"{r['ns_per_element']:8.1f} {r['real_time_factor']:12.3g}")
    for meth in ("implicit", "explicit"):
        for th in sorted({1, threads}):
            ns = [r["ns_per_element"] for r in rows if r["method"] == meth and r["threads"] == th]
            print(f"{meth}, {th} thread(s): per-element cost max/min over sizes = {max(ns) / min(ns):.2f}")
    imp = [r for r in big if r["method"] == "implicit"]
    per = {r["threads"]: r["real_time_factor"] for r in imp}  # a thread count's own figure, not only the best
    print("implicit at 500,000 elements: " + ", ".join(f"{v:.3g} x real time on {k} thread(s)" for k, v in
                                                      sorted(per.items())) + f" (target {TARGET_REAL_TIME})")
    print(f"\nimplicit vs explicit over {errs[0]['duration_s']} s ({errs[0]['elements']} elements, explicit dt "
          f"{errs[0]['explicit_dt_s']:.3g} s, kites travel up to {errs[0]['kite_travel_m']:.3g} m):")
    for e in errs:
        print(f"  dt {e['dt_s']:8.0e} s: kite position error {e['kite_error_m']:.3e} m, "
              f"any node {e['node_error_m']:.3e} m")
    out = {"scene": SCENE, "threads": threads, "held_bytes": held, "peak_rss_MB": peak, "costs": rows,
           "implicit_error": errs, "target_real_time": TARGET_REAL_TIME}
    if json_path:
        with open(json_path, "w", encoding="utf-8") as fh:
            json.dump(out, fh, indent=1)
    return out


def _run(args) -> int:
    if args.scaling:
        import numba

        from laddermill_gym.studies.commands import UsageError

        pool = numba.config.NUMBA_NUM_THREADS  # a count above it would run on the pool's threads, mislabelled
        bad = [k for k in args.scaling if not 1 <= k <= pool]
        if bad:
            raise UsageError(f"--scaling {bad[0]}: must be a thread count from 1 to the pool's {pool} "
                             "(NUMBA_NUM_THREADS or the cpu count)")
        rows = thread_scaling(tuple(dict.fromkeys(args.scaling)))
        if args.json:
            with open(args.json, "w", encoding="utf-8") as fh:
                json.dump(rows, fh, indent=1)
    else:
        run_pointmass_benchmark(args.quick, args.json)
    return 0


def add_parser(sub) -> argparse.ArgumentParser:
    """``laddermill bench-pointmass``-style subcommand (the lead wires it into ``laddermill bench``)."""
    p = sub.add_parser("bench-pointmass", help="point-mass fidelity: memory, per-element cost, real-time factor")
    p.add_argument("--quick", action="store_true", help="fewer repeats and a shorter error run")
    p.add_argument("--json", default=None, help="also write the results to this JSON file")
    p.add_argument("--scaling", type=int, nargs="+", default=None, metavar="THREADS",
                   help="only the thread scaling at 500,000 elements on these thread counts (e.g. 1 2 4 8 16)")
    p.set_defaults(func=_run)
    return p


def main(argv=None) -> int:
    return run_subcommand(add_parser, "bench-pointmass", argv,
                          prog="python -m laddermill_gym.studies.pointmass.pointmass_benchmark", dest="command")


if __name__ == "__main__":
    raise SystemExit(main())
