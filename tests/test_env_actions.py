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
from tests.env_cases import IDS, TW, make_native, make_single


def _invalid(shape: tuple[int, ...]) -> list[tuple[str, object]]:
    """(name, action) pairs that are not finite real arrays of ``shape``."""
    n = shape[-1]
    nan = np.zeros(shape)
    nan.flat[1] = np.nan
    inf = np.zeros(shape)
    inf.flat[0] = -np.inf
    return [("None", None), ("scalar", 0.5), ("empty", np.zeros(0)), ("one short", np.zeros(int(np.prod(shape)) - 1)),
            ("one more", np.zeros((*shape[:-1], n + 1))), ("transposed", np.zeros(shape[::-1] + (2,))),
            ("string", "0 0 0"), ("strings", np.full(shape, "0.1")), ("complex", np.full(shape, 0.1 + 0.2j)),
            ("complex, imaginary 0", np.full(shape, 0.1 + 0j)), ("booleans", np.ones(shape, bool)),
            ("objects", np.full(shape, None, dtype=object)), ("dict", {"a": 1}), ("ragged", [[0.0], [0.0, 0.0]]),
            ("NaN", nan), ("-inf", inf)]


def _state(env) -> list:
    """Everything a step would change: the task's snapshot, the observation and the generators' states."""
    snap = env.task.snapshot()
    rngs = env._rngs if hasattr(env, "_rngs") else [env.np_random]
    return [*_arrays(snap), env.task.obs.copy(), [r.bit_generator.state for r in rngs]]


def _arrays(x) -> list:
    """The arrays in a nest of dicts, tuples and lists (None left out)."""
    if isinstance(x, dict):
        return [a for v in x.values() for a in _arrays(v)]
    if isinstance(x, (tuple, list)):
        return [a for v in x for a in _arrays(v)]
    return [] if x is None else [np.array(x, copy=True)]


def _assert_same(a: list, b: list) -> None:
    assert len(a) == len(b)
    for x, y in zip(a[:-1], b[:-1], strict=True):
        np.testing.assert_array_equal(x, y)
    assert a[-1] == b[-1]


def _refuses_everything_invalid(env, twin, shape):
    before = _state(env)
    for name, action in _invalid(shape):
        with pytest.raises(ActionError) as err:
            env.step(action)
        msg = str(err.value)
        assert f"shape {shape}" in msg and "real array" in msg and "[-1, 1]" in msg, (name, msg)
        assert isinstance(err.value, ValueError) and isinstance(err.value, TypeError)
        _assert_same(before, _state(env))
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
    for _, action in _invalid((2, 3)):
        with pytest.raises(ActionError, match=r"shape \(2, 3\)"):
            venv.step(action)
    obs, *_ = venv.step(np.zeros((2, 3), np.float32))
    assert np.isfinite(obs).all()
