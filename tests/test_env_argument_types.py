"""Env arguments as a researcher's sweep passes them: numpy's scalars (``np.arange`` gives ``np.int64``,
``np.float32`` arrays give ``np.float32``) are numbers and were refused as "must be a finite number > 0" (review of
2026-12-07); a bool or a string is named as a type problem. A wind sampled more coarsely than the episode is long
smears its disturbances away without a word (``wind_dt = 1000``): it warns."""

from __future__ import annotations

import math
import sys
import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs.task_base import CoarseWindWarning

TW, RC = "laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"


def test_numpy_scalars_are_numbers():
    env = gym.make(TW, episode_time=np.int64(3), wind_dt=np.float32(0.5)).unwrapped
    assert env.task.episode_time == 3.0 and type(env.task.episode_time) is float and env.task.n_steps_max == 60
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # Gymnasium: Rotorcraft-v0 is out of date
        craft = gym.make(RC, collective=np.float32(math.radians(4.0)), episode_time=np.int64(1)).unwrapped
    assert craft.task.u_trim[0] == pytest.approx(math.radians(4.0), rel=1e-6)


@pytest.mark.parametrize("kwargs, says", [
    (dict(episode_time=True), r"episode_time = True: must be a number .* not bool"),
    (dict(control_dt="0.05"), r"control_dt = '0.05': must be a number .* not str"),
    (dict(episode_time=np.float64("nan")), r"episode_time = np.float64\(nan\): must be a finite number > 0"),
])
def test_other_types_are_named_as_types(kwargs, says):
    with pytest.raises(ValueError, match=says):
        gym.make(TW, **kwargs)


def test_a_wind_sampled_more_coarsely_than_the_episode_warns():
    with pytest.warns(CoarseWindWarning, match=r"wind_dt = 1000 s is longer than the episode \(episode_time = 20 s\)"):
        gym.make(TW, episode_time=20.0, wind_dt=1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", CoarseWindWarning)
        gym.make(TW, episode_time=20.0, wind_dt=1000.0, disturbances=[])  # nothing to smear: no warning


PMC = "laddermill_gym/PointMassChain-v0"


@pytest.mark.parametrize("env_id, kwargs, says", [
    # the point-mass chain's step was never checked: ZeroDivisionError, "cannot convert float NaN to integer", a
    # negative one blamed on control_dt; an infinite settle time overflowed in the simulator
    (PMC, dict(scene_options={"dt": 0.0}), r"its step dt = 0\.0 s .* must be a finite number > 0"),
    (PMC, dict(scene_options={"dt": float("nan")}), r"its step dt = nan s"),
    (PMC, dict(scene_options={"dt": -0.025}), r"its step dt = -0\.025 s"),
    (PMC, dict(settle_time=float("inf")), r"settle_time = inf: must be a finite number >= 0 s"),
    # a range that is not a pair: a bare "not enough values to unpack"
    (TW, dict(termination={"alpha_range_deg": (-30.0,)}), r"termination.alpha_range_deg = \(-30\.0,\): need a pair"),
])
def test_steps_settle_times_and_ranges_are_named(env_id, kwargs, says):
    with pytest.raises(ValueError, match=says):
        gym.make(env_id, **kwargs)


@pytest.mark.parametrize("kwargs, says", [
    (dict(generator_torque="no"), r"generator_torque = 'no': must be True or False"),  # was a torque action
    (dict(drum={"radius": 2.0}), r"drum = \{'radius': 2\.0\}: its settings apply only with generator_torque=True"),
    (dict(speed={"half_range": 1.0}), r"its settings apply only with cable_speed_command=True"),
])
def test_mill_station_settings_without_their_action_are_refused(kwargs, says):
    with pytest.raises(ValueError, match=says):
        gym.make("laddermill_gym/LadderMill-v0", scene_options={"n_wings": 11}, settle={"max_time": 100.0}, **kwargs)


@pytest.mark.parametrize("env_id, kwargs, says", [
    # the start's CG is at 296.3 m: every episode ended at t = 0.05 s "ground contact" (review of 2026-12-07)
    ("laddermill_gym/PumpingKite-v1", dict(termination={"min_altitude": 1e6}),
     r"termination.min_altitude = 1e\+06 m: at or above the start's CG altitude 296\.\d\d m"),
    # past a = breaking_factor the episode has ended on the breaking load: reward_tension was always 0
    ("laddermill_gym/PumpingKite-v1", dict(reward={"tension_allowed": 5.0}),
     r"reward.tension_allowed = 5: at or above termination.breaking_factor = 1"),
])
def test_pumping_settings_that_cannot_act_are_refused(env_id, kwargs, says):
    with pytest.raises(ValueError, match=says):
        gym.make(env_id, **kwargs)


@pytest.mark.parametrize("disturbance, says", [
    # a drawn amplitude below -1 was accepted and crashed 8 of 20 resets later ("negative wind speed factor"), a
    # fixed one at the first reset; an inverted range or a non-bool sign only when drawn (review of 2026-12-07)
    ({"type": "OneMinusCosineGust", "amplitude": [-2.5, 0.3], "time": 5.0},
     r"OneMinusCosineGust.amplitude = \(-2\.5, 0\.3\): every value must be >= -1 \(the speed factor at the peak"),
    ({"type": "OneMinusCosineGust", "amplitude": -3.0}, r"OneMinusCosineGust.amplitude = -3\.0: every value"),
    ({"type": "OneMinusCosineGust", "duration": [0.0, 2.0]}, r"OneMinusCosineGust.duration = \(0\.0, 2\.0\): every "
                                                             r"value must be > 0"),
    ({"type": "DirectionStep", "step": [0.3, 0.1]}, r"DirectionStep.step = \(0\.3, 0\.1\): a range must be"),
    ({"type": "DirectionStep", "random_sign": 1}, r"DirectionStep.random_sign = 1: must be true or false"),
])
def test_drawn_disturbance_ranges_are_checked_when_the_env_is_made(disturbance, says):
    with pytest.raises(ValueError, match=says):
        gym.make("laddermill_gym/PumpingKite-v1", disturbances=[disturbance])


def test_a_range_reaching_minus_one_at_most_resets_on_every_seed():
    env = gym.make("laddermill_gym/PumpingKite-v1", disturbances=[
        {"type": "OneMinusCosineGust", "amplitude": [np.float32(-1.0), 0.3], "time": 5.0}])
    for seed in range(20):
        env.reset(seed=seed)


def test_another_envs_reward_config_is_refused_not_half_ignored():
    """PumpingKite-v1's reward (sideslip and tension terms) given to v0 was accepted and its extra terms dropped; as
    a dict it was refused. numpy scalars in reward fields are numbers (np.float32 was refused, np.float64 passed)."""
    from laddermill_gym.envs.pumping.crosswind_task import CrosswindRewardConfig

    with pytest.raises(ValueError, match=r"a CrosswindRewardConfig, not this env's PumpingRewardConfig"):
        gym.make("laddermill_gym/PumpingKite-v0", reward=CrosswindRewardConfig(sideslip_weight=5.0))
    env = gym.make("laddermill_gym/PumpingKite-v0", reward={"reference_power": np.float32(1000.0)})
    assert env.unwrapped.task.reward_config.reference_power == 1000.0


@pytest.mark.parametrize("env_id", [TW, "laddermill_gym/PumpingKite-v0", PMC])
def test_an_unknown_scene_option_is_named(env_id):
    """It was a TypeError from inside load_scene ("unexpected keyword argument 'bogus'")."""
    with pytest.raises(ValueError, match=r"scene_options\['bogus'\] = 1: not an option of load_scene \(known: "):
        gym.make(env_id, scene_options={"bogus": 1})


def test_numpy_scalars_are_numbers_in_every_argument_check():
    """The arguments a review of 2026-12-08 found still testing ``(int, float)``: each takes numpy's scalars as the
    Python number they stand for (oracle: the same call with that number; a float32 read as its shortest decimal, as
    ``positive`` reads a control period), and still refuses a bool."""
    from laddermill_gym.atmosphere.disturbances import RandomPerturbation
    from laddermill_gym.atmosphere.iec_gusts import EOG
    from laddermill_gym.atmosphere.turbulence import Turbulence
    from laddermill_gym.envs.laddermill.actions import check_authority
    from laddermill_gym.envs.physics_step import env_physics_settings, physics_scene_options
    from laddermill_gym.envs.rotorcraft.settings import RotorcraftTerminationConfig as TerminationConfig
    from laddermill_gym.envs.task_base import check_copies

    assert check_authority(np.float32(0.2)) == check_authority(0.2) == 0.2
    assert check_authority(np.int64(1)) == 1.0
    assert check_copies(np.float32(2.0)) == check_copies(np.int64(2)) == 2
    with pytest.raises(ValueError, match=r"authority = True: must be a number in \(0, 1\]"):
        check_authority(True)
    env = gym.make(TW, physics_dt=np.float32(0.025)).unwrapped  # was "control_dt = 0.05 s is not a whole multiple"
    assert env.task.batch.settings.dt == 0.025 and env.task.n_substeps == 2
    assert physics_scene_options(None, None, np.float32(0.025), 0.05)["dt"] == 0.025
    settings = env.task.batch.settings
    assert env_physics_settings(settings, None, np.float32(0.025), 0.05).dt == 0.025
    assert env_physics_settings(settings, None, np.int64(1), 1.0).dt == 1.0
    assert TerminationConfig(max_abs_roll_deg=np.float32(45.0)).max_abs_roll_deg == 45.0
    with pytest.raises(ValueError, match=r"termination.max_abs_roll_deg = True: must be a finite number > 0"):
        TerminationConfig(max_abs_roll_deg=True)
    assert Turbulence(record=np.float32(2.0), heights=(np.float32(0.0), 100.0)).heights == (0.0, 100.0)
    assert EOG(time=np.float32(5.0)).time == 5.0
    assert RandomPerturbation(speed_std=np.float32(0.1)).speed_std == np.float32(0.1)


@pytest.mark.parametrize("env_id, vector", [(TW, False), (TW, True), (RC, False)])
def test_an_argument_s_warning_points_at_the_line_that_made_the_env(env_id, vector):
    """A fixed stacklevel pointed into Gymnasium's registration code (make, make_vec) or the package's own
    registration (review of 2026-12-08); the warning's file and line are now the caller's, here this test's."""
    kw = dict(episode_time=10.0, wind_dt=20.0, disturbances=[{"type": "DirectionStep", "time": 12.0}])
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        mode = dict(vectorization_mode="vector_entry_point")
        line = sys._getframe().f_lineno + 1
        env = gym.make_vec(env_id, 2, **mode, **kw) if vector else gym.make(env_id, **kw)
    env.close()
    mine = [(w.category.__name__, w.filename, w.lineno) for w in got
            if w.category.__name__ in ("CoarseWindWarning", "LateDisturbanceWarning")]
    assert sorted(mine) == [("CoarseWindWarning", __file__, line), ("LateDisturbanceWarning", __file__, line)]


@pytest.mark.parametrize("env_id, fidelity", [(TW, "pointmass"), (PMC, "rigid")])
def test_a_scene_fidelity_option_is_refused_by_name(env_id, fidelity):
    """Each env sets its scene's fidelity: PointMassChain-v0 with fidelity 'rigid' ended in a TypeError ("multiple
    values for keyword argument 'fidelity'"), TetheredWing-v0 with 'pointmass' in an error about an
    elements_per_piece override the user never gave (review of 2026-12-08)."""
    with pytest.raises(ValueError, match=rf"scene_options\['fidelity'\] = '{fidelity}': each env sets its scene's "
                                         r"fidelity"):
        gym.make(env_id, scene_options={"fidelity": fidelity})


def test_the_rotorcraft_s_refined_step_warning_points_at_the_line_that_made_the_env():
    """``stacklevel=2`` pointed into the package's env skeleton (review of 2026-12-08)."""
    from laddermill_gym.sim.stable_step import UnstableStepWarning

    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        line = sys._getframe().f_lineno + 1
        gym.make(RC, physics_step="rk4", physics_dt=0.0125).close()
    mine = [(w.filename, w.lineno) for w in got if issubclass(w.category, UnstableStepWarning)]
    assert mine == [(__file__, line)]
