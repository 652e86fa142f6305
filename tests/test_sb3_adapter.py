"""The SB3 adapter is the registered environment, complete (issue 17 point 3): built from an env id it steps the
same model as ``gymnasium.make`` bit for bit (oracle: the single env), gives every step the info keys that
``DummyVecEnv`` over ``gymnasium.make`` gives, answers ``get_attr`` / ``set_attr`` / ``env_method`` and renders
``rgb_array`` frames; the native and Gymnasium's sync vector envs give the same info keys."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401

pytest.importorskip("stable_baselines3")
from stable_baselines3.common.vec_env import DummyVecEnv  # noqa: E402

from laddermill_gym.envs.sb3 import WingSB3VecEnv, sb3_vec_env  # noqa: E402

TW = "laddermill_gym/TetheredWing-v0"
KW = {"episode_time": 2.0}


def _actions(n: int, shape, seed: int = 7) -> np.ndarray:
    return np.random.default_rng(seed).uniform(-0.3, 0.3, size=(n, *shape)).astype(np.float32)


def test_built_from_the_id_it_is_the_registered_model_bit_for_bit():
    env = gym.make(TW, **KW)
    venv = sb3_vec_env(TW, 1, seed=3, **KW)
    obs_single, _ = env.reset(seed=3)
    obs_vec = venv.reset()
    np.testing.assert_array_equal(obs_vec[0], obs_single)
    for a in _actions(30, env.action_space.shape):
        o1, r1, te, tr, _ = env.step(a)
        o2, r2, done, _ = venv.step(a[None])
        np.testing.assert_array_equal(o2[0], o1)
        assert np.float32(r1) == r2[0]
        if te or tr:
            break
    assert WingSB3VecEnv(1).task.scene.name == gym.make(TW).unwrapped.task.scene.name  # defaults registered too


def test_every_step_has_the_dummy_vec_env_info_keys():
    venv = sb3_vec_env(TW, 2, seed=0, **KW)
    dummy = DummyVecEnv([lambda: gym.make(TW, **KW) for _ in range(2)])
    dummy.seed(0)
    venv.reset()
    dummy.reset()
    a = np.zeros((2, *venv.action_space.shape), np.float32)
    for _ in range(int(2.0 / 0.05)):  # through the time limit
        _, _, d1, infos = venv.step(a)
        _, _, d2, dinfos = dummy.step(a)
        assert list(d1) == list(d2)
        for i in range(2):
            assert set(infos[i]) == set(dinfos[i]) - {"episode"}, (sorted(infos[i]), sorted(dinfos[i]))
    assert any("terminal_observation" in i for i in infos)


def test_get_attr_set_attr_env_method_and_render():
    venv = sb3_vec_env(TW, 2, seed=0, render_mode="rgb_array", **KW)
    spec = venv.get_attr("spec")[0]
    assert spec.id == TW and spec.kwargs["episode_time"] == 2.0 and spec.kwargs["scene"] == "tethered_wing"
    assert venv.get_attr("render_mode") == ["rgb_array", "rgb_array"]
    assert venv.get_attr("n_wings", indices=[1]) == [1]
    venv.set_attr("lateral_scale", 7.0)
    assert venv.get_attr("lateral_scale") == [7.0, 7.0]
    with pytest.raises(AttributeError, match="only be set for all"):
        venv.set_attr("lateral_scale", 1.0, indices=[0])
    with pytest.raises(AttributeError, match="no such attribute"):
        venv.set_attr("no_such_thing", 1.0)
    assert venv.env_method("failure_text", 0, 0) == ["", ""]
    venv.reset()
    frame = venv.render()
    assert frame.ndim == 3 and frame.shape[2] == 3 and frame.dtype == np.uint8


def test_native_and_sync_vector_envs_give_the_same_info_keys():
    keys = []
    for mode in ("vector_entry_point", "sync"):
        ve = gym.make_vec(TW, 2, vectorization_mode=mode, **KW)
        ve.reset(seed=0)
        _, _, _, _, info = ve.step(np.zeros(ve.action_space.shape, np.float32))
        keys.append(set(info))
        ve.close()
    assert keys[0] == keys[1]
