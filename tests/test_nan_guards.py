"""Non-finite inputs never become table or grid indices (a NaN index crashed the process with a segfault).

Oracle: with a NaN or infinite angle of attack the table lookup falls back to the first interval at its start,
whose value is the spline's constant coefficient there (closed form); a simulator stepped into a NaN state
reports the failure instead of crashing.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.rigid.aero import N_COLUMNS, spline_eval
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.packing import pack_model
from laddermill_gym.sim.simulator import SimulationError


@pytest.mark.parametrize("alpha", [np.nan, np.inf, -np.inf])
def test_table_lookup_with_non_finite_alpha(alpha):
    scene = load_scene("tethered_wing")
    m = pack_model(scene.assembly)
    from laddermill_gym.kernels.contract import GL_ALPHA0, GL_DALPHA

    out = np.zeros(N_COLUMNS)
    spline_eval(m.ac, 0, alpha, m.glob[GL_ALPHA0], m.glob[GL_DALPHA], out)
    np.testing.assert_array_equal(out, m.ac[0, 0, 3, :N_COLUMNS])


def test_nan_state_is_reported_not_crashed():
    sim = load_scene("tethered_wing").simulator()
    x = sim.state.copy()
    x[7] = np.nan  # body velocity of the wing
    sim.state = x  # reset() refuses a non-finite state; set it behind its back, as a diverged step would
    with pytest.raises(SimulationError):
        sim.step(None, n_steps=3)


def test_wind_modulation_at_a_nan_time_indexes_nothing():
    """A NaN time gives NaN factors (no table read); a finite time inside the grid interpolates linearly."""
    from laddermill_gym.kernels.wind import modulation

    ms, md = np.array([1.0, 2.0, 4.0]), np.array([0.0, 0.1, 0.3])
    assert np.all(np.isnan(modulation(np.nan, 0.0, 0.5, ms, md)))
    s, d, sd, dd = modulation(0.75, 0.0, 0.5, ms, md)  # halfway through the second interval
    assert (s, d, sd, dd) == pytest.approx((3.0, 0.2, 4.0, 0.4))


@pytest.mark.parametrize("alpha", [np.nan, np.inf, -np.inf])
def test_point_mass_kite_table_with_non_finite_alpha(alpha):
    """The point-mass kite's C_L, C_D lookup: NaN for a non-finite angle, the table's value on a grid point."""
    from laddermill_gym.kernels.pointmass.forces import kite_coefficients
    from laddermill_gym.model.builders import CableSpec
    from laddermill_gym.model.params import WindParams
    from laddermill_gym.model.pointmass import PointMassKite, PointMassString, pack

    a = np.radians(np.arange(-180.0, 180.1, 5.0))  # the uniform periodic grid the packer asks for
    cl, cd = np.sin(2.0 * a), 0.05 + np.sin(a) ** 2
    kite = PointMassKite(name="t", mass=20.0, area=10.0, alpha=a, cl=cl, cd=cd)
    wind = WindParams(v0=8.0, h0=10.0, v1=0.0, exponent=0.0, rho0=1.225, scale_height=8000.0)
    cab = CableSpec(diameter=0.001, mass_per_length=1e-5, EA=1e6, DA=1e2, cn0=0.0, ct0=0.0)
    s = PointMassString(wind=wind, gravity=9.81, cable=cab, element_length=3.0, n_nodes=10, anchor=np.zeros(3),
                        kite=kite, kite_nodes=np.array([9]))
    M = pack(s)
    assert np.all(np.isnan(kite_coefficients(alpha, M)))
    assert kite_coefficients(a[40], M) == pytest.approx((cl[40], cd[40]), rel=1e-12)


def test_rhs_refuses_a_nan_time_and_an_overflowing_quaternion():
    sim = load_scene("tethered_wing").simulator()
    with pytest.raises(ValueError, match="t must be finite"):
        sim.rhs(float("nan"), sim.state)
    x = sim.state.copy()
    x[3:7] *= 1e160  # finite, but beyond what the renormalisation can square
    with pytest.raises(SimulationError, match="wing 0 quaternion norm"):
        sim.rhs(0.0, x)
