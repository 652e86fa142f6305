"""Block algebra of the implicit point-mass step (``kernels/pointmass/implicit.py``) and the one-directional
block Thomas sweep with its checkpointed back substitution (``kernels/pointmass/partitioned.py`` runs these on
the end chunks of the string).

The step's matrix (M + dt C + dt^2 K) is block-tridiagonal with 3x3 blocks: element e adds
S_e = a t t^T + b I (a = dt DA/l0 + dt^2 EA/l0 - b, b = dt^2 T/l; unit vector t, length l) to the diagonal
blocks of its two nodes and -S_e off the diagonal. Symmetric 3x3 blocks are kept as 6 numbers (xx, yy, zz, xy,
xz, yz); an element's S as the 5 numbers (a, b, tx, ty, tz).
"""

from numba import njit

from laddermill_gym.kernels.contract import N3_SIZE, N3_VEL, PP_DA, PP_EA
from laddermill_gym.kernels.pointmass.forces import element_geometry, has_upper, node_mass, rest_length

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _block(x, e, tension, par, dt):
    """S_e = a t t^T + b I of element e: returns (a, b, tx, ty, tz). Every element keeps its axial stiffness
    and damping within the step (slack ones too: their start-of-step tension is 0; the stiffness resists the change
    of length during the step, a force that vanishes with dt, but the damping applies DA/l0 times the element's
    rate whatever dt: docs/pointmass.md); the geometric term b = dt^2 T/l only under tension."""
    tx, ty, tz, ln = element_geometry(x, e, par)
    l0 = rest_length(e, par)
    b = dt * dt * tension[e] / ln if ln > 0.0 else 0.0
    return dt * par[PP_DA] / l0 + dt * dt * par[PP_EA] / l0 - b, b, tx, ty, tz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def sds(a, b, tx, ty, tz, d0, d1, d2, d3, d4, d5):
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
def inv_sym(d0, d1, d2, d3, d4, d5):
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
def element_block(x, j, step, tension, M, dt):
    """S of the element between node j and node j + step (zero where there is none)."""
    e = j + 1 if step > 0 else j
    if step > 0 and not has_upper(j, M.par):
        return 0.0, 0.0, 0.0, 0.0, 0.0
    return _block(x, e, tension, M.par, dt)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def pivot_block(x, j, step, tension, M, dt, prev, q, first):
    """Inverse pivot of node j in a sweep going ``step`` (+1 up, -1 down): D_j minus, unless ``first``, the
    eliminated previous node's S q S (``prev``: S of the element to node j - step, ``q`` its inverse pivot).
    Returns (inverse pivot, S of the element to node j + step)."""
    m = node_mass(j, M)
    nxt = element_block(x, j, step, tension, M, dt)
    d = (m, m, m, 0.0, 0.0, 0.0)
    for s_e in (prev, nxt):
        a, b, tx, ty, tz = s_e
        d = (d[0] + a * tx * tx + b, d[1] + a * ty * ty + b, d[2] + a * tz * tz + b, d[3] + a * tx * ty,
             d[4] + a * tx * tz, d[5] + a * ty * tz)
    if not first:
        a, b, tx, ty, tz = prev
        e = sds(a, b, tx, ty, tz, q[0], q[1], q[2], q[3], q[4], q[5])
        d = (d[0] - e[0], d[1] - e[1], d[2] - e[2], d[3] - e[3], d[4] - e[4], d[5] - e[5])
    return inv_sym(d[0], d[1], d[2], d[3], d[4], d[5]), nxt


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def s_mul(a, b, tx, ty, tz, vx, vy, vz):
    """S v for S = a t t^T + b I."""
    p = a * (tx * vx + ty * vy + tz * vz)
    return p * tx + b * vx, p * ty + b * vy, p * tz + b * vz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def add_s_mul(x, o, s_e, vx, vy, vz):
    """x[o: o + 3] += S v for the element block s_e = (a, b, tx, ty, tz) of :func:`element_block`."""
    a, b, tx, ty, tz = s_e
    sx, sy, sz = s_mul(a, b, tx, ty, tz, vx, vy, vz)
    x[o] += sx
    x[o + 1] += sy
    x[o + 2] += sz


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def q_mul(q, vx, vy, vz):
    """Symmetric q (6) times v."""
    return (q[0] * vx + q[3] * vy + q[4] * vz, q[3] * vx + q[1] * vy + q[5] * vz,
            q[4] * vx + q[5] * vy + q[2] * vz)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def sweep(x, tension, M, dt, j0, count, step, ckpt, mid, seg):
    """Eliminate ``count`` nodes from j0 going ``step``: r'_j = r_j + S q_prev r'_prev in place in the
    velocities; the inverse pivot at the end of every segment of ``seg`` nodes into ``ckpt`` (columns 0-5);
    the last node's inverse pivot and q r' into ``mid`` (9,)."""
    prev = element_block(x, j0, -step, tension, M, dt)
    q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    yx, yy, yz = 0.0, 0.0, 0.0
    for i in range(count):
        j = j0 + i * step
        o = N3_SIZE * j + N3_VEL
        if i > 0:
            add_s_mul(x, o, prev, yx, yy, yz)
        q, prev = pivot_block(x, j, step, tension, M, dt, prev, q, i == 0)
        yx, yy, yz = q_mul(q, x[o], x[o + 1], x[o + 2])
        if (i + 1) % seg == 0 or i == count - 1:
            for k in range(6):
                ckpt[i // seg, k] = q[k]
    for k in range(6):
        mid[k] = q[k]
    mid[6], mid[7], mid[8] = yx, yy, yz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def back(x, tension, M, dt, j0, count, step, ckpt, buf, vx, vy, vz):
    """Back substitution of a :func:`sweep`: v_j = q_j (r'_j + S_next v_next) from the sweep's last node back
    to j0, v_next starting at (vx, vy, vz), the solution of the node beyond the last; each segment's inverse
    pivots recomputed from the previous segment's checkpoint into ``buf`` (seg, >= 6)."""
    seg = buf.shape[0]
    nseg = (count + seg - 1) // seg
    for c in range(nseg - 1, -1, -1):
        i0 = c * seg
        i1 = min(count, i0 + seg)
        q = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        if c > 0:
            q = (ckpt[c - 1, 0], ckpt[c - 1, 1], ckpt[c - 1, 2], ckpt[c - 1, 3], ckpt[c - 1, 4], ckpt[c - 1, 5])
        prev = element_block(x, j0 + i0 * step, -step, tension, M, dt)
        for i in range(i0, i1):
            q, prev = pivot_block(x, j0 + i * step, step, tension, M, dt, prev, q, i == 0)
            for k in range(6):
                buf[i - i0, k] = q[k]
        for i in range(i1 - 1, i0 - 1, -1):
            j = j0 + i * step
            o = N3_SIZE * j + N3_VEL
            a, b, tx, ty, tz = element_block(x, j, step, tension, M, dt)
            sx, sy, sz = s_mul(a, b, tx, ty, tz, vx, vy, vz)
            qj = (buf[i - i0, 0], buf[i - i0, 1], buf[i - i0, 2], buf[i - i0, 3], buf[i - i0, 4], buf[i - i0, 5])
            vx, vy, vz = q_mul(qj, x[o] + sx, x[o + 1] + sy, x[o + 2] + sz)
            x[o], x[o + 1], x[o + 2] = vx, vy, vz
