"""Disturbances as plain data (laddermill_gym/atmosphere/disturbance_spec.py): every type round-trips through a
mapping, JSON and YAML; environments take mappings (``gymnasium.make(id, disturbances=[...])``), their spec
survives ``EnvSpec.to_json`` and an rl-zoo3-style ``config.yml`` and replays the same episode; bad entries
name the entry, the field and the value. Oracle: the same episode from the objects and from their mappings
(the mapping is only another way to write the same parameters), and the turbulence field the kernels read
in the env equals the field drawn directly from the env's seed sequence.
"""

from __future__ import annotations

import json

import gymnasium as gym
import numpy as np
import pytest
import yaml

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.atmosphere.disturbance_spec import (
    DISTURBANCE_TYPES,
    disturbance_from_spec,
    disturbance_to_spec,
    parse_disturbances,
)
from laddermill_gym.atmosphere.disturbances import DirectionStep
from laddermill_gym.envs import ENV_IDS

TW = "laddermill_gym/TetheredWing-v0"
EXAMPLES = [
    {"type": "DirectionStep", "step": [0.01, 0.03], "time": 2.0, "random_sign": True},
    {"type": "OneMinusCosineGust", "amplitude": 0.2, "duration": 8.0},
    {"type": "RandomPerturbation", "speed_std": 0.5},
    {"type": "Schedule", "times": [0.0, 10.0], "speed": [1.0, 1.2], "direction": [0.0, 0.1]},
    {"type": "EOG", "wind_class": "IA", "wind_speed": 10.0, "diameter": 10.0},
    {"type": "EDC", "wind_class": "IIB", "sign": -1},
    {"type": "ECD", "wind_class": "IIIC", "wind_speed": 8.0},
    {"type": "EWS", "wind_class": "IA", "hub_height": 150.0, "diameter": 40.0},
    {"type": "SpeedStep", "step": 0.25},
    {"type": "Ramp", "speed_change": -0.2, "direction_change": 0.05, "duration": 20.0},
    {"type": "Turbulence", "model": "VonKarman", "severity": "severe", "heights": [0.0, 300.0]},
]


def test_every_type_has_an_example():
    assert {e["type"] for e in EXAMPLES} == set(DISTURBANCE_TYPES)


@pytest.mark.parametrize("spec", EXAMPLES, ids=[e["type"] for e in EXAMPLES])
def test_round_trip_through_mapping_json_and_yaml(spec):
    d = disturbance_from_spec(spec)
    full = disturbance_to_spec(d)
    assert {k: v for k, v in full.items() if k in spec} == spec
    for text in (json.dumps(full), yaml.safe_dump(full)):
        back = disturbance_from_spec(yaml.safe_load(text))
        assert back == d
    t = np.linspace(0.0, 20.0, 201)
    a, b = d.sample(t, np.random.default_rng(3)), back.sample(t, np.random.default_rng(3))
    np.testing.assert_array_equal(a, b)


def test_yaml_text_and_single_mapping_are_accepted():
    text = "- {type: DirectionStep, step: 0.02}\n- {type: EOG, wind_class: IIA}\n"
    ds = parse_disturbances(text)
    assert [type(d).__name__ for d in ds] == ["DirectionStep", "EOG"]
    assert parse_disturbances({"type": "SpeedStep"})[0].step == 0.2
    assert parse_disturbances(None, (DirectionStep(),)) == (DirectionStep(),)


@pytest.mark.parametrize("value, text", [
    ([{"type": "EOG", "wind_class": "IZ"}], r"disturbances\[0\] \(EOG\): EOG.wind_class = 'IZ'"),
    ([{"type": "DirectionStep"}, {"type": "Turbulence", "heigths": [0, 1]}], r"disturbances\[1\].heigths"),
    ([{"type": "Turbulence", "heights": [5.0, 1.0]}], r"Turbulence.heights = \(5.0, 1.0\)"),
    ([{"type": "Tornado"}], r"disturbances\[0\].type = 'Tornado'"),
    ([{"step": 0.1}], r"disturbances\[0\] = .*'type'"),
    ("- [unclosed", "not valid YAML"),
    ([3.0], r"disturbances\[0\] = 3.0"),
])
def test_bad_entries_name_the_field(value, text):
    with pytest.raises(ValueError, match=text):
        parse_disturbances(value)


def rollout(env, seed, n=40):
    obs, _ = env.reset(seed=seed)
    out = [obs]
    for _ in range(n):
        obs, *_ = env.step(np.zeros(env.action_space.shape, dtype=np.float32))
        out.append(obs)
    return np.array(out)


def test_make_with_mappings_round_trips_through_env_spec_and_config_yml():
    dist = [{"type": "DirectionStep", "step": 0.02}, {"type": "EOG", "wind_class": "IA", "wind_speed": 10.0}]
    env = gym.make(TW, episode_time=5.0, disturbances=dist)
    ref = rollout(env, seed=4)
    # EnvSpec.to_json / from_json
    spec = gym.envs.registration.EnvSpec.from_json(env.spec.to_json())
    np.testing.assert_array_equal(rollout(gym.make(spec), seed=4), ref)
    # rl-zoo3 writes its hyperparameters (env_kwargs included) with yaml.dump and reads them with UnsafeLoader
    saved = yaml.dump({"env_kwargs": {"episode_time": 5.0, "disturbances": dist}})
    kw = yaml.load(saved, Loader=yaml.UnsafeLoader)["env_kwargs"]
    np.testing.assert_array_equal(rollout(gym.make(TW, **kw), seed=4), ref)
    # the same parameters as objects give the same episode
    objs = [disturbance_from_spec(d) for d in dist]
    np.testing.assert_array_equal(rollout(gym.make(TW, episode_time=5.0, disturbances=objs), seed=4), ref)


def test_turbulence_in_an_env_is_the_field_drawn_from_its_seed():
    turb = {"type": "Turbulence", "model": "NTM", "wind_speed": 8.0, "heights": [0.0, 300.0], "dh": 20.0,
            "along_wind": [-300.0, 300.0], "dxi": 10.0}
    env = gym.make(TW, episode_time=5.0, disturbances=[turb]).unwrapped
    env.reset(seed=11)
    task = env.task
    assert task.batch.n_grid == task.batch.air.gv.shape[1] > 0
    # the env's per-episode generator: replay its draws from a generator seeded like the env's np_random
    rng = np.random.default_rng(np.random.SeedSequence(11))
    from laddermill_gym.atmosphere.disturbances import sample_wind_field

    field = sample_wind_field(task.disturbances, task.episode_time, task.wind_dt, rng)
    np.testing.assert_array_equal(task.batch.air.gv[0, : field.grid.size], field.grid.values.reshape(-1))
    a = rollout(gym.make(TW, episode_time=5.0, disturbances=[turb]), seed=11)
    b = rollout(gym.make(TW, episode_time=5.0, disturbances=[turb]), seed=11)
    c = rollout(gym.make(TW, episode_time=5.0, disturbances=[turb]), seed=12)
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, c)


@pytest.mark.parametrize("env_id", [TW, "laddermill_gym/Rotorcraft-v0"])
def test_wing_and_rotorcraft_envs_accept_mappings(env_id):
    env = gym.make(env_id, episode_time=2.0, disturbances=[{"type": "ECD", "wind_class": "IIA", "time": 0.5}])
    assert type(env.unwrapped.task.disturbances[0]).__name__ == "ECD"
    assert env_id in ENV_IDS


@pytest.mark.parametrize("env_id", [TW, "laddermill_gym/Rotorcraft-v0", "laddermill_gym/PointMassChain-v0"])
def test_envs_read_yaml_text_with_yaml_1_2_floats(env_id):
    """Issue 34 item 4: YAML text given to an env's ``disturbances=`` reads ``2e-2`` as a number (PyYAML's own loader
    reads it as text, refused as "must be a number"), equal to the mapping written with 0.02; a key given twice is
    refused naming ``disturbances``; empty text is refused, not read as the default."""
    text = "- {type: DirectionStep, step: 2e-2, time: 1.5e0}\n"
    env = gym.make(env_id, episode_time=2.0, disturbances=text).unwrapped
    assert env.task.disturbances == parse_disturbances([{"type": "DirectionStep", "step": 0.02, "time": 1.5}])
    with pytest.raises(ValueError, match="disturbances: not valid YAML: .*duplicated key 'step'"):
        gym.make(env_id, episode_time=2.0, disturbances="- {type: DirectionStep, step: 0.1, step: 0.2}\n")
    with pytest.raises(ValueError, match="disturbances = '': empty YAML text"):
        gym.make(env_id, episode_time=2.0, disturbances="")
