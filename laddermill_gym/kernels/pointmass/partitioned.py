"""Partitioned block Thomas elimination of the implicit point-mass step on P threads
(``kernels/pointmass/implicit.py``; the block algebra in ``kernels/pointmass/blocks.py``).

The string's n nodes are cut into P chunks by P - 1 single separator nodes s_0 < ... < s_{P-2}. With the
separators' velocities z_c known, the chunks are independent block-tridiagonal systems; eliminating them leaves
a reduced block-tridiagonal system for the z_c alone (its Schur complement, 3x3 blocks, symmetric positive
definite). Three parallel phases over the chunks and one serial one:

1. Every chunk is eliminated, independently. The lowest (chunk 0) by an upward block Thomas sweep, the highest
   by a downward one (both in place, :func:`blocks.sweep`): each ends next to its separator. A middle chunk
   needs both of its corners: a read-only downward sweep (:func:`_sweep_read`) gives its bottom pivot and
   solution (T^{-1} r)_bottom, then an upward sweep in place (:func:`_sweep_spike`) gives its top pivot and
   solution and carries the "spike" W_j = S_j q_{j-1} W_{j-1} (W = I at the bottom node: T^{-1}'s column of
   the bottom node eliminated), whose top value gives the corner block (T^{-1})_{top,bottom} = q_top W_top
   coupling the chunk's two separators.
2. The reduced system (size P - 1) is assembled and solved by block Thomas on one thread (:func:`_reduce`).
3. Every chunk back-substitutes in parallel from its separators' solution; a middle chunk adds
   W_j S_lo z_lo, W_j recomputed from its checkpoint with the segment's inverse pivots (:func:`_back_spike`).

Work: an end chunk costs two pivot passes per node (sweep, and the pivots recomputed for the back
substitution), a middle chunk three plus the spike; the chunk sizes are weighted (``END_WEIGHT``:``MID_WEIGHT``)
so that the threads finish together. P = 2 is the two-sided elimination (no middle chunk). O(n)
work and no allocation: checkpoints (rows, 15), one segment's buffer per chunk (P_max, seg, 9) and the chunk
and separator data (P_max, 48) are the workspace ``PMWork.ckpt``, ``.seg``, ``.mid`` (``model/pointmass.py``).
"""

from numba import njit, prange

from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    BUF_COLS,
    CKPT_COLS,
    MID_BOT,
    MID_COLS,
    MID_DINV,
    MID_GRED,
    MID_GTB,
    MID_LBLK,
    MID_TOP,
    MID_ZSEP,
    N3_SIZE,
    N3_VEL,
    PP_N,
)
from laddermill_gym.kernels.pointmass.blocks import (
    add_s_mul,
    back,
    element_block,
    inv_sym,
    pivot_block,
    q_mul,
    s_mul,
    sds,
    sweep,
)
from laddermill_gym.kernels.pointmass.forces import node_mass

_FM = {"contract", "nsz", "arcp"}

#: Relative size of an end chunk and of a middle chunk, the inverse of their cost per node: 54 ns (sweep and
#: back substitution) against 90 ns (read-only sweep, sweep with spike, back substitution with spike), ratio
#: 1.68, measured on one thread on the chunks of P = 4 at 100,000 and 500,000 nodes of podgaets_5km
#: (docs/pointmass.md, "Methods").
END_WEIGHT, MID_WEIGHT = 5, 3
#: Fewest nodes per chunk when the chunk count follows the threads (:func:`solver_parts`): below that the
#: middle chunks' extra pass and the pool's wake-up cost more than a thread gains (the parallel loops' rule,
#: ``explicit.CHUNK`` = 2048 nodes per task, doubled).
MIN_PART = 4096
#: Spike entries below this (relative) are flushed to zero (they only decay; no subnormal arithmetic).
TINY = 1e-150


@njit(cache=True, error_model="numpy", inline="always", _nrt=False)
def solver_parts(n, threads, capacity):
    """Chunks of the elimination of n nodes on ``threads`` threads with a workspace for ``capacity``: one
    chunk per thread, each at least ``MIN_PART`` nodes, and two (the two-sided elimination) at the least."""
    if n < 3 or capacity < 2:
        return 1
    return max(2, min(threads, n // MIN_PART, capacity))


@njit(cache=True, error_model="numpy", inline="always", _nrt=False)
def separator(n, P, c):
    """Node of separator c (0 <= c <= P - 2): every chunk one node, the rest shared by the weights."""
    rest = n - 2 * P + 1
    total = 2 * END_WEIGHT + (P - 2) * MID_WEIGHT
    return 2 * c + 1 + (rest * (END_WEIGHT + c * MID_WEIGHT) + total - 1) // total


@njit(cache=True, error_model="numpy", inline="always", _nrt=False)
def chunk_range(n, P, c):
    """First node and end (exclusive) of chunk c."""
    lo = 0 if c == 0 else separator(n, P, c - 1) + 1
    hi = n if c == P - 1 else separator(n, P, c)
    return lo, hi


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _sqw(s_e, q, w):
    """S q W for S = (a, b, t), symmetric q (6) and W (9, row-major)."""
    a, b, tx, ty, tz = s_e
    v0 = q_mul(q, w[0], w[3], w[6])
    v1 = q_mul(q, w[1], w[4], w[7])
    v2 = q_mul(q, w[2], w[5], w[8])
    c0 = s_mul(a, b, tx, ty, tz, v0[0], v0[1], v0[2])
    c1 = s_mul(a, b, tx, ty, tz, v1[0], v1[1], v1[2])
    c2 = s_mul(a, b, tx, ty, tz, v2[0], v2[1], v2[2])
    return c0[0], c1[0], c2[0], c0[1], c1[1], c2[1], c0[2], c1[2], c2[2]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _sweep_read(x, tension, M, dt, j0, count, step, out):
    """Read-only :func:`blocks.sweep`: the last node's inverse pivot and q r' into ``out`` (9,)."""
    prev = element_block(x, j0, -step, tension, M, dt)
    q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    yx, yy, yz = 0.0, 0.0, 0.0
    for i in range(count):
        o = N3_SIZE * (j0 + i * step) + N3_VEL
        rx, ry, rz = x[o], x[o + 1], x[o + 2]
        if i > 0:
            a, b, tx, ty, tz = prev
            sx, sy, sz = s_mul(a, b, tx, ty, tz, yx, yy, yz)
            rx, ry, rz = rx + sx, ry + sy, rz + sz
        q, prev = pivot_block(x, j0 + i * step, step, tension, M, dt, prev, q, i == 0)
        yx, yy, yz = q_mul(q, rx, ry, rz)
    for k in range(6):
        out[k] = q[k]
    out[6], out[7], out[8] = yx, yy, yz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _sweep_spike(x, tension, M, dt, j0, count, ckpt, row, seg):
    """Upward :func:`blocks.sweep` of a middle chunk carrying the spike W (9, row-major; I at j0): inverse
    pivot and W at every segment's end into ``ckpt`` (columns 0-5, 6-14); the top node's inverse pivot, q r'
    and q W into ``row`` (``MID_TOP``, ``MID_GTB``)."""
    prev = element_block(x, j0, -1, tension, M, dt)
    q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    w = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    yx, yy, yz = 0.0, 0.0, 0.0
    for i in range(count):
        o = N3_SIZE * (j0 + i) + N3_VEL
        if i > 0:
            add_s_mul(x, o, prev, yx, yy, yz)
            w = _sqw(prev, q, w)
            if (abs(w[0]) + abs(w[1]) + abs(w[2]) + abs(w[3]) + abs(w[4]) + abs(w[5]) + abs(w[6]) + abs(w[7])
                    + abs(w[8]) < TINY):
                w = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        q, prev = pivot_block(x, j0 + i, 1, tension, M, dt, prev, q, i == 0)
        yx, yy, yz = q_mul(q, x[o], x[o + 1], x[o + 2])
        if (i + 1) % seg == 0 or i == count - 1:
            for k in range(6):
                ckpt[i // seg, k] = q[k]
            ckpt[i // seg, 6], ckpt[i // seg, 7], ckpt[i // seg, 8] = w[0], w[1], w[2]
            ckpt[i // seg, 9], ckpt[i // seg, 10], ckpt[i // seg, 11] = w[3], w[4], w[5]
            ckpt[i // seg, 12], ckpt[i // seg, 13], ckpt[i // seg, 14] = w[6], w[7], w[8]
    for k in range(6):
        row[MID_TOP + k] = q[k]
    row[MID_TOP + 6], row[MID_TOP + 7], row[MID_TOP + 8] = yx, yy, yz
    for k in range(3):
        gx, gy, gz = q_mul(q, w[k], w[3 + k], w[6 + k])
        row[MID_GTB + k], row[MID_GTB + 3 + k], row[MID_GTB + 6 + k] = gx, gy, gz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _back_spike(x, tension, M, dt, j0, count, ckpt, buf, vx, vy, vz, wx, wy, wz):
    """Back substitution of :func:`_sweep_spike`: v_j = q_j (r'_j + S_next v_next + W_j w) from the top node
    down, v_next starting at the upper separator's solution (vx, vy, vz), w = S_lo z_lo the lower separator's
    load; each segment's inverse pivots and W_j w recomputed from the previous segment's checkpoint."""
    seg = buf.shape[0]
    tiny = TINY * (abs(wx) + abs(wy) + abs(wz))
    for c in range((count + seg - 1) // seg - 1, -1, -1):
        i0 = c * seg
        i1 = min(count, i0 + seg)
        q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        px, py, pz = wx, wy, wz
        if c > 0:
            r = c - 1
            q = (ckpt[r, 0], ckpt[r, 1], ckpt[r, 2], ckpt[r, 3], ckpt[r, 4], ckpt[r, 5])
            px = ckpt[r, 6] * wx + ckpt[r, 7] * wy + ckpt[r, 8] * wz
            py = ckpt[r, 9] * wx + ckpt[r, 10] * wy + ckpt[r, 11] * wz
            pz = ckpt[r, 12] * wx + ckpt[r, 13] * wy + ckpt[r, 14] * wz
        prev = element_block(x, j0 + i0, -1, tension, M, dt)
        for i in range(i0, i1):
            if i > 0:
                a, b, tx, ty, tz = prev
                ux, uy, uz = q_mul(q, px, py, pz)
                px, py, pz = s_mul(a, b, tx, ty, tz, ux, uy, uz)
                if abs(px) + abs(py) + abs(pz) <= tiny:
                    px, py, pz = 0.0, 0.0, 0.0
            q, prev = pivot_block(x, j0 + i, 1, tension, M, dt, prev, q, i == 0)
            for k in range(6):
                buf[i - i0, k] = q[k]
            buf[i - i0, 6], buf[i - i0, 7], buf[i - i0, 8] = px, py, pz
        for i in range(i1 - 1, i0 - 1, -1):
            o = N3_SIZE * (j0 + i) + N3_VEL
            a, b, tx, ty, tz = element_block(x, j0 + i, 1, tension, M, dt)
            sx, sy, sz = s_mul(a, b, tx, ty, tz, vx, vy, vz)
            qj = (buf[i - i0, 0], buf[i - i0, 1], buf[i - i0, 2], buf[i - i0, 3], buf[i - i0, 4], buf[i - i0, 5])
            vx, vy, vz = q_mul(qj, x[o] + sx + buf[i - i0, 6], x[o + 1] + sy + buf[i - i0, 7],
                               x[o + 2] + sz + buf[i - i0, 8])
            x[o], x[o + 1], x[o + 2] = vx, vy, vz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _coupling(x, tension, M, dt, n, P, c, mid):
    """L_c = -S_s (T_c^{-1})_{top,bottom} S_lo: separator c's coupling to separator c - 1 through middle chunk
    c (S_s: the element below separator c; S_lo: the element above separator c - 1), row-major into mid."""
    s_lo = element_block(x, separator(n, P, c - 1), 1, tension, M, dt)
    a, b, tx, ty, tz = element_block(x, separator(n, P, c), -1, tension, M, dt)
    g = mid[c, MID_GTB:MID_GTB + 9]
    h0 = s_mul(s_lo[0], s_lo[1], s_lo[2], s_lo[3], s_lo[4], g[0], g[1], g[2])
    h1 = s_mul(s_lo[0], s_lo[1], s_lo[2], s_lo[3], s_lo[4], g[3], g[4], g[5])
    h2 = s_mul(s_lo[0], s_lo[1], s_lo[2], s_lo[3], s_lo[4], g[6], g[7], g[8])
    for k in range(3):
        lx, ly, lz = s_mul(a, b, tx, ty, tz, h0[k], h1[k], h2[k])
        mid[c, MID_LBLK + k], mid[c, MID_LBLK + 3 + k], mid[c, MID_LBLK + 6 + k] = -lx, -ly, -lz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _reduce(x, tension, M, dt, n, P, mid):
    """Assemble and solve the separators' reduced system by block Thomas (one thread); the solutions into
    ``mid[:, MID_ZSEP]`` and the separators' velocities."""
    for c in range(P - 1):
        s = separator(n, P, c)
        o = N3_SIZE * s + N3_VEL
        mass = node_mass(s, M)
        d = (mass, mass, mass, 0.0, 0.0, 0.0)
        rx, ry, rz = x[o], x[o + 1], x[o + 2]
        for side in range(2):  # chunk c's top (below s), chunk c + 1's bottom (above s)
            a, b, tx, ty, tz = element_block(x, s, 2 * side - 1, tension, M, dt)
            rw, base = c + side, MID_TOP if side == 0 else MID_BOT
            d = (d[0] + a * tx * tx + b, d[1] + a * ty * ty + b, d[2] + a * tz * tz + b, d[3] + a * tx * ty,
                 d[4] + a * tx * tz, d[5] + a * ty * tz)
            e = sds(a, b, tx, ty, tz, mid[rw, base], mid[rw, base + 1], mid[rw, base + 2], mid[rw, base + 3],
                     mid[rw, base + 4], mid[rw, base + 5])
            d = (d[0] - e[0], d[1] - e[1], d[2] - e[2], d[3] - e[3], d[4] - e[4], d[5] - e[5])
            sx, sy, sz = s_mul(a, b, tx, ty, tz, mid[rw, base + 6], mid[rw, base + 7], mid[rw, base + 8])
            rx, ry, rz = rx + sx, ry + sy, rz + sz
        if c > 0:
            _coupling(x, tension, M, dt, n, P, c, mid)
            lb = mid[c, MID_LBLK:MID_LBLK + 9]
            dq = mid[c - 1, MID_DINV:MID_DINV + 6]
            y0 = q_mul(dq, lb[0], lb[1], lb[2])  # rows of Y = L Dinv (Dinv symmetric)
            y1 = q_mul(dq, lb[3], lb[4], lb[5])
            y2 = q_mul(dq, lb[6], lb[7], lb[8])
            d = (d[0] - (y0[0] * lb[0] + y0[1] * lb[1] + y0[2] * lb[2]),
                 d[1] - (y1[0] * lb[3] + y1[1] * lb[4] + y1[2] * lb[5]),
                 d[2] - (y2[0] * lb[6] + y2[1] * lb[7] + y2[2] * lb[8]),
                 d[3] - (y0[0] * lb[3] + y0[1] * lb[4] + y0[2] * lb[5]),
                 d[4] - (y0[0] * lb[6] + y0[1] * lb[7] + y0[2] * lb[8]),
                 d[5] - (y1[0] * lb[6] + y1[1] * lb[7] + y1[2] * lb[8]))
            gx, gy, gz = mid[c - 1, MID_GRED], mid[c - 1, MID_GRED + 1], mid[c - 1, MID_GRED + 2]
            rx -= y0[0] * gx + y0[1] * gy + y0[2] * gz
            ry -= y1[0] * gx + y1[1] * gy + y1[2] * gz
            rz -= y2[0] * gx + y2[1] * gy + y2[2] * gz
        q = inv_sym(d[0], d[1], d[2], d[3], d[4], d[5])
        for k in range(6):
            mid[c, MID_DINV + k] = q[k]
        mid[c, MID_GRED], mid[c, MID_GRED + 1], mid[c, MID_GRED + 2] = rx, ry, rz
    zx, zy, zz = 0.0, 0.0, 0.0
    for c in range(P - 2, -1, -1):
        rx, ry, rz = mid[c, MID_GRED], mid[c, MID_GRED + 1], mid[c, MID_GRED + 2]
        if c < P - 2:  # minus L_{c+1}^T z_{c+1}
            lb = mid[c + 1, MID_LBLK:MID_LBLK + 9]
            rx -= lb[0] * zx + lb[3] * zy + lb[6] * zz
            ry -= lb[1] * zx + lb[4] * zy + lb[7] * zz
            rz -= lb[2] * zx + lb[5] * zy + lb[8] * zz
        q = (mid[c, MID_DINV], mid[c, MID_DINV + 1], mid[c, MID_DINV + 2], mid[c, MID_DINV + 3],
             mid[c, MID_DINV + 4], mid[c, MID_DINV + 5])
        zx, zy, zz = q_mul(q, rx, ry, rz)
        mid[c, MID_ZSEP], mid[c, MID_ZSEP + 1], mid[c, MID_ZSEP + 2] = zx, zy, zz
        o = N3_SIZE * separator(n, P, c) + N3_VEL
        x[o], x[o + 1], x[o + 2] = zx, zy, zz


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def _eliminate_part(x, tension, M, dt, W, n, P, c):
    """Chunk c's forward pass of :func:`partitioned_solve` (the first and last chunks: a one-direction sweep; a
    middle chunk: its bottom block read and its spike eliminated)."""
    seg = W.seg.shape[1]
    lo, hi = chunk_range(n, P, c)
    ck = W.ckpt[lo // seg + c:]
    if c == 0:
        sweep(x, tension, M, dt, 0, hi, 1, ck, W.mid[c, MID_TOP:MID_TOP + 9], seg)
    elif c == P - 1:
        sweep(x, tension, M, dt, n - 1, hi - lo, -1, ck, W.mid[c, MID_BOT:MID_BOT + 9], seg)
    else:
        _sweep_read(x, tension, M, dt, hi - 1, hi - lo, -1, W.mid[c, MID_BOT:MID_BOT + 9])
        _sweep_spike(x, tension, M, dt, lo, hi - lo, ck, W.mid[c], seg)


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def _back_part(x, tension, M, dt, W, n, P, c):
    """Chunk c's back substitution of :func:`partitioned_solve`, from the separators' solution in ``W.mid``."""
    seg = W.seg.shape[1]
    lo, hi = chunk_range(n, P, c)
    ck = W.ckpt[lo // seg + c:]
    zx, zy, zz = 0.0, 0.0, 0.0
    if c < P - 1:
        zx, zy, zz = W.mid[c, MID_ZSEP], W.mid[c, MID_ZSEP + 1], W.mid[c, MID_ZSEP + 2]
    if c == 0:
        back(x, tension, M, dt, 0, hi, 1, ck, W.seg[c], zx, zy, zz)
    else:
        ux, uy, uz = W.mid[c - 1, MID_ZSEP], W.mid[c - 1, MID_ZSEP + 1], W.mid[c - 1, MID_ZSEP + 2]
        if c == P - 1:
            back(x, tension, M, dt, n - 1, hi - lo, -1, ck, W.seg[c], ux, uy, uz)
        else:
            a, b, tx, ty, tz = element_block(x, lo - 1, 1, tension, M, dt)
            wx, wy, wz = s_mul(a, b, tx, ty, tz, ux, uy, uz)
            _back_spike(x, tension, M, dt, lo, hi - lo, ck, W.seg[c], zx, zy, zz, wx, wy, wz)


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def clamp_parts(n, P, W):
    """The number of chunks :func:`partitioned_solve` uses: P clamped to the workspace's capacity and to
    (n + 1) // 2."""
    return max(1, min(P, W.mid.shape[0], W.seg.shape[0], (n + 1) // 2))


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def partitioned_solve(x, tension, M, dt, W, P):
    """Solve the step's block-tridiagonal system in place of the right-hand side in the velocities of x (6 n,)
    on P chunks (clamped to the workspace's capacity and to (n + 1) // 2): the chunks' eliminations and back
    substitutions in parallel, the separators' reduced system of size P - 1 on one thread. The partition
    depends on n and P only: a given P gives the same bits on any thread count and in every process."""
    n = int(M.par[PP_N])
    P = clamp_parts(n, P, W)
    for c in prange(P):
        _eliminate_part(x, tension, M, dt, W, n, P, c)
    if P > 1:
        _reduce(x, tension, M, dt, n, P, W.mid)
    for c in prange(P):
        _back_part(x, tension, M, dt, W, n, P, c)


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def partitioned_solve_serial(x, tension, M, dt, W, P):
    """:func:`partitioned_solve` on the calling thread (no parallel loop: numba's thread pool is not started;
    the same chunks in order, the same bits)."""
    n = int(M.par[PP_N])
    P = clamp_parts(n, P, W)
    for c in range(P):
        _eliminate_part(x, tension, M, dt, W, n, P, c)
    if P > 1:
        _reduce(x, tension, M, dt, n, P, W.mid)
    for c in range(P):
        _back_part(x, tension, M, dt, W, n, P, c)
