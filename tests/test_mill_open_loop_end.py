"""How LadderMill-v0's open loop ends after the paper's 0.01 rad direction step (docs/features.md,
docs/controllers.md: the loop diverges laterally and the episode ends at 8.7 s): the env's own failure sentence,
checked against the observation it was read from (the wing whose sideslip left the range, and where it sits)."""

import math

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_INDEX
from laddermill_gym.harness.evaluate import SCENARIOS

LM = "laddermill_gym/LadderMill-v0"


@pytest.mark.slow
def test_open_loop_ends_by_sideslip_near_the_top():
    """The open loop (the operating point's controls held) under evaluate's ``paper_step`` scenario terminates
    within 20 s by the aerodynamic range; the failure sentence names the slot whose |beta| is beyond the range
    and its angles as the last observation holds them; that wing's slot is in the top quarter of the loop (the
    slots' heights at the start). Prints the sentence and the slot's height rank."""
    kw = {"episode_time": 300.0, "disturbances": SCENARIOS["paper_step"]}
    env = gym.make(LM, **kw).unwrapped
    ctrl = make_controller("open_loop", LM, kw)
    obs, _ = env.reset(seed=0)
    task = env.task
    heights = -task.simulator(0).wing_positions()[:, 2]  # the slots' CG heights at the start [m] (z down)
    while True:
        obs, _, term, trunc, info = env.step(ctrl.predict(obs)[0])
        if term or trunc:
            break
    reason = info["failure_reason"]
    rows = np.asarray(task.raw_obs[0])[: task.n_wings * N_OBS_PER_WING].reshape(task.n_wings, N_OBS_PER_WING)
    k = int(reason.split("slot ")[1].split()[0])
    beta = math.degrees(rows[k, OBS_INDEX["beta"]])
    rank = int(np.sum(heights > heights[k]))
    print(f"\nLadderMill-v0 open loop, paper_step: {reason}; slot {k} of {task.n_wings}, {rank} slots higher "
          f"(the top at {heights.max():.0f} m, this slot at {heights[k]:.0f} m)")
    assert term and info["failure_name"] == "aerodynamic range exceeded" and info["t"] < 20.0
    assert f"beta = {beta:.1f} deg" in reason and abs(beta) > math.degrees(task.beta_max)
    assert rank < task.n_wings // 4
