"""The block-tree elimination factored once and solved for several right-hand sides (the Rosenbrock-W stages).

Oracle: numpy's dense solve of the same matrix assembled from its blocks, on trees with 6 x 6 body blocks and
3 x 3 node blocks, on the fast path (positive diagonals, no pivoting) and on the pivoting LU path.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.rigid.blocks import tree_factor, tree_solve, tree_solve_factored

# a tree: bodies 0-3 in a chain to the root 4, nodes 5 and 6 hanging from bodies 1 and 3; children first
PARENT = np.array([1, 2, 3, 4, -1, 1, 3])
BSZ = np.array([6, 6, 6, 6, 6, 3, 3])
ORDER = np.array([5, 0, 1, 2, 6, 3, 4])


def _system(rng, pivoting):
    nb = PARENT.size
    D, U = np.zeros((nb, 6, 6)), np.zeros((nb, 6, 6))
    for c in range(nb):
        n = BSZ[c]
        A = rng.normal(size=(n, n))
        D[c, :n, :n] = A @ A.T + 4.0 * n * np.eye(n)
        if pivoting:  # unsymmetric, with a zero leading entry: needs row exchanges
            D[c, :n, :n] += rng.normal(size=(n, n))
            D[c, 0, 0] = 0.0
        if PARENT[c] >= 0:
            U[c, :n, :BSZ[PARENT[c]]] = 0.3 * rng.normal(size=(n, BSZ[PARENT[c]]))
    start = np.concatenate([[0], np.cumsum(BSZ)])
    dense = np.zeros((start[-1], start[-1]))
    for c in range(nb):
        n, sc = BSZ[c], slice(start[c], start[c + 1])
        dense[sc, sc] = D[c, :n, :n]
        if PARENT[c] >= 0:
            p = PARENT[c]
            sp = slice(start[p], start[p + 1])
            dense[sc, sp] = U[c, :n, :BSZ[p]]
            dense[sp, sc] = U[c, :n, :BSZ[p]].T
    return D, U, dense, start


@pytest.mark.parametrize("pivoting", [False, True])
def test_factor_once_solve_many_equals_a_dense_solve(pivoting):
    rng = np.random.default_rng(3)
    D, U, dense, start = _system(rng, pivoting)
    nb = PARENT.size
    Df, Uf, Y, piv = D.copy(), U.copy(), np.zeros((nb, 6, 6)), np.zeros((nb, 6), dtype=np.int64)
    assert tree_factor(Df, Uf, Y, piv, ORDER, PARENT, BSZ)
    fast = piv[:, 0] == -1  # the fast path: a 6 x 6 body under a 6 x 6 parent with positive pivots
    assert (not fast[0]) if pivoting else fast.sum() == 4  # leaf 0's zero leading entry needs the LU path
    for _ in range(3):
        b = rng.normal(size=start[-1])
        bv = np.zeros((nb, 6))
        for c in range(nb):
            bv[c, :BSZ[c]] = b[start[c]:start[c + 1]]
        once = bv.copy()
        tree_solve_factored(Df, Uf, Y, piv, once, ORDER, PARENT, BSZ)
        x = np.concatenate([once[c, :BSZ[c]] for c in range(nb)])
        expected = np.linalg.solve(dense, b)
        assert np.allclose(x, expected, rtol=1e-12, atol=1e-13 * np.max(np.abs(expected)))
        fused = bv.copy()
        assert tree_solve(D.copy(), U.copy(), np.zeros_like(Y), piv.copy(), fused, ORDER, PARENT, BSZ)
        assert np.allclose(once, fused, rtol=1e-14, atol=1e-15 * np.max(np.abs(expected)))


def test_singular_block_is_reported():
    D, U, _, _ = _system(np.random.default_rng(4), True)
    D[5] = 0.0  # a node block of zeros
    assert not tree_factor(D, U, np.zeros((7, 6, 6)), np.zeros((7, 6), dtype=np.int64), ORDER, PARENT, BSZ)
