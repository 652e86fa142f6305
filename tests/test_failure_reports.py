"""What an episode's end says (a review of 2026-12-07): a speed or rate limit names the body and the value that
crossed it (the failed step taken again without the check), the winch's reel-in end stop is a physical limit in the
simulator's report as in the env's, and ``laddermill evaluate``'s summary.csv keeps each episode's reason."""

import csv
import re

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401
from laddermill_gym.atmosphere.disturbances import DirectionStep
from laddermill_gym.sim.simulator import SimulationError

TW = "laddermill_gym/TetheredWing-v0"


def test_a_rate_limit_names_the_wing_and_the_rate_over_it():
    """With the integrator's rate limit at 1 rad/s and full deflections the wing's rate passes it: the reason names
    wing 0 and a rate above the 1 rad/s the test set (before, only the last good state's rates, all below it)."""
    env = gym.make(TW, scene_options={"overrides": {"integrator": {"max_rate": 1.0}}})
    env.reset(seed=0)
    for _ in range(1000):
        _, _, term, trunc, info = env.step(np.ones(3, np.float32))
        if term or trunc:
            break
    assert term and info["failure"] == 1, info["failure_reason"]
    m = re.search(r"in the step to t = [\d.]+ s: wing 0 angular rate ([\d.]+) rad/s > 1 rad/s", info["failure_reason"])
    assert m and float(m.group(1)) > 1.0, info["failure_reason"]


def test_the_winch_end_stop_is_a_physical_limit_in_the_simulators_report():
    """Reeling in at full speed ends PumpingKite-v0 with code 5 (tether fully reeled in); the copy's simulator,
    stepped on from the same last good state, raises a report of a physical limit, naming a rest length below 5 %
    of the scene's 300 m start length, not an integration failure."""
    env = gym.make("laddermill_gym/PumpingKite-v0")
    env.reset(seed=0)
    for _ in range(2000):
        _, _, term, trunc, info = env.step(np.array([0.0, 0.0, 0.0, -1.0], np.float32))
        if term or trunc:
            break
    assert info["failure"] == 5, info["failure_reason"]
    sim = env.unwrapped.task.simulator(0)
    with pytest.raises(SimulationError) as err:
        sim.step(sim.controls, 1)
    text = str(err.value)
    assert text.startswith("physical limit at t = ") and "integration failed" not in text, text
    rest = float(re.search(r"rest length of ([\d.]+) m", text).group(1))
    assert rest < 0.05 * 300.0


def test_evaluates_summary_keeps_each_episodes_failure_reason(tmp_path):
    """The open loop after a 0.1 rad direction step fails; summary.csv's failure_reason of seed i is the single
    env's info["failure_reason"] at its last step, flown here by a loop of the test with the same controller."""
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.harness.evaluate import evaluate

    kw = {"episode_time": 120.0, "disturbances": [DirectionStep(step=0.1)]}
    evaluate(TW, ["open_loop"], 2, kw, tmp_path, progress=False)
    rows = list(csv.DictReader((tmp_path / "summary.csv").read_text().splitlines()))
    ctrl = make_controller("open_loop", TW, kw)
    for i, row in enumerate(rows):
        env = gym.make(TW, **kw)
        obs, _ = env.reset(seed=i)
        while True:
            obs, _, term, trunc, info = env.step(ctrl.predict(obs, deterministic=True)[0])
            if term or trunc:
                break
        assert term and row["failure_reason"] == info["failure_reason"] != "", (row, info["failure_reason"])
