"""Right-hand side of the 3D model: rigid bodies, free cable nodes and truss elements.

Implements docs/model.md: assembly of eq. (25) M v' = f + h - D^T sigma into blocks (6 dof per body,
3 per free node) and its O(N) solution by block elimination along the tree the elements form
(``order`` lists the blocks children-first, ``parent`` the one block each is coupled to later).

The external loads on each body come from the vehicle the model names (``kernels/dispatch.py``:
wing aerodynamics, or the rotorcraft's rotors), so this module imports no vehicle. The switches ``sag``
(``sag[0]`` 0: plain tension-only truss) and ``caero`` (C_N0 = C_T0 = 0: no cable aerodynamics) are arrays whose
*values* the element loop branches on (``model.packing.cable_switch``): every setting runs one compiled kernel and
a switched-off part is skipped. (With the switches as None-or-array *types*, one kernel per setting, LLVM compiled
the cable-aerodynamics-off variant 30 % slower than the full model: docs/numerics.md.)
"""

import math

from numba import njit

from laddermill_gym.kernels.cable import aero_load
from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.contract import (
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    EF_DA,
    EF_DIAMETER,
    EF_EA,
    EF_MU,
    END_NODE,
    END_WING,
    GL_GRAVITY,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    TF_JXX,
    TF_JXZ,
    TF_JYY,
    TF_JZZ,
    TF_MASS,
    TM_DT,
    TM_T0,
)
from laddermill_gym.kernels.dispatch import body_loads, elongation_rate, rest_length
from laddermill_gym.kernels.rigid.blocks import tree_solve
from laddermill_gym.kernels.rigid.element_loads import clear_blocks, element_tension, split_ends
from laddermill_gym.kernels.small import quat_rotation
from laddermill_gym.kernels.wind import density, modulation, wind_point


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def end_kinematics(kind, idx, att, x, Rw, fixed, nw, T, ev):
    """Position ev[0:3], velocity ev[3:6] and velocity-quadratic acceleration ev[6:9] (global) of an
    element end, and its 3 x nb velocity transformation T (eq. 13). Returns the block size (0: fixed)."""
    if kind == END_WING:
        o = B3_SIZE * idx
        R = Rw[idx]
        ax, ay, az = att[0], att[1], att[2]
        vx, vy, vz = x[o + B3_VEL], x[o + B3_VEL + 1], x[o + B3_VEL + 2]
        p, q, r = x[o + B3_RATE], x[o + B3_RATE + 1], x[o + B3_RATE + 2]
        # body velocity of the attachment point and w x (v + w x a)
        wax, way, waz = q * az - r * ay, r * ax - p * az, p * ay - q * ax
        bx, by, bz = vx + wax, vy + way, vz + waz
        cx, cy, cz = q * bz - r * by, r * bx - p * bz, p * by - q * bx
        for i in range(3):
            ev[i] = x[o + B3_POS + i] + R[i, 0] * ax + R[i, 1] * ay + R[i, 2] * az
            ev[3 + i] = R[i, 0] * bx + R[i, 1] * by + R[i, 2] * bz
            ev[6 + i] = R[i, 0] * cx + R[i, 1] * cy + R[i, 2] * cz
            T[i, 0] = R[i, 0]
            T[i, 1] = R[i, 1]
            T[i, 2] = R[i, 2]
            # -R a~ : column j is R (e_j x a)
            T[i, 3] = R[i, 2] * ay - R[i, 1] * az
            T[i, 4] = R[i, 0] * az - R[i, 2] * ax
            T[i, 5] = R[i, 1] * ax - R[i, 0] * ay
        return 6
    if kind == END_NODE:
        o = B3_SIZE * nw + N3_SIZE * idx
        for i in range(3):
            ev[i] = x[o + N3_POS + i]
            ev[3 + i] = x[o + N3_VEL + i]
            ev[6 + i] = 0.0
            for j in range(3):
                T[i, j] = 1.0 if i == j else 0.0
        return 3
    for i in range(3):
        ev[i] = fixed[idx, i]
        ev[3 + i] = 0.0
        ev[6 + i] = 0.0
    return 0


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _add_end_force(bv, blk, nb, T, fx, fy, fz):
    """Generalised force T^T F of a global force F at an element end."""
    for j in range(nb):
        bv[blk, j] += T[0, j] * fx + T[1, j] * fy + T[2, j] * fz


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _add_mass(A, nb1, T1, nb2, T2, m):
    """A[:nb1, :nb2] += m T1^T T2."""
    for i in range(nb1):
        for j in range(nb2):
            A[i, j] += m * (T1[0, i] * T2[0, j] + T1[1, i] * T2[1, j] + T1[2, i] * T2[2, j])


# inlined (the callers' flags): called with the literal ends 0 and 1, it compiled once per literal, twice per
# right-hand side (issue 32)
@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always")
def add_const_mass(D, blk, nb, ekd, e, end, m):
    """D[blk] += m T^T T, with T^T T of the element end precomputed (it does not depend on the rotation)."""
    for i in range(nb):
        for j in range(nb):
            D[blk, i, j] += m * ekd[e, end, i, j]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def block_of(kind, idx, nw):
    if kind == END_WING:
        return idx
    if kind == END_NODE:
        return nw + idx
    return -1


# One function of more than 80 lines on purpose: it is the hot loop of every scene, and each element's end
# kinematics, loads and tension stay in local scalars across its three phases (bodies, nodes, elements, marked
# by comments) instead of passing a dozen values through calls; the golden-trajectory test pins its arithmetic.
# _nrt=False: it allocates nothing, and without numba's reference counting the arrays of the packed model and
# workspace handed to the inlined body-loads plug-in cost no atomic increments (chain right-hand side 118 -> 55 us).
@callee_njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def assemble3d(t, x, u, dx, M, W, sag, caero, vehicle):
    """Assemble eq. (25) at time t, state x, controls u: the position and quaternion rates into dx, the mass
    matrix blocks into W.D (diagonal) and W.U (to the parent block), the generalised forces into W.bv, element
    tensions [N] into W.tension and the body rotations into W.Rw; nothing is solved (arguments as rhs3d)."""
    nw = M.wtype.size
    nn = M.node_mass.size
    ne = M.ef.shape[0]
    g = M.glob[GL_GRAVITY]
    wf = M.wf
    s_mod, d_mod, sd_mod, dd_mod = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    D, U, bv = W.D, W.U, W.bv
    nbk = nw + nn
    clear_blocks(D, U, bv, nbk, 6)
    # ---- bodies: kinematics, inertia, gravity, the vehicle's loads
    for k in range(nw):
        o = B3_SIZE * k
        R = W.Rw[k]
        oq, ov, orr = o + B3_QUAT, o + B3_VEL, o + B3_RATE
        q0, q1, q2, q3 = x[oq], x[oq + 1], x[oq + 2], x[oq + 3]
        quat_rotation(q0, q1, q2, q3, R)
        vx, vy, vz = x[ov], x[ov + 1], x[ov + 2]
        p, q, r = x[orr], x[orr + 1], x[orr + 2]
        xd = R[0, 0] * vx + R[0, 1] * vy + R[0, 2] * vz
        yd = R[1, 0] * vx + R[1, 1] * vy + R[1, 2] * vz
        zd = R[2, 0] * vx + R[2, 1] * vy + R[2, 2] * vz
        dx[o + B3_POS], dx[o + B3_POS + 1], dx[o + B3_POS + 2] = xd, yd, zd
        dx[oq] = 0.5 * (-q1 * p - q2 * q - q3 * r)
        dx[oq + 1] = 0.5 * (q0 * p + q2 * r - q3 * q)
        dx[oq + 2] = 0.5 * (q0 * q + q3 * p - q1 * r)
        dx[oq + 3] = 0.5 * (q0 * r + q1 * q - q2 * p)
        ty = M.wtype[k]
        m = M.tf[ty, TF_MASS]
        jxx, jyy, jzz, jxz = M.tf[ty, TF_JXX], M.tf[ty, TF_JYY], M.tf[ty, TF_JZZ], M.tf[ty, TF_JXZ]
        Dk = D[k]
        Dk[0, 0] = m
        Dk[1, 1] = m
        Dk[2, 2] = m
        Dk[3, 3] = jxx
        Dk[4, 4] = jyy
        Dk[5, 5] = jzz
        Dk[3, 5] = -jxz
        Dk[5, 3] = -jxz
        # angular momentum J w
        hx = jxx * p - jxz * r
        hy = jyy * q
        hz = jzz * r - jxz * p
        fx = m * g * R[2, 0] - m * (q * vz - r * vy)
        fy = m * g * R[2, 1] - m * (r * vx - p * vz)
        fz = m * g * R[2, 2] - m * (p * vy - q * vx)
        mx = -(q * hz - r * hy)
        my = -(r * hx - p * hz)
        mz = -(p * hy - q * hx)
        env = (s_mod, d_mod, sd_mod, dd_mod, zd)
        lx, ly, lz, lmx, lmy, lmz = body_loads(vehicle, k, t, x, R, u, M, W, Dk, env)
        fx += lx
        fy += ly
        fz += lz
        mx += lmx
        my += lmy
        mz += lmz
        bv[k, 0] = fx
        bv[k, 1] = fy
        bv[k, 2] = fz
        bv[k, 3] = mx
        bv[k, 4] = my
        bv[k, 5] = mz
    # ---- free nodes: kinematics and lumped mass
    base = B3_SIZE * nw
    for j in range(nn):
        o = base + N3_SIZE * j
        dx[o + N3_POS], dx[o + N3_POS + 1], dx[o + N3_POS + 2] = x[o + N3_VEL], x[o + N3_VEL + 1], x[o + N3_VEL + 2]
        mn = M.node_mass[j]
        b = nw + j
        D[b, 0, 0] = mn
        D[b, 1, 1] = mn
        D[b, 2, 2] = mn
        bv[b, 2] += mn * g
    # ---- cable elements
    Tr, Ts, er, es = W.Tr, W.Ts, W.er, W.es
    for e in range(ne):
        kr, ks = M.ek[e, 0], M.ek[e, 1]
        ir, is_ = M.ei[e, 0], M.ei[e, 1]
        nr = end_kinematics(kr, ir, M.ea[e, 0], x, W.Rw, M.fixed, nw, Tr, er)
        ns = end_kinematics(ks, is_, M.ea[e, 1], x, W.Rw, M.fixed, nw, Ts, es)
        l0 = rest_length(M.kind, e, t, x, M)
        mu, EA, DA, dia = M.ef[e, EF_MU], M.ef[e, EF_EA], M.ef[e, EF_DA], M.ef[e, EF_DIAMETER]
        lx, ly, lz = es[0] - er[0], es[1] - er[1], es[2] - er[2]
        ln = math.sqrt(lx * lx + ly * ly + lz * lz)
        if ln > 1e-9:
            ux, uy, uz = lx / ln, ly / ln, lz / ln
        else:
            ux, uy, uz = 0.0, 0.0, 0.0
        eps = ln - l0
        epsd = elongation_rate(M.kind, e, t, x, M, ln, l0,
                               ux * (es[3] - er[3]) + uy * (es[4] - er[4]) + uz * (es[5] - er[5]))
        me = mu * l0
        # nodal loads (global) at r and s: gravity, aerodynamics, quadratic velocity terms
        wg = 0.5 * me * g
        m6 = me / 6.0
        frx, fry, frz, fsx, fsy, fsz = split_ends(-m6, er[6], er[7], er[8], es[6], es[7], es[8])
        frz += wg
        fsz += wg
        pgz = mu * g
        prx, pry, prz = 0.0, 0.0, pgz
        psx, psy, psz = 0.0, 0.0, pgz
        if caero[0] != 0.0 or caero[1] != 0.0:
            rho_r = density(-er[2], wf)
            rho_s = density(-es[2], wf)
            w1, w2, w3 = wind_point(er[0], er[1], er[2], t, wf, s_mod, d_mod, M.gp, M.gv)
            ar1, ar2, ar3 = aero_load(w1 - er[3], w2 - er[4], w3 - er[5], ux, uy, uz,
                                      rho_r, dia, caero[0], caero[1])
            w1, w2, w3 = wind_point(es[0], es[1], es[2], t, wf, s_mod, d_mod, M.gp, M.gv)
            as1, as2, as3 = aero_load(w1 - es[3], w2 - es[4], w3 - es[5], ux, uy, uz,
                                      rho_s, dia, caero[0], caero[1])
            c6 = ln / 6.0
            frx += c6 * (2.0 * ar1 + as1)
            fry += c6 * (2.0 * ar2 + as2)
            frz += c6 * (2.0 * ar3 + as3)
            fsx += c6 * (ar1 + 2.0 * as1)
            fsy += c6 * (ar2 + 2.0 * as2)
            fsz += c6 * (ar3 + 2.0 * as3)
            prx += ar1
            pry += ar2
            prz += ar3
            psx += as1
            psy += as2
            psz += as3
        sig = element_tension(EA, DA, l0, ln, eps, epsd, sag[0] != 0.0, (ux, uy, uz),
                              (prx, pry, prz), (psx, psy, psz))
        W.tension[e] = sig
        frx += sig * ux
        fry += sig * uy
        frz += sig * uz
        fsx -= sig * ux
        fsy -= sig * uy
        fsz -= sig * uz
        br = block_of(kr, ir, nw)
        bs = block_of(ks, is_, nw)
        if br >= 0:
            _add_end_force(bv, br, nr, Tr, frx, fry, frz)
            add_const_mass(D, br, nr, M.ekd, e, 0, 2.0 * m6)
        if bs >= 0:
            _add_end_force(bv, bs, ns, Ts, fsx, fsy, fsz)
            add_const_mass(D, bs, ns, M.ekd, e, 1, 2.0 * m6)
        ch = M.echild[e]
        if ch == 0:
            _add_mass(U[br], nr, Tr, ns, Ts, m6)
        elif ch == 1:
            _add_mass(U[bs], ns, Ts, nr, Tr, m6)


# _nrt=False and the split from assemble3d as above: the linearly implicit integrator (kernels/rigid/rosenbrock.py)
# assembles the same blocks without solving them.
@callee_njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def rhs3d(t, x, u, dx, M, W, sag, caero, vehicle):
    """State derivative dx of the 3D model at time t, state x, controls u (the vehicle's, per body).

    M: packed model (``kernels/contract.py``), W: workspace. Element tensions [N] are left in W.tension.
    ``sag``, ``caero`` and ``vehicle`` are the model's fields, passed separately (the vehicle's type selects the
    compiled path; the cable switches are branched on by value). Returns 0, or 1 if the mass matrix is singular.
    """
    assemble3d(t, x, u, dx, M, W, sag, caero, vehicle)
    D, bv = W.D, W.bv
    nw = M.wtype.size
    nn = M.node_mass.size
    base = B3_SIZE * nw
    # ---- solve M v' = F
    if not tree_solve(D, W.U, W.Y, W.piv, bv, M.order, M.parent, M.bsz):
        return 1
    for k in range(nw):
        o = B3_SIZE * k + B3_VEL
        for i in range(6):
            dx[o + i] = bv[k, i]
    for j in range(nn):
        o = base + N3_SIZE * j + N3_VEL
        b = nw + j
        dx[o] = bv[b, 0]
        dx[o + 1] = bv[b, 1]
        dx[o + 2] = bv[b, 2]
    return 0
