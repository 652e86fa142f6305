"""Issue 34 item 10: ``gymnasium.make(id, **kwargs)`` (and ``make_vec``, and the SB3 adapter) build the env from
the id's registered defaults merged with the caller's arguments: a dict-valued argument is merged key by key at
every depth instead of replacing the registered one (Gymnasium's own ``make`` only replaces), so the README's
``scene_options={"overrides": {"wind": {"v0": 10.0}}}`` keeps TetheredWing-v0's ``elements_per_piece: 1`` and
``method: ros34pw2``. One test per registered id.

Oracle: the arguments each env must be built with, written out here by hand (the registered defaults with the
caller's keys added), and the built model itself (the scene's wind, method and element count)."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

from laddermill_gym.envs import ENV_IDS, merge_arguments, registered_arguments
from tests.env_cases import IDS, LC, LC1, LM, LM1, LM2, LM3, PK, PK1, PMC, RC, RC1, TW, TW1, case_kwargs

#: per id: (argument, the caller's dict, the dict the env must be built with)
MERGES = {
    TW: ("scene_options", {"overrides": {"wind": {"v0": 10.0}}},
         {"elements_per_piece": 1, "method": "ros34pw2", "overrides": {"wind": {"v0": 10.0}}}),
    TW1: ("scene_options", {"overrides": {"wind": {"v0": 10.0}}},
          {"elements_per_piece": 1, "overrides": {"wind": {"v0": 10.0}}}),
    PMC: ("scene_options", {"overrides": {"wind": {"v0": 10.0}}},
          {"element_length": 70.0, "method": "implicit", "dt": 0.025, "overrides": {"wind": {"v0": 10.0}}}),
    LC: ("scene_options", {"n_wings": 5, "overrides": {"wind": {"v0": 10.0}}},
         {"n_wings": 5, "overrides": {"wind": {"v0": 10.0}}}),
    LC1: ("scene_options", {"n_wings": 5, "overrides": {"wind": {"v0": 10.0}}},
          {"n_wings": 5, "overrides": {"wind": {"v0": 10.0}}}),
    RC: ("reward", {"power_weight": 0.5}, {"power_weight": 0.5}),
    RC1: ("termination", {"max_abs_roll_deg": 45.0}, {"blade_stall": True, "max_abs_roll_deg": 45.0}),
    LM: ("termination", {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0},
         {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0}),
    LM1: ("termination", {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0},
          {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0}),
    LM2: ("termination", {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0},
          {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0}),
    LM3: ("termination", {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0},
          {"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0}),
    PK: ("reward", {"power_weight": 0.5}, {"power_weight": 0.5}),
    PK1: ("reward", {"power_weight": 0.5}, {"power_weight": 0.5}),
}


def test_every_registered_id_has_a_merge_case():
    assert set(MERGES) == set(ENV_IDS) == set(IDS)


@pytest.mark.parametrize("env_id", IDS)
def test_make_merges_the_registered_defaults_with_the_callers_arguments(env_id):
    name, given, expected = MERGES[env_id]
    kwargs = case_kwargs(env_id, episode_time=1.0)
    kwargs.pop("scene_options", None) if env_id in (TW, PMC) else None  # the registered ones must come through
    kwargs[name] = given
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        env = gym.make(env_id, **kwargs).unwrapped
    built = env._kwargs
    assert built[name] == expected
    for key, value in ENV_IDS[env_id].items():  # the other registered defaults (and the small cases') stay
        if key != name:
            assert built[key] == kwargs.get(key, value), key
    if name == "scene_options" and "overrides" in given:
        scene = env.task.scene
        assert scene.string.wind.v0 == 10.0 if env_id == PMC else scene.assembly.wind.v0 == 10.0
    obs, info = env.reset(seed=0)
    obs, *_ = env.step(np.zeros(env.action_space.shape, np.float32))
    assert np.isfinite(obs).all()


def test_readme_example_keeps_the_registered_scene_options():
    """The README's way to change a parameter: before, the scene's own RK4 at 50 ms was refused."""
    env = gym.make(TW, scene_options={"overrides": {"wind": {"v0": 10.0}}}, episode_time=1.0).unwrapped
    scene = env.task.scene
    assert scene.assembly.wind.v0 == 10.0
    assert scene.settings.method == "ros34pw2" and scene.assembly.elements.count == 1
    vec = gym.make_vec(TW, 2, vectorization_mode="vector_entry_point", episode_time=1.0,
                       scene_options={"overrides": {"wind": {"v0": 10.0}}})
    assert vec.task.scene.settings.method == "ros34pw2" and vec.task.scene.assembly.wind.v0 == 10.0
    obs, _ = vec.reset(seed=0)
    np.testing.assert_array_equal(obs[0], env.reset(seed=0)[0])


def test_sb3_adapter_merges_the_same_way():
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.envs.sb3 import sb3_vec_env

    venv = sb3_vec_env(TW, 1, seed=0, episode_time=1.0, scene_options={"overrides": {"wind": {"v0": 10.0}}})
    assert venv.task.scene.settings.method == "ros34pw2" and venv.task.scene.assembly.wind.v0 == 10.0
    env = gym.make(TW, episode_time=1.0, scene_options={"overrides": {"wind": {"v0": 10.0}}})
    np.testing.assert_array_equal(venv.reset()[0], env.reset(seed=0)[0])


def test_merge_arguments():
    defaults = {"a": 1, "d": {"x": 1, "y": {"p": 1, "q": 2}}, "e": {"k": 1}}
    given = {"a": 2, "d": {"y": {"q": 3}, "z": 4}, "e": None, "f": {"new": 1}}
    merged = merge_arguments(defaults, given)
    # None where the default is a dict keeps it (the envs read None as their defaults: Rotorcraft-v1's termination
    # with None lost its blade limit); elsewhere None replaces, as any value
    assert merged == {"a": 2, "d": {"x": 1, "y": {"p": 1, "q": 3}, "z": 4}, "e": {"k": 1}, "f": {"new": 1}}
    assert merge_arguments({"a": 1}, {"a": None}) == {"a": None}
    assert defaults == {"a": 1, "d": {"x": 1, "y": {"p": 1, "q": 2}}, "e": {"k": 1}}  # inputs unchanged
    assert given == {"a": 2, "d": {"y": {"q": 3}, "z": 4}, "e": None, "f": {"new": 1}}
    out = registered_arguments(TW, {"scene_options": {"method": "rk4"}})
    assert out["scene_options"] == {"elements_per_piece": 1, "method": "rk4"}
    out["scene_options"]["method"] = "changed"
    assert ENV_IDS[TW]["scene_options"]["method"] == "ros34pw2"  # a copy, never the registry itself
    with pytest.raises(ValueError, match="must be one of"):
        registered_arguments("laddermill_gym/NoSuch-v0")


def test_entry_points_are_the_registered_classes():
    from laddermill_gym.envs import ENTRY_POINTS

    for env_id in IDS:
        spec = gym.spec(env_id)
        creator = gym.envs.registration.load_env_creator(spec.entry_point)
        vector = gym.envs.registration.load_env_creator(spec.vector_entry_point)
        assert f"{creator.env_class.__module__}:{creator.env_class.__name__}" == ENTRY_POINTS[env_id][0]
        assert f"{vector.env_class.__module__}:{vector.env_class.__name__}" == ENTRY_POINTS[env_id][1]
        assert creator.metadata == creator.env_class.metadata  # Gymnasium reads the render modes there
        assert spec.kwargs == ENV_IDS[env_id]


def test_controller_factory_merges_the_same_way():
    """``make_controller`` designs on the env's merged arguments: the LQR of TetheredWing-v0 in 10 m/s wind keeps
    the registered scene options (one element, ROS34PW2; before, the shallow merge dropped them and the scene's RK4
    at 50 ms was refused) and acts on the env made with the same arguments."""
    from laddermill_gym.control.factory import make_controller

    over = {"scene_options": {"overrides": {"wind": {"v0": 10.0}}}}
    ctrl = make_controller("lqr", TW, over)
    want = registered_arguments(TW, over)["scene_options"]
    assert want["elements_per_piece"] == 1 and want["method"] == "ros34pw2"
    env = gym.make(TW, episode_time=1.0, **over)
    obs, _ = env.reset(seed=0)
    act = np.asarray(ctrl.predict(obs)[0])
    assert act.shape == env.action_space.shape and np.all(np.isfinite(act))
