"""Small vibrations of a pretensioned straight cable between two fixed points (no gravity, vacuum).

Oracles (shared/design/oracles.md, "Rigid body and waves"; any vibrations text, e.g. Graff, "Wave Motion
in Elastic Solids", ch. 1-2):
- longitudinal wave speed c = sqrt(EA/mu), so the lowest axial mode of a fixed-fixed cable is
  omega_1 = pi c / L0 (L0 unstretched: EA/l0 is the element's axial stiffness and mu l0 its mass, so in
  material coordinates the pretension drops out exactly);
- transverse wave speed sqrt(T/mu') with mu' = mu L0/L the mass per stretched length: omega_1 = pi/L sqrt(T/mu');
- discrete dispersion of n equal elements with the consistent mass matrix (Meijaard eq. 11), derived by
  inserting u_j = sin(kappa j Delta) into the element equations:
      omega^2 = (6 s/m_e) (1 - cos(kappa Delta)) / (2 + cos(kappa Delta)),   kappa Delta = k pi / n,
  with element stiffness s (EA/l0 axial, T/l transverse) and element mass m_e = mu l0; the lumped chain of
  oracles.md would give omega = 2 sqrt(s/m_e) sin(kappa Delta / 2) instead.

The linearisation is a central-difference Jacobian of ``Simulator.rhs`` (node accelerations with respect to
node positions) at the equilibrium; its eigenvalues are -omega^2.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from laddermill_gym.model.builders import build_cable
from laddermill_gym.sim.simulator import Simulator
from tests.conftest import cable_spec

N_EL = 100
L0 = 100.0  # unstretched length [m]
STRAIN = 1e-4  # pretension strain [-]
EA = 1.0e6  # [N]
MU = 1.0  # [kg/m]
C_AXIAL = math.sqrt(EA / MU)  # 1000 m/s
TENSION = EA * STRAIN  # 100 N
L = L0 * (1.0 + STRAIN)


@functools.cache
def mode_frequencies(direction: int) -> np.ndarray:
    """Sorted natural frequencies [rad/s] of the node motions along global axis ``direction``
    (0: along the cable, 1: across)."""
    asm = build_cable([0.0, 0.0, 0.0], [L, 0.0, 0.0], L0, N_EL, cable_spec(MU, EA), sag=False, gravity=0.0)
    x = np.zeros(asm.state_size)
    nodes = x.reshape(asm.n_nodes, 6)
    nodes[:, 0] = np.arange(1, N_EL) / N_EL * L
    sim = Simulator(asm, x)
    pos = 6 * np.arange(asm.n_nodes) + direction
    assert np.max(np.abs(sim.rhs(0.0, x))) < 1e-6  # the straight, pretensioned cable is in equilibrium
    # small step: axially the element must stay taut (stretch 1e-4 m); transversely the cubic remainder is
    # (EA/T) (step/Delta)^2 / 2 relative, 5e-9 here
    step = 1e-6
    jac = np.empty((pos.size, pos.size))
    for k, i in enumerate(pos):
        xp, xm = x.copy(), x.copy()
        xp[i] += step
        xm[i] -= step
        jac[:, k] = (sim.rhs(0.0, xp)[pos + 3] - sim.rhs(0.0, xm)[pos + 3]) / (2 * step)
    lam = np.linalg.eigvals(jac)
    assert np.max(np.abs(lam.imag)) < 1e-6 * np.max(np.abs(lam.real))
    assert np.all(lam.real < 0)
    return np.sort(np.sqrt(-lam.real))


def consistent_dispersion(stiffness: float, k: np.ndarray) -> np.ndarray:
    ka = k * math.pi / N_EL
    return np.sqrt(6.0 * stiffness / (MU * L0 / N_EL) * (1.0 - np.cos(ka)) / (2.0 + np.cos(ka)))


def lumped_dispersion(stiffness: float, k: np.ndarray) -> np.ndarray:
    return 2.0 * np.sqrt(stiffness / (MU * L0 / N_EL)) * np.sin(k * math.pi / (2 * N_EL))


def test_longitudinal_wave_speed():
    """c = omega_1 L0 / pi of the lowest axial mode equals sqrt(EA/mu) within 1% (measured: 4e-5)."""
    omega = mode_frequencies(0)
    c = omega[0] * L0 / math.pi
    assert c == pytest.approx(C_AXIAL, rel=0.01)
    # the discretisation error of a consistent-mass chain is (k pi/n)^2/24 = 4e-5 for mode 1
    assert c == pytest.approx(C_AXIAL, rel=1e-4)


def test_transverse_wave_speed():
    """omega_1 L / pi of the lowest transverse mode equals sqrt(T/mu') within 1%."""
    omega = mode_frequencies(1)
    c = omega[0] * L / math.pi
    assert c == pytest.approx(math.sqrt(TENSION / (MU * L0 / L)), rel=0.01)


@pytest.mark.parametrize("direction, stiffness", [(0, EA / (L0 / N_EL)), (1, TENSION / (L / N_EL))],
                         ids=["axial", "transverse"])
def test_consistent_mass_dispersion(direction, stiffness):
    """All n-1 discrete frequencies follow the consistent-mass dispersion relation to 1e-6 relative, and
    differ from the lumped chain's (by 1.73x at the top of the spectrum; measured match 1e-9 axial,
    2.5e-9 transverse)."""
    omega = mode_frequencies(direction)
    k = np.arange(1, N_EL)
    np.testing.assert_allclose(omega, consistent_dispersion(stiffness, k), rtol=1e-6)
    assert np.max(omega / lumped_dispersion(stiffness, k)) > 1.5
