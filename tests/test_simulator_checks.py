"""Bad input to the simulator is refused with the quantity named, and a breakdown is reported with its true cause
(issue 13 point 4): times, tolerances, integrator settings, unusable start states, non-finite derivatives, a
vanished quaternion inside a step, and DP5(4) running out of steps."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from laddermill_gym import IntegratorSettings, SimulationError, load_scene
from laddermill_gym.kernels.contract import B3_QUAT, B3_RATE, B3_VEL, NONFINITE
from laddermill_gym.kernels.integrate import rk4_advance
from laddermill_gym.sim import simulator as simulator_module


@pytest.fixture(scope="module")
def wing():
    return load_scene("tethered_wing")


@pytest.fixture
def sim(wing):
    return wing.simulator()


@pytest.mark.parametrize("t", [float("nan"), float("inf"), -float("inf")])
def test_reset_refuses_a_non_finite_time(sim, t):
    with pytest.raises(ValueError, match="time must be a finite"):
        sim.reset(t=t)


@pytest.mark.parametrize("scale, what", [(0.0, "quaternion norm 0"), (1e160, "quaternion norm 1e\\+160")])
def test_reset_refuses_a_lost_attitude(sim, scale, what):
    x = sim.initial_state.copy()
    x[B3_QUAT: B3_QUAT + 4] *= scale
    with pytest.raises(ValueError, match=f"wing 0 {what}"):
        sim.reset(x)


def test_reset_refuses_speeds_and_rates_beyond_the_limits(sim):
    x = sim.initial_state.copy()
    x[B3_VEL] = 2.0 * sim.settings.max_speed
    with pytest.raises(ValueError, match="wing 0 speed 600 m/s > 300 m/s"):
        sim.reset(x)
    x = sim.initial_state.copy()
    x[B3_RATE + 2] = 1.5 * sim.settings.max_rate
    with pytest.raises(ValueError, match="wing 0 angular rate 150 rad/s > 100 rad/s"):
        sim.reset(x)


def test_advance_to_refuses_bad_times_and_tolerances(sim):
    sim.reset()
    sim.advance_to(0.02)
    for bad in (0.01, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="t_end"):
            sim.advance_to(bad)
    assert sim.t == 0.02  # the clock did not move
    with pytest.raises(ValueError, match="atol = 0.0"):
        sim.advance_to(0.03, atol=0.0)
    with pytest.raises(ValueError, match="rtol = -1"):
        sim.advance_to(0.03, rtol=-1e-6)
    sim.advance_to(0.02)  # t_end = t is a no-op
    assert sim.t == 0.02


@pytest.mark.parametrize("field, value", [("method", "euler"), ("dt", 0.0), ("dt", -0.005), ("dt", float("inf")),
                                          ("rtol", 0.0), ("atol", float("nan")), ("max_speed", -1.0),
                                          ("max_rate", True)])
def test_integrator_settings_name_the_bad_field(field, value):
    with pytest.raises(ValueError, match=f"IntegratorSettings.{field} = "):
        IntegratorSettings(**{field: value})


def test_rhs_reports_a_non_finite_derivative(sim):
    """A finite state the model cannot evaluate (a wing at 1e200 m/s) gives a named error, not inf / nan."""
    x = sim.initial_state.copy()
    x[B3_VEL] = 1e200
    with pytest.raises(SimulationError, match=r"derivative of wing 0 .* is (nan|inf|-inf)"):
        sim.rhs(0.0, x)


def test_a_step_that_loses_the_quaternion_is_non_finite(sim):
    """The kernel's renormalisation refuses a quaternion that vanished or overflowed (it used to return q = 0)."""
    x = sim.initial_state.copy()
    x[B3_QUAT: B3_QUAT + 4] *= 1e160  # injected behind reset's back
    x0 = x.copy()
    status, done = rk4_advance(0.0, x, sim.controls, sim.settings.dt, 1, sim.model, sim.work, sim.limits)
    assert status == NONFINITE and done == 0
    np.testing.assert_array_equal(x, x0)  # the state is left at the last good step


def test_dp54_out_of_steps_says_so(wing, monkeypatch):
    monkeypatch.setattr(simulator_module, "ADVANCE_MAX_STEPS", 5)
    sim = wing.simulator()
    sim = type(sim)(sim.assembly, sim.initial_state, dataclasses.replace(wing.settings, method="dp54"),
                    sim.initial_controls)
    with pytest.raises(SimulationError, match="used up its budget of steps"):
        sim.advance_to(1.0)
    assert 0.0 < sim.t < 1.0


def test_the_error_controlled_w_method_is_named_when_out_of_steps(wing, monkeypatch):
    """advance_to runs the settings' error-controlled method (here ROS34PW2), and its report names it, not DP5(4)."""
    monkeypatch.setattr(simulator_module, "ADVANCE_MAX_STEPS", 3)
    sim = wing.simulator()
    sim = type(sim)(sim.assembly, sim.initial_state, dataclasses.replace(wing.settings, method="ros34pw2a"),
                    sim.initial_controls)
    with pytest.raises(SimulationError, match=r"ROS34PW2 \(error-controlled\) used up its budget of steps"):
        sim.advance_to(1.0)


def test_a_run_of_no_steps_leaves_the_error_controlled_methods_a_step_to_take():
    """``step(n_steps=0)`` stored a zero proposal: DP5(4) then spun through its budget of steps without moving and
    ROS34PW2a reported a collapsed step (the review of 2026-12-07). Oracle: the same step(1) without the empty call."""
    import dataclasses

    from laddermill_gym import load_scene

    base = load_scene("tethered_wing").simulator()
    for method in ("dp54", "ros34pw2a"):
        s = dataclasses.replace(base.settings, method=method, dt=0.01)
        ref = type(base)(base.assembly, base.initial_state, s)
        ref.step(n_steps=1)
        sim = type(base)(base.assembly, base.initial_state, s)
        sim.step(n_steps=0)
        assert sim.t == 0.0
        sim.step(n_steps=1)
        assert sim.t == ref.t == 0.01
        np.testing.assert_array_equal(sim.state, ref.state)
