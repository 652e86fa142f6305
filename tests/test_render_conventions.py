"""Rendering conventions the video tools and PettingZoo read: the frame rate is the control rate (Gymnasium's
``render_fps``, SB3's ``VecEnv.metadata``, read by RecordVideo and VecVideoRecorder), a vector env renders only after
its reset, and the per-wing ParallelEnv takes PettingZoo's ``render_mode`` keyword. Oracles: 1 / control_dt and
Gymnasium's, SB3's and PettingZoo's documented contracts (the env checker's render_fps > 0 assertion,
``gymnasium.error.ResetNeeded``, ``env_fn(render_mode=...)``)."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)

WING = "laddermill_gym/TetheredWing-v0"


@pytest.mark.parametrize("control_dt", [0.05, 0.3, 2.5])
def test_render_fps_is_the_control_rate_for_any_control_period(control_dt):
    """render_fps = 1 / control_dt exactly (2.5 s gave 0, which Gymnasium's env checker refuses at render(); 0.3 s gave
    3 instead of 3.33); the single env renders a frame."""
    env = gym.make(WING, render_mode="rgb_array", control_dt=control_dt, physics_dt=0.05, episode_time=30.0)
    env.reset(seed=0)
    assert env.metadata["render_fps"] == pytest.approx(1.0 / control_dt, rel=1e-12)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.ndim == 3 and frame.shape[2] == 3
    env.close()
    venv = gym.make_vec(WING, 2, vectorization_mode="vector_entry_point", control_dt=control_dt, physics_dt=0.05,
                        episode_time=30.0)
    assert venv.metadata["render_fps"] == pytest.approx(1.0 / control_dt, rel=1e-12)
    venv.close()


def test_vector_env_renders_only_after_its_reset():
    venv = gym.make_vec(WING, 2, vectorization_mode="vector_entry_point", render_mode="rgb_array")
    with pytest.raises(gym.error.ResetNeeded):
        venv.render()
    venv.reset(seed=0)
    frames = venv.render()
    assert len(frames) == 2 and all(f.dtype == np.uint8 for f in frames)
    venv.close()


def test_sb3_vec_env_gives_video_recorders_the_control_rate_and_keeps_one_figure():
    import matplotlib.pyplot as plt

    from laddermill_gym.envs.sb3 import sb3_vec_env

    venv = sb3_vec_env(WING, 2, seed=0, render_mode="rgb_array")
    assert venv.metadata["render_fps"] == pytest.approx(20.0)  # SB3's VecVideoRecorder defaults to 30 without it
    with pytest.raises(gym.error.ResetNeeded):
        venv.get_images()
    venv.reset()
    before = len(plt.get_fignums())
    first = venv.get_images()
    for _ in range(3):
        venv.get_images()
    assert len(plt.get_fignums()) <= before + 1  # one figure, not one per call
    assert len(first) == 2 and first[0].dtype == np.uint8
    venv.close()
    assert len(plt.get_fignums()) <= before


def test_parallel_env_takes_pettingzoos_render_mode_keyword():
    from laddermill_gym.multiagent import parallel_env

    env = parallel_env("laddermill_gym/LadderChain-v0", render_mode=None)
    assert env.render_mode is None
    with pytest.raises(ValueError, match="does not render"):
        parallel_env("laddermill_gym/LadderChain-v0", render_mode="human")
