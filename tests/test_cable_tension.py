"""Sag-corrected tension (Meijaard eqs. 19-22) in the kernels: the root of the cubic against numpy.roots
over a wide range, and robustness where the paper's iteration is not guaranteed (zero length, no lateral
load, slack or compressed elements)."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.cable import tension_plain, tension_sag
from laddermill_gym.model.builders import CableSpec, build_cable
from laddermill_gym.sim.simulator import IntegratorSettings, Simulator


@pytest.mark.parametrize("strain", [-0.5, -1e-3, -1e-6, 0.0, 1e-6, 1e-3, 0.05])
@pytest.mark.parametrize("eps_p", [1e-12, 1e-3, 1.0, 1e3, 1e6])
def test_sag_root_matches_numpy_roots(strain, eps_p):
    EA, DA, l0 = 1.5e7, 1.5e4, 70.0
    eps, eps_dot = strain * l0, 0.3
    s = tension_sag(EA, DA, l0, eps, eps_dot, eps_p)
    s0 = (EA * eps + DA * eps_dot) / l0
    roots = np.roots([1.0, -s0, 0.0, -EA * eps_p / l0])
    real = roots[np.abs(roots.imag) <= 1e-9 * np.abs(roots)].real
    expected = real[real > 0].max()
    assert s > 0 and np.isfinite(s)
    assert s == pytest.approx(expected, rel=1e-9)


def test_no_lateral_load_or_zero_length_gives_clipped_hooke():
    assert tension_sag(1e6, 10.0, 10.0, 0.01, 0.0, 0.0) == pytest.approx(1e6 * 0.01 / 10.0)
    assert tension_sag(1e6, 10.0, 10.0, -0.01, 0.0, 0.0) == 0.0
    assert tension_plain(1e6, 10.0, 10.0, -0.01, 5.0) == 0.0, "a slack truss carries nothing"
    assert tension_plain(1e6, 1e4, 10.0, 0.001, -50.0) == 0.0, "damping never makes it push"


@pytest.mark.parametrize("sag", [True, False])
def test_coincident_and_slack_cable_stays_finite(sag):
    """A cable whose supports coincide (length 0 between them, all elements slack) falls freely without
    NaN and without compression."""
    cable = CableSpec(diameter=0.01, mass_per_length=0.1, EA=1e5, DA=10.0)
    asm = build_cable([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], 10.0, 4, cable, sag=sag)
    sim = Simulator(asm, np.zeros(asm.state_size), IntegratorSettings(ground_contact="off"))  # falls from z = 0
    dx = sim.rhs(0.0, sim.state, np.zeros(0))
    assert np.all(np.isfinite(dx))
    assert np.all(sim.work.tension[:4] >= 0.0)
    sim.step(n_steps=20)
    assert np.all(np.isfinite(sim.state))
    assert np.all(sim.tensions() >= 0.0)
