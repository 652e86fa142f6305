"""PointMassEnv on the moving cable (the laddermill at the point-mass fidelity, 70 m elements): the Gymnasium
contract (env checker), the power term against the generator's (T_first - T_last) V_c computed from the observed
ground tensions and the station's scheduled speed, the generator power of the mill simulator's own read-out
(``end_tensions``, another kernel path), actions per slot, the native vector env against single envs (bit for
bit), and the refusal of settle_time. The start (the rigid mill's periodic operating point, about 30 s
to a minute once per process) makes every test but the refusals slow."""

import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from laddermill_gym.atmosphere.disturbances import RandomPerturbation
from laddermill_gym.envs.pointmass.env import PointMassEnv, PointMassVectorEnv
from laddermill_gym.kernels.contract import PU_PITCH, PU_ROLL

MILL = {"scene": "laddermill", "scene_options": {"element_length": 70.0}}
#: configs/scenes/laddermill.yaml at element_length 70 m: 101 kites (one per 70 m piece), V_c = 2 m/s after the
#: 30 s ramp (the station's speed schedule)
N_KITES, V_C = 101, 2.0


@pytest.fixture(scope="module")
def env():
    return PointMassEnv(episode_time=1.0, **MILL)


@pytest.mark.slow
def test_env_checker(env):
    check_env(env, skip_render_check=True)
    assert env.observation_space.shape == (7 * N_KITES + 2,) and env.action_space.shape == (2,)


@pytest.mark.slow
def test_power_term_is_the_generator_power_of_the_observed_ground_tensions(env):
    task = env.task
    st = task.scene.station
    env.reset(seed=3)
    for k in range(5):
        a = np.array([0.4, -0.3], dtype=np.float32) * (k % 2)
        _, _, term, _, info = env.step(a)
        assert not term
        t_first, t_last = task.raw_obs[0, -2], task.raw_obs[0, -1]
        v = st.speed(task.mill.t0 + info["t"])  # the station's schedule V_c(t), not the simulator's state
        assert v == pytest.approx(V_C, rel=1e-12)
        p = (t_first - t_last) * v
        assert info["power_W"] == pytest.approx(p, rel=1e-12)
        assert info["reward_power"] == pytest.approx(task.reward_config.power_weight * p / task.p_ref, rel=1e-12)
        gen = task.simulator(0).generator_power()
        assert info["power_W"] == pytest.approx(gen["mechanical_W"], rel=1e-9)
        assert info["cable_speed_m_s"] == pytest.approx(gen["cable_speed_m_s"], rel=1e-12)
    # the mill's operating point pulls: between the rigid mill's 66.1 kW and twice it (docs/pointmass.md)
    print(f"reward's power reference (first period's mean power from the start) {task.p_ref / 1e3:.1f} kW")
    assert 66e3 < task.p_ref < 132e3


@pytest.mark.slow
def test_actions_offset_every_slots_scheduled_attitude(env):
    task = env.task
    env.reset(seed=0)
    env.step(np.array([0.5, -1.0], dtype=np.float32))
    sim = task.simulator(0)
    sim._command_attitudes()  # the attitude each slot's kite gets at the next step: its schedule plus the offsets
    commanded = sim.u.copy().reshape(N_KITES, 3)
    sim.offsets[:] = 0.0
    sim._command_attitudes()
    off = commanded - sim.u.reshape(N_KITES, 3)
    # closed form: pitch 0.5 x 5 deg, roll -1 x 15 deg (the default ranges), yaw untouched, in every slot
    np.testing.assert_allclose(off[:, PU_PITCH], np.radians(2.5), rtol=1e-12)
    np.testing.assert_allclose(off[:, PU_ROLL], np.radians(-15.0), rtol=1e-12)
    np.testing.assert_array_equal(np.delete(off, [PU_PITCH, PU_ROLL], axis=1), 0.0)


@pytest.mark.slow
def test_vector_env_equals_single_envs_bit_for_bit():
    kw = dict(MILL, episode_time=0.2, groups="per_kite",
              disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05)])
    n, steps = 2, 6  # 4 steps per episode: each copy resets once
    rng = np.random.default_rng(5)
    acts = rng.uniform(-1.0, 1.0, (steps, n, 2 * N_KITES)).astype(np.float32)
    venv = PointMassVectorEnv(n, **kw)
    vobs, _ = venv.reset(seed=20)
    runs = [venv.step(acts[k])[:4] for k in range(steps)]
    for i in range(n):
        e = PointMassEnv(**kw)
        obs, _ = e.reset(seed=20 + i)
        np.testing.assert_array_equal(vobs[i], obs)
        done = False
        for k in range(steps):
            if done:
                obs, _ = e.reset()
                r, te, tr = 0.0, False, False
            else:
                obs, r, te, tr, _ = e.step(acts[k, i])
            done = te or tr
            np.testing.assert_array_equal(runs[k][0][i], obs)
            assert (runs[k][1][i], runs[k][2][i], runs[k][3][i]) == (r, te, tr)
    assert not np.array_equal(runs[2][0][0], runs[2][0][1])  # the copies' winds differ


def test_settle_time_is_refused_on_the_moving_cable():
    with pytest.raises(ValueError, match="laddermill.*moving cable.*settle_time must be 0"):
        PointMassEnv(settle_time=1.0, **MILL)
