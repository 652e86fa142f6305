"""An episode is a whole number of control periods: ``episode_time`` that is not is refused, naming both, in every env
family (``envs/task_base.episode_periods``). Before, the fraction was rounded away without a word: ``episode_time =
0.07`` at the 50 ms period ended the episode after 0.05 s, and 10.01 after 10 s."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs.task_base import episode_periods

FAMILIES = ["laddermill_gym/TetheredWing-v1", "laddermill_gym/Rotorcraft-v0", "laddermill_gym/PointMassChain-v0",
            "laddermill_gym/LadderMill-v3", "laddermill_gym/PumpingKite-v1"]


@pytest.mark.parametrize("env_id", FAMILIES)
@pytest.mark.parametrize("episode_time", [0.07, 10.01])
def test_a_fraction_of_a_period_is_refused(env_id, episode_time):
    with pytest.raises(ValueError, match=rf"episode_time = {episode_time} s is not a whole number of control periods "
                                         r"\(control_dt = 0.05 s: "):
        gym.make(env_id, episode_time=episode_time)


def test_a_whole_number_of_periods_is_the_episode():
    """The episode ends, truncated, at the time asked for (sums of decimal times included)."""
    assert episode_periods(0.1 + 0.2, 0.05) == 6  # 0.30000000000000004 s
    assert episode_periods(61.0, 0.05) == 1220
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        env = gym.make("laddermill_gym/TetheredWing-v1", episode_time=0.25)
    env.reset(seed=0)
    action = np.zeros(env.action_space.shape, dtype=np.float32)  # 0.25 s of the zero action
    for k in range(5):
        _, _, term, trunc, info = env.step(action)
        assert not term and trunc == (k == 4)
    assert info["t"] == pytest.approx(0.25, abs=1e-12)
    env.close()


def test_a_training_config_names_its_file_and_field(tmp_path):
    """A config's episode length is checked when the config loads, before any env is built."""
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.model.configio import CONFIG_DIR, ConfigError

    text = (CONFIG_DIR / "agents" / "ppo_tethered_wing.yaml").read_text()
    assert "\n  episode_time: " in text
    path = tmp_path / "bad.yaml"
    path.write_text(text.replace("\n  episode_time: ", "\n  episode_time: 10.01 #", 1))
    with pytest.raises(ConfigError, match=r"field 'env_kwargs.episode_time' = 10.01: episode_time = 10.01 s is not a "
                                          r"whole number of control periods") as err:
        load_rl_config(path)
    assert str(path) in str(err.value)


@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v1", "laddermill_gym/Rotorcraft-v0",
                                    "laddermill_gym/PointMassChain-v0"])
def test_a_disturbance_after_the_episode_is_named(env_id):
    """A disturbance whose earliest onset is at or after the episode's end never acts: a warning names it (one that
    may start within the episode is silent)."""
    late = [{"type": "DirectionStep", "step": 0.01, "time": 2.0},
            {"type": "OneMinusCosineGust", "amplitude": 0.1, "duration": 1.0, "time": [0.5, 3.0]},
            {"type": "OneMinusCosineGust", "amplitude": 0.1, "duration": 1.0, "time": [1.0, 3.0]}]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        gym.make(env_id, episode_time=1.0, disturbances=late, **({"settle_time": 0.0} if "PointMass" in env_id else {}))
    named = [str(w.message) for w in caught if "never acts" in str(w.message)]
    assert named == ["disturbances[0] (DirectionStep, time = 2.0 s) starts at or after the episode's end "
                     "(episode_time = 1.0 s): it never acts",
                     "disturbances[2] (OneMinusCosineGust, time = (1.0, 3.0) s) starts at or after the episode's end "
                     "(episode_time = 1.0 s): it never acts"]
