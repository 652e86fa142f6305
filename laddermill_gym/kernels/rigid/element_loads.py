"""What the 3D and the in-plane right-hand sides (``rhs3d.py``, ``rhs2d.py``) compute alike: clearing the block
system, an element's consistent lumping of a linearly varying load to its two ends, and its tension (plain, or with
the sag's lateral elongation). Imports ``kernels`` only. Inlined into both (numba ``inline="always"``), so the
arithmetic is the callers' own."""

from numba import njit

from laddermill_gym.kernels.cable import lateral_elongation, tension_plain, tension_sag

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def clear_blocks(D, U, bv, nbk, nd):
    """Zero the first nd x nd entries of the diagonal blocks D, the blocks to the parent U and the first nd entries of
    the generalised forces bv of blocks 0 .. nbk - 1 (nd: 6 in 3D, 3 in-plane)."""
    for b in range(nbk):
        for i in range(nd):
            bv[b, i] = 0.0
            for j in range(nd):
                D[b, i, j] = 0.0
                U[b, i, j] = 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def split_ends(c, r1, r2, r3, s1, s2, s3):
    """The shares at the ends r and s of c times a quantity varying linearly from (r1, r2, r3) to (s1, s2, s3) along
    an element: c (2 r + s) and c (r + 2 s) per axis (docs/model.md eq. 24, c = l / 6 or -m / 6)."""
    return (c * (2.0 * r1 + s1), c * (2.0 * r2 + s2), c * (2.0 * r3 + s3),
            c * (r1 + 2.0 * s1), c * (r2 + 2.0 * s2), c * (r3 + 2.0 * s3))


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def element_tension(EA, DA, l0, ln, eps, epsd, sag, u, pr, ps):
    """Tension [N] of an element of length ln [m], elongation eps [m] and material elongation rate epsd [m/s]:
    plain, or (``sag``) with the lateral elongation of its distributed loads pr, ps [N/m] at its ends across its
    direction u (3-tuples; an in-plane element passes 0 for y)."""
    if not sag:
        return tension_plain(EA, DA, l0, eps, epsd)
    if ln > 1e-9:
        epsp = lateral_elongation(ln, u[0], u[1], u[2], pr[0], pr[1], pr[2], ps[0], ps[1], ps[2])
    else:
        epsp = 0.0
    return tension_sag(EA, DA, l0, eps, epsd, epsp)
