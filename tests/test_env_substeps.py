"""An env does not end an episode for a numerical failure that a smaller step avoids (issue 13, point 4).

TetheredWing-v0 with RK4 at 0.05 s (its step before ROS34PW2 became its default); after a 5x wind step its cable
stiffens past RK4's stability limit and the control period starting at 1.05 s diverges ("integration failed").
``BatchSimulator.advance`` reruns such a copy from its state before the period at a quarter (then a sixteenth) of
the step. Oracles: the same episode with the
reruns switched off fails numerically at that time; a copy that does not fail is bit-identical to a single env
that never reran anything.
"""

import math

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401
import laddermill_gym.sim.batch as batch_module
from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs import physics_step
from laddermill_gym.sim.stable_step import UnstableStepWarning

TW = "laddermill_gym/TetheredWing-v0"
STEP5X = [{"type": "SpeedStep", "step": 4.0, "time": 1.0}]  # speed factor 1 -> 5 at 1 s
RK4 = {"elements_per_piece": 1, "method": "rk4"}


def _run(env, ctrl, n):
    obs, info = env.reset(seed=0)
    for i in range(n):
        obs, _, term, trunc, info = env.step(ctrl.predict(obs)[0])
        if term or trunc:
            return i + 1, info
    return n, info


def test_numerical_failure_is_rerun_at_a_finer_step(monkeypatch):
    ctrl = make_controller("lqr", TW)
    monkeypatch.setattr(physics_step, "ENV_STEP_MARGIN", math.inf)  # keep the 50 ms step (see the next tests)
    monkeypatch.setattr(batch_module, "SUBSTEP_DIVISORS", ())
    env = gym.make(TW, disturbances=STEP5X, episode_time=5.0, scene_options=RK4)
    n_off, info_off = _run(env, ctrl, 100)
    assert "integration failed" in info_off["failure_reason"]
    monkeypatch.setattr(batch_module, "SUBSTEP_DIVISORS", (4, 16))
    env = gym.make(TW, disturbances=STEP5X, episode_time=5.0, scene_options=RK4)
    n_on, info_on = _run(env, ctrl, 100)
    assert env.unwrapped.task.batch.substep_reruns >= 1
    assert n_on > n_off and "integration failed" not in info_on.get("failure_reason", "")


def test_the_default_integrator_flies_through_the_5x_wind_step():
    """With its default ROS34PW2 at 0.05 s TetheredWing-v0's LQR flies the 5x wind step for 20 s without a rerun
    (as RK4 at 10 ms does)."""
    ctrl = make_controller("lqr", TW)
    env = gym.make(TW, disturbances=STEP5X, episode_time=20.0)
    n, info = _run(env, ctrl, 400)
    assert n == 400 and env.unwrapped.task.batch.substep_reruns == 0
    fine = gym.make(TW, disturbances=STEP5X, episode_time=20.0, physics_dt=0.01, scene_options=RK4)
    assert _run(fine, ctrl, 400)[0] == 400


def test_copies_that_do_not_fail_are_untouched_by_a_neighbours_rerun():
    """Two copies of the one-element tethered wing at RK4 0.05 s: copy 0 in a 5x wind (fails numerically and is
    rerun), copy 1 calm; copy 1 equals a batch of one calm copy bit for bit, copy 0 gets through."""
    from laddermill_gym.atmosphere.field import WindField
    from laddermill_gym.kernels.batch import fixed_batch
    from laddermill_gym.ladder.scene import load_scene
    from laddermill_gym.sim.batch import BatchSimulator

    sc = load_scene("tethered_wing", elements_per_piece=1, dt=0.05)
    x0, u0 = sc.initial_state()

    def make(n):
        b = BatchSimulator(sc.assembly, n, sc.settings)
        b.states[:], b.controls[:] = x0, u0
        return b

    def kernel_pass(b):
        def run(dt, ns):
            active = (ns > 0).astype(np.int64)
            fixed_batch(b.t, b.states, b.controls, dt, int(ns.max()), *b.detached, b.work, b.air, active, b.limits,
                        b.tableau, b.breaks, b.status, b.done)
        return run

    two, one = make(2), make(1)
    two.set_wind(0, WindField(t0=1.0, dt=0.1, speed=np.array([1.0, 5.0]), direction=np.zeros(2)))
    for _ in range(60):  # 3 s
        two.advance(np.array([1, 1]), kernel_pass(two))
        one.advance(np.array([1]), kernel_pass(one))
        assert np.array_equal(two.states[1], one.states[0]) and two.t[1] == one.t[0]
    assert two.substep_reruns >= 1 and one.substep_reruns == 0
    assert two.status[0] == 0 and two.t[0] == pytest.approx(3.0)


def test_rk4_past_its_stable_step_in_the_strongest_wind_steps_finer(monkeypatch):
    """RK4 at 50 ms: stable at the trim in the nominal wind (limit 0.11 s), past the limit after the 5x wind step
    (about 0.023 s: the wing's aerodynamic damping, 5x larger). Kept at 50 ms it ends at 1.3 s on an angle of
    attack "outside the aerodynamic range" even with the reruns (the state before the failing period is already
    off): a numerical end that looks physical. The env therefore estimates RK4's stable step at the trim in the
    disturbances' strongest wind and steps at 50/3 ms, with a warning naming both; the LQR flies the 20 s."""
    ctrl = make_controller("lqr", TW)
    monkeypatch.setattr(physics_step, "ENV_STEP_MARGIN", math.inf)
    kept = gym.make(TW, disturbances=STEP5X, episode_time=20.0, scene_options=RK4)
    n, info = _run(kept, ctrl, 400)
    assert n < 40 and "outside the aerodynamic range" in info["failure_reason"]
    monkeypatch.undo()
    named = r"physics_dt = 0.05 s .*\(speed factor 5\): stepping at 0.01667 s"
    with pytest.warns(UnstableStepWarning, match=named) as seen:
        env = gym.make(TW, disturbances=STEP5X, episode_time=20.0, scene_options=RK4)
    print(next(w.message for w in seen if "speed factor" in str(w.message)))  # the estimate and eigenvalue (pytest -s)
    assert env.unwrapped.task.scene.settings.dt == pytest.approx(0.05 / 3)
    assert _run(env, ctrl, 400)[0] == 400


def test_the_step_is_kept_where_it_is_stable():
    """The nominal wind (the default direction step): RK4 at 50 ms is within its limit and kept, silently."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableStepWarning)
        env = gym.make(TW, episode_time=5.0, scene_options=RK4)
    assert env.unwrapped.task.scene.settings.dt == 0.05 and env.unwrapped.task.physics_step_note == ""
