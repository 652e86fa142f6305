"""The mill's generator efficiency eta < 1 in LadderMill-v0 (issue 34 item 19: dropping eta from the reward's power
survived the tests, which all ran at the scene's eta = 1).

Oracle: the closed form P = (T_first - T_last) V_c eta with eta the number set here (0.8), V_c the cable speed the
env's generator holds (the scene's 2 m/s, prescribed) and T_first, T_last the first (veered) and last (hauled)
elements' tensions read by a separate simulator at the env's state (``Simulator.tensions``, not the env's observation
kernel); the reward's power term is w_P P / P_ref with P_ref given. A small mill (11 wings, the fallback start after
100 s of settling, as tests/test_laddermill_env.py) keeps it short.
"""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)

LM = "laddermill_gym/LadderMill-v0"
ETA = 0.8  # [-] generator efficiency (electrical over mechanical power)
V_C = 2.0  # [m/s] the laddermill scene's cable speed (configs/scenes/laddermill.yaml, speed_m_s)
P_REF = 5.0e4  # [W] a reference power given to the reward
WEIGHT = 1.5  # [-] power weight


def mill_env(eta: float, **kw):
    with warnings.catch_warnings():  # the small mill has no periodic motion: the fallback start is reported
        warnings.simplefilter("ignore", RuntimeWarning)
        return gym.make(LM, scene="laddermill", settle={"max_time": 100.0}, control_dt=0.05, episode_time=2.0,
                        scene_options={"n_wings": 11, "overrides": {"station": {"efficiency": eta}}},
                        disturbances=[], termination={"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0},
                        **kw)


def test_power_and_reward_carry_the_generator_efficiency():
    env = mill_env(ETA, reward={"reference_power_W": P_REF, "power_weight": WEIGHT, "lateral_weight": 0.0,
                                "rate_weight": 0.0, "effort_weight": 0.0})
    env.reset(seed=0)
    task = env.unwrapped.task
    assert task.batch.assembly.station.efficiency == ETA and task.op.cable_speed == pytest.approx(V_C)
    rng = np.random.default_rng(0)
    for _ in range(4):
        _, reward, terminated, _, info = env.step(0.3 * rng.uniform(-1, 1, env.action_space.shape).astype(np.float32))
        assert not terminated
        ten = task.simulator(0).tensions()
        mech = (ten[0] - ten[-1]) * V_C
        p = ETA * mech if mech >= 0 else mech / ETA  # a motoring generator draws more than it gives the cable
        assert abs(p) > 1e3  # the generator works: eta matters
        assert info["power_W"] == pytest.approx(p, rel=1e-9)
        assert info["mechanical_power_W"] == pytest.approx(mech, rel=1e-9)
        assert info["reward_power"] == pytest.approx(WEIGHT * p / P_REF, rel=1e-9)
        assert reward == pytest.approx(WEIGHT * p / P_REF, rel=1e-9)  # the other terms weigh 0
    env.close()


def test_default_reference_power_carries_the_efficiency():
    """Without a given P_ref, the reward's reference is eta times the operating point's mean mechanical power, or,
    for a mill that makes no net power (this small one), eta V_c times the mean first-element tension
    (envs/laddermill/operating_point.py): eta times a mechanical power either way."""
    env = mill_env(ETA)
    _, info = env.reset(seed=0)
    op = env.unwrapped.task.op
    mech = op.mechanical_power_W if op.mechanical_power_W > 0 else V_C * op.tension_first_N
    assert op.mechanical_power_W < 0 < op.tension_first_N  # the small mill: the second case
    assert info["reference_power_W"] == pytest.approx(ETA * mech, rel=1e-12)
    _, _, _, _, info = env.step(np.zeros(env.action_space.shape, np.float32))
    assert info["reward_power"] == pytest.approx(info["power_W"] / (ETA * mech), rel=1e-9)
    env.close()
