"""Linearly implicit (Rosenbrock-W) integrators whose step is not limited by the cable's axial modes.

docs/numerics.md, "A linearly implicit integrator". A Rosenbrock-W method (Hairer & Wanner, Solving ODEs II,
sect. IV.7, the transformed form (7.4')) solves per stage

    (I - h gamma J) U_i = h gamma [ f(t + alpha_i h, y0 + sum_j a_ij U_j) + sum_j (c_ij / h) U_j ],
    y1 = y0 + sum_i m_i U_i,

with one matrix I - h gamma J per step. J holds the cable's stiffness and damping (``kernels/rigid/cable_jacobian.py``)
and the bodies' own load derivatives (``kernels/rigid/body_jacobian.py``); for the cable part,
for the state y = (positions and quaternions x, block velocities v), J = [[0, A], [M^-1 K P, M^-1 C]], A the map
from block velocities to position and quaternion rates, P its left inverse (state increment to displacement,
P A = I), K = dQ/dq and C = dQ/dv of the cable. Eliminating the position rows leaves, per stage,

    S U_v = h gamma [ M r_v + h gamma K P r_x ],   S = M - h gamma C - (h gamma)^2 K,
    U_x = h gamma (r_x + A U_v),

where r is the bracket above: S has the block-tree structure of the mass matrix M (taken at y0), so a stage costs
one O(N) elimination. Entries of the state outside the blocks (the moving cable's station) are explicit
(U = h gamma r). A W-method's order holds for any J, so the Jacobian may leave out the non-stiff terms.

Methods:

* ``ros1``: the linearly implicit Euler method (s = 1, gamma = 1), its stage at the step's mid-time: order 1 for
  any J, L-stable for the exact one; one assembly and one elimination per step.
* ``ros2``: Verwer, Spee, Blom & Hundsdorfer (1999), SIAM J. Sci. Comput. 20(4), gamma = 1 + 1/sqrt(2): order 2
  for any J, L-stable for the exact one; two stages (one assembly, one right-hand side, two eliminations).
* ``ros2t``: the same with gamma = 1/4: order 2 for any J, A-stable and |R(iy)| = 1 for the exact one (not
  L-stable): it damps no oscillation the step does not resolve.
* ``ros34pw2``: Rang & Angermann (2005), BIT Numer. Math. 45: order 3 for any J, stiffly accurate, L-stable for the
  exact one; four stages (one assembly, three right-hand sides, four eliminations).

Status codes as ``kernels/integrate.py``; on a failure the state is left at the last good step.
"""

import math

import numpy as np
from numba import njit, types
from numba.extending import overload

from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    B3_POS,
    B3_QUAT,
    B3_SIZE,
    B3_VEL,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    OK,
    SINGULAR,
)
from laddermill_gym.kernels.dispatch import model_assemble, model_check, model_rhs
from laddermill_gym.kernels.far_call import far_call
from laddermill_gym.kernels.rigid.blocks import copy_blocks, tree_factor, tree_solve_factored
from laddermill_gym.kernels.rigid.body_jacobian import add_body_force, add_body_jacobian
from laddermill_gym.kernels.rigid.cable_jacobian import add_cable_stiffness, add_stiffness_force, moving_end_force

_FM = {"contract", "nsz", "arcp"}


def transformed_tableau(gamma: float, alpha: np.ndarray, gam: np.ndarray, b: np.ndarray, bhat: np.ndarray,
                        stage_times: np.ndarray | None = None):
    """(gamma (1,), stage times alpha_i (s,), a (s, s), c (s, s), m (s,), mhat (s,)) of the transformed form (Hairer &
    Wanner (7.4')) from a method's published coefficients: alpha (s, s) strictly lower, gam (s, s) strictly lower
    (gamma on the diagonal implied), weights b (s,) and the embedded method's bhat (s,). With G = gam + gamma I:
    a = alpha G^-1, c = diag(1/gamma) - G^-1, m = b G^-1, mhat = bhat G^-1. The stage times are alpha's row sums
    unless ``stage_times`` (s,) is given (``ros1``'s mid-time stage)."""
    s = b.size
    G = np.tril(gam, -1) + gamma * np.eye(s)
    Gi = np.linalg.inv(G)
    a = np.tril(alpha, -1) @ Gi
    c = np.tril(np.eye(s) / gamma - Gi, -1)
    # gamma as a one-element array: numba's parallel (prange) lowering passes a tuple argument to its worker
    # function element by element and accepts arrays, not scalars, inside it (a float there crashed the compiler)
    times = np.tril(alpha, -1).sum(axis=1) if stage_times is None else np.array(stage_times, dtype=float)
    return (np.array([float(gamma)]), times, np.ascontiguousarray(np.tril(a, -1)),
            np.ascontiguousarray(c), np.ascontiguousarray(b @ Gi), np.ascontiguousarray(bhat @ Gi))


#: ROS2 (Verwer, Spee, Blom & Hundsdorfer 1999): gamma = 1 + 1/sqrt(2), alpha_21 = 1, gamma_21 = -2 gamma,
#: b = (1/2, 1/2); order 2 for any J (a W-method), L-stable for the exact one; embedded: the first-order
#: linearly implicit Euler y0 + k1 (bhat = (1, 0)).
_G2 = 1.0 + 1.0 / math.sqrt(2.0)
ROS2 = transformed_tableau(_G2, np.array([[0.0, 0.0], [1.0, 0.0]]), np.array([[0.0, 0.0], [-2.0 * _G2, 0.0]]),
                           np.array([0.5, 0.5]), np.array([1.0, 0.0]))
#: ROS2 with gamma = 1/4 (``ros2t``): the same family (Verwer et al. 1999: order 2 for any J and any gamma, since
#: b2 alpha_21 = 1/2 and gamma + b2 gamma_21 = 0), at the smallest gamma for which it is A-stable (its stability
#: function is that of the two-stage SDIRK method of order 2, A-stable for gamma >= 1/4: Hairer & Wanner II,
#: IV.6). With the exact Jacobian R(z) = ((1 + z/4) / (1 - z/4))^2, the trapezoidal rule's at h/2 squared:
#: |R(iy)| = 1 for every y, so oscillations the step does not resolve keep their amplitude (with a phase error)
#: where ROS2 and ROS34PW2 (L-stable) damp them. Not L-stable: R(inf) = 1. Embedded: linearly implicit Euler.
#: Through the apex whip it is no better than ROS34PW2 (docs/work_precision.md, "The apex whip's modes").
ROS2T = transformed_tableau(0.25, np.array([[0.0, 0.0], [1.0, 0.0]]), np.array([[0.0, 0.0], [-0.5, 0.0]]),
                            np.array([0.5, 0.5]), np.array([1.0, 0.0]))
#: ROS1 (``ros1``), the linearly implicit Euler method (Rosenbrock's one-stage method: Hairer & Wanner II, IV.7,
#: (7.4') with s = 1, gamma = 1), its right-hand side taken at the step's middle: (I - h J) U = h f(t + h/2, y0),
#: y1 = y0 + U, with J the state Jacobian only (no f_t column). Order 1 for any J (a W-method: y(t + h) - y1 =
#: h^2 (f_y / 2 - J) f + O(h^3), whatever J), L-stable for the exact one (R(z) = 1 / (1 - z)); one assembly, no
#: further right-hand side, one elimination per step. The mid-time makes the h^2 f_t part of the local error vanish:
#: a rate that depends on time alone (the station's scheduled pay-out, ds/dt = V(t)) is integrated by the midpoint
#: rule, exact on the schedule's linear pieces, where f(t, y0) was explicit Euler and lagged the mill's ramp by
#: h a t / 2 (docs/work_precision_closed_loop.md). No embedded method (mhat = 0: fixed steps only).
ROS1 = transformed_tableau(1.0, np.zeros((1, 1)), np.zeros((1, 1)), np.array([1.0]), np.array([0.0]),
                           stage_times=np.array([0.5]))
#: ROS34PW2 (Rang & Angermann 2005, BIT 45, table 4.2): 4 stages, order 3 for any J (a W-method), stiffly
#: accurate and L-stable for the exact one; embedded method of order 2.
_G34 = 0.435866521508459
ROS34PW2 = transformed_tableau(
    _G34,
    np.array([[0.0, 0.0, 0.0, 0.0], [0.87173304301691801, 0.0, 0.0, 0.0],
              [0.84457060015369423, -0.11299064236484185, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]),
    np.array([[0.0, 0.0, 0.0, 0.0], [-0.87173304301691801, 0.0, 0.0, 0.0],
              [-0.90338057013044082, 0.054180672388095326, 0.0, 0.0],
              [0.24212380706095346, -1.2232505839045147, 0.54526025533510214, 0.0]]),
    np.array([0.24212380706095346, -1.2232505839045147, 1.5452602553351020, 0.435866521508459]),
    np.array([0.37810903145819369, -0.096042292212423178, 0.5, 0.2179332607542295]))


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _vel_offset(c, nw):
    """Offset in the state of block c's velocities (a body's v then omega, or a node's velocity)."""
    if c < nw:
        return B3_SIZE * c + B3_VEL
    return B3_SIZE * nw + N3_SIZE * (c - nw) + N3_VEL


# inlined into the W step (numba IR; called 3-4 times per step): inlining three such parts cut TetheredWing-v0's
# step from 7.1 to 6.3 us (2026-12-05; a slimmer argument list for add_stiffness_force instead gained nothing)
@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def _mass_times(Dm, Um, r, bv, M):
    """bv = M r_v: the block matrix (Dm, Um) times the velocity entries of the state-shaped vector r."""
    nw = M.wtype.size
    order, parent, bsz = M.order, M.parent, M.bsz
    for ii in range(order.size):
        c = order[ii]
        oc = _vel_offset(c, nw)
        n = bsz[c]
        for i in range(n):
            s = 0.0
            for j in range(n):
                s += Dm[c, i, j] * r[oc + j]
            bv[c, i] = s
    for ii in range(order.size):
        c = order[ii]
        p = parent[c]
        if p >= 0:
            oc, op = _vel_offset(c, nw), _vel_offset(p, nw)
            n, m = bsz[c], bsz[p]
            for i in range(n):
                s = 0.0
                for j in range(m):
                    s += Um[c, i, j] * r[op + j]
                bv[c, i] += s
            for j in range(m):
                s = 0.0
                for i in range(n):
                    s += Um[c, i, j] * r[oc + i]
                bv[p, j] += s


# inlined into the W step (numba IR; called 3-4 times per step): inlining three such parts cut TetheredWing-v0's
# step from 7.1 to 6.3 us (2026-12-05; a slimmer argument list for add_stiffness_force instead gained nothing)
@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def _stage_increment(xn, r, Ui, M, W, gh):
    """U_i from the solved block velocities W.bv: velocities as solved, positions and quaternions
    gh (r_x + A U_v) with A at the step's start (rotations W.Rn, quaternions of xn), other entries gh r."""
    nw = M.wtype.size
    nn = M.node_mass.size
    for i in range(Ui.size):
        Ui[i] = gh * r[i]
    for k in range(nw):
        o = B3_SIZE * k
        R = W.Rn[k]
        vx, vy, vz, p, q, rr = W.bv[k, 0], W.bv[k, 1], W.bv[k, 2], W.bv[k, 3], W.bv[k, 4], W.bv[k, 5]
        for i in range(6):
            Ui[o + B3_VEL + i] = W.bv[k, i]
        for i in range(3):
            Ui[o + B3_POS + i] += gh * (R[i, 0] * vx + R[i, 1] * vy + R[i, 2] * vz)
        oq = o + B3_QUAT
        q0, q1, q2, q3 = xn[oq], xn[oq + 1], xn[oq + 2], xn[oq + 3]
        Ui[oq] += gh * 0.5 * (-q1 * p - q2 * q - q3 * rr)
        Ui[oq + 1] += gh * 0.5 * (q0 * p + q2 * rr - q3 * q)
        Ui[oq + 2] += gh * 0.5 * (q0 * q + q3 * p - q1 * rr)
        Ui[oq + 3] += gh * 0.5 * (q0 * rr + q1 * q - q2 * p)
    for j in range(nn):
        o = B3_SIZE * nw + N3_SIZE * j
        b = nw + j
        for i in range(3):
            Ui[o + N3_VEL + i] = W.bv[b, i]
            Ui[o + N3_POS + i] += gh * W.bv[b, i]


#: a held iteration matrix serves steps whose h gamma is within this fraction of its own [-] (rounding of a step
#: size recomputed from times, not a change of step)
REUSE_RTOL = 1e-9


#: The most steps per iteration matrix: the kernels hold the count as an int64.
JACOBIAN_EVERY_MAX = int(np.iinfo(np.int64).max)


def with_jacobian_reuse(tableau, every: int):
    """``tableau`` (a transformed tableau above) whose W step keeps its iteration matrix for ``every`` steps: the
    bodies' load Jacobian, the cable's stiffness and the factorisation are rebuilt on the steps whose index
    round(t / dt) is a multiple of ``every`` (so on every episode's first step, t = 0), when the step size changed
    (beyond ``REUSE_RTOL``) and on a workspace's first step; the other steps solve with the held matrix. Still a
    W-method of the same order: with the mass matrix M0 and the rotations taken at each step's start, the held
    matrix S is M0 - h gamma C~ - (h gamma)^2 K~ for the held stiffness K~ and C~ = C_held + (M0 - M_held) /
    (h gamma), a Jacobian bounded as h -> 0 (Hairer & Wanner II, IV.7: a W-method's order conditions hold for any
    such J). ``every`` = 1 is the tableau itself (today's bits). ValueError naming the value unless an integer
    from 1 to :data:`JACOBIAN_EVERY_MAX`."""
    if isinstance(every, bool) or not isinstance(every, (int, np.integer)) or not 1 <= every <= JACOBIAN_EVERY_MAX:
        raise ValueError(f"jacobian_every = {every!r}: must be an integer from 1 to {JACOBIAN_EVERY_MAX} (steps per "
                         "Jacobian, an int64 in the kernels)")
    if int(every) == 1:
        return tableau
    return tuple(tableau[:6]) + (np.array([int(every)], dtype=np.int64),)


def _reuse_every(tableau):
    """Steps per iteration matrix of ``tableau``: 1 for a plain (6-entry) tableau, else its 7th entry's value
    (jitted code only; resolved by the tableau's type)."""
    raise NotImplementedError("_reuse_every is resolved inside numba kernels")


@overload(_reuse_every, inline="always")
def _reuse_every_impl(tableau):
    if len(tableau) == 6:
        return lambda tableau: 1
    return lambda tableau: tableau[6][0]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def _iteration_matrix(t, xp, u, dt, M, W, gh, every):
    """Build and factor the step's iteration matrix into W.Ds, W.Us, W.Yw, W.pivw (with W.kb, W.ke), unless
    ``every`` > 1 and the one held (h gamma = W.wjac[0]) is kept for this step (:func:`with_jacobian_reuse`).
    Returns False if it is singular."""
    if every > 1:
        # a step of the same size to rounding (a step run on its own between kinks: h = (t + dt) - t) keeps it
        if abs(W.wjac[0] - gh) <= REUSE_RTOL * gh and int(math.floor(t / dt + 0.5)) % every != 0:
            return True
        W.wjac[0] = 0.0
    add_body_jacobian(t, xp, u, M, W, gh, gh * gh)
    add_cable_stiffness(t, xp, M, W, gh, gh * gh)
    copy_blocks(W.D, W.U, W.Ds, W.Us, M.order, M.bsz)
    if not tree_factor(W.Ds, W.Us, W.Yw, W.pivw, M.order, M.parent, M.bsz):  # once: the stages share it
        return False
    if every > 1:
        W.wjac[0] = gh
    return True


# inlined into its callers (same flags): no separate compile of the whole W step (issue 32)
@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def w_step(t, x, u, dt, M, W, tableau):
    """One step of dt [s] of the Rosenbrock-W method ``tableau`` from (t, x): the stage increments into W.k1..k4,
    x into W.xp, the new state (not yet normalised or checked) into x. Returns OK or SINGULAR (x then restored)."""
    gam, alpha, a, c, m = tableau[0][0], tableau[1], tableau[2], tableau[3], tableau[4]
    stages = (W.k1, W.k2, W.k3, W.k4)
    f, r, xt, xp = W.k5, W.k6, W.xt, W.xp
    ns = x.size
    s = m.size
    gh = gam * dt
    nbk = M.order.size
    for i in range(ns):
        xp[i] = x[i]
    # the first stage's time: t for every method whose alpha_1 is 0, the step's middle for ros1 (ROS1 above)
    if model_assemble(M.kind, t + alpha[0] * dt, x, u, f, M, W) != 0:
        return SINGULAR
    copy_blocks(W.D, W.U, W.Dm, W.Um, M.order, M.bsz)
    for k in range(W.Rw.shape[0]):
        for i in range(3):
            for j in range(3):
                W.Rn[k, i, j] = W.Rw[k, i, j]
    if not _iteration_matrix(t, xp, u, dt, M, W, gh, _reuse_every(tableau)):
        return SINGULAR
    ut0, ut1, ut2 = 0.0, 0.0, 0.0  # the stages' time increments (the autonomised time's entries of U_i)
    for st in range(s):
        # the time column's weight: 1 (autonomised time), 0 for a first stage taken at a later time (ros1's
        # mid-time stage has its time derivative from the midpoint instead: no h^2 f_t term)
        rt = 1.0 if st > 0 or alpha[0] == 0.0 else 0.0
        for j in range(st):
            rt += (c[st, j] / dt) * (ut0 if j == 0 else (ut1 if j == 1 else ut2))
        if st == 0:
            for i in range(ns):
                r[i] = f[i]  # W.bv holds M r_v = the generalised forces of the assembly
        else:
            for i in range(ns):
                acc = xp[i]
                for j in range(st):
                    acc += a[st, j] * stages[j][i]
                xt[i] = acc
            if model_rhs(M.kind, t + alpha[st] * dt, xt, u, f, M, W) != 0:
                for i in range(ns):
                    x[i] = xp[i]
                return SINGULAR
            for i in range(ns):
                acc = f[i]
                for j in range(st):
                    acc += (c[st, j] / dt) * stages[j][i]
                r[i] = acc
            _mass_times(W.Dm, W.Um, r, W.bv, M)
        add_stiffness_force(xp, r, M, W, gh)
        add_body_force(xp, r, M, W, gh)
        moving_end_force(M.kind, t, xp, r, rt, M, W, gh)
        if st == 0:
            ut0 = gh * rt
        elif st == 1:
            ut1 = gh * rt
        elif st == 2:
            ut2 = gh * rt
        for b in range(nbk):
            for i in range(6):
                W.bv[b, i] *= gh
        tree_solve_factored(W.Ds, W.Us, W.Yw, W.pivw, W.bv, M.order, M.parent, M.bsz)
        _stage_increment(xp, r, stages[st], M, W, gh)
    for i in range(ns):
        acc = xp[i]
        for j in range(s):
            acc += m[j] * stages[j][i]
        x[i] = acc
    return OK


def w_step_calls(t, x, u, dt, M, W, tableau) -> list:
    """The kernels :func:`w_step` compiles as callees of its own (its model kind's assembly, right-hand side and
    check aside: the kind lists those, e.g. ``kernels/rigid/kinds.rigid3d_calls``), in the order it calls them, as
    (dispatcher, arguments) pairs whose Python values have the numba types w_step passes at (t [s], x, u, dt [s])
    with the model M and workspace W of one copy: ``dispatcher.compile`` of their types compiles (or loads) the
    same specialisation the step kernel uses, without running it (the kernel warm-up, ``envs/task_warmup.py``,
    issue 32). Keep it in step with :func:`w_step`: a pair that differs only costs a compile nothing uses. The
    stage's small parts ``_mass_times``, ``add_body_force`` and ``_stage_increment`` are inlined into the step
    (numba's ``inline="always"``), so they are not among them."""
    gh = float(tableau[0][0]) * float(dt)
    xp = W.xp
    return [(copy_blocks, (W.D, W.U, W.Dm, W.Um, M.order, M.bsz)),
            (add_body_jacobian, (t, xp, u, M, W, gh, gh * gh)),
            (add_cable_stiffness, (t, xp, M, W, gh, gh * gh)),
            (tree_factor, (W.Ds, W.Us, W.Yw, W.pivw, M.order, M.parent, M.bsz)),
            (add_stiffness_force, (xp, W.k6, M, W, gh)),
            (tree_solve_factored, (W.Ds, W.Us, W.Yw, W.pivw, W.bv, M.order, M.parent, M.bsz))]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def w_advance_one(t, x, u, dt, M, W, limits, tableau):
    """One step of dt [s] of the Rosenbrock-W method ``tableau`` from (t [s], x), x advanced in place and checked
    (``model_check``). Returns the status; on a failure x is the state before the step. The step the loop
    :func:`w_advance` calls through its address: compiled on its own, without a loop around it, the same
    arithmetic runs in 7.5 instead of 10.3 us on TetheredWing-v0's copies (one thread, 2026-12-05; LLVM optimises
    the inlined step worse inside the loop)."""
    if w_step(t, x, u, dt, M, W, tableau) != OK:
        return SINGULAR
    status = model_check(M.kind, x, M, limits)
    if status != OK:
        for i in range(x.size):
            x[i] = W.xp[i]
    return status


_W_ONE_FAR = far_call(w_advance_one, types.int64)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, nogil=True)
def w_advance(t, x, u, dt, n, M, W, limits, tableau):
    """Advance x in place by n steps of size dt [s] of the Rosenbrock-W method ``tableau`` (e.g. :data:`ROS2`:
    gamma, alpha, a, c, m, mhat; at most 4 stages), each by :func:`w_advance_one` through its compiled address
    (``kernels/far_call.py``: this loop compiles in a fraction of a second, the step once, on its own). Returns
    (status, steps done); on a failure x is the state before the failed step."""
    for step in range(n):
        status = _W_ONE_FAR(t, x, u, dt, M, W, limits, tableau)
        if status != OK:
            return status, step
        t += dt
    return OK, n
