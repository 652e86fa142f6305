"""The rotorcraft environment (``laddermill_gym/Rotorcraft-v0``): conformance (Gymnasium's and SB3's checkers),
determinism, pickling, rendering, the reward's terms, the starting state against the trim, episode ends, argument
errors, the open-loop controller, and the open-loop lateral instability against the eigenvalues of a numerical
Jacobian of the simulator's right-hand side (an independent linear analysis)."""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.control.open_loop import craft_open_loop_controller
from laddermill_gym.envs import ENV_IDS, DirectionStep
from laddermill_gym.envs.rotorcraft.env import (
    CRAFT_OBS_FIELDS,
    CRAFT_OBS_INDEX,
    OBS_P,
    OBS_PHI,
    OBS_PSI,
    OBS_R,
    OBS_VY,
    OBS_Y,
    RotorcraftEnv,
    trim_action,
)
from laddermill_gym.model.states import euler_from_quaternion

RC = "laddermill_gym/Rotorcraft-v0"


def short(**kw):
    return dict(ENV_IDS[RC], **{"episode_time": 10.0, **kw})


def rollout(env, actions, seed):
    obs, _ = env.reset(seed=seed)
    out, rewards = [obs], []
    for a in actions:
        obs, r, term, trunc, _ = env.step(a)
        out.append(obs)
        rewards.append(r)
        if term or trunc:
            break
    return np.array(out), np.array(rewards)


def test_registration_and_gymnasium_checker():
    env = gym.make(RC, episode_time=2.0, render_mode="rgb_array")
    assert isinstance(env.unwrapped, RotorcraftEnv)
    check_env(env.unwrapped)
    assert env.observation_space.shape == (len(CRAFT_OBS_FIELDS),)
    assert env.action_space.shape == (2,)
    names = ("dy", "phi", "vy", "p", "psi", "r")
    assert (OBS_Y, OBS_PHI, OBS_VY, OBS_P, OBS_PSI, OBS_R) == tuple(CRAFT_OBS_INDEX[k] for k in names)
    env.close()


def test_sb3_checker_and_ppo_smoke():
    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import PPO
    from stable_baselines3.common.env_checker import check_env as sb3_check

    sb3_check(RotorcraftEnv(**short(episode_time=2.0)), warn=True)
    env = RotorcraftEnv(**short(episode_time=5.0))
    model = PPO("MlpPolicy", env, n_steps=128, batch_size=64, n_epochs=1, seed=0, device="cpu")
    model.learn(total_timesteps=256)
    action, _ = model.predict(env.reset(seed=0)[0], deterministic=True)
    assert env.action_space.contains(action.astype(np.float32))


def test_render_rgb_array():
    env = RotorcraftEnv(render_mode="rgb_array", **short())
    env.reset(seed=0)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.shape == (480, 640, 3)
    assert len(np.unique(frame.reshape(-1, 3), axis=0)) > 10  # tethers, disks and axes drawn, not blank
    env.close()


def test_reset_is_the_trim():
    """Offsets, velocities and rates zero, ratios one, attitude and blade pitch those of the trim state
    (read from the trim's quaternion and controls, not through the environment's observation code)."""
    env = RotorcraftEnv(**short())
    obs, info = env.reset(seed=0)
    i = CRAFT_OBS_INDEX
    zero = [i[k] for k in ("dx", "dy", "dz", "vx", "vy", "vz", "p", "q", "r")]
    np.testing.assert_allclose(obs[zero], 0.0, atol=1e-9)
    ratios = [i[k] for k in ("thrust_right", "thrust_left", "tension_rear_right", "tension_rear_left", "tension_front")]
    np.testing.assert_allclose(obs[ratios], 1.0, rtol=1e-6)
    euler = euler_from_quaternion(env.x_trim[3:7])
    np.testing.assert_allclose(obs[[i["phi"], i["theta"], i["psi"]]], euler, atol=1e-6)
    assert abs(euler[0]) < 1e-9 and abs(euler[2]) < 1e-9 and 0.1 < euler[1] < 1.0  # level, nose up
    np.testing.assert_allclose(obs[[i["pitch_right"], i["pitch_left"]]], env.u_trim[0], rtol=1e-6)
    assert info["reference_power_W"] > 0
    np.testing.assert_allclose(trim_action(), env.trim_action)
    np.testing.assert_allclose(env.trim_action, [(4.0 - 5.0) / 10.0, 0.0], atol=1e-7)  # 4 deg in [-5, 15] deg


def test_reward_terms_sum_to_reward_and_clipping_counted():
    env = RotorcraftEnv(**short(disturbances=[DirectionStep(step=0.05, time=0.0)], reward={"failure_penalty": 5.0}))
    env.reset(seed=0)
    _, r, _, _, info = env.step(env.trim_action)
    assert abs(info["reward_power"] - 1.0) < 2e-2  # one period near the trim
    rng = np.random.default_rng(1)
    for _ in range(40):
        a = rng.uniform(-1.5, 1.5, size=2).astype(np.float32)
        _, r, term, _, info = env.step(a)
        terms = [v for k, v in info.items() if k.startswith("reward_")]
        assert len(terms) == 5 and math.isclose(r, sum(terms), rel_tol=1e-12, abs_tol=1e-12)
        assert info["n_clipped"] == int(np.count_nonzero(np.abs(a) > 1.0))
        if term:
            assert info["reward_failure"] == -5.0
            break


def test_huge_differential_terminates_with_reason():
    env = RotorcraftEnv(**short(episode_time=60.0))
    env.reset(seed=0)
    a = np.array([env.trim_action[0], 1.0], dtype=np.float32)  # full differential held
    for _ in range(1200):
        _, _, term, trunc, info = env.step(a)
        if term or trunc:
            break
    assert term and not trunc
    assert info["failure"] != 0 and info["failure_name"] and "t = " in info["failure_reason"]
    assert info["t"] < 10.0  # rolls over within seconds
    with pytest.raises(RuntimeError, match="reset"):
        env.step(a)


@pytest.mark.parametrize("termination, name", [({"min_altitude": 1000.0}, "ground contact"),
                                               ({"breaking_factor": 1e-3}, "tether over its breaking load")])
def test_other_failures_are_named(termination, name):
    env = RotorcraftEnv(**short(termination=termination))
    env.reset(seed=0)
    _, _, term, trunc, info = env.step(env.trim_action)
    assert term and not trunc and info["failure_name"] == name


def test_time_limit_truncates():
    env = RotorcraftEnv(**short(episode_time=0.2))
    env.reset(seed=0)
    flags = [env.step(env.trim_action)[2:4] for _ in range(4)]
    assert flags == [(False, False)] * 3 + [(False, True)]


@pytest.mark.parametrize("kw, words", [
    ({"control_dt": 0.033}, "control_dt = 0.033"),
    ({"episode_time": -1.0}, "episode_time = -1.0"),
    ({"wind_speed": float("nan")}, "wind_speed = nan"),
    ({"physics_dt": 0.0}, "physics_dt = 0.0"),
    ({"collective": 1.0}, "collective = 1.0"),
    ({"craft": "no_such_craft"}, "craft = 'no_such_craft'"),
    ({"reward": {"lateral_scale": -1.0}}, "reward.lateral_scale = -1.0"),
    ({"reward": {"bogus": 1.0}}, "bogus"),
    ({"termination": {"max_abs_roll_deg": 0.0}}, "termination.max_abs_roll_deg = 0.0"),
    ({"initial_noise": {"roll_rate": -1.0}}, "initial_noise.roll_rate = -1.0"),
    ({"disturbances": [{"type": "Nope"}]}, "disturbances[0].type = 'Nope'"),
    ({"render_mode": "movie"}, "render_mode = 'movie'"),
    ({"physics_step": "euler"}, "physics_step = 'euler'"),
    ({"physics_step": "rk4"}, "physics_step = 'rk4' needs physics_dt"),
])
def test_bad_arguments_raise_naming_them(kw, words):
    with pytest.raises(ValueError) as err:
        RotorcraftEnv(**short(**kw))
    assert words in str(err.value)


def test_physics_step_swaps_the_configs_integrator():
    """``physics_step`` replaces the config's ROS34PW2 step (one W step per control period, or RK4 at the given
    step); the trim and spaces stay the config's."""
    base = RotorcraftEnv(**short())
    for kw, want in (({"physics_step": "ros2"}, ("ros2", 0.05, 1)),
                     ({"physics_step": "rk4", "physics_dt": 0.005}, ("rk4", 0.005, 10)),
                     ({"physics_step": "ros2", "jacobian_every": 4}, ("ros2", 0.05, 1))):
        env = RotorcraftEnv(**short(**kw))
        s = env.unwrapped.task._settings
        assert (s.method, s.dt, env.unwrapped.task.n_substeps) == want
        assert s.jacobian_every == kw.get("jacobian_every", 1)
        np.testing.assert_array_equal(env.unwrapped.task.x_trim, base.unwrapped.task.x_trim)
        env.close()
    base.close()


def test_bad_action_shape_raises():
    env = RotorcraftEnv(**short())
    env.reset(seed=0)
    with pytest.raises(ValueError, match="action"):
        env.step(np.zeros(3, dtype=np.float32))


def test_open_loop_controller_holds_trim():
    env = RotorcraftEnv(**short())
    obs, _ = env.reset(seed=0)
    ctrl = craft_open_loop_controller(ENV_IDS[RC])
    a, state = ctrl.predict(obs)
    np.testing.assert_allclose(a, env.trim_action)
    batch, _ = ctrl.predict(np.stack([obs, obs, obs]))
    assert batch.shape == (3, 2) and state is None
    from laddermill_gym.control.factory import make_controller

    np.testing.assert_allclose(make_controller("open_loop", RC).predict(obs)[0], env.trim_action)


def jacobian_eigenvalues(env):
    """Eigenvalues of d(rhs)/dx at the trim by central differences on the simulator's rhs."""
    sim, x, u = env.sim, np.array(env.x_trim), np.array(env.u_trim)
    n = x.size
    J = np.empty((n, n))
    for i in range(n):
        h = 1e-6 * max(1.0, abs(x[i]))
        e = np.zeros(n)
        e[i] = h
        J[:, i] = (sim.rhs(0.0, x + e, u) - sim.rhs(0.0, x - e, u)) / (2.0 * h)
    return np.linalg.eigvals(J)


def test_open_loop_lateral_instability_matches_linear_growth_rate():
    """Trim controls held at 10 m/s after the 0.01 rad direction step: y oscillates with a growing envelope
    (Roberts sec. 7). Its growth rate (half swings between successive extrema of y, which removes the offset
    of the turned wind's equilibrium) and half period match the unstable oscillatory eigenvalue of the
    numerical Jacobian within 25 % and 15 %."""
    env = RotorcraftEnv(**dict(ENV_IDS[RC], episode_time=60.0))
    assert env.craft.config.wind.v0 == 10.0
    ev = jacobian_eigenvalues(env)
    lam = ev[np.argmax(ev.real)]
    assert lam.real > 0 and abs(lam.imag) > 0.1  # one unstable oscillatory mode
    assert np.sum(ev.real > 1e-6) == 2  # ... and only that pair
    obs, _ = env.reset(seed=0)
    a = craft_open_loop_controller(ENV_IDS[RC]).predict(obs)[0]
    ts, ys = [0.0], [float(obs[OBS_Y])]
    while True:
        obs, _, term, trunc, info = env.step(a)
        ts.append(info["t"])
        ys.append(float(obs[OBS_Y]))
        if term or trunc:
            break
    ts, ys = np.array(ts), np.array(ys)
    early, late = np.max(np.abs(ys[ts < 15.0])), np.max(np.abs(ys[ts > ts[-1] - 20.0]))
    assert late > 3.0 * early  # |y| grows
    d = np.diff(ys)
    ext = np.flatnonzero(np.sign(d[1:]) != np.sign(d[:-1])) + 1
    ext = ext[ts[ext] > 3.0]  # after the step and its fast transients
    amp = 0.5 * np.abs(np.diff(ys[ext]))
    tm = 0.5 * (ts[ext][1:] + ts[ext][:-1])
    lin = amp < 5.0  # linear regime: a few metres on 60 m tethers
    assert np.count_nonzero(lin) >= 3
    sigma = np.polyfit(tm[lin], np.log(amp[lin]), 1)[0]
    assert abs(sigma - lam.real) < 0.25 * lam.real, (sigma, lam)
    half_period = np.mean(np.diff(ts[ext][: np.count_nonzero(lin) + 1]))
    assert abs(half_period - math.pi / abs(lam.imag)) < 0.15 * math.pi / abs(lam.imag), (half_period, lam)


def test_blade_pitch_observations_cover_asymmetric_differential_limits(tmp_path):
    """Differential limits [-8, 2] deg: each rotor's pitch (collective +- differential) reaches -13 to 23 deg; the
    observation's bounds cover it, so the pitches observed at the corner actions are the simulator's, unclipped."""
    from laddermill_gym.envs.rotorcraft.observation import CRAFT_OBS_INDEX
    from laddermill_gym.rotorcraft.config import load_craft_config

    src = load_craft_config().file
    text = src.read_text().replace("differential_limits_deg: [-5.0, 5.0]", "differential_limits_deg: [-8.0, 2.0]")
    craft = tmp_path / "asymmetric.yaml"
    craft.write_text(text.replace("../", str(src.parent.parent) + "/"))
    env = gym.make("laddermill_gym/Rotorcraft-v0", craft=str(craft), episode_time=1.0).unwrapped
    lo, hi = np.degrees(env.observation_space.low), np.degrees(env.observation_space.high)
    idx = [CRAFT_OBS_INDEX[k] for k in CRAFT_OBS_INDEX if "pitch" in k]
    assert len(idx) == 2 and np.allclose(lo[idx], -13.0, atol=1e-4) and np.allclose(hi[idx], 23.0, atol=1e-4)
    for a in ([-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]):
        env.reset(seed=0)
        obs, *_ = env.step(np.array(a, np.float32))
        pitch = env.task.simulator(0).rotor_outputs()["pitch_rad"]
        np.testing.assert_allclose(np.sort(obs[idx]), np.sort(pitch.astype(np.float32)), rtol=1e-6)


def test_float32_periods_are_read_as_the_numbers_written():
    """A control period or physics step from a float32 array (np.float32(0.05) is 0.0500000007) was refused as not
    dividing the episode; it is read as its shortest decimal, so the env is the one built from the float64 value
    (oracle: the same env from 0.05 and 0.025, the same observations after a step)."""
    kw32 = dict(control_dt=np.float32(0.05), physics_dt=np.float32(0.025), episode_time=np.float32(120.0))
    a, b = gym.make("laddermill_gym/Rotorcraft-v0", **kw32), gym.make("laddermill_gym/Rotorcraft-v0",
                                                                       control_dt=0.05, physics_dt=0.025)
    assert a.unwrapped.task.control_dt == 0.05 and a.unwrapped.task.n_steps_max == 2400
    oa, ob = a.reset(seed=1)[0], b.reset(seed=1)[0]
    act = np.array([0.3, -0.2], np.float32)
    assert np.array_equal(oa, ob) and np.array_equal(a.step(act)[0], b.step(act)[0])


def test_a_failed_trim_names_the_values_used_not_none():
    with pytest.raises(ValueError, match=r"wind_speed = 10 m/s \(the config's\), collective = -0.0872 rad: craft trim"):
        RotorcraftEnv(collective=-0.0872)
