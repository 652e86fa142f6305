"""Faster physics steps for the single-craft envs, and what each does to the gust scorecard (issue 32 point 2).

Point 2 asks TetheredWing-v0 for 400,000 env steps/s at 512 copies on two threads and Rotorcraft-v0 for 150,000;
their steps cost what their physics step's model evaluations cost (docs/benchmarks.md), so the way there is a
step with fewer of them. This measures, per env and per physics step (``METHOD:DT`` or ``METHOD:DT:K``, the labels of
:mod:`laddermill_gym.studies.gusts.step_convergence`), the native vector env's steps/s at ``--copies`` copies (all
steps of one env in one run, :func:`~laddermill_gym.studies.benchmarks.env_benchmark.bench_vector`) and the LQR's
gust scorecard against the finest step: whether the LQR loses the same scenarios and how far the ends of the episodes
lost on both move. A step that is fast but moves the scorecard changes what the env's benchmark measures.

    python -m laddermill_gym.studies.benchmarks.craft_step_options --quick

Defaults: TetheredWing-v1 against RK4 at 3.125 ms, Rotorcraft-v0 against RK4 at 1.5625 ms, gusts-v4's scenarios.
"""

from __future__ import annotations

import argparse

from laddermill_gym.studies.gusts.step_convergence import parse_step, scorecards

__all__ = ["STEPS", "step_options", "main"]

#: per env id: (the reference step, the steps compared); the first compared step is the id's registered one
STEPS = {
    "laddermill_gym/TetheredWing-v1": ("rk4:0.003125", ("rk4:0.025", "ros34pw2:0.05", "rk4:0.05", "ros2:0.05",
                                                        "ros2:0.05:2", "ros2:0.05:4")),
    "laddermill_gym/Rotorcraft-v0": ("rk4:0.0015625", ("ros34pw2:0.05", "ros2:0.05", "ros2:0.05:2", "ros2:0.05:4",
                                                       "ros2:0.05:8")),
}


def _card(count: tuple[int, int]) -> str:
    return f"{count[0]} / {count[1]}"


def step_options(env_ids=tuple(STEPS), copies: int = 512, quick: bool = False, suite: str = "gusts-v4",
                 echo=print) -> dict:
    """{env id: {step label: {"steps_per_s", "lqr_count", "same_scenarios", "largest_shift_s"}}} for every step of
    :data:`STEPS` of each env: its throughput at ``copies`` copies and its LQR scorecard against the reference."""
    from laddermill_gym.studies.benchmarks.env_benchmark import bench_vector

    out = {}
    for env_id in env_ids:
        ref, steps = STEPS[env_id]
        rows = bench_vector(env_id, counts=(copies,), quick=quick, echo=lambda *a: None,
                            variants={label: parse_step(label) for label in steps})
        rates = {k: v["steps_per_s"] for k, v in rows[0]["variants"].items()}
        cards = scorecards(suite, env_id, ["lqr"], [ref, *steps], echo=lambda *a: None)
        echo(f"{env_id}, {copies} copies (the LQR on {suite} against {ref}: "
             f"{_card(cards[ref]['counts']['lqr'])}):")
        res = {}
        for label in steps:
            c = cards[label]
            res[label] = {"steps_per_s": rates[label], "lqr_count": c["counts"]["lqr"],
                          "same_scenarios": c["same_scenarios"], "largest_shift_s": c["largest_shift_s"]}
            verdict = "the same scenarios lost" if c["same_scenarios"] else "OTHER scenarios lost"
            echo(f"  {label:14s} {rates[label]:10,.0f} steps/s   the LQR {_card(c['counts']['lqr'])}, {verdict}, "
                 f"ends of the episodes lost on both within {c['largest_shift_s']:.2f} s")
        out[env_id] = res
    return out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--envs", nargs="+", default=list(STEPS), choices=list(STEPS), help="env ids (default: both)")
    p.add_argument("--copies", type=int, default=512, help="copies of the native vector env (default 512)")
    p.add_argument("--quick", action="store_true", help="fewer repetitions of the throughput runs")
    p.add_argument("--suite", default="gusts-v4", help="gust suite (default gusts-v4)")
    a = p.parse_args(argv)
    if a.copies < 1:
        p.error(f"--copies = {a.copies}: must be a positive integer")
    step_options(a.envs, a.copies, a.quick, a.suite)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
