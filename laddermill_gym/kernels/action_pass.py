"""The envs' action path in compiled code (issue 32 point 2): the finiteness check, the clip to [-1, 1] with its
count, and the map of normalised actions to the controls of the copies stepped, in one pass over the copies each,
so that the Python work of a vector step does not grow with the number of copies.

The arithmetic is that of the numpy code these kernels replace (``envs/actions.py``: ``np.clip``,
``np.count_nonzero(np.abs(a) > 1)``, ``mid + a * half`` clipped to the limits), operation for operation and without
fastmath (a fused multiply-add would change last bits), so the controls are bit for bit those of before
(tests/test_action_pass.py holds them to the numpy code as the reference). Serial: a copy costs nanoseconds here.
"""

from numba import njit


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def clip_count(a, out, n_clipped):
    """out (B, n) float64 = ``a`` (B, n) clipped to [-1, 1], n_clipped (B,) the entries with |a| > 1 per row.
    Returns -1, or the flat index of the first non-finite entry (out is then incomplete)."""
    nb, n = a.shape
    for b in range(nb):
        k = 0
        for j in range(n):
            v = float(a[b, j])
            if v - v != 0.0:  # nan or inf
                return b * n + j
            if abs(v) > 1.0:
                k += 1
            v = v if v > -1.0 else -1.0  # numpy's clip: min(max(v, lo), hi), max(a, b) = a if a > b else b
            out[b, j] = v if v < 1.0 else 1.0
        n_clipped[b] = k
    return -1


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def grouped_controls(a, group_of, mid, half, lo, hi, sel, controls, last_action):
    """For every copy b with sel[b]: controls[b, 3 k + j] = clip(mid[k, j] + a[b, 3 g(k) + j] half[k, j], lo[k, j],
    hi[k, j]) for each wing k of group g(k) = group_of[k] and control j, and last_action[b] = a[b] (a already
    clipped). Copies outside ``sel`` are untouched."""
    nb, na = a.shape
    nw, nc = mid.shape
    for b in range(nb):
        if not sel[b]:
            continue
        for k in range(nw):
            g = group_of[k]
            for j in range(nc):
                u = mid[k, j] + a[b, nc * g + j] * half[k, j]
                u = u if u > lo[k, j] else lo[k, j]
                controls[b, nc * k + j] = u if u < hi[k, j] else hi[k, j]
        for i in range(na):
            last_action[b, i] = a[b, i]


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def affine_controls(a, mid, half, sel, controls, last_action):
    """For every copy b with sel[b]: controls[b] = mid + a[b] half (no clip: a within [-1, 1] keeps the controls
    within [mid - half, mid + half]) and last_action[b] = a[b]. Copies outside ``sel`` are untouched."""
    nb, na = a.shape
    for b in range(nb):
        if not sel[b]:
            continue
        for i in range(na):
            controls[b, i] = mid[i] + a[b, i] * half[i]
            last_action[b, i] = a[b, i]
