"""``laddermill stress SCENE``: numerical stress tests; a table of each case, pass or fail, with its figures.

Cases per scene (``studies/numerics/stress_cases.py`` for the outcome rules): the largest stable RK4 step by bisection
against a DP5(4) reference and a kinetic-energy bound, beside the eigenvalue estimate, and DP5(4)'s mean step
beside its estimated limit; a long run (``--hours``, default 1 h) held by a controller (:func:`scene_holder`: the
tethered wing and the chain by their lateral LQR, the rotorcraft by its eq. (6) LQR, the mill at its equilibrium
controls), reporting the drift of the wing height, the largest tension and the kinetic energy between its first and
last tenth;
slack-taut transitions (the wind to zero and back, a gust that unloads the cable); mean winds from 0 to 40 m/s
at the reference height (ramped over 5 s from the scene's); bang-bang and random controls; very long and very
short cable elements (1 and 8 per piece: the scene's step is checked against the estimate, a run at half the
estimate must pass); NaN, inf and huge values injected into the state (each must be reported with the time,
the body and a quantity). Then ``--episodes`` reset-and-run episodes of each env in ``--envs`` with random
actions: every end must be a documented termination (ground, altitude, tension, alpha/beta) or the time limit,
never failure code 1 (the integrator) or an exception.

Output: the printed table, ``stress.csv`` and ``stress.json`` in ``--out``. ``--quick`` shortens every case
(the test suite's version).
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import warnings

import numpy as np

from laddermill_gym.kernels.contract import N_CONTROLS
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.sim.simulator import SimulationError
from laddermill_gym.sim.stable_step import UnstableStepWarning, estimate_stable_step
from laddermill_gym.studies.commands import UsageError, check_number, run_subcommand, writable_folder
from laddermill_gym.studies.numerics import stress_cases as sc
from laddermill_gym.studies.numerics.scenes import CRAFT_NAMES, DEFAULT_SCENES, build_simulator, with_settings


def control_limits(sim) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper limits of every control entry [rad; the station's in its unit]."""
    if hasattr(sim, "config"):  # the rotorcraft: (collective, differential)
        lim = np.array([sim.config.collective_limits, sim.config.differential_limits])
        return lim[:, 0], lim[:, 1]
    lo, hi = sim.initial_controls.copy(), sim.initial_controls.copy()  # station controls held
    for k in range(sim.assembly.n_wings):
        cl = sim.assembly.wing(k).control_limits
        lo[N_CONTROLS * k: N_CONTROLS * (k + 1)], hi[N_CONTROLS * k: N_CONTROLS * (k + 1)] = cl[:, 0], cl[:, 1]
    return lo, hi


def _row(case, scene, **r):
    return {"case": case, "scene": scene, **r}


#: the wing scenes held by their env's lateral LQR in the hour (the env id whose LQR config and design apply)
WING_LQR_ENVS = {"tethered_wing": "laddermill_gym/TetheredWing-v0", "ladder_chain": "laddermill_gym/LadderChain-v0"}


def scene_holder(scene: str, sim):
    """How ``scene`` is held: (control period [s], controls(sim) -> controls or None, name). The rotorcraft, open-loop
    unstable at its trim (rotorcraft.md), by its eq. (6) LQR; the tethered wing and the chain by their envs' lateral
    LQR (``control/lqr.py``, designed on the scene itself, applied to the env observation of the simulator's state:
    ``control.base.observe``); the laddermill, stable at its operating point, by its equilibrium controls (its LQR
    needs the env's periodic operating point)."""
    if scene in CRAFT_NAMES:
        from laddermill_gym.control.craft_lqr import design_craft_lqr

        design = design_craft_lqr()
        if design.config.craft != scene or not np.array_equal(design.x_trim, sim.initial_state):
            raise ValueError(f"{design.config.file}: its design trim ({design.config.craft} at "
                             f"{design.config.wind_speed} m/s) is not the trim of scene {scene}")
        return design.config.control_period, lambda s: design.state_controls(s.state), "eq. (6) LQR"
    if scene not in WING_LQR_ENVS:
        return sim.settings.dt, None, "equilibrium controls"
    from laddermill_gym.control.base import control_ranges, controls_from_actions, elements_below_wings, observe
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.ladder.scene import load_scene

    # the scene as its file has it: None undoes a registered option (the env's arguments merge key by key)
    ctrl = make_controller("lqr", WING_LQR_ENVS[scene], {"scene_options": {"elements_per_piece": None, "method": None},
                                                         "physics_dt": None})
    asm, nw = sim.assembly, sim.assembly.n_wings
    nominal, below = sim.wing_positions().copy(), elements_below_wings(load_scene(scene).layout, nw)
    mid, half = control_ranges(asm)

    def controls(s):
        return controls_from_actions(ctrl.predict(observe(s, nominal, below))[0], mid, half)

    return ENV_IDS[WING_LQR_ENVS[scene]]["control_dt"], controls, "lateral LQR"


def long_run_rows(scene: str, duration: float, progress: bool) -> list[dict]:
    """The scene held for ``duration`` [s] (:func:`scene_holder`); drift of bounded quantities (last tenth - first)."""
    sim = build_simulator(scene)
    period, controls, held_by = scene_holder(scene, sim)
    n_sub, n = int(round(period / sim.settings.dt)), 100
    per_sample = max(1, int(round(duration / n / period)))  # control periods per sample (t_end_s: what ran)
    samples, err = [], None
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=n, desc=f"stress {scene}: {duration:g} s held", unit="%", leave=False)
    try:
        for _ in range(n):
            if controls is None:
                sim.step(n_steps=per_sample * n_sub)
            else:
                for _ in range(per_sample):
                    sim.step(controls(sim), n_steps=n_sub)
            samples.append((float(np.mean(sim.body_heights()[0])), float(np.max(sim.tensions())),
                            sc.kinetic_energy(sim)))
            if bar:
                bar.update(1)
    except SimulationError as e:
        err = e
    finally:
        if bar:
            bar.close()
    text, ok = sc.outcome(err)
    s = np.array(samples) if samples else np.full((1, 3), np.nan)
    first, last = s[: max(1, len(s) // 10)], s[-max(1, len(s) // 10):]
    bounded = bool(np.max(last[:, 2]) <= 1.5 * np.max(first[:, 2]) + 1.0)
    return [_row(f"hold {duration / 3600:g} h", scene, passed=ok and err is None and bounded, outcome=text,
                 held_by=held_by, t_end_s=sim.t,
                 height_drift_m=float(np.mean(last[:, 0]) - np.mean(first[:, 0])),
                 tension_drift_N=float(np.mean(last[:, 1]) - np.mean(first[:, 1])),
                 kinetic_energy_first_J=float(np.max(first[:, 2])), kinetic_energy_last_J=float(np.max(last[:, 2])))]


def wind_rows(scene: str, duration: float) -> list[dict]:
    """Slack-taut transitions and mean winds from 0 to 40 m/s, each from the scene's equilibrium."""
    base = build_simulator(scene)
    w = base.assembly.wind
    cases = [("wind to zero and back", w.with_modulation(1.0, 1.0, np.array([1.0, 0.0, 0.0, 0.0, 1.0]),
                                                         np.zeros(5))),
             ("unloading gust (to 30 %)", w.with_modulation(1.0, 0.5, np.array([1.0, 0.3, 1.0]), np.zeros(3)))]
    for v in (0.0, 5.0, 10.0, 20.0, 30.0, 40.0):
        cases.append((f"wind {v:g} m/s", w.with_modulation(0.0, 5.0, np.array([1.0, v / w.v0]), np.zeros(2))))
    rows = []
    for label, wind in cases:
        sim = with_settings(base, wind=wind)
        rows.append(_row(label, scene, **sc.run_for(sim, duration)))
    return rows


def control_rows(scene: str, duration: float) -> list[dict]:
    """Bang-bang controls (every entry between its limits, switching every 0.5 s) and random controls (uniform
    within the limits, new every 0.1 s, seeded)."""
    base = build_simulator(scene)
    lo, hi = control_limits(base)
    rng = np.random.default_rng(0)
    rows = []
    bang = with_settings(base)
    rows.append(_row("bang-bang controls", scene, **sc.run_for(
        bang, duration, lambda t: np.where((np.arange(lo.size) + int(t / 0.5)) % 2 == 0, lo, hi), sample=0.5)))
    rand = with_settings(base)
    rows.append(_row("random controls", scene, **sc.run_for(rand, duration, lambda t: rng.uniform(lo, hi),
                                                            sample=0.1)))
    return rows


#: the most steps a run of the elements cases takes (the mill at 8 elements per piece: a 2.8 us RK4 limit, so 20 s
#: would be 14 million steps; 20,000 of them are 28 ms)
ELEMENT_RUN_STEPS = 20_000


def _file_dt(scene: str, settings) -> float:
    """The integrator step [s] the scene file asks for (``settings.dt``'s default where it names none)."""
    from laddermill_gym.ladder.scene import scene_path
    from laddermill_gym.model.configio import read_yaml
    from laddermill_gym.sim.simulator import IntegratorSettings

    data = read_yaml(scene_path(scene)).data.get("integrator") or {}
    return float(data.get("dt", IntegratorSettings().dt))


def element_rows(scene: str, duration: float) -> list[dict]:
    """Very long and very short elements: the scene's step against the estimate, and a run at half of it (each
    ``duration`` [s] or :data:`ELEMENT_RUN_STEPS` steps, whichever is shorter). A step that the scene's loader
    refuses (more than twice the stiffest element's closed-form bound, ``ladder/scene.py``) counts as detected;
    the scene is then loaded with a step below the bound to find its equilibrium."""
    if scene in CRAFT_NAMES:
        return []
    from laddermill_gym.ladder.scene import load_scene

    rows = []
    for n in (1, 8):
        refused = None
        try:
            with warnings.catch_warnings():  # the scene's step past the estimate is this case's finding (flagged)
                warnings.simplefilter("ignore", UnstableStepWarning)
                sim = build_simulator(scene, elements_per_piece=n)
        except ConfigError as e:
            if "cannot work with RK4" not in str(e):  # the scene's initial-state solver: a finding, a failed case
                rows.append(_row(f"{n} element(s) per piece", scene, passed=False,
                                 outcome=str(e).splitlines()[0][-160:]))
                continue
            refused = str(e).splitlines()[0]
            sim = load_scene(scene, elements_per_piece=n, dt=1e-6).simulator()
            sim = with_settings(sim, dt=_file_dt(scene, sim.settings))
        est = estimate_stable_step(sim, "rk4")
        flagged = refused is not None or sim.settings.dt > est.dt_max
        at_scene = ({"passed": False, "outcome": f"refused at load ({refused[refused.index('oscillates'):][:90]})"}
                    if refused else sc.run_for(with_settings(sim), min(duration, ELEMENT_RUN_STEPS * sim.settings.dt)))
        h = 0.5 * est.dt_max
        safe = sc.run_for(with_settings(sim, dt=h), min(duration, ELEMENT_RUN_STEPS * h))
        detected = at_scene["passed"] or flagged
        rows.append(_row(f"{n} element(s) per piece", scene, passed=bool(safe["passed"] and detected),
                         outcome=f"scene dt: {at_scene['outcome']}; half the estimate: {safe['outcome']}",
                         dt_scene_s=sim.settings.dt, dt_estimate_s=est.dt_max, scene_dt_flagged=flagged,
                         n_states=sim.n_state))
    return rows


def _ended_failures(info: dict, ended: np.ndarray) -> np.ndarray:
    """The failure codes of the copies that ended in a vector step: from ``final_info`` where the env puts the
    ended copies' step info there (Gymnasium's same-step autoreset), else from the step's own info, masked by its
    ``_failure`` (a copy reset in the step holds none of the step's keys)."""
    src = info.get("final_info") or info
    if "failure" not in src:
        return np.zeros(0, dtype=int)
    mask = ended & np.asarray(src.get("_failure", np.ones_like(ended)), dtype=bool)
    return np.asarray(src["failure"])[mask]


def episode_rows(env_id: str, episodes: int, episode_time: float, n_copies: int = 64) -> list[dict]:
    """Reset-and-run episodes of a vector env with random actions; counts each end by its failure code."""
    import gymnasium as gym

    from laddermill_gym.envs import register_envs
    from laddermill_gym.envs.task import FAILURES as WING_FAILURES

    register_envs()
    codes: dict[int, int] = {}
    done, err, env = 0, None, None
    try:
        env = gym.make_vec(env_id, num_envs=n_copies, vectorization_mode="vector_entry_point",
                           episode_time=episode_time)
        env.action_space.seed(0)
        env.reset(seed=0)
        while done < episodes:
            _, _, term, trunc, info = env.step(env.action_space.sample())
            ended = term | trunc
            for c in _ended_failures(info, ended):
                codes[int(c)] = codes.get(int(c), 0) + 1
            done += int(np.sum(ended))
    except Exception as e:  # a crash is what this case looks for: report it, do not hide it
        err = f"{type(e).__name__}: {e}"
    finally:
        if env is not None:
            env.close()
    names = dict(getattr(getattr(env, "task", None), "failure_names", None) or WING_FAILURES)
    solver = sorted(c for c, name in names.items() if "failed" in name)  # integration, rotor inflow
    passed = err is None and not any(codes.get(c, 0) for c in solver)
    ends = {(names.get(c) or "time limit"): n for c, n in sorted(codes.items())}
    return [_row(f"{done} env episodes", env_id, passed=passed, outcome=err or "ok", episode_time_s=episode_time,
                 ends=json.dumps(ends), solver_failure_codes=str(solver))]


def run_stress(scenes, hours: float, episodes: int, envs, quick: bool, progress: bool = True,
               rows: list | None = None) -> list[dict]:
    """Every case on every scene, then the env episodes; the rows of the table, appended to ``rows`` as each case
    ends (so a caller keeps the finished ones when the run is interrupted)."""
    dur = 4.0 if quick else 20.0
    rows = [] if rows is None else rows
    for scene in scenes:
        rows += sc.stable_step_rows(scene, horizon=2.0 if quick else 4.0, iters=5 if quick else 8)
        rows += long_run_rows(scene, 3600.0 * hours, progress)
        rows += wind_rows(scene, dur)
        rows += control_rows(scene, dur)
        rows += element_rows(scene, dur)
        rows += sc.injection_rows(scene)
    for env_id in envs:
        rows += episode_rows(env_id, episodes, 2.0 if quick else 5.0)
    return rows


def print_table(rows, echo=print) -> None:
    skip = {"case", "scene", "passed", "outcome"}
    for r in rows:
        figs = ", ".join(f"{k}={_fmt(v)}" for k, v in r.items() if k not in skip)
        echo(f"{'PASS' if r['passed'] else 'FAIL'}  {r['scene']:22s} {r['case']:28s} {r['outcome'][:90]}")
        if figs:
            echo(f"      {figs}")
    n_fail = sum(not r["passed"] for r in rows)
    echo(f"\n{len(rows) - n_fail} passed, {n_fail} failed")


def _fmt(v):
    if isinstance(v, (float, np.floating)):
        return "nan" if math.isnan(v) else f"{v:.4g}"
    return str(v)


#: env episodes per env: the default, and with --quick (an explicit --episodes wins over both)
EPISODES, QUICK_EPISODES = 10_000, 200


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("stress", help="numerical stress tests of the scenes and envs",
                       description=__doc__.replace("``", ""), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", nargs="*", default=list(DEFAULT_SCENES), help="scenes (default: all four)")
    p.add_argument("--hours", type=float, default=1.0, help="simulated time of the held run [h] (default 1)")
    p.add_argument("--episodes", type=int, default=None,
                   help=f"env episodes per env (default {EPISODES}, with --quick {QUICK_EPISODES}; given, it holds "
                        "with --quick too)")
    p.add_argument("--envs", nargs="*", default=["laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"])
    p.add_argument("--quick", action="store_true", help="short cases (the test suite's version)")
    p.add_argument("--out", default="results/stress", help="output folder")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.set_defaults(func=_cmd)
    return p


def check_options(args) -> int:
    """Refuse bad options before any case runs (UsageError naming the option and the value); the episodes."""
    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.studies.numerics.scenes import check_scene_names

    check_scene_names(args.scene)
    check_number("--hours", args.hours, low=0, high=1000, unit="h")
    check_number("--episodes", args.episodes, low=1, high=10**8, integer=True, strict=False)
    for env_id in args.envs:
        if env_id not in ENV_IDS:
            raise UsageError(f"--envs {env_id!r}: not a registered environment ({', '.join(sorted(ENV_IDS))})")
    return args.episodes if args.episodes is not None else QUICK_EPISODES if args.quick else EPISODES


def _cmd(args) -> int:
    episodes = check_options(args)
    out = writable_folder(args.out)  # a bad folder named before the episodes, not after them
    rows: list[dict] = []
    interrupted = False
    try:
        run_stress(args.scene, args.hours, episodes, args.envs, args.quick, not args.quiet, rows=rows)
    except KeyboardInterrupt:
        interrupted = True
    print_table(rows)
    keys = list(dict.fromkeys(k for r in rows for k in r))
    with open(out / "stress.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    (out / "stress.json").write_text(json.dumps(rows, indent=1, default=lambda v: v.item() if hasattr(v, "item")
                                                else str(v)))
    print(f"wrote {out / 'stress.csv'} and {out / 'stress.json'}")
    if interrupted:
        print(f"laddermill stress: interrupted (Ctrl-C): wrote the {len(rows)} cases that finished", file=sys.stderr)
        return 130
    return 0 if all(r["passed"] for r in rows) else 1


def main(argv=None) -> int:
    return run_subcommand(add_parser, "stress", argv)


if __name__ == "__main__":
    raise SystemExit(main())
