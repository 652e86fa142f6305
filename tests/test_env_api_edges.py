"""Gymnasium's and Stable-Baselines3's conventions at the edges of the native vector env, the SB3 adapter and the
single env, each checked against the library's own reference (SyncVectorEnv, DummyVecEnv, gymnasium.make's
TimeLimit) or a value known by construction; found by a review of 2026-12-07 (steps before a reset ran from an empty
state, ``max_episode_steps`` was dropped, a pickled env lost its seed, the SB3 adapter's reset infos, options and
attributes, counts of copies coerced, the alpha mode's elevator clipped without a count)."""

from __future__ import annotations

import pickle
import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)

ID = "laddermill_gym/TetheredWing-v0"
SHORT = dict(episode_time=0.3)


def _native(n, **kw):
    return gym.make_vec(ID, n, vectorization_mode="vector_entry_point", **kw)


def test_a_step_before_the_first_reset_is_refused_as_sync_vector_env_does():
    sync = gym.make_vec(ID, 2, vectorization_mode="sync", **SHORT)
    with pytest.raises(gym.error.ResetNeeded):
        sync.step(np.zeros((2, 3), np.float32))
    env = _native(3, **SHORT)
    with pytest.raises(gym.error.ResetNeeded, match=r"copies \[0, 1, 2\] were never reset"):
        env.step(np.zeros((3, 3), np.float32))
    env.reset(seed=0, options={"reset_mask": np.array([True, False, False])})
    with pytest.raises(gym.error.ResetNeeded, match=r"copies \[1, 2\]"):
        env.step(np.zeros((3, 3), np.float32))
    env.reset(seed=0)
    env.step(np.zeros((3, 3), np.float32))


def test_max_episode_steps_truncates_the_native_vector_env_as_the_sync_one():
    n_steps = {}
    for mode in ("sync", "vector_entry_point"):
        env = gym.make_vec(ID, 2, vectorization_mode=mode, max_episode_steps=4)
        env.reset(seed=1)
        for k in range(1, 10):
            _, _, terminated, truncated, _ = env.step(np.zeros((2, 3), np.float32))
            if truncated.any() or terminated.any():
                n_steps[mode] = (k, truncated.tolist(), terminated.tolist())
                break
    assert n_steps["vector_entry_point"] == n_steps["sync"] == (4, [True, True], [False, False])
    with pytest.raises(ValueError, match=r"max_episode_steps = 0"):
        _native(2, max_episode_steps=0)


def test_seeds_are_reported_per_copy_and_a_bad_seed_is_named():
    env = _native(2, **SHORT)
    sync = gym.make_vec(ID, 2, vectorization_mode="sync", **SHORT)
    env.reset(seed=3)
    sync.reset(seed=3)
    assert env.np_random_seed == tuple(sync.np_random_seed) == (3, 4)
    with pytest.raises(ValueError, match=r"seed = 1\.5"):
        env.reset(seed=1.5)


@pytest.mark.parametrize("bad", [2.5, True, "2", None])
def test_a_count_of_copies_that_is_not_a_positive_integer_is_named(bad):
    with pytest.raises(ValueError, match=r"num_envs = "):
        _native(bad)
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.envs.sb3 import sb3_vec_env

    with pytest.raises(ValueError, match=r"num_envs = "):
        sb3_vec_env(ID, bad)


def test_a_pickled_env_keeps_its_seed_and_spec():
    env = gym.make(ID, **SHORT).unwrapped
    env.reset(seed=3)
    env.step(np.zeros(3, np.float32))
    copy = pickle.loads(pickle.dumps(env))
    assert copy.spec is not None and copy.spec.id == ID
    assert copy.np_random_seed == env.np_random_seed == 3  # reading it reseeded a restored generator
    np.testing.assert_array_equal(copy.reset()[0], env.reset()[0])


def test_the_sb3_adapter_follows_dummy_vec_env():
    pytest.importorskip("stable_baselines3")
    from stable_baselines3.common.vec_env import DummyVecEnv

    from laddermill_gym.envs.sb3 import sb3_vec_env

    venv = sb3_vec_env(ID, 2, seed=3, **SHORT)
    dummy = DummyVecEnv([lambda: gym.make(ID, **SHORT) for _ in range(2)])
    dummy.seed(3)
    with pytest.raises(gym.error.ResetNeeded):
        venv.step(np.zeros((2, 3), np.float32))
    np.testing.assert_array_equal(venv.reset(), dummy.reset())
    assert venv.reset_infos == dummy.reset_infos
    for _ in range(7):  # through the end of the 0.3 s episodes and their auto-resets
        venv.step(np.zeros((2, 3), np.float32))
        dummy.step(np.zeros((2, 3), np.float32))
    assert venv.reset_infos == dummy.reset_infos
    for attr in ("action_space", "observation_space"):
        assert venv.get_attr(attr, [0]) == dummy.get_attr(attr, [0])
    assert venv.get_attr("metadata")[0]["render_fps"] == dummy.get_attr("metadata")[0]["render_fps"]
    assert isinstance(venv.get_attr("np_random", [1])[0], np.random.Generator)
    with pytest.raises(AttributeError, match=r"env_method\('reset'\)"):
        venv.env_method("reset", indices=[0])
    venv.set_options({"foo": 1})
    with pytest.raises(ValueError, match=r"options = \{'foo': 1\}"):
        venv.reset()


def test_the_alpha_mode_commands_no_elevator_beyond_its_limit():
    """At a = -1 and +1 the elevator is the trim map plus the wing's own offset, within the limits: the range of
    alpha is chosen so (it was the map's alone, and a = -1 asked for 0.2734 rad where the limit is 0.2618)."""
    env = gym.make(ID, action_mode="alpha").unwrapped
    am = env.task.actions
    lo, hi = am._lo[0, 0], am._hi[0, 0]
    for a0 in (-1.0, 1.0):
        am.reset(1)
        for _ in range(60):  # the servo settles on the command
            u = am.controls(np.array([[a0, 0.0, 0.0]]))
        alpha = am._alpha_lo[0] if a0 < 0 else am._alpha_hi[0]
        wanted = float(am._maps[0][0](alpha)) + am._elevator_offset[0]
        assert lo <= wanted <= hi
        assert u[0, 0] == pytest.approx(wanted, abs=1e-12)


def test_a_ground_contact_names_the_altitude_limit():
    env = gym.make(ID, termination={"min_altitude": 1000.0}).unwrapped
    env.reset(seed=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        _, _, terminated, _, info = env.step(np.zeros(3, np.float32))
    assert terminated and info["failure"] == 2
    assert "min_altitude 1e+03 m" in info["failure_reason"]


def test_a_broken_cable_names_its_most_loaded_element():
    """Failure 3 names the element whose tension broke the cable; oracle: the plain-numpy reference
    implementation's tensions of the copy's state (``laddermill_gym.reference.element_tensions``)."""
    from laddermill_gym.reference import element_tensions
    from tests.env_cases import LC, case_kwargs

    env = gym.make(LC, **dict(case_kwargs(LC), termination={"breaking_factor": 1e-6})).unwrapped
    env.reset(seed=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        _, _, terminated, _, info = env.step(np.zeros(env.action_space.shape, np.float32))
    assert terminated and info["failure"] == 3
    bt = env.task.batch
    ref = element_tensions(bt.assembly, float(bt.t[0]), bt.states[0])
    assert info["failure_reason"].endswith(f" in element {int(np.argmax(ref))}"), info["failure_reason"]
    assert info["max_tension_N"] == pytest.approx(ref.max(), rel=1e-2)  # the tension named is that element's
