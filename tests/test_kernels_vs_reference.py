"""The numba kernels against the independent plain-numpy reference (laddermill_gym/reference.py), which
is written from docs/model.md with dense matrices: equal to 1e-10 relative on random states."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from laddermill_gym import reference as ref
from laddermill_gym.model.builders import CableSpec, build_chain
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.states import planar_from_3d, planar_to_3d, quaternion_from_euler
from laddermill_gym.sim.simulator import Simulator
from tests.reference_builders import make_wing_type


def random_chain_state(asm, rng, spread=1.0):
    """A random 3D state: wings roughly along a line upwind-down, random attitudes, rates and velocities."""
    parts = []
    for k in range(asm.n_wings):
        pos = np.array([-30.0 * (k + 1), 2.0 * rng.normal(), -40.0 * (k + 1) - 20]) + spread * rng.normal(size=3)
        eul = rng.normal(scale=[0.3, 0.3, 0.5])
        q = quaternion_from_euler(*eul) * rng.uniform(0.9, 1.1)  # not normalised on purpose
        parts.append(np.concatenate([pos, q, rng.normal(scale=3.0, size=3) + [8, 0, 0], rng.normal(scale=0.5, size=3)]))
    for j in range(asm.n_nodes):
        parts.append(np.concatenate([np.array([-15.0 * (j + 1), rng.normal(), -25.0 * (j + 1)]),
                                     rng.normal(scale=2.0, size=3)]))
    return np.concatenate(parts)


def make_chain(n_wings, end, epp, sag, cable_aero, turning=0.3, mod=True, direction_mod=0.05):
    wind = WindParams(v0=9.0, h0=60.0, v1=0.002, direction_inf=turning, direction_height=300.0)
    if mod:
        t = np.arange(6) * 0.5
        wind = wind.with_modulation(0.0, 0.5, 1.0 + 0.2 * np.sin(t), direction_mod * np.cos(t))
    cable = CableSpec(diameter=0.01, mass_per_length=0.2, EA=3.0e5, DA=300.0)
    fixed = np.array([[0.0, 0.0, 0.0], [-10.0, 3.0, 0.0]])
    return build_chain((make_wing_type(),), np.zeros(n_wings, dtype=np.int64), 50.0, epp, cable, fixed, 0,
                       1 if end else None, wind, sag=sag, cable_aero=cable_aero)[0]


CASES = [
    dict(n_wings=1, end=False, epp=1, sag=True, cable_aero=True),
    dict(n_wings=1, end=False, epp=3, sag=False, cable_aero=False),
    dict(n_wings=3, end=True, epp=2, sag=True, cable_aero=True),
    dict(n_wings=4, end=True, epp=1, sag=False, cable_aero=True),
    dict(n_wings=2, end=True, epp=3, sag=True, cable_aero=False),
]


@pytest.mark.parametrize("case", CASES)
def test_rhs_equals_reference_on_random_states(case):
    rng = np.random.default_rng(7)
    asm = make_chain(**case)
    x0 = random_chain_state(asm, rng)
    sim = Simulator(asm, x0)
    for trial in range(5):
        x = random_chain_state(asm, rng)
        u = rng.uniform(-0.2, 0.2, size=sim.n_controls)
        t = rng.uniform(0.0, 3.5)
        fast = sim.rhs(t, x, u)
        slow = ref.reference_rhs(t, x, u, asm)
        scale = np.maximum(np.abs(slow), 1e-6 * np.max(np.abs(slow)))
        err = np.max(np.abs(fast - slow) / scale)
        assert err < 1e-10, f"trial {trial}: max relative difference {err:.3g}"
        np.testing.assert_allclose(sim.work.tension[: asm.elements.count], ref.element_tensions(asm, t, x),
                                   rtol=1e-10, atol=1e-9)


@pytest.mark.parametrize("sag,cable_aero", [(True, True), (False, False)])
def test_planar_mode_equals_3d_in_plane(sag, cable_aero):
    """The in-plane kernel is the 3D kernel restricted to the plane: same derivatives to 1e-9."""
    asm3 = make_chain(3, True, 2, sag, cable_aero, turning=0.0, mod=True, direction_mod=0.0)
    asm3 = dataclasses.replace(asm3, fixed_points=np.array([[0.0, 0.0, 0.0], [-10.0, 0.0, 0.0]]))
    asm2 = dataclasses.replace(asm3, dim=2)
    sim3 = Simulator(asm3, np.zeros(asm3.state_size) + planar_to_3d(np.zeros(asm2.state_size), 3, asm3.n_nodes))
    rng = np.random.default_rng(3)
    for _ in range(5):
        x3 = random_chain_state(asm3, rng)
        x2 = planar_from_3d(x3, asm3.n_wings, asm3.n_nodes)
        x3p = planar_to_3d(x2, asm3.n_wings, asm3.n_nodes)
        sim2 = Simulator(asm2, x2)
        u = np.zeros(sim3.n_controls)
        u[0::3] = rng.uniform(-0.2, 0.2, size=asm3.n_wings)
        d3 = planar_from_3d_rates(sim3.rhs(1.2, x3p, u), x3p, asm3)
        d2 = sim2.rhs(1.2, x2, u)
        np.testing.assert_allclose(d2, d3, rtol=1e-9, atol=1e-9 * np.max(np.abs(d3)))


def planar_from_3d_rates(dx3, x3, asm):
    """Map a 3D state derivative of an in-plane state to the in-plane derivative layout."""
    out = []
    for k in range(asm.n_wings):
        s, d = x3[13 * k: 13 * k + 13], dx3[13 * k: 13 * k + 13]
        out.append([d[0], d[2], s[11], d[7], d[9], d[11]])  # theta' = q in plane
    b = 13 * asm.n_wings
    for j in range(asm.n_nodes):
        d = dx3[b + 6 * j: b + 6 * j + 6]
        out.append([d[0], d[2], d[3], d[5]])
    return np.concatenate(out)
