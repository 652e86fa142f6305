"""One benchmark episode flown by one controller up to a time and by another after it (a hand-over test).

Where two controllers differ on a scenario (one survives, the other not), handing over at several times tells
whether the difference is in the state the first one leaves (the second cannot recover from it) or in the
recovery (the second recovers from the first's state), or neither: when the outcome flips with the hand-over time
in no order, the episode is on a knife edge (chaotic), and one seed of it does not rank the controllers.

    python -m laddermill_gym.studies.gusts.switch_controllers --scenario NTM_IB --seed 0 \\
        --controllers ppo_tethered_wing lqr --times 10 18 20 21 21.5 22 22.5
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

__all__ = ["Handover", "SUITE", "scenario", "handover_outcomes", "main"]

#: the suite whose scenarios the hand-overs fly (a name of ``configs/benchmarks/``, read by ``gust_suite.load_suite``)
SUITE = "gusts-v1"


class Handover:
    """``predict`` of ``first`` for the first ``steps`` calls, of ``second`` after (one episode at a time)."""

    def __init__(self, first, second, steps: int):
        self.first, self.second, self.steps, self.calls = first, second, int(steps), 0

    def predict(self, observation, state=None, episode_start=None, deterministic=True):
        ctrl = self.first if self.calls < self.steps else self.second
        self.calls += 1
        return ctrl.predict(observation, deterministic=True)


def scenario(env_id: str, name: str, suite: str | Path = SUITE) -> dict:
    """The scenario ``name`` of ``env_id`` in ``suite`` (a shipped suite's name or a YAML path, read and checked by
    ``gust_suite.load_suite``) as a mapping (``name``, ``start``, ``duration``, ``seeds``, ``disturbances``) with
    the suite's ``env_kwargs`` for the env; ValueError naming the suite and the names."""
    from dataclasses import asdict

    from laddermill_gym.studies.gusts.gust_suite import load_suite

    s = load_suite(suite)
    env_kwargs, scenarios = s.envs.get(env_id, ({}, ()))
    found = {sc.name: sc for sc in scenarios}
    if name not in found:
        raise ValueError(f"{s.path}: no scenario {name!r} for {env_id} (scenarios: {sorted(found)})")
    return dict(asdict(found[name]), env_kwargs=dict(env_kwargs))


def handover_outcomes(env_id: str, name: str, seed: int, controllers: list[str], times: list[float],
                      suite: str | Path = SUITE) -> list:
    """(hand-over time [s], failure code, end time [s]) of ``controllers[0]`` handing over to ``controllers[1]``
    at each of ``times`` on seed ``seed`` of the scenario ``name`` of ``suite``. Both are built before any episode
    as gust-bench builds them (``controller_specs.build_controllers``: the suite's env arguments with a policy's
    control settings over them); ValueError when the two need different env arguments (one env flies both)."""
    import gymnasium as gym

    from laddermill_gym.studies.controller_specs import build_controllers
    from laddermill_gym.studies.gusts.gust_bench import run_episodes

    sc = scenario(env_id, name, suite)
    built = build_controllers(controllers, env_id, sc["env_kwargs"])
    (first, kw), (second, kw2) = (built[c] for c in controllers)
    if kw != kw2:
        raise ValueError(f"controllers {controllers}: fly on different env arguments ({kw} and {kw2}); one episode "
                         "needs one env")
    env = gym.make(env_id, **kw)
    dt = float(env.unwrapped.task.control_dt)  # [s] the control period
    env.close()
    rows = []
    for t in times:
        steps = round(float(t) / dt)
        rec = run_episodes(Handover(first, second, steps), env_id, kw, [seed], sc["duration"], sc["disturbances"])
        rows.append((float(t), int(rec["failure"][0]), float(rec["t_end"][0])))
    return rows


def main(argv: list[str] | None = None) -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0")
    p.add_argument("--suite", default=SUITE, help="suite name in configs/benchmarks/ or a YAML path (default: "
                   "%(default)s)")
    p.add_argument("--scenario", required=True, help="scenario name of the suite")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--controllers", nargs=2, required=True, help="first (flies up to the time) and second")
    p.add_argument("--times", nargs="+", type=float, required=True, help="hand-over times [s]")
    a = p.parse_args(argv)
    bad = [t for t in a.times if not (math.isfinite(t) and t >= 0.0)]
    if bad:  # before the controllers are built
        p.error(f"--times {bad[0]!r}: each hand-over time must be a finite number >= 0 s")
    try:
        end = float(scenario(a.env, a.scenario, a.suite)["duration"])  # [s] the episode's length
    except ValueError as err:
        p.error(f"--scenario {a.scenario!r}: {err}")
    late = [t for t in a.times if t >= end]
    if late:  # the first controller would fly the whole episode: no hand-over to report
        p.error(f"--times {late[0]!r}: at or after the end of {a.scenario}'s episode ({end:g} s): no hand-over")
    first, second = a.controllers
    for t, code, t_end in handover_outcomes(a.env, a.scenario, a.seed, a.controllers, a.times, a.suite):
        print(f"{first} -> {second} at {t:g} s: " + ("survives" if code == 0 else f"fails at {t_end:.2f} s"))


if __name__ == "__main__":
    main()
