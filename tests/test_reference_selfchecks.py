"""Self-checks of the numpy reference (laddermill_gym/reference.py) against closed forms.

None of these tests touches the numba kernels: they check the oracle itself against hand-derived
results, finite differences and numpy.roots.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym import reference as ref
from laddermill_gym.model.params import (
    END_FIXED,
    END_NODE,
    WindParams,
)
from tests.reference_builders import G, make_assembly, make_elements, random_quaternion

# --------------------------------------------------------------------------------------------------
# Rotations
# --------------------------------------------------------------------------------------------------


def test_rotation_and_euler_roundtrip():
    phi, theta, psi = 0.3, -0.4, 2.5
    c, s = np.cos, np.sin
    Rx = np.array([[1, 0, 0], [0, c(phi), -s(phi)], [0, s(phi), c(phi)]])
    Ry = np.array([[c(theta), 0, s(theta)], [0, 1, 0], [-s(theta), 0, c(theta)]])
    Rz = np.array([[c(psi), -s(psi), 0], [s(psi), c(psi), 0], [0, 0, 1]])
    R = Rz @ Ry @ Rx
    assert np.allclose(ref.euler_321(R), (phi, theta, psi), atol=1e-14)
    # quaternion of the same rotation: product of the three elementary quaternions
    qz = np.array([c(psi / 2), 0, 0, s(psi / 2)])
    qy = np.array([c(theta / 2), 0, s(theta / 2), 0])
    qx = np.array([c(phi / 2), s(phi / 2), 0, 0])
    q = ref.quaternion_product(ref.quaternion_product(qz, qy), qx)
    assert np.allclose(ref.rotation(3.0 * q), R, atol=1e-14)


# --------------------------------------------------------------------------------------------------
# (a) a single free wing in vacuum
# --------------------------------------------------------------------------------------------------


def test_free_wing_in_vacuum_is_rigid_body_under_gravity():
    rng = np.random.default_rng(1)
    asm = make_assembly(n_wings=1, wind=WindParams(rho0=0.0))
    wt = asm.wing(0)
    q = random_quaternion(rng)
    v = np.array([20.0, -1.0, 3.0])
    w = np.array([0.3, -0.2, 0.5])
    x = np.concatenate([[1.0, 2.0, -100.0], q, v, w])
    u = np.array([0.1, -0.05, 0.02])
    dx = ref.reference_rhs(0.5, x, u, asm)

    qn = q / np.linalg.norm(q)
    R = ref.rotation(q)
    Jxx, Jyy, Jzz, Jxz = wt.inertia
    J = np.array([[Jxx, 0, -Jxz], [0, Jyy, 0], [-Jxz, 0, Jzz]])
    assert np.allclose(R.T @ R, np.eye(3), atol=1e-14)
    # R^T (0, 0, g) is the third row of R
    assert np.allclose(R.T @ [0, 0, G], G * R[2], atol=1e-14)
    v_dot = -np.cross(w, v) + R.T @ np.array([0.0, 0.0, G])
    w_dot = np.linalg.solve(J, -np.cross(w, J @ w))
    q0, q1, q2, q3 = q
    p, qq, r = w
    q_dot = 0.5 * np.array([
        -q1 * p - q2 * qq - q3 * r,
        q0 * p + q2 * r - q3 * qq,
        q0 * qq + q3 * p - q1 * r,
        q0 * r + q1 * qq - q2 * p,
    ])
    np.testing.assert_allclose(dx[0:3], R @ v, rtol=1e-13, atol=1e-12)
    np.testing.assert_allclose(dx[3:7], q_dot, rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(dx[7:10], v_dot, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(dx[10:13], w_dot, rtol=1e-12, atol=1e-14)
    assert np.isclose(np.linalg.norm(qn), 1.0)


def test_dim_other_than_3_is_rejected():
    import dataclasses

    asm = dataclasses.replace(make_assembly(n_wings=1), dim=2)
    with pytest.raises(ValueError, match="dim"):
        ref.reference_rhs(0.0, np.zeros(6), np.zeros(3), asm)


# --------------------------------------------------------------------------------------------------
# (b) two fixed points, one free node, two elements, sag and aero off
# --------------------------------------------------------------------------------------------------


def _v_truss(node_pos, node_vel, node_mass, l0=10.0, mu=0.05, EA=2.0e5, DA=50.0):
    fixed = np.array([[-8.0, 0.0, 0.0], [8.0, 0.0, 0.0]])
    el = make_elements([((END_FIXED, 0), (END_NODE, 0)), ((END_NODE, 0), (END_FIXED, 1))], l0=l0, mu=mu,
                       EA=EA, DA=DA)
    asm = make_assembly(node_mass=[node_mass], fixed_points=fixed, elements=el, sag=False, cable_aero=False)
    x = np.concatenate([node_pos, node_vel])
    return asm, x, fixed


def test_v_truss_force_balance_by_hand():
    node_pos = np.array([0.5, 0.3, 6.9])  # below the fixed points (z down), both elements stretched
    node_vel = np.array([0.2, -0.1, 0.4])
    l0, mu, EA, DA, m_node = 10.0, 0.05, 2.0e5, 50.0, 3.0
    asm, x, fixed = _v_truss(node_pos, node_vel, m_node, l0, mu, EA, DA)
    M, F = ref.mass_matrix_and_forces(asm, 0.0, x, np.zeros(0))

    m_e = mu * l0
    M_hand = (m_node + 2 * (2 * m_e / 6)) * np.eye(3)
    # element 0: r = fixed 0, s = node -> node pulled towards fixed 0
    F_hand = np.array([0.0, 0.0, (m_node + m_e) * G])  # node weight + half of each element
    for p in fixed:
        d = p - node_pos
        length = np.linalg.norm(d)
        unit = d / length
        eps = length - l0
        eps_dot = unit @ (0 - node_vel)
        sigma = (EA * eps + DA * eps_dot) / l0
        assert sigma > 0
        F_hand += sigma * unit
    np.testing.assert_allclose(M, M_hand, rtol=1e-14)
    np.testing.assert_allclose(F, F_hand, rtol=1e-12)
    dx = ref.reference_rhs(0.0, x, np.zeros(0), asm)
    np.testing.assert_allclose(dx[:3], node_vel)
    np.testing.assert_allclose(dx[3:], F_hand / M_hand[0, 0], rtol=1e-12)


def test_v_truss_static_equilibrium_has_zero_acceleration():
    l0, mu, EA = 10.0, 0.05, 2.0e5
    z = 6.5
    node_pos = np.array([0.0, 0.0, z])
    length = np.hypot(8.0, z)
    sigma = EA * (length - l0) / l0
    # vertical balance: 2 sigma z/length = (m_node + m_e) g
    m_node = 2 * sigma * z / length / G - mu * l0
    assert m_node > 0
    asm, x, _ = _v_truss(node_pos, np.zeros(3), m_node, l0, mu, EA)
    dx = ref.reference_rhs(0.0, x, np.zeros(0), asm)
    np.testing.assert_allclose(dx, 0.0, atol=1e-10)


def test_slack_element_without_sag_has_no_tension():
    asm, x, _ = _v_truss(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -5.0]), 1.0, l0=10.0)
    np.testing.assert_array_equal(ref.element_tensions(asm, 0.0, x), [0.0, 0.0])


# --------------------------------------------------------------------------------------------------
# (c) the sag Newton root
# --------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("sigma0", [-500.0, -1.0, 0.0, 3.0, 250.0, 4.0e4])
@pytest.mark.parametrize("eps_p", [1e-8, 1e-2, 10.0, 1e5])
def test_sag_newton_root_matches_cubic(sigma0, eps_p):
    EA, l0 = 2.0e5, 10.0
    c = EA * eps_p / l0
    s = ref.sag_tension(sigma0, EA, l0, eps_p, length=10.0)
    assert s > 0
    # residual of the cubic, relative to the size of its terms
    scale = max(s**3, abs(sigma0) * s**2, c)
    assert abs(s**3 - sigma0 * s**2 - c) <= 1e-12 * scale
    roots = np.roots([1.0, -sigma0, 0.0, -c])
    positive = [r.real for r in roots if abs(r.imag) <= 1e-9 * abs(r) and r.real > 0]
    assert len(positive) == 1
    assert s == pytest.approx(positive[0], rel=1e-9)


def test_sag_degenerate_cases():
    assert ref.sag_tension(12.0, 1e5, 1.0, 0.0, 1.0) == 12.0
    assert ref.sag_tension(-12.0, 1e5, 1.0, 0.0, 1.0) == 0.0
    assert ref.sag_tension(-12.0, 1e5, 1.0, 1.0, 1e-10) == 0.0


def test_sag_elongation_matches_integral_of_deflection_slope():
    rng = np.random.default_rng(3)
    length = 7.0
    p_r, p_s = rng.normal(size=3), rng.normal(size=3)
    # sigma * slope of the deflection (M17) integrated numerically: int 1/2 |sigma v'|^2 l dxi
    xi = np.linspace(0.0, 1.0, 20001)
    slope = (np.outer(1 / 3 - xi + xi**2 / 2, p_r) + np.outer(1 / 6 - xi**2 / 2, p_s)) * length
    integrand = 0.5 * np.sum(slope**2, axis=1) * length
    integral = np.sum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(xi))
    assert ref.sag_elongation(length, p_r, p_s) == pytest.approx(integral, rel=1e-7)


def test_tension_with_sag_uses_lateral_gravity_load():
    # single horizontal element between two fixed points, no wind: lateral load = mu g at both ends
    l0, mu, EA, DA = 10.0, 0.05, 2.0e5, 50.0
    el = make_elements([((END_FIXED, 0), (END_FIXED, 1))], l0=l0, mu=mu, EA=EA, DA=DA)
    fixed = np.array([[0.0, 0.0, -50.0], [10.001, 0.0, -50.0]])
    asm = make_assembly(fixed_points=fixed, elements=el, sag=True, cable_aero=False)
    sigma = ref.element_tensions(asm, 0.0, np.zeros(0))[0]
    length = 10.001
    p = mu * G
    eps_p = length**3 * (2 * p**2 / 90 + 7 / 360 * p**2)
    sigma0 = EA * (length - l0) / l0
    assert sigma**3 - sigma0 * sigma**2 == pytest.approx(EA * eps_p / l0, rel=1e-11)
    assert sigma > sigma0


# --------------------------------------------------------------------------------------------------
# (d) cable aerodynamics
# --------------------------------------------------------------------------------------------------


def test_cable_aero_load_perpendicular_and_parallel():
    rho, d, cn0, ct0 = 1.1, 0.004, 1.1, 0.02
    u = np.array([-9.0, 0.0, 0.0])
    qd = 0.5 * rho * 81.0 * d
    perpendicular = ref.cable_aero_load(rho, d, cn0, ct0, u, np.array([0.0, 1.0, 0.0]))
    np.testing.assert_allclose(perpendicular, (cn0 + ct0) * qd * u / 9.0, rtol=1e-14)
    parallel = ref.cable_aero_load(rho, d, cn0, ct0, u, np.array([1.0, 0.0, 0.0]))
    np.testing.assert_allclose(parallel, ct0 * qd * u / 9.0, rtol=1e-14, atol=1e-18)
    # general angle a_c: drag C_N0 sin^3 + C_T0 along u, lift C_N0 sin^2 cos perpendicular to u
    a_c = 0.7
    e = np.array([np.cos(a_c), np.sin(a_c), 0.0])
    f = ref.cable_aero_load(rho, d, cn0, ct0, u, e)
    u_hat = u / 9.0
    drag = f @ u_hat
    lift = np.linalg.norm(f - drag * u_hat)
    assert drag == pytest.approx(qd * (cn0 * np.sin(a_c) ** 3 + ct0), rel=1e-13)
    assert lift == pytest.approx(qd * cn0 * np.sin(a_c) ** 2 * np.cos(a_c), rel=1e-13)


def test_cable_aero_nodal_force_through_assembly():
    # fixed point and free node at the same height, element along y (perpendicular to the north wind),
    # unstretched, sag off, zero gravity, node at rest: node force = l f / 2 with f the same at both ends
    h = 120.0
    wind = WindParams(v0=8.0, h0=50.0, v1=0.01, rho0=1.2)
    el = make_elements([((END_FIXED, 0), (END_NODE, 0))], l0=10.0, mu=0.05, diameter=0.005)
    asm = make_assembly(node_mass=[1.0], fixed_points=[[0.0, 0.0, -h]], elements=el, wind=wind, sag=False,
                        cable_aero=True, gravity=0.0)
    x = np.array([0.0, 10.0, -h, 0.0, 0.0, 0.0])
    M, F = ref.mass_matrix_and_forces(asm, 0.0, x, np.zeros(0))
    V = 8.0 + 0.01 * (h - 50.0)
    rho = 1.2 * np.exp(-h / 8400.0)
    f = 0.5 * rho * 0.005 * (1.1 + 0.02) * V**2 * np.array([-1.0, 0.0, 0.0])
    np.testing.assert_allclose(F, 10.0 * f / 2, rtol=1e-13)
    np.testing.assert_allclose(M, (1.0 + 2 * 0.5 / 6) * np.eye(3), rtol=1e-14)


# --------------------------------------------------------------------------------------------------
# (e) wind profile and density
# --------------------------------------------------------------------------------------------------


def test_wind_profile_against_hand_values():
    wind = WindParams(v0=8.0, h0=50.0, v1=0.0016, exponent=0.2, direction_inf=0.4, direction_height=500.0)
    for h, V in [(-3.0, 0.0), (0.0, 0.0), (10.0, 8.0 * 0.2**0.2), (50.0, 8.0), (450.0, 8.0 + 0.0016 * 400.0)]:
        phi = 0.4 * (1 - np.exp(-h / 500.0))
        w = ref.wind_velocity(wind, np.array([3.0, 4.0, -h]), 0.0)
        np.testing.assert_allclose(w, -V * np.array([np.cos(phi), np.sin(phi), 0.0]), rtol=1e-14, atol=1e-15)
    assert ref.air_density(wind, 1000.0) == pytest.approx(1.225 * np.exp(-1000.0 / 8400.0), rel=1e-15)
    import dataclasses

    isa = dataclasses.replace(wind, density_model="isa")
    assert ref.air_density(isa, 1000.0) == pytest.approx(1.225 * (1 - 2.2558e-2) ** 4.2559, rel=1e-15)


def test_wind_modulation_interpolation_and_hold():
    wind = WindParams(v0=8.0, h0=50.0).with_modulation(2.0, 0.5, np.array([1.0, 1.2, 0.8]), np.array([0.0, 0.1, -0.2]))
    p = np.array([0.0, 0.0, -50.0])  # V_w = 8 exactly, direction 0
    cases = [(0.0, 1.0, 0.0), (2.0, 1.0, 0.0), (2.25, 1.1, 0.05), (2.5, 1.2, 0.1), (2.75, 1.0, -0.05),
             (3.0, 0.8, -0.2), (9.0, 0.8, -0.2)]
    for t, s, delta in cases:
        w = ref.wind_velocity(wind, p, t)
        np.testing.assert_allclose(w, -8.0 * s * np.array([np.cos(delta), np.sin(delta), 0.0]), rtol=1e-13, atol=1e-15)
    # slopes: interval [k, k+1) containing t, 0 outside the grid
    for t, ds, dd in [(1.0, 0.0, 0.0), (2.0, 0.4, 0.2), (2.3, 0.4, 0.2), (2.5, -0.8, -0.6), (3.0, 0.0, 0.0)]:
        _, ds_dt, _, dd_dt = ref.wind_modulation(wind, t)
        assert (ds_dt, dd_dt) == pytest.approx((ds, dd), rel=1e-13, abs=1e-15)


def test_wind_rate_matches_finite_difference():
    wind = WindParams(v0=8.0, h0=50.0, v1=0.01, direction_inf=0.5, direction_height=300.0).with_modulation(
        0.0, 1.0, np.array([1.0, 1.3, 0.9]), np.array([0.0, 0.2, 0.1]))
    for z in [-30.0, -120.0]:  # inside and above the boundary layer
        p = np.array([1.0, 2.0, z])
        vel = np.array([3.0, -1.0, -4.0])
        t, h = 0.4, 1e-6
        fd = (ref.wind_velocity(wind, p + h * vel, t + h) - ref.wind_velocity(wind, p - h * vel, t - h)) / (2 * h)
        np.testing.assert_allclose(ref.wind_rate(wind, p, vel, t), fd, rtol=1e-7, atol=1e-9)
