"""The native vector env of ``laddermill_gym/Rotorcraft-v0`` against the single env (copy i equals a single env
seeded seed + i bit for bit, through a termination and its autoreset, in both autoreset modes), its registration
as Gymnasium's ``vector_entry_point``, Gymnasium's env checker on the single env, the SB3 adapter on the craft, and
the compiled observation against the simulator's own read-outs (an independent assembly of the same quantities:
Euler angles from the quaternion, velocities rotated in numpy, rotor and tether read-outs of CraftSimulator)."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS, DirectionStep, RandomPerturbation
from laddermill_gym.envs.rotorcraft.env import CRAFT_OBS_INDEX, RotorcraftEnv, RotorcraftVectorEnv
from laddermill_gym.envs.rotorcraft.task import CraftTask
from laddermill_gym.kernels.contract import (
    CA_ALTITUDE,
    CA_INFLOW_OK,
    CA_MAX_ELEMENT,
    CA_MAX_TENSION,
    CA_POWER,
    CA_TENSION,
    CA_THRUST,
    CA_TIP_AOA,
)

RC = "laddermill_gym/Rotorcraft-v0"
KW = dict(ENV_IDS[RC], episode_time=3.0, initial_noise={"roll_rate": 0.02, "lateral_velocity": 0.1},
          disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05), DirectionStep(step=(-0.05, 0.05))])
SCALARS = ("t", "power_W", "altitude_m", "max_tip_incidence_rad", "n_clipped", "failure", "reward_power",
           "reward_lateral", "reward_rates", "reward_effort", "reward_failure")


def _actions(n_steps: int, n: int, seed: int = 5) -> np.ndarray:
    """Random actions (n_steps, n, 2), partly outside [-1, 1]; copy 1 holds full differential for its first 30
    steps, which rolls the craft over within a second (a termination and an autoreset inside the run)."""
    a = np.random.default_rng(seed).uniform(-1.2, 1.2, size=(n_steps, n, 2)).astype(np.float32)
    a[:30, 1] = (-0.5, 1.0)
    return a


def _assert_step_equal(single_out, vec_out, i):
    o1, r1, te1, tr1, info1 = single_out
    obs, r, te, tr, info = vec_out
    np.testing.assert_array_equal(obs[i], o1)
    assert r[i] == r1 and te[i] == te1 and tr[i] == tr1
    for k in SCALARS:
        assert info[k][i] == info1[k], k
    np.testing.assert_array_equal(info["thrust_N"][i], info1["thrust_N"])
    np.testing.assert_array_equal(info["tether_tension_N"][i], info1["tether_tension_N"])


def test_copies_equal_single_envs_through_termination_and_autoreset():
    n, seed = 3, 11
    venv = RotorcraftVectorEnv(n, **KW)
    singles = [RotorcraftEnv(**KW) for _ in range(n)]
    obs, _ = venv.reset(seed=seed)
    for i, env in enumerate(singles):
        np.testing.assert_array_equal(obs[i], env.reset(seed=seed + i)[0])
    acts = _actions(75, n)
    pending = np.zeros(n, bool)  # NextStep: the step after an end resets the copy
    ended = []
    for a in acts:
        out = venv.step(a)
        for i, env in enumerate(singles):
            if pending[i]:
                o1, _ = env.reset()
                np.testing.assert_array_equal(out[0][i], o1)
                assert out[1][i] == 0.0 and not out[2][i] and not out[3][i] and out[4]["failure"][i] == 0
                assert out[4]["t"][i] == 0.0
            else:
                _assert_step_equal(env.step(a[i]), out, i)
        done = out[2] | out[3]
        ended += [(i, int(out[4]["failure"][i]), bool(out[2][i])) for i in np.flatnonzero(done)]
        pending = done
    assert (1, 5, True) in ended  # copy 1 rolled over (attitude) and started again
    assert any(i != 1 or not term for i, _, term in ended)  # the others ran into the time limit
    venv.close()


def test_same_step_autoreset_matches_single_envs():
    n, seed = 2, 3
    venv = RotorcraftVectorEnv(n, autoreset_mode="SameStep", **dict(KW, episode_time=2.0))
    singles = [RotorcraftEnv(**dict(KW, episode_time=2.0)) for _ in range(n)]
    venv.reset(seed=seed)
    for i, env in enumerate(singles):
        env.reset(seed=seed + i)
    saw_final = False
    for a in _actions(45, n, seed=8):
        obs, r, te, tr, info = venv.step(a)
        for i, env in enumerate(singles):
            o1, r1, te1, tr1, i1 = env.step(a[i])
            # a copy reset in this step holds its reset info; its last step's is in final_info (as SyncVectorEnv)
            step_info = info["final_info"] if te1 or tr1 else info
            assert r[i] == r1 and te[i] == te1 and tr[i] == tr1 and step_info["failure"][i] == i1["failure"]
            if te1 or tr1:
                saw_final = True
                np.testing.assert_array_equal(info["final_obs"][i], o1)
                assert info["_final_obs"][i] and info["final_info"]["t"][i] == i1["t"]
                np.testing.assert_array_equal(obs[i], env.reset()[0])
            else:
                np.testing.assert_array_equal(obs[i], o1)
    assert saw_final
    venv.close()


def test_make_vec_vector_entry_point_and_spaces():
    venv = gym.make_vec(RC, 4, vectorization_mode="vector_entry_point", episode_time=1.0, render_mode="rgb_array")
    assert isinstance(venv, RotorcraftVectorEnv) and venv.num_envs == 4
    single = RotorcraftEnv(**dict(ENV_IDS[RC], episode_time=1.0))
    assert venv.single_observation_space == single.observation_space
    assert venv.single_action_space == single.action_space
    obs, info = venv.reset(seed=0)
    assert obs.shape == (4, 19) and obs.dtype == np.float32 and venv.observation_space.contains(obs)
    obs, r, te, tr, info = venv.step(np.tile(single.trim_action, (4, 1)))
    assert info["thrust_N"].shape == (4, 2) and info["tether_tension_N"].shape == (4, 3) and info["_t"].all()
    frames = venv.render()  # one per copy, as SyncVectorEnv
    assert len(frames) == 4 and all(f.dtype == np.uint8 and f.shape == (480, 640, 3) for f in frames)
    venv.close()
    with pytest.raises(ValueError, match="scene = 'tethered_wing'"):
        RotorcraftVectorEnv(2, scene="tethered_wing")
    with pytest.raises(ValueError, match="num_envs = 0"):
        RotorcraftVectorEnv(0)


def test_sb3_adapter_runs_the_craft_task():
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.envs.sb3 import sb3_vec_env

    kw = dict(KW, episode_time=1.0)
    venv = sb3_vec_env(RC, 2, seed=4, **kw)
    ref = RotorcraftVectorEnv(2, **kw)
    np.testing.assert_array_equal(venv.reset(), ref.reset(seed=4)[0])
    a = _actions(20, 2, seed=2)
    for k in range(20):
        obs, r, done, infos = venv.step(a[k])
        o2, r2, te2, tr2, _ = ref.step(a[k])
        np.testing.assert_array_equal(r, r2.astype(np.float32))
        for i in np.flatnonzero(done):
            np.testing.assert_array_equal(infos[i]["terminal_observation"], o2[i])
            assert infos[i]["failure_name"] == ref.failure_names[int(infos[i]["failure"])]
        if done.any():
            break
        np.testing.assert_array_equal(obs, o2)
    with pytest.raises(ValueError, match="scene = 'x'.*Rotorcraft-v0"):
        sb3_vec_env(RC, 1, scene="x")


def test_kernel_observation_matches_simulator_read_outs():
    """After a disturbed random flight, every observation entry and auxiliary quantity of each copy equals what
    the CraftSimulator's Python views give at that copy's state (rtol 1e-9: a different order of operations)."""
    task = CraftTask(2, **KW)
    task.reset(np.ones(2, bool), [np.random.default_rng(s) for s in (1, 2)])
    rng = np.random.default_rng(0)
    for _ in range(12):
        task.step(rng.uniform(-0.4, 0.4, size=(2, 2)))
    i = CRAFT_OBS_INDEX
    for b in range(2):
        sim = task.simulator(b)
        ro = sim.rotor_outputs()
        R = sim.wing_rotations()[0]
        expect = np.concatenate([sim.wing_positions()[0] - task.nominal_position, R @ sim.wing_velocities()[0],
                                 sim.wing_euler()[0], sim.wing_rates()[0], ro["thrust_N"] / task.thrust_trim,
                                 sim.tether_tensions() / task.tension_trim, ro["pitch_rad"]])
        np.testing.assert_allclose(task.raw_obs[b], expect, rtol=1e-9, atol=1e-12)
        assert abs(task.raw_obs[b, i["dy"]]) > 1e-3  # the flight was disturbed
        ten = sim.tensions()
        aux = task.aux[b]
        np.testing.assert_allclose(aux[CA_POWER], sim.electrical_power(), rtol=1e-12)
        np.testing.assert_allclose(aux[CA_THRUST: CA_THRUST + 2], ro["thrust_N"], rtol=1e-12)
        np.testing.assert_allclose(aux[CA_TENSION: CA_TENSION + 3], sim.tether_tensions(), rtol=1e-12)
        np.testing.assert_allclose(aux[CA_TIP_AOA: CA_TIP_AOA + 2], ro["tip_incidence_rad"], rtol=1e-12)
        assert aux[CA_MAX_TENSION] == ten.max() and aux[CA_MAX_ELEMENT] == np.argmax(ten)
        assert aux[CA_ALTITUDE] == -sim.wing_positions()[0, 2] and aux[CA_INFLOW_OK] == 1.0


def test_integration_failure_is_code_one_with_the_diagnosis():
    """A yaw rate past the integrator's rate limit (50 rad/s) fails the first RK4 step: failure 1, the state
    kept at the start, and the simulator's diagnosis in the reason; single env and vector copy agree."""
    kw = dict(ENV_IDS[RC], episode_time=1.0, initial_noise={"yaw_rate": 200.0})
    env = RotorcraftEnv(**kw)
    env.reset(seed=0)
    venv = RotorcraftVectorEnv(1, **kw)
    venv.reset(seed=0)
    _, r, term, trunc, info = env.step(env.trim_action)
    _, rv, tv, _, iv = venv.step(env.trim_action[None])
    assert term and not trunc and info["failure"] == 1 and info["t"] == 0.0
    assert "speed or rate limit exceeded" in info["failure_reason"] and "angular rate" in info["failure_reason"]
    assert tv[0] and iv["failure"][0] == 1 and rv[0] == r
