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
  samples), which reach far beyond RK4's limit; with ``--jacobian-every K ...`` also with their iteration matrix
  kept over K steps (``IntegratorSettings.jacobian_every``; rows "METHOD/jK", e.g. ``ros2/j4``).

Errors are against a reference: our DP5(4) at rtol = atol = 1e-12 and scipy's DOP853 (an independent
implementation) at 1e-12, both stepping onto the kinks; their difference is reported (``reference_agreement``)
and is the floor of what can be measured. Errors are taken at the final time and as an RMS over ``--samples``
equally spaced times, for the positions (wing CGs and cable nodes, [m]) and the full state (each entry scaled
by max(1, |reference|)); the largest position error over the samples relative to the scene's extent (the largest
distance of a body from the origin in the reference) is ``err_max_pos_rel``, the measure of the summary's
"fastest at 1e-3" table. Beside them, what a controller sees (``controller_errors.py``): the element tensions and
the generator power (largest error over the largest value of the run), the wings' lateral offsets [m] and
attitudes [rad], and whether a run is within 1 %, 1 %, 0.1 m and 0.01 rad; the summary names the run that meets
these in the least CPU time per method and its speed-up over the fastest such RK4 run. Wall time: the median of
``--repeats`` warm runs (after one untimed run, which is the one whose errors are recorded), CPU time the least of
them, one numba thread. ``--controller lqr`` also runs each forcing closed by the scene's lateral LQR at the envs'
control period (``closed_loop.py``, rows "FORCING+lqr"; steps then divide the control period, the feedback's own
time is left out). Output: ``SCENE.csv``, ``SCENE.json`` and ``SCENE.png``
(log-log) in ``--out``.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from laddermill_gym.sim.simulator import ADAPTIVE_METHODS, FIXED_STEP_METHODS, SimulationError, Simulator
from laddermill_gym.studies.commands import UsageError, check_number, run_subcommand, writable_folder
from laddermill_gym.studies.numerics import pointmass_precision
from laddermill_gym.studies.numerics.closed_loop import (
    CONTROLLERS,
    LQR_CONFIGS,
    Feedback,
    closed_loop_reference,
    closed_loop_trajectory,
    design_feedback,
)
from laddermill_gym.studies.numerics.controller_errors import controller_errors, controller_quantities
from laddermill_gym.studies.numerics.precision import (
    FORCINGS,
    explicit_step_counts,
    forcing_wind,
    measure,
    piecewise_reference,
    run_forcings,
    scaled_difference,
    timed,
)
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings

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
    return piecewise_reference(sim.rhs, sim.state.copy(), times, sim.breakpoint_times, "DOP853", REF_TOL)


def integration_only(once, clock: dict):
    """``once`` (``precision.timed``) less the feedback's time that the closed loop left in ``clock`` (none open
    loop): the rows time the integration, not the controller."""

    def run():
        clock.update(wall=0.0, cpu=0.0)
        xs, ps, wall, cpu = once()
        return xs, ps, wall - clock["wall"], cpu - clock["cpu"]

    return run


def case_settings(label: str, value: float) -> tuple[str, dict]:
    """(method, integrator settings changes) of a run labelled ``METHOD[-BREAKPOINTS][/jK]`` at step or tolerance
    ``value``: ``rk4-all`` RK4 with breakpoints "all", ``ros2/j4`` ros2 with its iteration matrix kept 4 steps."""
    name, _, every = label.partition("/j")
    method, _, mode = name.partition("-")
    kw = dict(method=method, breakpoints=mode or "inside")
    if method not in ADAPTIVE_METHODS:
        kw["dt"] = value
    if every:
        kw["jacobian_every"] = int(every)
    return method, kw


def run_cases(base: Simulator, forcing: str, duration: float, n_samples: int, repeats: int, dt_stable: float,
              n_dt: int, bar=None, fb: Feedback | None = None, jacobian_every=(1,)) -> tuple[list[dict], dict]:
    """All methods on one forcing, open loop or (``fb``, ``closed_loop.py``) closed by a feedback held over its
    control period, which then replaces the sample period in the step grids: (rows, reference summary). Each
    ``jacobian_every`` k > 1 adds the fixed-step W-methods with their iteration matrix kept k steps (rows
    "METHOD/jK")."""
    x0, wind = forcing_setup(base, forcing, duration)
    times = np.linspace(0.0, duration, n_samples + 1)

    def path(sim, method, value, clock=None):
        if fb is None:
            return trajectory(sim, times, method, value)
        return closed_loop_trajectory(sim, times, method, value, fb, positions, clock)

    ref_sim = with_settings(base, state=x0, wind=wind, method="dp54", breakpoints="all")
    xr, pr = path(ref_sim, "dp54", REF_TOL)
    sp = with_settings(base, state=x0, wind=wind, method="dp54")
    xs2 = scipy_reference(sp, times) if fb is None else closed_loop_reference(sp, times, fb, "DOP853", REF_TOL)
    agree = float(np.max(np.abs(scaled_difference(xs2, xr))))
    ev = with_settings(base, state=x0, wind=wind, method="dp54")  # reads the controller quantities of a state
    qr = controller_quantities(ev, times, xr)
    ref = {"dp54_rtol": REF_TOL, "scipy_dop853_rtol": REF_TOL, "reference_agreement_state": agree,
           "extent_m": float(np.max(np.linalg.norm(pr, axis=2))),  # the errors' scale (precision.errors)
           **{f"{k}_reference_agreement": v for k, v in controller_errors(controller_quantities(ev, times, xs2), qr)
              .items() if k != "meets_controller"}}
    period = duration / n_samples if fb is None else fb.period
    ms = explicit_step_counts(period, dt_stable, n_dt)
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
    cases += [(f"{other}/j{k}", period / d) for k in jacobian_every if k != 1 for other in FIXED_STEP_METHODS
              if other != "rk4" for d in W_STEP_DIVISORS]
    rows = []
    for label, value in cases:
        method, kw = case_settings(label, value)

        last = {}  # the states of the latest timed run: the controller quantities are read from them afterwards

        def go(sim, method=method, value=value, last=last):
            last["xs"], ps = path(sim, method, value, last)
            return last["xs"], ps

        once = integration_only(timed(lambda: with_settings(base, state=x0, wind=wind, **kw), go), last)
        adaptive = method in ADAPTIVE_METHODS
        row = {"forcing": forcing if fb is None else f"{forcing}+lqr", "method": label,
               "dt_s": math.nan if adaptive else value, "tol": value if adaptive else math.nan}
        measure(row, once, xr, pr, duration, repeats, SimulationError, bar)
        if row["status"] == "ok":
            row.update(controller_errors(controller_quantities(ev, times, last["xs"]), qr))
            if fb is not None:
                row["feedback_cpu_s"] = last["cpu"]  # the feedback's own time, left out of cpu_s and wall_s
        rows.append(row)
    return rows, ref


def run_scene(scene: str, forcings=FORCINGS, duration: float = 5.0, n_samples: int = 20, repeats: int = 3,
              n_dt: int = 7, progress: bool = True, controllers=("none",), jacobian_every=(1,)) -> dict:
    """The study on one scene: {"scene", "dt_stable_s", "references": {forcing: ...}, "rows": [...]}; with the
    controller ``lqr`` among ``controllers`` each forcing is also run closed loop (``closed_loop.py``), its rows
    and reference under "FORCING+lqr", and the design's wall time is ``lqr_design_s``; ``jacobian_every``: see
    :func:`run_cases`."""
    import numba

    from laddermill_gym.sim.stable_step import estimate_stable_step

    numba.set_num_threads(1)
    base = build_simulator(scene)
    est = estimate_stable_step(base, "rk4")
    out = {"scene": scene, "duration_s": duration, "samples": n_samples, "repeats": repeats,
           "dt_stable_s": est.dt_max, "limiting_eigenvalue": [est.eigenvalue.real, est.eigenvalue.imag],
           "jacobian_every": list(jacobian_every), "references": {}, "rows": []}
    fbs = {c: design_feedback(scene, base, c) for c in controllers}
    if fbs.get("lqr") is not None:
        out.update(lqr_design_s=fbs["lqr"].design_s, lqr_config=fbs["lqr"].config, control_period_s=fbs["lqr"].period)
    labels = [f if c == "none" else f"{f}+{c}" for c in controllers for f in forcings]
    return run_forcings(out, labels, f"work-precision {scene}", progress,
                        lambda lab, bar: run_cases(base, lab.partition("+")[0], duration, n_samples, repeats,
                                                   est.dt_max, n_dt, bar, fbs[lab.partition("+")[2] or "none"],
                                                   jacobian_every))


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("work-precision", help="error against wall time of the integrators on a scene",
                       description=__doc__.replace("``", ""), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", nargs="+",
                   help="scene names or YAML paths; 'roberts_flying_model' for the rotorcraft; a point-mass scene "
                   "(podgaets_5km) runs its explicit and implicit methods (studies/numerics/pointmass_precision.py)")
    p.add_argument("--forcing", nargs="+", choices=FORCINGS, default=list(FORCINGS))
    p.add_argument("--controller", nargs="+", choices=CONTROLLERS, default=["none"],
                   help="none: open loop (default); lqr: also closed by the scene's lateral LQR at its control "
                   "period, zero-order hold (studies/numerics/closed_loop.py); 'none lqr': both in one run")
    p.add_argument("--jacobian-every", nargs="+", type=int, default=[1], metavar="K",
                   help="also run the fixed-step W-methods with their iteration matrix kept K steps (rows "
                   "METHOD/jK; 1: built every step, the rows always run; default 1)")
    p.add_argument("--time", type=float, default=5.0, help="simulated time per run [s] (default 5)")
    p.add_argument("--samples", type=int, default=20,
                   help="output times: the RMS error and the controller errors are read there (default 20); closed "
                   "loop, --time / --samples = the control period reads every period (coarser samples can miss the "
                   "swing of a kept matrix: docs/work_precision_closed_loop.md)")
    p.add_argument("--repeats", type=int, default=3, help="timed repeats per run, median taken (default 3)")
    p.add_argument("--n-dt", type=int, default=7, help="RK4 steps on the grid (halving every two; default 7)")
    p.add_argument("--element-length", type=float, default=25.0,
                   help="point-mass scenes: element length [m] (default 25: 200 nodes on podgaets_5km)")
    p.add_argument("--out", default="results/work_precision", help="output folder")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd)
    return p


def _cmd(args) -> int:
    from laddermill_gym.studies.numerics.scenes import check_scene_names, file_stem
    from laddermill_gym.studies.numerics.work_precision_output import plot_work_precision, print_summary, save_rows

    check_scene_names(args.scene)
    check_number("--time", args.time, low=0, high=3600, unit="s")
    check_number("--element-length", args.element_length, low=0, unit="m")
    for name, v, lo in (("--samples", args.samples, 1), ("--repeats", args.repeats, 1), ("--n-dt", args.n_dt, 1)):
        check_number(name, v, low=lo, high=1000, integer=True, strict=False)
    for k in args.jacobian_every:
        check_number("--jacobian-every", k, low=1, high=1000, integer=True, strict=False)
    out = writable_folder(args.out)
    for scene in args.scene:
        if "lqr" in args.controller and Path(scene).stem not in LQR_CONFIGS:
            raise UsageError(f"--controller lqr: scene {scene!r} has no LQR design here (one of "
                             f"{', '.join(LQR_CONFIGS)})")
        if "lqr" in args.controller:  # checked now, not after the open-loop runs and the design
            from laddermill_gym.control.lqr_config import load_lqr_config
            from laddermill_gym.studies.numerics.closed_loop import periods_per_sample

            period = load_lqr_config(LQR_CONFIGS[Path(scene).stem]).control_period
            try:
                periods_per_sample(np.array([0.0, args.time / args.samples]), period)
            except ValueError as err:
                raise UsageError(f"--controller lqr with --time {args.time:g} and --samples {args.samples}: {err}"
                                 ) from None
    for scene in args.scene:
        if pointmass_precision.is_pointmass_scene(scene):
            res = pointmass_precision.run_scene(scene, args.forcing, args.time, args.samples, args.repeats,
                                                args.element_length, not args.quiet)
        else:
            res = run_scene(scene, args.forcing, args.time, args.samples, args.repeats, args.n_dt, not args.quiet,
                            args.controller, tuple(dict.fromkeys(args.jacobian_every)))
        stem = out / file_stem(scene)  # a bare name wing_v2.5 keeps its dot
        save_rows(res, Path(f"{stem}.csv"))  # not with_suffix: a scene file named wing_v2.5 kept wing_v2
        Path(f"{stem}.json").write_text(json.dumps(res, indent=1, default=float))
        plot_work_precision(res, Path(f"{stem}.png"))
        print_summary(res)
        print(f"wrote {stem}.csv, .json, .png")
    return 0


def main(argv=None) -> int:
    return run_subcommand(add_parser, "work-precision", argv)


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("work-precision", main))
