"""The Gymnasium environments: conformance (Gymnasium's and SB3's checkers), determinism, single vs batched
copies, pickling, rendering, episode ends, the reward's power term against the simulator's tension, and the
environment's RK4 step against an error-controlled Dormand-Prince reference of the same disturbed flight."""

from __future__ import annotations

import dataclasses
import math

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS, DirectionStep, WingEnv, WingVectorEnv
from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_INDEX

TW = "laddermill_gym/TetheredWing-v0"
TW_KW = ENV_IDS[TW]


def short(**kw):
    return dict(TW_KW, **{"episode_time": 20.0, **kw})


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


def test_gymnasium_checker_and_registration():
    env = gym.make(TW, episode_time=5.0)
    check_env(env.unwrapped, skip_render_check=True)
    assert env.observation_space.shape == (N_OBS_PER_WING,)
    assert env.action_space.shape == (3,)
    vec = gym.make_vec(TW, num_envs=2, vectorization_mode="vector_entry_point", episode_time=5.0)
    assert isinstance(vec, WingVectorEnv)
    assert vec.metadata["autoreset_mode"] == gym.vector.AutoresetMode.NEXT_STEP


def test_render_rgb_array():
    env = WingEnv(render_mode="rgb_array", **short())
    env.reset(seed=0)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.ndim == 3 and frame.shape[2] == 3
    assert len(np.unique(frame.reshape(-1, 3), axis=0)) > 10  # wing, cable and axes drawn, not blank
    env.close()


def test_open_loop_large_step_terminates_with_reason():
    env = WingEnv(**short(episode_time=300.0, disturbances=[DirectionStep(step=0.3)]))
    env.reset(seed=0)
    a = env.task.actions.nominal_action.astype(np.float32)
    for _ in range(6000):
        _, _, term, trunc, info = env.step(a)
        if term or trunc:
            break
    assert term and not trunc
    assert info["failure"] != 0 and "t = " in info["failure_reason"]


def test_power_term_is_ground_tension_times_reel_speed():
    """P = T_ground v_reel with v_reel = v0 / 3 (Lansdorp et al. 2008), T_ground from the simulator's own
    tension view at the trim (a separate code path from the env kernel's observation)."""
    env = WingEnv(**short())
    env.reset(seed=0)
    task = env.task
    sim = task.scene.simulator(task.x_trim, task.u_trim)
    t_ground = sim.tensions()[0]
    v0 = task.scene.assembly.wind.v0
    assert math.isclose(task.p_ref, t_ground * v0 / 3.0, rel_tol=1e-9)
    _, r, _, _, info = env.step(task.actions.nominal_action.astype(np.float32))
    assert abs(info["reward_power"] - 1.0) < 1e-3  # one period at trim before the 1 s direction step
    total = sum(info[k] for k in ("reward_power", "reward_lateral", "reward_rates", "reward_effort",
                                  "reward_failure"))
    assert math.isclose(r, total, rel_tol=1e-12)


def test_env_rk4_matches_dormand_prince_reference():
    """The env's integrator (RK4, 0.05 s, one tether element) against DP5(4) at rtol 1e-10 on the same scene
    with the same sampled wind modulation (a 0.05 rad direction step at 1 s), open loop for 20 s."""
    kw = short(disturbances=[DirectionStep(step=0.05)])
    env = WingEnv(**kw)
    env.reset(seed=0)
    task = env.task
    a = task.actions.nominal_action.astype(np.float32)
    for _ in range(400):
        obs, *_ = env.step(a)
    b = task.batch
    sc = task.scene
    asm = sc.assembly
    wind = asm.wind.with_modulation(float(b.tmod[0, 0]), float(b.tmod[0, 1]), b.mod_speed[0].copy(),
                                    b.mod_direction[0].copy())
    ref_scene = sc.replace(assembly=dataclasses.replace(asm, wind=wind))
    sim = ref_scene.simulator(task.x_trim.copy(), b.controls[0].copy())
    sim.advance_to(20.0, rtol=1e-10, atol=1e-10)
    y_ref = sim.wing_positions()[0, 1] - task.nominal[0, 1]
    y_env = obs[OBS_INDEX["dy"]]
    assert abs(y_ref) > 0.05  # the step has moved the wing sideways
    assert abs(y_env - y_ref) < 2e-3 * abs(y_ref) + 1e-4


def test_ladder_chain_env_steps_with_grouped_actions():
    env = gym.make("laddermill_gym/LadderChain-v0", groups="halves", episode_time=1.0).unwrapped
    assert env.action_space.shape == (6,)
    assert env.observation_space.shape == (101 * N_OBS_PER_WING,)
    obs, _ = env.reset(seed=0)
    for _ in range(3):
        obs, r, term, trunc, info = env.step(np.zeros(6, np.float32))
    assert np.all(np.isfinite(obs)) and not term
    assert info["power_W"] > 0  # the ascending leg pulls harder than the descending one


@pytest.mark.parametrize("kwargs, field", [
    (dict(control_dt=-0.05), "control_dt"),
    (dict(episode_time=float("nan")), "episode_time"),
    (dict(action_mode="flaps"), "action_mode"),
    (dict(groups=[[0, 0]]), "groups"),
    (dict(reward={"power_wieght": 1.0}), "reward"),
    (dict(reward={"lateral_weight": -1.0}), "lateral_weight"),
    (dict(termination={"alpha_range_deg": (10.0, -10.0)}), "alpha_range_deg"),
    (dict(control_dt=0.07), "control_dt"),
    # a string compared with a number raised a bare TypeError; n_copies was dropped (one copy built)
    (dict(termination={"breaking_factor": "x"}), "termination.breaking_factor = 'x'"),
    (dict(termination={"max_abs_beta_deg": -1.0}), "termination.max_abs_beta_deg = -1.0"),
    (dict(termination={"min_altitude": float("nan")}), "termination.min_altitude = nan"),
    (dict(n_copies=5), "n_copies = 5: a single env has one copy"),
])
def test_bad_arguments_name_the_field(kwargs, field):
    with pytest.raises(ValueError, match=field):
        WingEnv(**dict(short(), **kwargs))


def test_bad_actions_and_order():
    env = WingEnv(**short())
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros(3, np.float32))
    env.reset(seed=0)
    with pytest.raises(ValueError, match="non-finite"):
        env.step(np.array([np.nan, 0, 0], np.float32))
    _, _, _, _, info = env.step(np.array([2.0, 0.0, -3.0], np.float32))
    assert info["n_clipped"] == 2  # clipped to the box, and counted


@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v1", "laddermill_gym/Rotorcraft-v0"])
def test_reset_options_the_env_would_ignore_are_refused(env_id):
    """The single envs take no reset options: one given (a typo, or a setting that belongs to gymnasium.make) is
    refused by name instead of being ignored; an empty mapping or None is a plain reset."""
    env = gym.make(env_id)
    with pytest.raises(ValueError, match=rf"options = {{'disturbances': \[\]}}: {env_id} takes no reset options"):
        env.reset(seed=0, options={"disturbances": []})
    for options in ({}, None):
        obs, _ = env.reset(seed=0, options=options)
        assert obs.shape == env.observation_space.shape
    env.close()
    venv = gym.make_vec(env_id, num_envs=2, vectorization_mode="vector_entry_point")
    with pytest.raises(ValueError, match=r"options \['disturbances'\]: the vector env takes only 'reset_mask'"):
        venv.reset(seed=0, options={"disturbances": [], "reset_mask": np.array([True, True])})
    obs, _ = venv.reset(seed=0, options={"reset_mask": np.array([True, False])})
    assert obs.shape == venv.observation_space.shape
    venv.close()


def test_alpha_mode_servo_lag_and_achieved_alpha():
    """action_mode='alpha': the servo state follows the first-order lag in closed form,
    alpha_k = cmd + (alpha_0 - cmd) exp(-k dt / tau), and the wing settles near the commanded angle of attack
    (the elevator map is a static pitch balance without weight, exact at the trim; 1 deg allowed)."""
    tau = 0.5
    env = WingEnv(**short(action_mode="alpha", alpha_servo_tau=tau, disturbances=[], episode_time=60.0))
    env.reset(seed=0)
    task = env.task
    lo, hi = task.actions.layout.low[0], task.actions.layout.high[0]
    alpha0 = float(task.actions.alpha_servo[0, 0])
    cmd = alpha0 + math.radians(2.0)
    a = task.actions.nominal_action.astype(np.float32).copy()
    a[0] = (cmd - 0.5 * (lo + hi)) / (0.5 * (hi - lo))
    for k in range(1, 11):
        obs, *_ = env.step(a)
        expected = cmd + (alpha0 - cmd) * math.exp(-k * task.control_dt / tau)
        assert task.actions.alpha_servo[0, 0] == pytest.approx(expected, abs=1e-5)
    for _ in range(590):
        obs, _, term, _, _ = env.step(a)
    assert not term
    assert abs(obs[OBS_INDEX["alpha"]] - cmd) < math.radians(1.0)
