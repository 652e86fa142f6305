"""The linearly implicit (Rosenbrock-W) integrators: tableaux, Jacobian, order, stability beyond RK4, batch.

Oracles: an independent numpy implementation of the methods in their published (untransformed) form and scipy's
DOP853 on a small ODE; finite differences of the assembled generalised forces for the cable Jacobian; our DP5(4)
at tight tolerances on the scenes (itself checked against scipy's DOP853 in tests/test_work_precision.py).
"""

import numpy as np
import pytest
from numba import njit
from scipy.integrate import solve_ivp

from laddermill_gym.kernels.dispatch import model_assemble
from laddermill_gym.kernels.rigid.cable_jacobian import add_cable_stiffness
from laddermill_gym.kernels.rigid.rosenbrock import ROS2, ROS2T, ROS34PW2
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.simulator import IntegratorSettings, SimulationError
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings

# published coefficients (alpha_ij, gamma_ij strictly lower, gamma, b, embedded bhat): Verwer et al. 1999; Rang &
# Angermann 2005
G2 = 1.0 + 1.0 / np.sqrt(2.0)
BHAT = {"ros2": [1.0, 0.0], "ros2t": [1.0, 0.0],
        "ros34pw2": [0.37810903145819369, -0.096042292212423178, 0.5, 0.2179332607542295]}
PUBLISHED = {
    "ros2": (G2, [[0, 0], [1.0, 0]], [[0, 0], [-2.0 * G2, 0]], [0.5, 0.5], ROS2, 2),
    "ros2t": (0.25, [[0, 0], [1.0, 0]], [[0, 0], [-0.5, 0]], [0.5, 0.5], ROS2T, 2),  # the same family at gamma 1/4
    "ros34pw2": (0.435866521508459,
                 [[0, 0, 0, 0], [0.87173304301691801, 0, 0, 0], [0.84457060015369423, -0.11299064236484185, 0, 0],
                  [0, 0, 1.0, 0]],
                 [[0, 0, 0, 0], [-0.87173304301691801, 0, 0, 0], [-0.90338057013044082, 0.054180672388095326, 0, 0],
                  [0.24212380706095346, -1.2232505839045147, 0.54526025533510214, 0]],
                 [0.24212380706095346, -1.2232505839045147, 1.5452602553351020, 0.435866521508459], ROS34PW2, 3),
}


def pendulum(t, y):
    """A damped, forced pendulum: nonlinear and non-autonomous."""
    return np.array([y[1], -np.sin(y[0]) - 0.1 * y[1] + 0.3 * np.cos(1.3 * t)])


def pendulum_jac(t, y):
    return np.array([[0.0, 1.0], [-np.cos(y[0]), -0.1]])


def published_step(t, y, h, gamma, alpha, gam, b, J):
    """One step of the untransformed form: (I - gamma h J) k_i = h f(t + a_i h, y + sum alpha_ij k_j)
    + h J sum gamma_ij k_j, y1 = y + sum b_i k_i (Hairer & Wanner (7.4), J fixed over the step)."""
    alpha, gam = np.asarray(alpha, float), np.asarray(gam, float)
    s = len(b)
    W = np.eye(y.size) - gamma * h * J
    k = np.zeros((s, y.size))
    for i in range(s):
        ti = t + alpha[i].sum() * h
        rhs = h * pendulum(ti, y + alpha[i] @ k) + h * J @ (gam[i] @ k)
        k[i] = np.linalg.solve(W, rhs)
    return y + np.asarray(b) @ k


def transformed_step(t, y, h, tableau, J, embedded=False):
    """One step of the transformed form with our tableau (the form the kernels use); the embedded solution when
    ``embedded``."""
    gamma, al, a, c, m, mhat = tableau
    gamma = gamma[0]
    m = mhat if embedded else m
    W = np.eye(y.size) / (gamma * h) - J
    U = np.zeros((m.size, y.size))
    for i in range(m.size):
        rhs = pendulum(t + al[i] * h, y + a[i] @ U) + (c[i] @ U) / h
        U[i] = np.linalg.solve(W, rhs)
    return y + m @ U


@pytest.mark.parametrize("name", list(PUBLISHED))
def test_tableau_is_the_published_method_and_has_its_order_for_any_jacobian(name):
    gamma, alpha, gam, b, tableau, order = PUBLISHED[name]
    y0, T = np.array([1.0, 0.0]), 2.0
    ref = solve_ivp(pendulum, (0, T), y0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
    for jac_scale in (1.0, 0.3, 0.0):  # exact, wrong, and no Jacobian: a W-method keeps its order for any J
        errs = []
        for n in (20, 40, 80, 160):
            h, y, yp = T / n, y0.copy(), y0.copy()
            for i in range(n):
                J = jac_scale * pendulum_jac(i * h, y)
                y = transformed_step(i * h, y, h, tableau, J)
                yp = published_step(i * h, yp, h, gamma, alpha, gam, b, J)
                assert np.allclose(y, yp, rtol=0, atol=1e-13)
            errs.append(np.max(np.abs(y - ref)))
        slopes = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
        assert abs(slopes[-1] - order) < 0.25, (jac_scale, errs, slopes)
    # the embedded solution (the error estimate of the adaptive method) is the published one, of order p - 1
    errs = []
    for n in (40, 80, 160, 320):
        h, y, yp = T / n, y0.copy(), y0.copy()
        for i in range(n):
            J = pendulum_jac(i * h, y)
            y = transformed_step(i * h, y, h, tableau, J, embedded=True)
            yp = published_step(i * h, yp, h, gamma, alpha, gam, BHAT[name], J)
            assert np.allclose(y, yp, rtol=0, atol=1e-13)
        errs.append(np.max(np.abs(y - ref)))
    assert abs(np.log2(errs[-2] / errs[-1]) - (order - 1)) < 0.25, errs


@njit
def _stiffness_blocks(t, x, u, f, M, W):
    """(D, U) of the mass matrix and of M - dQ/dq (the cable part) at x."""
    model_assemble(M.kind, t, x, u, f, M, W)
    D0, U0 = W.D.copy(), W.U.copy()
    W.Rn[:] = W.Rw
    add_cable_stiffness(t, x, M, W, 0.0, 1.0)
    return D0, U0, W.D.copy(), W.U.copy()


@njit
def _forces(t, x, u, f, M, W):
    model_assemble(M.kind, t, x, u, f, M, W)
    return W.bv.copy()


def test_cable_stiffness_equals_finite_differences_of_the_node_forces():
    from laddermill_gym.ladder.scene import load_scene

    # two elements with a free node between them; without the sag correction the Jacobian is the exact one
    sim = load_scene("tethered_wing", sag=False).simulator()
    M, W = sim.model, sim.work
    x, u, f = sim.state.copy(), sim.controls.copy(), np.zeros(sim.state.size)
    D0, U0, D1, U1 = _stiffness_blocks(0.0, x, u, f, M, W)
    nw = sim.assembly.n_wings
    base = _forces(0.0, x, u, f, M, W)
    node = 0  # the free node between the two elements (block nw + node)
    b = nw + node
    o = 13 * nw + 6 * node
    eps = 1e-4  # [m]
    fd = np.zeros((3, 3))
    for j in range(3):
        xp = x.copy()
        xp[o + j] += eps
        fd[:, j] = (_forces(0.0, xp, u, f, M, W)[b, :3] - base[b, :3]) / eps
    K = D1[b, :3, :3] - D0[b, :3, :3]  # = -dQ/dq of the cable
    assert np.linalg.norm(K) > 1e3  # a taut element: thousands of N/m at least
    np.testing.assert_allclose(K, -fd, rtol=2e-3, atol=1e-3 * np.abs(K).max())


@pytest.mark.parametrize("method, dt, ratio_min", [("ros1", 0.0025, 1.7), ("ros2", 0.01, 3.0), ("ros2t", 0.01, 3.0),
                                                   ("ros34pw2", 0.01, 6.0)])
def test_observed_order_on_the_tethered_wing(method, dt, ratio_min):
    """Halving the step divides the error by about 2^p once the cable's excited axial modes are resolved (at
    larger steps the L-stable methods damp them, so the observed order approaches p from below; the ratio
    from 0.01 to 0.005 s is printed (pytest -s; 2026-11-30: ros2 3.96, ros34pw2 7.32; docs/numerics.md)). ros1 (order
    1) from 2.5 ms: 1.85 (2026-12-06)."""
    base = build_simulator("tethered_wing")
    rng = np.random.default_rng(0)
    x0 = base.initial_state.copy()
    x0[7 + 1] += 0.2 * rng.normal()
    x0[10] += 0.02 * rng.normal()
    ref = with_settings(base, state=x0, method="dp54")
    ref.advance_to(2.0, rtol=1e-12, atol=1e-12)
    errs = []
    for h in (dt, dt / 2):
        sim = with_settings(base, state=x0, method=method, dt=h)
        sim.step(n_steps=int(round(2.0 / h)))
        errs.append(np.max(np.abs(sim.wing_positions() - ref.wing_positions())))
    print(f"{method}: wing position errors {errs[0]:.3g}, {errs[1]:.3g} m at {dt:g}, {dt / 2:g} s: ratio per halving "
          f"{errs[0] / errs[1]:.3g}")  # the ratio held below (pytest -s)
    assert errs[0] / errs[1] > ratio_min, errs


def test_steps_five_times_rk4s_limit_where_rk4_fails():
    """The tethered wing's RK4 limit is 0.019 s (docs/work_precision.md); at 0.1 s RK4 diverges and ROS34PW2 stays
    within 1 mm of the reference over 10 s after a wind-direction step."""
    base = build_simulator("tethered_wing")
    wind = base.assembly.wind.with_modulation(1.0, 1e-3, np.ones(2), np.array([0.0, 0.1]))
    ref = with_settings(base, wind=wind, method="dp54", breakpoints="all")
    ref.advance_to(10.0, rtol=1e-10, atol=1e-10)
    sim = with_settings(base, wind=wind, method="ros34pw2", dt=0.1)
    sim.step(n_steps=100)
    assert np.max(np.linalg.norm(sim.wing_positions() - ref.wing_positions(), axis=1)) < 1e-3
    rk4 = with_settings(base, wind=wind, method="rk4", dt=0.1)
    with pytest.raises(SimulationError):
        rk4.step(n_steps=100)


def test_adaptive_method_takes_steps_beyond_rk4s_limit_at_its_tolerance():
    """ros34pw2a on the tethered wing with a direction step: the error follows the tolerance and the mean accepted
    step is several times RK4's stability limit (0.019 s)."""
    from laddermill_gym.kernels.rigid.rosenbrock import ROS34PW2
    from laddermill_gym.kernels.rigid.rosenbrock_adaptive import w_adaptive

    base = build_simulator("tethered_wing")
    wind = base.assembly.wind.with_modulation(0.0, 1.0, np.array([1.0, 1.0]), np.array([0.1, 0.1]))  # turned 0.1 rad
    ref = with_settings(base, wind=wind, method="dp54")
    ref.advance_to(10.0, rtol=1e-11, atol=1e-11)
    errs = []
    for tol in (1e-4, 1e-6):
        sim = with_settings(base, wind=wind, method="ros34pw2a", dt=0.05)
        x = sim.state.copy()
        status, acc, rej, h, t = w_adaptive(0.0, 10.0, x, sim.controls, 0.05, tol, tol, sim.model, sim.work,
                                            sim.limits, 100_000, ROS34PW2, 2)
        assert status == 0 and t == 10.0
        if tol == 1e-4:
            assert 10.0 / acc > 3 * 0.019, (acc, rej)
        sim.state[:] = x
        errs.append(np.max(np.linalg.norm(sim.wing_positions() - ref.wing_positions(), axis=1)))
    assert errs[1] < errs[0] / 10, errs
    sim = with_settings(base, method="ros34pw2a")  # through the simulator: advance_to uses the settings' method
    sim.advance_to(2.0, rtol=1e-6, atol=1e-6)
    assert sim.t == 2.0


@pytest.mark.parametrize("method, every", [("ros2", 1), ("ros1", 1), ("ros1", 4)])
def test_batch_copies_equal_single_runs_bit_for_bit(method, every):
    base = build_simulator("tethered_wing", method=method, dt=0.05, jacobian_every=every)
    settings = IntegratorSettings(method=method, dt=0.05, jacobian_every=every)
    batch = BatchSimulator(base.assembly, 2, settings)
    batch.states[:] = base.initial_state
    batch.controls[:] = base.initial_controls
    batch.controls[1, 0] += 0.01  # a different elevator on copy 1
    batch.step(40)
    for b in range(2):
        sim = with_settings(base, controls=batch.controls[b])
        sim.step(n_steps=40)
        assert np.array_equal(sim.state, batch.states[b])


def test_models_without_an_assembly_are_refused_by_name():
    from laddermill_gym.ladder.scene import load_scene

    sc = load_scene("tethered_wing", dimension=2)
    sim = with_settings(sc.simulator(), method="ros2")  # built (the statics build such simulators), not stepped
    with pytest.raises(ValueError, match="linearly implicit methods need a 3D rigid model"):
        sim.step()


def test_order_on_a_gust_with_kinks_at_the_step_ends():
    """A gust sampled every 0.1 s (a kink at the end of many steps, where the W-methods' last stage sits; such
    steps run with their own segment's line, sim/breakpoints.py): once the steps resolve the cable modes the gust
    excites, the observed orders are the methods' (measured ratios ROS2 3.9, 4.2; ROS34PW2 8.1, 8.2 from 5 ms to
    1.25 ms). At larger steps the L-stable methods damp those modes and the error falls more slowly (ROS2: 1.3 mm
    at 50 ms and 25 ms, 0.7 mm at 12.5 ms: the missing vibration)."""
    from laddermill_gym.studies.numerics.work_precision import forcing_setup

    base = build_simulator("tethered_wing")
    x0, wind = forcing_setup(base, "gust", 5.0)
    ref = with_settings(base, state=x0, wind=wind, method="dp54", breakpoints="all")
    ref.advance_to(5.0, rtol=1e-12, atol=1e-12)
    for method, ratio_min in (("ros2", 3.5), ("ros34pw2", 6.5)):
        errs = []
        for dt in (0.005, 0.0025):
            sim = with_settings(base, state=x0, wind=wind, method=method, dt=dt)
            sim.step(n_steps=int(round(5.0 / dt)))
            errs.append(np.max(np.linalg.norm(sim.wing_positions() - ref.wing_positions(), axis=1)))
        assert errs[0] / errs[1] > ratio_min, (method, errs)


def scalar_step_factor(tableau, z):
    """y1 / y0 of one transformed-form step on y' = lambda y with the exact Jacobian, z = h lambda (h = 1)."""
    gamma, _, a, c, m, _ = tableau
    U = np.zeros(m.size, dtype=complex)
    for i in range(m.size):
        U[i] = (z * (1.0 + a[i] @ U) + c[i] @ U) / (1.0 / gamma[0] - z)
    return 1.0 + m @ U


def test_ros2t_keeps_the_amplitude_of_unresolved_oscillations():
    """ROS2 at gamma = 1/4: R(z) = ((1 + z/4) / (1 - z/4))^2 (closed form), |R(iy)| = 1 on the whole imaginary axis
    and |R| < 1 in the left half-plane (A-stable); ROS34PW2 (L-stable) damps an oscillation of h omega = 4 to 0.61
    per step. The study's stability function (whip_spectrum.stability_function_w) agrees with one step of the
    transformed form on y' = lambda y."""
    from laddermill_gym.studies.numerics.whip_spectrum import stability_function_w

    y = np.array([0.1, 1.0, 4.0, 12.0, 1e4])
    zs = np.concatenate([1j * y, -0.3 + 1j * y, -y])
    closed = ((1 + zs / 4) / (1 - zs / 4)) ** 2
    step = np.array([scalar_step_factor(ROS2T, z) for z in zs])
    np.testing.assert_allclose(step, closed, rtol=1e-12)
    np.testing.assert_allclose(stability_function_w(ROS2T, zs), closed, rtol=1e-12)
    np.testing.assert_allclose(np.abs(step[: y.size]), 1.0, rtol=1e-12)
    assert np.all(np.abs(step[y.size:]) < 1.0)
    r34 = np.array([scalar_step_factor(ROS34PW2, z) for z in 1j * y])
    # at h omega = 1e4, R = 1 + z b^T (I - z B)^-1 1 is a few 1e-4 left by cancelling terms of size 1, so both ways of
    # computing it agree to a few units in the last place of 1 (4.4e-16 with OpenBLAS's Haswell kernels, 2026-12-02)
    np.testing.assert_allclose(stability_function_w(ROS34PW2, 1j * y), r34, rtol=1e-12, atol=1e-14)
    assert abs(r34[2]) < 0.62 and abs(r34[-1]) < 1e-3


def _prothero_robinson_errors(tableau, jacobian_with_time_column: bool, lam=-1.0e4):
    """Errors at t = 1 s of the transformed form on Prothero & Robinson's (1974) stiff test y' = lam (y - sin t) +
    cos t (exact solution y = sin t) at h = 50 ms halved four times. The kernels' W leaves the right-hand side's time
    derivative out (a W-method's J may); with ``jacobian_with_time_column`` the problem is autonomised (t a state)
    and J is its exact Jacobian, time column included."""
    gamma, al, a, c, m, _ = tableau
    f = lambda z: np.array([lam * (z[0] - np.sin(z[1])) + np.cos(z[1]), 1.0])  # noqa: E731
    errs = []
    for n in (20, 40, 80, 160, 320):
        h, z = 1.0 / n, np.zeros(2)
        for _ in range(n):
            J = np.array([[lam, -lam * np.cos(z[1]) - np.sin(z[1]) if jacobian_with_time_column else 0.0], [0, 0]])
            W, U = np.eye(2) / (gamma[0] * h) - J, np.zeros((m.size, 2))
            for i in range(m.size):
                U[i] = np.linalg.solve(W, f(z + a[i] @ U) + (c[i] @ U) / h)
            z = z + m @ U
        errs.append(abs(z[0] - np.sin(z[1])))
    return np.array(errs)


def test_ros2_loses_an_order_on_a_stiff_problem_whose_w_misses_a_stiff_coupling():
    """What a stiff time coupling left out of J costs (docs/numerics.md; why the mill's moving end puts its time column
    into J; not the cause on the fixed chain, whose right-hand side does not depend on time:
    tests/test_chain_pitch_modes.py): without it ROS2 converges at order 1 on Prothero & Robinson's problem (|h lam|
    500 to 31), 25 times less accurate at 50 ms than with it, where it has its order 2; ROS34PW2, built for W-matrices
    (Rang & Angermann 2005), keeps order 2 and errors below 1e-8 either way. Oracle: the closed-form solution."""
    slope = lambda e: np.log2(e[:-1] / e[1:])  # noqa: E731
    ros2_w, ros2_j = _prothero_robinson_errors(ROS2, False), _prothero_robinson_errors(ROS2, True)
    print(f"\nProthero-Robinson, lam = -1e4, h = 50 ms / 2^k: ROS2 without the coupling {ros2_w}, with it {ros2_j}")
    assert np.all(np.abs(slope(ros2_w) - 1.0) < 0.1) and ros2_w[0] > 1e-2
    assert np.all(np.abs(slope(ros2_j) - 2.0) < 0.15) and ros2_w[0] > 20 * ros2_j[0]
    for coupled in (False, True):
        e = _prothero_robinson_errors(ROS34PW2, coupled)
        assert np.all(slope(e) > 1.9) and e.max() < 1e-8
