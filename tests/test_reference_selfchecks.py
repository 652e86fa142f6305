"""Self-checks of the numpy reference (laddermill_gym/kernels/rigid/reference.py) against closed forms.

None of these tests touches the numba kernels: they check the oracle itself against hand-derived
results, finite differences and numpy.roots.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.rigid import reference as ref
from laddermill_gym.model.params import (
    AERO_COLUMNS,
    END_FIXED,
    END_NODE,
    END_WING,
    AeroTable,
    Assembly,
    Elements,
    WindParams,
    WingType,
)

G = 9.81


# --------------------------------------------------------------------------------------------------
# Builders
# --------------------------------------------------------------------------------------------------


def make_table(n: int = 37) -> AeroTable:
    """Smooth made-up periodic table on a uniform grid from -pi to pi."""
    a = np.linspace(-np.pi, np.pi, n)
    cols = {
        "CL": 2 * np.pi * np.sin(a) * np.cos(a),
        "CD": 0.05 + 1.2 * np.sin(a) ** 2,
        "Cm": -0.1 * np.sin(a),
    }
    small = {
        "CLq": 5.0, "CLad": 2.0, "CLde": 0.4,
        "Cmq": -8.0, "Cmad": -3.0, "Cmde": -1.1,
        "CYb": -0.3, "CYp": 0.05, "CYr": 0.2, "CYdr": 0.15,
        "Clb": -0.08, "Clp": -0.45, "Clr": 0.1, "Clda": 0.2, "Cldr": 0.01,
        "Cnb": 0.06, "Cnp": -0.03, "Cnr": -0.1, "Cnda": -0.01, "Cndr": -0.07,
    }
    values = np.zeros((n, len(AERO_COLUMNS)))
    for i, name in enumerate(AERO_COLUMNS):
        values[:, i] = cols[name] if name in cols else small[name] * np.cos(a)
    values[-1] = values[0]  # exactly periodic
    return AeroTable(alpha=a, values=values, source="made-up")


def make_wing_type(attachment=(0.1, 0.0, 0.2)) -> WingType:
    return WingType(
        name="test",
        mass=12.0,
        inertia=(30.0, 4.0, 33.0, 1.5),
        area=10.0,
        span=8.0,
        chord=1.25,
        r_ref=np.array([0.2, 0.0, -0.05]),
        attachment=np.array(attachment, dtype=float),
        control_limits=np.array([[-0.3, 0.3]] * 3),
        aero=make_table(),
    )


def make_elements(ends, l0, mu=0.05, EA=2.0e5, DA=50.0, diameter=0.004, attach=None) -> Elements:
    """``ends``: list of ((kind_r, index_r), (kind_s, index_s)); scalars broadcast."""
    n = len(ends)
    kind = np.array([[r[0], s[0]] for r, s in ends], dtype=np.int64).reshape(n, 2)
    index = np.array([[r[1], s[1]] for r, s in ends], dtype=np.int64).reshape(n, 2)
    att = np.zeros((n, 2, 3)) if attach is None else np.asarray(attach, dtype=float).reshape(n, 2, 3)

    def arr(v):
        return np.broadcast_to(np.asarray(v, dtype=float), (n,)).copy()

    return Elements(
        end_kind=kind, end_index=index, attach=att, l0=arr(l0), mu=arr(mu), EA=arr(EA), DA=arr(DA),
        diameter=arr(diameter),
    )


def make_assembly(
    n_wings=0, node_mass=(), fixed_points=None, elements=None, wind=None, sag=True,
    cable_aero=True, gravity=G,
) -> Assembly:
    wt = make_wing_type()
    return Assembly(
        dim=3,
        gravity=gravity,
        wind=WindParams() if wind is None else wind,
        wing_types=(wt,),
        wing_type_index=np.zeros(n_wings, dtype=np.int64),
        node_mass=np.asarray(node_mass, dtype=float),
        fixed_points=np.asarray(() if fixed_points is None else fixed_points, dtype=float).reshape(-1, 3),
        elements=make_elements([], []) if elements is None else elements,
        sag=sag,
        cable_aero=cable_aero,
    )


def random_quaternion(rng) -> np.ndarray:
    q = rng.normal(size=4)
    return 1.7 * q / np.linalg.norm(q)  # deliberately not unit


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


# --------------------------------------------------------------------------------------------------
# Further consistency checks
# --------------------------------------------------------------------------------------------------


def _wing_on_tether(sag=True, cable_aero=True):
    """Wing 0 tethered to a fixed ground point through a free node (two elements)."""
    wind = WindParams(v0=8.0, h0=50.0, v1=0.0016, direction_inf=0.3, direction_height=400.0).with_modulation(
        0.0, 1.0, np.array([1.0, 1.2, 0.9]), np.array([0.0, 0.1, -0.1]))
    wt = make_wing_type()
    el = make_elements([((END_FIXED, 0), (END_NODE, 0)), ((END_NODE, 0), (END_WING, 0))], l0=[50.0, 50.5],
                       attach=[[[0, 0, 0], [0, 0, 0]], [[0, 0, 0], list(wt.attachment)]])
    asm = make_assembly(n_wings=1, node_mass=[0.2], fixed_points=[[0.0, 0.0, 0.0]], elements=el, wind=wind,
                        sag=sag, cable_aero=cable_aero)
    rng = np.random.default_rng(7)
    q = np.array([0.95, 0.05, -0.2, 0.1]) * 1.01
    x = np.concatenate([[-60.0, 5.0, -75.0], q, [18.0, 0.5, 2.0], [0.2, -0.1, 0.15],
                        [-30.0, 2.0, -40.0], rng.normal(size=3)])
    u = np.array([0.05, -0.03, 0.02])
    return asm, x, u


def test_alpha_rate_equals_finite_difference_along_the_motion():
    asm, x, u = _wing_on_tether()
    t = 0.3

    def alpha_at(tt, xx):
        R = ref.rotation(xx[3:7])
        va = xx[7:10] - R.T @ ref.wind_velocity(asm.wind, xx[0:3], tt)
        return np.arctan2(va[2], va[0])

    dx = ref.reference_rhs(t, x, u, asm)
    R = ref.rotation(x[3:7])
    _, _, _, g, adot0 = ref.wing_aero(asm.wing(0), x[0:3], R, x[7:10], x[10:13], u, asm.wind, t)
    h = 1e-6
    fd = (alpha_at(t + h, x + h * dx) - alpha_at(t - h, x - h * dx)) / (2 * h)
    assert g @ dx[7:10] + adot0 == pytest.approx(fd, rel=1e-6, abs=1e-8)


def test_attachment_acceleration_equals_T_vdot_plus_quadratic_term():
    asm, x, u = _wing_on_tether()
    t = 0.3
    dx = ref.reference_rhs(t, x, u, asm)
    M, F = ref.mass_matrix_and_forces(asm, t, x, u)
    accel = np.linalg.solve(M, F)
    e, end = 1, 1  # the wing end
    T = ref.end_transformation(asm, e, end, x)
    wt = asm.wing(0)
    R = ref.rotation(x[3:7])
    v, w = x[7:10], x[10:13]
    a = wt.attachment
    quad = R @ np.cross(w, v + np.cross(w, a))
    h = 1e-6
    fd = (ref.element_state(asm, e, x + h * dx).xd_s - ref.element_state(asm, e, x - h * dx).xd_s) / (2 * h)
    np.testing.assert_allclose(T @ accel + quad, fd, rtol=1e-6, atol=1e-6)
    # and T maps the generalised velocities to the attachment velocity
    gen_vel = np.concatenate([v, w, x[16:19]])
    np.testing.assert_allclose(T @ gen_vel, ref.element_state(asm, e, x).xd_s, rtol=1e-13)


def test_mass_matrix_symmetric_positive_definite_without_alpha_rate_term():
    asm, x, u = _wing_on_tether()
    import dataclasses

    vac = dataclasses.replace(asm, wind=dataclasses.replace(asm.wind, rho0=0.0))
    M, _ = ref.mass_matrix_and_forces(vac, 0.0, x, u)
    np.testing.assert_allclose(M, M.T, atol=1e-12)
    assert np.all(np.linalg.eigvalsh(M) > 0)
    # with air the only asymmetry is -k g^T in the wing's v columns
    M_air, _ = ref.mass_matrix_and_forces(asm, 0.0, x, u)
    R = ref.rotation(x[3:7])
    _, _, k, g, _ = ref.wing_aero(asm.wing(0), x[0:3], R, x[7:10], x[10:13], u, asm.wind, 0.0)
    diff = M - M_air
    expected = np.zeros_like(M)
    expected[0:6, 0:3] = np.outer(k, g)
    np.testing.assert_allclose(diff, expected, atol=1e-12)


def test_element_loads_do_no_virtual_work_mismatch():
    """The generalised element forces equal T^T of the global end forces: check by virtual power."""
    asm, x, u = _wing_on_tether(sag=True, cable_aero=True)
    t = 0.3
    rng = np.random.default_rng(11)
    gen_vel = rng.normal(size=9)
    # virtual power of the tension of element 1 computed with global end velocities
    st = ref.element_state(asm, 1, x)
    sigma = ref.tension(asm, 1, x, t)
    T_r, T_s = (ref.end_transformation(asm, 1, k, x) for k in (0, 1))
    power_global = sigma * st.e @ (T_r @ gen_vel) - sigma * st.e @ (T_s @ gen_vel)
    power_gen = (sigma * T_r.T @ st.e - sigma * T_s.T @ st.e) @ gen_vel
    assert power_gen == pytest.approx(power_global, rel=1e-13)
    # a wing end: R^T F and a x R^T F
    wt = asm.wing(0)
    R = ref.rotation(x[3:7])
    Fg = np.array([1.0, -2.0, 3.0])
    gen = T_s.T @ Fg
    np.testing.assert_allclose(gen[0:3], R.T @ Fg, rtol=1e-14)
    np.testing.assert_allclose(gen[3:6], np.cross(wt.attachment, R.T @ Fg), rtol=1e-13, atol=1e-14)


def test_wing_aero_with_zero_airspeed_and_controls_sign():
    asm, x, u = _wing_on_tether()
    wt = asm.wing(0)
    R = ref.rotation(x[3:7])
    v_still = R.T @ ref.wind_velocity(asm.wind, x[0:3], 0.3)
    out = ref.wing_aero(wt, x[0:3], R, v_still, np.zeros(3), u, asm.wind, 0.3)
    for part in out[:4]:
        np.testing.assert_array_equal(part, 0.0)
    assert out[4] == 0.0
    # level flight, no wind: X, Z from CL, CD by hand at alpha = atan2(w, u)
    calm = WindParams(v0=0.0, v1=0.0)
    v = np.array([20.0, 0.0, 2.0])
    force, moment, k, g, adot0 = ref.wing_aero(wt, np.array([0, 0, -100.0]), np.eye(3), v, np.zeros(3),
                                               np.zeros(3), calm, 0.0)
    alpha = np.arctan2(2.0, 20.0)
    C = ref.aero_coefficients(wt.aero, alpha)
    qS = 0.5 * 1.225 * np.exp(-100 / 8400) * (v @ v) * wt.area
    X = qS * (C["CL"] * np.sin(alpha) - C["CD"] * np.cos(alpha))
    Z = qS * (-C["CL"] * np.cos(alpha) - C["CD"] * np.sin(alpha))
    np.testing.assert_allclose(force, [X, 0.0, Z], rtol=1e-13, atol=1e-12)
    M_ref = np.array([0.0, qS * wt.chord * C["Cm"], 0.0])
    np.testing.assert_allclose(moment, M_ref + np.cross(wt.r_ref, force), rtol=1e-13, atol=1e-12)
    np.testing.assert_allclose(g, np.array([-2.0, 0.0, 20.0]) / 404.0, rtol=1e-14)
    assert adot0 == 0.0


def test_aero_coefficients_reproduce_table_nodes_and_wrap():
    table = make_table()
    for i in [0, 5, 18, 30]:
        C = ref.aero_coefficients(table, table.alpha[i])
        np.testing.assert_allclose([C[n] for n in AERO_COLUMNS], table.values[i], rtol=1e-12, atol=1e-14)
    a = 0.3
    C1, C2 = ref.aero_coefficients(table, a), ref.aero_coefficients(table, a + 2 * np.pi)
    assert all(C1[n] == pytest.approx(C2[n], rel=1e-12, abs=1e-14) for n in AERO_COLUMNS)


def test_energy_is_conserved_without_damping_air_and_sag():
    """d/dt (kinetic + elastic + gravitational energy) = 0: checks T^T M0e T against the (M15) terms."""
    import dataclasses

    asm, x, u = _wing_on_tether(sag=False, cable_aero=False)
    el = dataclasses.replace(asm.elements, DA=np.zeros(2), l0=np.array([45.0, 40.0]))  # both stretched
    asm = dataclasses.replace(asm, elements=el, wind=dataclasses.replace(asm.wind, rho0=0.0))
    x = x.copy()
    x[10:13] = [0.8, -0.6, 1.1]  # fast rotation so that the eccentric terms matter

    def energy(xx):
        M, _ = ref.mass_matrix_and_forces(asm, 0.0, xx, u)
        gen_vel = np.concatenate([xx[7:13], xx[16:19]])
        kinetic = 0.5 * gen_vel @ M @ gen_vel
        wt = asm.wing(0)
        potential = -G * (wt.mass * xx[2] + asm.node_mass[0] * xx[15])
        for e in range(el.count):
            st = ref.element_state(asm, e, xx)
            assert st.eps > 0
            potential += 0.5 * el.EA[e] * st.eps**2 / el.l0[e]
            potential -= G * el.mu[e] * el.l0[e] / 2 * (st.x_r[2] + st.x_s[2])
        return kinetic + potential

    dx = ref.reference_rhs(0.0, x, u, asm)
    h = 1e-5
    rate = (energy(x + h * dx) - energy(x - h * dx)) / (2 * h)
    # compare with a typical power scale: tension times a velocity
    scale = np.max(np.abs(ref.element_tensions(asm, 0.0, x))) * np.linalg.norm(x[7:10])
    assert abs(rate) < 1e-7 * scale


def test_alpha_rate_load_equals_k_times_finite_difference_alpha_rate():
    """M0 v' = F0 + k alpha' where M0, F0 are computed with CLad = Cmad = 0 and alpha' by finite differences."""
    import dataclasses

    asm, x, u = _wing_on_tether()
    t = 0.3
    wt = asm.wing(0)
    values = wt.aero.values.copy()
    for name in ("CLad", "Cmad"):
        values[:, AERO_COLUMNS.index(name)] = 0.0
    wt0 = dataclasses.replace(wt, aero=AeroTable(alpha=wt.aero.alpha, values=values))
    asm0 = dataclasses.replace(asm, wing_types=(wt0,))

    dx = ref.reference_rhs(t, x, u, asm)
    accel = np.concatenate([dx[7:13], dx[16:19]])
    M0, F0 = ref.mass_matrix_and_forces(asm0, t, x, u)
    R = ref.rotation(x[3:7])
    _, _, k, _, _ = ref.wing_aero(wt, x[0:3], R, x[7:10], x[10:13], u, asm.wind, t)
    assert np.linalg.norm(k) > 0

    def alpha_at(tt, xx):
        Rr = ref.rotation(xx[3:7])
        va = xx[7:10] - Rr.T @ ref.wind_velocity(asm.wind, xx[0:3], tt)
        return np.arctan2(va[2], va[0])

    h = 1e-6
    alpha_dot = (alpha_at(t + h, x + h * dx) - alpha_at(t - h, x - h * dx)) / (2 * h)
    lhs = M0 @ accel
    rhs = F0.copy()
    rhs[0:6] += k * alpha_dot
    np.testing.assert_allclose(lhs, rhs, rtol=1e-6, atol=1e-6 * np.max(np.abs(F0)))
