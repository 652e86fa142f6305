"""``laddermill work-precision SCENE``: error against wall time of every integrator on a scene.

For each forcing (``smooth``: a disturbed start in steady wind; ``step``: a 0.1 rad wind-direction step as a 1 ms
ramp that falls inside an RK4 step; ``gust``: a 1-cosine speed gust sampled every 0.1 s, whose every sample is a
kink) the scene is run over ``--time`` seconds by

* RK4 on a grid of steps up to its stability limit (``studies/numerics/stable_step.py``) with the default breakpoint
  stepping (``rk4``: steps split at kinks inside them) and, on the non-smooth forcings, with ``rk4-all`` (steps
  that end on a kink too get their own segment) and ``rk4-off`` (across kinks: the behaviour before);
* DP5(4) over tolerances rtol = atol from 1e-3 to 1e-10, the error-controlled ROS34PW2 (``ros34pw2a``) from 1e-2
  to 1e-8 (``W_TOLERANCES``);
* the linearly implicit Rosenbrock-W methods (``ros2``, ``ros34pw2``; any other fixed-step method the simulator
  lists in ``INTEGRATOR_METHODS``) on the steps period / k, k = 1, 2, 3, 4, 6, 8, 12, 16 (period = the time between
  samples), which reach far beyond RK4's limit.

Errors are against a reference: our DP5(4) at rtol = atol = 1e-12 and scipy's DOP853 (an independent
implementation) at 1e-12, both stepping onto the kinks; their difference is reported (``reference_agreement``)
and is the floor of what can be measured. Errors are taken at the final time and as an RMS over ``--samples``
equally spaced times, for the positions (wing CGs and cable nodes, [m]) and the full state (each entry scaled
by max(1, |reference|)); the largest position error over the samples relative to the scene's extent (the largest
distance of a body from the origin in the reference) is ``err_max_pos_rel``, the measure of the summary's
"fastest at 1e-3" table. Wall time: the median of ``--repeats`` warm runs (after one untimed run, which is the
one whose errors are recorded), one numba thread. Output: ``SCENE.csv``, ``SCENE.json`` and ``SCENE.png``
(log-log) in ``--out``.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from laddermill_gym.sim.simulator import ADAPTIVE_METHODS, FIXED_STEP_METHODS, SimulationError, Simulator
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings

FORCINGS = ("smooth", "step", "gust")
#: the linearly implicit methods run at the sample period divided by these
W_STEP_DIVISORS = (1, 2, 3, 4, 6, 8, 12, 16)
TOLERANCES = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10)
#: the error-controlled W-method's: it starts looser, since its estimate is that of the embedded order-2 solution
#: while the order-3 one is propagated (measured on the laddermill over 10 s: rtol 3e-3 -> position error 1.4e-4
#: of the extent)
W_TOLERANCES = (1e-2, 3e-3, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
REF_TOL = 1e-12


def forcing_setup(sim: Simulator, forcing: str, duration: float):
    """(start state, wind) of a forcing: ``smooth`` a disturbed start (sideways velocity 0.2 m/s, roll rate
    0.02 rad/s per wing, seeded) in the steady wind; ``step`` a 0.1 rad direction step ramped over 1 ms from
    0.3037 T; ``gust`` a 1-cosine gust of +30 % speed over 0.4 T from 0.2 T, sampled every 0.1 s."""
    from laddermill_gym.kernels.contract import B3_RATE, B3_SIZE, B3_VEL

    x0 = sim.initial_state.copy()
    wind = sim.assembly.wind
    if forcing == "smooth":
        rng = np.random.default_rng(0)
        if sim.assembly.dim == 3:
            for k in range(sim.assembly.n_wings):
                x0[B3_SIZE * k + B3_VEL + 1] += 0.2 * rng.normal()
                x0[B3_SIZE * k + B3_RATE] += 0.02 * rng.normal()
        return x0, None
    return x0, forcing_wind(wind, forcing, duration)


def forcing_wind(wind, forcing: str, duration: float):
    """The ``WindParams`` of a non-smooth forcing over ``duration`` [s] (:func:`forcing_setup`), None for smooth."""
    if forcing == "smooth":
        return None
    if forcing == "step":
        return wind.with_modulation(0.3037 * duration, 1e-3, np.ones(2), np.array([0.0, 0.1]))
    if forcing == "gust":
        t0, length = 0.2 * duration, 0.4 * duration
        tt = np.arange(0.0, length + 1e-9, 0.1)
        speed = 1.0 + 0.15 * (1.0 - np.cos(2 * np.pi * tt / length))
        return wind.with_modulation(t0, 0.1, speed, np.zeros_like(speed))
    raise ValueError(f"forcing = {forcing!r}: must be one of {FORCINGS}")


def positions(sim: Simulator) -> np.ndarray:
    """Wing CG and free node positions stacked, shape (n_wings + n_nodes, 3) [m]."""
    return np.vstack([sim.wing_positions(), sim.node_positions()])


def trajectory(sim: Simulator, times: np.ndarray, method: str, value: float) -> tuple[np.ndarray, np.ndarray]:
    """Run ``sim`` through ``times`` [s] (fixed-step methods: steps of ``value`` [s]; DP5(4): tolerance ``value``);
    (states (n, n_state), positions (n, n_bodies, 3)) at the times. SimulationError when it breaks down."""
    xs, ps = [sim.state.copy()], [positions(sim)]
    for t in times[1:]:
        if method in ADAPTIVE_METHODS:
            sim.advance_to(t, rtol=value, atol=value)
        else:
            sim.step(n_steps=int(round((t - sim.t) / value)))
        xs.append(sim.state.copy())
        ps.append(positions(sim))
    return np.array(xs), np.array(ps)


def scipy_reference(sim: Simulator, times: np.ndarray) -> np.ndarray:
    """States at ``times`` from scipy's DOP853 at rtol = atol = 1e-12 on ``sim.rhs``, integrated piece by piece
    between the wind's kinks (inside a piece the rhs sees times just below its end, so its own segment)."""
    from scipy.integrate import solve_ivp

    kinks = sim.breakpoint_times
    x = sim.state.copy()
    out = [x.copy()]
    for ta, tb in zip(times[:-1], times[1:], strict=True):
        ends = [ta, *[float(b) for b in kinks if ta < b < tb], tb]
        for a, b in zip(ends[:-1], ends[1:], strict=True):
            top = b - 1e-12 * max(1.0, abs(b))
            sol = solve_ivp(lambda t, y, top=top: sim.rhs(min(t, top), y), (a, b), x, method="DOP853",
                            rtol=REF_TOL, atol=REF_TOL)
            if not sol.success:
                raise RuntimeError(f"scipy DOP853 reference failed on [{a}, {b}] s: {sol.message}")
            x = sol.y[:, -1]
        out.append(x.copy())
    return np.array(out)


def errors(xs, ps, xr, pr) -> dict:
    """Final-time, RMS and largest errors of positions [m] (per body Euclidean; the largest also relative to the
    reference's extent, the largest distance of a body from the origin) and of the scaled full state [-]."""
    dp = np.linalg.norm(ps - pr, axis=2)
    dx = (xs - xr) / np.maximum(1.0, np.abs(xr))
    extent = float(np.max(np.linalg.norm(pr, axis=2)))
    return {"err_final_pos_m": float(np.max(dp[-1])), "err_rms_pos_m": float(np.sqrt(np.mean(dp**2))),
            "err_max_pos_m": float(np.max(dp)), "err_max_pos_rel": float(np.max(dp)) / extent,
            "err_final_state": float(np.max(np.abs(dx[-1]))), "err_rms_state": float(np.sqrt(np.mean(dx**2)))}


def run_cases(base: Simulator, forcing: str, duration: float, n_samples: int, repeats: int, dt_stable: float,
              n_dt: int, bar=None) -> tuple[list[dict], dict]:
    """All methods on one forcing: (rows, reference summary)."""
    x0, wind = forcing_setup(base, forcing, duration)
    times = np.linspace(0.0, duration, n_samples + 1)
    ref_sim = with_settings(base, state=x0, wind=wind, method="dp54", breakpoints="all")
    xr, pr = trajectory(ref_sim, times, "dp54", REF_TOL)
    xs2 = scipy_reference(with_settings(base, state=x0, wind=wind, method="dp54"), times)
    agree = float(np.max(np.abs((xs2 - xr) / np.maximum(1.0, np.abs(xr)))))
    ref = {"dp54_rtol": REF_TOL, "scipy_dop853_rtol": REF_TOL, "reference_agreement_state": agree}
    period = duration / n_samples
    m0 = max(1, math.ceil(period / dt_stable - 1e-9))
    ms = sorted({int(round(m0 * 2 ** (k / 2))) for k in range(n_dt)})
    cases = [("rk4", period / m) for m in ms]
    if forcing != "smooth":
        cases += [(label, period / m) for label in ("rk4-all", "rk4-off") for m in ms]
    cases += [("dp54", tol) for tol in TOLERANCES]
    for other in FIXED_STEP_METHODS:
        if other != "rk4":
            cases += [(other, period / k) for k in W_STEP_DIVISORS]
    for other in ADAPTIVE_METHODS:
        if other != "dp54":
            cases += [(other, tol) for tol in W_TOLERANCES]
    rows = []
    for label, value in cases:
        method, _, mode = label.partition("-")
        kw = dict(method=method, breakpoints=mode or "inside")
        if method not in ADAPTIVE_METHODS:
            kw["dt"] = value

        def once():
            """(states, positions, wall time [s] of the integration alone)."""
            sim = with_settings(base, state=x0, wind=wind, **kw)
            t0 = time.perf_counter()
            xs, ps = trajectory(sim, times, method, value)
            return xs, ps, time.perf_counter() - t0

        adaptive = method in ADAPTIVE_METHODS
        row = {"forcing": forcing, "method": label, "dt_s": math.nan if adaptive else value,
               "tol": value if adaptive else math.nan}
        rows.append(measure(row, once, xr, pr, duration, repeats, SimulationError))
        if bar is not None:
            bar.update(1)
    return rows, ref


def measure(row: dict, once, xr, pr, duration: float, repeats: int, failure=SimulationError) -> dict:
    """Fill ``row`` for one run: ``once()`` gives (states, positions, wall time [s]); the errors of its first call
    against the reference (xr, pr), the median wall time of ``repeats`` more and the real-time factor; a
    ``failure`` raised becomes the row's status (its first line), with no time."""
    try:
        xs, ps, _ = once()
        row.update(errors(xs, ps, xr, pr), status="ok")
        row["wall_s"] = statistics.median([once()[2] for _ in range(repeats)])
        row["real_time_factor"] = duration / row["wall_s"]
    except failure as err:
        row.update(status=f"failed: {str(err).splitlines()[0][:160]}", wall_s=math.nan)
    return row


def run_scene(scene: str, forcings=FORCINGS, duration: float = 5.0, n_samples: int = 20, repeats: int = 3,
              n_dt: int = 7, progress: bool = True) -> dict:
    """The study on one scene: {"scene", "dt_stable_s", "references": {forcing: ...}, "rows": [...]}."""
    import numba

    from laddermill_gym.sim.stable_step import estimate_stable_step

    numba.set_num_threads(1)
    base = build_simulator(scene)
    est = estimate_stable_step(base, "rk4")
    out = {"scene": scene, "duration_s": duration, "samples": n_samples, "repeats": repeats,
           "dt_stable_s": est.dt_max, "limiting_eigenvalue": [est.eigenvalue.real, est.eigenvalue.imag],
           "references": {}, "rows": []}
    return run_forcings(out, forcings, f"work-precision {scene}", progress,
                        lambda f, bar: run_cases(base, f, duration, n_samples, repeats, est.dt_max, n_dt, bar))


def run_forcings(out: dict, forcings, desc: str, progress: bool, run) -> dict:
    """Add ``run(forcing, bar)``'s (rows, reference summary) of every forcing to the result ``out`` (its
    "references" and "rows"), with a progress bar counting the runs when ``progress``."""
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(desc=desc, unit="run", leave=False)
    try:
        for f in forcings:
            rows, ref = run(f, bar)
            out["references"][f] = ref
            out["rows"] += rows
    finally:
        if bar is not None:
            bar.close()
    return out


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("work-precision", help="error against wall time of the integrators on a scene",
                       description=__doc__.replace("``", ""), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", nargs="+",
                   help="scene names or YAML paths; 'roberts_flying_model' for the rotorcraft; a point-mass scene "
                   "(podgaets_5km) runs its explicit and implicit methods (studies/numerics/pointmass_precision.py)")
    p.add_argument("--forcing", nargs="+", choices=FORCINGS, default=list(FORCINGS))
    p.add_argument("--time", type=float, default=5.0, help="simulated time per run [s] (default 5)")
    p.add_argument("--samples", type=int, default=20, help="times in the RMS error (default 20)")
    p.add_argument("--repeats", type=int, default=3, help="timed repeats per run, median taken (default 3)")
    p.add_argument("--n-dt", type=int, default=7, help="RK4 steps on the grid (halving every two; default 7)")
    p.add_argument("--element-length", type=float, default=25.0,
                   help="point-mass scenes: element length [m] (default 25: 200 nodes on podgaets_5km)")
    p.add_argument("--out", default="results/work_precision", help="output folder")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd)
    return p


def _cmd(args) -> int:
    from laddermill_gym.studies.numerics import pointmass_precision
    from laddermill_gym.studies.numerics.work_precision_output import plot_work_precision, print_summary, save_rows

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for scene in args.scene:
        if pointmass_precision.is_pointmass_scene(scene):
            res = pointmass_precision.run_scene(scene, args.forcing, args.time, args.samples, args.repeats,
                                                args.element_length, not args.quiet)
        else:
            res = run_scene(scene, args.forcing, args.time, args.samples, args.repeats, args.n_dt, not args.quiet)
        stem = out / Path(scene).stem
        save_rows(res, stem.with_suffix(".csv"))
        stem.with_suffix(".json").write_text(json.dumps(res, indent=1, default=float))
        plot_work_precision(res, stem.with_suffix(".png"))
        print_summary(res)
        print(f"wrote {stem}.csv, .json, .png")
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="laddermill")
    sub = parser.add_subparsers(dest="cmd", required=True)
    add_parser(sub)
    args = parser.parse_args(["work-precision", *(sys.argv[1:] if argv is None else argv)])
    return args.func(args)


if __name__ == "__main__":
    raise SystemExit(main())
