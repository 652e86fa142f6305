"""The inflow root and the collective at the blade-incidence limit in near-axial flow (a review of 2026-12-07).

Before: the bracket search's growing steps could pass over momentum theory's two close roots of the heavily loaded
windmill state and return the reversed-flow root with status OK (C_p -0.10 at 6.1 deg collective where 6.0 deg gave
+0.36); and ``collective_at_limit`` bracketed the whole collective range, so past the fold it returned a later
crossing on the reversed-flow branch (13.3 deg at mu 0.02, alpha 82.5 deg, where the tip passes the limit near
7 deg on the light branch). Oracle: every root of the inflow equation found independently on a fine grid of lam
(numpy) and polished by scipy's brentq; the root the solver must return is the first one met walking from lam_inf
in the direction that reduces the residual (the light branch, continuous with zero thrust: docs/rotor.md).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from laddermill_gym.rotorcraft.rotor import (
    DEFAULT_ROTOR_CONFIG,
    collective_at_limit,
    load_rotor_config,
    rotor_coefficients,
    solve_inflow,
)

P = load_rotor_config(DEFAULT_ROTOR_CONFIG).params


def light_root(mu: float, alpha: float, theta0: float) -> float | None:
    """The first root of f(lam) = lam - lam_inf + C_T(lam) / (2 sqrt(mu^2 + lam^2)) from lam_inf, walking the way
    f's sign says (down where f > 0), from a grid of 200,001 points over lam_inf -+ 0.6 (Roberts eq. 1's C_T)."""
    s, a, b = P.sigma, P.a, P.B
    lam_inf = mu * math.tan(alpha)
    c0 = 0.5 * s * a * theta0 * (b ** 3 / 3.0 + 0.5 * b * mu * mu)
    c1 = 0.25 * s * a * b * b

    def f(x):
        return x - lam_inf + (c0 + c1 * x) / (2.0 * np.hypot(mu, x))

    down = f(lam_inf) > 0.0
    xs = np.linspace(lam_inf, lam_inf - 0.6 if down else lam_inf + 0.6, 200_001)
    fx = f(xs)
    change = np.flatnonzero(np.sign(fx[1:]) != np.sign(fx[:-1]))
    return None if change.size == 0 else brentq(f, xs[change[0]], xs[change[0] + 1], xtol=1e-15)


CASES = [(mu, math.radians(alpha), math.radians(theta)) for mu in (0.0056, 0.01, 0.02, 0.03)
         for alpha in (80.0, 85.0, 87.5, 89.0) for theta in (2.0, 4.0, 6.0, 6.1, 8.0, 10.0)]


@pytest.mark.parametrize("mu, alpha, theta0", CASES)
def test_the_inflow_is_the_first_root_from_the_free_stream(mu, alpha, theta0):
    want = light_root(mu, alpha, theta0)
    sol = solve_inflow(P, mu, alpha, theta0)
    assert want is not None and sol.converged
    assert sol.lam == pytest.approx(want, abs=1e-9), (want, sol.lam)


def test_the_reviewed_case_keeps_its_power_sign():
    mu, alpha = 0.0056, math.radians(87.5)
    cps = [rotor_coefficients(P, mu, alpha, math.radians(t)).cp for t in (5.9, 6.0, 6.1)]
    assert all(cp > 0.3 for cp in cps), cps  # the light branch up to its fold near 6.15 deg: no -0.10 at 6.1 deg


def test_the_collective_at_the_limit_is_the_first_crossing():
    mu, alpha, limit = 0.02, math.radians(82.5), math.radians(13.0)
    theta = collective_at_limit(P, mu, alpha, limit)
    assert math.degrees(theta) == pytest.approx(7.0, abs=0.1)  # not 13.3 deg (the reversed-flow branch)
    tip = rotor_coefficients(P, mu, alpha, theta)
    assert math.degrees(tip.tip_aoa) == pytest.approx(13.0, abs=1e-8) and tip.cp > 0.5
    below = [rotor_coefficients(P, mu, alpha, t).tip_aoa for t in np.linspace(math.radians(-60.0), theta, 400)[:-1]]
    assert max(below) < limit  # no earlier collective reaches the limit
