"""Small dense algebra written out in scalars: quaternions, rotations and an LU solver for n <= 6."""

import math

from numba import njit


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def quat_rotation(q0, q1, q2, q3, R):
    """Write the rotation matrix of the normalised quaternion (q0 scalar) into R (3x3, body -> global)."""
    n = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    a, b, c, d = q0 / n, q1 / n, q2 / n, q3 / n
    R[0, 0] = a * a + b * b - c * c - d * d
    R[0, 1] = 2.0 * (b * c - a * d)
    R[0, 2] = 2.0 * (b * d + a * c)
    R[1, 0] = 2.0 * (b * c + a * d)
    R[1, 1] = a * a - b * b + c * c - d * d
    R[1, 2] = 2.0 * (c * d - a * b)
    R[2, 0] = 2.0 * (b * d - a * c)
    R[2, 1] = 2.0 * (c * d + a * b)
    R[2, 2] = a * a - b * b - c * c + d * d


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def lu_factor(A, piv, n):
    """In-place LU factorisation with partial pivoting of the leading n x n part of A (n <= 6).

    Returns False if a pivot is exactly zero (singular block)."""
    for k in range(n):
        p = k
        big = abs(A[k, k])
        for i in range(k + 1, n):
            if abs(A[i, k]) > big:
                big = abs(A[i, k])
                p = i
        piv[k] = p
        if big == 0.0:
            return False
        if p != k:
            for j in range(n):
                tmp = A[k, j]
                A[k, j] = A[p, j]
                A[p, j] = tmp
        inv = 1.0 / A[k, k]
        for i in range(k + 1, n):
            A[i, k] *= inv
            f = A[i, k]
            if f != 0.0:
                for j in range(k + 1, n):
                    A[i, j] -= f * A[k, j]
    return True


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def lu_solve_vec(LU, piv, n, b):
    """Solve (LU) x = b in place for the leading n entries of the 1-D array b."""
    for k in range(n):
        p = piv[k]
        if p != k:
            tmp = b[k]
            b[k] = b[p]
            b[p] = tmp
    for i in range(1, n):
        s = b[i]
        for j in range(i):
            s -= LU[i, j] * b[j]
        b[i] = s
    for i in range(n - 1, -1, -1):
        s = b[i]
        for j in range(i + 1, n):
            s -= LU[i, j] * b[j]
        b[i] = s / LU[i, i]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def lu_solve_cols(LU, piv, n, B, m):
    """Solve (LU) X = B in place for the leading n x m part of the 2-D array B (rows swept together)."""
    for k in range(n):
        p = piv[k]
        if p != k:
            for c in range(m):
                tmp = B[k, c]
                B[k, c] = B[p, c]
                B[p, c] = tmp
    for i in range(1, n):
        for j in range(i):
            f = LU[i, j]
            for c in range(m):
                B[i, c] -= f * B[j, c]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, n):
            f = LU[i, j]
            for c in range(m):
                B[i, c] -= f * B[j, c]
        inv = 1.0 / LU[i, i]
        for c in range(m):
            B[i, c] *= inv
