"""Videos of the environments: Gymnasium's RecordVideo and Stable-Baselines3's VecVideoRecorder (used by
``rl_zoo3.record_video``) write an MP4 of the ``rgb_array`` frames when moviepy is installed (the ``video`` extra).
Slow tests (``-m slow``), skipped without moviepy.

Oracle: a twin environment (same id, arguments, seed and actions) rendered frame by frame; the video, decoded by
imageio's ffmpeg reader (not moviepy, which wrote it), must hold those frames up to the codec's loss. moviepy 2.x
may drop the last frame of a clip (its duration rounding: 11 frames at 20 frames/s come out as 10), so one frame
fewer than rendered is accepted.
"""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the environments)

pytest.importorskip("moviepy", reason="moviepy is not installed (the video extra: pip install moviepy)")
iio = pytest.importorskip("imageio.v2", reason="imageio (installed with moviepy) is missing")
#: slow: CI installs no video extra (moviepy and a 165 MB ffmpeg binary); run with -m slow where it is installed
pytestmark = pytest.mark.slow

ENV_ID = "laddermill_gym/TetheredWing-v0"
KW = dict(render_mode="rgb_array", episode_time=0.5)  # [s] 10 control periods of 0.05 s: 11 frames with the reset
CODEC_LOSS = 2.0  # [0-255 grey levels] mean absolute difference allowed per frame (H.264 at moviepy's defaults)


def twin_frames(n_steps: int) -> list[np.ndarray]:
    """The frames of a second environment: after reset(seed=0) and after each of ``n_steps`` zero actions."""
    env = gym.make(ENV_ID, **KW)
    env.reset(seed=0)
    frames = [env.render()]
    for _ in range(n_steps):
        env.step(np.zeros(env.action_space.shape, np.float32))
        frames.append(env.render())
    env.close()
    return frames


def decoded(path) -> list[np.ndarray]:
    reader = iio.get_reader(path, "ffmpeg")
    try:
        return [np.asarray(f) for f in reader]
    finally:
        reader.close()


def assert_video_holds(path, reference: list[np.ndarray]) -> None:
    frames = decoded(path)
    assert len(reference) - 1 <= len(frames) <= len(reference), (len(frames), len(reference))
    assert frames[0].shape == reference[0].shape
    assert reference[0].std() > 10.0  # the rendering is a picture, not a blank frame
    for k, (got, want) in enumerate(zip(frames, reference[:len(frames)], strict=True)):
        loss = np.abs(got.astype(float) - want.astype(float)).mean()
        assert loss < CODEC_LOSS, f"frame {k}: mean difference {loss:.2f} grey levels"


def test_gymnasium_record_video_writes_the_rendered_frames(tmp_path):
    env = gym.wrappers.RecordVideo(gym.make(ENV_ID, **KW), str(tmp_path / "videos"), episode_trigger=lambda e: e == 0,
                                   name_prefix="wing", disable_logger=True)
    env.reset(seed=0)
    n_steps = 0
    while True:
        *_, terminated, truncated, _ = env.step(np.zeros(env.action_space.shape, np.float32))
        n_steps += 1
        if terminated or truncated:
            break
    env.close()
    assert n_steps == 10
    assert_video_holds(tmp_path / "videos" / "wing-episode-0.mp4", twin_frames(n_steps))


def test_sb3_vec_video_recorder_writes_the_rendered_frames(tmp_path):
    from stable_baselines3.common.vec_env import DummyVecEnv, VecVideoRecorder

    length = 6  # [steps] recorded after the reset frame
    venv = VecVideoRecorder(DummyVecEnv([lambda: gym.make(ENV_ID, **KW)]), str(tmp_path),
                            record_video_trigger=lambda step: step == 0, video_length=length, name_prefix="wing")
    venv.seed(0)
    venv.reset()
    for _ in range(length + 2):
        venv.step(np.zeros((1, *venv.action_space.shape), np.float32))
    venv.close()
    assert_video_holds(tmp_path / f"wing-step-0-to-step-{length}.mp4", twin_frames(length))
