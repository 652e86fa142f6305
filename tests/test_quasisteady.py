"""Quasi-steady pumping power (Lansdorp et al. 2008 eqs. 1-15; Schmehl et al. 2013 / van der Vlugt et al. 2019)
against independent answers: the check values and closed forms of ../shared/design/oracles.md (Loyd 1980, the
massless zeta_max), the optimum reeling factor found by a scalar optimiser, a force balance solved by fsolve, and
the limits of eqs. 7 and 12-14."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import fsolve, minimize_scalar

from laddermill_gym.quasisteady import lansdorp, schmehl
from laddermill_gym.quasisteady.lansdorp import PumpingParams

RHO = 1.225


def test_glide_ratio_and_tension_check_values():
    # oracles.md: rho 1.225, C_L 1.0, C_D 0.1, S 100, d 0.03, L 1000, C_Dc 1.2, w 10 m/s
    G = lansdorp.glide_ratio(1.0, 0.1, 0.03, 1000.0, 100.0, 1.2)
    assert G == pytest.approx(5.263158, rel=1e-6)
    assert lansdorp.tension(RHO, 1.0, 100.0, G, 10.0) == pytest.approx(178937.5, rel=1e-6)
    cd_total = 0.1 + lansdorp.cable_drag_share(0.03, 1000.0, 100.0, 1.2)
    assert lansdorp.tension_from_coefficients(RHO, 1.0, cd_total, 100.0, 10.0) == pytest.approx(178937.5, rel=1e-6)


def test_cable_length_enters_through_eq7():
    h, theta = 600.0, np.radians(60.0)
    r = lansdorp.cycle_power(np.array([10.0]), h, theta, 0.03, 100.0, 1.0, 0.1, reel_out_factor=0.0)
    L = 1200.0  # = 600 / cos 60 deg
    G = 1.0 / (0.1 + 0.03 * L * 1.2 / 400.0)
    w_e = 10.0 * np.sin(theta)
    expected = 0.5 * RHO * 1.0 * 100.0 * G**2 * (1 + 1 / G**2) ** 1.5 * w_e**2
    assert r.tension_out[0] == pytest.approx(expected, rel=1e-12)


def test_loyd_crosswind_optimum():
    # Loyd (1980): P = (2/27) rho A V^3 C_L (C_L/C_D)^2 at reel-out speed V/3, for a large glide ratio
    S, cl, cd, V = 10.0, 1.0, 0.01, 10.0
    loyd = 2.0 / 27.0 * RHO * S * V**3 * cl * (cl / cd) ** 2
    r = lansdorp.cycle_power(np.array([V]), 0.0, np.pi / 2, 0.0, S, cl, cd)
    assert r.power_out[0] == pytest.approx(loyd, rel=3e-4)  # (1 + 1/E^2)^(3/2) = 1.00015


def test_zeta_max_closed_form_check_values():
    # oracles.md: S 10, C_L 1, C_D 0.2, V 10: Loyd 22.69 kW, zeta_max form 24.06 kW, at beta = 30 deg 15.63 kW
    S, cl, cd, V = 10.0, 1.0, 0.2, 10.0
    assert 2 / 27 * RHO * S * V**3 * cl * (cl / cd) ** 2 == pytest.approx(22.69e3, abs=5.0)  # quoted to 10 W
    r = lansdorp.cycle_power(np.array([V]), 0.0, np.pi / 2, 0.0, S, cl, cd)
    assert r.power_out[0] == pytest.approx(24.06e3, abs=5.0)
    theta = np.radians(60.0)  # elevation 30 deg; reel out at a third of the wind along the cable
    r30 = lansdorp.cycle_power(np.array([V]), 100.0, theta, 0.0, S, cl, cd, reel_out_rule="radial")
    assert r30.power_out[0] == pytest.approx(15.63e3, abs=5.0)


@pytest.mark.parametrize("beta_deg, phi_deg", [(30.0, 0.0), (25.0, 20.0), (45.0, 35.0)])
def test_optimal_reeling_factor_found_numerically(beta_deg, phi_deg):
    # massless Schmehl model, horizontal crosswind course: the optimum f = cos(b) cos(p) / 3 (oracles.md)
    beta, phi = np.radians(beta_deg), np.radians(phi_deg)
    S, cl, cd, V = 10.0, 1.0, 0.2, 10.0

    def minus_power(f):
        F, _ = schmehl.traction(np.array([V]), beta, f, S, cl, cd, 0.0, RHO, phi, np.pi / 2)
        return -F[0] * f * V

    res = minimize_scalar(minus_power, bounds=(0.0, 1.0), method="bounded", options={"xatol": 1e-9})
    c = np.cos(beta) * np.cos(phi)
    assert res.x == pytest.approx(c / 3.0, abs=1e-6)
    zeta_max = 4 / 27 * np.hypot(cl, cd) * (1 + (cl / cd) ** 2) * c**3
    assert -res.fun == pytest.approx(zeta_max * 0.5 * RHO * S * V**3, rel=1e-9)


def test_schmehl_with_mass_matches_a_force_balance():
    # climbing course (chi = 0, phi = 0): gravity lies in the plane of e_r and e_beta, and the force balance of
    # tether force, weight, lift and drag can be solved directly for the kite speed and the tether force
    V, beta, f, S, cl, cd, m = 9.0, np.radians(35.0), 0.25, 20.0, 1.0, 0.125, 60.0
    g = schmehl.GRAVITY
    wr, wb = V * np.cos(beta), -V * np.sin(beta)          # wind along e_r and e_beta

    def balance(x):
        v_tau, F_t = x
        ar, ab = wr - f * V, wb - v_tau                    # apparent wind
        va = np.hypot(ar, ab)
        q = 0.5 * RHO * S * va
        lift = q * cl * np.array([-ab, ar])                # perpendicular to v_a, towards higher elevation
        drag = q * cd * np.array([ar, ab])
        weight = -m * g * np.array([np.sin(beta), np.cos(beta)])
        total = lift + drag + weight + np.array([-F_t, 0.0])
        return total

    v_tau, F_t = fsolve(balance, [40.0, 5000.0], xtol=1e-12)
    F, lam = schmehl.traction(np.array([V]), beta, f, S, cl, cd, m, RHO, 0.0, 0.0)
    assert F[0] == pytest.approx(F_t, rel=1e-7)
    assert lam[0] * V == pytest.approx(v_tau, rel=1e-7)


def test_retraction_holds_the_elevation():
    qs = schmehl.SchmehlParams()
    V, beta, v_in, S, m = np.array([6.0, 12.0]), np.radians(60.0), 16.7, 100.0, 80.0
    F, cl, _ = schmehl.retraction(V, beta, v_in, S, 0.01, m, RHO, qs)
    ar, ab = V * np.cos(beta) + v_in, -V * np.sin(beta)
    va = np.hypot(ar, ab)
    q = 0.5 * RHO * S * va
    cd = qs.cd0 + qs.cd2 * cl**2 + 0.01
    across = q * (cl * ar + cd * ab) - m * schmehl.GRAVITY * np.cos(beta)
    radial = q * (-cl * ab + cd * ar) - m * schmehl.GRAVITY * np.sin(beta)
    assert np.abs(across) == pytest.approx(0.0, abs=1e-6 * F.max())
    assert F == pytest.approx(radial, rel=1e-9)


def test_zero_cable_length_gives_kite_glide_ratio():
    G = lansdorp.glide_ratio(1.1, 0.08, 0.03, 0.0, 50.0, 1.2)
    assert G == pytest.approx(1.1 / 0.08, rel=1e-15)


def test_reel_in_speed_limits():
    T, v_out = np.array([2.0e5]), np.array([4.0])
    base = PumpingParams()
    # instantaneous reel-in: P = (eta T - T_r / eta) v_out
    fast = PumpingParams(reel_in_speed=np.inf)
    p = lansdorp.cycle(T, v_out, fast)[4]
    assert p[0] == pytest.approx((0.92 * T[0] - T[0] / 50 / 0.92) * v_out[0], rel=1e-12)
    # reel-in speed going to zero: power ~ E v_in / Delta L -> 0, exactly 0 at v_in = 0
    for v_in in (1e-3, 1e-6):
        p = lansdorp.cycle(T, v_out, PumpingParams(reel_in_speed=v_in))[4]
        E = (0.92 - 1 / 50 / 0.92) * T[0] * 200.0
        assert p[0] == pytest.approx(E * v_in / 200.0, rel=2e-3)
    assert lansdorp.cycle(T, v_out, PumpingParams(reel_in_speed=0.0))[4][0] == 0.0
    # eqs. 12-14 by hand at the paper's parameters
    t_c = 200 / 4.0 + 200 / 16.7
    E = 0.92 * T[0] * 4.0 * 200 / 4.0 - T[0] / 50 * 16.7 / 0.92 * 200 / 16.7
    assert lansdorp.cycle(T, v_out, base)[4][0] == pytest.approx(E / t_c, rel=1e-12)


def test_max_cable_force_eq15():
    # Table 1 cable, 29.68 mm: 1.6 GPa / 2.5 * pi d^2 / 4
    assert lansdorp.max_cable_force(0.02968, PumpingParams()) == pytest.approx(442.80e3, rel=1e-4)


def test_models_agree_where_their_assumptions_meet():
    # massless Schmehl kite on one horizontal crosswind course at phi = 0, no transition (beta_in = beta) is
    # Lansdorp's model with the wind component along the cable
    w = np.array([6.0, 10.0, 14.0])
    theta = np.radians(55.0)
    qs = schmehl.SchmehlParams(kite_mass_per_area=0.0, tether_mass_share=0.0, n_course=1, retraction_elevation=0.0)
    a = lansdorp.cycle_power(w, 300.0, theta, 0.02, 100.0, 1.0, 0.08)
    b = schmehl.cycle_power(w, 300.0, theta, 0.02, 100.0, 1.0, 0.08, qs=qs)
    assert b.tension_out == pytest.approx(a.tension_out, rel=1e-9)
    assert b.power_out == pytest.approx(a.power_out, rel=1e-9)


def test_loop_mean_is_the_time_mean_of_a_flown_loop():
    # a loop flown at a constant turn per arc length: d chi / dt = lambda(chi) v_w / r, integrated in time with
    # solve_ivp to chi = 2 pi; the loop's mean tether force is (integral of F dt) / T and its mean speed 2 pi r / T
    from scipy.integrate import solve_ivp

    V, h, theta, d, S, cl, cd = np.array([7.0]), 300.0, np.radians(60.0), 0.02, 100.0, 1.0, 0.08
    qs = schmehl.SchmehlParams(n_course=256)
    L = lansdorp.cable_length(h, theta)
    share = lansdorp.cable_drag_share(d, L, S, 1.2)
    mass = qs.kite_mass_per_area * S + qs.tether_mass_share * 970.0 * np.pi * d * d / 4.0 * L
    beta, f = 0.5 * np.pi - theta, 1.0 / 3.0

    def course(chi):
        F, lam = schmehl.traction(V, beta, f, S, cl, cd + share, mass, RHO, 0.0, chi)
        return F[0], lam[0]

    def rhs(t, y):
        F, lam = course(y[0])
        return [lam * V[0], F]

    done = lambda t, y: y[0] - 2.0 * np.pi  # noqa: E731
    done.terminal = True
    sol = solve_ivp(rhs, (0.0, 1e3), [0.0, 0.0], events=done, rtol=1e-11, atol=1e-9)
    T_loop = sol.t_events[0][0]
    forces = [course(c)[0] for c in np.linspace(0.0, 2.0 * np.pi, 9)]
    assert max(forces) > 1.2 * min(forces)  # the weight makes the courses differ: the weighting matters here
    r = schmehl.cycle_power(V, h, theta, d, S, cl, cd, qs=qs)
    assert r.tension_out[0] == pytest.approx(sol.y_events[0][0][1] / T_loop, rel=1e-7)
    assert r.kite_speed[0] == pytest.approx(2.0 * np.pi / T_loop, rel=1e-7)


@pytest.mark.parametrize("mass_per_area", [0.6, 3.0])
@pytest.mark.parametrize("f", [0.1, 0.2, 1.0 / 3.0])
def test_traction_power_with_weight_below_the_massless_optimum(mass_per_area, f):
    # the weight can only cost: over the loop the reel-out power stays below the closed-form massless optimum
    # zeta_max P_w (oracles.md) at every wind; below the wind that carries the kite round the loop it is 0
    w, h, theta, d, S, cl, cd = np.linspace(0.5, 25.0, 99), 300.0, np.radians(60.0), 0.02, 100.0, 1.0, 0.08
    r = schmehl.cycle_power(w, h, theta, d, S, cl, cd, qs=schmehl.SchmehlParams(kite_mass_per_area=mass_per_area),
                            reel_out_factor=f)
    cdt = cd + lansdorp.cable_drag_share(d, lansdorp.cable_length(h, theta), S, 1.2)
    zeta_max = 4 / 27 * np.hypot(cl, cdt) * (1 + (cl / cdt) ** 2) * np.cos(0.5 * np.pi - theta) ** 3
    assert np.all(r.power_out <= zeta_max * 0.5 * RHO * S * w**3)
    assert r.power[0] == 0.0 and r.energy[0] == 0.0 and np.isinf(r.time_cycle[0])
    assert r.power[-1] > 0.0


def test_a_loop_with_a_course_the_kite_cannot_fly_gives_no_power():
    # a heavy kite in light wind: it can dive (chi = pi) but not climb (chi = 0), so the loop never closes
    V, beta, f, S, cl, cd, m = np.array([4.0]), np.radians(30.0), 1.0 / 3.0, 100.0, 1.0, 0.1, 300.0
    up, _ = schmehl.traction(V, beta, f, S, cl, cd, m, RHO, 0.0, 0.0)
    down, _ = schmehl.traction(V, beta, f, S, cl, cd, m, RHO, 0.0, np.pi)
    assert np.isnan(up[0]) and down[0] > 0.0
    force, lam, flyable = schmehl.pattern_mean(np.array([up, down]), np.array([[0.5], [2.0]]))
    assert not flyable[0] and force[0] == 0.0 and lam[0] == 0.0
