"""The point-mass tethered wing's lateral response to the paper's 0.01 rad wind-direction step (docs/pointmass.md,
"What the point-mass fidelity leaves out"): without attitude dynamics the kite has no lateral divergence, it swings
to the turned wind's equilibrium and stays. Oracle: the equilibrium turns with the wind about the vertical through
the station, so the kite's final sideways offset is its horizontal distance before the step times sin(0.01)."""

import numpy as np

from laddermill_gym.envs.pointmass.env import PointMassEnv

TURN, STEP_AT = 0.01, 1.0  # [rad] the env's default direction step and its start [s]


def test_kite_follows_the_direction_step_and_stays():
    """PointMassEnv on tethered_wing (1 m elements), settled 60 s with the start attitude held, then 120 s of the
    default disturbance with zero actions: the kite ends at the rotated equilibrium (1e-3 of the offset), its
    swing has died out to 1 % of the offset within 40 s of the step, and every node is at rest to 1e-8 m/s at
    120 s. Prints the offset, the overshoot, the settling times and the largest node speed."""
    env = PointMassEnv(scene="tethered_wing", settle_time=60.0, episode_time=120.0)
    env.reset(seed=0)
    task = env.unwrapped.task
    x = task.batch.states[0].reshape(-1, 6)
    before = x[task.kite_nodes[0], :2].copy()  # the settled kite's horizontal position [m]
    y0 = task.raw_obs[0, 1]
    ts, ys = [], []
    done, action = False, np.zeros(env.action_space.shape, dtype=np.float32)
    while not done:
        _, _, terminated, truncated, info = env.step(action)
        ts.append(info["t"])
        ys.append(task.raw_obs[0, 1] - y0)
        done = terminated or truncated
    assert not terminated and ts[-1] > 119.9
    ts, ys = np.array(ts), np.array(ys)
    x = task.batch.states[0].reshape(-1, 6)
    expected = before[0] * np.sin(TURN) + before[1] * (np.cos(TURN) - 1.0)  # the rotated position's y change
    final = ys[-1]
    speed = np.abs(x[:, 3:]).max()

    def settled(fraction):  # the time after the step from which the offset stays within fraction of its end
        out = np.nonzero(np.abs(ys - final) > fraction * abs(final))[0]
        return ts[out[-1] + 1] - STEP_AT

    peak = np.argmax(np.abs(ys))
    print(f"kite offset {final:.4f} m sideways (the wind's turn of its {np.hypot(*before):.2f} m horizontal "
          f"distance: {expected:.4f} m); overshoot {100 * (ys[peak] / final - 1):.0f} % at "
          f"{ts[peak] - STEP_AT:.1f} s after the step; within 10 % of the end from {settled(0.1):.1f} s and within "
          f"1 % from {settled(0.01):.1f} s after it; largest node speed {speed:.2g} m/s at {ts[-1]:.0f} s")
    assert abs(final - expected) < 1e-3 * abs(expected)
    assert settled(0.01) < 40.0
    assert speed < 1e-8
