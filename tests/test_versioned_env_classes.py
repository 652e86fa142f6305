"""A versioned env class is its id (a review of 2026-12-07, sixth session): built directly, or through
``gymnasium.make`` with ``None`` for a setting the id registers as a dict, it keeps the id's registered defaults.
Before, ``RotorcraftV1Env()`` and ``make("Rotorcraft-v1", termination=None)`` flew v0's episode end (a blade tip at
22.7 deg went on), and ``LadderMillV1Env()`` was LadderMill-v0's scene at full authority.

Oracles: the registration table ``envs.ENV_IDS`` (what each id is), and the craft's own blade-incidence limit
against the tip incidence the step reports.
"""

import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS, merge_arguments
from laddermill_gym.envs.rotorcraft.env_v1 import RotorcraftV1Env, RotorcraftV1VectorEnv
from laddermill_gym.envs.rotorcraft.settings import RotorcraftTerminationConfig
from laddermill_gym.envs.tethered_wing_v1 import TetheredWingV1Env, TetheredWingV1VectorEnv

V1 = "laddermill_gym/Rotorcraft-v1"


def _first_step_at_full_collective(env):
    env.reset(seed=0)
    _, _, terminated, _, info = env.step(np.array([1.0, 0.0], np.float32))  # collective 15 deg: a tip past 13 deg
    return bool(terminated), float(info["max_tip_incidence_rad"])


@pytest.mark.parametrize("build", [lambda: gym.make(V1), lambda: gym.make(V1, termination=None),
                                   lambda: RotorcraftV1Env(), lambda: RotorcraftV1Env(termination=None)])
def test_rotorcraft_v1_ends_at_the_blade_limit_however_it_is_built(build):
    assert ENV_IDS[V1]["termination"] == {"blade_stall": True}  # the oracle: what v1 is
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)  # no warning that the limit is off
        env = build()
    limit = env.unwrapped.task.craft.config.blade_incidence_limit
    terminated, tip = _first_step_at_full_collective(env)
    assert tip > limit and terminated


def test_rotorcraft_v1_vector_class_keeps_the_limit():
    env = RotorcraftV1VectorEnv(2, termination=None)
    assert env.task.termination_config.blade_stall


def test_turning_the_limit_off_on_v1_warns():
    with pytest.warns(UserWarning, match="blade_stall off"):
        env = gym.make(V1, termination=RotorcraftTerminationConfig(max_abs_roll_deg=45.0))
    terminated, tip = _first_step_at_full_collective(env)
    assert not terminated  # as asked: v0's episode end
    with pytest.warns(UserWarning, match="blade_stall off"):
        gym.make(V1, termination={"blade_stall": False})


def test_the_wing_v1_classes_take_their_ids_physics_step():
    ids = ENV_IDS["laddermill_gym/TetheredWing-v1"]
    made = gym.make("laddermill_gym/TetheredWing-v1").unwrapped.task
    for task in (TetheredWingV1Env().task, TetheredWingV1VectorEnv(2).task, made):
        assert task.batch.settings.method == ids["physics_step"] and task.batch.settings.dt == ids["physics_dt"]


def test_none_keeps_a_registered_dict_and_replaces_anything_else():
    defaults = {"termination": {"blade_stall": True}, "physics_step": "rk4", "scene_options": {"a": {"b": 1}}}
    out = merge_arguments(defaults, {"termination": None, "physics_step": None, "scene_options": {"a": None}})
    assert out == {"termination": {"blade_stall": True}, "physics_step": None, "scene_options": {"a": {"b": 1}}}
    assert merge_arguments({"x": 1}, {"x": None}) == {"x": None}
