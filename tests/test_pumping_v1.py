"""laddermill_gym/PumpingKite-v1 (crosswind pumping): v0's entries unchanged (against the v0 env, same seed and
actions), the wind-window entries against closed forms of the wing's state and the scene's wind profile, the
reward's terms, the crosswind controller as its baseline. The shared contract (checkers, seeding, vector = single,
pickling, autoreset) is tests/test_env_contract.py's."""

import math

import gymnasium as gym
import numpy as np
import pytest

from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.crosswind_observation import CROSSWIND_OBS_INDEX, N_CROSSWIND_OBS
from laddermill_gym.envs.pumping.observation import N_OBS, WINCH_OBS_INDEX

V0, V1 = "laddermill_gym/PumpingKite-v0", "laddermill_gym/PumpingKite-v1"


def _actions(n, seed=3):
    return np.random.default_rng(seed).uniform(-0.3, 0.3, size=(n, 4)).astype(np.float32)


def test_v1_extends_v0_bit_for_bit():
    """The same seed and actions: v1's first 20 entries are v0's observation, its power term is v0's energy over
    10 kW instead of 1 kW."""
    e0, e1 = gym.make(V0, episode_time=5.0).unwrapped, gym.make(V1, episode_time=5.0).unwrapped
    o0, _ = e0.reset(seed=4)
    o1, _ = e1.reset(seed=4)
    assert o1.shape == (N_CROSSWIND_OBS,) and e1.observation_space.shape == (N_CROSSWIND_OBS,)
    np.testing.assert_array_equal(o1[:N_OBS], o0)
    for a in _actions(40):
        o0, _, _, _, i0 = e0.step(a)
        o1, _, _, _, i1 = e1.step(a)
        np.testing.assert_array_equal(o1[:N_OBS], o0)
        assert i1["reward_power"] == pytest.approx(i0["reward_power"] / 10.0, rel=1e-12)


def test_wind_window_entries_against_closed_forms():
    """Steady wind (no disturbance): elevation asin(h / |p|), azimuth atan2(y, -x) of the wing's position (the
    v0 entries plus the start position), apparent wind |w(h) - v| with the scene's profile w = -V(h) x,
    V(h) = v0 + v1 (h - h0) above h0 (configs/scenes/pumping_kite.yaml), the cycle fraction s / Delta L."""
    env = gym.make(V1, episode_time=20.0, disturbances=[]).unwrapped
    env.reset(seed=0)
    wind = env.task.scene.assembly.wind
    for a in _actions(200, seed=5):
        env.step(a)
        o = env.task.raw_obs[0]
        p = env.task.nominal[0] + o[:3]
        j = CROSSWIND_OBS_INDEX
        h = -p[2]
        assert h > wind.h0
        w = np.array([-(wind.v0 + wind.v1 * (h - wind.h0)), 0.0, 0.0])
        np.testing.assert_allclose(o[j["elevation"]], math.asin(h / np.linalg.norm(p)), atol=1e-12)
        np.testing.assert_allclose(o[j["azimuth"]], math.atan2(p[1], -p[0]), atol=1e-12)
        np.testing.assert_allclose(o[j["apparent_wind"]], np.linalg.norm(w - o[3:6]), rtol=1e-9)
        np.testing.assert_allclose(o[j["course_sin"]] ** 2 + o[j["course_cos"]] ** 2, 1.0, atol=1e-12)
        assert o[j["cycle_fraction"]] == pytest.approx(o[WINCH_OBS_INDEX["paid_out"]] / 200.0, rel=1e-12)


def test_reward_terms_sum_and_the_tension_term():
    """The terms in info sum to the reward; the tension term is 0 below 0.4 x the breaking load and
    -(1 - exp(-x)) above, x the excess over 0.1 x the breaking load."""
    env = gym.make(V1, episode_time=5.0).unwrapped
    env.reset(seed=1)
    for a in _actions(20, seed=7):
        _, r, _, _, info = env.step(a)
        terms = [v for k, v in info.items() if k.startswith("reward_")]
        assert r == pytest.approx(sum(terms), rel=1e-12, abs=1e-12)
        assert info["reward_tension"] == 0.0  # about 2 kN, far below 210 kN
    task = env.task
    brk = task.scene.cable.breaking_load
    task.reward_config = type(task.reward_config)(tension_allowed=1e-3, tension_scale=1e-3)
    _, _, _, _, info = env.step(np.zeros(4, np.float32))
    x = (info["max_tension_N"] - 1e-3 * brk) / (1e-3 * brk)
    assert info["reward_tension"] == pytest.approx(-(1.0 - math.exp(-x)), rel=1e-9)


def test_crosswind_controller_is_v1s_baseline():
    """make_controller('crosswind', v1) flies v1's native vector env (2 copies, different seeds of the default
    direction step): figure eights during reel-out, 60 s without a failure, more than 20 kW of mean power."""
    ctl = make_controller("crosswind", V1)
    env = gym.make_vec(V1, num_envs=2, vectorization_mode="vector_entry_point", episode_time=60.0)
    obs, _ = env.reset(seed=[0, 1])
    power, az = [], []
    for _ in range(1200):
        a, _ = ctl.predict(obs)
        obs, _, term, trunc, info = env.step(a)
        assert not term.any()
        power.append(info["power_W"])
        az.append(obs[:, CROSSWIND_OBS_INDEX["azimuth"]])
    az = np.array(az)
    assert (az.min(axis=0) < -0.25).all() and (az.max(axis=0) > 0.25).all()
    assert (np.mean(power, axis=0) > 2.0e4).all()
    assert np.all(np.abs(obs[:, OBS_INDEX["beta"]]) < 1.0)


def test_a_fall_out_of_the_reel_in_hang_goes_to_the_entry():
    """The reel-in's recovery (control/crosswind.py): a reel-in whose wing has hung above 80 deg elevation and falls
    below 78 deg goes to the entry at once (re-powered) and is counted; a reel-in that has not reached its hang
    (climbing from the retraction) is not; the hang is forgotten once the phase changes."""
    from types import SimpleNamespace

    from laddermill_gym.control.crosswind import ENTRY, REEL_IN

    ctl = make_controller("crosswind", V1)
    ctl.reset(2)
    ctl.phase[:] = REEL_IN
    s, tension = np.array([100.0, 100.0]), np.array([2000.0, 2000.0])
    seen = []
    for el0, el1 in ((60.0, 77.0), (79.0, 79.0), (81.0, 77.5), (79.0, 77.0), (77.9, 77.0)):
        ph = ctl._advance_phase(SimpleNamespace(elevation=np.radians([el0, el1])), s, tension)
        seen.append(ph.copy())
    assert [int(p[0]) for p in seen] == [REEL_IN, REEL_IN, REEL_IN, REEL_IN, ENTRY]
    assert all(int(p[1]) == REEL_IN for p in seen)  # copy 1 never hung above 80 deg
    assert ctl.recoveries.tolist() == [1, 0] and not ctl.hung.any()


@pytest.mark.slow
def test_an_hour_of_crosswind_cycles_under_ntm_turbulence():
    """IEC 61400-1 normal turbulence (class IB) at the scene's wind at the start height (10.39 m/s at 296 m, as
    gusts-v2's NTM_IB of PumpingKite-v0), one hour (seed 0) with the crosswind controller: no failure of any kind
    (no numerical failure, no flight failure: the reel-in's recovery and the entry's taut tether,
    docs/pumping.md "Turbulence"), more than ten cycles and more than 20 kW of mean net electrical power."""
    ntm = {"type": "Turbulence", "fade_in": 10.0, "model": "NTM", "wind_class": "IB", "wind_speed": 10.39,
           "hub_height": 296.3, "heights": [0.0, 600.0], "dh": 5.0, "along_wind": [-50.0, 600.0], "dxi": 5.0}
    ctl = make_controller("crosswind", V1)
    env = gym.make(V1, episode_time=3600.0, disturbances=[ntm]).unwrapped
    obs, _ = env.reset(seed=0)
    cycles, prev, energy = 0, 0, 0.0
    for _ in range(72000):
        a, _ = ctl.predict(obs)
        obs, _, term, trunc, info = env.step(a)
        assert not term, env.task.failure_text(0, int(info["failure"]))
        energy += float(info["power_W"]) * env.task.control_dt
        phase = int(ctl.last_phase[0])
        cycles += prev == 2 and phase != 2
        prev = phase
    print(f"seed 0, an hour under NTM IB: {cycles} cycles, {energy / 1e6:.1f} MJ net ({energy / 3.6e6:.1f} kW)")
    assert trunc
    assert cycles > 10 and energy / 3600.0 > 2.0e4, (cycles, energy)


def test_gusts_v3_is_v2_plus_pumping_kite_v1():
    """gusts-v3 holds every registered id but LadderMill-v1 to -v3, LadderChain-v1, TetheredWing-v1 and
    Rotorcraft-v1 (registered later); its other envs are gusts-v2's unchanged; PumpingKite-v1's scenarios are
    PumpingKite-v0's of gusts-v2 (names, starts, disturbances) with 300 s episodes (one crosswind cycle)."""
    from laddermill_gym.envs import ENV_IDS
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    v2, v3 = load_suite("gusts-v2"), load_suite("gusts-v3")
    # gusts-v3 was fixed before LadderMill-v1..v3 and LadderChain-v1 existed (a suite is never changed, a later
    # version adds envs)
    later = {"laddermill_gym/LadderMill-v1", "laddermill_gym/LadderMill-v2", "laddermill_gym/LadderMill-v3",
             "laddermill_gym/LadderChain-v1", "laddermill_gym/TetheredWing-v1", "laddermill_gym/Rotorcraft-v1"}
    assert v3.version == 3 and set(v3.envs) == set(ENV_IDS) - later == set(v2.envs) | {V1}
    for env_id in v2.envs:
        assert v3.envs[env_id] == v2.envs[env_id], env_id
    old, new = v2.envs[V0][1], v3.envs[V1][1]
    assert [s.name for s in new] == [s.name for s in old]
    for a, b in zip(old, new, strict=True):
        assert (b.start, b.seeds, b.disturbances, b.duration) == (a.start, a.seeds, a.disturbances, 300.0)
