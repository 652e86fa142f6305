"""Issue 34 item 11: every registered id works in every Gymnasium vectorization mode ("sync", "async",
"vector_entry_point") and with SB3's ``make_vec_env``, renders, and raises no Gymnasium warning (float32 spaces).

PointMassChain-v0's string runs the serial point-mass kernels, which start no numba thread pool, so the default
"fork" context works even after this process started GNU OpenMP's (tests/test_pointmass_fork.py).

Oracle: Gymnasium's SyncVectorEnv over ``gymnasium.make`` single envs (its own code); the other modes must give the
same observations and rewards bit for bit (the serial kernels run a single env's arithmetic)."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

from laddermill_gym.envs.task_base import LateDisturbanceWarning
from tests.env_cases import IDS, PMC, case_kwargs

MODES = ("sync", "async", "vector_entry_point")


def _tiny(env_id: str) -> dict:
    """Short episodes; the point-mass chain without its 600 s settling (the children of "forkserver" compute it)."""
    kw = case_kwargs(env_id, episode_time=0.2)
    if env_id == PMC:
        kw["settle_time"] = 0.0
    return kw


def _rollout(vec, n_steps: int = 5):
    obs, _ = vec.reset(seed=3)
    out, rewards = [obs], []
    a = np.full(vec.action_space.shape, 0.1, np.float32)
    for _ in range(n_steps):  # past the 0.2 s episode: one autoreset
        obs, r, *_ = vec.step(a)
        out.append(obs)
        rewards.append(r)
    vec.close()
    return np.array(out), np.array(rewards)


def _make_vec(env_id, mode, **vector_kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        return gym.make_vec(env_id, 2, vectorization_mode=mode, **({"vector_kwargs": vector_kwargs}
                                                                    if vector_kwargs else {}), **_tiny(env_id))


@pytest.mark.parametrize("env_id", IDS)
def test_every_vectorization_mode_gives_the_sync_rollout(env_id):
    ref_obs, ref_rew = _rollout(_make_vec(env_id, "sync"))
    for mode in MODES[1:]:
        vec = _make_vec(env_id, mode)
        obs, rew = _rollout(vec)
        np.testing.assert_array_equal(obs, ref_obs, err_msg=mode)
        np.testing.assert_array_equal(rew, ref_rew, err_msg=mode)


@pytest.mark.parametrize("env_id", IDS)
def test_sb3_make_vec_env_steps_and_renders(env_id):
    pytest.importorskip("stable_baselines3")
    from stable_baselines3.common.env_util import make_vec_env

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        venv = make_vec_env(env_id, n_envs=2, seed=0, env_kwargs=_tiny(env_id))  # render_mode="rgb_array"
    obs = venv.reset()
    obs, r, done, infos = venv.step(np.zeros((2, *venv.action_space.shape), np.float32))
    assert obs.shape == (2, *venv.observation_space.shape) and np.isfinite(r).all()
    frames = venv.get_images()
    assert len(frames) == 2 and all(f.dtype == np.uint8 and f.shape == (480, 640, 3) for f in frames)
    venv.close()


def test_sb3_make_vec_env_with_point_mass_defaults():
    """The issue's call, with every registered default (before: refused, the env could not render)."""
    pytest.importorskip("stable_baselines3")
    from stable_baselines3.common.env_util import make_vec_env

    venv = make_vec_env(PMC)
    venv.reset()
    obs, *_ = venv.step(np.zeros((1, *venv.action_space.shape), np.float32))
    assert np.isfinite(obs).all()
    venv.close()


@pytest.mark.parametrize("env_id", IDS)
def test_no_gymnasium_warning_and_float32_spaces(env_id):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        warnings.simplefilter("error", UserWarning)  # Gymnasium's checker warns with UserWarning
        warnings.simplefilter("ignore", LateDisturbanceWarning)  # the cases' direction step at 1 s: after 0.2 s
        env = gym.make(env_id, **_tiny(env_id))
        env.reset(seed=0)
        env.step(env.action_space.sample())
    for space in (env.observation_space, env.action_space):
        assert space.dtype == np.float32 and space.low.dtype == np.float32 and space.high.dtype == np.float32
    assert "rgb_array" in env.metadata["render_modes"]
