"""The behaviour every registered environment shares through the one skeleton (``envs/task_env.py``,
``envs/vector.py``), checked once over every id: Gymnasium's and SB3's checkers, seeding (the same seed gives the
same rollout, another seed another one), the native vector env against single envs (copy i seeded seed + i, bit for
bit on the serial kernel), pickling in the middle of an episode, and the time limit with NextStep autoreset.

The oracles are independent of the code under test: Gymnasium's and SB3's own checkers, and single envs against the
batched kernel (a different code path per copy: one copy per kernel call against all copies in one call)."""

from __future__ import annotations

import pickle
import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from laddermill_gym.envs import ENTRY_POINTS, ENV_IDS
from tests.env_cases import CASES, IDS, LM, PMC
from tests.env_cases import make_native as _make_vec
from tests.env_cases import make_single as _make


def test_every_registered_id_is_covered():
    assert set(IDS) == set(ENV_IDS) == set(ENTRY_POINTS)


def _actions(env, env_id, steps, seed, n=None):
    scale = CASES[env_id][1]
    shape = (steps, env.action_space.shape[-1]) if n is None else (steps, n, env.single_action_space.shape[0])
    return np.random.default_rng(seed).uniform(-scale, scale, size=shape).astype(np.float32)


def _rollout(env, actions, seed):
    obs, _ = env.reset(seed=seed)
    out, rewards = [obs], []
    for a in actions:
        obs, r, term, trunc, _ = env.step(a)
        out.append(obs)
        rewards.append(r)
        if term or trunc:
            break
    return np.array(out), np.array(rewards)


@pytest.mark.parametrize("env_id", IDS)
def test_gymnasium_and_sb3_checkers(env_id):
    env = _make(env_id, episode_time=2.0)
    check_env(env, skip_render_check=True)
    vec = _make_vec(env_id, 2, episode_time=2.0)
    assert type(vec).__name__ == ENTRY_POINTS[env_id][1].split(":")[1]
    assert vec.metadata["autoreset_mode"] == gym.vector.AutoresetMode.NEXT_STEP
    assert vec.single_observation_space == env.observation_space and vec.single_action_space == env.action_space
    pytest.importorskip("stable_baselines3")
    from stable_baselines3.common.env_checker import check_env as sb3_check

    sb3_check(_make(env_id, episode_time=1.0), warn=True)


@pytest.mark.parametrize("env_id", IDS)
def test_same_seed_same_rollout_and_seeds_matter(env_id):
    steps = CASES[env_id][2]
    acts = _actions(_make(env_id), env_id, steps, seed=0)
    o1, r1 = _rollout(_make(env_id), acts, seed=7)
    o2, r2 = _rollout(_make(env_id), acts, seed=7)
    o3, _ = _rollout(_make(env_id), acts, seed=8)
    np.testing.assert_array_equal(o1, o2)
    np.testing.assert_array_equal(r1, r2)
    assert not np.array_equal(o1[:5], o3[:5])


#: the mill's is in tests/test_laddermill_env.py (across a wing transfer); the point-mass copies run one after another
VECTOR_CASES = [(i, p) for i in IDS if i != LM for p in ((False,) if i == PMC else (False, True))]


@pytest.mark.parametrize("env_id, parallel", VECTOR_CASES)
def test_vector_copies_equal_single_envs(env_id, parallel):
    n, steps = 3, CASES[env_id][2]
    vec = _make_vec(env_id, n, **({} if env_id == PMC else {"parallel": parallel}))
    acts = _actions(vec, env_id, steps, seed=1, n=n)
    obs_v, _ = vec.reset(seed=11)
    hist_v, rew_v = [obs_v], []
    for a in acts:
        o, r, *_ = vec.step(a)
        hist_v.append(o)
        rew_v.append(r)
    # serial or on threads, each copy runs the single env's kernel (envs/copy_threads.py): equal bit for bit
    for i in range(n):
        o_s, r_s = _rollout(_make(env_id), acts[:, i], seed=11 + i)
        k = len(o_s)  # up to a copy's first episode end (then the vector env autoresets it)
        np.testing.assert_array_equal(np.array(hist_v)[:k, i], o_s)
        np.testing.assert_array_equal(np.array(rew_v)[:k - 1, i], r_s)
    assert not np.array_equal(hist_v[-1][0], hist_v[-1][1])  # the copies' seeds differ


@pytest.mark.parametrize("env_id", IDS)
def test_pickle_round_trip_continues_identically(env_id):
    steps = CASES[env_id][2]
    env = _make(env_id)
    env.reset(seed=3)
    acts = _actions(env, env_id, steps, seed=2)
    for a in acts[: steps // 2]:
        env.step(a)
    clone = pickle.loads(pickle.dumps(env))
    for a in acts[steps // 2:]:
        o1, r1, *_ = env.step(a)
        o2, r2, *_ = clone.step(a)
        np.testing.assert_array_equal(o1, o2)
        assert r1 == r2


@pytest.mark.parametrize("env_id", IDS)
def test_time_limit_truncates_and_next_step_autoreset(env_id):
    kw = {k: v for k, v in CASES[env_id][0].items() if k != "initial_noise"}  # every start the same
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        vec = gym.make_vec(env_id, num_envs=2, vectorization_mode="vector_entry_point",
                           **dict(kw, episode_time=0.2, disturbances=[]))
    obs0, _ = vec.reset(seed=0)
    a = vec.task.last_action.astype(np.float32)  # the start's action: trim, or zero offsets
    for k in range(4):
        obs, r, term, trunc, info = vec.step(a)
        assert not term.any() and trunc.all() == (k == 3)
    np.testing.assert_allclose(info["t"], 0.2, atol=1e-9)
    obs, r, term, trunc, info = vec.step(a)  # the autoreset step: action ignored, reward 0, fresh start
    np.testing.assert_array_equal(obs, obs0)
    np.testing.assert_array_equal(r, 0.0)
