"""Evaluate controllers of the harness on N seeded episodes of a registered scenario; CSV tables and plots.

    laddermill evaluate --env laddermill_gym/TetheredWing-v0 --controllers open_loop lqr runs/ppo \
        [--episodes 4] [--episode-time 300] [--direction-step 0.01] [--out results/tethered_wing]

Controllers: ``open_loop``, ``lqr`` (the environment's default design), ``lqr:<config.yaml>`` or the path of an
SB3 training run (its best model) or model file (``<run>/model.zip`` for the last one), or an rl-zoo3 log folder
``logs/<algo>/<env name>_<n>`` (its last model and ``vecnormalize.pkl``; docs/rl_zoo3.md); see
:mod:`laddermill_gym.control.factory`. Episode i uses seed i, so every
controller meets the same disturbances. Writes ``summary.csv`` (one row per controller and episode: return,
length [s], failure, mean power [W], largest lateral excursion [m], share of clipped action entries),
``lateral.csv`` (controller, t, wing, lateral offset of episode 0) and ``lateral.png``. On Rotorcraft-v0 the
"wing" is the craft (one lateral CG offset) and the failure names are the craft's. No evaluation replaces another's
tables unasked: an ``--out`` that holds them is refused (``--force`` replaces them), and without ``--out`` the tables
go to ``results/<env name>``, or ``results/<env name>_2``, ``_3``, ... when that holds an earlier evaluation's.
"""

from __future__ import annotations

import csv
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.atmosphere.disturbances import DirectionStep, OneMinusCosineGust
from laddermill_gym.envs import ENV_IDS
from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_INDEX
from laddermill_gym.envs.task import FAILURES
from laddermill_gym.studies.commands import Parser, UsageError, check_controllers, check_number
from laddermill_gym.studies.controller_specs import build_controllers, check_labels, controller_label, policy_env_kwargs

__all__ = ["SCENARIOS", "EpisodeResults", "run_episodes", "write_tables", "plot_results", "controller_label",
           "check_env_kwargs", "vector_env", "policy_env_kwargs", "build_controllers", "evaluate", "output_folder",
           "RESULT_FILES", "main"]

#: Named evaluation scenarios (disturbance lists); "paper_step" is the registered default of the environments
SCENARIOS = {
    "paper_step": [DirectionStep(step=0.01)],
    "step_minus_0.05": [DirectionStep(step=-0.05)],
    "step_0.1": [DirectionStep(step=0.1)],
    "gust": [OneMinusCosineGust(amplitude=0.3, duration=10.0, time=5.0, direction_amplitude=0.05)],
}


@dataclass
class EpisodeResults:
    """Per-episode figures of one controller (n episodes, n_wings wings, T control periods).

    returns (n,) [-];  lengths_s (n,) [s];  failures (n,) failure codes (0 = ran to the time limit);
    mean_power_W (n,);  max_lateral_m (n, n_wings) largest |lateral offset| of every wing;
    clipped_fraction (n,) share of action entries outside [-1, 1];
    t (T + 1,) [s] and lateral_m (n, T + 1, n_wings) lateral offsets (nan after an episode ended), if recorded;
    failure_names: failure code -> name of the environment (the wings' :data:`FAILURES` or the craft's);
    failure_reasons (n,) the env's ``info["failure_reason"]`` at the episode's end (time, body, quantity, value;
    "" where it ran to the time limit).
    """

    returns: np.ndarray
    lengths_s: np.ndarray
    failures: np.ndarray
    mean_power_W: np.ndarray
    max_lateral_m: np.ndarray
    clipped_fraction: np.ndarray
    t: np.ndarray | None = None
    lateral_m: np.ndarray | None = None
    failure_names: dict[int, str] = field(default_factory=lambda: dict(FAILURES))
    failure_reasons: list[str] | None = None


def run_episodes(controller, env, n_episodes: int | None = None, record: bool = True,
                 progress: bool = False) -> EpisodeResults:
    """Run ``controller`` deterministically on every copy of the native vector env ``env`` (:func:`vector_env`:
    :class:`~laddermill_gym.envs.wing_env.WingVectorEnv` or
    :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftVectorEnv`, seeds 0 .. num_envs - 1), each copy to
    the end of its first episode. The lateral offsets come from ``env.lateral_offsets(obs)`` where the env has
    it, else from the wing observation layout."""
    n = env.num_envs
    if n_episodes is not None and n_episodes != n:
        raise ValueError(f"n_episodes = {n_episodes}: the env has {n} copies")
    task = env.task
    nw = task.n_wings
    lateral = getattr(env, "lateral_offsets", None) or (
        lambda o: o.reshape(n, nw, N_OBS_PER_WING)[:, :, OBS_INDEX["dy"]].astype(float))
    obs, _ = env.reset(seed=list(range(n)))
    alive = np.ones(n, bool)
    ret, power, steps, clipped = np.zeros(n), np.zeros(n), np.zeros(n, int), np.zeros(n)
    failures = np.zeros(n, int)
    reasons = [""] * n
    lengths = np.zeros(n)
    dy0 = lateral(obs)
    max_lat = np.abs(dy0)
    series = [dy0] if record else None
    bar = tqdm(total=task.n_steps_max, unit="step", disable=not progress, leave=False)
    while alive.any():
        a, _ = controller.predict(obs, deterministic=True)
        obs, r, term, trunc, info = env.step(a)
        dy = lateral(obs)
        ret[alive] += r[alive]
        power[alive] += info["power_W"][alive]
        clipped[alive] += info["n_clipped"][alive]
        steps[alive] += 1
        max_lat[alive] = np.maximum(max_lat[alive], np.abs(dy[alive]))
        if record:
            series.append(np.where(alive[:, None], dy, np.nan))
        ended = alive & (term | trunc)
        failures[ended] = info["failure"][ended]
        for i in np.flatnonzero(ended & (info["failure"] != 0)):
            reasons[i] = str(info["failure_reason"][i])
        lengths[ended] = info["t"][ended]
        alive &= ~ended
        bar.update(1)
    bar.close()
    out = EpisodeResults(returns=ret, lengths_s=lengths, failures=failures, mean_power_W=power / np.maximum(steps, 1),
                         max_lateral_m=max_lat, clipped_fraction=clipped / np.maximum(steps * task.n_actions, 1),
                         failure_names=dict(getattr(env, "failure_names", FAILURES)), failure_reasons=reasons)
    if record:
        lat = np.stack(series, axis=1)
        out.t = task.control_dt * np.arange(lat.shape[1])
        out.lateral_m = lat
    return out


def write_tables(out: Path, results: dict[str, EpisodeResults]) -> None:
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "summary.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["controller", "seed", "return", "length_s", "failure", "mean_power_W", "max_lateral_m",
                    "clipped_fraction", "failure_reason"])
        for name, res in results.items():
            for i in range(len(res.returns)):
                fail = res.failure_names[int(res.failures[i])]
                w.writerow([name, i, f"{res.returns[i]:.4f}", f"{res.lengths_s[i]:.2f}", fail,
                            f"{res.mean_power_W[i]:.1f}", f"{res.max_lateral_m[i].max():.4f}",
                            f"{res.clipped_fraction[i]:.4f}", res.failure_reasons[i] if res.failure_reasons else ""])
    with open(out / "lateral.csv", "w", newline="") as fh:  # long format: the episodes end at different times
        w = csv.writer(fh)
        w.writerow(["controller", "t_s", "wing", "dy_m"])
        for name, res in results.items():
            for j, t in enumerate(res.t):
                row = res.lateral_m[0, j]
                if np.isnan(row).all():
                    break
                w.writerows([name, f"{t:.3f}", k, f"{v:.5g}"] for k, v in enumerate(row))


def plot_results(out: Path, results: dict[str, EpisodeResults], title: str) -> Path:
    """Lateral offset against time (episode 0) per controller; for chains also the largest excursion of
    every wing over the episode."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    first = next(iter(results.values()))
    nw = first.lateral_m.shape[2]
    ncol = 1 if nw == 1 else 2
    fig, axes = subplots(1, ncol, figsize=(6.5 * ncol, 4), squeeze=False)
    ax = axes[0, 0]
    for i, (name, res) in enumerate(results.items()):
        for k in range(nw):
            ax.plot(res.t, res.lateral_m[0, :, k], color=f"C{i}", lw=1.2 if nw == 1 else 0.4,
                    label=name if k == 0 else None)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("lateral offset dy [m]" + ("" if nw == 1 else " (every wing)"))
    peak = max(float(np.nanmax(np.abs(r.lateral_m[0]), initial=0.0)) for r in results.values())
    if peak > 1.0:  # decades apart (a crash beside a held wing): symlog; below, its locator gave two odd ticks
        ax.set_yscale("symlog", linthresh=0.1)
    ax.grid(alpha=0.3)
    ax.legend()
    if nw > 1:
        ax = axes[0, 1]
        for i, (name, res) in enumerate(results.items()):
            ax.plot(np.arange(nw), res.max_lateral_m[0], "o-", ms=2, color=f"C{i}", label=name)
        ax.set_xlabel("slot (0: lowest ascending, veered side; the wing in it changes at each transfer)"
                      if "LadderMill" in title else "wing index (0 at the hauled end)")
        ax.set_ylabel("largest |dy| over the episode [m]")
        ax.set_yscale("log")
        ax.grid(alpha=0.3)
        ax.legend()
    fig.suptitle(title, fontsize=10)
    return save_figure(fig, out / "lateral.png")


def check_env_kwargs(env_id: str, env_kwargs: dict) -> None:
    """ValueError naming an argument (and its value) that the registered environment ``env_id`` does not take,
    e.g. a scenario's ``disturbances`` or ``episode_time`` for an environment without them."""
    from laddermill_gym.envs import env_arguments

    known = env_arguments(env_id)
    for key, value in env_kwargs.items():
        if key not in known:
            raise ValueError(f"{key} = {value!r}: {env_id} takes no such argument (known: {', '.join(known)})")


def vector_env(env_id: str, n: int, env_kwargs: dict):
    """``n`` copies of the registered environment ``env_id`` (arguments ``env_kwargs`` over the registered ones,
    checked by :func:`check_env_kwargs`): its native vector env (Gymnasium's ``vector_entry_point``), stepped by
    one compiled kernel."""
    import gymnasium as gym

    check_env_kwargs(env_id, env_kwargs)
    kw = dict(ENV_IDS[env_id], **env_kwargs)
    return gym.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **kw)


def evaluate(env_id: str, controllers: list[str], episodes: int, env_kwargs: dict, out: Path,
             progress: bool = True, built: dict | None = None) -> dict[str, EpisodeResults]:
    """Run every controller spec on ``episodes`` seeded episodes (seeds 0 .. episodes - 1) of ``env_id`` with
    arguments ``env_kwargs`` (episode_time [s], disturbances) and write the tables into ``out``. Every controller is
    built (:func:`build_controllers`, each on ``env_kwargs`` with its policy's settings) before the first episode,
    so a spec the environment refuses raises (ValueError, FileNotFoundError) before any runs, and so do a spec named
    twice and two specs of the same label (UsageError, :func:`~laddermill_gym.studies.controller_specs.check_labels`);
    ``built``: those already built by :func:`build_controllers` for these arguments (the command line builds them
    first)."""
    check_labels(controllers)  # results are keyed by label: none may hide another
    if built is None:
        built = build_controllers(controllers, env_id, env_kwargs)
    results = {}
    for spec in controllers:
        ctrl, kw = built[spec]
        env = vector_env(env_id, episodes, kw)
        results[controller_label(spec)] = run_episodes(ctrl, env, progress=progress)
        env.close()
    write_tables(out, results)
    return results


#: the files :func:`write_tables` and :func:`plot_results` write into a folder
RESULT_FILES = ("summary.csv", "lateral.csv", "lateral.png")


def _arguments(p: Parser) -> None:
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0", choices=sorted(ENV_IDS), metavar="ID",
                   help="a registered id (default laddermill_gym/TetheredWing-v0; a shipped policy's own id for it: "
                        "--env laddermill_gym/LadderMill-v1 --controllers ppo_mill)")
    p.add_argument("--controllers", nargs="+", default=["open_loop", "lqr"],
                   help="each one of: open_loop (trim controls held); lqr (the environment's default design in "
                   "configs/agents/lqr_<scene>.yaml); lqr:PATH (an LQR config file); a shipped policy's name; a "
                   "training run folder (its best model, with its VecNormalize statistics), a model .zip file, or an "
                   "rl-zoo3 log folder logs/<algo>/<env name>_<n> (its last model and statistics); each named once, "
                   "no two with the same label in the tables (default: open_loop lqr)")
    p.add_argument("--episodes", type=int, default=4, help="seeded episodes per controller (seeds 0..n-1)")
    p.add_argument("--episode-time", type=float, help="[s] episode length, a whole number of control periods "
                   "(default: the environment's)")
    p.add_argument("--direction-step", type=float, help="[rad] wind-direction step at t = 1 s (default: the "
                   "environment's, 0.01 rad)")
    p.add_argument("--scenario", choices=sorted(SCENARIOS), help="a named disturbance: paper_step (0.01 rad "
                   "direction step at 1 s), step_minus_0.05, step_0.1, gust (1-cosine, +30 %% speed and 0.05 rad "
                   "direction over 10 s from t = 5 s)")
    p.add_argument("--out", type=Path, help="output folder; one holding an evaluation's tables is refused unless "
                   "--force (default results/<env name>, or results/<env name>_2, _3, ... when that holds one)")
    p.add_argument("--force", action="store_true", help="replace the tables an earlier evaluation left in --out")


def _held(folder: Path) -> list[str]:
    """The evaluation's tables and figure (:data:`RESULT_FILES`) that ``folder`` holds."""
    return [f for f in RESULT_FILES if (folder / f).exists()]


def output_folder(out: Path | None, env_id: str, force: bool = False) -> Path:
    """The folder an evaluation writes into, checked before any episode (not created): ``out`` (UsageError when it
    is a file, or holds :data:`RESULT_FILES` and not ``force``), or by default ``results/<env name>``, or the first
    of ``results/<env name>_2``, ``_3``, ... that holds none of them (``force``: ``results/<env name>`` always), so
    that no evaluation silently replaces another's tables."""
    if out is not None:
        if out.exists() and not out.is_dir():
            raise UsageError(f"--out = {str(out)!r}: is a file, not a folder")
        if _held(out) and not force:
            raise UsageError(f"--out = {str(out)!r}: holds an evaluation's tables already ({', '.join(_held(out))}); "
                             "give another --out, or --force to replace them")
        return out
    base = Path("results") / env_id.split("/")[-1]
    folder, k = base, 1
    while not force and (_held(folder) or (folder.exists() and not folder.is_dir())):
        k += 1
        folder = base.with_name(f"{base.name}_{k}")
    return folder


def _env_kwargs(args, p: Parser) -> dict:
    """The env arguments of the options (checked: UsageError naming the option)."""
    check_number("--episodes", args.episodes, low=1, high=4096, integer=True, strict=False)  # copies of one env
    check_number("--episode-time", args.episode_time, low=0, high=86400, unit="s")
    check_number("--direction-step", args.direction_step, low=-3.15, high=3.15, unit="rad")
    env_kwargs = {}
    if args.episode_time is not None:
        env_kwargs["episode_time"] = args.episode_time
    if args.direction_step is not None and args.scenario is not None:
        p.error("--direction-step and --scenario exclude each other")
    if args.direction_step is not None:
        env_kwargs["disturbances"] = [DirectionStep(step=args.direction_step)]
    if args.scenario is not None:
        env_kwargs["disturbances"] = SCENARIOS[args.scenario]
    try:
        check_env_kwargs(args.env, env_kwargs)
    except ValueError as err:
        raise UsageError(str(err)) from None
    return env_kwargs


def _check_episodes(env_id: str, built: dict) -> None:
    """UsageError naming ``--episode-time`` (and the controller whose settings make it so) for an episode that is
    not a whole number of control periods (``envs.episode_argument_error``, as the suite reader applies it)."""
    from laddermill_gym.envs import episode_argument_error

    for spec, (_, kw) in built.items():
        why = episode_argument_error(env_id, kw)
        if why:
            whose = f" with the control period of {spec!r}" if "control_dt" in policy_env_kwargs(spec, env_id) else ""
            what = "the env's episode_time" if kw.get("episode_time") is None else "--episode-time = " \
                f"{kw['episode_time']!r}"
            raise UsageError(f"{what}{whose}: {why}")


def main(argv: list[str] | None = None) -> int:
    from laddermill_gym.studies.commands import writable_folder

    p = Parser(prog="laddermill evaluate", description=__doc__.split("\n\n")[0])
    _arguments(p)
    args = p.parse_args(argv)
    env_kwargs = _env_kwargs(args, p)
    check_controllers(args.controllers)
    check_labels(args.controllers)
    out = output_folder(args.out, args.env, args.force)
    # every controller built and checked against the env before any episode: a refused one is one line, exit 2
    built = build_controllers(args.controllers, args.env, env_kwargs, option="--controllers")
    _check_episodes(args.env, built)
    out = writable_folder(out)  # created now, before any episode
    results = evaluate(args.env, args.controllers, args.episodes, env_kwargs, out, built=built)
    fig = plot_results(out, results, f"{args.env}: {args.episodes} episode(s), lateral offset (episode 0)")
    print(f"{'controller':<28} {'return':>10} {'length [s]':>11} {'max |dy| [m]':>13} {'power [W]':>10}  failures")
    for spec, res in results.items():
        fails = sorted({res.failure_names[int(c)] for c in res.failures if c})
        print(f"{spec:<28} {np.mean(res.returns):10.2f} {np.mean(res.lengths_s):11.1f} "
              f"{np.max(res.max_lateral_m):13.4f} {np.mean(res.mean_power_W):10.1f}  {', '.join(fails) or '-'}")
    print(f"tables in {out}/summary.csv, {out}/lateral.csv; figure {fig}")
    return 0


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    sys.exit(run_guarded("evaluate", main))
