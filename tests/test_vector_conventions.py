"""Issue 34 item 12: the native vector env of every registered id follows Gymnasium's ``SyncVectorEnv`` over the
same single envs (copy i seeded seed + i): observations, rewards, terminations and the whole info dict (every key,
mask, value and dtype; a copy reset in the call holds its reset info, ``t`` and e.g. ``reference_power_W``) in the
three autoreset modes (NextStep; SameStep with ``final_obs`` / ``final_info``; Disabled with
``reset(options={"reset_mask": ...})``), and ``render()`` gives one frame per copy.

Oracle: ``gymnasium.vector.SyncVectorEnv`` (Gymnasium's own code) over ``gymnasium.make`` single envs; the serial
kernels run a single env's arithmetic, so everything is compared bit for bit."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.vector import AutoresetMode

from tests.env_cases import IDS, PK, PK1, PMC, TW, case_kwargs, make_native

MODES = (AutoresetMode.NEXT_STEP, AutoresetMode.SAME_STEP, AutoresetMode.DISABLED)


def _sync(env_id: str, n: int, mode=AutoresetMode.NEXT_STEP, **kw):
    kwargs = case_kwargs(env_id, **kw)

    def make():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            return gym.make(env_id, **kwargs)

    return gym.vector.SyncVectorEnv([make for _ in range(n)], autoreset_mode=mode)


def assert_same_info(a: dict, b: dict, where: str = "info") -> None:
    """Two vector infos are the same: keys, masks, values and dtypes, at every depth."""
    assert set(a) == set(b), f"{where}: keys differ: {sorted(set(a) ^ set(b))}"
    for k in a:
        x, y = a[k], b[k]
        if isinstance(y, dict):
            assert_same_info(x, y, f"{where}[{k!r}]")
        elif k == "final_obs":
            for xi, yi in zip(x, y, strict=True):
                assert (xi is None) == (yi is None), where
                if yi is not None:
                    np.testing.assert_array_equal(xi, yi)
        else:
            assert x.dtype == y.dtype, f"{where}[{k!r}]: {x.dtype} != {y.dtype}"
            np.testing.assert_array_equal(x, y, err_msg=f"{where}[{k!r}]")


def _episode_time(env_id: str) -> float:
    """A few control periods: episodes end (and copies are reset) within the test."""
    return 0.2 if env_id != PMC else 0.15


@pytest.mark.parametrize("mode", MODES, ids=[m.value for m in MODES])
@pytest.mark.parametrize("env_id", IDS)
def test_native_vector_env_equals_sync_vector_env(env_id, mode):
    n, steps = 2, 12
    kw = {"episode_time": _episode_time(env_id)}
    native = make_native(env_id, n, autoreset_mode=mode, **kw)
    sync = _sync(env_id, n, mode, **kw)
    assert native.metadata["autoreset_mode"] == mode
    o1, i1 = native.reset(seed=5)
    o2, i2 = sync.reset(seed=5)
    np.testing.assert_array_equal(o1, o2)
    assert_same_info(i1, i2, "reset")
    # every single env but the pumping kite's, v0 and v1 (whose reward scale is reward.reference_power), reports its
    # reference power at reset: so must the native one (compared above, key by key)
    assert ("reference_power_W" in i1) == (env_id not in (PK, PK1))
    rng = np.random.default_rng(2)
    scale = 0.3
    saw_end = False
    for k in range(steps):
        a = rng.uniform(-scale, scale, size=native.action_space.shape).astype(np.float32)
        out, ref = native.step(a), sync.step(a)
        for x, y in zip(out[:4], ref[:4], strict=True):
            np.testing.assert_array_equal(x, y, err_msg=f"step {k}")
        assert_same_info(out[4], ref[4], f"step {k}")
        done = ref[2] | ref[3]
        saw_end |= bool(done.any())
        if mode == AutoresetMode.DISABLED and done.any():
            mask = done.copy()
            with pytest.raises(RuntimeError, match="reset_mask"):
                native.step(a)  # an ended copy must be reset first
            o1, i1 = native.reset(options={"reset_mask": mask})
            o2, i2 = sync.reset(options={"reset_mask": mask.copy()})
            np.testing.assert_array_equal(o1, o2)
            assert_same_info(i1, i2, f"reset_mask after step {k}")
    assert saw_end


def test_reset_mask_resets_only_the_masked_copies_with_their_seeds():
    n = 3
    native = make_native(TW, n, autoreset_mode="Disabled")
    sync = _sync(TW, n, AutoresetMode.DISABLED)
    native.reset(seed=1)
    sync.reset(seed=1)
    a = np.full(native.action_space.shape, 0.2, np.float32)
    for _ in range(3):
        native.step(a)
        sync.step(a)
    mask = np.array([False, True, False])
    o1, i1 = native.reset(seed=[None, 40, 41], options={"reset_mask": mask})
    o2, i2 = sync.reset(seed=[None, 40, 41], options={"reset_mask": mask.copy()})
    np.testing.assert_array_equal(o1, o2)
    assert_same_info(i1, i2)
    assert i1["_t"].tolist() == [False, True, False]
    for _ in range(3):
        out, ref = native.step(a), sync.step(a)
        np.testing.assert_array_equal(out[0], ref[0])
        assert_same_info(out[4], ref[4])
    for bad, err in ((np.array([1, 0, 0]), TypeError), (np.zeros(2, bool), ValueError), (np.zeros(3, bool), ValueError),
                     ([True, False, False], TypeError)):
        with pytest.raises(err, match="reset_mask"):
            native.reset(options={"reset_mask": bad})


@pytest.mark.parametrize("env_id", [TW, PMC])
def test_render_gives_one_frame_per_copy_as_sync(env_id):
    n = 2
    native = make_native(env_id, n, render_mode="rgb_array")
    sync = _sync(env_id, n, render_mode="rgb_array")
    native.reset(seed=0)
    sync.reset(seed=0)
    a = np.full(native.action_space.shape, 0.3, np.float32)
    for _ in range(3):
        native.step(a)
        sync.step(a)
    frames, expected = native.render(), sync.render()
    assert isinstance(frames, tuple) and len(frames) == n
    for f, g in zip(frames, expected, strict=True):
        assert f.dtype == np.uint8 and f.shape == g.shape == (480, 640, 3)
        np.testing.assert_array_equal(f, g)
    assert len(np.unique(frames[0].reshape(-1, 3), axis=0)) > 10  # a picture, not a blank frame
    native.close()
    sync.close()
