"""Initial states of chain scenes with several cable elements per piece (issue 13).

Oracles: the equations of motion themselves (every body's acceleration from ``Simulator.rhs`` at the state found,
and a short integration that must stay at rest); Irvine's (1981) closed-form elastic catenary through each piece's
end points (the nodes of a piece carrying only its weight, ``cable_aero`` off); and the O(1/n^2) convergence law of
a discrete chain to that catenary (the wing and the ground tension with n elements per piece approach their limit
as C / n^2, so they differ from the one-element solution by at most its own discretisation error C).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest
from scipy.optimize import fsolve

from laddermill_gym.kernels.contract import N3_VEL
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.states import rotation_from_euler
from laddermill_gym.sim.statics import accelerations, mass_scales, rest_acceleration

#: RK4 steps the scenes accept with 8 elements per piece (ladder/rigid_scene._refuse_impossible_step) [s]
DT = {"tethered_wing": 0.0005, "ladder_chain": 0.001}


@functools.cache
def solved(name: str, n: int, cable_aero: bool | None = None):
    """(scene, simulator at the initial state) of scene ``name`` with n elements per piece."""
    scene = load_scene(name, elements_per_piece=n, cable_aero=cable_aero, dt=DT[name])
    x, u = scene.initial_state()
    return scene, scene.simulator(x, u)


def _check_at_rest(sim):
    """Every body's acceleration below 1e-4 m/s^2 (rad/s^2), the mass-weighted RMS below 1e-6 m/s^2 (the
    solver's acceptance, sim/statics.py), and every body's unbalanced force below 1e-8 of the largest tension."""
    acc = accelerations(sim, sim.rhs(0.0, sim.state, sim.controls))
    print(f"{sim.assembly.n_wings} wings, {sim.assembly.n_nodes} nodes: largest acceleration "
          f"{np.max(np.abs(acc)):.2g}, mass-weighted RMS {rest_acceleration(sim, acc):.2g} m/s^2")
    assert np.max(np.abs(acc)) < 1e-4, np.max(np.abs(acc))
    assert rest_acceleration(sim, acc) < 1e-6
    force = mass_scales(sim) * acc
    nw = sim.assembly.n_wings
    lin = np.concatenate([force[: 6 * nw].reshape(nw, 6)[:, :3].ravel(), force[6 * nw:]])
    assert np.max(np.abs(lin)) < 1e-8 * np.max(sim.tensions())


@pytest.mark.parametrize("name, n", [("tethered_wing", 2), ("tethered_wing", 4), ("tethered_wing", 8),
                                     ("ladder_chain", 2), ("ladder_chain", 4)])
def test_initial_state_is_at_rest(name, n):
    scene, sim = solved(name, n)
    _check_at_rest(sim)
    if scene.initial.method == "trim":  # the trimmed wing flies at the scene's angle of attack
        assert sim.wing_alpha_beta()[0, 0] == pytest.approx(scene.initial.alpha, abs=1e-8)


@pytest.mark.slow
def test_ladder_chain_eight_elements_at_rest():
    _check_at_rest(solved("ladder_chain", 8)[1])


def _irvine(span: float, rise: float, L0: float, w: float, EA: float):
    """Horizontal and vertical tension (H, V) [N] at the lower end A of an elastic catenary (Irvine 1981, eqs.
    2.23-2.24) of unstretched length L0 [m] and weight w [N/m] whose upper end is ``span`` across and ``rise``
    above A [m]; and its shape (x, z_up) [m] at unstretched arc length s from A."""
    def shape(s, H, V):
        x = H * s / EA + H / w * (np.arcsinh((V + w * s) / H) - np.arcsinh(V / H))
        z = (V * s + 0.5 * w * s * s) / EA + H / w * (np.hypot(1.0, (V + w * s) / H) - np.hypot(1.0, V / H))
        return x, z

    H, V = fsolve(lambda p: np.array(shape(L0, *p)) - [span, rise], [0.1 * w * L0, w * L0], xtol=1e-13)
    return H, V, functools.partial(shape, H=H, V=V)


def _piece_against_catenary(n: int):
    """Largest distance [m] of the free nodes of the tethered wing's cable (weight only) from Irvine's catenary
    through its ends, and the relative errors of the ground reaction's H and V."""
    scene, sim = solved("tethered_wing", n, cable_aero=False)
    a = scene.assembly
    att = sim.wing_positions()[0] + rotation_from_euler(*sim.wing_euler()[0]) @ a.wing(0).attachment
    w, EA, L0 = a.elements.mu[0] * a.gravity, a.elements.EA[0], scene.piece_length
    H, V, shape = _irvine(-att[0], -att[2], L0, w, EA)  # the wing flies upwind (-x) and up (-z) of the station
    nodes = sim.node_positions()
    xs, zs = shape(np.arange(1, n) * L0 / n)
    dev = np.max(np.hypot(-nodes[:, 0] - xs, -nodes[:, 2] - zs))
    e0 = nodes[0] / np.linalg.norm(nodes[0])
    T0 = sim.tensions()[0]  # element 0; the support also carries half its weight
    return dev, -T0 * e0[0] / H - 1.0, (-T0 * e0[2] - 0.5 * w * L0 / n) / V - 1.0


def test_nodes_on_the_elastic_catenary():
    """Nodes within 2e-3 m / n^2 of Irvine's catenary through the piece's ends (measured 3.6e-4, 8.6e-5, 2.1e-5 m
    at n = 2, 4, 8: the O(1/n^2) law with C = 1.4e-3 m), the error falling as n^-2, and the ground reaction's H and
    V within 5e-3 / n^2 relative (measured C = 1.0e-3 for H, 3.4e-3 to 3.8e-3 for V at n = 2 to 16)."""
    errs = {n: _piece_against_catenary(n) for n in (2, 4, 8)}
    for n, (dev, eh, ev) in errs.items():
        print(f"n = {n}: nodes within {dev:.3g} m of the catenary; H, V errors {eh:.3g}, {ev:.3g} (times n^2: "
              f"{eh * n**2:.3g}, {ev * n**2:.3g})")
        assert dev < 2e-3 / n**2, (n, dev)
        assert abs(eh) < 5e-3 / n**2 and abs(ev) < 5e-3 / n**2, (n, eh, ev)
    slope = np.polyfit(np.log([2, 4, 8]), np.log([errs[n][0] for n in (2, 4, 8)]), 1)[0]
    print(f"slope {slope:.3f}")
    assert -2.2 < slope < -1.8, slope


def _station_reaction(a, tension: float, far: np.ndarray) -> np.ndarray:
    """Force (3,) [N] (global, z down) of the first element, from the station at the origin to ``far`` [m], on the
    station: its tension along its chord plus the share of its loads the kernels lump at its ends (eq. 24 and
    docs/model.md: half its weight, and (l/6)(2 p_r + p_s) of its aerodynamic loads per length p at the ends)."""
    from laddermill_gym.kernels.cable import aero_load
    from laddermill_gym.kernels.wind import density, wind_at
    from laddermill_gym.model.packing import wind_fields

    ln = float(np.linalg.norm(far))
    e = far / ln
    out = tension * e + np.array([0.0, 0.0, 0.5 * a.elements.mu[0] * a.elements.l0[0] * a.gravity])
    if a.cable_aero:
        wf = wind_fields(a.wind)
        p = [np.array(aero_load(*wind_at(z, wf, 1.0, 0.0), *e, density(-z, wf), a.elements.diameter[0],
                                a.cable_cn0, a.cable_ct0)) for z in (0.0, far[2])]
        out += ln / 6.0 * (2.0 * p[0] + p[1])
    return out


def test_wing_converges_to_the_one_element_state_within_its_discretisation_error():
    """The wing's position and the ground tension with n = 2, 4, 8 elements per piece (cable aerodynamics on) move
    by successive differences in the ratio 4 (O(1/n^2)). The station's reaction converges as n^-1.4 (ratio 2.6): the
    drag per length near the ground goes as v^2 ~ h^0.4 (the wind's power law, exponent 0.2), whose lumping at the
    nodes errs by O(dh^1.4); with the cable's weight alone it is O(1/n^2) (test_nodes_on_the_elastic_catenary).
    The one-element state's discretisation error C, its distance from the Richardson limit, is below 2 m and 50 N
    (measured 1.35 m and 37 N of 1190 N: one element evaluates the cable's drag at its ends only), and every n
    lies within C of the one-element state and within 1.2 C / n^p of the limit."""
    pos, reaction = {}, {}
    for n in (1, 2, 4, 8):
        scene, sim = solved("tethered_wing", n)
        a = scene.assembly
        pos[n] = sim.wing_positions()[0]
        far = sim.node_positions()[0] if n > 1 else pos[n] + sim.wing_rotations()[0] @ a.wing(0).attachment
        reaction[n] = _station_reaction(a, sim.tensions()[0], far)
    for q, order, tol in ((pos, 2.0, 2.0), (reaction, 1.4, 50.0)):  # [m], [N]
        ratio = np.linalg.norm(q[2] - q[4]) / np.linalg.norm(q[4] - q[8])
        print(f"moves by {np.linalg.norm(q[2] - q[1]):.3g}, {np.linalg.norm(q[4] - q[2]):.3g}, "
              f"{np.linalg.norm(q[8] - q[4]):.3g} from n = 1 to 8, ratio {ratio:.3g}")
        assert abs(np.log2(ratio) - order) < 0.15, ratio
        limit = q[8] + (q[8] - q[4]) / (2.0**order - 1.0)  # Richardson
        C = np.linalg.norm(q[1] - limit)
        print(f"the one-element state {C:.3g} from the limit")
        assert C < tol
        for n in (2, 4, 8):
            assert np.linalg.norm(q[n] - q[1]) <= C
            assert np.linalg.norm(q[n] - limit) <= 1.2 * C / n**order


@pytest.mark.parametrize("name, n, method, dt, duration", [("tethered_wing", 8, "ros34pw2", 0.005, 2.0),
                                                         ("tethered_wing", 4, "rk4", 0.0005, 1.0),
                                                         ("ladder_chain", 2, "rk4", 0.002, 0.5)])
def test_short_run_stays_at_rest(name, n, method, dt, duration):
    """From the state found, every wing and node stays below 1e-3 m/s (its rates below 1e-3 rad/s)."""
    scene, sim = solved(name, n)
    run = type(sim)(sim.assembly, sim.initial_state, dataclasses.replace(sim.settings, method=method, dt=dt),
                    sim.initial_controls)
    run.step(n_steps=int(round(duration / dt)))
    a = run.assembly
    nodes = run.state[a.n_wings * a.wing_state_size: a.body_state_size].reshape(a.n_nodes, a.node_state_size)
    assert np.max(np.abs(run.wing_velocities())) < 1e-3
    assert np.max(np.abs(run.wing_rates())) < 1e-3
    assert np.max(np.abs(nodes[:, N3_VEL: N3_VEL + 3])) < 1e-3
