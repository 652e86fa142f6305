"""Block operations on the tree-structured mass matrix of the rigid models (docs/numerics.md, "Equations of motion
in O(N)"): the O(N) elimination along the tree, and copies of the blocks.

The matrix is held as diagonal blocks D[c] and the blocks U[c] = M[c, parent[c]] to each block's parent
(M[parent[c], c] = U[c]^T); ``order`` lists the blocks children-first and ``bsz`` their sizes (6 for a body, 3 for
a free node in 3D).
"""

from numba import njit

from laddermill_gym.kernels.small import lu_factor, lu_solve_cols, lu_solve_vec


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def eliminate6(D, U, Y, bv, c, p):
    """Fixed-size (6 x 6 child, 6 x 6 parent) elimination step without pivoting: the diagonal blocks of
    wings are symmetric positive definite plus a small apparent-mass term, and so are their Schur
    complements. Constant loop bounds let the compiler unroll and vectorise."""
    _factor6(D, U, Y, c, p)
    _solve6(D, U, bv, c, p)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def _fast6(D, bsz, c, p):
    """Whether block c is eliminated on the fast 6 x 6 path: a 6 x 6 block under a 6 x 6 parent whose diagonal
    entries are all positive (finite or not)."""
    if not (bsz[c] == 6 and p >= 0 and bsz[p] == 6):
        return False
    ok = True
    for k in range(6):
        if not D[c, k, k] > 0.0:
            ok = False
    return ok


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def _coupling(D, U, Y, piv, c, n, m):
    """Y[c] = D[c]^-1 U[c] (n x m) by the LU factors of D[c] (in D[c], piv[c])."""
    for i in range(n):
        for j in range(m):
            Y[c, i, j] = U[c, i, j]
    lu_solve_cols(D[c], piv[c], n, Y[c], m)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def tree_solve(D, U, Y, piv, bv, order, parent, bsz):
    """Solve the block system in place (solution in bv) by elimination children-first.

    D[c] diagonal blocks (may be unsymmetric), U[c] = M[c, parent[c]], M[parent[c], c] = U[c]^T.
    Returns False if a diagonal block off the fast 6 x 6 path is singular. The fast path (a wing's block under a
    wing's, its diagonal positive) eliminates without pivoting and does not test its pivots: a zero pivot there
    gives non-finite values, which the step's check reports as a non-finite state; an indefinite block with nonzero
    pivots is solved as any other (the blocks are symmetric positive definite plus a small apparent-mass term, so
    neither is met in practice)."""
    nbk = order.size
    for ii in range(nbk):
        c = order[ii]
        n = bsz[c]
        p = parent[c]
        if _fast6(D, bsz, c, p):
            eliminate6(D, U, Y, bv, c, p)
            continue
        if not lu_factor(D[c], piv[c], n):
            return False
        lu_solve_vec(D[c], piv[c], n, bv[c])
        if p >= 0:
            m = bsz[p]
            _coupling(D, U, Y, piv, c, n, m)
            for k in range(n):
                bk = bv[c, k]
                for i in range(m):
                    f = U[c, k, i]
                    bv[p, i] -= f * bk
                    for j in range(m):
                        D[p, i, j] -= f * Y[c, k, j]
    _back_substitute(Y, bv, order, parent, bsz)
    return True


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _back_substitute(Y, bv, order, parent, bsz):
    """The elimination's second pass, parents first: bv[c] -= Y[c] bv[parent[c]]."""
    for ii in range(order.size - 1, -1, -1):
        c = order[ii]
        p = parent[c]
        if p >= 0:
            n = bsz[c]
            m = bsz[p]
            for i in range(n):
                s = 0.0
                for j in range(m):
                    s += Y[c, i, j] * bv[p, j]
                bv[c, i] -= s


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def copy_blocks(Ds, Us, Dd, Ud, order, bsz):
    """Dd, Ud = Ds, Us over the blocks in use."""
    for ii in range(order.size):
        c = order[ii]
        for i in range(6):
            for j in range(6):
                Dd[c, i, j] = Ds[c, i, j]
                Ud[c, i, j] = Us[c, i, j]


# The rows of the 6 x 6 solves below are held as 6-tuples of floats: values, not memory, so LLVM keeps them in
# registers and vectorises the row operations, which it did not do for the same loops over the arrays (it cannot tell
# that D, U and Y do not overlap). Each entry goes through the same operations in the same order as in those loops
# (the same fused multiply-adds), so D and the right-hand side are the same bits (Y, which no result reads but
# through the Schur complement, can differ in the sign of a zero: nsz): the chain's factorisation 15.7 -> 9.9 us
# (issue 32 point 3). The price is compile time: _factor6 1.2 s against 0.5 s cold (the helpers left to LLVM's
# inliner: numba's inline="always" took 1.5 s for the same code; a loop over Y's columns on scalars compiled in 0.8 s
# but factored in 11.9 us against 10.5, LLVM keeping it scalar).
@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _row(A, c, i):
    """Row i of block c of A as a 6-tuple."""
    return A[c, i, 0], A[c, i, 1], A[c, i, 2], A[c, i, 3], A[c, i, 4], A[c, i, 5]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _set_row(A, c, i, r):
    """Row i of block c of A = the 6-tuple r."""
    A[c, i, 0] = r[0]
    A[c, i, 1] = r[1]
    A[c, i, 2] = r[2]
    A[c, i, 3] = r[3]
    A[c, i, 4] = r[4]
    A[c, i, 5] = r[5]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _less(r, f, y):
    """The 6-tuple r - f y (entrywise, f a scalar)."""
    return r[0] - f * y[0], r[1] - f * y[1], r[2] - f * y[2], r[3] - f * y[3], r[4] - f * y[4], r[5] - f * y[5]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _times(r, s):
    """The 6-tuple s r."""
    return r[0] * s, r[1] * s, r[2] * s, r[3] * s, r[4] * s, r[5] * s


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _factor6(D, U, Y, c, p):
    """:func:`eliminate6` without a right-hand side: D[c] into its unit-lower / upper factors in place, Y[c] =
    D[c]^-1 U[c], and the Schur complement on the parent, D[p] -= U[c]^T Y[c]."""
    for k in range(6):
        inv = 1.0 / D[c, k, k]
        for i in range(k + 1, 6):
            f = D[c, i, k] * inv
            D[c, i, k] = f
            for j in range(k + 1, 6):
                D[c, i, j] -= f * D[c, k, j]
    d0, d1, d2, d3, d4, d5 = _row(D, c, 0), _row(D, c, 1), _row(D, c, 2), _row(D, c, 3), _row(D, c, 4), _row(D, c, 5)
    # Y rows: forward substitution with the unit-lower factor, then back substitution with the upper one
    y0 = _row(U, c, 0)
    y1 = _less(_row(U, c, 1), d1[0], y0)
    y2 = _less(_less(_row(U, c, 2), d2[0], y0), d2[1], y1)
    y3 = _less(_less(_less(_row(U, c, 3), d3[0], y0), d3[1], y1), d3[2], y2)
    y4 = _less(_less(_less(_less(_row(U, c, 4), d4[0], y0), d4[1], y1), d4[2], y2), d4[3], y3)
    y5 = _less(_less(_less(_less(_less(_row(U, c, 5), d5[0], y0), d5[1], y1), d5[2], y2), d5[3], y3), d5[4], y4)
    y5 = _times(y5, 1.0 / d5[5])
    y4 = _times(_less(y4, d4[5], y5), 1.0 / d4[4])
    y3 = _times(_less(_less(y3, d3[4], y4), d3[5], y5), 1.0 / d3[3])
    y2 = _times(_less(_less(_less(y2, d2[3], y3), d2[4], y4), d2[5], y5), 1.0 / d2[2])
    y1 = _times(_less(_less(_less(_less(y1, d1[2], y2), d1[3], y3), d1[4], y4), d1[5], y5), 1.0 / d1[1])
    y0 = _times(_less(_less(_less(_less(_less(y0, d0[1], y1), d0[2], y2), d0[3], y3), d0[4], y4), d0[5], y5),
                1.0 / d0[0])
    _set_row(Y, c, 0, y0)
    _set_row(Y, c, 1, y1)
    _set_row(Y, c, 2, y2)
    _set_row(Y, c, 3, y3)
    _set_row(Y, c, 4, y4)
    _set_row(Y, c, 5, y5)
    # Schur complement, row by row of D[p]: the sum over k in order 0..5 as before
    for i in range(6):
        r = _less(_row(D, p, i), U[c, 0, i], y0)
        r = _less(_less(_less(_less(_less(r, U[c, 1, i], y1), U[c, 2, i], y2), U[c, 3, i], y3), U[c, 4, i], y4),
                  U[c, 5, i], y5)
        _set_row(D, p, i, r)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _solve6(D, U, bv, c, p):
    """The right-hand side's part of a 6 x 6 elimination step (:func:`_factor6` done): bv[c] = D[c]^-1 bv[c] by
    the unit-lower and upper factors, then the parent's update bv[p] -= U[c]^T bv[c]."""
    for i in range(1, 6):
        for j in range(i):
            bv[c, i] -= D[c, i, j] * bv[c, j]
    for i in range(5, -1, -1):
        for j in range(i + 1, 6):
            bv[c, i] -= D[c, i, j] * bv[c, j]
        inv = 1.0 / D[c, i, i]
        bv[c, i] *= inv
    r = bv[p, 0], bv[p, 1], bv[p, 2], bv[p, 3], bv[p, 4], bv[p, 5]
    for k in range(6):
        r = _less(r, bv[c, k], _row(U, c, k))
    bv[p, 0], bv[p, 1], bv[p, 2], bv[p, 3], bv[p, 4], bv[p, 5] = r


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def tree_factor(D, U, Y, piv, order, parent, bsz):
    """Factor the block system in place for repeated solves (:func:`tree_solve_factored`): the elimination of
    :func:`tree_solve` without a right-hand side. A block factored on the fast 6 x 6 path is marked piv[c, 0] = -1.
    Returns False if a diagonal block off the fast path is singular (the fast path tests no pivot: as
    :func:`tree_solve`)."""
    for ii in range(order.size):
        c = order[ii]
        n = bsz[c]
        p = parent[c]
        if _fast6(D, bsz, c, p):
            _factor6(D, U, Y, c, p)
            piv[c, 0] = -1
            continue
        if not lu_factor(D[c], piv[c], n):
            return False
        if p >= 0:
            m = bsz[p]
            _coupling(D, U, Y, piv, c, n, m)
            for k in range(n):
                for i in range(m):
                    f = U[c, k, i]
                    for j in range(m):
                        D[p, i, j] -= f * Y[c, k, j]
    return True


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def tree_solve_factored(D, U, Y, piv, bv, order, parent, bsz):
    """Solve the system factored by :func:`tree_factor` for the right-hand side bv, in place; the same operations
    on bv, in the same order, as :func:`tree_solve`."""
    nbk = order.size
    for ii in range(nbk):
        c = order[ii]
        n = bsz[c]
        p = parent[c]
        if piv[c, 0] == -1:
            _solve6(D, U, bv, c, p)
            continue
        lu_solve_vec(D[c], piv[c], n, bv[c])
        if p >= 0:
            m = bsz[p]
            for k in range(n):
                bk = bv[c, k]
                for i in range(m):
                    bv[p, i] -= U[c, k, i] * bk
    _back_substitute(Y, bv, order, parent, bsz)
