"""A gust scorecard against the physics step: do its episodes end as they do on a finer step?

A turbulent gust-bench episode can end or survive by a hair (docs/controllers.md), and an integrator's error moves
such an episode as the machine's last bits do. This flies a suite's scenarios of one env id with each physics step of
``--steps`` (``METHOD:DT``: the env's ``physics_step`` and ``physics_dt`` [s], ``METHOD:DT:K`` with the W-method's
matrix kept K steps, ``jacobian_every``; the first is the reference, so give the
finest first) and prints, per step and controller, the scenarios survived on every seed and the episodes lost (with
the time they ended), and against the reference whether the same episodes are lost and how far apart their ends are.
A step whose scorecard is the reference's within a fraction of a second decides nothing by its own error.

    python -m laddermill_gym.studies.gusts.step_convergence --suite gusts-v4 --env laddermill_gym/TetheredWing-v1 \\
        --controllers lqr ppo_tethered_wing --steps rk4:0.003125 rk4:0.0125 rk4:0.025 rk4:0.05 ros34pw2:0.00625 \\
        ros34pw2:0.0125 ros34pw2:0.05 ros2:0.05

The env must take ``physics_step`` (TetheredWing-v1, Rotorcraft-v0 and the ids that register one; TetheredWing-v0
names its method in its scene options: its step is TetheredWing-v1's ``ros34pw2:0.05``).
"""

from __future__ import annotations

import argparse
import dataclasses

from laddermill_gym.envs.physics_step import check_physics_step
from laddermill_gym.sim.breakpoints import W_METHODS

__all__ = ["parse_step", "lost_episodes", "lost_scenarios", "survived_count", "scorecards", "main"]


def parse_step(label: str) -> dict:
    """The env arguments of ``METHOD:DT`` (``rk4:0.025``) or ``METHOD:DT:K`` (``ros2:0.05:4``): ``physics_step``,
    ``physics_dt`` [s] and ``jacobian_every`` (K, a W-method's iteration matrix kept K steps; default 1). ValueError
    naming the label for another form, an unknown method, a step that is not a number > 0 or a K below 1."""
    method, _, rest = label.partition(":")
    dt, _, every = rest.partition(":")
    try:
        step = float(dt)
    except ValueError:
        step = -1.0
    if not step > 0.0 or (every and not (every.isdigit() and int(every) >= 1)):
        raise ValueError(f"physics step {label!r}: write METHOD:DT or METHOD:DT:K, DT the step in s > 0 and K >= 1 "
                         "steps per Jacobian (rk4:0.025, ros2:0.05:4)")
    check_physics_step(method)
    k = int(every) if every else 1
    if k > 1 and method not in W_METHODS:
        raise ValueError(f"physics step {label!r}: only a W-method keeps its Jacobian ({', '.join(W_METHODS)})")
    return {"physics_step": method, "physics_dt": step, "jacobian_every": k}


def lost_episodes(rows: list[dict]) -> dict:
    """{(controller, scenario, seed): end time [s]} of the rows' episodes that did not survive."""
    return {(r["controller"], r["scenario"], int(r["seed"])): float(r["t_end_s"]) for r in rows if not r["survived"]}


def lost_scenarios(lost: dict) -> set:
    """{(controller, scenario)} of :func:`lost_episodes`' keys: the scenarios a controller does not survive."""
    return {(c, s) for c, s, _ in lost}


def survived_count(rows: list[dict], controller: str) -> tuple[int, int]:
    """(scenarios survived on every seed, scenarios) of one controller's rows."""
    by: dict[str, bool] = {}
    for r in rows:
        if r["controller"] == controller:
            by[r["scenario"]] = by.get(r["scenario"], True) and bool(r["survived"])
    return sum(by.values()), len(by)


def scorecards(suite_name: str, env_id: str, controllers, steps, echo=print) -> dict:
    """{step label: {"rows", "counts": {controller: (survived, scenarios)}, "same_scenarios", "same_lost",
    "largest_shift_s"}} of the suite's scenarios of ``env_id`` on each physics step of ``steps`` (the first the
    reference), printed as it goes: whether every controller loses the reference's scenarios, whether the same
    episodes end, and the largest difference of the end times of episodes lost on both [s]."""
    from laddermill_gym.studies.gusts.gust_bench import controller_label, run_suite
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    step_args = {label: parse_step(label) for label in steps}
    suite = load_suite(suite_name)
    if env_id not in suite.envs:
        raise ValueError(f"env = {env_id!r}: not in suite {suite.name} ({', '.join(sorted(suite.envs))})")
    from laddermill_gym.envs import env_arguments

    if "physics_step" not in env_arguments(env_id):  # the point-mass and pumping envs step their own way
        raise ValueError(f"env = {env_id!r}: takes no physics_step, so its scorecard cannot be flown on other steps")
    kwargs, scenarios = suite.envs[env_id]
    longest = max(s.duration for s in scenarios)
    for label, args in step_args.items():  # a step too fine to finish is named before any episode
        from laddermill_gym.sim.recording import check_step_count

        note = check_step_count(args["physics_dt"], longest, f"--steps {label}: the step")
        if note:
            echo(f"warning: {note}")
    labels = [controller_label(c) for c in controllers]
    echo(f"{suite.name}, {env_id}: {len(scenarios)} scenarios; reference step {steps[0]}")
    out, ref = {}, None
    for label, args in step_args.items():
        one = dataclasses.replace(suite, envs={env_id: ({**kwargs, **args}, scenarios)})
        rows = run_suite(one, [env_id], list(controllers), progress=True)
        lost = lost_episodes(rows)
        ref = lost if ref is None else ref
        common = set(lost) & set(ref)
        shift = max((abs(lost[k] - ref[k]) for k in common), default=0.0)
        res = {"rows": rows, "counts": {c: survived_count(rows, c) for c in labels},
               "same_scenarios": lost_scenarios(lost) == lost_scenarios(ref), "same_lost": set(lost) == set(ref),
               "largest_shift_s": shift}
        out[label] = res
        echo(f"  {label}:")
        for c in labels:
            ok, n = res["counts"][c]
            mine = sorted((s, seed, t) for (cc, s, seed), t in lost.items() if cc == c)
            text = ", ".join(f"{s} seed {seed} at {t:.2f} s" for s, seed, t in mine) or "none"
            echo(f"    {c}: {ok} / {n}; lost {text}")
        if label != steps[0]:
            scen = ("the same scenarios lost by every controller" if res["same_scenarios"] else
                    "OTHER scenarios lost")
            verdict = ("the same episodes" if res["same_lost"] else
                       f"episodes: {len(set(lost) - set(ref))} more lost, {len(set(ref) - set(lost))} fewer")
            echo(f"    against {steps[0]}: {scen}; {verdict}; the episodes lost on both end within {shift:.2f} s")
    return out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--suite", default="gusts-v4", help="suite name in configs/benchmarks/ or a YAML path")
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v1", help="one env id of the suite")
    p.add_argument("--controllers", nargs="+", default=["lqr"], help="controller specs (lqr, ppo_tethered_wing)")
    p.add_argument("--steps", nargs="+", required=True,
                   help="METHOD:DT or METHOD:DT:K physics steps, the reference (finest) first")
    a = p.parse_args(argv)
    try:
        for label in a.steps:
            parse_step(label)
        scorecards(a.suite, a.env, a.controllers, a.steps)
    except ValueError as err:
        p.error(str(err))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
