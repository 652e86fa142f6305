"""A state made non-finite by hand (as a numerical blow-up would leave it) ends the episode with a finite reward and
a sentence naming the entry, in the rotorcraft and point-mass envs (found by a review on 2026-12-06: the craft's
failure text raised ValueError from the simulator it asked for a diagnosis, and the point-mass chain's terminating
reward was NaN)."""

import gymnasium as gym
import numpy as np
import pytest


@pytest.mark.parametrize("env_id, needle", [
    ("laddermill_gym/Rotorcraft-v0", "state[5] = nan is not finite"),
    ("laddermill_gym/PointMassChain-v0", "non-finite state"),
])
def test_a_non_finite_state_terminates_with_a_finite_reward_and_its_cause(env_id, needle):
    env = gym.make(env_id)
    task = env.unwrapped.task
    env.reset(seed=0)
    zero = np.zeros(env.action_space.shape)
    for _ in range(3):
        env.step(zero)
    task.batch.states[0, 5] = np.nan
    _, reward, terminated, truncated, info = env.step(zero)
    assert terminated and not truncated
    assert np.isfinite(reward)
    assert needle in info["failure_reason"]
    assert all(np.isfinite(v) for k, v in info.items() if k.startswith("reward_"))


@pytest.mark.parametrize("env_id, kwargs, wing", [
    ("laddermill_gym/TetheredWing-v0", {}, 0),
    ("laddermill_gym/LadderMill-v0", dict(scene_options={"n_wings": 11}, settle={"max_time": 100.0}), 4),
])
def test_the_wing_families_name_the_entry_or_the_fastest_body(env_id, kwargs, wing):
    """The wings' and the mill's integration failures said only "non-finite state" or "speed or rate limit" (review
    of 2026-12-07): a NaN written into wing k's roll rate is named with its value, and a speed of 5000 m/s written
    into its velocity names wing k as the fastest, at that speed."""
    from laddermill_gym.kernels.contract import B3_SIZE

    unit = "slot" if "Mill" in env_id else "wing"  # the mill names its state's wings by slot (2026-12-07)
    for entry, value, needle in ((10, np.nan, f"{unit} {wing} p [rad/s] = nan (state entry {wing * B3_SIZE + 10};"),
                                 (7, 5000.0, f"fastest {unit} {wing}: speed 5000 m/s")):
        env = gym.make(env_id, **kwargs)
        env.reset(seed=0)
        zero = np.zeros(env.action_space.shape, np.float32)
        env.step(zero)
        env.unwrapped.task.batch.states[0, wing * B3_SIZE + entry] = value
        _, reward, terminated, _, info = env.step(zero)
        assert terminated and np.isfinite(reward) and info["failure"] == 1
        assert needle in info["failure_reason"], info["failure_reason"]
        env.close()
