"""PointMassEnv: the Gymnasium contract (env checker, determinism), actions mapped onto the kites' commanded
attitude (closed form: start attitude + a x range, clipped), and the physical ends of an episode."""

import math

import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from laddermill_gym.envs.pointmass.env import PointMassEnv


@pytest.fixture(scope="module")
def env():
    return PointMassEnv(episode_time=2.0)


def test_env_checker(env):
    check_env(env, skip_render_check=True)


def test_actions_command_the_attitude(env):
    u0 = env.u0.reshape(-1, 3)
    u = env.commanded_attitude(np.array([0.4, -1.7])).reshape(-1, 3)
    assert u[:, 1] == pytest.approx(u0[:, 1] + 0.4 * math.radians(5.0))
    assert u[:, 0] == pytest.approx(u0[:, 0] - math.radians(15.0))  # clipped at -1
    assert u[:, 2] == pytest.approx(u0[:, 2])
    env.reset(seed=1)
    _, _, _, _, info = env.step(np.array([0.4, -1.7], dtype=np.float32))
    assert info["n_clipped"] == 1
    np.testing.assert_allclose(env.sim.u.reshape(-1, 3), u)


def test_episodes_are_deterministic(env):
    runs = []
    for _ in range(2):
        env.reset(seed=3)
        obs = [env.step(np.array([0.0, 0.0], dtype=np.float32)) for _ in range(3)]
        runs.append(np.concatenate([o[0] for o in obs]))
    np.testing.assert_array_equal(runs[0], runs[1])


def test_episode_ends():
    e = PointMassEnv(episode_time=0.2, groups="per_kite")
    e.reset()
    done = [e.step(np.zeros(2, dtype=np.float32))[3] for _ in range(4)]
    assert done == [False, False, False, True]  # truncated at episode_time
    e = PointMassEnv(episode_time=60.0, pitch_range_deg=20.0)
    e.reset()
    for _ in range(1200):  # pitched 20 deg nose down the kite loses its lift and falls
        _, _, terminated, _, info = e.step(np.array([-1.0, 0.0], dtype=np.float32))
        if terminated:
            break
    assert terminated and info["failure"]


def test_wing_env_points_to_the_point_mass_env():
    from laddermill_gym.envs.wing_env import WingEnv

    with pytest.raises(ValueError, match="PointMassEnv"):
        WingEnv(scene="tethered_wing", scene_options={"fidelity": "pointmass", "element_length": 1.0})
