"""The moving cable at the point-mass fidelity (docs/pointmass.md, "The moving cable"), against oracles: the fixed
two-ground-point string (V_c = 0), the steady pay-out of a straight string (closed form), the rigid mill's cable
length, the generator power from the observed tensions, the rigid mill's speed schedule, and the rigid mill's
periodic power and tensions (slow)."""

import math

import numpy as np
import pytest

from laddermill_gym.kernels.contract import N3_SIZE, SP_NSCHED, SP_SCHED
from laddermill_gym.ladder.pointmass_mill import mill_simulator
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.pointmass import PointMassKite, PointMassString
from laddermill_gym.model.pointmass_mill import PointMassStation, mill_layout, pack_pm_station
from laddermill_gym.model.station import StationParams, pack_station
from laddermill_gym.sim.pointmass import PointMassSimulator
from laddermill_gym.sim.pointmass_mill import PointMassMillSimulator

EA, MU = 2.16e7, 0.3  # [N], [kg/m] the laddermill's 2.5 cm Dyneema (configs/cables/dyneema_25mm.yaml)


def straight_string(v_c, da=2.16e4, le=1.0, per=10, nk=8, eps=1e-3, method="implicit", dt=0.01, insertion="cable"):
    """A string without gravity or air between two ground points pulled to the strain eps, kites (54 kg, no
    aerodynamics) every ``per`` nodes, started in the steady pay-out: every node at V_c (1 + eps) along the line."""
    cable = CableSpec(diameter=0.025, mass_per_length=MU, EA=EA, DA=da, breaking_load=5e5, cn0=0.0, ct0=0.0)
    wind = WindParams(v0=1.0, h0=10.0, v1=0.0, exponent=0.0, rho0=1e-12)
    al = np.linspace(-np.pi, np.pi, 181)
    kite = PointMassKite("mass only", 54.0, 1.0, al, np.zeros_like(al), np.zeros_like(al))
    n, a, b = nk * per, 0.1 * le, 1.1 * le
    length = a + b + (n - 1) * le
    d = length * (1.0 + eps)
    s = PointMassString(wind=wind, gravity=0.0, cable=cable, element_length=le, n_nodes=n,
                        anchor=np.array([0.0, 0.0, -100.0]), end=np.array([d, 0.0, -100.0]), kite=kite,
                        kite_nodes=3 + per * np.arange(nk))
    x = np.zeros(s.state_size)
    xs = x.reshape(-1, N3_SIZE)
    xs[:, 0] = (a + le * np.arange(n)) * (1.0 + eps)
    xs[:, 2] = -100.0
    xs[:, 3] = v_c * (1.0 + eps)
    st = PointMassStation(le, a, b, (0.0,), (v_c,), insertion=insertion)
    return PointMassMillSimulator(s, st, x, np.zeros(3 * nk), dt, method), length


@pytest.mark.parametrize("v_c", [2.0, -2.0])
def test_steady_pay_out_of_a_straight_string(v_c):
    """Closed form: the string moving through the station at V_c stays straight at the strain the ground points
    impose, every node at V_c (1 + eps), the tension EA eps everywhere, across node insertions both ways."""
    sim, _ = straight_string(v_c)
    sim.advance(3.0)  # six node transfers
    assert sim.transfers() == (6 if v_c > 0 else -7)  # backwards: s < 0 after the first step, a transfer at once
    np.testing.assert_allclose(sim.tensions(), EA * 1e-3, rtol=1e-7)
    np.testing.assert_allclose(sim.velocities[:, 0], v_c * 1.001, rtol=1e-8)
    assert np.max(np.abs(sim.velocities[:, 1:])) < 1e-12
    p = sim.generator_power()
    assert abs(p["mechanical_W"]) < 1e-6 * EA * 1e-3 * abs(v_c)


@pytest.mark.parametrize("insertion", ["cable", "paper"])
def test_insertion_rule_of_the_new_node(insertion):
    """``station.insertion`` at this fidelity: right after the first transfer the new node 0 sits at the fraction f =
    (a + s) / (a + s + l_e) of the way to node 1 and moves at u + f (v_1 - u), u the material's velocity at the
    ground point: V_c (l / l0) = V_c (1 + eps) along the string with the cable's rule (the steady pay-out kept), 0
    with the paper's (the node at f v_1, about V_c / 11)."""
    sim, _ = straight_string(2.0, insertion=insertion)
    while sim.transfers() == 0:
        sim.step()
    le, a = 1.0, 0.1
    f = (a + sim.moved()) / (a + sim.moved() + le)
    v1 = sim.velocities[1, 0]
    u = 2.0 * 1.001 if insertion == "cable" else 0.0
    assert sim.velocities[0, 0] == pytest.approx(u + f * (v1 - u), rel=1e-9)
    assert (abs(sim.velocities[0, 0] - 2.002) < 1e-6) == (insertion == "cable")
    # the first two elements' tensions just after the transfer against the steady EA eps: the paper's slow node
    # leaves element 0 slack and stretches element 1
    t0, t1, steady = sim.tensions()[0], sim.tensions()[1], EA * 1e-3
    print(f"insertion {insertion}: element 0 {t0 / 1e3:.3g} kN, element 1 {(t1 - steady) / 1e3:.3g} kN over the "
          f"steady {steady / 1e3:.3g} kN")
    if insertion == "cable":
        assert t0 == pytest.approx(steady, rel=1e-7) and t1 == pytest.approx(steady, rel=1e-7)
    else:
        assert t0 == 0.0 and t1 > 1.5 * steady


def test_steady_pay_out_explicit():
    """The explicit method (undamped string, step below l0 / c of the shortest end element) holds the same state."""
    sim, _ = straight_string(2.0, da=0.0, method="explicit", dt=5e-6)
    sim.advance(0.6)
    assert sim.transfers() == 1
    np.testing.assert_allclose(sim.tensions(), EA * 1e-3, rtol=1e-5)
    np.testing.assert_allclose(sim.velocities[:, 0], 2.002, rtol=1e-7)


def test_kites_advance_one_piece_per_period_and_mass_is_conserved():
    """Geometry oracle: over one period l0 / V_c every kite rides l0 (1 + eps) along the cable and each slot then
    holds the kite of the slot below it (the last one round the station into slot 0). The cable between the
    ground points keeps its unstretched length and mass through every node insertion (to round-off)."""
    sim, length = straight_string(2.0)
    per, le = 10, 1.0
    p0, who0 = sim.kite_positions(), sim.slot_kites()
    m_cable = sim.node_masses() - 54.0 * np.isin(np.arange(sim.string.n_nodes), sim.kite_nodes)
    for _ in range(per):
        sim.advance(le / 2.0)
        assert abs(sim.cable_length() - length) < 1e-12 * length
        first, last = sim.rest_lengths()
        m_now = sim.node_masses() - 54.0 * np.isin(np.arange(sim.string.n_nodes), sim.kite_nodes)
        # node shares plus the halves of the end elements at the ground points: mu times the cable length
        assert abs(m_now.sum() + MU * (first + last) / 2 - MU * length) < 1e-12 * MU * length
    assert abs(m_now.sum() - m_cable.sum()) < 1e-12 * m_cable.sum()
    assert sim.transfers() == per and sim.kite_transfers() == 1
    p1, who1 = sim.kite_positions(), sim.slot_kites()
    np.testing.assert_array_equal(who1, np.roll(who0, 1))
    moved = p1[1:] - p0[:-1]  # the kite of slot k is now in slot k + 1
    np.testing.assert_allclose(moved[:, 0], per * le * 1.001, rtol=1e-9)
    np.testing.assert_allclose(moved[:, 1:], 0.0, atol=1e-9)


def small_mill(element_length=7.0, n_wings=11):
    return load_scene("laddermill", fidelity="pointmass", element_length=element_length, n_wings=n_wings)


def test_zero_speed_equals_the_fixed_string():
    """V_c = 0 with both end elements at l_e: the moving-cable driver steps exactly the fixed two-ground-point
    string (``ladder_chain`` at one 70 m element per piece, from its rigid equilibrium) of the plain point-mass
    simulator, an independent path round the station code."""
    sc = load_scene("ladder_chain", fidelity="pointmass", element_length=70.0)
    x, u = sc.initial_state()
    le = sc.string.element_length
    fixed = PointMassSimulator(sc.string, x, u, sc.dt)
    mill = PointMassMillSimulator(sc.string, PointMassStation(le, le, le), x, u, sc.dt)
    fixed.advance(5.0)
    mill.advance(5.0)
    np.testing.assert_array_equal(mill.x, fixed.x)  # bit for bit
    assert np.max(np.abs(mill.x - x)) > 1e-2  # it moved
    assert mill.generator_energy() == 0.0 and mill.transfers() == 0


def test_zero_speed_equals_the_fixed_string_with_other_end_lengths():
    """The same with the mill's own end elements (7 m elements, first 7 m, last 14 m): the plain simulator with
    those two rest lengths set in its packed slots."""
    from laddermill_gym.kernels.contract import PP_L_FIRST, PP_L_LAST

    sc = small_mill()
    x, u = mill_simulator(sc, "static").x.copy(), sc.controls
    st = sc.station
    fixed = PointMassSimulator(sc.string, x, u, sc.dt)
    fixed.M.par[PP_L_FIRST], fixed.M.par[PP_L_LAST] = st.first_length, st.last_length
    mill = PointMassMillSimulator(sc.string, PointMassStation(st.element_length, st.first_length, st.last_length),
                                  x, u, sc.dt)
    fixed.advance(2.0)
    mill.advance(2.0)
    np.testing.assert_array_equal(mill.x, fixed.x)  # bit for bit
    assert np.max(np.abs(mill.x - x)) > 1e-3


def test_power_is_the_tension_difference_times_the_speed():
    """Per step, the energy the station books equals dt (T_first - T_last) V_c with the tensions observed before
    the step (``tensions()``, damped) and V_c from the file's schedule (numpy)."""
    sc = small_mill()
    sim = mill_simulator(sc, "static")
    sim.advance(20.0)  # into the ramp: V_c = 1.33 m/s
    for _ in range(50):
        te, v, e0 = sim.tensions(), sc.station.speed(sim.t), sim.generator_energy()
        p = sim.generator_power()
        assert p["tension_first_N"] == pytest.approx(te[0], rel=1e-12)
        assert p["mechanical_W"] == pytest.approx((te[0] - te[-1]) * v, rel=1e-9)
        sim.step()
        assert sim.generator_energy() - e0 == pytest.approx(sim.dt * (te[0] - te[-1]) * v, rel=1e-9)


def test_schedule_matches_the_rigid_station():
    from laddermill_gym.kernels.pointmass.mill import schedule_speed
    from laddermill_gym.kernels.station import scheduled_speed

    rigid = StationParams(piece_length=70.0, speed_times=(0.0, 30.0, 50.0), speed_values=(0.0, 2.0, 1.0))
    sp_r = pack_station(rigid, 3, 0, 0)
    sp_p = pack_pm_station(PointMassStation(1.0, 0.1, 1.1, rigid.speed_times, rigid.speed_values))
    assert sp_p[SP_NSCHED] == 3 and np.all(sp_p[SP_SCHED:] == sp_r[SP_SCHED:])
    for t in (-1.0, 0.0, 12.3, 30.0, 41.0, 50.0, 99.0):
        assert schedule_speed(sp_p, t) == scheduled_speed(sp_r, t)[0] == pytest.approx(rigid.speed(t), abs=1e-12)


@pytest.mark.parametrize("el", [70.0, 35.0, 7.0, 1.0])
def test_layout_holds_the_rigid_cable(el):
    """The point-mass mill between the ground points holds the rigid mill's cable, (n_k + 0.2) l0, with its kites
    where the wings sit along it: the first at 0.1 l0 from the veered ground point, the last 1.1 l0 from the
    hauled one, the end elements the rigid mill's 7 m (+ one element at the hauled end); one element per piece is
    the rigid layout itself."""
    lay = mill_layout(101, 70.0, el, 0.1, 1.1)
    per = round(70.0 / el)
    assert lay.n_nodes == 101 * per
    total = lay.first_length + lay.last_length + (lay.n_nodes - 1) * el
    assert total == pytest.approx(101.2 * 70.0, rel=1e-12)
    assert lay.first_length + lay.kite_nodes[0] * el == pytest.approx(7.0, rel=1e-12)
    assert lay.last_length + (lay.n_nodes - 1 - lay.kite_nodes[-1]) * el == pytest.approx(77.0, rel=1e-12)
    assert lay.first_length == pytest.approx(7.0) and lay.last_length == pytest.approx(7.0 + el)


def test_scene_switch_by_keyword_and_by_yaml():
    a = load_scene("laddermill", fidelity="pointmass", element_length=70.0)
    b = load_scene("laddermill", overrides={"fidelity": {"wing": "pointmass", "element_length": 70.0}})
    for sc in (a, b):
        assert sc.station is not None and sc.string.n_nodes == 101 and sc.string.n_kites == 101
        assert (sc.station.first_length, sc.station.last_length) == pytest.approx((7.0, 77.0))
        assert sc.station.speed(30.0) == 2.0


def test_bad_station_is_refused():
    with pytest.raises(ValueError, match="last_length"):
        PointMassStation(1.0, 0.1, 0.5, (0.0,), (2.0,))
    with pytest.raises(ValueError, match="last_length"):
        PointMassStation(1.0, 0.1, 0.9, (0.0,), (-2.0,))
    with pytest.raises(ValueError, match="first_length"):
        PointMassStation(1.0, 0.0, 1.1, (0.0,), (2.0,))


@pytest.mark.slow
def test_periodic_power_and_tension_against_the_rigid_mill():
    """From the rigid mill's periodic operating point (66 kW; first element 160 kN, last 127 kN) the point-mass
    mill at one element per piece settles to its own periodic motion with more power: no tail, so every kite
    keeps the wing table's full lift (the rigid wings' elevator tail takes 9.6 % of it on the ascending side,
    docs/pointmass.md); the difference is stated there, checked here within the measured band."""
    from laddermill_gym.ladder.pointmass_mill import rigid_periodic, run_pointmass_periodic

    sc = load_scene("laddermill", fidelity="pointmass", element_length=70.0)
    rigid = rigid_periodic(str(sc.file), 101)[2]
    res = run_pointmass_periodic(mill_simulator(sc), max_time=1500.0)
    assert res.converged, res.summary()
    assert 1.0 < res.mean_power_W / rigid.mean_power_W < 2.0
    assert math.isclose(res.tension_first_N, rigid.tension_mean_N[0], rel_tol=0.25)
    assert math.isclose(res.tension_last_N, rigid.tension_mean_N[-1], rel_tol=0.25)
