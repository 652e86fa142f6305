"""LadderMill-v0: argument errors, the registered 101-wing mill's reference power, turbulence over the mill (split
from tests/test_laddermill_env.py, whose helpers it uses)."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

from laddermill_gym.envs.laddermill.env import LadderMillEnv
from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, OBS_INDEX
from tests.test_laddermill_env import LM, WIDE, N, slots, small


def test_bad_arguments_are_named():
    with pytest.raises(ValueError, match="bogus"):
        LadderMillEnv(**small(bogus=1))
    with pytest.raises(ValueError, match="dimension"):
        LadderMillEnv(**small(scene_options={"n_wings": N, "dimension": 2}))
    with pytest.raises(ValueError, match="groups"):
        LadderMillEnv(**small(groups="pairs"))
    with pytest.raises(ValueError, match="moving cable"):
        LadderMillEnv(scene="ladder_chain", scene_options={"n_wings": 5})
    with pytest.raises(ValueError, match="settle.max_time"):
        LadderMillEnv(**small(settle={"max_time": -1.0}))


@pytest.mark.slow
def test_default_mill_starts_periodic_and_pays_its_reference_power():
    """The registered mill (101 wings) from its operating point without disturbance: the power term averages 1 over
    one period (the electrical energy of the period / period = P_ref to 1e-3; the operating point is periodic to
    2e-4), and the 3D mill stays in plane (largest |dy| < 1e-6 m)."""
    env = gym.make(LM, disturbances=[]).unwrapped
    obs, info = env.reset(seed=0)
    assert info["operating_point_converged"], info["operating_point_note"]
    a = np.zeros(env.action_space.shape, np.float32)
    n = int(round(env.task.op.period_s / env.task.control_dt))
    energy, rewards, dy = 0.0, [], 0.0
    for _ in range(n):
        obs, r, term, trunc, info = env.step(a)
        assert not term
        energy += info["mean_power_W"] * env.task.control_dt
        rewards.append(info["reward_power"])
        dy = max(dy, float(np.abs(obs[: -4].reshape(-1, N_OBS_PER_SLOT)[:, OBS_INDEX["dy"]]).max()))
    assert energy / (n * env.task.control_dt) == pytest.approx(env.task.p_ref, rel=1e-3)
    assert np.mean(rewards) == pytest.approx(1.0, rel=1e-2)
    assert dy < 1e-6


def test_turbulence_reaches_the_mill_and_replays_from_the_seed():
    """A turbulence mapping sizes the batch's gust grid, and the same seed gives the same wind at the wings (the
    field is drawn from the env's np_random); a different seed a different one."""
    turb = [{"type": "Turbulence", "model": "NTM", "wind_class": "IB", "heights": [0, 400]}]
    env = LadderMillEnv(**small(disturbances=turb, termination=WIDE))
    assert env.task.batch.air.gv is not None and env.task.batch.air.gv.shape[1] > 0

    def airspeed(seed):
        env.reset(seed=seed)
        obs = [env.step(np.zeros(env.action_space.shape, np.float32))[0] for _ in range(10)]
        return np.array([slots(o)[:, OBS_INDEX["alpha"]] for o in obs])

    a, b, c = airspeed(3), airspeed(3), airspeed(4)
    np.testing.assert_array_equal(a, b)
    assert np.max(np.abs(a - c)) > 1e-6


def test_authority_scales_a_unit_action_to_its_share_of_the_half_range():
    """``authority`` s: a = +-1 moves a surface by s x half its range from the operating point (closed form; the
    default wing's elevator range is +-15 deg); values outside (0, 1] are refused by name."""
    import math

    env = LadderMillEnv(**small(groups="all", surfaces=("elevator",), termination=WIDE, authority=0.1))
    env.reset(seed=0)
    u0 = env.task.u_op[: 3 * N].reshape(N, 3)[:, 0].copy()
    env.step(np.array([1.0], np.float32))
    u = env.task.batch.controls[0].reshape(N, 3)
    np.testing.assert_allclose(u[:, 0], u0 + 0.1 * math.radians(15.0), atol=1e-12)
    lay = env.task.actions.layout
    np.testing.assert_allclose([lay.low[0], lay.high[0]], u0[0] + np.array([-1, 1]) * 0.1 * math.radians(15.0))
    for bad in (0.0, 1.5, True, "x"):
        with pytest.raises(ValueError, match=f"authority = {bad!r}"):
            LadderMillEnv(**small(authority=bad))
