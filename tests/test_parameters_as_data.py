"""Parameters as data (issue 17 point 2): an env takes scene overrides as a plain nested mapping, checked like the
file; the LQR factory designs for the modified scene; a fixed reference power makes returns comparable across
winds (oracle: reward_power = P / reference_power_W, the reward's definition)."""

from __future__ import annotations

import json

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401
from laddermill_gym.control.factory import make_controller
from laddermill_gym.model.configio import ConfigError

TW = "laddermill_gym/TetheredWing-v0"
#: scene_options replaces the registered one, so TetheredWing-v0's one element per piece and its ROS34PW2 (which
#: its 50 ms physics step needs: two elements with the scene's RK4 are refused at load) are given again
WIND10 = {"elements_per_piece": 1, "method": "ros34pw2", "overrides": {"wind": {"v0": 10.0}}}


def test_scene_overrides_reach_the_model_and_survive_the_spec():
    env = gym.make(TW, scene_options=WIND10, episode_time=1.0)
    task = env.unwrapped.task
    assert task.scene.assembly.wind.v0 == 10.0
    default = gym.make(TW, episode_time=1.0).unwrapped.task
    assert task.p_ref > default.p_ref  # more wind, more pull at the trim
    again = gym.make(gym.envs.registration.EnvSpec.from_json(env.spec.to_json()))
    assert again.unwrapped.task.scene.assembly.wind.v0 == 10.0
    json.dumps(env.spec.kwargs)  # plain data


def test_bad_overrides_name_the_field():
    with pytest.raises(ConfigError, match=r"field 'wind.v0' = -1.0: must be > 0"):
        gym.make(TW, scene_options={"elements_per_piece": 1, "overrides": {"wind": {"v0": -1.0}}})
    with pytest.raises(ConfigError, match=r"unknown field 'wind.speed'"):
        gym.make(TW, scene_options={"elements_per_piece": 1, "overrides": {"wind": {"speed": 9.0}}})
    with pytest.raises(ConfigError, match=r"field 'integrator.dt' = 0.05 s with the overrides dt = 0.05, method = "
                                          r"'rk4', elements_per_piece = 2 cannot work with RK4"):
        # two elements on RK4 at 50 ms (the registered options, one element on ROS34PW2, merge in unless replaced)
        gym.make(TW, scene_options={"elements_per_piece": 2, "method": "rk4", "overrides": {"wind": {"v0": 10.0}}})


def test_lqr_designs_for_the_modified_scene():
    base = make_controller("lqr", TW)
    windy = make_controller("lqr", TW, {"scene_options": WIND10})
    assert base.gains.shape == windy.gains.shape
    assert np.max(np.abs(base.gains - windy.gains)) > 1e-3 * np.max(np.abs(base.gains))


def test_fixed_reference_power_normalises_the_reward():
    for opts in ({"elements_per_piece": 1}, WIND10):
        env = gym.make(TW, scene_options=opts, episode_time=1.0, reward={"reference_power_W": 5000.0})
        env.reset(seed=0)
        _, _, _, _, info = env.step(np.zeros(env.action_space.shape, np.float32))
        assert env.unwrapped.task.p_ref == 5000.0
        assert info["reward_power"] == pytest.approx(info["power_W"] / 5000.0, rel=1e-12)
    with pytest.raises(ValueError, match="reward.reference_power_W = -1.0"):
        gym.make(TW, reward={"reference_power_W": -1.0})


def test_lqr_designs_for_a_user_scene_file(tmp_path):
    from laddermill_gym.model.configio import CONFIG_DIR

    text = (CONFIG_DIR / "scenes" / "tethered_wing.yaml").read_text()
    text = text.replace("wing_type: ../wings/", "wing_type: package:wings/", 1)
    text = text.replace("cable: ../cables/", "cable: package:cables/", 1)
    assert "  v0: 8.0 " in text
    path = tmp_path / "my_wing.yaml"
    path.write_text(text.replace("  v0: 8.0 ", "  v0: 11.0", 1))  # another wind: another trim and gain
    ctrl = make_controller("lqr", TW, {"scene": str(path)})
    default = make_controller("lqr", TW)
    assert ctrl.gains.shape == default.gains.shape == (1, 2, 6)
    # the user's file is the one designed on (a review of 2026-12-07: ignoring it passed): the gains differ
    assert np.abs(ctrl.gains - default.gains).max() > 1e-3 * np.abs(default.gains).max()
