"""Explicit stepping of the point-mass fidelity: symplectic (semi-implicit) Euler, Podgaets & Ockels eq. (22)
with the position updated from the new velocity.

One step holds nothing but the state (6 n) and the element tensions (n_e): pass 1 (parallel over elements)
writes the Voigt tensions from the old state, pass 2 (parallel over nodes) updates each node's velocity from
them, its own velocity and the old positions, pass 3 (parallel over nodes) moves the nodes and checks them.
An RK4 would hold four stage vectors (4 x 24 MB at 500,000 nodes) and not fit the 40 MB budget; symplectic
Euler is second-order accurate in phase for the undamped string and stable for dt < l0 / c (c = sqrt(EA/mu));
with Voigt damping while (dt c / l0)^2 + dt 2 DA / (mu l0^2) < 1 (``sim.pointmass.explicit_stable_dt``,
docs/pointmass.md).
"""

import math

from numba import njit, prange

from laddermill_gym.kernels.contract import (
    N3_POS,
    N3_SIZE,
    N3_VEL,
    PM_GROUND,
    PM_LIMIT,
    PM_NONFINITE,
    PM_OK,
    PP_GROUND,
    PP_MAX_SPEED,
    PP_N,
    TM_DT,
    TM_T0,
)
from laddermill_gym.kernels.pointmass.forces import element_tension, n_elements, node_force, node_mass
from laddermill_gym.kernels.wind import modulation

_FM = {"contract", "nsz", "arcp"}


#: Nodes (elements) per task of the parallel loops: each task calls a kernel compiled without numba's reference
#: counting (``_nrt=False``; the field reads of the packed model would otherwise incref and decref its arrays
#: at every node, a tenfold cost measured on the elimination), and a task amortises the call.
CHUNK = 2048


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _tension_chunk(x, M, tension, damped, e0, e1):
    par = M.par
    for e in range(e0, e1):
        tension[e] = element_tension(x, e, par, damped)


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def tensions(x, M, tension, damped):
    """Write every element's tension [N] into ``tension`` (n_e,), with Voigt damping when ``damped``."""
    ne = n_elements(M.par)
    for c in prange((ne + CHUNK - 1) // CHUNK):
        _tension_chunk(x, M, tension, damped, c * CHUNK, min(ne, (c + 1) * CHUNK))


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _move_chunk(x, dt, par, j0, j1):
    """Move nodes j0..j1-1; returns the worst status among them."""
    hg, vmax = par[PP_GROUND], par[PP_MAX_SPEED]
    st = PM_OK
    for j in range(j0, j1):
        o = N3_SIZE * j
        v2 = 0.0
        for i in range(3):
            v = x[o + N3_VEL + i]
            x[o + N3_POS + i] += dt * v
            v2 += v * v
        z = x[o + N3_POS + 2]
        if not (math.isfinite(z) and math.isfinite(v2)):
            return PM_NONFINITE
        if v2 > vmax * vmax:
            st = PM_LIMIT
        elif -z <= hg and st == PM_OK:
            st = PM_GROUND
    return st


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def _worst(bad_nf, bad_v, bad_g):
    """The status of a move from the counts of chunks that ended non-finite, over the speed limit, on the ground."""
    if bad_nf > 0:
        return PM_NONFINITE
    if bad_v > 0:
        return PM_LIMIT
    if bad_g > 0:
        return PM_GROUND
    return PM_OK


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def move_and_check(x, dt, par):
    """x += dt v for every node (parallel); returns a status: non-finite, speed limit, ground (h <= h_g)."""
    n = int(par[PP_N])
    nc = (n + CHUNK - 1) // CHUNK
    bad_nf, bad_v, bad_g = 0, 0, 0
    for c in prange(nc):
        st = _move_chunk(x, dt, par, c * CHUNK, min(n, (c + 1) * CHUNK))
        bad_nf += st == PM_NONFINITE
        bad_v += st == PM_LIMIT
        bad_g += st == PM_GROUND
    return _worst(bad_nf, bad_v, bad_g)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _kick_chunk(t, x, u, dt, M, tension, s, d, j0, j1):
    for j in range(j0, j1):
        fx, fy, fz = node_force(t, x, j, u, M, tension, s, d)
        h = dt / node_mass(j, M)
        o = N3_SIZE * j + N3_VEL
        x[o] += h * fx
        x[o + 1] += h * fy
        x[o + 2] += h * fz


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def _kick(t, x, u, dt, M, tension, s, d):
    n = int(M.par[PP_N])
    for c in prange((n + CHUNK - 1) // CHUNK):
        _kick_chunk(t, x, u, dt, M, tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def explicit_advance(t, x, u, dt, nsteps, M, W):
    """Advance the state x (6 n,) in place by ``nsteps`` symplectic Euler steps of dt [s] from time t [s] with
    the kites' commanded attitude u (n_k * 3,) [rad]. Returns (status, steps done)."""
    for k in range(nsteps):
        tk = t + k * dt
        s, d, _, _ = modulation(tk, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        tensions(x, M, W.tension, True)
        _kick(tk, x, u, dt, M, W.tension, s, d)
        st = move_and_check(x, dt, M.par)
        if st != PM_OK:
            return st, k + 1
    return PM_OK, nsteps


# The serial twins: the same chunks in the same order on the calling thread, in functions that hold no parallel
# loop, so a process that only runs these never starts numba's thread pool (GNU OpenMP's is not fork-safe: a
# process forked from one that started it cannot run a parallel loop; issue 34 item 11). Same bits as the parallel
# kernels on any thread count (each chunk's arithmetic is independent of the others).
@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def tensions_serial(x, M, tension, damped):
    """:func:`tensions` on the calling thread."""
    ne = n_elements(M.par)
    for c in range((ne + CHUNK - 1) // CHUNK):
        _tension_chunk(x, M, tension, damped, c * CHUNK, min(ne, (c + 1) * CHUNK))


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def move_and_check_serial(x, dt, par):
    """:func:`move_and_check` on the calling thread."""
    n = int(par[PP_N])
    bad_nf, bad_v, bad_g = 0, 0, 0
    for c in range((n + CHUNK - 1) // CHUNK):
        st = _move_chunk(x, dt, par, c * CHUNK, min(n, (c + 1) * CHUNK))
        bad_nf += st == PM_NONFINITE
        bad_v += st == PM_LIMIT
        bad_g += st == PM_GROUND
    return _worst(bad_nf, bad_v, bad_g)


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def explicit_advance_serial(t, x, u, dt, nsteps, M, W):
    """:func:`explicit_advance` on the calling thread (no parallel loop)."""
    n = int(M.par[PP_N])
    for k in range(nsteps):
        tk = t + k * dt
        s, d, _, _ = modulation(tk, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        tensions_serial(x, M, W.tension, True)
        for c in range((n + CHUNK - 1) // CHUNK):
            _kick_chunk(tk, x, u, dt, M, W.tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))
        st = move_and_check_serial(x, dt, M.par)
        if st != PM_OK:
            return st, k + 1
    return PM_OK, nsteps


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _accel_chunk(t, x, u, M, tension, out, s, d, j0, j1):
    for j in range(j0, j1):
        fx, fy, fz = node_force(t, x, j, u, M, tension, s, d)
        m = node_mass(j, M)
        out[3 * j] = fx / m
        out[3 * j + 1] = fy / m
        out[3 * j + 2] = fz / m


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def accelerations(t, x, u, M, tension, out):
    """Accelerations [m/s^2] of every node (3 n,) with Voigt tensions: the right-hand side of the string
    (the tests' reference integrations use it)."""
    n = int(M.par[PP_N])
    s, d, _, _ = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    tensions(x, M, tension, True)
    for c in prange((n + CHUNK - 1) // CHUNK):
        _accel_chunk(t, x, u, M, tension, out, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))
