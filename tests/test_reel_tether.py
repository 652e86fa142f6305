"""The reeling multi-element tether (kernels/reel.py, model/reel.py, envs/pumping/reel_start.py): split and merge
against closed-form sums of mass and momentum, the pay-out rate against the winch's closed form, the kind against
the single-winch kind on the same chain, the ground contact against its closed forms, the catenary start against
the inextensible catenary."""

import math

import numpy as np
import pytest

from laddermill_gym.envs.pumping.reel_start import catenary_point, solve_catenary
from laddermill_gym.envs.pumping.winch_scene import load_pumping
from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.reel import contact_force, relabel
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.packing import pack_model
from laddermill_gym.model.reel import ground_contacts, nodes_in_air, stable_dt
from laddermill_gym.model.states import rotations_from_quaternions


@pytest.fixture(scope="module")
def reeling():
    ps = load_pumping("pumping_kite_reeling")
    x, u = ps.initial_state()
    return ps, ps.assembly, x, u


def _rest_lengths(asm, x):
    """Rest lengths [m] of the elements in the air, drum element first (module docstring of kernels/reel.py)."""
    st, o = asm.station, asm.body_state_size
    air = nodes_in_air(asm, x)
    ld = st.piece_length + x[o + C.SX_MOVED] - x[o + C.SX_TRANSFERS] * st.reel.element_length
    return np.array([ld] + [st.reel.element_length] * air)


def _mass_momentum(asm, x):
    """Tether mass mu sum(l) [kg] and momentum of the consistent mass, sum mu l (v_r + v_s) / 2, plus the wing's
    m v [kg m/s] (the ground end at rest, the top element's upper end the wing's attachment)."""
    n, air = asm.n_nodes, nodes_in_air(asm, x)
    mu = float(asm.elements.mu[0])
    base = C.B3_SIZE
    v_nodes = [np.zeros(3)] + [x[base + C.N3_SIZE * j + C.N3_VEL: base + C.N3_SIZE * j + C.N3_VEL + 3]
                               for j in range(n - air, n)]
    R = rotations_from_quaternions(x[C.B3_QUAT:C.B3_QUAT + 4].reshape(1, 4))[0]
    vb, w = x[C.B3_VEL:C.B3_VEL + 3], x[C.B3_RATE:C.B3_RATE + 3]
    v_top = R @ (vb + np.cross(w, asm.elements.attach[-1, 1]))
    ends = v_nodes + [v_top]
    lengths = _rest_lengths(asm, x)
    p = sum(mu * le * (ends[i] + ends[i + 1]) / 2 for i, le in enumerate(lengths))
    m_wing = asm.wing_types[0].mass
    return mu * lengths.sum(), p + m_wing * (R @ vb)


def _stirred(asm, x, drum_fraction, seed):
    """x with random velocities of the wing and the nodes in the air and the drum element at drum_fraction l_n."""
    rng = np.random.default_rng(seed)
    x = x.copy()
    n, air = asm.n_nodes, nodes_in_air(asm, x)
    x[C.B3_VEL:C.B3_VEL + 3] = rng.normal(0, 10, 3)
    x[C.B3_RATE:C.B3_RATE + 3] = rng.normal(0, 0.3, 3)
    for j in range(n - air, n):
        o = C.B3_SIZE + C.N3_SIZE * j + C.N3_VEL
        x[o:o + 3] = rng.normal(0, 10, 3)
    st = asm.station
    x[asm.body_state_size + C.SX_MOVED] = drum_fraction * st.reel.element_length - st.piece_length
    return x


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_split_keeps_mass_and_momentum(reeling, seed):
    """A split (drum element at f = split_fraction + 0.05 = 1.8 l_n) pays one node out onto the drum element's
    chord at l_n from the top, the drum element (f - 1) l_n after it; the tether's mass and the momentum
    (consistent mass + wing) unchanged."""
    _, asm, x0, _ = reeling
    M = pack_model(asm)
    f = asm.station.reel.split_fraction + 0.05
    x = _stirred(asm, x0, f, seed)
    air = nodes_in_air(asm, x)
    m0, p0 = _mass_momentum(asm, x)
    assert relabel(M.kind, x, M) == C.OK
    assert nodes_in_air(asm, x) == air + 1
    np.testing.assert_allclose(_rest_lengths(asm, x)[:2], [(f - 1) * 40.0, 40.0], rtol=1e-12)
    m1, p1 = _mass_momentum(asm, x)
    assert m1 == pytest.approx(m0, rel=1e-13)
    np.testing.assert_allclose(p1, p0, rtol=0, atol=1e-12 * np.abs(p0).max())
    k = asm.n_nodes - air - 1  # the new node: on the chord ground -> node above, at fraction (f - 1) / f of the way
    new, up = x[C.B3_SIZE + 6 * k: C.B3_SIZE + 6 * k + 3], x[C.B3_SIZE + 6 * (k + 1): C.B3_SIZE + 6 * (k + 1) + 3]
    np.testing.assert_allclose(new, (f - 1) / f * up, atol=1e-9)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_merge_keeps_mass_and_momentum(reeling, seed):
    """A merge (drum element at f = merge_fraction - 0.05 = 0.45 l_n) takes the lowest node onto the drum (at the
    ground point, at rest), the drum element (f + 1) l_n after it; mass and momentum unchanged."""
    _, asm, x0, _ = reeling
    M = pack_model(asm)
    f = asm.station.reel.merge_fraction - 0.05
    x = _stirred(asm, x0, f, seed)
    air = nodes_in_air(asm, x)
    m0, p0 = _mass_momentum(asm, x)
    assert relabel(M.kind, x, M) == C.OK
    assert nodes_in_air(asm, x) == air - 1
    assert _rest_lengths(asm, x)[0] == pytest.approx((f + 1) * 40.0, rel=1e-12)
    m1, p1 = _mass_momentum(asm, x)
    assert m1 == pytest.approx(m0, rel=1e-13)
    np.testing.assert_allclose(p1, p0, rtol=0, atol=1e-12 * np.abs(p0).max())
    k = asm.n_nodes - air
    assert np.all(x[C.B3_SIZE + 6 * k: C.B3_SIZE + 6 * k + 6] == 0.0)


def test_no_split_or_merge_between_the_thresholds(reeling):
    _, asm, x0, _ = reeling
    M = pack_model(asm)
    r = asm.station.reel
    for f in (r.merge_fraction + 0.01, 1.0, r.split_fraction - 0.01):
        x = _stirred(asm, x0, f, 0)
        before = x.copy()
        assert relabel(M.kind, x, M) == C.OK
        np.testing.assert_array_equal(x, before)


def test_paying_out_adds_elements_at_v_over_ln(reeling):
    """The winch reels out at V_cmd = 2 m/s (s = V (t - tau (1 - e^(-t/tau)))): nodes go into the air when the drum
    element passes a l_n, (a + 1) l_n, ... (a = split_fraction): m(t) = floor((l_p + s - a l_n) / l_n) + 1, a rate
    of V / l_n. The static wing sinks meanwhile and the lowest node touches the ground (a contact: the run goes
    on)."""
    ps, asm, x, u = reeling
    u = u.copy()
    u[-1] = 2.0
    sim = ps.simulator(x, u)
    tau, ln, lp, a = ps.winch.speed_time_constant, 40.0, asm.station.piece_length, asm.station.reel.split_fraction
    rows = []
    for _ in range(90):
        sim.advance_to(sim.t + 1.0)
        rows.append((sim.t, nodes_in_air(asm, sim.state) - asm.station.nodes_in_air, ground_contacts(asm, sim.state)))
    t, m, contacts = np.array(rows).T
    s = 2.0 * (t - tau * (1 - np.exp(-t / tau)))
    expect = np.maximum(np.floor((lp + s - a * ln) / ln) + 1, 0)
    np.testing.assert_array_equal(m, expect)
    assert m[-1] == 5  # s = 179 m: nodes out at s = 10, 50, 90, 130 and 170 m
    assert contacts.max() >= 1 and sim.ground_contacts() == contacts[-1]


def test_same_as_the_winch_kind_without_relabelling():
    """With no node on the drum (max_length = the start) and no split in reach, the reeling kind is the winch kind
    (kernels/winch.py) on the same 3-element chain: the same trajectory over 2 s of reel-out at 1 m/s."""
    reel = load_pumping("pumping_kite_reeling", reeling={"element_length": 100.0, "max_length": 300.0, "dt": 0.005})
    plain = load_pumping("pumping_kite", elements_per_piece=3)
    x, u = reel.initial_state()
    assert reel.assembly.n_nodes == plain.assembly.n_nodes == 2
    u = u.copy()
    u[-1] = 1.0
    a, b = reel.simulator(x, u), plain.simulator(x.copy(), u.copy())
    a.advance_to(2.0)
    b.advance_to(2.0)
    np.testing.assert_allclose(a.state, b.state, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(a.tensions(), b.tensions(), rtol=1e-10)


def test_contact_force_closed_forms():
    """Penalty spring-damper: a node of mass m at rest at depth g / omega^2 carries its weight m g; sliding faster
    than the slip speed the friction is mu F_n against the motion; above the ground, nothing."""
    rl = np.zeros(C.RL_SIZE)
    rl[C.RL_OMEGA], rl[C.RL_ZETA], rl[C.RL_MU], rl[C.RL_VSLIP] = 20.0, 1.0, 0.5, 0.1
    m, g = 12.0, 9.80665
    fx, fy, fz = contact_force(rl, m, g / 400.0, 0.0, 0.0, 0.0)
    assert (fx, fy) == (0.0, 0.0) and fz == pytest.approx(-m * g, rel=1e-14)
    fx, fy, fz = contact_force(rl, m, 0.01, 0.5, 3.0, -4.0)
    fn = m * (400.0 * 0.01 + 2.0 * 20.0 * 0.5)
    assert fz == pytest.approx(-fn) and math.hypot(fx, fy) == pytest.approx(0.5 * fn)
    assert fx / fy == pytest.approx(3.0 / -4.0)
    assert contact_force(rl, m, -0.01, 1.0, 3.0, 0.0) == (0.0, 0.0, 0.0)
    assert contact_force(rl, m, 0.001, -10.0, 0.0, 0.0) == (0.0, 0.0, 0.0)  # leaving fast: no pull


def test_catenary_against_the_inextensible_one():
    """With EA -> infinity the elastic catenary is a cosh(x / a) with a = H / w: its length L, span D and rise h
    obey sqrt(L^2 - h^2) = 2 a sinh(D / (2 a)); the solved ends are the given ones."""
    w, length, span, rise = 2.94, 300.0, 120.0, 250.0
    h, v = solve_catenary(span, rise, length, w, 1e16)
    a = h / w
    assert math.sqrt(length ** 2 - rise ** 2) == pytest.approx(2 * a * math.sinh(span / (2 * a)), rel=1e-8)
    x, z = catenary_point(length, h, v, w, 1e16)
    assert (x, z) == (pytest.approx(span, rel=1e-9), pytest.approx(rise, rel=1e-9))


def test_bad_reeling_fields_are_named():
    with pytest.raises(ConfigError, match="merge_fraction"):
        load_pumping("pumping_kite_reeling", reeling={"merge_fraction": 0.8})
    with pytest.raises(ConfigError, match="no 'reeling' section"):
        load_pumping("pumping_kite", reeling={"element_length": 50.0})


def test_stable_dt_resolves_the_highest_axial_mode():
    """omega_max = (2 / l) sqrt(3 EA / mu) of a taut consistent-mass chain: 735 rad/s at 40 m of the 25 mm tether;
    the step kept is the largest of the list with omega_max dt <= 2."""
    w = 2.0 / 40.0 * math.sqrt(3 * 2.16e7 / 0.3)
    assert w == pytest.approx(734.8, abs=0.1)
    assert stable_dt(40.0, 2.16e7, 0.3) == 0.0025 and 0.0025 * w <= 2.0 < 0.005 * w
    assert stable_dt(100.0, 2.16e7, 0.3) == 0.005
    with pytest.raises(ValueError, match="need a step below"):
        stable_dt(1.0, 2.16e7, 0.3)


@pytest.mark.parametrize("case", [(110.0, 0.0, 651.998593, 550.0), (120.0, 30.0, 517.6813, 399.2525)])
def test_catenary_solver_against_irvines_cases(case):
    """The start's catenary solver against the two elastic catenaries of shared/design/oracles.md ("Elastic
    catenary", solved independently; tests/test_catenary.py holds the rigid chain to them): w = 10 N/m, EA = 1e6 N,
    span 100 m; L0 = 110 m level (H = 651.998593 N, V = 550 N) and L0 = 120 m with B 30 m up (H = 517.6813 N,
    V_A = 399.2525 N). V here is the lower end's upward pull, minus the reaction's vertical part at A."""
    length, rise, h_ref, v_ref = case
    h, v = solve_catenary(100.0, rise, length, 10.0, 1e6)
    assert h == pytest.approx(h_ref, rel=1e-6)
    assert -v == pytest.approx(v_ref, rel=1e-6)


@pytest.mark.parametrize("case", ["level", "inclined"])
def test_hanging_tether_of_5_and_10_elements_is_the_catenary(case):
    """A tether of 5 and of 10 sag-corrected elements (the reeling tether's elements) hanging between two fixed
    points in static equilibrium (tests/test_catenary.py's Newton solve) against Irvine's elastic catenary: the
    horizontal tension within 1.2 % at 5 elements and 0.3 % at 10, the error falling as 1/n^2 (ratio 3-5)."""
    from tests.test_catenary import INCLINED, LEVEL, equilibrium

    c = LEVEL if case == "level" else INCLINED
    err = [abs(equilibrium(n, c["L0"], c["rise"], True)["H"] / c["H"] - 1.0) for n in (5, 10)]
    print(f"{case}: horizontal tension off by {100 * err[0]:.2f} % at 5 elements, {100 * err[1]:.2f} % at 10")
    assert err[0] < 0.012 and err[1] < 0.003
    assert 3.0 < err[0] / err[1] < 5.0


@pytest.mark.slow
def test_crosswind_cycles_from_200_to_500_m_keep_five_elements():
    """Crosswind cycles from a 200 m tether out to 500 m and back on 40 m elements (tether_convergence
    --start-length 200): at least 5 elements at every length (the layout's rule: 200 m is 5 elements of 40 m), up to
    13, no failure, the tether through the whole range."""
    from laddermill_gym.studies.pumping.tether_convergence import tether_run

    r = tether_run(40.0, cycles=1, start=200.0)
    assert r["elements_min"] >= 5 and r["elements_max"] >= 12
    assert r["tether_min_m"] <= 200.0 and r["tether_max_m"] >= 500.0
    assert r["power_W"] > 0.0


@pytest.mark.slow
def test_cycle_power_converges_in_the_element_length():
    """The crosswind cycle's net power on 40 m elements within 1 % of that on 30 m elements (measured: 0.16 %), and
    60 m within 1 % of 40 m (0.34 %): the element count is converged at the config's 40 m."""
    from laddermill_gym.studies.pumping.tether_convergence import tether_run

    p = {ln: tether_run(ln, cycles=1)["power_W"] for ln in (60.0, 40.0, 30.0)}
    assert abs(p[40.0] / p[30.0] - 1.0) < 0.01
    assert abs(p[60.0] / p[40.0] - 1.0) < 0.01


def test_the_task_reports_elements_and_ground_contacts():
    """PumpingTask on the reeling config: info carries the elements in the air and the nodes on the ground (those of
    the state: model.reel's counts); the single-element config's info has neither key."""
    from laddermill_gym.envs.pumping.task import PumpingTask

    task = PumpingTask(1, config="pumping_kite_reeling", episode_time=10.0)
    task.reset(np.ones(1, bool), [np.random.default_rng(0)])
    a = np.zeros((1, task.n_actions))
    a[:, -1] = 0.5  # reel out at 5 m/s
    for _ in range(80):  # 4 s: s = 5 (4 - tau (1 - e^(-4/tau))) = 17.5 m, past the first split at 10 m
        info = task.step(a)[3]
    asm, x = task.batch.assembly, task.batch.states[0]
    assert info["tether_elements"][0] == nodes_in_air(asm, x) + 1 == 8  # 7 at the start
    assert info["tether_ground_contacts"][0] == ground_contacts(asm, x)
    plain = PumpingTask(1, config="pumping_kite", episode_time=10.0)
    plain.reset(np.ones(1, bool), [np.random.default_rng(0)])
    assert "tether_elements" not in plain.step(a)[3]
