"""The laddermill_gym command line (also ``python -m laddermill_gym ...``).

Examples:
  laddermill simulate --start periodic --direction-step 0.01 --animate      # the moving mill, the paper's step
  laddermill simulate tethered_wing --time 30 --out runs/wing
  laddermill bench                                                          # real-time factors, ratios
  laddermill train configs/agents/ppo_tethered_wing.yaml                    # Stable-Baselines3 from a config
  laddermill evaluate --env laddermill_gym/LadderMill-v0 --controllers open_loop lqr
  laddermill lqr --config configs/agents/lqr_laddermill.yaml                # LQR design report
  laddermill COMMAND --help                                                 # each command's options
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
import time
from pathlib import Path

import numpy as np

from laddermill_gym.studies.commands import Parser, UsageError, check_number, run_guarded, writable_folder


def _scene_from_args(args):
    from laddermill_gym.ladder.scene import load_scene

    return load_scene(args.scene, dimension=args.dimension, sag=args.sag, cable_aero=args.cable_aero,
                      elements_per_piece=args.elements_per_piece, n_wings=args.n_wings, dt=args.dt)


def start_state(scene, args):
    """(state, controls, time [s]) the run starts from: the scene's initial state, or the periodic motion of a
    moving-cable scene (--start periodic)."""
    if args.start == "scene":
        x0, u0 = scene.initial_state()
        return x0, u0, 0.0
    if scene.assembly.station is None:
        raise UsageError(f"--start periodic needs a moving-cable scene (one with a station:), not {scene.name}")
    from laddermill_gym.ladder.periodic import periodic_start

    print("finding the periodic motion of the in-plane mill (the operating point) ...")
    x0, u0, t_start, res = periodic_start(scene, progress=not args.quiet)
    print(res.summary())
    return x0, u0, t_start


def _positive(name: str, value, allow_none: bool = False, integer: bool = False) -> None:
    if value is None and not allow_none:
        raise UsageError(f"{name} = None: must be {'a whole number >= 1' if integer else 'a finite number > 0'}")
    check_number(name, value, low=1 if integer else 0, strict=not integer, integer=integer)


def _check_simulate_args(args) -> Path:
    """Refuse bad numbers before any work (one line naming the option, the value and what is allowed); returns the
    output folder, created and checked writable."""
    _positive("--time", args.time)
    _positive("--sample-dt", args.sample_dt)
    _positive("--dt", args.dt, allow_none=True)
    _positive("--n-wings", args.n_wings, allow_none=True, integer=True)
    _positive("--elements-per-piece", args.elements_per_piece, allow_none=True, integer=True)
    for name, v in (("--direction-step", args.direction_step), ("--step-time", args.step_time),
                    ("--ground-height", args.ground_height)):
        check_number(name, v)
    if args.step_time < 0:
        raise UsageError(f"--step-time = {args.step_time!r}: must be >= 0 s")
    if args.sample_dt > args.time:
        raise UsageError(f"--sample-dt = {args.sample_dt!r} s: must not exceed --time = {args.time!r} s")
    return writable_folder(args.out)


def _simulate_setup(args):
    """(scene, simulator) of ``laddermill simulate``: the scene with its start, direction step and ground options;
    UsageError for a point-mass scene and for a run of more than ``sim.recording.MAX_STEPS`` steps (a warning line
    above ``WARN_STEPS``)."""
    from laddermill_gym.sim.recording import check_step_count

    scene = _scene_from_args(args)
    if not hasattr(scene, "assembly"):
        raise UsageError(f"scene {args.scene!r} is a point-mass scene (fidelity.wing: pointmass): simulate runs the "
                         "rigid scenes; run it with load_scene(...).simulator().advance(seconds) or laddermill "
                         "work-precision")
    try:
        warning = check_step_count(scene.settings.dt, args.time,
                                   "--dt" if args.dt is not None else f"{scene.file}: integrator.dt")
    except ValueError as err:
        raise UsageError(f"--time = {args.time!r} s: {err}") from None
    if warning:
        print(f"warning: {warning}", file=sys.stderr)
    per = max(1, int(round(args.sample_dt / scene.settings.dt)))
    if abs(per * scene.settings.dt - args.sample_dt) > 1e-9 * args.sample_dt:
        print(f"warning: --sample-dt = {args.sample_dt:g} s is not a whole number of physics steps of "
              f"{scene.settings.dt:g} s: recording every {per * scene.settings.dt:g} s", file=sys.stderr)
    t_end = round(args.time / (per * scene.settings.dt)) * per * scene.settings.dt  # the recording's whole samples
    if not t_end > 0:
        raise UsageError(f"--time = {args.time:g} s: shorter than half a sample interval ({per * scene.settings.dt:g} "
                         "s, --sample-dt): nothing would be simulated")
    if abs(t_end - args.time) > 1e-9 * args.time:
        print(f"warning: --time = {args.time:g} s is not a whole number of sample intervals of "
              f"{per * scene.settings.dt:g} s (--sample-dt): simulating {t_end:g} s", file=sys.stderr)
    if args.direction_step and not args.step_time < t_end:
        raise UsageError(f"--step-time = {args.step_time:g} s: the direction step would come at or after the end of "
                         f"the run ({t_end:g} s, --time {args.time:g} s) and never act")
    x0, u0, t_start = start_state(scene, args)
    asm = scene.assembly
    if args.direction_step:
        # the paper's disturbance: a step in wind direction [rad] at --step-time after the start
        ts = t_start + args.step_time
        wind = asm.wind.with_modulation(ts - 1e-3, 1e-3, np.ones(2), np.array([0.0, args.direction_step]))
        scene = scene.replace(assembly=dataclasses.replace(asm, wind=wind))
    if args.ground_contact is not None or args.ground_height is not None:
        g = scene.settings
        scene = scene.replace(settings=dataclasses.replace(
            g, ground_contact=g.ground_contact if args.ground_contact is None else args.ground_contact,
            ground_height=g.ground_height if args.ground_height is None else args.ground_height))
    sim = scene.simulator(x0, u0)
    sim.reset(x0, t=t_start, controls=u0)
    if sim.settings.ground_contact != "off":  # a start at or below the ground would end (or flag) at once
        from laddermill_gym.sim.reports import start_below_ground

        if below := start_below_ground(sim):
            raise UsageError(below + (" (--ground-height)" if args.ground_height is not None else ""))
    return scene, sim


def cmd_simulate(args) -> int:
    from laddermill_gym.plotting import plot_generator, plot_histories, plot_shape
    from laddermill_gym.sim.recording import record

    out = _check_simulate_args(args)
    t0 = time.perf_counter()
    scene, sim = _simulate_setup(args)
    asm = scene.assembly
    print(f"scene {scene.name}: {asm.n_wings} wings, {asm.n_nodes} cable nodes, {asm.elements.count} elements, "
          f"{asm.state_size} states, {'3D' if asm.dim == 3 else 'in-plane'}, sag {'on' if asm.sag else 'off'}, "
          f"cable aerodynamics {'on' if asm.cable_aero else 'off'}, dt {scene.settings.dt:g} s "
          f"(set up in {time.perf_counter() - t0:.1f} s)")
    if scene.settings.method == "rk4" and not args.no_step_check:
        _check_step(sim)
    t1 = time.perf_counter()
    rec = record(sim, args.time, args.sample_dt, progress=not args.quiet, interruptible=True)
    wall = time.perf_counter() - t1
    stem = out / scene.name
    files = [rec.save_npz(Path(f"{stem}.npz"))]  # not with_suffix: a scene named wing_v2.5 kept wing_v2
    if args.csv:
        files.append(rec.save_csv(Path(f"{stem}.csv")))
    title = f"{scene.name}: {asm.n_wings} wings, {rec.t[-1]:.1f} s"
    files.append(plot_shape(rec, Path(f"{stem}_shape.png"), title, asm=asm))
    files.append(plot_histories(rec, Path(f"{stem}_histories.png"), title))
    if asm.station is not None:
        files.append(plot_generator(rec, Path(f"{stem}_generator.png"), title))
    if args.animate and not rec.interrupted:
        from laddermill_gym.animation import animate_loop

        files.append(animate_loop(rec, asm, Path(f"{stem}_loop.gif"), title=scene.name, progress=not args.quiet))
    span = rec.t[-1] - rec.t[0]
    print(f"simulated {span:.2f} s in {wall:.2f} s wall ({span / max(wall, 1e-9):.1f}x real time)")
    if rec.error:
        # a periodic start runs on the operating-point search's clock: say when that is from the run's own start
        since = f" ({span:.2f} s after the run's start at t = {rec.t[0]:.6g} s)" if rec.t[0] != 0.0 else ""
        print(f"run stopped early: {rec.error}{since}")
    for line in _flag_lines(rec):
        print(line)
    for f in files:
        print(f"wrote {f}")
    if rec.interrupted:
        print(f"interrupted (Ctrl-C) at t = {rec.t[-1]:.6g} s: wrote what was recorded, {len(rec.t)} samples "
              f"(exit status 130)", file=sys.stderr)
        return 130
    if rec.error and not rec.error.startswith("ground contact") and not args.allow_breakdown:
        print("exit status 3: the run broke down (outputs written up to the breakdown; --allow-breakdown exits 0)",
              file=sys.stderr)
        return 3
    return 1 if rec.error and args.strict else 0


def _check_step(sim) -> None:
    """Print the RK4 step against its estimated stability limit at the start (studies.numerics.stable_step:
    eigenvalues of the Jacobian), with a warning line when the step is beyond it (the run could oscillate without
    failing)."""
    import warnings

    from laddermill_gym.sim.stable_step import check_step

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        est = check_step(sim, action="warn")
    print(f"RK4 step {sim.settings.dt:g} s; estimated stability limit at the start {est.dt_max:.4g} s "
          f"(eigenvalue {est.eigenvalue:.4g} 1/s)")
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)


def _flag_lines(rec) -> list[str]:
    """Printed summary of a recording's flags: ground contacts (``ground_contact: flag``), cable elements over
    their breaking load (``sim/overload.py``) and wings outside the accurate range of their aerodynamic data."""
    lines = []
    if rec.overloads:
        shown = "; ".join(e.text() for e in rec.overloads[:5])
        more = f" (and {len(rec.overloads) - 5} more)" if len(rec.overloads) > 5 else ""
        lines.append(f"CABLE OVERLOAD, tension above the cable's breaking load (the run went on): {shown}{more}")
    if rec.ground_contacts:
        shown = "; ".join(f"t = {c.t:.6g} s {c.body} at height {c.height:.4g} m" for c in rec.ground_contacts[:5])
        more = f" (and {len(rec.ground_contacts) - 5} more)" if len(rec.ground_contacts) > 5 else ""
        lines.append(f"ground contacts flagged (the run went on): {shown}{more}")
    out = rec.views["aero_out_of_range"]
    for k in np.flatnonzero(out.any(axis=0))[:5]:
        i = int(np.argmax(out[:, k]))
        lines.append(f"wing {k} outside the accurate range of its aerodynamic data in {int(out[:, k].sum())} of "
                     f"{len(rec.t)} samples, first at t = {rec.t[i]:.6g} s (alpha "
                     f"{np.degrees(rec.views['wing_alpha_rad'][i, k]):.1f} deg, beta "
                     f"{np.degrees(rec.views['wing_beta_rad'][i, k]):.1f} deg)")
    return lines


def _check_json(args) -> None:
    """UsageError for a ``--json`` file whose folder does not exist or cannot be written (found before the run)."""
    if args.json is not None:
        if Path(args.json).is_dir():
            raise UsageError(f"--json = {args.json!r}: is a folder, not a file")
        folder = Path(args.json).parent
        if not folder.is_dir():
            raise UsageError(f"--json = {args.json!r}: no such folder {str(folder)!r}")
        writable_folder(str(folder))


def cmd_bench(args) -> int:
    from laddermill_gym.studies.benchmarks.benchmark import run_benchmark
    from laddermill_gym.studies.mill.mill_benchmark import bench_mill
    from laddermill_gym.studies.numerics.scenes import check_scene_names, refuse_scene_kinds

    _check_json(args)
    if args.startup:  # issue 32 point 1: cold and warm start of the envs in fresh processes
        given = [o for o, v in (("--scenes", args.scenes), ("--no-mill", args.no_mill),
                                ("--no-pointmass", args.no_pointmass)) if v]
        if given:
            raise UsageError(f"--startup measures the envs' start-up alone: {', '.join(given)} would be ignored")
        from laddermill_gym.studies.benchmarks.startup import run_startup

        res = run_startup(quick=args.quick)
        if args.json:
            Path(args.json).write_text(json.dumps(res, indent=2))
            print(f"wrote {args.json}")
        return 0
    check_scene_names(args.scenes or [], "--scenes", crafts=False)
    refuse_scene_kinds(args.scenes or [], "--scenes", {
        "pointmass": "the point-mass part of this command measures the 5 km string (--no-pointmass leaves it out)",
        "moving": "the mill part of this command measures it (--no-mill leaves it out)"})

    res = run_benchmark(quick=args.quick, scenes=args.scenes)
    if not args.no_mill:
        res["laddermill"] = bench_mill(quick=args.quick)
    if not args.no_pointmass:
        from laddermill_gym.studies.pointmass.pointmass_benchmark import run_pointmass_benchmark

        res["pointmass"] = run_pointmass_benchmark(quick=args.quick)
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2))
        print(f"wrote {args.json}")
    return 0


def cmd_bench_envs(args) -> int:
    from laddermill_gym.studies.benchmarks.env_benchmark import bench_envs_command

    _check_json(args)
    return bench_envs_command(args)


def cmd_scenes(args) -> int:
    from laddermill_gym.ladder.scene import available_scenes, load_scene

    for name in available_scenes():
        s = load_scene(name)
        n = s.assembly.n_wings if hasattr(s, "assembly") else s.n_wings  # a point-mass scene has no Assembly
        print(f"{name:20s} {n:4d} wings  {s.description}")
    return 0


#: commands with their own parser, run as ``laddermill NAME ARGS``: name -> (module with ``main(argv)``, help)
FORWARDED: dict[str, tuple[str, str]] = {
    "train": ("laddermill_gym.harness.train", "train a Stable-Baselines3 agent from configs/agents/*.yaml"),
    "evaluate": ("laddermill_gym.harness.evaluate", "evaluate controllers (open_loop, lqr, trained runs) on "
                 "seeded episodes; tables and plots"),
    "zoo": ("laddermill_gym.harness.zoo", "run an rl-zoo3 script (train, enjoy, record_video, plot_train, ...) with "
            "the laddermill_gym environments registered"),
    "lqr": ("laddermill_gym.harness.lqr_report", "design an LQR from configs/agents/lqr_*.yaml and report its "
            "modes; optionally fly it against open loop"),
    "site": ("laddermill_gym.quasisteady.cli", "pumping kite: quasi-steady power and site optimisation on wind data "
             "(Lansdorp et al. 2008, Tables 1-2, Figs. 10-20, a turbine beside it)"),
    "work-precision": ("laddermill_gym.studies.numerics.work_precision", "error against run time of the integrators "
                       "on a scene (RK4 over dt, DP5(4) over tolerances; smooth and non-smooth forcing)"),
    "stable-step": ("laddermill_gym.studies.numerics.stable_step", "estimate the largest stable explicit step of a "
                    "scene from the eigenvalues of its Jacobian"),
    "stress": ("laddermill_gym.studies.numerics.stress", "numerical stress suite of a scene: stable steps, hour-long "
               "runs, slack-taut, wind extremes, bang-bang controls, injected NaN, env episodes"),
    "train-seeds": ("laddermill_gym.harness.train_seeds", "train one config with several seeds, serially, on "
                    "local processes (--workers N) or on Ray (--ray)"),
    "workers": ("laddermill_gym.studies.gusts.warm_workers", "laddermill workers warm: prepare a node for "
                "--workers / --ray (fill numba's cache, compute the operating points once)"),
    "pumping-cycle": ("laddermill_gym.studies.pumping.pumping_cycle", "pumping kite: the crosswind cycle (figure "
                      "eights; --controller lqr: the scripted cycle with the lateral LQR) against the quasi-steady "
                      "prediction (Lansdorp, Schmehl)"),
    "tether-convergence": ("laddermill_gym.studies.pumping.tether_convergence", "pumping kite: the crosswind cycle "
                           "on the single element and on reeling tethers of 3 to 10 elements (docs/reeling_tether.md)"),
    "demo": ("laddermill_gym.studies.mill.control_demo", "the main job: the mill through the paper's direction step, "
             "open loop and under the LQR (or a policy); power, lateral excursion, top views, GIF"),
    "gust-bench": ("laddermill_gym.studies.gusts.gust_bench", "run controllers on a versioned gust benchmark suite "
                   "(configs/benchmarks/); CSV, JSON and a scorecard"),
    "power-curve": ("laddermill_gym.studies.mill.power_curve", "laddermill: mean electrical power against the cable "
                    "speed at the paper's wind and the best cable speed against the wind (laddermill_v2 or v1, in "
                    "plane); CSV, JSON, PNG"),
}


def _benchmark_parser(sub, name: str, text: str, func) -> argparse.ArgumentParser:
    """A benchmark command on the subparsers ``sub``: the options every benchmark takes (``--json``, ``--quick``)."""
    p = sub.add_parser(name, help=text)
    p.add_argument("--json", default=None, help="also write the figures as JSON to this file")
    p.add_argument("--quick", action="store_true", help="fewer repetitions (a smoke run)")
    p.set_defaults(func=func)
    return p


def build_parser() -> argparse.ArgumentParser:
    from laddermill_gym import __version__

    p = Parser(prog="laddermill", description=__doc__.replace("``", ""),
               formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--version", action="version", version=f"laddermill_gym {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    for name, (_module, text) in FORWARDED.items():
        sub.add_parser(name, help=text, add_help=False)
    s = sub.add_parser("simulate", help="simulate a scene, save states (npz, CSV) and plots")
    s.add_argument("scene", nargs="?", default="laddermill",
                   help="scene name in configs/scenes or a YAML path (default: laddermill)")
    s.add_argument("--start", choices=("scene", "periodic"), default="scene",
                   help="start from the scene's initial state, or (moving cable) from its periodic motion")
    s.add_argument("--animate", action="store_true", help="also write a GIF of the loop")
    s.add_argument("--time", type=float, default=60.0, help="simulated time [s]")
    s.add_argument("--sample-dt", type=float, default=0.1, help="recording interval [s]")
    s.add_argument("--out", default="results", help="output directory")
    s.add_argument("--csv", action="store_true", help="also write a CSV")
    s.add_argument("--dt", type=float, default=None, help="RK4 step [s] (default: the scene's)")
    s.add_argument("--dimension", type=int, choices=(2, 3), default=None)
    s.add_argument("--sag", action=argparse.BooleanOptionalAction, default=None, help="sag correction")
    s.add_argument("--cable-aero", action=argparse.BooleanOptionalAction, default=None)
    s.add_argument("--elements-per-piece", type=int, default=None)
    s.add_argument("--n-wings", type=int, default=None)
    s.add_argument("--direction-step", type=float, default=0.0,
                   help="wind direction step [rad] (the paper's disturbance is 0.01)")
    s.add_argument("--step-time", type=float, default=1.0, help="time of the direction step after the start [s]")
    s.add_argument("--ground-contact", choices=("stop", "flag", "off"), default=None,
                   help="a wing or cable node reaching the ground: stop with a report, flag and go on, or no "
                        "ground (default: the scene's integrator.ground_contact, else stop)")
    s.add_argument("--ground-height", type=float, default=None,
                   help="ground height [m] (default: the scene's integrator.ground_height, else 0)")
    s.add_argument("--allow-breakdown", action="store_true",
                   help="exit 0 even if the integration breaks down (default: exit status 3, outputs written)")
    s.add_argument("--strict", action="store_true",
                   help="also exit 1 when the run stops at a ground contact (a documented termination, else exit 0)")
    s.add_argument("--quiet", action="store_true", help="no progress bar")
    s.add_argument("--no-step-check", action="store_true",
                   help="skip the estimate of RK4's stable step at the start (one Jacobian, about 0.1-2 s)")
    s.set_defaults(func=cmd_simulate)
    b = _benchmark_parser(sub, "bench", "run the benchmark and print its figures", cmd_bench)
    b.add_argument("--scenes", nargs="*", default=None)
    b.add_argument("--no-mill", action="store_true", help="leave out the moving-cable laddermill")
    b.add_argument("--no-pointmass", action="store_true",
                   help="leave out the point-mass scenes (podgaets_5km: 500,000 elements, memory and cost)")
    b.add_argument("--startup", action="store_true",
                   help="only the envs' start-up: make + reset + step in fresh processes, cold (empty numba and "
                        "operating-point caches) and warm; with --quick warm only, from the current caches")
    e = _benchmark_parser(sub, "bench-envs", "env steps/s: native batched vector env vs SyncVectorEnv", cmd_bench_envs)
    e.add_argument("--envs", nargs="+", default=None, help="only these envs, e.g. TetheredWing-v0 (default: all)")
    e.add_argument("--copies", nargs="+", type=int, default=None, help="these copy counts for every env named")
    e.add_argument("--threads", nargs="+", type=int, default=None, help="thread scaling at the largest --copies (512)")
    c = sub.add_parser("scenes", help="list the scenes")
    c.set_defaults(func=cmd_scenes)
    return p


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv and argv[0] in FORWARDED:
        import importlib

        return run_guarded(argv[0], lambda: importlib.import_module(FORWARDED[argv[0]][0]).main(argv[1:]))
    args = build_parser().parse_args(argv)
    return run_guarded(args.command, lambda: args.func(args))


if __name__ == "__main__":
    sys.exit(main())
