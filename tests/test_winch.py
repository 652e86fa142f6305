"""The winch kind (kernels/winch.py, model/winch.py): tether bookkeeping and drum dynamics against closed forms
and independent quadratures of the recorded tension and speed."""

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

from laddermill_gym.envs.pumping.winch_scene import electrical_energy, load_pumping
from laddermill_gym.kernels.contract import SX_ENERGY, SX_MOVED, SX_SPEED
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.winch import winch_params


@pytest.fixture(scope="module")
def pumping():
    return load_pumping("pumping_kite")


@pytest.fixture(scope="module")
def trim(pumping):
    return pumping.initial_state()


def _run(sim, n, controls=None):
    """(t, T_0, V, s, E) sampled at every step (n + 1 samples)."""
    if controls is not None:
        sim.reset(controls=controls)
    off = sim.assembly.body_state_size
    rows = []
    for k in range(n + 1):
        if k:
            sim.step()
        rows.append((sim.t, sim.tensions()[0], sim.state[off + SX_SPEED], sim.state[off + SX_MOVED],
                     sim.state[off + SX_ENERGY]))
    return np.array(rows).T


def test_commanded_speed_closed_form(pumping, trim):
    """dV/dt = (V_cmd - V)/tau from V = 0: V = V_cmd (1 - e^{-t/tau}), s = V_cmd (t - tau (1 - e^{-t/tau}));
    the energy is the quadrature of T_0 V (trapezoid of the per-step samples)."""
    x, u = trim
    sim = pumping.simulator(x, u)
    tau, vc = pumping.winch.speed_time_constant, 2.5
    u = u.copy()
    u[-1] = vc
    t, ten, v, s, e = _run(sim, 600, u)
    np.testing.assert_allclose(v, vc * (1 - np.exp(-t / tau)), atol=1e-9)
    np.testing.assert_allclose(s, vc * (t - tau * (1 - np.exp(-t / tau))), atol=1e-9)
    quad = cumulative_trapezoid(ten * v, t, initial=0.0)
    np.testing.assert_allclose(e[-1], quad[-1], rtol=1e-4)
    assert sim.cable_paid_out() == pytest.approx(s[-1])


def test_prescribed_schedule_pays_out_its_integral(pumping, trim):
    """A prescribed ramp 0 -> 3 m/s over 2 s then held: s(3 s) = 3 + 3 = 6 m (area under the schedule)."""
    x, u = trim
    w = winch_params(pumping.winch.piece_length, mode="prescribed", speed_times=(0.0, 2.0),
                     speed_values=(0.0, 3.0))
    ps = pumping.replace_winch(**{f: getattr(w, f) for f in ("mode", "speed_times", "speed_values")})
    sim = ps.simulator(x, u[:-1])
    t, ten, v, s, e = _run(sim, 600)
    assert s[-1] == pytest.approx(6.0, abs=1e-9)
    sched = np.interp(t, [0.0, 2.0], [0.0, 3.0])
    np.testing.assert_allclose(v, sched, atol=0.01)  # the state integrates the slope (RK4 stage at the kink)
    np.testing.assert_allclose(e[-1], cumulative_trapezoid(ten * sched, t)[-1], rtol=1e-3)


def test_drum_against_closed_forms(pumping, trim):
    """(J / r^2) dV/dt = T_0 - Q / r with a constant torque Q: the drum energy is (Q / r) s exactly, V(t) - V(0) is
    r^2 / J times the quadrature of T_0 - Q / r, and the work of T_0 less the drum's energy is the kinetic energy
    (J / r^2)(V^2 - V0^2) / 2."""
    x, u = trim
    r, J, Q = 0.3, 9.0, 400.0
    ps = pumping.replace_winch(mode="drum", drum_radius=r, drum_inertia=J, torque_limits=(0.0, 2000.0))
    u = u.copy()
    u[-1] = Q
    sim = ps.simulator(x, u)
    t, ten, v, s, e = _run(sim, 600)
    np.testing.assert_allclose(e, Q / r * s, rtol=1e-12, atol=1e-9)
    dv = r * r / J * cumulative_trapezoid(ten - Q / r, t, initial=0.0)
    np.testing.assert_allclose(v, dv, atol=2e-4 * np.max(np.abs(v)))
    work = cumulative_trapezoid(ten * v, t, initial=0.0)
    kinetic = 0.5 * J / r ** 2 * v ** 2
    np.testing.assert_allclose(work - e, kinetic, atol=2e-3 * kinetic.max())
    assert v[-1] > 0.5  # the tension (about 2.2 kN) exceeds Q / r = 1.33 kN: the drum reels out


def test_reel_in_stops_before_the_drum(pumping, trim):
    """Reeling in more than 95 % of the element ends the run with the kind's LIMIT (named in the error)."""
    x, u = trim
    x = x.copy()
    x[pumping.scene.assembly.body_state_size + SX_MOVED] = -0.949 * pumping.winch.piece_length
    sim = pumping.simulator(x, u)
    u = u.copy()
    u[-1] = -16.7
    with pytest.raises(Exception, match="(?i)limit"):
        sim.step(u, n_steps=400)


def test_electrical_efficiency_both_ways():
    """eta E generating, E / eta motoring (Lansdorp eq. 13)."""
    np.testing.assert_allclose(electrical_energy([100.0, -92.0], 0.92), [92.0, -100.0])


def test_bad_winch_config_names_file_and_field(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("scene: pumping_kite\nwinch:\n  mode: commanded\n  speed_time_constant: -1\n"
                   "  speed_limits: [-1, 1]\ncycle: {reel_out_factor: 0.3, reel_length: 200, reel_in_speed: 5,"
                   " alpha_out_deg: 8, alpha_in_deg: 0, depower_tension: 300, depower_overrun: 20}\n")
    with pytest.raises(ConfigError, match=r"bad.yaml.*winch.speed_time_constant"):
        load_pumping(bad)
    bad.write_text(bad.read_text().replace("speed_time_constant: -1", "speed_time_constant: 1\n  drumm: 2"))
    with pytest.raises(ConfigError, match=r"winch.drumm"):
        load_pumping(bad)
    bad.write_text(bad.read_text().replace("  drumm: 2\n", "").replace("alpha_in_deg: 0", "alpha_in_deg: 9"))
    with pytest.raises(ConfigError, match=r"bad.yaml.*alpha_in_deg"):
        load_pumping(bad)
    assert math.isfinite(load_pumping("pumping_kite").cycle.reel_length)


def test_in_plane_winch_pays_out_the_closed_form():
    """The in-plane kind (Winch2D) integrates the same speed lag: s = V_cmd (t - tau (1 - e^{-t/tau}))."""
    ps = load_pumping("pumping_kite", dimension=2)
    x, u = ps.initial_state()
    sim = ps.simulator(x, u)
    assert type(sim.model.kind).__name__ == "Winch2D"
    u = u.copy()
    u[-1] = 2.5
    sim.step(u, 600)
    tau = ps.winch.speed_time_constant
    assert sim.cable_paid_out() == pytest.approx(2.5 * (sim.t - tau * (1 - math.exp(-sim.t / tau))), abs=1e-9)


def test_a_simulator_names_the_winchs_reel_in_limit():
    """The winch element reeled in below 5 % of its start length stops the run with the integrators' LIMIT status;
    ``WinchSimulator``'s report named only the (unbroken) speed and rate limits (the review of 2026-12-07). The
    element 2 cm above 15 m reeling in at 10 m/s passes 15 m within the 5 ms step: the report names the winch, a rest
    length under 15 m and within 10.5 m/s x 5 ms of 15.02 m."""
    import dataclasses
    import re

    from laddermill_gym.envs.pumping.winch_scene import WinchSimulator
    from laddermill_gym.kernels.contract import B3_POS
    from laddermill_gym.sim.simulator import SimulationError

    ps = load_pumping()
    x, u = ps.initial_state()
    x = np.array(x, dtype=float)
    asm = ps.assembly
    xoff = asm.body_state_size
    g = asm.fixed_points[0]
    p = x[B3_POS: B3_POS + 3]
    x[B3_POS: B3_POS + 3] = g + (p - g) * 15.02 / np.linalg.norm(p - g)
    x[xoff + SX_MOVED] = 15.02 - 300.0
    x[xoff + SX_SPEED] = -10.0
    sim = WinchSimulator(asm, x, dataclasses.replace(ps.scene.settings, ground_contact="off"), u)
    u = np.array(sim.controls)
    u[-1] = -10.0
    with pytest.raises(SimulationError) as err:
        sim.step(u, n_steps=1)
    m = re.search(r"winch reeled the tether's first element in to a rest length of ([0-9.]+) m .* below 5 % of its "
                  r"start length 300 m \(15 m\)", str(err.value))
    assert m, str(err.value)
    assert 15.02 - 10.5 * sim.settings.dt < float(m.group(1)) < 15.0
