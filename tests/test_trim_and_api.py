"""The trim solver against static force balance, the python-control contract, and the in-plane mode."""

from __future__ import annotations

import dataclasses

import control
import numpy as np
import pytest

from laddermill_gym import reference as ref
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.states import planar_from_3d, planar_to_3d


@pytest.fixture(scope="module")
def bare_tether():
    """The default tethered wing on a single, (almost) massless element without cable aerodynamics:
    the straight-tether case of the kite force-balance oracle."""
    scene = load_scene("tethered_wing", elements_per_piece=1, cable_aero=False)
    a = scene.assembly
    el = dataclasses.replace(a.elements, mu=np.full(a.elements.count, 1e-9))
    return scene.replace(assembly=dataclasses.replace(a, elements=el))


def test_trimmed_tether_elevation_matches_force_balance(bare_tether):
    """Static kite on a straight tether: tan(elevation) = (L - W)/D (oracles.md), with L and D computed by
    the independent numpy reference at the trim state."""
    x, u = bare_tether.initial_state()
    a = bare_tether.assembly
    wt = a.wing(0)
    R = ref.rotation(x[3:7])
    F, _, _, _, _ = ref.wing_aero(wt, x[0:3], R, x[7:10], x[10:13], u[0:3], a.wind, 0.0)
    Fg = R @ F
    D, L = -Fg[0], -Fg[2]  # wind blows along -x; z is down
    W = wt.mass * a.gravity
    attach = x[0:3] + R @ wt.attachment
    station = bare_tether.ground_points["station"]
    d = attach - station
    elevation = np.arctan2(-d[2], abs(d[0]))
    assert abs(d[1]) < 1e-6
    assert np.tan(elevation) == pytest.approx((L - W) / D, rel=1e-6)
    sim = bare_tether.simulator(x, u)
    alpha = sim.wing_alpha_beta()[0, 0]
    assert alpha == pytest.approx(bare_tether.initial.alpha, abs=1e-8)
    assert np.max(np.abs(sim.rhs(0.0, x, u)[7:13])) < 1e-6, "the trim state is at rest"


def test_rhs_works_with_python_control(bare_tether):
    """control.nlsys takes Simulator.rhs as its updfcn and linearize returns the Jacobian, which matches
    central differences of the independent numpy reference."""
    x, u = bare_tether.initial_state()
    sim = bare_tether.simulator(x, u)
    sys = control.nlsys(sim.rhs, None, states=sim.n_state, inputs=sim.n_controls, name="tethered_wing")
    lin = control.linearize(sys, x, u)
    a = bare_tether.assembly
    A_ref = np.zeros((sim.n_state, sim.n_state))
    for j in range(sim.n_state):
        h = 1e-6 * max(1.0, abs(x[j]))
        xp, xm = x.copy(), x.copy()
        xp[j] += h
        xm[j] -= h
        A_ref[:, j] = (ref.reference_rhs(0.0, xp, u, a) - ref.reference_rhs(0.0, xm, u, a)) / (2 * h)
    scale = np.max(np.abs(A_ref))
    assert np.max(np.abs(lin.A - A_ref)) < 1e-4 * scale
    assert lin.B.shape == (sim.n_state, sim.n_controls)


def test_3d_started_in_plane_stays_in_plane_and_matches_2d():
    """A 3D run from an in-plane state keeps y, roll, yaw and the lateral rates at round-off and equals the
    in-plane mode's run to 1e-9 (Meijaard et al.: the 2D and 3D programmes agree in plane)."""
    scene3 = load_scene("tethered_wing")
    scene2 = load_scene("tethered_wing", dimension=2)
    x3, u = scene3.initial_state()
    a = scene3.assembly
    x2 = planar_from_3d(x3, a.n_wings, a.n_nodes)
    x2[4] += 0.5     # disturb in the plane: body w [m/s]
    x2[5] += 0.05    # pitch rate [rad/s]
    x3 = planar_to_3d(x2, a.n_wings, a.n_nodes)
    sim3 = scene3.simulator(x3, u)
    sim2 = scene2.simulator(x2, u)
    for _ in range(10):
        sim3.step(n_steps=100)
        sim2.step(n_steps=100)
        lateral = np.concatenate([sim3.wing_positions()[:, 1], sim3.wing_euler()[:, [0, 2]].ravel(),
                                  sim3.wing_velocities()[:, 1], sim3.wing_rates()[:, [0, 2]].ravel(),
                                  sim3.node_positions()[:, 1]])
        assert np.max(np.abs(lateral)) < 1e-12
        back = planar_from_3d(sim3.state, a.n_wings, a.n_nodes)
        np.testing.assert_allclose(back, sim2.state, rtol=0, atol=1e-9 * np.max(np.abs(sim2.state)))
