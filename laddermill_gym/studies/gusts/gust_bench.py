"""The scripted gust benchmark: run controllers on a versioned suite of named disturbance scenarios.

    laddermill gust-bench --suite gusts-v1 --env laddermill_gym/TetheredWing-v0 --controllers open_loop lqr runs/ppo_x
    python -m laddermill_gym.studies.gusts.gust_bench --suite gusts-v1 [--env ID ...] [--scenarios NAME ...] [--out DIR]
        [--workers N] [--ray auto|local|ADDRESS]

A suite (``configs/benchmarks/<name>.yaml``, read by :mod:`laddermill_gym.studies.gusts.gust_suite`) names, per
environment, scenarios of a disturbance list, a duration and seeds; every controller meets the same episodes
(same seeds, same wind). Per controller, scenario and seed: survived or the time and cause of failure, largest
and RMS lateral excursion [m], energy produced [J] and its ratio to the same controller's undisturbed run (same
seed and duration, no disturbance), peak tension over its limit, settling time [s] and control effort (RMS of
the action's deviation from the trim action). Writes ``gust_bench.csv``, ``gust_bench.json`` and a scorecard
figure per environment into ``--out`` (default ``results/gust_bench/<suite>``), merged into the results an earlier
run of the same suite file, package version and source left there (a row per env, scenario, controller and seed;
:mod:`laddermill_gym.studies.gusts.gust_results`); other results there are refused before any episode unless
``--force`` replaces them. Two controllers of one label (:func:`controller_label`) are refused. The episode sets
run serially, on ``--workers`` local processes or on Ray (:mod:`laddermill_gym.studies.parallel`,
docs/scale_out.md), with the same rows.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

from laddermill_gym.studies.commands import Command, UsageError, check_controllers, writable_folder
from laddermill_gym.studies.controller_specs import (
    CONFIG_PREFIXES,
    build_controllers,
    check_labels,
    controller_label,
    policy_env_kwargs,
    spec_path,
)
from laddermill_gym.studies.gusts.gust_results import earlier_rows, merge_rows, run_provenance, summarise, write_outputs
from laddermill_gym.studies.gusts.gust_suite import Scenario, Suite, load_suite
from laddermill_gym.studies.parallel import add_arguments, check_arguments, run_tasks

__all__ = ["controller_label", "absolute_spec", "run_episodes", "settling_time", "episode_metrics",
           "built_controller", "build_suite_controllers", "episodes_task", "warmup_tasks", "warmup_episode",
           "run_suite", "run_provenance", "summarise", "write_outputs", "add_parser", "main"]

#: The settling band's half width as a share of the excursion's largest deviation from its final value after the
#: disturbance's start (a 10 % band; chosen: the lateral motion of these systems is lightly damped).
SETTLE_BAND = 0.1
#: The band's least half width [m] (a floor for disturbances that hardly move the system).
SETTLE_FLOOR = 1e-3
#: The tail whose mean is the final value: this share of the time from the disturbance's start to the end.
SETTLE_TAIL = 0.1
#: A settled tail is level: a least-squares line through it changes by at most this share of the band's half
#: width across the tail (a steady drift, whose band grows with it, is not settled).
SETTLE_LEVEL = 0.5


def _lateral_fn(env, n: int, nw: int):
    if hasattr(env, "lateral_offsets"):
        return lambda o: np.asarray(env.lateral_offsets(o), dtype=float).reshape(n, -1)
    from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_INDEX

    return lambda o: o.reshape(n, nw, N_OBS_PER_WING)[:, :, OBS_INDEX["dy"]].astype(float)


def _nominal_action(task) -> np.ndarray:
    """The trim action (n_actions,) the control effort is measured from: the action map's ``nominal_action``, the
    task's ``trim_action``, else zeros (PumpingKite-v0: a = 0 is the reel-out trim with the winch stopped, so there
    the effort includes the cycle's winch commands)."""
    actions = getattr(task, "actions", None)
    if actions is not None and hasattr(actions, "nominal_action"):
        return np.asarray(actions.nominal_action, dtype=float)
    if hasattr(task, "trim_action"):
        return np.asarray(task.trim_action, dtype=float)
    return np.zeros(int(task.n_actions))


def _tension(info) -> np.ndarray:
    if "max_tension_N" in info:
        return np.asarray(info["max_tension_N"], dtype=float)
    return np.max(np.asarray(info["tether_tension_N"], dtype=float), axis=1)


def run_episodes(controller, env_id: str, env_kwargs: dict, seeds, duration: float, disturbances) -> dict:
    """One episode per seed (one vector-env copy each) of ``controller`` on ``env_id`` with ``env_kwargs``, the
    given ``disturbances`` (mappings) and ``duration`` [s]. Returns arrays over the copies: ``t_end`` [s],
    ``failure`` (code), ``cause`` (text), ``lateral`` (T + 1, n) largest |lateral offset| [m] (nan after the
    end), ``lateral_sq`` (n,) sum of the mean-square offsets, ``energy_J``, ``peak_tension_N``, ``effort_sq``
    (sum of mean-square action deviations), ``steps`` (n,), ``limit_N`` and ``control_dt`` [s]."""
    import gymnasium as gym

    n = len(seeds)
    kw = dict(env_kwargs, episode_time=float(duration), disturbances=[dict(d) for d in disturbances])
    env = gym.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **kw)
    task = env.task
    lateral = _lateral_fn(env, n, task.n_wings)
    nominal = _nominal_action(task)
    obs, _ = env.reset(seed=[int(s) for s in seeds])
    alive = np.ones(n, bool)
    out = {"t_end": np.zeros(n), "failure": np.zeros(n, int), "cause": [""] * n, "energy_J": np.zeros(n),
           "peak_tension_N": np.zeros(n), "lateral_sq": np.zeros(n), "effort_sq": np.zeros(n),
           "steps": np.zeros(n, int), "limit_N": float(task.breaking_tension), "control_dt": float(task.control_dt)}
    dy = lateral(obs)
    series = [np.max(np.abs(dy), axis=1)]
    while alive.any():
        a, _ = controller.predict(obs, deterministic=True)
        obs, _, term, trunc, info = env.step(a)
        dy = lateral(obs)
        dev = np.asarray(a, dtype=float).reshape(n, -1) - nominal
        out["energy_J"][alive] += task.control_dt * np.asarray(info["power_W"], dtype=float)[alive]
        out["peak_tension_N"][alive] = np.maximum(out["peak_tension_N"][alive], _tension(info)[alive])
        out["lateral_sq"][alive] += np.mean(dy ** 2, axis=1)[alive]
        out["effort_sq"][alive] += np.mean(dev ** 2, axis=1)[alive]
        out["steps"][alive] += 1
        series.append(np.where(alive, np.max(np.abs(dy), axis=1), np.nan))
        ended = alive & (term | trunc)
        for b in np.flatnonzero(ended):
            code = int(info["failure"][b])
            out["failure"][b], out["t_end"][b] = code, float(info["t"][b])
            out["cause"][b] = task.failure_text(int(b), code) if code else ""
        alive &= ~ended
    out["lateral"] = np.array(series)
    from laddermill_gym.envs.task import FAILURES

    out["failure_names"] = dict(getattr(env, "failure_names", None) or getattr(task, "failure_names", None)
                                or FAILURES)
    env.close()
    return out


def settling_time(series: np.ndarray, dt: float, start: float, duration: float) -> float:
    """Time [s] from ``start`` until the excursion e(t) (sampled every ``dt`` [s] from t = 0; nan after the end)
    enters, for good, the band around its final value: the final value is the mean of e over the tail (the last
    SETTLE_TAIL of the time from ``start`` to ``duration``, so a new equilibrium counts as settled), the band's half
    width SETTLE_BAND x the largest deviation of e from the final value after ``start``, at least SETTLE_FLOOR. nan
    (not settled) when e leaves the band in the tail, or when the tail is not level: a least-squares line through it
    changes by more than SETTLE_LEVEL x the band's half width across the tail (a steady drift, whose own growth sets
    the band, stays within it over the tail but has no final value)."""
    t = dt * np.arange(series.size)
    after = (t >= start) & np.isfinite(series)
    if not after.any():
        return math.nan
    ta, e = t[after], series[after]
    tail = ta >= start + (1.0 - SETTLE_TAIL) * (duration - start)
    final = float(np.mean(e[tail])) if tail.any() else float(e[-1])
    d = np.abs(e - final)
    band = max(SETTLE_BAND * float(np.max(d)), SETTLE_FLOOR)
    if tail.any() and float(np.max(d[tail])) > band:
        return math.nan
    if np.count_nonzero(tail) >= 2:
        slope = np.polyfit(ta[tail] - ta[tail][0], e[tail], 1)[0]
        if abs(slope) * float(ta[tail][-1] - ta[tail][0]) > SETTLE_LEVEL * band:
            return math.nan
    above = np.flatnonzero(d > band)
    return float(ta[above[-1]] - start + dt) if above.size else 0.0


def episode_metrics(rec: dict, ref_energy: np.ndarray, scenario: Scenario, names: dict) -> list[dict]:
    """The per-seed rows of one controller on one scenario (``rec`` from :func:`run_episodes`, ``ref_energy``
    the undisturbed runs' energies [J] per seed)."""
    rows = []
    dt = rec["control_dt"]
    for b, seed in enumerate(scenario.seeds):
        steps = max(int(rec["steps"][b]), 1)
        code = int(rec["failure"][b])
        survived = code == 0
        rows.append({
            "scenario": scenario.name, "seed": int(seed), "survived": survived,
            "t_end_s": float(rec["t_end"][b]),
            "failure": "" if survived else str(names.get(code, code)), "cause": rec["cause"][b],
            "max_lateral_m": float(np.nanmax(rec["lateral"][:, b])),
            "rms_lateral_m": math.sqrt(rec["lateral_sq"][b] / steps),
            "energy_J": float(rec["energy_J"][b]),
            "energy_ratio": float(rec["energy_J"][b] / ref_energy[b]) if ref_energy[b] != 0 else math.nan,
            "peak_tension_ratio": float(rec["peak_tension_N"][b] / rec["limit_N"]),
            "settling_time_s": settling_time(rec["lateral"][:, b], dt, scenario.start, scenario.duration)
            if survived else math.nan,
            "control_effort": math.sqrt(rec["effort_sq"][b] / steps),
        })
    return rows


def _jobs(suite: Suite, env_ids, controllers, scenarios) -> list[tuple]:
    """(env_id, env_kwargs with the policy's control settings (:func:`policy_env_kwargs`), controller spec,
    scenario) in the benchmark's order; UsageError for an env the suite lacks or a scenario an env named in
    ``env_ids`` lacks (with every env of the suite: a scenario is run where it is)."""
    named = bool(env_ids)
    env_ids = list(env_ids) or list(suite.envs)
    for e in env_ids:
        if e not in suite.envs:
            raise UsageError(f"--env {e!r}: suite {suite.name} has {sorted(suite.envs)}")
    jobs = []
    for env_id in env_ids:
        env_kwargs, scen = suite.envs[env_id]
        missing = sorted(set(scenarios or ()) - {s.name for s in scen})
        if missing and named:
            raise UsageError(f"--scenarios {missing}: not scenarios of {env_id} in suite {suite.name} "
                             f"({', '.join(s.name for s in scen)})")
        chosen = [s for s in scen if not scenarios or s.name in scenarios]
        for spec in controllers:
            kw = dict(env_kwargs, **policy_env_kwargs(spec, env_id))
            jobs += [(env_id, kw, spec, s) for s in chosen]
    return jobs


def absolute_spec(spec: str) -> str:
    """``spec`` with the file or folder it names made absolute (workers on Ray do not share the caller's working
    directory), resolved as ``make_controller`` resolves it: a shipped policy's name stays a name (the shipped policy,
    whatever the working directory holds); a config after a prefix (``lqr:``, ``lqr_guard:``, ``crosswind:``) is
    ``model.configio.config_path``'s file (a bare name, a path, the shipped file of a ``configs/...`` path); other
    specs as they are."""
    from laddermill_gym.model.configio import config_path

    for prefix in CONFIG_PREFIXES:
        if spec.startswith(prefix):
            path = config_path("agents", spec[len(prefix):])
            return prefix + str(path.resolve()) if path.is_file() else spec
    path = spec_path(spec)
    return str(path.resolve()) if path is not None and path.exists() and path == Path(spec) else spec


def warmup_tasks(suite: Suite, env_ids, controllers, scenarios=None, forget: bool = True) -> list[tuple]:
    """What a worker runs once before its first task (:mod:`laddermill_gym.studies.parallel`): per environment
    and controller a WARMUP_S episode without disturbance and, if a chosen scenario has a gust grid, one with
    the first such scenario's disturbances (numba compiles the grid-free and the grid code apart). This builds
    the worker's controllers and compiles, or loads from numba's cache, every kernel the tasks reach; first
    (``forget``) it drops the process's built controllers (:func:`forget_controllers`)."""
    from laddermill_gym.atmosphere.disturbance_spec import parse_disturbances
    from laddermill_gym.atmosphere.disturbances import grid_geometry

    tasks: list[tuple] = [(forget_controllers, {})] if forget else []
    seen = set()
    for env_id, kw, spec, s in _jobs(suite, env_ids, controllers, scenarios):
        spatial = grid_geometry(parse_disturbances(list(s.disturbances)), s.duration) is not None
        for dist in ((), s.disturbances) if spatial else ((),):
            key = (env_id, spec, bool(dist))
            if key not in seen:
                seen.add(key)
                tasks.append((warmup_episode, dict(env_id=env_id, env_kwargs=kw, spec=absolute_spec(spec),
                                                   seeds=(0,), duration=WARMUP_S, disturbances=dist)))
    return tasks


def warmup_episode(**task) -> dict:
    """:func:`episodes_task` cut to the warm-up's length: a disturbance that starts after it is expected there, so
    its LateDisturbanceWarning is not shown (the scenarios' own episodes warn as ever)."""
    import warnings

    from laddermill_gym.envs.task_base import LateDisturbanceWarning

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", LateDisturbanceWarning)
        return episodes_task(**task)


#: Length [s] of the warm-up episodes (several control steps of every environment).
WARMUP_S = 0.5

# Controllers as built, per (env id, spec, env kwargs), in this process (a worker builds each once).
_CONTROLLERS: dict = {}


def forget_controllers() -> None:
    """Drop this process's built controllers (a run starts from the files as they are now)."""
    _CONTROLLERS.clear()


def built_controller(spec: str, env_id: str, env_kwargs: dict):
    """The controller ``spec`` for ``env_id`` with ``env_kwargs`` (:func:`~laddermill_gym.control.factory.
    make_controller`), built once per process (kept until :func:`forget_controllers`)."""
    from laddermill_gym.control.factory import make_controller

    key = (env_id, spec, repr(sorted(env_kwargs.items())))
    if key not in _CONTROLLERS:
        _CONTROLLERS[key] = make_controller(spec, env_id, env_kwargs)
    return _CONTROLLERS[key]


def build_suite_controllers(suite: Suite, env_ids, controllers, scenarios=None, option: str | None = None) -> None:
    """Build every controller spec for every environment with a chosen scenario (as :func:`run_suite` chooses
    them) into this process's cache, emptied first (:func:`forget_controllers`), as the tasks will use them
    (:func:`built_controller`: absolute paths, the policy's control settings over the suite's env kwargs): a spec
    an environment refuses raises now, before any episode
    (:func:`~laddermill_gym.studies.controller_specs.build_controllers`; with ``option`` a one-line UsageError)."""
    forget_controllers()
    for env_id in list(env_ids) or list(suite.envs):
        env_kwargs, scen = suite.envs[env_id]
        if any(not scenarios or s.name in scenarios for s in scen):
            build_controllers(controllers, env_id, env_kwargs, option=option,
                              build=lambda spec, e, kw: built_controller(absolute_spec(spec), e, kw))


def episodes_task(env_id: str, env_kwargs: dict, spec: str, seeds, duration: float, disturbances) -> dict:
    """A picklable task: :func:`run_episodes` of the controller ``spec`` (built once per process and copied for
    every task, so a controller with internal state starts each task alike, whichever worker runs it)."""
    import copy

    ctrl = built_controller(spec, env_id, env_kwargs)
    return run_episodes(copy.deepcopy(ctrl), env_id, env_kwargs, seeds, duration, disturbances)


def run_suite(suite: Suite, env_ids, controllers, scenarios=None, progress: bool = True, workers: int = 0,
              ray: str | None = None, built: bool = False) -> list[dict]:
    """Every controller spec on every scenario of the chosen environments (all of the suite's if ``env_ids`` is
    empty; scenario names filtered by ``scenarios``); rows as :func:`episode_metrics` plus env and controller.

    The episode sets (each scenario's, and each undisturbed reference once per env, controller, duration and
    seeds) are independent tasks run by :func:`laddermill_gym.studies.parallel.run_tasks`: serially
    (``workers=0``), in ``workers`` local processes or on Ray (``ray``); the rows are the same either way.
    ``built``: the controllers were just built in this process (:func:`build_suite_controllers`), so a serial run
    uses them as they are instead of forgetting and building them again."""
    jobs = _jobs(suite, env_ids, controllers, scenarios)
    tasks, refs, runs = [], {}, []
    for env_id, kw, spec, s in jobs:
        base = dict(env_id=env_id, env_kwargs=kw, spec=absolute_spec(spec), seeds=s.seeds, duration=s.duration)
        ref_key = (env_id, spec, repr(sorted(kw.items())), s.duration, s.seeds)
        if ref_key not in refs:
            refs[ref_key] = len(tasks)
            tasks.append((episodes_task, dict(base, disturbances=())))
        runs.append((refs[ref_key], len(tasks)))
        tasks.append((episodes_task, dict(base, disturbances=s.disturbances)))
    warmup = warmup_tasks(suite, env_ids, controllers, scenarios, forget=not (built and not workers and ray is None))
    results = run_tasks(tasks, workers=workers, ray=ray, warmup=warmup, desc=f"gust-bench {suite.name}",
                        unit="episode set", progress=progress)
    rows = []
    for (env_id, _, spec, s), (i_ref, i_run) in zip(jobs, runs, strict=True):
        rec = results[i_run]
        for row in episode_metrics(rec, results[i_ref]["energy_J"], s, rec["failure_names"]):
            rows.append({"env": env_id, "controller": controller_label(spec), **row})
    return rows


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--suite", default="gusts-v1", help="suite name in configs/benchmarks/ or a YAML path")
    p.add_argument("--env", nargs="*", default=[], help="environment ids (default: all of the suite's)")
    p.add_argument("--controllers", nargs="+", default=["open_loop"],
                   help="open_loop, lqr, lqr:<config.yaml>, a shipped policy's name or a training run folder / model "
                   "file; each named once, no two with the same label in the rows")
    p.add_argument("--scenarios", nargs="*", default=[], help="scenario names (default: all)")
    p.add_argument("--out", type=Path, help="output folder (default results/gust_bench/<suite>); the rows of a run "
                   "merge into those an earlier run of the same suite, package version and source left there (a row "
                   "per env, scenario, controller and seed, this run's replacing the same), other results are refused")
    p.add_argument("--force", action="store_true", help="replace the results in --out instead of merging into them")
    add_arguments(p)


def _check_options(args) -> Suite:
    """The suite, after the options' checks that need no controller built (UsageError or ConfigError: one line)."""
    check_arguments(args, "laddermill gust-bench")
    check_controllers(args.controllers)
    if len(set(args.env)) != len(args.env):  # its rows would count twice in the summary
        raise UsageError(f"--env {sorted({e for e in args.env if args.env.count(e) > 1})}: named twice")
    check_labels(args.controllers)  # rows are keyed by label: two specs of one label would merge into one
    suite = load_suite(args.suite)
    _jobs(suite, args.env, [], args.scenarios)  # an unknown --env before any run
    names = {s.name for _, scen in suite.envs.values() for s in scen}
    unknown = sorted(set(args.scenarios) - names)
    if unknown:
        raise UsageError(f"--scenarios {unknown}: not scenarios of suite {suite.name} ({', '.join(sorted(names))})")
    return suite


def _run(args) -> int:
    suite = _check_options(args)
    out = args.out or Path("results") / "gust_bench" / suite.name
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out = {str(out)!r}: is a file, not a folder")
    earlier = earlier_rows(out, suite, args.env or list(suite.envs), args.force)  # refused before any episode
    # every controller built and checked against each env before any episode (a refused one: one line, exit 2).
    # Serially (--workers 0) the tasks then use these very controllers, at no extra cost; with --workers or --ray
    # each worker builds its own again, so this is a one-time extra cost there, paid for the early, clean error.
    build_suite_controllers(suite, args.env, args.controllers, args.scenarios, option="--controllers")
    out = writable_folder(out)  # before any episode
    try:
        rows = run_suite(suite, args.env, args.controllers, args.scenarios, workers=args.workers, ray=args.ray,
                         built=True)
    except ConnectionError as err:  # Ray's cluster not reached (ray.init): no episode has run
        if args.ray is None:
            raise
        raise UsageError(f"--ray {args.ray!r}: {err}") from None
    if args.force:  # the scorecards of envs the replaced results held
        for old in out.glob("scorecard_*.png"):
            old.unlink()
    for path in write_outputs(merge_rows(earlier, rows), suite, out):
        print(path)
    return 0


#: ``laddermill gust-bench``
COMMAND = Command("gust-bench", "run controllers on a versioned gust benchmark suite", __doc__.split("\n\n")[0],
                  _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
