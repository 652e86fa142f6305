"""The moving cable (issue 12, Meijaard et al. 1999 "Boundary conditions"): rest lengths, transfers, generator.

Oracles: the plain-numpy reference right-hand side (``reference``) on an assembly whose first and
last elements are given the station's lengths; the closed-form Voigt damping of a cable paid out at V_c; the
integral of a piecewise-linear speed schedule; the drum's energy identity E = (Q / r) x paid-out length; and, at
a transfer, mass and linear momentum computed here from the states with the reference's element-end kinematics
and the paper's interpolation rule.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from laddermill_gym import Simulator, load_scene
from laddermill_gym.kernels.contract import SX_MOVED, SX_SPEED
from laddermill_gym.kernels.integrate import normalise_and_check
from laddermill_gym.reference import reference_rhs
from laddermill_gym.reference.cable import end_kinematics
from laddermill_gym.reference.rotations import rotation

N_WINGS = 11


@pytest.fixture(scope="module")
def mill3d():
    # at 12.5 ms (the scene's step until it became 10 ms): the states these oracle tests start from (a taut first
    # element at 35 s) and the schedule's kinks on exact step times depend on it, not on the default step
    return load_scene("laddermill", n_wings=N_WINGS, dt=0.0125)


def _with_station(scene, **changes):
    st = dataclasses.replace(scene.assembly.station, **changes)
    return dataclasses.replace(scene.assembly, station=st)


def _running_state(scene, seconds=40.0):
    """A state of the running mill (wings moving, cable at speed) and its simulator."""
    sim = scene.simulator()
    sim.step(n_steps=int(round(seconds / sim.settings.dt)))
    return sim


def _fixed_length_assembly(asm, s):
    """The assembly without a station, its first and last elements at the station's lengths for moved cable s."""
    st = asm.station
    l0 = asm.elements.l0.copy()
    l0[0] = st.first_fraction * st.piece_length + s
    l0[-1] = st.last_fraction * st.piece_length - s
    return dataclasses.replace(asm, station=None, elements=dataclasses.replace(asm.elements, l0=l0))


def test_rhs_equals_reference_with_station_lengths(mill3d):
    """With the cable at rest (V_c = 0) the moving-cable rhs is the rigid rhs of the station's element lengths."""
    sim = _running_state(mill3d, 35.0)
    x = sim.state.copy()
    s = 23.5
    x[sim.assembly.body_state_size + SX_MOVED] = s
    asm0 = _with_station(mill3d, speed_times=(0.0,), speed_values=(0.0,))
    still = Simulator(asm0, x, mill3d.settings, sim.controls)
    dx = still.rhs(0.0, x)
    nb = asm0.body_state_size
    ref = reference_rhs(0.0, x[:nb], sim.controls, _fixed_length_assembly(asm0, s))
    scale = np.maximum(np.abs(ref), 1.0)
    assert np.max(np.abs(dx[:nb] - ref) / scale) < 1e-8
    assert dx[nb + SX_MOVED] == 0.0


def test_damping_acts_on_material_strain_rate(mill3d):
    """Plain truss (no sag): paying out at V_c lowers the first element's tension by DA (l / l0) V_c / l0 and
    raises the last one's by the same law (the strain of cable paid out at constant strain does not change)."""
    sim = _running_state(mill3d, 35.0)
    x = sim.state.copy()
    asm = dataclasses.replace(mill3d.assembly, sag=False)
    tens = {}
    for v in (0.0, 3.0):
        sv = Simulator(dataclasses.replace(asm, station=dataclasses.replace(asm.station, speed_times=(0.0,),
                                                                            speed_values=(v,))),
                       x, mill3d.settings, sim.controls)
        tens[v] = sv.tensions()
    fixed = _fixed_length_assembly(asm, x[asm.body_state_size + SX_MOVED])
    DA = asm.elements.DA[0]
    for e, sign in ((0, -1.0), (-1, 1.0)):
        e = e % asm.elements.count
        xr, _, _ = end_kinematics(fixed, e, 0, x[:asm.body_state_size])
        xs, _, _ = end_kinematics(fixed, e, 1, x[:asm.body_state_size])
        ln, l0 = np.linalg.norm(xs - xr), fixed.elements.l0[e]
        assert tens[0.0][e] > 0
        expected = sign * DA * (ln / l0) * 3.0 / l0
        assert tens[3.0][e] - tens[0.0][e] == pytest.approx(expected, rel=1e-9)


def test_paid_out_length_is_the_integral_of_the_speed(mill3d):
    """Schedule 0 -> 3 m/s in 10 s, -> 5 m/s at 20 s, then held: 15 + 40 + 5 (T - 20) m, kinks on step times."""
    asm = _with_station(mill3d, speed_times=(0.0, 10.0, 20.0), speed_values=(0.0, 3.0, 5.0))
    x0, u0 = mill3d.initial_state()
    sim = Simulator(asm, x0, mill3d.settings, u0)
    sim.step(n_steps=int(round(60.0 / sim.settings.dt)))
    assert sim.t == pytest.approx(60.0)
    assert sim.cable_paid_out() == pytest.approx(255.0, abs=1e-9)
    assert sim.transfers() == 3  # 255 m = 3 pieces of 70 m + 45 m
    assert sim.state[asm.body_state_size + SX_MOVED] == pytest.approx(45.0, abs=1e-9)
    assert sim.state[asm.body_state_size + SX_SPEED] == pytest.approx(5.0, abs=1e-12)
    assert list(sim.slot_wings()[:4]) == [N_WINGS - 3, N_WINGS - 2, N_WINGS - 1, 0]


def _momentum_and_mass(asm, x):
    """Total linear momentum (global) [N s] and mass [kg] of the wings and the cable (consistent element mass:
    element momentum m_e (v_r + v_s) / 2 with the end velocities of the reference kinematics)."""
    st = asm.station
    nb = asm.body_state_size
    s = x[nb + SX_MOVED]
    fixed = _fixed_length_assembly(asm, s)
    p, m = np.zeros(3), 0.0
    for k in range(asm.n_wings):
        o = 13 * k
        mk = asm.wing(k).mass
        p += mk * rotation(x[o + 3:o + 7]) @ x[o + 7:o + 10]
        m += mk
    for e in range(asm.elements.count):
        me = fixed.elements.mu[e] * fixed.elements.l0[e]
        _, vr, _ = end_kinematics(fixed, e, 0, x[:nb])
        _, vs, _ = end_kinematics(fixed, e, 1, x[:nb])
        p += 0.5 * me * (vr + vs)
        m += me
    assert st is not None
    return p, m


@pytest.mark.parametrize("forwards", [True, False])
def test_transfer_bookkeeping(mill3d, forwards):
    """Across a transfer: total mass unchanged, the wings shift one slot, the new wing sits at the interpolated
    point, and the momentum changes by exactly what the added and removed wing and the re-cut elements carry."""
    sim = _running_state(mill3d, 40.0)
    asm, nb = mill3d.assembly, mill3d.assembly.body_state_size
    lp, n = asm.station.piece_length, asm.n_wings
    x = sim.state.copy()
    x[nb + SX_MOVED] = lp + 0.3 if forwards else -0.2
    p0, m0 = _momentum_and_mass(asm, x)
    y = x.copy()
    assert normalise_and_check(y, sim.model, sim.limits) == 0
    p1, m1 = _momentum_and_mass(asm, y)
    assert m1 == pytest.approx(m0, rel=1e-14)
    w = 13
    fixed0 = _fixed_length_assembly(asm, x[nb + SX_MOVED])
    if forwards:  # slots shift up, the last wing leaves, a wing enters slot 0 on the first element
        np.testing.assert_allclose(y[w:w * n], x[:w * (n - 1)], rtol=1e-15, atol=0)  # (quaternions renormalised)
        new, gone, e, end, frac_len = 0, n - 1, 0, 1, asm.station.first_fraction * lp + 0.3
    else:
        np.testing.assert_allclose(y[:w * (n - 1)], x[w:w * n], rtol=1e-15, atol=0)
        new, gone, e, end, frac_len = n - 1, 0, asm.elements.count - 1, 0, asm.station.last_fraction * lp + 0.2 - lp
    f = frac_len / fixed0.elements.l0[e]
    g, _, _ = end_kinematics(fixed0, e, 1 - end, x[:nb])
    a, va, _ = end_kinematics(fixed0, e, end, x[:nb])
    fixed1 = _fixed_length_assembly(asm, y[nb + SX_MOVED])
    e_new = 0 if forwards else asm.elements.count - 1
    pn, vn, _ = end_kinematics(fixed1, e_new, end, y[:nb])
    np.testing.assert_allclose(pn, g + f * (a - g), rtol=0, atol=1e-9)
    np.testing.assert_allclose(vn, f * va, rtol=0, atol=1e-9)
    np.testing.assert_array_equal(y[w * new + 10:w * new + 13], 0.0)  # no rotation
    # expected change: wings in and out, and the momenta of the elements that were re-cut
    mw = asm.wing(0).mass
    p_wing_new = mw * rotation(y[w * new + 3:w * new + 7]) @ y[w * new + 7:w * new + 10]
    p_wing_gone = mw * rotation(x[w * gone + 3:w * gone + 7]) @ x[w * gone + 7:w * gone + 10]

    def elem_p(fx, xx, es):
        out = np.zeros(3)
        for ee in es:
            _, vr, _ = end_kinematics(fx, ee, 0, xx[:nb])
            _, vs, _ = end_kinematics(fx, ee, 1, xx[:nb])
            out += 0.5 * fx.elements.mu[ee] * fx.elements.l0[ee] * (vr + vs)
        return out

    last = asm.elements.count - 1
    # forwards: element 0 is split (after: 0 and 1), elements last-1 and last merge (after: last); the others
    # keep their momentum and move up one index. Backwards the mirror image.
    gone_e, new_e = ([0, last - 1, last], [0, 1, last]) if forwards else ([0, 1, last], [0, last - 1, last])
    expected = p0 + p_wing_new - p_wing_gone - elem_p(fixed0, x, gone_e) + elem_p(fixed1, y, new_e)
    np.testing.assert_allclose(p1, expected, rtol=0, atol=1e-9 * np.abs(p0).max())


def test_drum_energy_is_force_times_paid_out_length(mill3d):
    """A drum held by a constant generator torque Q: dE/dt = (Q / r) V_c and d(paid out)/dt = V_c, so
    E = (Q / r) x paid out at every step (exact for RK4); and V_c' = (T_first - T_last - Q / r) r^2 / J."""
    asm = _with_station(mill3d, mode="drum", speed_times=(0.0,), speed_values=(0.5,), drum_radius=0.8,
                        drum_inertia=400.0, torque_limits=(0.0, 2e4))
    x0, u0 = mill3d.initial_state()
    x0[asm.body_state_size + SX_SPEED] = 0.5
    q = 3000.0
    sim = Simulator(asm, x0, mill3d.settings, np.concatenate([u0, [q]]))
    assert sim.control_labels[-1] == "generator_torque"
    dx = sim.rhs(sim.t, sim.state)
    ten = sim.tensions()
    assert dx[asm.body_state_size + SX_SPEED] == pytest.approx((ten[0] - ten[-1] - q / 0.8) * 0.8 ** 2 / 400.0,
                                                               rel=1e-12)
    sim.step(n_steps=int(round(30.0 / sim.settings.dt)))
    assert sim.generator_energy() == pytest.approx(q / 0.8 * sim.cable_paid_out(), rel=1e-12)
    with pytest.raises(ValueError, match="generator_torque = 30000.0 N m is outside"):
        sim.step(np.concatenate([u0, [3e4]]))


def test_bad_station_is_named():
    from laddermill_gym.model.station import StationParams

    with pytest.raises(ValueError, match=r"station.speed_times = \(0.0, 0.0\)"):
        StationParams(piece_length=70.0, speed_times=(0.0, 0.0), speed_values=(1.0, 2.0))
    with pytest.raises(ValueError, match="station.drum_inertia"):
        StationParams(piece_length=70.0, mode="drum", drum_inertia=0.0)


def test_commanded_speed_follows_a_first_order_lag(mill3d):
    """Commanded mode: V_c(t) = V_cmd + (V_0 - V_cmd) exp(-t / tau) (closed form, RK4 to 1e-9 m/s), the paid-out
    length its integral V_cmd t + tau (V_0 - V_cmd)(1 - exp(-t / tau)), and the power (T_first - T_last) V_c."""
    asm = _with_station(mill3d, mode="commanded", speed_times=(0.0,), speed_values=(1.0,), speed_time_constant=2.0,
                        speed_limits=(-1.0, 4.0))
    x0, u0 = mill3d.initial_state()
    x0[asm.body_state_size + SX_SPEED] = 1.0
    sim = Simulator(asm, x0, mill3d.settings, np.concatenate([u0, [3.0]]))
    assert sim.control_labels[-1] == "cable_speed_command"
    t = 10.0
    sim.step(n_steps=int(round(t / sim.settings.dt)))
    decay = np.exp(-t / 2.0)
    assert sim.cable_speed() == pytest.approx(3.0 + (1.0 - 3.0) * decay, abs=1e-9)
    assert sim.cable_paid_out() == pytest.approx(3.0 * t + 2.0 * (1.0 - 3.0) * (1.0 - decay), abs=1e-8)
    p = sim.generator_power()
    ten = sim.tensions()
    assert p["mechanical_W"] == pytest.approx((ten[0] - ten[-1]) * sim.cable_speed(), rel=1e-12)
    with pytest.raises(ValueError, match="cable_speed_command = 5.0 m/s is outside station.speed_limits"):
        sim.step(np.concatenate([u0, [5.0]]))
