"""Rotorcraft-v1: Rotorcraft-v0 whose episode also ends when a retreating blade tip passes the rotor's
blade-incidence limit (Roberts sec. 4: 13 deg, read here from configs/rotors/roberts_rotor.yaml with yaml itself).
Oracles: v0 flown with the same actions (v1 changes nothing else), the tip incidence v0 reports, and the rotor's
file."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import gymnasium as gym
import numpy as np
import pytest
import yaml

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs.rotorcraft.trim import BladeLimitWarning

ROOT = Path(__file__).resolve().parent.parent
V0, V1 = "laddermill_gym/Rotorcraft-v0", "laddermill_gym/Rotorcraft-v1"
LIMIT_DEG = yaml.safe_load((ROOT / "configs/rotors/roberts_rotor.yaml").read_text())["blade_incidence_limit_deg"]


def _fly(env_id: str, actions: np.ndarray):
    env = gym.make(env_id)
    obs, _ = env.reset(seed=3)
    out = []
    for a in actions:
        obs, r, terminated, truncated, info = env.step(a)
        out.append((obs, r, terminated, info))
        if terminated or truncated:
            break
    env.close()
    return out


def test_v1_ends_the_episode_at_the_first_tip_past_the_limit_and_is_v0_before_it():
    """The collective ramped from the trim to full (which doubled v0's power past the limit) over 10 s: v1 ends in the
    first control period whose tip incidence (as v0 reports it) passes 13 deg, with v0's observations and rewards
    until then."""
    actions = np.zeros((200, 2), dtype=np.float32)
    actions[:, 0] = np.linspace(-0.1, 1.0, 200)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # Gymnasium: v0 is out of date
        ref, v1 = _fly(V0, actions), _fly(V1, actions)
    tips = np.degrees([info["max_tip_incidence_rad"] for *_, info in ref])
    first = int(np.argmax(tips > LIMIT_DEG))
    assert tips[first] > LIMIT_DEG >= tips[:first].max() and not any(t for *_, t, _ in ref)
    assert len(v1) == first + 1 and v1[-1][2] and v1[-1][3]["failure_name"] == "blade incidence past its limit"
    for (o0, r0, *_), (o1, r1, *_) in zip(ref[:first], v1[:first], strict=True):
        assert np.array_equal(o0, o1) and r0 == r1
    text = v1[-1][3]["failure_reason"]
    assert f"{tips[first]:.2f} deg" in text and f"{LIMIT_DEG:.3g} deg blade-incidence limit" in text, text


def test_the_lqr_flies_v1_as_v0():
    """At the trim collective the tip stays near 10 deg: the LQR's 120 s episode is v0's, reward for reward."""
    from laddermill_gym.control.factory import make_controller

    returns = []
    for env_id in (V0, V1):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            env, ctl = gym.make(env_id), make_controller("lqr", env_id)
        obs, _ = env.reset(seed=0)
        total, done = 0.0, False
        while not done:
            obs, r, terminated, truncated, info = env.step(ctl.predict(obs)[0])
            total, done = total + r, terminated or truncated
        returns.append((total, terminated, math.degrees(info["max_tip_incidence_rad"])))
        env.close()
    assert returns[0] == returns[1] and not returns[1][1] and returns[1][2] < LIMIT_DEG


def test_a_trim_past_the_limit_is_refused_by_v1_and_warned_by_v0():
    """At 22 m/s the config's 4 deg collective puts the tip far past 13 deg: v1 refuses (its episode would end at
    once), v0 warns; both name the blade-limited collective, which is below the config's."""
    with pytest.raises(ValueError, match=r"wind_speed = 22\.0 m/s.* past the 13 deg limit.*pass collective <= ") as e:
        gym.make(V1, wind_speed=22.0)
    bound = float(str(e.value).split("pass collective <= ")[1].split(" rad")[0])
    assert bound < math.radians(4.0)
    with pytest.warns(BladeLimitWarning, match=r"pass collective <= "):
        gym.make(V0, wind_speed=22.0).close()
    env = gym.make(V1, wind_speed=22.0, collective=bound - 1e-4)  # the schedule's collective flies
    env.reset(seed=0)
    assert math.degrees(env.unwrapped.task.trim_tip_incidence) <= LIMIT_DEG
    env.close()


def test_blade_stall_must_be_a_bool():
    with pytest.raises(ValueError, match=r"termination.blade_stall = 'yes': must be true or false"):
        gym.make(V1, termination={"blade_stall": "yes"})


def test_gusts_v5_is_v4_plus_v1_on_v0s_scenarios_of_gusts_v1():
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    v1, v4, v5 = load_suite("gusts-v1"), load_suite("gusts-v4"), load_suite("gusts-v5")
    assert v5.version == 5 and set(v5.envs) == set(v4.envs) | {V1}
    for env_id in v4.envs:
        assert v5.envs[env_id] == v4.envs[env_id], env_id
    assert v5.envs[V1] == v1.envs[V0]
