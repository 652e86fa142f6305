"""The rotorcraft env on RK4 past RK4's stable step: it steps at a finer whole fraction of the control period, with an
UnstableStepWarning, as the wing envs do (``envs/physics_step.py``). Oracles: the stable step from the eigenvalues of a
central-difference Jacobian of the simulator's right-hand side at the trim and RK4's stability polynomial (bisected
here along each eigenvalue's ray), and a run at a resolved step (RK4 at 0.78 ms). Before, a requested 12.5 ms step
ran as asked and a seeded episode ended 0.8 s in on a tether node at 91 m/s ("integration failed")."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs.physics_step import ENV_STEP_MARGIN
from laddermill_gym.sim.stable_step import UnstableStepWarning
from tests.test_rotorcraft_env import jacobian_eigenvalues

RC = "laddermill_gym/Rotorcraft-v0"


def _rk4_limit(lam: complex) -> float:
    """The largest h with |R(h lam)| <= 1 for RK4's R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 (bisection along the ray;
    inf for an eigenvalue with a non-negative real part, a physical instability)."""
    if lam.real >= 0.0:
        return np.inf

    def grows(h):
        z = h * lam
        return abs(1 + z + z * z / 2 + z ** 3 / 6 + z ** 4 / 24) > 1.0

    lo, hi = 0.0, 1.0
    while not grows(hi):
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if grows(mid) else (mid, hi)
    return lo


def _stable_step(task) -> float:
    """RK4's stable step [s] at the task's trim from the eigenvalues of a central-difference Jacobian of its
    simulator's rhs (``tests/test_rotorcraft_env.py``)."""
    return min(_rk4_limit(complex(v)) for v in jacobian_eigenvalues(task) if abs(v) > 1e-9)


def _episode(env, periods=200):
    """CG positions (periods + 1, 3) [m] under the trim action plus seeded uniform noise of 0.3, and whether the
    episode ended early."""
    env.reset(seed=0)
    rng = np.random.default_rng(3)
    states = env.unwrapped.task.batch.states
    cg = [states[0][:3].copy()]
    for _ in range(periods):
        a = np.clip(env.unwrapped.task.trim_action + rng.uniform(-0.3, 0.3, 2), -1.0, 1.0)
        _, _, term, trunc, info = env.step(a.astype(np.float32))
        if term or trunc:
            return np.array(cg), info.get("failure_reason", "ended")
        cg.append(states[0][:3].copy())
    return np.array(cg), ""


def test_a_step_past_rk4s_limit_is_refined_with_a_warning_and_runs_as_a_resolved_step():
    with pytest.warns(UnstableStepWarning, match=r"physics_dt = 0.0125 s is above 0.9 x RK4's estimated stable step"):
        env = gym.make(RC, physics_step="rk4", physics_dt=0.0125, episode_time=10.0)
    task = env.unwrapped.task
    limit = _stable_step(task)
    assert 0.004 < limit < 0.008, limit  # the tether's fast mode, not the 50 ms of the config
    dt, n = task.batch.settings.dt, task.n_substeps
    assert n * dt == pytest.approx(task.control_dt, rel=1e-12)
    assert dt <= ENV_STEP_MARGIN * limit * (1 + 1e-3)  # within the margin of the oracle's limit (the env's own
    assert task.control_dt / (n - 1) > ENV_STEP_MARGIN * limit * (1 - 1e-3)  # estimate differs in its differences)
    assert str(n) in task.physics_step_note and "0.0125" in task.physics_step_note
    cg, ended = _episode(env)
    assert ended == "", ended
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableStepWarning)  # a resolved step: no warning
        ref_env = gym.make(RC, physics_step="rk4", physics_dt=0.05 / 64, episode_time=10.0)
    ref, ref_ended = _episode(ref_env)
    assert ref_ended == "" and ref_env.unwrapped.task.physics_step_note == ""
    extent = np.max(np.linalg.norm(ref, axis=1))
    assert np.max(np.linalg.norm(cg - ref, axis=1)) < 1e-3 * extent
    env.close()
    ref_env.close()


def test_a_step_within_the_limit_is_kept():
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableStepWarning)
        env = gym.make(RC, physics_step="rk4", physics_dt=0.005, episode_time=10.0)
    task = env.unwrapped.task
    assert (task.batch.settings.dt, task.n_substeps, task.physics_step_note) == (0.005, 10, "")
    env.close()


def test_a_step_that_does_not_divide_the_period_is_refused_before_any_refinement():
    """As in the wing envs: the step asked for must divide the control period, past RK4's limit or not."""
    with pytest.raises(ValueError, match="not a whole multiple of the physics step 0.03 s"):
        gym.make(RC, physics_step="rk4", physics_dt=0.03)
