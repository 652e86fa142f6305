"""The cable's stiffness and damping as block matrices: the implicit part of the linearly implicit integrator
(``kernels/rigid/rosenbrock.py``, docs/numerics.md "A linearly implicit integrator").

A taut element between attachment points p_r and p_s (unit vector u from r to s, length l, tension sigma) pulls
end r with F_r = sigma u and end s with -F_r. Its force changes with the relative displacement d = dp_s - dp_r and
relative velocity d' as dF_r = K_e d + C_e d' with

    K_e = (dsigma/dl) u u^T + (sigma / l) (I - u u^T)        (axial and geometric stiffness) [N/m]
    C_e = (dsigma/dl') u u^T                                  (Voigt damping) [N s/m]

with dsigma/dl = EA / l0 and dsigma/dl' = DA / l0, the plain truss's, used for every element:

* With the sag correction sigma is the root of s^3 - s0 s^2 - c = 0 (s0 = (EA eps + DA eps') / l0, c = EA eps_p /
  l0 growing like l^3); implicit differentiation gives the softer ds = (s^2 ds0 + dc) / (3 s^2 - 2 s0 s) with
  dc/dl = 3 c / l, c = s^3 - s0 s^2 (3.6 times softer on the tethered wing's lower element). Measured on
  ladder_chain (10 s, direction step): with it, ROS34PW2's position error at 0.05 s halves (0.028 against 0.058 m),
  but its largest stable step falls from 0.2 s to 0.1 s (the wings at the chain's apex diverge at t = 7.8 s). The
  stiffer plain value damps the axial modes more and keeps the larger steps; we chose it.
* A slack element (zero tension) contributes nothing (its true Jacobian); with the sag correction an element shorter
  than its rest length that carries a lateral load has a tension and counts as taut (docs/numerics.md: up to 693x
  its true d sigma / d l at ladder_chain's apex). Giving a slack one EA / l0 as if taut changed nothing measurable
  on ladder_chain (the same errors and failures on the smooth and direction-step forcings). With an attachment
point's velocity T v of its block's velocity v (eq. 13), the generalised forces Q = T^T F change by
-T_r^T K_e T_r on the r-block's diagonal, +T_r^T K_e T_s off it, and likewise for s: the same sparsity as the mass
matrix, so the iteration matrix S = M - h gamma dQ/dv - (h gamma)^2 dQ/dq keeps its tree and its O(N) elimination.
The moving cable's rest length and its rate (station states and time) enter through :func:`add_moving_end_force`.
The change of c with the direction of the lateral loads is left out of this Jacobian on purpose: the integrator is a
W-method, whose order holds for any approximation of the Jacobian (only its stability relies on the stiff part
being there).
"""

import math

from numba import njit

from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.contract import (
    B3_POS,
    B3_QUAT,
    B3_SIZE,
    EF_DA,
    EF_EA,
    END_NODE,
    END_WING,
    KE_XX,
    KE_XY,
    KE_XZ,
    KE_YY,
    KE_YZ,
    KE_ZZ,
    N3_POS,
    N3_SIZE,
)
from laddermill_gym.kernels.dispatch import elongation_rate, has_moving_ends, inline_overload, rest_length
from laddermill_gym.kernels.rigid.rhs3d import block_of, end_kinematics

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _add_t_g_t(A, n1, T1, n2, T2, G, sign):
    """A[:n1, :n2] += sign T1^T G T2 (G symmetric 3 x 3)."""
    for i in range(n1):
        g0 = G[0, 0] * T1[0, i] + G[1, 0] * T1[1, i] + G[2, 0] * T1[2, i]
        g1 = G[0, 1] * T1[0, i] + G[1, 1] * T1[1, i] + G[2, 1] * T1[2, i]
        g2 = G[0, 2] * T1[0, i] + G[1, 2] * T1[1, i] + G[2, 2] * T1[2, i]
        for j in range(n2):
            A[i, j] += sign * (g0 * T2[0, j] + g1 * T2[1, j] + g2 * T2[2, j])


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _element_ends(e, x, M, W, nw):
    """Element e's ends at x with the rotations W.Rn: (end kinds and indices kr, ir, ks, is_, their block sizes nr,
    ns, the vector from r to s (lx, ly, lz) [m] and its length [m]); the ends' maps in W.Tr, W.Ts, W.er, W.es."""
    kr, ks = M.ek[e, 0], M.ek[e, 1]
    ir, is_ = M.ei[e, 0], M.ei[e, 1]
    nr = end_kinematics(kr, ir, M.ea[e, 0], x, W.Rn, M.fixed, nw, W.Tr, W.er)
    ns = end_kinematics(ks, is_, M.ea[e, 1], x, W.Rn, M.fixed, nw, W.Ts, W.es)
    lx, ly, lz = W.es[0] - W.er[0], W.es[1] - W.er[1], W.es[2] - W.er[2]
    return kr, ir, ks, is_, nr, ns, lx, ly, lz, math.sqrt(lx * lx + ly * ly + lz * lz)


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def add_cable_stiffness(t, x, M, W, gh, gh2):
    """Add to the blocks W.D, W.U (holding the mass matrix at t, x) the cable's gh C + gh2 K terms of the iteration
    matrix, gh = h gamma [s] and gh2 = (h gamma)^2 [s^2], and store each element's K_e in W.ke (slots ``KE_*``).

    Uses the body rotations W.Rn and the tensions W.tension of the assembly at (t, x); W.Tr, W.Ts, W.er, W.es
    and W.Y[0, :3, :3] are scratch. A taut element's pull on a body also turns with it (:func:`_add_lever_turn`):
    that part adds to W.kb, so :func:`~laddermill_gym.kernels.rigid.body_jacobian.add_body_jacobian` runs first."""
    nw = M.wtype.size
    G = W.Y[0]
    for e in range(M.ef.shape[0]):
        kr, ir, ks, is_, nr, ns, lx, ly, lz, ln = _element_ends(e, x, M, W, nw)
        sig = W.tension[e]
        ke = W.ke[e]
        if not ln > 1e-9:
            for i in range(ke.size):
                ke[i] = 0.0
            continue
        ux, uy, uz = lx / ln, ly / ln, lz / ln
        l0 = rest_length(M.kind, e, t, x, M)
        EA, DA = M.ef[e, EF_EA], M.ef[e, EF_DA]
        # the plain truss's derivatives for a taut element, sagging or not; none for a slack one (module docstring)
        ka = EA / l0 if sig > 0.0 else 0.0
        ca = DA / l0 if sig > 0.0 else 0.0
        gs = sig / ln
        uu = ((ux * ux, ux * uy, ux * uz), (uy * ux, uy * uy, uy * uz), (uz * ux, uz * uy, uz * uz))
        for i in range(3):
            for j in range(3):
                kij = (ka - gs) * uu[i][j] + (gs if i == j else 0.0)
                G[i, j] = gh * ca * uu[i][j] + gh2 * kij
        ke[KE_XX], ke[KE_YY], ke[KE_ZZ] = (ka - gs) * ux * ux + gs, (ka - gs) * uy * uy + gs, (ka - gs) * uz * uz + gs
        ke[KE_XY], ke[KE_XZ], ke[KE_YZ] = (ka - gs) * ux * uy, (ka - gs) * ux * uz, (ka - gs) * uy * uz
        br = block_of(kr, ir, nw)
        bs = block_of(ks, is_, nw)
        if br >= 0:
            _add_t_g_t(W.D[br], nr, W.Tr, nr, W.Tr, G, 1.0)
        if bs >= 0:
            _add_t_g_t(W.D[bs], ns, W.Ts, ns, W.Ts, G, 1.0)
        ch = M.echild[e]
        if ch == 0:
            _add_t_g_t(W.U[br], nr, W.Tr, ns, W.Ts, G, -1.0)
        elif ch == 1:
            _add_t_g_t(W.U[bs], ns, W.Ts, nr, W.Tr, G, -1.0)
        if sig > 0.0:
            if kr == END_WING:
                _add_lever_turn(W, ir, M.ea[e, 0], sig * ux, sig * uy, sig * uz, gh2)
            if ks == END_WING:
                _add_lever_turn(W, is_, M.ea[e, 1], -sig * ux, -sig * uy, -sig * uz, gh2)


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _add_lever_turn(W, k, a, fx, fy, fz, gh2):
    """The change of a body's generalised cable force Q = (R^T F, a x R^T F) when the body turns by a small dtheta
    (body axes) under a fixed global force F at its attachment a: R^T F gains F_b x dtheta, so dQ/dtheta =
    ([F_b]x, [a]x [F_b]x) (6 x 3), added to W.kb[k] and, times gh2, subtracted from the rotation columns of the
    block W.D[k]."""
    R = W.Rn[k]
    bx = R[0, 0] * fx + R[1, 0] * fy + R[2, 0] * fz
    by = R[0, 1] * fx + R[1, 1] * fy + R[2, 1] * fz
    bz = R[0, 2] * fx + R[1, 2] * fy + R[2, 2] * fz
    fb = ((0.0, -bz, by), (bz, 0.0, -bx), (-by, bx, 0.0))
    am = ((0.0, -a[2], a[1]), (a[2], 0.0, -a[0]), (-a[1], a[0], 0.0))
    kb = W.kb[k]
    Dk = W.D[k]
    for i in range(3):
        for j in range(3):
            v = fb[i][j]
            w = am[i][0] * fb[0][j] + am[i][1] * fb[1][j] + am[i][2] * fb[2][j]
            kb[i, j] += v
            kb[3 + i, j] += w
            Dk[i, 3 + j] -= gh2 * v
            Dk[3 + i, 3 + j] -= gh2 * w


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _end_displacement(kind, idx, att, xn, rx, Rn, nw):
    """Displacement (global, 3) [m] of an element end for the state increment rx at the state xn: a body's
    CG displacement plus R (dtheta x a) with the small rotation dtheta = 2 vec(conj(q) * dq) [rad]."""
    if kind == END_WING:
        o = B3_SIZE * idx
        oq = o + B3_QUAT
        q0, q1, q2, q3 = xn[oq], xn[oq + 1], xn[oq + 2], xn[oq + 3]
        d0, d1, d2, d3 = rx[oq], rx[oq + 1], rx[oq + 2], rx[oq + 3]
        tx = 2.0 * (q0 * d1 - d0 * q1 - (q2 * d3 - q3 * d2))
        ty = 2.0 * (q0 * d2 - d0 * q2 - (q3 * d1 - q1 * d3))
        tz = 2.0 * (q0 * d3 - d0 * q3 - (q1 * d2 - q2 * d1))
        ax, ay, az = att[0], att[1], att[2]
        cx, cy, cz = ty * az - tz * ay, tz * ax - tx * az, tx * ay - ty * ax
        R = Rn[idx]
        return (rx[o + B3_POS] + R[0, 0] * cx + R[0, 1] * cy + R[0, 2] * cz,
                rx[o + B3_POS + 1] + R[1, 0] * cx + R[1, 1] * cy + R[1, 2] * cz,
                rx[o + B3_POS + 2] + R[2, 0] * cx + R[2, 1] * cy + R[2, 2] * cz)
    if kind == END_NODE:
        o = B3_SIZE * nw + N3_SIZE * idx + N3_POS
        return rx[o], rx[o + 1], rx[o + 2]
    return 0.0, 0.0, 0.0


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _add_end_pull(W, br, nr, bs, ns, fx, fy, fz):
    """W.bv[br] += T_r^T F and W.bv[bs] -= T_s^T F for a change F (global) of an element's pull on its end r, with
    the ends' maps in W.Tr, W.Ts (a block index < 0: a fixed end, nothing to add)."""
    if br >= 0:
        for j in range(nr):
            W.bv[br, j] += W.Tr[0, j] * fx + W.Tr[1, j] * fy + W.Tr[2, j] * fz
    if bs >= 0:
        for j in range(ns):
            W.bv[bs, j] -= W.Ts[0, j] * fx + W.Ts[1, j] * fy + W.Ts[2, j] * fz


# not inlined into the W step: inlined, it made Rotorcraft-v0's step 8-20 % slower (2026-12-05)
@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def add_stiffness_force(xn, rx, M, W, fac):
    """W.bv += fac (dQ/dq) P rx: the generalised forces of the elements' stiffness K_e (W.ke, from
    :func:`add_cable_stiffness` at xn) for the state increment rx (positions and quaternions; P maps it to
    displacements of the attachment points), times fac [s]. W.Tr, W.Ts, W.er, W.es are scratch."""
    nw = M.wtype.size
    for e in range(M.ef.shape[0]):
        ke = W.ke[e]
        if ke[KE_XX] == 0.0 and ke[KE_YY] == 0.0 and ke[KE_ZZ] == 0.0:
            continue
        kr, ks = M.ek[e, 0], M.ek[e, 1]
        ir, is_ = M.ei[e, 0], M.ei[e, 1]
        nr = end_kinematics(kr, ir, M.ea[e, 0], xn, W.Rn, M.fixed, nw, W.Tr, W.er)
        ns = end_kinematics(ks, is_, M.ea[e, 1], xn, W.Rn, M.fixed, nw, W.Ts, W.es)
        rx0, ry0, rz0 = _end_displacement(kr, ir, M.ea[e, 0], xn, rx, W.Rn, nw)
        sx0, sy0, sz0 = _end_displacement(ks, is_, M.ea[e, 1], xn, rx, W.Rn, nw)
        dx, dy, dz = sx0 - rx0, sy0 - ry0, sz0 - rz0
        fx = fac * (ke[KE_XX] * dx + ke[KE_XY] * dy + ke[KE_XZ] * dz)
        fy = fac * (ke[KE_XY] * dx + ke[KE_YY] * dy + ke[KE_YZ] * dz)
        fz = fac * (ke[KE_XZ] * dx + ke[KE_YZ] * dy + ke[KE_ZZ] * dz)
        _add_end_pull(W, block_of(kr, ir, nw), nr, block_of(ks, is_, nw), ns, fx, fy, fz)


#: Size of the directional difference of :func:`add_moving_end_force` along the largest entry of its direction
DIFF_END = 1e-6


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _end_change(kind, e, t, te, xn, xe, M, ln, step):
    """(rest length l0 [m] of element e at (t, xn), its change and the change of its elongation rate per unit of
    the direction from (t, xn) to (te, xe) of size ``step``), the rate taken at length ln [m] (l0 when ln < 0)."""
    l0 = _rest(kind, e, t, xn, M)
    dl0 = (_rest(kind, e, te, xe, M) - l0) / step
    lr = l0 if ln < 0.0 else ln
    drate = (_rate(kind, e, te, xe, M, lr, l0) - _rate(kind, e, t, xn, M, lr, l0)) / step
    return l0, dl0, drate


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _rest(kind, e, t, x, M):
    """The kind's rest length of element e (one inlined call per function: numba's inliner mis-scopes a second)."""
    return rest_length(kind, e, t, x, M)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _rate(kind, e, t, x, M, ln, l0):
    """The kind's elongation rate of element e at length ln [m], rest length l0 [m] and length rate 0."""
    return elongation_rate(kind, e, t, x, M, ln, l0, 0.0)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def add_moving_end_force(t, xn, r, rt, M, W, fac):
    """W.bv += fac dQ/dz (r_z, rt): the change of the elements' pull as their rest length and its rate move with
    the states outside the block tree (a station's pay-out and cable speed) and with time, along the stage
    direction r (state-shaped; its non-block entries count) and rt (time), for the taut elements at xn, with the
    tensions in ``W.tension`` (from the second stage on the stage state's: docs/numerics.md).

    This is the Jacobian's column for those states and for time (the stage's time increment rt, H&W IV.7's
    gamma_i h f_t term). A W-method keeps its order without it; with it, a stiff element driven by a moving
    rest length (the mill's short first element, l0 = l_p / 10 + s(t)) is not left explicit, which cost the
    method its order on the laddermill (local errors at wing 0 nearly independent of the step). Derivatives of
    the plain truss: dsigma / dl0 = -(EA + sigma) / l0, dsigma / d(elongation rate) = DA / l0; the rest length and
    the rate come from the kind (``kernels/dispatch.py``) at (t, xn) and at (t + e rt, xn + e r), a directional
    difference (exact for the mill's linear ends). W.k7 is scratch (unused by the W-methods' stages); W.Tr, W.Ts,
    W.er, W.es too."""
    big = abs(rt)
    for i in range(xn.size):
        a = abs(r[i])
        if a > big:
            big = a
    if not big > 0.0:
        return
    step = DIFF_END / big
    xe = W.k7
    for i in range(xn.size):
        xe[i] = xn[i] + step * r[i]
    te = t + step * rt
    nw = M.wtype.size
    for e in range(M.ef.shape[0]):
        sig = W.tension[e]
        if not sig > 0.0:
            continue
        l0, dl0, drate = _end_change(M.kind, e, t, te, xn, xe, M, -1.0, step)
        if dl0 == 0.0 and drate == 0.0:
            continue
        kr, ir, ks, is_, nr, ns, lx, ly, lz, ln = _element_ends(e, xn, M, W, nw)
        if not ln > 1e-9:
            continue
        if drate != 0.0:  # the rate at the element's own length (it scales with ln / l0 on the mill's ends)
            drate = _end_change(M.kind, e, t, te, xn, xe, M, ln, step)[2]
        EA, DA = M.ef[e, EF_EA], M.ef[e, EF_DA]
        ds = fac * (-(EA + sig) / l0 * dl0 + DA / l0 * drate)
        fx, fy, fz = ds * lx / ln, ds * ly / ln, ds * lz / ln
        _add_end_pull(W, block_of(kr, ir, nw), nr, block_of(ks, is_, nw), ns, fx, fy, fz)


def moving_end_force(kind, t, xn, r, rt, M, W, fac):
    """:func:`add_moving_end_force` for a model kind that registered moving ends (the moving cable, the reel), else
    nothing (jitted code only): for fixed ends its rest lengths and rates do not move (each element's change is
    exactly 0 and it adds nothing), so a scene without moving ends does not compile it (issue 32)."""
    raise NotImplementedError("moving_end_force is resolved inside numba kernels")


@inline_overload(moving_end_force)
def _moving_end_force(kind, t, xn, r, rt, M, W, fac):
    if has_moving_ends(kind):
        return lambda kind, t, xn, r, rt, M, W, fac: add_moving_end_force(t, xn, r, rt, M, W, fac)
    return lambda kind, t, xn, r, rt, M, W, fac: None
