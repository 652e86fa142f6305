"""The benchmark behind ``laddermill bench``: speed, stability limit, memory and start-up of the scenes,
with ratios against baselines measured in the same run (the numpy reference, switched-off fidelity,
the wing count). Prints a table; ``--json FILE`` writes the figures.

Times are medians of repeated runs after compilation, one thread. Machines are shared and noisy:
compare the ratios, not the absolute numbers.
"""

from __future__ import annotations

import dataclasses
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from numba import njit

from laddermill_gym.kernels.contract import B3_RATE, B3_SIZE, B3_VEL, CTRL_ELEVATOR, N_CONTROLS
from laddermill_gym.kernels.integrate import rhs as rhs_kernel
from laddermill_gym.kernels.integrate import rk4_advance
from laddermill_gym.sim.simulator import SimulationError, Simulator


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def _rhs_loop(n, t, x, u, dx, M, W):
    s = 0
    for _ in range(n):
        s += rhs_kernel(t, x, u, dx, M, W)
    return s


def median_time(fn, repeats: int) -> float:
    """Median wall time [s] of ``repeats`` calls of ``fn``."""
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _rhs_runner(sim: Simulator, n: int):
    """A compiled, warmed-up loop of n right-hand sides of ``sim`` at its state."""
    x = sim.state.copy()
    dx = np.zeros_like(x)
    args = (0.0, x, sim.controls, dx, sim.model, sim.work)
    _rhs_loop(1, *args)
    return lambda: _rhs_loop(n, *args)


def time_rhs(sim: Simulator, n: int, repeats: int) -> float:
    """Median wall time of one compiled right-hand side [s] (loop inside numba, no Python overhead)."""
    return median_time(_rhs_runner(sim, n), repeats) / n


def time_rhs_interleaved(sims: dict[str, Simulator], n: int, repeats: int) -> dict[str, float]:
    """Median time of one right-hand side [s] of each simulator, timed in turn within every repeat so that
    slow drifts of a shared machine hit all of them alike (the fidelity savings are differences of these)."""
    return interleaved_medians({k: _rhs_runner(sim, n) for k, sim in sims.items()}, n, repeats)


def interleaved_medians(runners: dict, n: int, repeats: int) -> dict:
    """Median wall time of one of the ``n`` units [s] each of ``runners`` (name -> a callable doing ``n`` units)
    does, the runners timed in turn within every repeat (a shared, noisy machine then slows all of them alike)."""
    times: dict[str, list[float]] = {k: [] for k in runners}
    for _ in range(repeats):
        for k, run in runners.items():
            t0 = time.perf_counter()
            run()
            times[k].append(time.perf_counter() - t0)
    return {k: statistics.median(v) / n for k, v in times.items()}


def time_step(sim: Simulator, n: int, repeats: int) -> float:
    """Median wall time of one RK4 step [s] from the initial state."""
    x0 = sim.state.copy()

    def run():
        x = x0.copy()
        rk4_advance(0.0, x, sim.controls, sim.settings.dt, n, sim.model, sim.work, sim.limits)

    run()
    return median_time(run, repeats) / n


def time_reference(sim: Simulator, repeats: int) -> float:
    """Median wall time of one right-hand side of the plain-numpy reference [s]."""
    from laddermill_gym.reference import reference_rhs

    x = sim.state.copy()
    reference_rhs(0.0, x, sim.controls, sim.assembly)
    n = max(1, int(0.2 / max(1e-4, median_time(lambda: reference_rhs(0.0, x, sim.controls, sim.assembly), 1))))
    return median_time(lambda: [reference_rhs(0.0, x, sim.controls, sim.assembly) for _ in range(n)], repeats) / n


def largest_stable_dt(scene, x0, u0, horizon: float = 4.0, tol: float = 0.01, iters: int = 8, t0: float = 0.0,
                      lateral: bool = True) -> dict:
    """Largest RK4 step [s] whose run over ``horizon`` seconds from a slightly disturbed initial state stays
    within ``tol`` x piece length of a DP5(4) reference (rtol 1e-9) in every wing and node position.

    Bisection between a step that passes and one that fails; a run that breaks down fails. ``t0`` [s] is the time
    of the state (schedules such as a moving cable's speed depend on it). A failing reference is reported in
    ``note``, not raised. ``lateral``: disturb sideways velocity and roll rate (3D); else the in-plane velocity
    (for a laterally unstable system such as the moving mill, whose lateral divergence would otherwise swamp the
    step-size error). Above the stability limit RK4 on a tension-only cable need not produce NaN, hence the
    comparison with a reference.
    """
    rng = np.random.default_rng(0)
    x_pert = x0.copy()
    a = scene.assembly
    if a.dim == 3:
        for k in range(a.n_wings):
            if lateral:
                x_pert[B3_SIZE * k + B3_VEL + 1] += 0.2 * rng.normal()  # sideways velocity [m/s]
                x_pert[B3_SIZE * k + B3_RATE] += 0.02 * rng.normal()  # roll rate [rad/s]
            else:
                x_pert[B3_SIZE * k + B3_VEL] += 0.2 * rng.normal()  # forward velocity [m/s]
                x_pert[B3_SIZE * k + B3_VEL + 2] += 0.2 * rng.normal()  # normal velocity [m/s]
    ref = Simulator(a, x_pert, dataclasses.replace(scene.settings, method="dp54"), u0)
    ref.reset(x_pert, t=t0, controls=u0)
    try:
        ref.advance_to(t0 + horizon, rtol=1e-9, atol=1e-9)
    except SimulationError as err:
        return {"dt_stable_s": float("nan"), "note": f"the DP5(4) reference failed: {err}"}
    pos_ref = np.vstack([ref.wing_positions(), ref.node_positions()])
    limit = tol * scene.piece_length

    def ok(dt):
        n = int(round(horizon / dt))
        sim = Simulator(a, x_pert, dataclasses.replace(scene.settings, dt=horizon / n, method="rk4"), u0)
        sim.reset(x_pert, t=t0, controls=u0)
        try:
            sim.step(n_steps=n)
        except SimulationError:
            return False, float("inf")
        err = float(np.max(np.linalg.norm(np.vstack([sim.wing_positions(), sim.node_positions()]) - pos_ref, axis=1)))
        return err < limit, err

    lo, hi = scene.settings.dt / 4, scene.settings.dt
    while ok(hi)[0]:
        lo, hi = hi, hi * 2
        if hi > 1.0:
            break
    if not ok(lo)[0]:
        return {"dt_stable_s": float("nan"), "note": "even dt/4 fails"}
    for _ in range(iters):
        mid = np.sqrt(lo * hi)
        if ok(mid)[0]:
            lo = mid
        else:
            hi = mid
    return {"dt_stable_s": lo, "dt_unstable_s": hi, "horizon_s": horizon, "tolerance_m": limit,
            "error_at_default_dt_m": ok(scene.settings.dt)[1]}


def startup_times(scene_name: str, warm_repeats: int = 3) -> dict:
    """Wall time of a fresh process that imports the package, loads the scene, finds its initial state,
    builds the simulator and takes one step: with empty caches (numba's and the package's start cache, a new folder:
    the cold compile, once) and the median of ``warm_repeats`` starts from the caches that run left (warm)."""
    code = ("import time; t=time.perf_counter(); from laddermill_gym import load_scene; "
            f"s=load_scene({scene_name!r}); sim=s.simulator(); sim.step(n_steps=1); "
            "print(time.perf_counter()-t)")
    out = {}
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache, LADDERMILL_CACHE_DIR=os.path.join(cache, "laddermill"))
        for label, runs in (("cold_start_s", 1), ("warm_start_s", warm_repeats)):
            walls, inside = [], []
            for _ in range(runs):
                t0 = time.perf_counter()
                r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
                walls.append(time.perf_counter() - t0)
                inside.append(float(r.stdout.strip().splitlines()[-1]))
            out[label] = statistics.median(walls)
            out[label[:-2] + "_inside_s"] = statistics.median(inside)
    return out


def _layout_state(scene):
    """The shooting layout (no Newton): a representative state for timing long chains."""
    from laddermill_gym.ladder.layout import layout
    from laddermill_gym.model.builders import chain_state

    a = scene.assembly
    n = a.n_wings
    half = (n + 1) // 2
    el = [scene.initial.elevator_up if k < half else scene.initial.elevator_down for k in range(n)]
    pos, alphas = layout(scene, el)
    u = np.zeros(N_CONTROLS * n)
    u[CTRL_ELEVATOR::N_CONTROLS] = el
    end = None if scene.end is None else scene.ground_points[scene.end]
    x = chain_state(a, scene.layout, pos, [[0.0, al, 0.0] for al in alphas], scene.ground_points[scene.start], end)
    if a.dim == 2:
        from laddermill_gym.model.states import planar_from_3d

        x = planar_from_3d(x, n, a.n_nodes)
    return x, u


def run_benchmark(quick: bool = False, scenes: list[str] | None = None, echo=print) -> dict:
    """Measure everything and print a table; returns the figures as a dict (the moving-cable mill is measured by
    ``studies/mill/mill_benchmark.py``; ``laddermill bench`` runs both)."""
    from laddermill_gym.ladder.scene import load_scene

    reps = 3 if quick else 7
    scenes = scenes or ["tethered_wing", "ladder_chain"]
    res: dict = {"machine": {"cpus": os.cpu_count(), "python": sys.version.split()[0],
                             "numba_threads": os.environ.get("NUMBA_NUM_THREADS", "default")}, "scenes": {}}
    t_start = time.perf_counter()
    for name in scenes:
        echo(f"[{time.perf_counter() - t_start:5.0f} s] measuring {name}: right-hand side, RK4 step, numpy reference, "
             f"fidelity variants{'' if quick else ', largest stable step'} ...")
        sys.stdout.flush()
        t0 = time.perf_counter()
        scene = load_scene(name)
        x0, u0 = scene.initial_state()
        setup = time.perf_counter() - t0
        sim = scene.simulator(x0, u0)
        a = scene.assembly
        r: dict = {"n_wings": a.n_wings, "n_nodes": a.n_nodes, "n_elements": a.elements.count,
                   "n_states": a.state_size, "dt_s": scene.settings.dt, "scene_setup_s": setup}
        n_rhs = 20000 if a.n_wings < 10 else 400
        r["rhs_s"] = time_rhs(sim, n_rhs, reps)
        r["rk4_step_s"] = time_step(sim, max(10, n_rhs // 8), reps)
        r["real_time_factor"] = scene.settings.dt / r["rk4_step_s"]
        r["reference_rhs_s"] = time_reference(sim, 3 if quick else 5)
        r["speedup_vs_numpy_reference"] = r["reference_rhs_s"] / r["rhs_s"]
        sims = {}
        for label, kw in (("full", {}), ("sag_off", dict(sag=False)), ("cable_aero_off", dict(cable_aero=False)),
                          ("both_off", dict(sag=False, cable_aero=False)), ("in_plane_2d", dict(dimension=2))):
            sc = load_scene(name, **kw)
            x, u = _layout_state(sc)
            sims[label] = Simulator(sc.assembly, x, sc.settings, u)
        fid = time_rhs_interleaved(sims, n_rhs, 3 * reps)
        r["fidelity_rhs_s"] = fid
        r["fidelity_saving"] = {k: 1.0 - v / fid["full"] for k, v in fid.items() if k != "full"}
        if not quick:
            r["stability"] = largest_stable_dt(scene, x0, u0)
        r["state_and_workspace_bytes"] = int(sum(np.asarray(v).nbytes for v in sim.model) +
                                             sum(np.asarray(v).nbytes for v in sim.work) + x0.nbytes)
        res["scenes"][name] = r
    # cost per step against the number of wings (ladder chains of 10, 100, 1000 wings, layout states)
    echo(f"[{time.perf_counter() - t_start:5.0f} s] measuring the cost per wing at 10, 100 and 1000 wings ...")
    sys.stdout.flush()
    scal = {}
    for n in (10, 100, 1000):
        sc = load_scene("ladder_chain", n_wings=n)
        x, u = _layout_state(sc)
        sim = Simulator(sc.assembly, x, sc.settings, u)
        scal[n] = time_rhs(sim, max(20, 40000 // n), reps)
    res["scaling_rhs_s"] = {str(k): v for k, v in scal.items()}
    res["scaling_per_wing_ratio_1000_vs_10"] = (scal[1000] / 1000) / (scal[10] / 10)
    res["scaling_per_wing_ratio_1000_vs_100"] = (scal[1000] / 1000) / (scal[100] / 100)
    if not quick:
        res["startup"] = {name: startup_times(name) for name in scenes}
    _print_scenes(res, echo)
    res["peak_rss_MiB"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    echo(f"peak resident memory of this process {res['peak_rss_MiB']:.0f} MiB")
    return res


def _print_scenes(res: dict, echo) -> None:
    echo(f"laddermill_gym benchmark ({res['machine']['cpus']} CPUs, one thread, medians)")
    for name, r in res["scenes"].items():
        echo(f"\n== {name}: {r['n_wings']} wings, {r['n_nodes']} nodes, {r['n_elements']} elements, "
             f"{r['n_states']} states, dt {r['dt_s']:g} s")
        echo(f"  right-hand side        {r['rhs_s'] * 1e6:10.2f} us")
        echo(f"  RK4 step               {r['rk4_step_s'] * 1e6:10.2f} us")
        echo(f"  real-time factor       {r['real_time_factor']:10.1f} x")
        echo(f"  numpy reference rhs    {r['reference_rhs_s'] * 1e6:10.1f} us  -> kernels "
             f"{r['speedup_vs_numpy_reference']:.0f}x faster")
        for k, v in r["fidelity_saving"].items():
            echo(f"  rhs with {k:15s}{r['fidelity_rhs_s'][k] * 1e6:10.2f} us  (saves {100 * v:4.0f}% of "
                 f"{r['fidelity_rhs_s']['full'] * 1e6:.2f} us)")
        if "stability" in r:
            s = r["stability"]
            echo(f"  largest stable RK4 dt  {s.get('dt_stable_s', float('nan')):10.4f} s "
                 f"(fails at {s.get('dt_unstable_s', float('nan')):.4f} s; error at default dt "
                 f"{s.get('error_at_default_dt_m', float('nan')):.2e} m)")
        echo(f"  arrays (model, workspace, state) {r['state_and_workspace_bytes'] / 1024:.0f} KiB; "
             f"scene set-up {r['scene_setup_s']:.2f} s")
    sc = res["scaling_rhs_s"]
    echo("\n== cost against the number of wings (ladder chain right-hand side)")
    for n, v in sc.items():
        echo(f"  {n:>5s} wings  {v * 1e6:10.1f} us  ({v / int(n) * 1e9:7.1f} ns per wing)")
    echo(f"  per-wing cost 1000 vs 10 wings: {res['scaling_per_wing_ratio_1000_vs_10']:.2f}; "
         f"1000 vs 100: {res['scaling_per_wing_ratio_1000_vs_100']:.2f} (1 = linear)")
    if "startup" in res:
        for name, s in res["startup"].items():
            echo(f"== start-up {name}: cold (compiling) {s['cold_start_s']:.1f} s, warm cache "
                 f"{s['warm_start_s']:.2f} s (inside the process {s['warm_start_inside_s']:.2f} s)")
