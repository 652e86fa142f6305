"""The mill task's inputs (a review of 2026-12-07, sixth session): a search that cannot give a start, an operating
point of another scene, a station with its own control, the action settings, the power-ratio observation.

Oracles: the scene's own equilibrium at rest (``ladder/initial.initial_state``: the lowest wing and its height), the
simulator run by hand on the same scene (where the search's breakdown happens), the task's own layout counted by
hand (groups x surfaces + the station entry), and the observation's definition P / P_ref of the operating point.
"""

import warnings

import numpy as np
import pytest

from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.laddermill.actions import action_count
from laddermill_gym.envs.laddermill.env import LadderMillEnv
from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, STATION_OBS_INDEX
from laddermill_gym.envs.laddermill.operating_point import compute_operating_point, mill_scene, scene_digest
from laddermill_gym.ladder.initial import initial_state
from laddermill_gym.ladder.scene import options_key

N = 5
SMALL = dict(scene="laddermill", scene_options={"n_wings": N}, settle={"max_time": 100.0}, episode_time=2.0)


def _quiet(**kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill wanders: a non-converged point
        return LadderMillEnv(**kw)


@pytest.fixture(scope="module")
def small_env():
    return _quiet(**SMALL, disturbances=[])


def test_a_rest_state_below_the_ground_is_refused_naming_the_wing_and_the_wind():
    options = options_key({"n_wings": 11, "overrides": {"wind": {"v0": 4.0}}})
    sc2 = mill_scene("laddermill_v1", options, 2)
    x, _ = initial_state(sc2)
    heights = -sc2.simulator(x).wing_positions()[:, 2]
    k = int(np.argmin(heights))
    assert heights[k] < 0.0  # the oracle: too weak a wind to hold the chain up at rest
    with pytest.raises(ValueError, match=rf"scene 'laddermill_v1' \(11 wings, wind v0 = 4 m/s.*equilibrium at "
                                         rf"rest has wing {k} at height {heights[k]:.4g} m, at or below the ground"):
        compute_operating_point("laddermill_v1", options, warn=False)


def test_a_breakdown_during_the_search_is_named_as_the_searchs():
    # the 11-wing mill at 5 m/s starts above the ground and reaches it during the search (found by the review)
    options = options_key({"n_wings": 11, "overrides": {"wind": {"v0": 5.0}}})
    sim = mill_scene("laddermill_v1", options, 2).simulator()
    assert np.min(-sim.wing_positions()[:, 2]) > 0.0
    with pytest.raises(ValueError, match=r"scene 'laddermill_v1' \(11 wings, wind v0 = 5 m/s.*the in-plane mill "
                                         r"broke down .*ground contact at t = .*no periodic start exists"):
        compute_operating_point("laddermill_v1", options, warn=False)


def test_an_operating_point_of_another_scene_is_refused(small_env):
    op = small_env.operating_point
    assert op.scene_digest == scene_digest(small_env.task.scene)
    again = _quiet(**SMALL, disturbances=[], operating_point=op)  # its own scene: taken
    assert again.operating_point is op
    other = dict(SMALL, scene_options={"n_wings": N, "overrides": {"wind": {"v0": 9.0}}})
    with pytest.raises(ValueError, match=r"operating_point: found for another scene.*'laddermill' \(5 wings, wind "
                                         r"v0 = 9 m/s"):
        _quiet(**other, operating_point=op)


def test_a_scene_whose_station_has_a_control_gives_the_tails_controls():
    st = {"mode": "commanded", "speed_time_constant": 1.0, "speed_limits": [0.0, 4.0], "speed_m_s": [2.0],
          "speed_times_s": [0.0]}
    env = _quiet(**dict(SMALL, scene_options={"n_wings": N, "overrides": {"station": st}}), disturbances=[])
    assert env.operating_point.controls.shape == (3 * N,)  # before: 3 N + 1, and the task's broadcast failed
    env.reset(seed=0)
    env.step(np.zeros(env.action_space.shape, np.float32))


def test_a_drum_that_lets_the_cable_run_back_is_named_as_the_searchs_failure():
    # a drum's torque held at its lower limit 0 does not hold the cable: it speeds up, then runs backwards, and no
    # transfer comes within the search's first two periods (2 x 70 m / 2 m/s = 7000 steps of 10 ms)
    st = {"mode": "drum", "drum_radius": 1.0, "drum_inertia": 1000.0, "torque_limits": [0.0, 30000.0],
          "speed_m_s": [2.0], "speed_times_s": [0.0]}
    sim = mill_scene("laddermill", options_key({"n_wings": N, "overrides": {"station": st}}), 2).simulator()
    sim.step(n_steps=7000)
    assert sim.transfers() == 0 and sim.cable_speed() < 0.0  # the oracle: the simulator run by hand
    with pytest.raises(ValueError, match=r"scene 'laddermill' \(5 wings, wind v0 = 8 m/s.*no periodic motion: .*no "
                                         r"wing transfer .*V_c = -"):
        _quiet(**dict(SMALL, scene_options={"n_wings": N, "overrides": {"station": st}}))


def test_action_settings_are_refused_before_the_search(monkeypatch):
    import laddermill_gym.envs.laddermill.task as task_module

    def no_search(*a, **k):
        raise AssertionError("the operating point was searched for before the action settings were checked")

    monkeypatch.setattr(task_module, "operating_point", no_search)
    kw = dict(SMALL, settle={"max_time": 123.0})  # a point no earlier test memoised
    for bad, match in (({"authority": 2.0}, r"authority = 2\.0"), ({"surfaces": ("flap",)}, r"surfaces = "),
                       ({"groups": "bands", "n_bands": None}, r"n_bands = None"),
                       ({"groups": "rows"}, r"groups = 'rows'")):
        with pytest.raises(ValueError, match=match):
            LadderMillEnv(**kw, **bad)


@pytest.mark.parametrize("station", [{"cable_speed_command": True}, {"generator_torque": True}, {}])
def test_action_count_and_the_open_loop_controller_count_the_station_entry(small_env, station):
    kw = dict(SMALL, groups="all", **station)
    env = _quiet(**kw, operating_point=small_env.operating_point)
    by_hand = 1 * 3 + (1 if station else 0)  # one group, three surfaces, the station's entry
    assert env.action_space.shape == (by_hand,)
    assert action_count(N, "all", **station) == by_hand
    ctrl = make_controller("open_loop", "laddermill_gym/LadderMill-v0", kw)
    obs, _ = env.reset(seed=0)
    action, _ = ctrl.predict(obs)
    assert np.shape(action) == (by_hand,)
    env.step(action)


def test_the_power_ratio_observation_ignores_the_rewards_normalisation(small_env):
    op = small_env.operating_point
    env = _quiet(**SMALL, disturbances=[], operating_point=op, reward={"reference_power_W": 1.0e5})
    obs, _ = env.reset(seed=0)
    station = np.asarray(obs, float)[N_OBS_PER_SLOT * N:]
    assert station[STATION_OBS_INDEX["power_ratio"]] == pytest.approx(env.task.power[0] / op.reference_power_W,
                                                                      rel=1e-6)
    assert env.task.p_ref == 1.0e5  # the reward keeps the given normalisation


def test_explicit_slot_groups_are_refused_in_the_mills_words():
    from laddermill_gym.envs.laddermill.actions import resolve_slot_groups

    with pytest.raises(ValueError, match=r"every slot 0\.\.4 must appear in exactly one non-empty group"):
        resolve_slot_groups([[0, 1], [1, 2]], 5)
    with pytest.raises(ValueError, match=r"one of \('per_slot', 'all', 'halves', 'bands'\) or a list of slot index"):
        resolve_slot_groups(5, 5)  # it named the wing env's 'per_wing' and "wing index lists"


def test_a_mill_breakdown_names_the_slot(small_env):
    """The simulator names a state entry by its wing index, which in the mill's state is the slot (wings move up a
    slot at every transfer): the mill's failure text said "wing 3 u" beside its "slot" everywhere else."""
    from laddermill_gym.kernels.contract import B3_SIZE, B3_VEL

    env = _quiet(**SMALL, disturbances=[], operating_point=small_env.operating_point)
    env.reset(seed=0)
    env.unwrapped.task.batch.states[0, B3_SIZE * 3 + B3_VEL] = np.nan  # slot 3's forward speed
    _, _, term, _, info = env.step(np.zeros(env.action_space.shape, np.float32))
    assert term and info["failure"] == 1
    assert "slot 3 u" in info["failure_reason"] and "wing 3" not in info["failure_reason"], info["failure_reason"]
