"""Issue 34: a fuzz test that steps every registered id, single env and native vector env, with random, extreme and
invalid actions (slow set: ``pytest -m slow tests/test_env_fuzz.py``).

Each step draws an action from a mixture: uniform in [-1, 1]; uniform in [-1e3, 1e3]; extreme entries (+-1e30,
+-float32 max, +-1e300, +-5e-324, -0.0, exactly +-1); integer and float16 arrays; and malformed ones (None, NaN,
inf, complex, strings, wrong shapes ... ``tests/env_cases.invalid_actions``). Oracles, per step:

* a malformed action raises ActionError and changes nothing (the env's state read-out is the same after);
* a well-formed one gives a finite observation inside the observation space, a finite reward, bool flags, a known
  failure code with a reason exactly when it is not 0, and ``n_clipped`` = the number of entries with |a| > 1
  counted here;
* episodes end (by the time limit of 10 s or 5 s, or a failure: the wing chain, craft and kite fail under such
  actions) and the env goes on after its reset (single) or autoreset (vector).

About 2,500 well-formed steps per id on the single env and 800 on three vector copies (some 30,000 copy-steps)."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.envs.actions import ActionError
from tests.env_cases import IDS, assert_same_state, env_state, invalid_actions, make_native, make_single

pytestmark = pytest.mark.slow

EXTREMES = np.array([1e30, -1e30, np.finfo(np.float32).max, -np.finfo(np.float32).max, 1e300, -1e300, 5e-324,
                     -5e-324, -0.0, 1.0, -1.0])


def _action(rng: np.random.Generator, shape: tuple[int, ...]):
    """(action, well_formed) from the mixture of the module docstring."""
    kind = rng.integers(6)
    if kind == 0:
        return rng.uniform(-1.0, 1.0, shape).astype(np.float32), True
    if kind == 1:
        return rng.uniform(-1e3, 1e3, shape), True
    if kind == 2:
        return rng.choice(EXTREMES, size=shape), True
    if kind == 3:
        a = rng.uniform(-2.0, 2.0, shape)
        return (a.astype(int) if rng.integers(2) else a.astype(np.float16)), True
    if kind == 4:  # a mix of extreme and ordinary entries
        a = rng.uniform(-1.0, 1.0, shape)
        pick = rng.random(shape) < 0.3
        a[pick] = rng.choice(EXTREMES, size=int(pick.sum()))
        return a, True
    bad = invalid_actions(shape)
    return bad[rng.integers(len(bad))][1], False


def _check(action, obs, reward, terminated, truncated, info, space, names, n):
    a = np.asarray(action, dtype=float).reshape(n, -1)
    obs = np.asarray(obs).reshape(n, -1)
    assert np.isfinite(obs).all() and all(space.contains(o) for o in obs)
    assert np.isfinite(np.asarray(reward, dtype=float)).all()
    flags = np.asarray(terminated), np.asarray(truncated)
    assert all(f.dtype == np.bool_ for f in flags)
    if "failure" not in info:  # every copy was reset in this (NextStep autoreset) step: its reset info only
        assert info["_t"].all() and not info["t"].any()
        return
    failure = np.atleast_1d(info["failure"])
    reason = np.atleast_1d(info["failure_reason"])
    mask = info.get("_failure", np.ones(n, bool))
    for i in np.flatnonzero(mask):
        assert int(failure[i]) in names and bool(reason[i]) == bool(failure[i])
        assert int(np.atleast_1d(info["n_clipped"])[i]) == np.count_nonzero(np.abs(a[i]) > 1.0)


def _refused(env, action) -> None:
    """A malformed ``action`` raises ActionError and leaves ``env`` where it was."""
    before = env_state(env)
    with pytest.raises(ActionError):
        env.step(action)
    assert_same_state(before, env_state(env))


@pytest.mark.parametrize("env_id", IDS)
def test_fuzz_single_env(env_id):
    rng = np.random.default_rng(IDS.index(env_id))
    env = make_single(env_id, episode_time=10.0)
    env.reset(seed=0)
    shape, names = env.action_space.shape, env.task.failure_names
    episodes, refused = 0, 0
    for _ in range(3000):
        action, good = _action(rng, shape)
        if not good:
            _refused(env, action)
            refused += 1
            continue
        obs, r, term, trunc, info = env.step(action)
        _check(action, obs, r, term, trunc, info, env.observation_space, names, 1)
        if term or trunc:
            episodes += 1
            env.reset()
    assert episodes >= 3 and refused >= 10


@pytest.mark.parametrize("env_id", IDS)
def test_fuzz_native_vector_env(env_id):
    n = 3
    rng = np.random.default_rng(100 + IDS.index(env_id))
    env = make_native(env_id, n, episode_time=5.0)
    env.reset(seed=0)
    shape, names = env.action_space.shape, env.task.failure_names
    ends, refused = 0, 0
    for _ in range(1000):
        action, good = _action(rng, shape)
        if not good:
            _refused(env, action)
            refused += 1
            continue
        obs, r, term, trunc, info = env.step(action)
        _check(action, obs, r, term, trunc, info, env.single_observation_space, names, n)
        ends += int(np.count_nonzero(term | trunc))
    assert ends >= 3 * n and refused >= 5
