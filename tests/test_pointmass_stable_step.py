"""The point-mass env on the explicit step past its stable step: it steps at a finer whole fraction of the control
period, with an UnstableStepWarning, as the wing envs do for RK4 (``envs/physics_step.py``). Oracle: the closed-form
limit of symplectic Euler on the string, min(l0 / c, mu l0^2 / (2 DA)) with c = sqrt(EA / mu), computed here from the
cable's data. Before, PointMassChain-v0 with ``{"method": "explicit", "dt": 0.025}`` stopped within its first control
period ("the simulator stopped: speed limit exceeded")."""

from __future__ import annotations

import math
import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.sim.stable_step import UnstableStepWarning

PM = "laddermill_gym/PointMassChain-v0"
EXPLICIT = {"element_length": 70.0, "method": "explicit"}


def _limit(string) -> float:
    c = string.cable
    l0 = string.element_length
    return min(l0 / math.sqrt(c.EA / c.mass_per_length), c.mass_per_length * l0 ** 2 / (2.0 * c.DA))


def _run_to_the_end(env) -> str:
    env.reset(seed=0)
    zero = np.zeros(env.action_space.shape, dtype=np.float32)
    while True:
        _, _, term, trunc, info = env.step(zero)
        if term:
            return info.get("failure_reason", "terminated")
        if trunc:
            return ""


def test_an_explicit_step_past_its_limit_is_refined_with_a_warning_and_runs():
    with pytest.warns(UnstableStepWarning, match=r"dt = 0.025 s is above 0.9 x the explicit step's stable step"):
        env = gym.make(PM, scene_options={**EXPLICIT, "dt": 0.025}, settle_time=0.0, episode_time=5.0)
    task = env.unwrapped.task
    limit = _limit(task.string)
    assert 0.008 < limit < 0.0085, limit  # 70 m of Dyneema: l0 / c = 8.25 ms
    n = task.n_substeps
    assert task.scene.dt == pytest.approx(task.control_dt / n, rel=1e-12)
    assert task.scene.dt <= 0.9 * limit < task.control_dt / (n - 1)  # the largest whole fraction below the margin
    assert _run_to_the_end(env) == ""
    env.close()


def test_a_step_within_the_limit_and_the_implicit_step_are_kept():
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableStepWarning)
        env = gym.make(PM, scene_options={**EXPLICIT, "dt": 0.005}, settle_time=0.0, episode_time=1.0)
        assert (env.unwrapped.task.scene.dt, env.unwrapped.task.n_substeps) == (0.005, 10)
        env.close()
        env = gym.make(PM, settle_time=0.0, episode_time=1.0)  # the registered implicit step at 25 ms
        assert (env.unwrapped.task.scene.method, env.unwrapped.task.scene.dt) == ("implicit", 0.025)
        env.close()


def test_a_step_that_does_not_divide_the_period_is_refused_before_any_refinement():
    with pytest.raises(ValueError, match=r"must be a whole number of scene steps \(0.03 s\)"):
        gym.make(PM, scene_options={**EXPLICIT, "dt": 0.03}, settle_time=0.0)
