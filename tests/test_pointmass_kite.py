"""Point-mass kite (Podgaets & Ockels 2007, eqs. 2-19) against closed forms: a kite at rest on a light tether
in a uniform wind lies along the resultant of lift, drag and weight (oracles.md: tan(elevation) = (L - W)/D),
lift tilted by the commanded roll; the podgaets_5km scene's held memory against the 40 MB budget."""

import math

import numpy as np
import pytest

from laddermill_gym.ladder.pointmass_scene import load_pointmass_scene
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.pointmass import PointMassKite, PointMassString, attitude_controls
from laddermill_gym.sim.pointmass import PointMassSimulator

V, RHO0, HB, G = 10.0, 1.225, 8400.0, 9.81


def _table():
    """alpha [deg], C_L, C_D read from the wing's CSV with numpy (not through the package's readers)."""
    path = CONFIG_DIR / "wings" / "meijaard_wing_aero.csv"
    rows = [ln for ln in path.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
    head = rows[0].split(",")
    data = np.array([[float(v) for v in r.split(",")] for r in rows[1:]])
    return data[:, head.index("alpha_deg")], data[:, head.index("CL")], data[:, head.index("CD")]


def _settled_kite(roll, pitch, mass=20.0, area=10.0, n_el=10, length=30.0):
    a, cl, cd = _table()
    kite = PointMassKite(name="t", mass=mass, area=area, alpha=np.radians(a), cl=cl, cd=cd)
    wind = WindParams(v0=V, h0=1e-3, v1=0.0, exponent=0.0, rho0=RHO0, scale_height=HB)  # uniform above 1 mm
    cab = CableSpec(diameter=0.001, mass_per_length=1e-5, EA=1e6, DA=1e2, cn0=0.0, ct0=0.0)
    s = PointMassString(wind=wind, gravity=G, cable=cab, element_length=length / n_el, n_nodes=n_el,
                        anchor=np.zeros(3), kite=kite, kite_nodes=np.array([n_el - 1]))
    x0 = np.zeros(s.state_size)
    r = np.arange(1, n_el + 1) * length / n_el
    x0[0::6], x0[2::6] = -r * 0.3, -r * 0.95
    sim = PointMassSimulator(s, x0, attitude_controls(1, roll, pitch, 0.0), dt=0.02, method="implicit")
    sim.advance(300.0, chunk=1000)  # the tethered point mass oscillates lightly damped (decay time about 30 s)
    assert np.abs(sim.velocities).max() < 1e-6
    return sim.positions[-1], kite


def test_static_kite_elevation_is_lift_minus_weight_over_drag():
    pitch = math.radians(6.0)  # on a grid point of the table: C_L, C_D exact there
    p, kite = _settled_kite(0.0, pitch)
    a, cl, cd = _table()
    i = int(np.argmin(abs(a - 6.0)))
    q = 0.5 * RHO0 * math.exp(p[2] / HB) * kite.area * V * V  # rho at h = -z
    L, D, W = q * cl[i], q * cd[i], kite.mass * G
    assert math.atan2(-p[2], -p[0]) == pytest.approx(math.atan2(L - W, D), abs=2e-5)  # the tether weighs 3e-3 N
    assert abs(p[1]) < 1e-9


def test_rolled_kite_leans_its_lift():
    """Roll phi tilts the span axis d = (sin th sin phi, cos phi, cos th sin phi): lift = q C_L (d x V)/V along
    (0, cos th sin phi, -cos phi) for air-relative velocity V = (V, 0, 0); alpha from tan a = tan th cos phi;
    the tether lies along the resultant with weight (z down)."""
    th, phi = math.radians(8.0), math.radians(15.0)
    p, kite = _settled_kite(phi, th)
    a, cl, cd = _table()
    alpha = math.degrees(math.atan(math.tan(th) * math.cos(phi)))
    q = 0.5 * RHO0 * math.exp(p[2] / HB) * kite.area * V * V
    f = q * (np.interp(alpha, a, cl) * np.array([0.0, math.cos(th) * math.sin(phi), -math.cos(phi)])
             - np.interp(alpha, a, cd) * np.array([1.0, 0.0, 0.0])) + np.array([0.0, 0.0, kite.mass * G])
    np.testing.assert_allclose(p / np.linalg.norm(p), f / np.linalg.norm(f), atol=2e-5)


def test_podgaets_scene_holds_at_most_40_mb():
    sc = load_pointmass_scene("podgaets_5km")
    s = sc.string
    assert (s.n_nodes, s.n_elements, s.n_kites) == (500_000, 500_000, 100)
    assert s.kite_nodes[-1] == s.n_nodes - 1 and np.all(np.diff(s.kite_nodes) == 5000)
    sim = PointMassSimulator(s, np.zeros(s.state_size), sc.controls, sc.dt, "implicit")
    b = sim.held_bytes()
    # 6 float64 per node, 1 float64 tension per element, a kite flag byte per node, elimination checkpoints
    assert b["state"] == 48 * 500_000
    assert b["total"] <= 40e6
