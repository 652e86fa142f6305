"""Roberts' tethered twin-rotor craft in the simulator: trim against his eq. (3), power against the rotor
module's power coefficient, eq. (6) against the full simulator's Jacobian, the critical wind speed against
nonlinear runs, and the eq. (6) LQR on the linear model and on the nonlinear craft."""

import dataclasses
import math
import re

import numpy as np
import pytest

from laddermill_gym.control.craft_lqr import design_craft_lqr
from laddermill_gym.control.linearize import linearize
from laddermill_gym.kernels.wind import density, wind_at
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.rotorcraft.config import load_craft_config
from laddermill_gym.rotorcraft.craft import CraftSimulator, load_craft
from laddermill_gym.rotorcraft.roll_lateral import lateral_state, perturbed_state
from laddermill_gym.rotorcraft.rotor import cable_angle, rotor_coefficients
from laddermill_gym.studies.rotorcraft.craft_stability import (
    closed_loop_run,
    growth_rate,
    jacobian_check,
    straight_tether_variant,
)


@pytest.fixture(scope="module")
def craft():
    return load_craft()


@pytest.fixture(scope="module")
def design():
    return design_craft_lqr()


def test_trim_matches_roberts_eq3(craft):
    """With massless straight tethers and no fin or frame loads, the tethers' pull on the trimmed craft points
    along Roberts' equilibrium cable angle beta, eq. (3), evaluated from the rotors' thrust and H-force."""
    cfg = craft.config
    cable = dataclasses.replace(cfg.tethers.cable, mass_per_length=1e-9)
    t = dataclasses.replace(cfg.tethers, cable=cable, elements=1)
    c = load_craft(config=cfg.replace(tethers=t, sag=False, cable_aero=False, fin_area=0.0, drag_area=0.0,
                                      hub_height=0.0))
    sim = c.simulator()
    ro = sim.rotor_outputs()
    mg = cfg.mass * cfg.gravity
    alpha_c = sim.wing_euler()[0, 1]  # horizontal wind: the disk incidence is the pitch
    beta = cable_angle(ro["thrust_N"][0], ro["hforce_N"][0], mg, alpha_c)
    pull = np.zeros(3)
    R = sim.wing_rotations()[0]
    pos = sim.wing_positions()[0]
    ten = sim.tensions()
    for i, els in enumerate(c.layout.tether_elements):
        e = els[-1]
        a = pos + R @ c.layout.attach[i]
        n = c.layout.anchors[i] - a
        pull += ten[e] * n / np.linalg.norm(n)
    beta_sim = math.atan2(pull[2], pull[0])  # below the horizontal, towards the anchors (upwind)
    assert abs(ro["thrust_N"][0] - ro["thrust_N"][1]) < 1e-9 * ro["thrust_N"][0]
    assert beta_sim == pytest.approx(beta, abs=1e-6)


def test_power_matches_rotor_module(craft):
    """Each rotor's power equals C_p (Roberts eq. 4) of the rotor module solved independently at the hub's
    advance ratio, incidence and pitch; the electrical power is 95 % of the sum."""
    sim = craft.simulator()
    cfg = craft.config
    ro = sim.rotor_outputs()
    R = sim.wing_rotations()[0]
    pos = sim.wing_positions()[0]
    total = 0.0
    for r, hy in enumerate((0.5 * cfg.hub_spacing, -0.5 * cfg.hub_spacing)):
        hub = pos + R @ np.array([cfg.hub_x, hy, -cfg.hub_height])
        w = np.array(wind_at(hub[2], sim.model.wf, 1.0, 0.0))
        a_b = R.T @ w
        V = float(np.linalg.norm(a_b))
        alpha_c = math.atan2(-a_b[2], math.hypot(a_b[0], a_b[1]))
        mu = V * math.cos(alpha_c) / (cfg.rotor_speed * cfg.rotor_radius)
        st = rotor_coefficients(cfg.rotor, mu, alpha_c, ro["pitch_rad"][r])
        rho = density(-hub[2], sim.model.wf)
        p = st.cp * 0.5 * rho * math.pi * cfg.rotor_radius ** 2 * V ** 3
        assert ro["mu"][r] == pytest.approx(mu, rel=1e-9)
        assert ro["power_W"][r] == pytest.approx(p, rel=1e-7)
        total += p
    assert sim.electrical_power() == pytest.approx(0.95 * total, rel=1e-7)
    assert total > 0.0


def test_eq6_matches_restricted_jacobian(craft):
    """M, D, K and the input column derived from the craft's physics agree with the full simulator's
    Jacobian restricted to (y, phi) entry by entry: the issue asks for 5 %; they agree to 1.0 % (the roll damping,
    through the product of inertia eq. (6) leaves out), so 1.5 % is the bound that catches a few-percent error in
    the derivation (a 3 % roll inertia gave 2.95 %: a review of 2026-12-07)."""
    chk = jacobian_check(straight_tether_variant(craft))
    assert chk["max_rel_error"] < 0.015
    # the roll input is the differential thrust: beta = -2 s dT/dtheta, alpha = 0 at a level trim
    assert chk["alpha_beta"][0] == 0.0 and chk["alpha_beta"][1] < 0.0


def test_symmetric_trim_solves_the_full_equilibrium(craft):
    """The trim (solved on mirror-symmetric poses) is an equilibrium of the full craft: every entry of the
    full right-hand side vanishes, across collectives continued from one trim to the next at 22 m/s, where the
    unrestricted problem is ill-conditioned (sideways drift) and once failed to converge."""
    c = load_craft(config=craft.config.with_wind_speed(22.0))
    x_prev = None
    for deg in (0.0, -1.0, -2.5, -2.78, -3.0):
        th = math.radians(deg)
        x = c.trim(th, x_guess=x_prev)
        u = np.array([th, 0.0])
        sim = CraftSimulator(c.config, c.assembly, c.layout, x, u)
        acc = sim.rhs(0.0, x, u)
        assert np.max(np.abs(acc)) < 1e-6
        assert abs(x[1]) < 1e-9 and np.allclose(sim.state[[4, 6]], 0.0, atol=1e-9)  # no sideways offset, roll, yaw
        x_prev = x


def _envelope_rate(t, y, omega, t0=20.0):
    """Growth rate [1/s] of the envelope of an oscillation of frequency omega [rad/s]: log-linear fit through
    the largest |y| of each half period after t0 (the other modes have died out by then)."""
    half = math.pi / omega
    tt, aa = [], []
    start = t0
    while start + half <= t[-1]:
        m = (t >= start) & (t < start + half)
        k = np.argmax(np.abs(y[m]))
        tt.append(t[m][k])
        aa.append(abs(y[m][k]))
        start += half
    return np.polyfit(tt, np.log(aa), 1)[0]


@pytest.mark.parametrize("v0", [10.0, 22.0])
def test_critical_wind_speed_linear_vs_nonlinear(craft, v0):
    """Below the critical wind speed (about 20.5 m/s) the lateral mode grows, above it decays: the linearised
    growth rate's sign and size agree with the envelope of a nonlinear run after a small lateral push."""
    c = load_craft(config=craft.config.with_wind_speed(v0))
    rate, x, ev, th = growth_rate(c)
    x = x.copy()
    x[8] += 0.01  # 1 cm/s lateral (body y) velocity
    sim = CraftSimulator(c.config, c.assembly, c.layout, x, np.array([th, 0.0]))
    ts, ys = [], []
    while sim.t < 75.0 and (not ys or abs(ys[-1]) < 1.0):  # stop while still small (linear regime)
        sim.step(n_steps=25)
        ts.append(sim.t)
        ys.append(sim.state[1])
    rate_nl = _envelope_rate(np.array(ts), np.array(ys), abs(ev.imag), t0=10.0)
    assert np.sign(rate) == (1 if v0 < 20.0 else -1)
    assert rate_nl == pytest.approx(rate, rel=0.15)


def test_lqr_stable_on_eq6_and_full_linear_model(design):
    assert np.max(np.abs(design.lqr.closed_loop)) < 1.0
    assert np.max(design.lqr.open_loop.real) < 0.0  # eq. (6) alone is stable; the full craft is not
    lin = linearize(design.sim, design.x_trim, design.u_trim)
    assert np.max(np.linalg.eigvals(lin.A).real) > 0.03
    import control

    n = lin.A.shape[0]
    idx = [list(lin.state_names).index(f"wing0_{k}") for k in ("y", "phi", "vy", "p")]
    C = np.zeros((4, n))
    C[range(4), idx] = 1.0
    sysd = control.c2d(control.ss(lin.A, lin.B, np.eye(n), 0), design.config.control_period)
    Acl = sysd.A - sysd.B[:, 1:2] @ (design.gain[None, :] @ C)
    assert np.max(np.abs(np.linalg.eigvals(Acl))) < 1.0


def test_lqr_holds_nonlinear_craft_below_critical_speed(design):
    """After the 0.01 rad direction step the open-loop craft swings out; the eq. (6) LQR keeps it within
    0.2 m with the differential collective well inside its +-5 deg."""
    ol = closed_loop_run(design, 45.0, controller=False)
    cl = closed_loop_run(design, 45.0, controller=True)
    assert np.max(np.abs(ol["y"][ol["t"] > 30])) > 1.0
    assert math.isnan(cl["failure_time"])
    assert np.max(np.abs(cl["y"])) < 0.2
    assert np.max(np.abs(cl["dtheta"])) < math.radians(1.0)


def test_lateral_state_reads_back_a_perturbation(design):
    """lateral_state against the perturbation built by quaternion product (roll about the body x axis) and
    rotated velocity: a roll about the body x axis adds to the 3-2-1 roll angle exactly, so the read-back
    equals what was put in to roundoff; the LQR's differential is -K z of it."""
    dz = np.array([0.3, 0.02, -0.15, 0.04])
    x = perturbed_state(design.x_trim, *dz)
    np.testing.assert_allclose(lateral_state(x, design.x_trim), dz, rtol=1e-12, atol=1e-14)
    u = design.state_controls(x)
    assert u[0] == design.u_trim[0]
    assert u[1] == pytest.approx(float(np.clip(-design.gain @ dz, *design.sim.config.differential_limits)), rel=1e-12)


def test_bad_craft_config(tmp_path):
    src = load_craft_config().file.read_text()
    cases = [(r"^mass: \S+", "mass: -3.0", "mass"), (r"^hub_spacing: \S+", "hub_spacing: 3.0", "hub_spacing"),
             (r"^  elements: \S+", "  elements: 0", "tethers.elements"),
             # reachable blade pitches past the rotor model's |pitch| < 90 deg (rotor.check_theta)
             (r"^collective_limits_deg: \S+ \S+", "collective_limits_deg: [-5.0, 150.0]", "collective_limits_deg"),
             (r"^differential_limits_deg: \S+ \S+", "differential_limits_deg: [-120.0, 120.0]",
              "differential_limits_deg"),
             # principal moments 0.1, 48.4, 53.8 (about): 48.5 < 53.8, no rigid body (Jxx + Jyy >= Jzz)
             (r"^inertia: \[48\.4, 6\.9,", "inertia: [48.4, 0.1,", "inertia")]
    for old, new, field in cases:
        p = tmp_path / "craft.yaml"
        text = re.sub(old, new, src, count=1, flags=re.M)
        assert text != src
        p.write_text(text.replace("../", str(load_craft_config().file.parent.parent) + "/"))
        with pytest.raises(ConfigError, match=field.replace(".", r"\.")):
            load_craft_config(p)
    p.write_text(src.replace("../", str(load_craft_config().file.parent.parent) + "/") + "\nrotor_colour: red\n")
    with pytest.raises(ConfigError, match="rotor_colour"):
        load_craft_config(p)
    with pytest.raises(ValueError, match="collective"):
        load_craft().simulator().step(np.array([math.radians(40.0), 0.0]))


def test_harness_lqr_on_rotorcraft_env():
    """The harness's LQR (make_controller) on Rotorcraft-v0: a full episode without failure and a higher
    return than the open loop, which crashes."""
    import gymnasium as gym

    import laddermill_gym  # noqa: F401  (registers the environments)
    from laddermill_gym.control.factory import make_controller

    env_id = "laddermill_gym/Rotorcraft-v0"
    env = gym.make(env_id)
    result = {}
    for spec in ("open_loop", "lqr"):
        ctl = make_controller(spec, env_id)
        obs, _ = env.reset(seed=3)
        ret, term, trunc = 0.0, False, False
        while not (term or trunc):
            a, _ = ctl.predict(obs, deterministic=True)
            obs, r, term, trunc, info = env.step(a)
            ret += r
        result[spec] = (ret, term)
    assert result["open_loop"][1] and not result["lqr"][1]
    assert result["lqr"][0] > result["open_loop"][0]
    with pytest.raises(ValueError, match="wind_speed"):
        make_controller("lqr", env_id, {"wind_speed": 12.0})


@pytest.mark.parametrize("name, alt", [("roberts_35m_15kft", 4572.0), ("roberts_35m_30kft", 9144.0)])
def test_35m_crafts_trim_below_the_ideal_power_coefficient(name, alt):
    """Roberts' 35 m crafts trim in the simulator near their design altitude and generate; their power
    coefficient (eq. 4, at the density and wind the trimmed craft meets) lies below Roberts' ideal curve at
    their incidence (no profile drag; the blade-element model passes it in places, docs/rotor.md, but not at these
    trims) and between half and all of the steady
    study's optimum, which chooses incidence and collective freely (2 % allowance: the study's density)."""
    from laddermill_gym.rotorcraft.rotor import ideal_power_coefficient
    from laddermill_gym.studies.rotorcraft.rotor_design import best_operating_point, load_design

    c = load_craft(name)
    sim = c.simulator()
    z = sim.state[2]
    assert abs(-z - alt) < 0.15 * alt
    wind = -wind_at(z, sim.model.wf, 1.0, 0.0)[0]
    rho = density(-z, sim.model.wf)
    r = c.config.rotor_radius
    cp = sim.electrical_power() / (0.95 * 2 * 0.5 * rho * math.pi * r ** 2 * wind ** 3)
    alpha_c = sim.wing_euler()[0, 1]
    best = best_operating_point(load_design(c.config.file), wind)
    print(f"{name}: trims at {-z:.0f} m ({-z - alt:+.0f} m from the design {alt:.0f} m, "
          f"{100 * abs(-z - alt) / alt:.1f} % of it, within 15 %), wind {wind:.2f} m/s, pitch = incidence "
          f"{math.degrees(alpha_c):.2f} deg, electrical power {sim.electrical_power() / 1e6:.3f} MW, C_p {cp:.4f} "
          f"(ideal {ideal_power_coefficient(alpha_c):.4f}, the study's optimum there {best.cp:.4f}); tether "
          f"tension at the craft (rear right, rear left, front) {np.round(sim.tether_tensions() / 1e3, 2)} kN "
          "(printed, not asserted)")
    assert 0.0 < cp < ideal_power_coefficient(alpha_c)
    assert 0.5 * best.cp < cp < 1.02 * best.cp
