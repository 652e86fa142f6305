"""The gust benchmark (laddermill_gym/studies/gusts/gust_bench.py, gust_suite.py): the shipped suite loads, bad suites
name file and field, every controller meets the same episodes, and the metrics against independent answers:
a scenario without disturbance has energy ratio 1 (it is its own reference); the peak tension and the
energy against a plain Gymnasium rollout of the same env and seed; the settling time of an exponential decay
against tau ln(1 / band)."""

from __future__ import annotations

import argparse
import json
import math

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.gusts.gust_suite import load_suite

TW = "laddermill_gym/TetheredWing-v0"
SUITE = f"""
version: 1
envs:
  {TW}:
    env_kwargs: {{}}
    scenarios:
      - {{name: calm, start: 0.0, duration: 3.0, seeds: [0, 1], disturbances: []}}
      - {{name: gust, start: 0.5, duration: 3.0, seeds: [0, 1],
         disturbances: [{{type: OneMinusCosineGust, amplitude: [0.1, 0.4], duration: 2.0, time: 0.5}},
                        {{type: DirectionStep, step: 0.05, time: 0.5}}]}}
"""


def test_shipped_suite_loads_with_every_env():
    s = load_suite("gusts-v1")
    # gusts-v1 was fixed before PumpingKite-v0 and PointMassChain-v0 existed; a suite is never changed, a later
    # version adds envs
    assert s.version == 1 and set(s.envs) == set(ENV_IDS) - {"laddermill_gym/PumpingKite-v0",
                                                             "laddermill_gym/PointMassChain-v0",
                                                             "laddermill_gym/PumpingKite-v1",
                                                             "laddermill_gym/LadderMill-v1",
                                                             "laddermill_gym/LadderMill-v2",
                                                             "laddermill_gym/LadderMill-v3",
                                                             "laddermill_gym/LadderChain-v1",
                                                             "laddermill_gym/TetheredWing-v1",
                                                             "laddermill_gym/Rotorcraft-v1"}
    for _, scenarios in s.envs.values():
        assert all(sc.duration > sc.start for sc in scenarios)


@pytest.mark.parametrize("edit, text", [
    (("version: 1", "version: 0"), "field 'version' = 0"),
    (("start: 0.5", "start: 0.5, strat: 1.0"),
     r"unknown field 'envs.laddermill_gym/TetheredWing-v0.scenarios\[1\].strat'"),
    (("seeds: [0, 1], disturbances: []", "seeds: [0, 0], disturbances: []"), "seeds"),
    (("type: DirectionStep, step: 0.05", "type: DirectionStep, stepp: 0.05"), r"disturbances\[1\].stepp"),
    (("env_kwargs: {}", "env_kwargs: {episode_time: 3.0}"), "episode_time"),
    (("start: 0.0, duration: 3.0", "start: 0.0, duration: 3.01"),
     r"'envs.laddermill_gym/TetheredWing-v0.scenarios\[0\].duration' = 3.01 s: episode_time = 3.01 s is not a whole "
     r"number of control periods \(control_dt = 0.05 s: 60.2 periods\)"),
    (("env_kwargs: {}", "env_kwargs: {control_dt: 0.4}"), r"scenarios\[0\].duration' = 3.0 s: .*\(control_dt = 0.4 s"),
])
def test_bad_suites_name_file_and_field(tmp_path, edit, text):
    path = tmp_path / "bad.yaml"
    path.write_text(SUITE.replace(*edit, 1))
    with pytest.raises(ConfigError, match=text) as err:
        load_suite(path)
    assert str(path) in str(err.value)


def test_same_episodes_for_every_controller_and_metrics_against_a_plain_rollout(tmp_path):
    path = tmp_path / "tiny.yaml"
    path.write_text(SUITE)
    suite = load_suite(path)
    rows = gb.run_suite(suite, [], ["open_loop", "open_loop"], progress=False)
    a, b = rows[:4], rows[4:]
    assert [{k: v for k, v in r.items()} for r in a] == b  # same seeds, same wind
    calm = [r for r in a if r["scenario"] == "calm"]
    assert all(r["energy_ratio"] == 1.0 and r["survived"] for r in calm)
    # a plain rollout of the gust scenario, seed 1: energy and peak tension
    env = gym.make(TW, **dict(ENV_IDS[TW], episode_time=3.0, disturbances=list(suite.envs[TW][1][1].disturbances)))
    env.reset(seed=1)
    task = env.unwrapped.task
    a0 = task.actions.nominal_action.astype(np.float32)
    energy, peak, done = 0.0, 0.0, False
    while not done:
        _, _, term, trunc, info = env.step(a0)
        energy += task.control_dt * info["power_W"]
        peak = max(peak, info["max_tension_N"])
        done = term or trunc
    row = next(r for r in a if r["scenario"] == "gust" and r["seed"] == 1)
    assert row["energy_J"] == pytest.approx(energy, rel=1e-9)
    assert row["peak_tension_ratio"] == pytest.approx(peak / task.breaking_tension, rel=1e-9)
    paths = gb.write_outputs(rows, suite, tmp_path / "out")
    assert [p.name for p in paths] == ["gust_bench.csv", "gust_bench.json", "scorecard_TetheredWing-v0.png"]
    data = json.loads(paths[1].read_text())
    assert data["suite"] == "tiny" and len(data["rows"]) == 8 and len(data["summary"]) == 2
    # the physics the figures came from: the env's arguments (registered ones merged with the suite's), the code
    from laddermill_gym import __version__
    from laddermill_gym.envs import registered_arguments

    assert data["env_arguments"] == json.loads(json.dumps({TW: registered_arguments(TW, {})}))
    assert data["package_version"] == __version__ and len(data["source_digest"]) == 16


def test_settling_time_of_an_exponential_decay():
    dt, start, tau, duration = 0.05, 2.0, 3.0, 60.0
    t = dt * np.arange(int(duration / dt) + 1)
    e = np.where(t < start, 0.0, np.exp(-(t - start) / tau))
    ts = gb.settling_time(e, dt, start, duration)
    assert ts == pytest.approx(tau * math.log(1.0 / gb.SETTLE_BAND), abs=2 * dt)
    growing = np.where(t < start, 0.0, np.exp((t - start) / tau) - 1.0)
    assert math.isnan(gb.settling_time(growing, dt, start, duration))


def test_subcommand_parser():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers()
    gb.add_parser(sub)
    args = p.parse_args(["gust-bench", "--suite", "gusts-v1", "--env", TW, "--controllers", "open_loop", "lqr"])
    assert args.func is not None and args.controllers == ["open_loop", "lqr"] and args.env == [TW]
