"""The blade-tip guard (control/craft_tip_guard.py): its tip estimate and its collective against the craft simulator's
own rotor outputs off the trim (the oracle: Gessow & Myers' rotor in the simulator, evaluated at the perturbed air and
state, not the guard's linearisation), its calm-air action against the LQR's, its gust benchmark episode against the
LQR's on Rotorcraft-v1, and its config errors."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.control.craft_tip_guard import (
    STATE_NAMES,
    TipGuardController,
    load_tip_guard_config,
    observed_state,
    with_observed_state,
)
from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.rotorcraft.observation import CRAFT_OBS_INDEX, N_CRAFT_OBS
from laddermill_gym.kernels.contract import B3_SIZE
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.rotorcraft.craft import load_craft
from laddermill_gym.rotorcraft.craft_observe import CRAFT_BODY

V1 = "laddermill_gym/Rotorcraft-v1"
BODY = B3_SIZE * CRAFT_BODY


@pytest.fixture(scope="module")
def guard() -> TipGuardController:
    return make_controller("lqr_guard", V1, {})


def _simulated(guard, wind_factor: float, ds: np.ndarray, collective: float, differential: float):
    """The simulator's thrust [N] and tip incidence [rad] per rotor, and the observation the env would give, with the
    craft's observed state moved by ds (STATE_NAMES order) from the trim, in wind_factor x the design wind."""
    from laddermill_gym.control.craft_lqr import design_craft_lqr

    design = design_craft_lqr()
    x0, u0 = np.array(design.x_trim), np.array(design.u_trim)
    s0 = observed_state(x0, BODY)
    ref = design.sim.rotor_outputs()["thrust_N"]
    sim = load_craft(config=design.sim.config.with_wind_speed(design.sim.config.wind.v0 * wind_factor)).simulator(
        state=x0)
    sim.state[:] = with_observed_state(x0, BODY, s0 + ds, s0)
    sim.controls[:] = [collective, differential]
    out = sim.rotor_outputs()
    obs = np.zeros((1, N_CRAFT_OBS))
    for name, v in zip(STATE_NAMES, s0 + ds, strict=True):
        obs[0, CRAFT_OBS_INDEX[name]] = v
    obs[0, CRAFT_OBS_INDEX["thrust_right"]], obs[0, CRAFT_OBS_INDEX["thrust_left"]] = out["thrust_N"] / ref
    obs[0, CRAFT_OBS_INDEX["pitch_right"]] = collective + differential
    obs[0, CRAFT_OBS_INDEX["pitch_left"]] = collective - differential
    return out, obs, u0


def test_tip_estimate_matches_the_simulator_off_the_trim(guard):
    """5 % more wind, the craft pitched 0.5 deg, sinking at 0.2 m/s, rolling at 0.02 rad/s, a 1 deg differential:
    the estimate from thrust, pitch and state is each rotor's simulated tip to within 0.05 deg (second order)."""
    ds = np.zeros(12)
    ds[STATE_NAMES.index("theta")] = math.radians(0.5)
    ds[STATE_NAMES.index("vz")] = 0.2
    ds[STATE_NAMES.index("p")] = 0.02
    coll = guard.lqr.collective
    out, obs, _ = _simulated(guard, 1.05, ds, coll, math.radians(1.0))
    est = guard.estimated_tips(obs)[0]
    assert abs(out["tip_incidence_rad"][0] - out["tip_incidence_rad"][1]) > math.radians(0.5)  # the rotors differ
    np.testing.assert_allclose(np.degrees(est), np.degrees(out["tip_incidence_rad"]), atol=0.05)


def test_tip_estimate_from_the_envs_own_observation_matches_the_envs_tip():
    """Rotorcraft-v0 (LQR flown) in a 20 % wind-speed step: the estimate from the env's observation (its thrust
    references, pitches, attitude) against the larger retreating-tip incidence the env's kernel reports, at the trim
    (to 1e-5 deg) and over the 10 s after the step (to 0.25 deg: the rise is not linear in the wind, 0.15 deg at
    20 %)."""
    import gymnasium as gym

    env_id = "laddermill_gym/Rotorcraft-v0"
    guard0, lqr = make_controller("lqr_guard", env_id, {}), make_controller("lqr", env_id, {})
    env = gym.make(env_id, disturbances=[{"type": "SpeedStep", "step": 0.2, "time": 0.5}], episode_time=20.0)
    obs, _ = env.reset(seed=0)
    errors = []
    for _ in range(210):
        obs, _, _, _, info = env.step(lqr.predict(obs)[0])
        errors.append(math.degrees(np.max(guard0.estimated_tips(obs[None])) - info["max_tip_incidence_rad"]))
    env.close()
    assert abs(errors[0]) < 1e-5
    assert max(abs(e) for e in errors[10:]) < 0.25
    assert max(abs(e) for e in errors[10:]) > 0.01  # the step moved the tips: 12.3 deg against 10.1


def test_guard_collective_puts_the_tip_at_its_target_in_one_period(guard):
    """In 30 % more wind the trim collective puts the tips at 13.5 deg, past the limit; the guard's collective from that
    one observation, applied in the same air, puts the larger tip at limit - margin (0.15 deg: the linearisation)."""
    coll = guard.lqr.collective
    out, obs, _ = _simulated(guard, 1.3, np.zeros(12), coll, 0.0)
    assert np.max(out["tip_incidence_rad"]) > guard.model.limit
    u = guard.controls(obs)[0]
    assert u[0] < coll
    after, _, _ = _simulated(guard, 1.3, np.zeros(12), u[0], u[1])
    target = guard.model.limit - guard.margin
    assert abs(math.degrees(np.max(after["tip_incidence_rad"]) - target)) < 0.15


def test_guard_collective_counts_the_differential_on_the_rotor_it_raises(guard):
    """With the craft 0.6 m off sideways the LQR commands a differential (0.9 deg); in 30 % more wind the guard's
    collective less (right) or plus (left) that differential puts the larger tip at the target and the other below."""
    ds = np.zeros(12)
    ds[STATE_NAMES.index("dy")] = 0.6
    coll = guard.lqr.collective
    _, obs, _ = _simulated(guard, 1.3, ds, coll, 0.0)
    u = guard.controls(obs)[0]
    assert abs(math.degrees(u[1])) > 0.5  # the LQR's differential
    after, _, _ = _simulated(guard, 1.3, ds, u[0], u[1])
    tips = np.degrees(after["tip_incidence_rad"])
    target = math.degrees(guard.model.limit - guard.margin)
    assert abs(tips.max() - target) < 0.15 and tips.min() < target - 1.0


def test_hold_mode_holds_the_mean_tip_at_the_trims():
    """mode: hold in 30 % more wind: one period of its collective brings the rotors' mean tip back to the trim's
    incidence (to 0.25 deg: the linearisation's error over a 3.4 deg move), where the trim collective leaves it 3.4 deg
    above."""
    hold = make_controller("lqr_guard:lqr_tip_hold_rotorcraft", V1, {})
    assert hold.mode == "hold" and hold.margin == 0.0
    out, obs, _ = _simulated(hold, 1.3, np.zeros(12), hold.lqr.collective, 0.0)
    assert np.mean(out["tip_incidence_rad"]) - np.mean(hold.model.alpha0) > math.radians(3.0)
    u = hold.controls(obs)[0]
    after, _, _ = _simulated(hold, 1.3, np.zeros(12), u[0], u[1])
    assert abs(math.degrees(np.mean(after["tip_incidence_rad"]) - np.mean(hold.model.alpha0))) < 0.25


def test_guard_is_the_lqr_in_calm_air(guard):
    """At the trim (tips 10.1 deg, 2.9 deg below the limit) the guard holds the trim collective: the LQR's action."""
    import gymnasium as gym

    env = gym.make(V1)
    obs, _ = env.reset(seed=0)
    lqr = make_controller("lqr", V1, {})
    for _ in range(40):
        a, _ = guard.predict(obs)
        np.testing.assert_array_equal(a, lqr.predict(obs)[0])
        obs, *_ = env.step(a)
    env.close()


def test_guard_survives_the_gust_the_lqr_loses_on_v1():
    """gusts-v5's 1-cos gust on Rotorcraft-v1: the LQR's episode ends on the blade limit, the guard's lasts 60 s."""
    from laddermill_gym.studies.gusts.gust_bench import run_suite
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    rows = run_suite(load_suite("gusts-v5"), [V1], ["lqr", "lqr_guard"], scenarios=["one_cos_4s"], progress=False)
    got = {r["controller"]: r for r in rows}
    assert not got["lqr"]["survived"] and "blade incidence" in got["lqr"]["failure"]
    assert got["lqr_guard"]["survived"] and got["lqr_guard"]["t_end_s"] == pytest.approx(60.0)


def _write(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "guard.yaml"
    p.write_text(text)
    return p


@pytest.mark.parametrize("text, field", [
    ("lqr: lqr_rotorcraft\nmode: hold\nmargin_deg: 1.0\n", "margin_deg"),
    ("lqr: lqr_rotorcraft\nmode: clamp\nmargin_deg: 1.0\n", "mode"),
    ("lqr: lqr_rotorcraft\nmargin_deg: 6.0\n", "margin_deg"),
    ("lqr: lqr_rotorcraft\nmargin_deg: -1.0\n", "margin_deg"),
    ("lqr: no_such_lqr\nmargin_deg: 1.0\n", "no_such_lqr"),
    ("lqr: lqr_rotorcraft\nmargin_deg: 1.0\nmargin: 2\n", "margin"),
])
def test_bad_guard_configs_are_refused_naming_the_file_and_field(tmp_path, text, field):
    path = _write(tmp_path, text)
    with pytest.raises(ConfigError, match=field) as err:
        load_tip_guard_config(path)
    assert "no_such" in field or str(path) in str(err.value)


def test_lqr_guard_on_another_env_is_refused_by_name():
    with pytest.raises(ValueError, match="lqr_guard' \\(rotorcraft"):
        make_controller("lqr_guard", "laddermill_gym/TetheredWing-v0", {})


def test_the_commands_accept_lqr_guard_and_refuse_a_missing_guard_config():
    """``--controllers lqr_guard`` passes the commands' up-front check; ``lqr_guard:<file>`` with no such file is a
    UsageError naming the option and the spec (before any env is built)."""
    from laddermill_gym.studies.commands import UsageError, check_controllers

    check_controllers(["lqr_guard", "lqr_guard:lqr_guard_rotorcraft"])
    with pytest.raises(UsageError, match="--controllers 'lqr_guard:no_such_guard'"):
        check_controllers(["lqr_guard:no_such_guard"])


def test_a_linear_actor_cannot_start_at_the_guard_in_limit_mode(tmp_path):
    """init_from: lqr_guard:<limit-mode config> is refused when the training config is read (its min() is not affine:
    the actor would start at the LQR); the hold mode is accepted."""
    from laddermill_gym.control.rl_config import load_rl_config

    src = (Path(__file__).resolve().parent.parent / "configs/agents/ppo_rotorcraft_v1_hold.yaml").read_text()
    assert load_rl_config(_write(tmp_path, src)).init_from == "lqr_guard:lqr_tip_hold_rotorcraft"
    bad = src.replace("init_from: lqr_guard:lqr_tip_hold_rotorcraft", "init_from: lqr_guard:lqr_guard_rotorcraft")
    with pytest.raises(ConfigError, match="limit mode"):
        load_rl_config(_write(tmp_path, bad))
