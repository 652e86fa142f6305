"""The air's variation in time and space (laddermill_gym/atmosphere/field.py, kernels/wind.py).

Oracles: closed forms (a bilinear field is reproduced exactly by bilinear interpolation; a frozen field
advected at U is the t = 0 field shifted by U t; the rate along a path is the derivative of the sampled wind,
checked by central differences), and the plain-numpy reference right-hand side
(reference, which interpolates the grid with scipy's RegularGridInterpolator) for the wings', the
cable's and the alpha-rate term's use of the field.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym import reference as ref
from laddermill_gym.atmosphere.field import GustGrid, WindField, pack_wind_field
from laddermill_gym.kernels.wind import gust_at, wind_point, wind_point_rate
from laddermill_gym.model.params import WindParams
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.simulator import Simulator
from tests.test_kernels_vs_reference import make_chain, random_chain_state


def bilinear_grid(a, b, c, heading=0.3, advection=7.0):
    """A grid sampling the field u = a + b xi + c h + 0.01 xi h (and scaled copies for v, w): bilinear, so the
    interpolation must reproduce it exactly inside the grid."""
    xi = -200.0 + 25.0 * np.arange(17)
    h = 10.0 + 20.0 * np.arange(9)
    X, H = np.meshgrid(xi, h, indexing="ij")
    base = a + b * X + c * H + 0.01 * X * H
    vals = np.stack([base, -0.5 * base, 0.25 * base], axis=-1)
    return GustGrid(vals, xi0=-200.0, dxi=25.0, h0=10.0, dh=20.0, advection=advection, heading=heading)


def _global(grid, uvw):
    e = -np.array([math.cos(grid.heading), math.sin(grid.heading), 0.0])
    right = np.array([-e[1], e[0], 0.0])
    return uvw[0] * e + uvw[1] * right + np.array([0.0, 0.0, -uvw[2]])


def test_bilinear_field_is_reproduced_and_advected():
    g = bilinear_grid(1.0, 0.01, -0.02)
    _, _, _, gp, gv = pack_wind_field(WindField(grid=g))
    e = -np.array([math.cos(g.heading), math.sin(g.heading), 0.0])
    rng = np.random.default_rng(1)
    for _ in range(20):
        p = np.array([rng.uniform(-100, 100), rng.uniform(-50, 50), -rng.uniform(20, 160)])
        t = rng.uniform(0.0, 10.0)
        xi, h = float(e @ p) - g.advection * t, -p[2]
        u = 1.0 + 0.01 * xi - 0.02 * h + 0.01 * xi * h
        expected = _global(g, np.array([u, -0.5 * u, 0.25 * u]))
        np.testing.assert_allclose(gust_at(*p, t, gp, gv), expected, rtol=1e-12, atol=1e-12)
        # frozen: the field at (p, t) is the field at t = 0 at the point moved upwind by U t
        np.testing.assert_allclose(gust_at(*p, t, gp, gv), gust_at(*(p - g.advection * t * e), 0.0, gp, gv),
                                   rtol=1e-12, atol=1e-12)


def test_edges_hold_and_nan_is_safe():
    g = bilinear_grid(2.0, 0.0, 0.0, heading=0.0, advection=0.0)
    _, _, _, gp, gv = pack_wind_field(WindField(grid=g))
    corner = g.values[-1, -1]
    far = gust_at(-1e5, 0.0, -1e4, 0.0, gp, gv)  # far downwind (xi = 1e5) and high: the last column and row
    np.testing.assert_allclose(far, _global(g, corner), rtol=1e-12)
    assert np.all(np.isfinite(gust_at(np.nan, 0.0, np.nan, 0.0, gp, gv)))


def test_rate_along_a_path_is_the_derivative_of_the_wind():
    wind = WindParams(v0=9.0, h0=60.0, v1=0.002, direction_inf=0.3, direction_height=300.0)
    f = WindField(0.0, 0.5, 1.0 + 0.1 * np.sin(np.arange(8.0)), 0.05 * np.cos(np.arange(8.0)),
                  bilinear_grid(0.5, 0.003, 0.01))
    tmod, ms, md, gp, gv = pack_wind_field(f)
    from laddermill_gym.kernels.wind import modulation
    from laddermill_gym.model.packing import wind_fields

    wf = wind_fields(wind)
    p0, v = np.array([10.0, -5.0, -70.0]), np.array([3.0, 2.0, -1.5])
    t0 = 1.2  # inside a modulation interval and a grid cell, away from their edges

    def w_at(t):
        s, d, _, _ = modulation(t, tmod[0], tmod[1], ms, md)
        return np.array(wind_point(*(p0 + v * (t - t0)), t, wf, s, d, gp, gv))

    s, d, sd, dd = modulation(t0, tmod[0], tmod[1], ms, md)
    rate = np.array(wind_point_rate(*p0, *v, t0, wf, s, d, sd, dd, gp, gv))
    h = 1e-4
    np.testing.assert_allclose(rate, (w_at(t0 + h) - w_at(t0 - h)) / (2 * h), rtol=1e-6, atol=1e-8)


@pytest.mark.parametrize("n_wings,end,epp", [(1, False, 2), (3, True, 2)])
def test_rhs_with_gust_grid_equals_reference(n_wings, end, epp):
    """Wings (incl. the alpha-rate term) and cable ends sample the grid at their own positions."""
    asm = make_chain(n_wings, end, epp, sag=True, cable_aero=True)
    rng = np.random.default_rng(5)
    vals = rng.normal(scale=1.5, size=(12, 10, 3))
    grid = GustGrid(vals, xi0=-150.0, dxi=30.0, h0=0.0, dh=25.0, advection=8.0, heading=0.2)
    import dataclasses

    asm = dataclasses.replace(asm, wind=asm.wind.with_field(WindField(0.0, 0.5, asm.wind.mod_speed,
                                                                       asm.wind.mod_direction, grid)))
    sim = Simulator(asm, random_chain_state(asm, rng))
    for trial in range(4):
        x = random_chain_state(asm, rng)
        u = rng.uniform(-0.2, 0.2, size=sim.n_controls)
        t = rng.uniform(0.0, 3.5)
        fast = sim.rhs(t, x, u)
        slow = ref.reference_rhs(t, x, u, asm)
        assert not np.allclose(slow, ref.reference_rhs(t, x, u, dataclasses.replace(
            asm, wind=dataclasses.replace(asm.wind, gust=None))))  # the grid matters
        scale = np.maximum(np.abs(slow), 1e-6 * np.max(np.abs(slow)))
        err = np.max(np.abs(fast - slow) / scale)
        assert err < 1e-9, f"trial {trial}: max relative difference {err:.3g}"


def test_one_way_to_set_the_wind_single_and_batched():
    """set_wind on a Simulator and on one batch copy give the same trajectory bit for bit."""
    from laddermill_gym.ladder.scene import load_scene

    scene = load_scene("tethered_wing")
    asm, settings = scene.assembly, scene.settings
    x0, _ = scene.initial_state()
    rng = np.random.default_rng(2)
    grid = GustGrid(rng.normal(scale=1.0, size=(6, 5, 3)), xi0=-100.0, dxi=40.0, h0=0.0, dh=30.0, advection=9.0)
    gusty = WindField(0.0, 0.25, np.array([1.0, 1.05, 1.0]), np.array([0.0, 0.02, 0.0]), grid)
    plain = WindField(0.0, 0.25, np.array([1.0, 0.95]), np.array([0.0, -0.01]))
    batch = BatchSimulator(asm, 2, settings, n_modulation=4, n_grid=grid.size)
    batch.set_wind(0, gusty)
    batch.set_wind(1, plain)
    batch.states[:] = x0
    batch.controls[:] = scene.simulator().controls
    batch.step(25)
    sims = []
    for field in (gusty, plain):
        sim = scene.simulator()
        sim.set_wind(field)
        sim.step(None, n_steps=25)
        sims.append(sim)
    assert np.array_equal(sims[0].state, batch.states[0])
    # a grid-less copy of a batch that holds grids runs the grid-enabled code with an empty row: the same
    # wind up to floating-point contraction, so equal to a plain simulator to rounding, not bit for bit
    np.testing.assert_allclose(batch.states[1], sims[1].state, rtol=1e-11, atol=1e-11)
    plain_batch = BatchSimulator(asm, 1, settings, n_modulation=4)
    plain_batch.set_wind(0, plain)
    plain_batch.states[:], plain_batch.controls[:] = x0, batch.controls[1]
    plain_batch.step(25)
    assert np.array_equal(plain_batch.states[0], sims[1].state)
    assert not np.allclose(batch.states[0], batch.states[1])
    with pytest.raises(ValueError, match="n_grid"):
        BatchSimulator(asm, 1, settings, n_modulation=4).set_wind(0, gusty)


def test_bad_fields_are_refused():
    with pytest.raises(ValueError, match=r"GustGrid.values"):
        GustGrid(np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"GustGrid.dxi"):
        GustGrid(np.zeros((2, 2, 3)), dxi=0.0)
    with pytest.raises(ValueError, match=r"WindField.speed\[1\]"):
        WindField(0.0, 1.0, np.array([1.0, -0.1]), np.zeros(2))
    with pytest.raises(ValueError, match="in-plane"):
        asm = make_chain(1, False, 1, sag=False, cable_aero=False, turning=0.0, direction_mod=0.0)
        import dataclasses

        Simulator(dataclasses.replace(asm, dim=2, wind=dataclasses.replace(
            asm.wind, gust=GustGrid(np.zeros((2, 2, 3))))), np.zeros(dataclasses.replace(asm, dim=2).state_size))
