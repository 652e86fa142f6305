"""The compiled action path (kernels/action_pass.py, issue 32 point 2) against the numpy code it replaced as the
oracle: the clip and its count, the grouped map to the wings' controls, the rotorcraft's affine map, bit for bit,
and the errors for actions that are not finite real arrays."""

import numpy as np
import pytest

from laddermill_gym.envs.actions import ActionError, clip_actions
from laddermill_gym.kernels.action_pass import affine_controls, clip_count, grouped_controls


def _numpy_clip(action, n_copies, n_actions):
    """The numpy code of before: float64, clipped to [-1, 1], |a| > 1 counted per row."""
    a = np.asarray(action).astype(float).reshape(n_copies, n_actions)
    return np.clip(a, -1.0, 1.0), np.count_nonzero(np.abs(a) > 1.0, axis=1)


def _actions(rng, shape, dtype):
    a = rng.normal(0.0, 1.2, shape)
    a.flat[:: 7] = 1.0  # the bounds themselves, and signed zeros
    a.flat[1:: 11] = -1.0
    a.flat[2:: 13] = -0.0
    return a.astype(dtype)


@pytest.mark.parametrize("dtype", [np.float32, np.float64, np.int64])
def test_clip_actions_bit_for_bit(dtype):
    rng = np.random.default_rng(3)
    for shape in [(1, 3), (64, 3), (512, 6), (5, 2)]:
        a = _actions(rng, shape, dtype)
        got, n = clip_actions(a, *shape)
        want, n_want = _numpy_clip(a, *shape)
        assert got.dtype == want.dtype and n.dtype == n_want.dtype
        assert np.array_equal(got.view(np.int64), want.view(np.int64))  # signs of zero included
        assert np.array_equal(n, n_want)
    # an action of n_copies x n_actions entries in another shape is taken in row order, as before
    a = _actions(rng, (4 * 3,), np.float64)
    assert np.array_equal(clip_actions(a, 4, 3)[0], _numpy_clip(a, 4, 3)[0])


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_clip_actions_names_non_finite_entries(bad):
    a = np.zeros((3, 3))
    a[2, 1] = bad
    with pytest.raises(ActionError, match=r"non-finite entries at \[\(2, 1\)\]"):
        clip_actions(a, 3, 3)
    assert clip_count(a, np.empty((3, 3)), np.empty(3, dtype=np.intp)) == 2 * 3 + 1
    with pytest.raises(ActionError, match="shape"):
        clip_actions(np.zeros((3, 2)), 3, 3)
    with pytest.raises(ActionError, match="complex"):
        clip_actions(np.zeros((3, 3), complex), 3, 3)


def test_grouped_controls_bit_for_bit():
    """The ActionMap's tail-mode map (numpy: mid + a[:, group_of] half clipped to the limits, the masked rows
    written) against its numpy code, with limits tighter than the range so that the clip acts."""
    rng = np.random.default_rng(5)
    nb, nw, ng = 257, 5, 2
    group_of = np.array([0, 0, 1, 1, 0], dtype=np.int64)
    mid = rng.normal(0.0, 0.1, (nw, 3))
    half = rng.uniform(0.1, 0.4, (nw, 3))
    lo, hi = mid - 0.8 * half, mid + 0.9 * half
    lo[0, 0] = 0.0  # a zero limit: numpy's clip keeps max(-0.0, 0.0) = 0.0
    a, _ = clip_actions(_actions(rng, (nb, 3 * ng), np.float64), nb, 3 * ng)
    a[0, 0] = -0.0
    sel = rng.uniform(size=nb) < 0.7
    per_group = a.reshape(-1, ng, 3)
    u = np.clip(mid + per_group[:, group_of] * half, lo, hi).reshape(nb, -1)
    controls, last = np.full((nb, 3 * nw), 7.0), np.full((nb, 3 * ng), 7.0)
    want_c, want_l = controls.copy(), last.copy()
    want_c[sel], want_l[sel] = u[sel], a[sel]
    grouped_controls(a, group_of, mid, half, lo, hi, sel, controls, last)
    assert np.array_equal(controls.view(np.int64), want_c.view(np.int64))
    assert np.array_equal(last, want_l)


def test_affine_controls_bit_for_bit():
    """The rotorcraft's map (numpy: (mid + a half)[sel]) against its numpy code."""
    rng = np.random.default_rng(7)
    nb = 300
    mid, half = rng.normal(0.0, 1.0, 2), rng.uniform(0.5, 2.0, 2)
    a, _ = clip_actions(_actions(rng, (nb, 2), np.float32), nb, 2)
    sel = rng.uniform(size=nb) < 0.5
    controls, last = np.zeros((nb, 2)), np.zeros((nb, 2))
    want_c, want_l = controls.copy(), last.copy()
    want_c[sel], want_l[sel] = (mid + a * half)[sel], a[sel]
    affine_controls(a, mid, half, sel, controls, last)
    assert np.array_equal(controls, want_c) and np.array_equal(last, want_l)


def test_wing_env_controls_as_before():
    """TetheredWing-v0's vector step writes the controls the numpy ActionMap.controls gives (tail mode, a mask)."""
    import gymnasium as gym

    env = gym.make_vec("laddermill_gym/TetheredWing-v0", num_envs=6, vectorization_mode="vector_entry_point",
                       autoreset_mode="Disabled")
    env.reset(seed=0)
    task = env.unwrapped.task
    rng = np.random.default_rng(11)
    a = rng.normal(0.0, 1.3, (6, task.n_actions))
    before = task.batch.controls.copy()
    mask = np.array([True, False, True, True, False, True])
    task.step(a, mask)
    clipped, _ = _numpy_clip(a, 6, task.n_actions)
    want = task.actions.controls(clipped)
    assert np.array_equal(task.batch.controls[mask], want[mask])
    assert np.array_equal(task.batch.controls[~mask], before[~mask])
    env.close()
