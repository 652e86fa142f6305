"""ROS1, the linearly implicit Euler method at the step's mid-time (``ros1``): tableau, order for any Jacobian,
stability function, a time-only rate integrated exactly (the mill's pay-out), its iteration matrix kept over steps
(the compiled step's order on the tethered wing and batch copies against single runs: tests/test_rosenbrock.py).

Oracles: the method's closed form y1 = y0 + (I - h J)^-1 h f(t0 + h/2, y0) (Hairer & Wanner, Solving ODEs II, IV.7
with s = 1, gamma = 1, the stage at the mid-time) evaluated with numpy; scipy's DOP853 on a small ODE; R(z) = 1 /
(1 - z) for y' = lambda y; the schedule's pay-out in closed form, s(t) = a t^2 / 2 on a ramp of rate a; our DP5(4)
at tight tolerances on the tethered wing (itself checked against scipy's DOP853 in tests/test_work_precision.py).
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from laddermill_gym import load_scene
from laddermill_gym.kernels.rigid.rosenbrock import ROS1
from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS, W_METHODS
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings
from tests.test_rosenbrock import pendulum, pendulum_jac, transformed_step


def test_ros1_is_registered_as_a_fixed_step_w_method():
    assert W_METHODS["ros1"] is ROS1 and "ros1" in FIXED_STEP_METHODS
    gamma, alpha, a, c, m, mhat = ROS1
    assert gamma.tolist() == [1.0] and alpha.tolist() == [0.5] and m.tolist() == [1.0]
    assert a.shape == c.shape == (1, 1) and not a.any() and not c.any() and not mhat.any()


def test_the_tableau_is_linearly_implicit_euler_with_order_one_for_any_jacobian():
    y0, T = np.array([1.0, 0.0]), 2.0
    ref = solve_ivp(pendulum, (0, T), y0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
    for jac_scale in (1.0, 0.3, 0.0):  # exact, wrong and no Jacobian (then it is explicit Euler)
        errs = []
        for n in (40, 80, 160, 320):
            h, y = T / n, y0.copy()
            for i in range(n):
                J = jac_scale * pendulum_jac(i * h, y)
                closed = y + np.linalg.solve(np.eye(2) - h * J, h * pendulum(i * h + 0.5 * h, y))
                y = transformed_step(i * h, y, h, ROS1, J)
                np.testing.assert_allclose(y, closed, rtol=0, atol=1e-14)
            errs.append(np.max(np.abs(y - ref)))
        slopes = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
        assert abs(slopes[-1] - 1.0) < 0.1, (jac_scale, errs, slopes)


def test_the_mills_pay_out_follows_its_schedule_exactly():
    """The 11-wing mill on its speed ramp (V = a t, a = 2/30 m/s^2 in configs/scenes/laddermill.yaml): after 2 s of
    ros1 steps of 0.05 s the cable paid out is a t^2 / 2 to rounding; with the stage at t it would be h a t / 2 =
    3.3 mm short (explicit Euler on ds/dt = V(t))."""
    sc = load_scene("laddermill", dimension=3, n_wings=11)
    sim = with_settings(sc.simulator(), method="ros1", dt=0.05)
    sim.step(n_steps=40)
    a = 2.0 / 30.0
    assert sim.t == pytest.approx(2.0, abs=1e-12)
    assert sim.cable_paid_out() == pytest.approx(0.5 * a * sim.t ** 2, rel=1e-12, abs=1e-12)


def test_stability_function_is_one_over_one_minus_z():
    """L-stable: R(z) = 1 / (1 - z), |R| < 1 on the imaginary axis (it damps every oscillation), R(-inf) = 0. The
    study's stability function (whip_spectrum.stability_function_w) gives the same."""
    from laddermill_gym.studies.numerics.whip_spectrum import stability_function_w

    zs = np.array([-0.3, 0.5, 4j, -0.3 + 2j, -50 + 20j, -1e8])
    # at z = -1e8 the formula's 1 + z / (1 - z) cancels terms of size 1: a few units in the last place of 1
    np.testing.assert_allclose(stability_function_w(ROS1, zs), 1.0 / (1.0 - zs), rtol=1e-12, atol=1e-14)
    assert np.all(np.abs(stability_function_w(ROS1, 1j * np.array([0.1, 1.0, 10.0]))) < 1.0)


def test_a_kept_iteration_matrix_stays_first_order_close():
    """With the matrix kept 4 steps the method is still order 1 (a W-method's order holds for any J): over 2 s of
    the tethered wing at 10 ms its error stays within twice the every-step run's."""
    base = build_simulator("tethered_wing")
    wind = base.assembly.wind.with_modulation(0.5, 1e-3, np.ones(2), np.array([0.0, 0.1]))
    ref = with_settings(base, wind=wind, method="dp54", breakpoints="all")
    ref.advance_to(2.0, rtol=1e-11, atol=1e-11)
    errs = {}
    for every in (1, 4):
        sim = with_settings(base, wind=wind, method="ros1", dt=0.01, jacobian_every=every)
        sim.step(n_steps=200)
        errs[every] = np.max(np.abs(sim.wing_positions() - ref.wing_positions()))
    assert 0 < errs[4] < 2.0 * errs[1], errs
