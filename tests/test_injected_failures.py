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
