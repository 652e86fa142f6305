"""Linearly implicit Euler for the point-mass string: the string's stiffness (axial EA/l0 and geometric T/l)
and its Voigt damping are taken implicitly along the string; gravity, cable drag and the kites' aerodynamics
explicitly. One step solves

    (M + dt C + dt^2 K) v+ = M v + dt F(x, v),   x+ = x + dt v+,

with M the lumped node masses (diagonal), C and K the string's damping and tangent stiffness at the start of
the step and F the elastic and external forces. Element e adds S_e = dt C_e + dt^2 K_e =
a t t^T + b I (a = dt DA/l0 + dt^2 EA/l0 - b, b = dt^2 T/l; zero when slack) to the diagonal blocks of its two
nodes and -S_e off the diagonal: a block-tridiagonal system with 3x3 blocks, solved by block elimination along
the string in O(n) (Thomas). Each pivot D'_j = D_j - S_j D'_{j-1}^{-1} S_j is symmetric positive definite
(M > 0, S_e >= 0), so no pivoting is needed.

Memory: the right-hand side and the eliminated right-hand side overwrite the velocities in place; the inverse
pivots (6 numbers each) are kept only at every ``seg``-th node (``W.ckpt``) and recomputed one segment at a time
on the way back (``W.seg``): 6 (n / seg + 2 seg) numbers instead of 6 n, at the price of a second forward pass
over the blocks (no right-hand side). The elimination is two-sided (:func:`_solve`: from both ends towards the
middle on two threads); the assembly and the move are parallel over chunks of nodes.
"""

from numba import njit, prange

from laddermill_gym.atmosphere.wind_kernels import modulation
from laddermill_gym.kernels.contract import N3_SIZE, N3_VEL, TM_DT, TM_T0
from laddermill_gym.kernels.pointmass.explicit import CHUNK, move_and_check, tensions
from laddermill_gym.kernels.pointmass.forces import (
    element_geometry,
    external_force,
    has_upper,
    node_mass,
    rest_length,
    string_force,
)
from laddermill_gym.kernels.pointmass.layout import PM_OK, PP_DA, PP_EA, PP_N

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _block(x, e, tension, par, dt):
    """S_e = a t t^T + b I of element e: returns (a, b, tx, ty, tz). Every element keeps its axial stiffness
    and damping within the step (slack ones too: their start-of-step tension is 0, so they resist only the
    change of length during the step); the geometric term b = dt^2 T/l only under tension."""
    tx, ty, tz, ln = element_geometry(x, e, par)
    l0 = rest_length(e, par)
    b = dt * dt * tension[e] / ln if ln > 0.0 else 0.0
    return dt * par[PP_DA] / l0 + dt * dt * par[PP_EA] / l0 - b, b, tx, ty, tz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _sds(a, b, tx, ty, tz, d0, d1, d2, d3, d4, d5):
    """S D S for S = a t t^T + b I and symmetric D (xx, yy, zz, xy, xz, yz)."""
    wx = d0 * tx + d3 * ty + d4 * tz
    wy = d3 * tx + d1 * ty + d5 * tz
    wz = d4 * tx + d5 * ty + d2 * tz
    s = tx * wx + ty * wy + tz * wz
    aa, ab, bb = a * a * s, a * b, b * b
    return (aa * tx * tx + 2.0 * ab * wx * tx + bb * d0, aa * ty * ty + 2.0 * ab * wy * ty + bb * d1,
            aa * tz * tz + 2.0 * ab * wz * tz + bb * d2, aa * tx * ty + ab * (wx * ty + tx * wy) + bb * d3,
            aa * tx * tz + ab * (wx * tz + tx * wz) + bb * d4, aa * ty * tz + ab * (wy * tz + ty * wz) + bb * d5)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _inv(d0, d1, d2, d3, d4, d5):
    """Inverse of a symmetric 3x3 matrix (xx, yy, zz, xy, xz, yz) by cofactors."""
    c0 = d1 * d2 - d5 * d5
    c1 = d0 * d2 - d4 * d4
    c2 = d0 * d1 - d3 * d3
    c3 = d4 * d5 - d3 * d2
    c4 = d3 * d5 - d4 * d1
    c5 = d3 * d4 - d0 * d5
    r = 1.0 / (d0 * c0 + d3 * c3 + d4 * c4)
    return c0 * r, c1 * r, c2 * r, c3 * r, c4 * r, c5 * r


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _between(x, j, step, tension, M, dt):
    """S of the element between node j and node j + step (zero where there is none)."""
    e = j + 1 if step > 0 else j
    if step > 0 and not has_upper(j, M.par):
        return 0.0, 0.0, 0.0, 0.0, 0.0
    return _block(x, e, tension, M.par, dt)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _pivot(x, j, step, tension, M, dt, prev, q, first):
    """Inverse pivot of node j in a sweep going ``step`` (+1 up, -1 down): D_j minus, unless ``first``, the
    eliminated previous node's S q S (``prev``: S of the element to node j - step, ``q`` its inverse pivot).
    Returns (inverse pivot, S of the element to node j + step)."""
    m = node_mass(j, M)
    nxt = _between(x, j, step, tension, M, dt)
    d = (m, m, m, 0.0, 0.0, 0.0)
    for s_e in (prev, nxt):
        a, b, tx, ty, tz = s_e
        d = (d[0] + a * tx * tx + b, d[1] + a * ty * ty + b, d[2] + a * tz * tz + b, d[3] + a * tx * ty,
             d[4] + a * tx * tz, d[5] + a * ty * tz)
    if not first:
        a, b, tx, ty, tz = prev
        e = _sds(a, b, tx, ty, tz, q[0], q[1], q[2], q[3], q[4], q[5])
        d = (d[0] - e[0], d[1] - e[1], d[2] - e[2], d[3] - e[3], d[4] - e[4], d[5] - e[5])
    return _inv(d[0], d[1], d[2], d[3], d[4], d[5]), nxt


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _smul(a, b, tx, ty, tz, vx, vy, vz):
    """S v for S = a t t^T + b I."""
    p = a * (tx * vx + ty * vy + tz * vz)
    return p * tx + b * vx, p * ty + b * vy, p * tz + b * vz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _qmul(q, vx, vy, vz):
    """Symmetric q (6) times v."""
    return (q[0] * vx + q[3] * vy + q[4] * vz, q[3] * vx + q[1] * vy + q[5] * vz,
            q[4] * vx + q[5] * vy + q[2] * vz)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _sweep(x, tension, M, dt, j0, count, step, ckpt, mid, seg):
    """Eliminate ``count`` nodes from j0 going ``step``: r'_j = r_j + S q_prev r'_prev in place in the
    velocities; the inverse pivot at the end of every segment of ``seg`` nodes into ``ckpt``; the last node's
    inverse pivot and q r' into ``mid`` (9,)."""
    prev = _between(x, j0, -step, tension, M, dt)
    q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    yx, yy, yz = 0.0, 0.0, 0.0
    for i in range(count):
        j = j0 + i * step
        o = N3_SIZE * j + N3_VEL
        if i > 0:
            a, b, tx, ty, tz = prev
            sx, sy, sz = _smul(a, b, tx, ty, tz, yx, yy, yz)
            x[o] += sx
            x[o + 1] += sy
            x[o + 2] += sz
        q, prev = _pivot(x, j, step, tension, M, dt, prev, q, i == 0)
        yx, yy, yz = _qmul(q, x[o], x[o + 1], x[o + 2])
        if (i + 1) % seg == 0 or i == count - 1:
            for k in range(6):
                ckpt[i // seg, k] = q[k]
    for k in range(6):
        mid[k] = q[k]
    mid[6], mid[7], mid[8] = yx, yy, yz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _back(x, tension, M, dt, j0, count, step, ckpt, buf, vx, vy, vz):
    """Back substitution of a sweep: v_j = q_j (r'_j + S_next v_next) from the sweep's last node back to j0,
    v_next starting at (vx, vy, vz), the solution of the node beyond the last; each segment's inverse pivots
    recomputed from the previous segment's checkpoint."""
    seg = buf.shape[0]
    nseg = (count + seg - 1) // seg
    for c in range(nseg - 1, -1, -1):
        i0 = c * seg
        i1 = min(count, i0 + seg)
        q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        if c > 0:
            q = (ckpt[c - 1, 0], ckpt[c - 1, 1], ckpt[c - 1, 2], ckpt[c - 1, 3], ckpt[c - 1, 4], ckpt[c - 1, 5])
        prev = _between(x, j0 + i0 * step, -step, tension, M, dt)
        for i in range(i0, i1):
            q, prev = _pivot(x, j0 + i * step, step, tension, M, dt, prev, q, i == 0)
            for k in range(6):
                buf[i - i0, k] = q[k]
        for i in range(i1 - 1, i0 - 1, -1):
            j = j0 + i * step
            o = N3_SIZE * j + N3_VEL
            a, b, tx, ty, tz = _between(x, j, step, tension, M, dt)
            sx, sy, sz = _smul(a, b, tx, ty, tz, vx, vy, vz)
            qj = (buf[i - i0, 0], buf[i - i0, 1], buf[i - i0, 2], buf[i - i0, 3], buf[i - i0, 4], buf[i - i0, 5])
            vx, vy, vz = _qmul(qj, x[o] + sx, x[o + 1] + sy, x[o + 2] + sz)
            x[o], x[o + 1], x[o + 2] = vx, vy, vz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _middle(x, tension, M, dt, m, n_lo, n_hi, mid):
    """Solve the meeting node m from both sweeps' last pivots and eliminated right-hand sides."""
    o = N3_SIZE * m + N3_VEL
    lo = _between(x, m, -1, tension, M, dt)
    hi = _between(x, m, 1, tension, M, dt)
    mass = node_mass(m, M)
    d = (mass, mass, mass, 0.0, 0.0, 0.0)
    rx, ry, rz = x[o], x[o + 1], x[o + 2]
    for side in range(2):
        a, b, tx, ty, tz = lo if side == 0 else hi
        d = (d[0] + a * tx * tx + b, d[1] + a * ty * ty + b, d[2] + a * tz * tz + b, d[3] + a * tx * ty,
             d[4] + a * tx * tz, d[5] + a * ty * tz)
        if (n_lo if side == 0 else n_hi) > 0:
            e = _sds(a, b, tx, ty, tz, mid[side, 0], mid[side, 1], mid[side, 2], mid[side, 3], mid[side, 4],
                     mid[side, 5])
            d = (d[0] - e[0], d[1] - e[1], d[2] - e[2], d[3] - e[3], d[4] - e[4], d[5] - e[5])
            sx, sy, sz = _smul(a, b, tx, ty, tz, mid[side, 6], mid[side, 7], mid[side, 8])
            rx, ry, rz = rx + sx, ry + sy, rz + sz
    q = _inv(d[0], d[1], d[2], d[3], d[4], d[5])
    x[o], x[o + 1], x[o + 2] = _qmul(q, rx, ry, rz)


@njit(cache=True, error_model="numpy", parallel=True)
def _solve(x, tension, M, dt, W):
    """Two-sided block elimination: nodes below the middle m = n // 2 eliminated upwards and nodes above it
    downwards at the same time (two parallel tasks), the middle node solved, then both back substitutions
    at the same time. Each side keeps its own checkpoints ``W.ckpt[side]`` and segment ``W.seg[side]``."""
    n = int(M.par[PP_N])
    m = n // 2
    counts = (m, n - 1 - m)
    for side in prange(2):
        step = 1 if side == 0 else -1
        j0 = 0 if side == 0 else n - 1
        _sweep(x, tension, M, dt, j0, counts[side], step, W.ckpt[side], W.mid[side], W.seg.shape[1])
    _middle(x, tension, M, dt, m, counts[0], counts[1], W.mid)
    o = N3_SIZE * m + N3_VEL
    vx, vy, vz = x[o], x[o + 1], x[o + 2]
    for side in prange(2):
        step = 1 if side == 0 else -1
        j0 = 0 if side == 0 else n - 1
        _back(x, tension, M, dt, j0, counts[side], step, W.ckpt[side], W.seg[side], vx, vy, vz)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _assemble_chunk(t, x, u, dt, M, tension, s, d, j0, j1):
    par = M.par
    for j in range(j0, j1):
        fx, fy, fz = external_force(t, x, j, u, M, s, d)
        gx, gy, gz = string_force(x, j, tension, par)
        m = node_mass(j, M)
        o = N3_SIZE * j + N3_VEL
        x[o] = m * x[o] + dt * (fx + gx)
        x[o + 1] = m * x[o + 1] + dt * (fy + gy)
        x[o + 2] = m * x[o + 2] + dt * (fz + gz)


@njit(cache=True, error_model="numpy", parallel=True)
def _assemble(t, x, u, dt, M, tension, s, d):
    """r_j = m_j v_j + dt (F_ext + F_elastic) in place in the velocities (parallel over nodes)."""
    n = int(M.par[PP_N])
    for c in prange((n + CHUNK - 1) // CHUNK):
        _assemble_chunk(t, x, u, dt, M, tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))


@njit(cache=True, error_model="numpy")
def implicit_advance(t, x, u, dt, nsteps, M, W):
    """Advance the state x (6 n,) in place by ``nsteps`` linearly implicit Euler steps of dt [s] from time t
    [s], kites' attitude u (n_k * 3,) [rad]. ``W.tension`` holds the elastic tensions at the start of the last
    step. Returns (status, steps done)."""
    for k in range(nsteps):
        tk = t + k * dt
        s, d, _, _ = modulation(tk, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        tensions(x, M, W.tension, False)
        _assemble(tk, x, u, dt, M, W.tension, s, d)
        _solve(x, W.tension, M, dt, W)
        st = move_and_check(x, dt, M.par)
        if st != PM_OK:
            return st, k + 1
    return PM_OK, nsteps

