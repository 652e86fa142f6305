"""Issue 34 item 7: an action that is not a finite real array of the action space's shape is refused, by the single
env, the native vector env and the SB3 adapter of every registered id, with one clear error
(:class:`~laddermill_gym.envs.actions.ActionError`, a ValueError and a TypeError) that says the shape, the dtype and
the range, before anything moves: a complex action is refused, not cut to its real part; None, a scalar, an empty
array, another shape, strings, booleans, objects, ragged lists and non-finite entries alike.

Oracle: the env itself before the call. Its task's snapshot (states, controls, times, air, step counters), its
observation and its random generators are the same after the refused call, and the next valid step gives what a
twin env that never saw the refused action gives."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.envs.actions import ActionError
from tests.env_cases import IDS, TW, assert_same_state, env_state, invalid_actions, make_native, make_single


def _refuses_everything_invalid(env, twin, shape):
    before = env_state(env)
    for name, action in invalid_actions(shape):
        with pytest.raises(ActionError) as err:
            env.step(action)
        msg = str(err.value)
        assert f"shape {shape}" in msg and "real array" in msg and "[-1, 1]" in msg, (name, msg)
        assert isinstance(err.value, ValueError) and isinstance(err.value, TypeError)
        assert_same_state(before, env_state(env))
    a = np.full(shape, 0.05, np.float32)
    out, ref = env.step(a), twin.step(a)
    for x, y in zip(out[:4], ref[:4], strict=True):
        np.testing.assert_array_equal(x, y)


@pytest.mark.parametrize("env_id", IDS)
def test_single_env_refuses_invalid_actions_before_moving(env_id):
    env, twin = make_single(env_id), make_single(env_id)
    env.reset(seed=1)
    twin.reset(seed=1)
    n = env.action_space.shape[0]
    _refuses_everything_invalid(env, twin, (n,))
    assert "complex numbers" in _message(env, np.full(n, 0.1 + 0.2j))
    assert f"has shape ({n + 2},)" in _message(env, np.zeros(n + 2))


@pytest.mark.parametrize("env_id", IDS)
def test_native_vector_env_refuses_invalid_actions_before_moving(env_id):
    env, twin = make_native(env_id, 2), make_native(env_id, 2)
    env.reset(seed=1)
    twin.reset(seed=1)
    n = env.single_action_space.shape[0]
    _refuses_everything_invalid(env, twin, (2, n))
    # a single env's action is not a batch of two
    assert f"has shape ({n},)" in _message(env, np.zeros(n))


def _message(env, action) -> str:
    with pytest.raises(ActionError) as err:
        env.step(action)
    return str(err.value)


def test_accepted_forms_give_the_float64_result():
    """A list, an integer array, float16 / float32 / float64 arrays and a (1, n) batch of one are the same action."""
    envs = [make_single(TW) for _ in range(6)]
    a = np.array([0.0, 1.0, -1.0])
    forms = [a, a.tolist(), a.astype(int), a.astype(np.float16), a.astype(np.float32), a[None]]
    outs = []
    for env, form in zip(envs, forms, strict=True):
        env.reset(seed=4)
        outs.append(env.step(form))
    for o in outs[1:]:
        np.testing.assert_array_equal(o[0], outs[0][0])
        assert o[1] == outs[0][1]


def test_sb3_adapter_refuses_invalid_actions():
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.envs.sb3 import sb3_vec_env

    venv = sb3_vec_env(TW, 2, seed=0, episode_time=1.0)
    venv.reset()
    for _, action in invalid_actions((2, 3)):
        with pytest.raises(ActionError, match=r"shape \(2, 3\)"):
            venv.step(action)
    obs, *_ = venv.step(np.zeros((2, 3), np.float32))
    assert np.isfinite(obs).all()
