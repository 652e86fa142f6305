"""The rotor over its whole disk (laddermill_gym/rotorcraft/rotor_kernels.section_aoa) and the closed-form torque at
mu = 0.3 (docs/rotor.md, "The blade-incidence check" and "Checks").

Oracles:

* The section angle of attack from the blade's geometry written out with vectors in numpy: the hub frame (x
  downwind in the disk plane, z up the shaft), the blade's span, chord and normal directions for the flapping angle
  beta(psi) = a0 - a1 cos psi - b1 sin psi, the blade element's velocity from the rotation and the flapping, and the
  flow relative to it projected on the chord (U_T) and on the normal (U_P); the geometry is taken to first order in
  beta (the model's small angles), so alpha = theta0 + U_P / U_T must be the kernel's to rounding. The largest angle
  on a grid is refined by a bounded optimiser, which must not find a larger one beyond the grid's resolution.
* The blade-element integration of tests/test_rotor.py (thrust, H-force, flapping and the direct torque integral),
  flown at mu = 0.3 at the incidences and collectives of that file's mu = 0.1 and 0.2 cases.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize

from laddermill_gym.rotorcraft import rotor_kernels as krotor
from laddermill_gym.rotorcraft.rotor import (
    DEFAULT_ROTOR_CONFIG,
    RotorParams,
    collective_at_limit,
    load_rotor_config,
    rotor_coefficients,
)
from tests.test_rotor import ORACLE_PARAMS, blade_element

DEG = math.pi / 180.0


def geometry_aoa(theta0, mu, lam, a0, a1, b1, x, psi):
    """Section angle [rad] from vectors: blade element at x (s + beta z) moving with the rotation and the flapping,
    the flow (mu, 0, lam) relative to it on the chord t and the normal n = z - beta r (first order in beta)."""
    x, psi = np.broadcast_arrays(np.asarray(x, float), np.asarray(psi, float))
    beta = a0 - a1 * np.cos(psi) - b1 * np.sin(psi)
    dbeta = a1 * np.sin(psi) - b1 * np.cos(psi)
    zero, one = np.zeros_like(psi), np.ones_like(psi)
    radial = np.stack([np.cos(psi), np.sin(psi), zero])
    chord = np.stack([-np.sin(psi), np.cos(psi), zero])  # the direction of the blade's motion
    up = np.stack([zero, zero, one])
    normal = up - beta * radial
    blade = x * (chord + dbeta * up)  # d/dpsi of x (radial + beta up), first order in beta
    flow = np.array([mu, 0.0, lam]).reshape(3, *([1] * psi.ndim)) - blade
    return theta0 + np.sum(flow * normal, axis=0) / -np.sum(flow * chord, axis=0)


def kernel_grid(args, xs, psis):
    """section_aoa [rad] on the (x, psi) grid."""
    return np.array([[krotor.section_aoa(*args, x, p) for p in psis] for x in xs])


def largest(args, xs, psis):
    """The largest section angle [rad] on the grid and where (x, psi), refined by L-BFGS-B within x >= xs[0]."""
    grid = kernel_grid(args, xs, psis)
    i, j = np.unravel_index(np.argmax(grid), grid.shape)
    res = minimize(lambda q: -krotor.section_aoa(*args, q[0], q[1]), (xs[i], psis[j]), method="L-BFGS-B",
                   bounds=((xs[0], xs[-1]), (psis[j] - 2 * DEG, psis[j] + 2 * DEG)))
    return grid[i, j], -res.fun, xs[i], psis[j], grid


@pytest.mark.parametrize("alpha_deg", [52.5, 22.5])
def test_section_angles_over_the_disk_at_the_tip_limit(alpha_deg):
    """At mu = 0.1 on the shipped rotor at the chart's collective (retreating tip at the 13 deg limit): the kernel's
    section angle equals the vector geometry everywhere off the reversed-flow circle, the tip is at the limit, and the
    largest angles over x >= 0.5, over x >= 0.7 and at x = 0.2 are printed (inboard sections beyond the tip's)."""
    cfg = load_rotor_config(DEFAULT_ROTOR_CONFIG)
    mu, alpha = 0.1, alpha_deg * DEG
    theta0 = collective_at_limit(cfg.params, mu, alpha, cfg.blade_incidence_limit)
    st = rotor_coefficients(cfg.params, mu, alpha, theta0)
    assert st.converged
    args = (theta0, mu, st.lam, st.a0, st.a1, st.b1)
    tip = krotor.section_aoa(*args, 1.0, 1.5 * math.pi)
    assert tip == pytest.approx(cfg.blade_incidence_limit, abs=1e-9)
    psis = np.radians(np.arange(0.0, 360.0, 0.25))
    xs = np.linspace(0.2, 1.0, 161)
    grid = kernel_grid(args, xs, psis)
    diff = np.max(np.abs(grid - geometry_aoa(*args, xs[:, None], psis[None, :])))
    assert diff < 1e-12
    print(f"mu {mu}, alpha_c {alpha_deg} deg: collective {math.degrees(theta0):.2f} deg, lam {st.lam:.4f}, tip "
          f"(x = 1, psi = 270 deg) at {math.degrees(tip):.2f} deg; kernel against the vector geometry {diff:.1e} rad")
    found = {}
    for lo in (0.5, 0.7):
        on_grid, refined, x_at, psi_at, _ = largest(args, xs[xs >= lo - 1e-12], psis)
        assert on_grid <= refined < on_grid + 0.05 * DEG  # the grid resolves the largest angle
        assert refined > tip
        found[lo] = refined
        print(f"  largest section angle over x >= {lo}: {math.degrees(refined):.2f} deg at x = {x_at:.2f}, psi = "
              f"{math.degrees(psi_at):.1f} deg (grid {math.degrees(on_grid):.3f} deg)")
    ring = kernel_grid(args, [0.2], psis)[0]
    print(f"  largest section angle at x = 0.2: {math.degrees(ring.max()):.2f} deg (psi = "
          f"{math.degrees(psis[ring.argmax()]):.1f} deg)")
    assert found[0.5] >= found[0.7] and ring.max() > found[0.5]  # the angles rise inboard


CASES = ((22.5, 2.0), (22.5, 10.0), (50.0, 5.0), (30.0, 6.0), (30.0, 4.0))  # test_rotor.py's (alpha_c, theta0)


def test_closed_forms_against_blade_element_at_mu_0_3():
    """test_rotor.py's comparison flown at mu = 0.3 at its other cases' incidences and collectives: thrust, H-force
    and flapping equal the integration to 1e-9, and the energy identity's C_Q differs from the direct torque integral
    by under 2 % of its terms (the higher flapping harmonics dropped), more at a larger collective."""
    params = RotorParams(sigma=0.07, **ORACLE_PARAMS)
    mu, worst_cq = 0.3, {}
    for alpha_deg, theta_deg in CASES:
        st = rotor_coefficients(params, mu, alpha_deg * DEG, theta_deg * DEG)
        assert st.converged
        ct, ch, cq, a0, a1, b1 = blade_element(params.sigma, params.a, params.delta, params.B, params.gamma, mu,
                                               st.lam, st.theta0)
        mine, theirs = np.array((st.ct, st.ch, st.a0, st.a1, st.b1)), np.array((ct, ch, a0, a1, b1))
        worst = np.max(np.abs(mine - theirs) / np.abs(theirs))
        scale = abs(st.lam * st.ct) + abs(mu * st.ch) + params.sigma * params.delta * (1.0 + 3.0 * mu**2) / 8.0
        worst_cq[(alpha_deg, theta_deg)] = 100.0 * abs(st.cq - cq) / scale
        print(f"mu = {mu}, alpha_c = {alpha_deg} deg, collective {theta_deg} deg: C_Q differs by "
              f"{worst_cq[(alpha_deg, theta_deg)]:.2f} % of the terms; thrust, H-force and flapping by at most "
              f"{worst:.1e} relative (tolerance 1e-9)")
        assert worst < 1e-9
    print(f"largest C_Q difference at mu = {mu}: {max(worst_cq.values()):.2f} %")
    assert max(worst_cq.values()) < 2.0
    assert worst_cq[(22.5, 10.0)] > worst_cq[(22.5, 2.0)] and worst_cq[(30.0, 6.0)] > worst_cq[(30.0, 4.0)]
