"""Steady design study of the twin 35 m rotorcraft (laddermill_gym/studies/rotorcraft/rotor_design.py,
docs/rotorcraft_design.md).

Independent oracles only: the ICAO standard-atmosphere table, the closed-form symmetric catenary, a discretised
hanging chain solved by a different method (link-by-link force balance with shooting, and minimum potential
energy), the rotor functions of laddermill_gym.rotorcraft.rotor with Roberts' eqs. 3 and 4 recomputed here, energy
bounds
(Betz; power <= rotor force along the wind x wind speed), a coarse brute-force search written in this file, and
the published material data quoted in the configs.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy.optimize import fsolve, minimize

from laddermill_gym.kernels import wind as kwind
from laddermill_gym.rotorcraft.rotor import cable_angle, power_coefficient, rotor_coefficients
from laddermill_gym.studies.rotorcraft.rotor_design import (
    CRAFT_CONFIGS,
    ROBERTS_PEAK_POWER,
    best_operating_point,
    catenary,
    evaluate_point,
    isa_density,
    isa_temperature,
    load_design,
    speed_of_sound,
)

ROOT = Path(__file__).resolve().parents[1]
#: ICAO standard atmosphere table: density [kg/m^3] at 0, 15,000 and 30,000 ft.
ISA_TABLE_DENSITY = {0.0: 1.2250, 4572.0: 0.7708, 9144.0: 0.4583}
#: Allowed tether tension over breaking load and Kevlar data quoted by the study (DuPont Kevlar 49).
SAFE_FRACTION, KEVLAR_E, KEVLAR_STRENGTH, KEVLAR_RHO = 0.5, 112e9, 3.6e9, 1440.0


@pytest.fixture(scope="module")
def designs():
    return {ft: load_design(CRAFT_CONFIGS[ft]) for ft in (15000, 30000)}


@pytest.fixture(scope="module")
def points(designs):
    """Best points at the doc's bracket winds for 3.13 MW and at the top of the wind range."""
    winds = {15000: (25.0, 26.0, 45.0), 30000: (32.0, 33.0, 45.0)}
    return {(ft, v): best_operating_point(designs[ft], v) for ft in winds for v in winds[ft]}


# ---------------------------------------------------------------------------------------------- atmosphere
@pytest.mark.parametrize("h, rho", sorted(ISA_TABLE_DENSITY.items()))
def test_isa_density_against_the_standard_atmosphere_table(h, rho):
    assert isa_density(h) == pytest.approx(rho, rel=5e-3)


def test_isa_temperature_and_speed_of_sound_against_the_table():
    assert isa_temperature(9144.0) == pytest.approx(273.15 - 44.4, abs=0.1)  # table: -44.4 C at 30,000 ft
    assert speed_of_sound(0.0) == pytest.approx(340.29, abs=0.05)
    assert speed_of_sound(9144.0) == pytest.approx(303.2, abs=0.2)


@pytest.mark.parametrize("ft, wind", [(15000, 26.0), (30000, 33.0)])
def test_config_wind_gives_table_density_and_design_wind_in_the_wind_kernel(ft, wind):
    cfg = yaml.safe_load(CRAFT_CONFIGS[ft].read_text())
    w = cfg["wind"]
    h = cfg["tethers"]["length"] * math.sin(math.radians(cfg["tethers"]["elevation_deg"]))
    assert h == pytest.approx(ft * 0.3048, abs=0.5)
    wf = np.array([w["v0"], w["h0"], w["v1"], w["exponent"], w["direction_inf_rad"], w["direction_height"],
                   w["rho0"], 0.0 if w["density_model"] == "barometric" else 1.0, w["scale_height"], 0.0])
    assert kwind.density(h, wf) == pytest.approx(ISA_TABLE_DENSITY[round(h)], rel=5e-3)
    assert kwind.profile(h, wf)[0] == pytest.approx(wind, abs=0.01)


def test_cable_file_matches_roberts_and_kevlar_data():
    c = yaml.safe_load((ROOT / "configs" / "cables" / "kevlar_aluminium_10mm.yaml").read_text())
    flying = yaml.safe_load((ROOT / "configs" / "cables" / "kevlar_2p5mm.yaml").read_text())
    assert list(c) == list(flying)
    assert c["mass_per_length"] == 0.23                                   # Roberts sec. 6
    area = 0.5 * 0.23 / KEVLAR_RHO                                        # half the mass in Kevlar
    assert c["EA"] == pytest.approx(KEVLAR_E * area, rel=1e-3)
    assert c["breaking_load"] == pytest.approx(KEVLAR_STRENGTH * area * 0.67, rel=1e-3)
    solid = area + 0.5 * 0.23 / 2705.0                                    # + aluminium (2705 kg/m^3)
    assert c["diameter"] >= math.sqrt(4.0 * solid / math.pi)              # the materials must fit


def test_craft_configs_have_the_flying_model_keys():
    def keys(d):
        return {k: keys(v) if isinstance(v, dict) else None for k, v in d.items()}

    ref = keys(yaml.safe_load((ROOT / "configs" / "rotorcraft" / "roberts_flying_model.yaml").read_text()))
    for path in CRAFT_CONFIGS.values():
        assert keys(yaml.safe_load(path.read_text())) == ref
        assert yaml.safe_load(path.read_text())["rotor_radius"] == 17.5   # Roberts sec. 6: 35 m diameter


# ---------------------------------------------------------------------------------------------- catenary
def test_catenary_symmetric_closed_form():
    H, w, L = 1.2e4, 2.3, 800.0
    c = catenary(H, 0.5 * w * L, w, L)          # ends at the same height: V = +-wL/2
    a = H / w                                   # y = a cosh(x/a), half-length a sinh(x_half/a) = L/2
    assert c.span == pytest.approx(2.0 * a * math.asinh(L / (2.0 * a)), rel=1e-12)
    assert abs(c.height) < 1e-9 * L
    assert c.anchor_vertical == pytest.approx(-0.5 * w * L, rel=1e-12)
    assert c.weight == pytest.approx(w * L, rel=1e-12)
    assert c.anchor_tension == pytest.approx(c.top_tension, rel=1e-12)


def _chain_end(H, Vt, w, L, n):
    """Lower end of an n-link chain hung from its upper end, relative to it (link weights at the joints)."""
    d = L / n
    v = Vt - w * d * (np.arange(n) + 0.5)        # vertical tension in each link, top link first
    t = np.hypot(H, v)
    return d * np.sum(H / t), d * np.sum(v / t)


@pytest.mark.parametrize("H, Vt", [(3.0e4, 6.0e4), (5.0e4, 3.0e4), (2.0e3, 1.0e4)])
def test_catenary_against_a_discrete_chain_by_force_balance(H, Vt):
    w, L = 0.23 * 9.80665, 9144.0
    c = catenary(H, Vt, w, L)
    span, height = _chain_end(H, Vt, w, L, 20000)
    assert span == pytest.approx(c.span, rel=1e-6)
    assert height == pytest.approx(c.height, rel=1e-6, abs=1e-6 * L)
    # shooting: the end forces that put a 400-link chain's ends where the catenary's are
    sol = fsolve(lambda f: np.array(_chain_end(f[0] * 1e4, f[1] * 1e4, w, L, 400)) - (c.span, c.height),
                 [H / 1e4 * 1.3, Vt / 1e4 * 0.8], xtol=1e-12)
    assert sol[0] * 1e4 == pytest.approx(H, rel=1e-3)
    assert sol[1] * 1e4 == pytest.approx(Vt, rel=1e-3)


def test_catenary_against_a_minimum_energy_chain():
    """A 60-link chain between the catenary's ends, shaped by minimum potential energy (SLSQP): every joint lies
    on the closed-form curve to 1e-3 of the length, the end links follow the tension directions."""
    H, Vt, w, L, n = 3.0e4, 6.0e4, 0.23 * 9.80665, 9144.0, 60
    c = catenary(H, Vt, w, L)
    d = L / n
    k = np.arange(n)

    def joints(phi):
        return (np.concatenate([[0.0], np.cumsum(d * np.cos(phi))]),
                np.concatenate([[0.0], np.cumsum(d * np.sin(phi))]))

    def energy(phi):                             # sum of link weight x midpoint height, over w L^2
        z = joints(phi)[1]
        return d * np.sum(0.5 * (z[:-1] + z[1:])) / L ** 2

    def grad(phi):
        return d * d * np.cos(phi) * (n - k - 0.5) / L ** 2

    cons = {"type": "eq", "fun": lambda p: np.array([np.sum(np.cos(p)) * d - c.span, np.sum(np.sin(p)) * d
                                                     - c.height]) / L,
            "jac": lambda p: np.vstack([-np.sin(p), np.cos(p)]) * d / L}
    phi0 = math.atan2(c.height, c.span) + np.linspace(-0.1, 0.1, n)
    r = minimize(energy, phi0, jac=grad, constraints=[cons], method="SLSQP", options={"ftol": 1e-15,
                                                                                      "maxiter": 500})
    assert r.success
    x, z = joints(r.x)
    for j in range(1, n + 1):                    # joint j is at arc length j d from the anchor
        seg = catenary(H, c.anchor_vertical + w * j * d, w, j * d)
        assert math.hypot(x[j] - seg.span, z[j] - seg.height) < 1e-3 * L
    mid_top = catenary(H, Vt - 0.5 * w * d, w, L - 0.5 * d)   # tangent at the top link's midpoint
    assert r.x[-1] == pytest.approx(mid_top.top_angle, abs=1e-3)
    assert r.x[0] == pytest.approx(math.atan2(c.anchor_vertical + 0.5 * w * d, H), abs=1e-3)


def test_catenary_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="'horizontal' = -1.0"):
        catenary(-1.0, 1.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="'length' = 0.0"):
        catenary(1.0, 1.0, 1.0, 0.0)
    with pytest.raises(ValueError, match="'top_vertical'"):
        catenary(0.0, 1.0, 1.0, 2.0)             # slack vertical cable
    with pytest.raises(ValueError, match="'altitude' = 20000.0"):
        isa_density(20000.0)


# ---------------------------------------------------------------------------------------------- the study
def _forces(design, p):
    """Rotor state, thrust and H-force of one rotor [N] and the density, recomputed with
    laddermill_gym.rotorcraft.rotor."""
    mu = p.wind * math.cos(p.alpha_c) / (design.rotor_speed * design.radius)
    st = rotor_coefficients(design.rotor, mu, p.alpha_c, p.theta0)
    assert st.converged
    q = isa_density(design.altitude) * math.pi * design.radius ** 2 * (design.rotor_speed * design.radius) ** 2
    return st, mu, st.ct * q, st.ch * q


def test_power_is_roberts_eq4_from_the_rotor_functions(designs, points):
    for (ft, v), p in points.items():
        d = designs[ft]
        st, mu, _, _ = _forces(d, p)
        cp = power_coefficient(st.cq, mu, p.alpha_c)             # Roberts eq. 4 from the torque
        rho_table = ISA_TABLE_DENSITY[round(d.altitude)]
        expected = 0.95 * cp * 0.5 * rho_table * math.pi * 17.5 ** 2 * v ** 3 * 2
        assert p.power == pytest.approx(expected, rel=5e-4)      # table density has 4 digits
        shaft = -st.cq * isa_density(d.altitude) * math.pi * 17.5 ** 2 * (d.rotor_speed * 17.5) ** 2 * 17.5
        assert p.power == pytest.approx(2 * 0.95 * shaft * d.rotor_speed, rel=1e-9)


def test_limits_hold_at_the_reported_points(designs, points):
    for (ft, _), p in points.items():
        d = designs[ft]
        st, _, thrust, hforce = _forces(d, p)
        assert st.tip_aoa <= math.radians(13.0) + 1e-9                     # Roberts' blade-incidence limit
        tethers = 3 * d.cable_mass_per_length * d.tether_length * d.gravity
        # Roberts eq. 3 with the tethers' weight added to the craft's: the cables leave the anchors upwards
        assert cable_angle(thrust, hforce, d.mass * d.gravity + tethers, p.alpha_c) >= -1e-9
        ca, sa = math.cos(p.alpha_c), math.sin(p.alpha_c)
        rho = isa_density(d.altitude)
        fx = 2 * (thrust * sa + hforce * ca) + 0.5 * rho * p.wind ** 2 * d.drag_area
        fz = 2 * (thrust * ca - hforce * sa) - d.mass * d.gravity
        assert math.hypot(fx, fz) / 3 <= SAFE_FRACTION * d.breaking_load * (1 + 1e-9)
        assert catenary(fx / 3, fz / 3, d.cable_mass_per_length * d.gravity, d.tether_length).height \
            >= d.altitude * (1 - 1e-9)                                       # the tethers reach the altitude


def test_power_within_energy_bounds(designs, points):
    for (ft, v), p in points.items():
        d = designs[ft]
        _, _, thrust, hforce = _forces(d, p)
        rho = isa_density(d.altitude)
        betz = 0.95 * 2 * (16 / 27) * 0.5 * rho * math.pi * 17.5 ** 2 * v ** 3
        along_wind = 0.95 * 2 * (thrust * math.sin(p.alpha_c) + hforce * math.cos(p.alpha_c)) * v
        assert 0.0 < p.power <= min(betz, along_wind)
        assert p.power <= 0.95 * 3 * SAFE_FRACTION * d.breaking_load * v   # the tethers hold the rotor force


def test_optimum_beats_a_coarse_independent_search(designs, points):
    d, p = designs[15000], points[(15000, 26.0)]
    rho, w = isa_density(d.altitude), d.cable_mass_per_length * d.gravity
    q = rho * math.pi * 17.5 ** 2 * (d.rotor_speed * 17.5) ** 2
    best = -math.inf
    for a in np.radians(np.arange(25.0, 46.0, 1.0)):
        mu = 26.0 * math.cos(a) / (d.rotor_speed * 17.5)
        for th in np.radians(np.arange(-4.0, 12.0, 0.25)):
            st = rotor_coefficients(d.rotor, mu, a, th)
            if not st.converged or st.tip_aoa > math.radians(13.0):
                continue
            ht = (2 * q * (st.ct * math.sin(a) + st.ch * math.cos(a)) + 0.5 * rho * 26.0 ** 2 * d.drag_area) / 3
            vt = (2 * q * (st.ct * math.cos(a) - st.ch * math.sin(a)) - d.mass * d.gravity) / 3
            va = vt - w * d.tether_length
            height = (math.hypot(ht, vt) - math.hypot(ht, va)) / w
            if va >= 0 and height >= d.altitude and math.hypot(ht, vt) <= SAFE_FRACTION * d.breaking_load:
                best = max(best, -2 * 0.95 * st.cq * q * 17.5 * d.rotor_speed)
    assert math.isfinite(best)
    assert best <= p.power * (1 + 1e-9)


def test_roberts_power_is_reached_in_the_stated_brackets(points):
    # rotorcraft_design.md: 3.13 MW between 25 and 26 m/s at 15,000 ft and between 32 and 33 m/s at 30,000 ft
    assert points[(15000, 25.0)].power < ROBERTS_PEAK_POWER <= points[(15000, 26.0)].power
    assert points[(30000, 32.0)].power < ROBERTS_PEAK_POWER <= points[(30000, 33.0)].power
    # and the power keeps rising to the top of the wind range (no limit caps it inside 5-45 m/s)
    assert points[(15000, 45.0)].power > 2 * ROBERTS_PEAK_POWER
    assert points[(30000, 45.0)].power > 1.5 * ROBERTS_PEAK_POWER


def test_evaluate_point_bad_input_names_the_argument(designs):
    with pytest.raises(ValueError, match="'wind' = -3.0"):
        evaluate_point(designs[15000], -3.0, 0.5, 0.05)
    with pytest.raises(ValueError, match="'alpha_c' = 2.0"):
        evaluate_point(designs[15000], 20.0, 2.0, 0.05)
    with pytest.raises(ValueError, match="'design'"):
        best_operating_point("roberts_35m_15kft", 20.0)
