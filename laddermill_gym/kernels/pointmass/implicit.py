"""Linearly implicit Euler for the point-mass string: the string's stiffness (axial EA/l0 and geometric T/l)
and its Voigt damping are taken implicitly along the string; gravity, cable drag and the kites' aerodynamics
explicitly. One step solves

    (M + dt C + dt^2 K) v+ = M v + dt F(x, v),   x+ = x + dt v+,

with M the lumped node masses (diagonal), C and K the string's damping and tangent stiffness at the start of
the step and F the elastic and external forces. Element e adds S_e = dt C_e + dt^2 K_e =
a t t^T + b I (a = dt DA/l0 + dt^2 EA/l0 - b, b = dt^2 T/l; b zero when slack) to the diagonal blocks of its two
nodes and -S_e off the diagonal: a block-tridiagonal system with 3x3 blocks (``kernels/pointmass/blocks.py``),
solved by block elimination along the string in O(n). Each pivot D'_j = D_j - S_j D'_{j-1}^{-1} S_j is
symmetric positive definite (M > 0, S_e >= 0), so no pivoting is needed.

The elimination is partitioned (``kernels/pointmass/partitioned.py``): P chunks separated by P - 1 nodes are
eliminated on P threads, the separators' reduced system of size P - 1 is solved on one, and the chunks
back-substitute on P threads again; P = 2 (the least, from three nodes on) is the two-sided elimination (from
both ends towards the middle). P follows numba's thread count (``solver_parts``: one chunk per thread, at
least ``MIN_PART`` nodes each), or is given (:func:`implicit_advance_parts`).

Memory: the right-hand side and the eliminated right-hand side overwrite the velocities in place; the inverse
pivots (6 numbers each) are kept only at every ``seg``-th node (``W.ckpt``) and recomputed one segment at a time
on the way back (``W.seg``): 6 (n / seg + P seg) numbers instead of 6 n, at the price of a second forward pass
over the blocks (no right-hand side). The assembly and the move are parallel over chunks of nodes.

The moving cable (``kernels/pointmass/mill.py``) steps with :func:`mill_implicit_step`: the same step with the end
elements' pay-out term (``mill.pay_out_rhs``) added to the right-hand side of nodes 0 and n-1 after the assembly,
M v + dt (F(x, v) + F_pay-out(x)), so that the kites' aerodynamics and the cable drag are taken at the state's
velocity (docs/pointmass_mill.md). The fixed string's kernels are left as they were.
"""

from numba import njit, prange
from numba.np.ufunc.parallel import _iget_num_threads

from laddermill_gym.kernels.contract import N3_SIZE, N3_VEL, PM_OK, PP_N, TM_DT, TM_T0
from laddermill_gym.kernels.pointmass.explicit import (
    CHUNK,
    move_and_check,
    move_and_check_serial,
    tensions,
    tensions_serial,
)
from laddermill_gym.kernels.pointmass.forces import node_force, node_mass
from laddermill_gym.kernels.pointmass.mill import pay_out_rhs
from laddermill_gym.kernels.pointmass.partitioned import partitioned_solve, partitioned_solve_serial, solver_parts
from laddermill_gym.kernels.wind import modulation

_FM = {"contract", "nsz", "arcp"}

# numba's thread count inside a compiled function is ``_iget_num_threads()``, the intrinsic of numba's own
# parallel loops (cacheable, unlike ``numba.get_num_threads()``, a ctypes call); its symbol exists once the thread
# pool is started, which this module no longer does at import (GNU OpenMP's pool is not fork-safe, issue 34 item
# 11): only :func:`implicit_advance` reads it, and its callers start the pool first (``numba.set_num_threads``,
# ``sim.pointmass.run_on_threads``).


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _assemble_chunk(t, x, u, dt, M, tension, s, d, j0, j1):
    for j in range(j0, j1):
        fx, fy, fz = node_force(t, x, j, u, M, tension, s, d)
        m = node_mass(j, M)
        o = N3_SIZE * j + N3_VEL
        x[o] = m * x[o] + dt * fx
        x[o + 1] = m * x[o + 1] + dt * fy
        x[o + 2] = m * x[o + 2] + dt * fz


@njit(cache=True, error_model="numpy", parallel=True, _nrt=True, fastmath=False)
def _assemble(t, x, u, dt, M, tension, s, d):
    """r_j = m_j v_j + dt (F_ext + F_elastic) in place in the velocities (parallel over nodes)."""
    n = int(M.par[PP_N])
    for c in prange((n + CHUNK - 1) // CHUNK):
        _assemble_chunk(t, x, u, dt, M, tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def implicit_advance_parts(t, x, u, dt, nsteps, M, W, parts):
    """:func:`implicit_advance` with the elimination on ``parts`` chunks (``partitioned_solve``; at least 1)."""
    P = max(1, parts)
    for k in range(nsteps):
        tk = t + k * dt
        s, d, _, _ = modulation(tk, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        tensions(x, M, W.tension, False)
        _assemble(tk, x, u, dt, M, W.tension, s, d)
        partitioned_solve(x, W.tension, M, dt, W, P)
        st = move_and_check(x, dt, M.par)
        if st != PM_OK:
            return st, k + 1
    return PM_OK, nsteps


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def implicit_advance(t, x, u, dt, nsteps, M, W):
    """Advance the state x (6 n,) in place by ``nsteps`` linearly implicit Euler steps of dt [s] from time t
    [s], kites' attitude u (n_k * 3,) [rad]. ``W.tension`` holds the elastic tensions at the start of the last
    step. The elimination runs on one chunk per thread of numba's current count (``solver_parts``). Returns
    (status, steps done)."""
    n = int(M.par[PP_N])
    return implicit_advance_parts(t, x, u, dt, nsteps, M, W, solver_parts(n, _iget_num_threads(), W.mid.shape[0]))


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def implicit_advance_serial(t, x, u, dt, nsteps, M, W):
    """:func:`implicit_advance` on the calling thread, the elimination on the chunks of one thread
    (``solver_parts(n, 1, ...)``): no parallel loop, so numba's thread pool is never started (a fork of the
    process can run it); the same bits as :func:`implicit_advance` on one thread."""
    n = int(M.par[PP_N])
    P = solver_parts(n, 1, W.mid.shape[0])
    for k in range(nsteps):
        tk = t + k * dt
        s, d, _, _ = modulation(tk, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
        tensions_serial(x, M, W.tension, False)
        for c in range((n + CHUNK - 1) // CHUNK):
            _assemble_chunk(tk, x, u, dt, M, W.tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))
        partitioned_solve_serial(x, W.tension, M, dt, W, P)
        st = move_and_check_serial(x, dt, M.par)
        if st != PM_OK:
            return st, k + 1
    return PM_OK, nsteps


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def mill_implicit_step(t, x, u, dt, M, W):
    """One step of the moving string from t [s]: :func:`implicit_advance`'s step with the pay-out term
    (``mill.pay_out_rhs``) added to the assembled right-hand side, the elimination on one chunk per thread of numba's
    current count. Returns the status."""
    n = int(M.par[PP_N])
    P = max(1, solver_parts(n, _iget_num_threads(), W.mid.shape[0]))
    s, d, _, _ = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    tensions(x, M, W.tension, False)
    _assemble(t, x, u, dt, M, W.tension, s, d)
    pay_out_rhs(x, M, dt)
    partitioned_solve(x, W.tension, M, dt, W, P)
    return move_and_check(x, dt, M.par)


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def mill_implicit_step_serial(t, x, u, dt, M, W):
    """:func:`mill_implicit_step` on the calling thread (no parallel loop, as :func:`implicit_advance_serial`)."""
    n = int(M.par[PP_N])
    P = solver_parts(n, 1, W.mid.shape[0])
    s, d, _, _ = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    tensions_serial(x, M, W.tension, False)
    for c in range((n + CHUNK - 1) // CHUNK):
        _assemble_chunk(t, x, u, dt, M, W.tension, s, d, c * CHUNK, min(n, (c + 1) * CHUNK))
    pay_out_rhs(x, M, dt)
    partitioned_solve_serial(x, W.tension, M, dt, W, P)
    return move_and_check_serial(x, dt, M.par)
