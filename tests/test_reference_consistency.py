"""Further consistency checks of the numpy reference (laddermill_gym/reference.py): finite
differences, virtual work, energy and symmetry (split from tests/test_reference_selfchecks.py)."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym import reference as ref
from laddermill_gym.model.params import AERO_COLUMNS, AeroTable, WindParams
from tests.reference_builders import (
    G,
    make_table,
    wing_on_tether,
)


def test_alpha_rate_equals_finite_difference_along_the_motion():
    asm, x, u = wing_on_tether()
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
    asm, x, u = wing_on_tether()
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
    asm, x, u = wing_on_tether()
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
    asm, x, u = wing_on_tether(sag=True, cable_aero=True)
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
    asm, x, u = wing_on_tether()
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

    asm, x, u = wing_on_tether(sag=False, cable_aero=False)
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

    asm, x, u = wing_on_tether()
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
