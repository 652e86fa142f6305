"""The doubling solver of the discrete Riccati equation against scipy's QZ solver (an independent method)."""

import numpy as np
import scipy.linalg as sl

from laddermill_gym.control.discrete_lqr import discrete_lqr
from laddermill_gym.control.riccati import DOUBLING_MIN_STATES, dare_doubling


def _system(n, m, seed, unstable=True):
    rng = np.random.default_rng(seed)
    A = rng.normal(size=(n, n)) / np.sqrt(n)
    if unstable:  # a few modes just outside the unit circle, like the disturbed mill's lateral modes
        A = A / np.max(np.abs(np.linalg.eigvals(A))) * 1.02
    B = rng.normal(size=(n, m))
    L = rng.normal(size=(n, n)) / np.sqrt(n)
    Q = L @ L.T + 1e-3 * np.eye(n)
    R = np.diag(rng.uniform(0.5, 2.0, m))
    return A, B, Q, R


def test_doubling_equals_scipy_qz_on_random_unstable_systems():
    for n, m, seed in [(6, 2, 0), (40, 8, 1), (120, 30, 2)]:
        A, B, Q, R = _system(n, m, seed)
        S = dare_doubling(A, B, Q, R)
        S_qz = sl.solve_discrete_are(A, B, Q, R)
        assert S is not None
        assert np.abs(S - S_qz).max() <= 1e-9 * np.abs(S_qz).max()
        K = np.linalg.solve(R + B.T @ S @ B, B.T @ S @ A)
        assert np.abs(np.linalg.eigvals(A - B @ K)).max() < 1.0


def test_doubling_gives_up_on_an_unstabilisable_system():
    A = np.diag([1.5, 0.5])
    B = np.array([[0.0], [1.0]])  # the unstable mode is not reachable: no stabilising solution
    assert dare_doubling(A, B, np.eye(2), np.eye(1)) is None


def test_discrete_lqr_of_a_large_system_uses_doubling_and_matches_qz():
    n = DOUBLING_MIN_STATES
    rng = np.random.default_rng(3)
    A = rng.normal(size=(n, n)) / np.sqrt(n) - 0.5 * np.eye(n)  # continuous, a few unstable modes
    B = rng.normal(size=(n, 10))
    Q, R = np.eye(n), np.eye(10)
    d = discrete_lqr(A, B, Q, R, 0.05)
    S_qz = sl.solve_discrete_are(d.Ad, d.Bd, Q, R)
    assert np.abs(d.S - S_qz).max() <= 1e-9 * np.abs(S_qz).max()
    assert np.allclose(np.sort(np.abs(d.closed_loop)), np.sort(np.abs(np.linalg.eigvals(d.Ad - d.Bd @ d.K))))
    assert np.abs(d.closed_loop).max() < 1.0
