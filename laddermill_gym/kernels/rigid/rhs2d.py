"""Right-hand side of the in-plane (2D) model: the 3D model restricted to the x-z plane.

State per wing (6): x, z, theta, u, w, q; per free node (4): x, z, x', z'. Blocks: 3 dof per wing
(u, w, q), 2 per node. Lateral states and lateral aerodynamics are absent, not zeroed. The packed
model and workspace are the 3D ones; switches as in rhs3d. Only winged bodies (their longitudinal
aerodynamics is written here; the in-plane mode has no vehicle plug-in).
"""

import math

from numba import njit

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.cable import aero_load
from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.dispatch import elongation_rate, rest_length
from laddermill_gym.kernels.rigid.aero import wing_aero_long
from laddermill_gym.kernels.rigid.blocks import tree_solve
from laddermill_gym.kernels.rigid.element_loads import clear_blocks, element_tension, split_ends
from laddermill_gym.kernels.rigid.rhs3d import add_const_mass, block_of
from laddermill_gym.kernels.wind import density, modulation, wind_point, wind_point_rate


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _end_kinematics2(kind, idx, att, x, fixed, nw, T, ev):
    """In-plane version of rhs3d.end_kinematics: ev = (x, z, x', z', ax, az), T is 2 x nb."""
    if kind == C.END_WING:
        o = C.B2_SIZE * idx
        c, s = math.cos(x[o + C.B2_THETA]), math.sin(x[o + C.B2_THETA])
        ax, az = att[0], att[2]
        u, w, q = x[o + C.B2_U], x[o + C.B2_W], x[o + C.B2_Q]
        bx, bz = u + q * az, w - q * ax
        cx, cz = q * bz, -q * bx
        ev[0] = x[o + C.B2_X] + c * ax + s * az
        ev[1] = x[o + C.B2_Z] - s * ax + c * az
        ev[2] = c * bx + s * bz
        ev[3] = -s * bx + c * bz
        ev[4] = c * cx + s * cz
        ev[5] = -s * cx + c * cz
        T[0, 0], T[0, 1], T[0, 2] = c, s, c * az - s * ax
        T[1, 0], T[1, 1], T[1, 2] = -s, c, -s * az - c * ax
        return 3
    if kind == C.END_NODE:
        o = C.B2_SIZE * nw + C.N2_SIZE * idx
        ev[0], ev[1] = x[o + C.N2_POS], x[o + C.N2_POS + 1]
        ev[2], ev[3] = x[o + C.N2_VEL], x[o + C.N2_VEL + 1]
        ev[4] = 0.0
        ev[5] = 0.0
        T[0, 0], T[0, 1], T[1, 0], T[1, 1] = 1.0, 0.0, 0.0, 1.0
        return 2
    ev[0], ev[1] = fixed[idx, 0], fixed[idx, 2]
    for i in range(2, 6):
        ev[i] = 0.0
    return 0


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _add_end_force2(bv, blk, nb, T, fx, fz):
    for j in range(nb):
        bv[blk, j] += T[0, j] * fx + T[1, j] * fz


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _add_mass2(A, nb1, T1, nb2, T2, m):
    for i in range(nb1):
        for j in range(nb2):
            A[i, j] += m * (T1[0, i] * T2[0, j] + T1[1, i] * T2[1, j])


# One function of more than 80 lines on purpose: it is the hot loop of every scene, and each element's end
# kinematics, loads and tension stay in local scalars across its three phases (bodies, nodes, elements, marked
# by comments) instead of passing a dozen values through calls; the golden-trajectory test pins its arithmetic.
@callee_njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def rhs2d(t, x, u, dx, M, W, sag, caero):
    """State derivative of the in-plane model (see rhs3d.rhs3d for the arguments). Returns 0 or 1."""
    nw = M.wtype.size
    nn = M.node_mass.size
    ne = M.ef.shape[0]
    g = M.glob[C.GL_GRAVITY]
    a0, da = M.glob[C.GL_ALPHA0], M.glob[C.GL_DALPHA]
    wf = M.wf
    s_mod, d_mod, sd_mod, dd_mod = modulation(t, M.tmod[C.TM_T0], M.tmod[C.TM_DT], M.ms, M.md)
    D, U, bv = W.D, W.U, W.bv
    nbk = nw + nn
    clear_blocks(D, U, bv, nbk, 3)
    ao = W.aout
    for k in range(nw):
        o = C.B2_SIZE * k
        c, s = math.cos(x[o + C.B2_THETA]), math.sin(x[o + C.B2_THETA])
        uu, ww, q = x[o + C.B2_U], x[o + C.B2_W], x[o + C.B2_Q]
        xd = c * uu + s * ww
        zd = -s * uu + c * ww
        dx[o + C.B2_X], dx[o + C.B2_Z], dx[o + C.B2_THETA] = xd, zd, q
        ty = M.wtype[k]
        m = M.tf[ty, C.TF_MASS]
        Dk = D[k]
        Dk[0, 0] = m
        Dk[1, 1] = m
        Dk[2, 2] = M.tf[ty, C.TF_JYY]
        fx = -m * g * s - m * q * ww
        fz = m * g * c + m * q * uu
        my = 0.0
        rho = density(-x[o + C.B2_Z], wf)
        if rho > 0.0:
            wgx, _, wgz = wind_point(x[o + C.B2_X], 0.0, x[o + C.B2_Z], t, wf, s_mod, d_mod, M.gp, M.gv)
            wbx = c * wgx - s * wgz
            wbz = s * wgx + c * wgz
            ua, wa = uu - wbx, ww - wbz
            dwx, _, dwz = wind_point_rate(x[o + C.B2_X], 0.0, x[o + C.B2_Z], xd, 0.0, zd, t, wf, s_mod, d_mod,
                                          sd_mod, dd_mod, M.gp, M.gv)
            ex_ = q * wbz - (c * dwx - s * dwz)
            ez_ = -q * wbx - (s * dwx + c * dwz)
            d2 = ua * ua + wa * wa
            ad0 = (-wa * ex_ + ua * ez_) / d2 if d2 > 1e-18 else 0.0
            wing_aero_long(ty, M.tf, M.ac, a0, da, rho, ua, wa, q, u[C.N_CONTROLS * k + C.CTRL_ELEVATOR], ad0, W.coef,
                           ao)
            fx += ao[C.AO2_FORCE_X]
            fz += ao[C.AO2_FORCE_Z]
            my += ao[C.AO2_MOMENT]
            for i in range(3):
                ki = ao[C.AO2_KAPPA + i]
                if ki != 0.0:
                    Dk[i, 0] -= ki * ao[C.AO2_G]
                    Dk[i, 1] -= ki * ao[C.AO2_G + 1]
        bv[k, 0] = fx
        bv[k, 1] = fz
        bv[k, 2] = my
    base = C.B2_SIZE * nw
    for j in range(nn):
        o = base + C.N2_SIZE * j
        dx[o + C.N2_POS], dx[o + C.N2_POS + 1] = x[o + C.N2_VEL], x[o + C.N2_VEL + 1]
        mn = M.node_mass[j]
        b = nw + j
        D[b, 0, 0] = mn
        D[b, 1, 1] = mn
        bv[b, 1] += mn * g
    Tr, Ts, er, es = W.Tr, W.Ts, W.er, W.es
    for e in range(ne):
        kr, ks = M.ek[e, 0], M.ek[e, 1]
        ir, is_ = M.ei[e, 0], M.ei[e, 1]
        nr = _end_kinematics2(kr, ir, M.ea[e, 0], x, M.fixed, nw, Tr, er)
        ns = _end_kinematics2(ks, is_, M.ea[e, 1], x, M.fixed, nw, Ts, es)
        l0 = rest_length(M.kind, e, t, x, M)
        mu, EA, DA, dia = M.ef[e, C.EF_MU], M.ef[e, C.EF_EA], M.ef[e, C.EF_DA], M.ef[e, C.EF_DIAMETER]
        lx, lz = es[0] - er[0], es[1] - er[1]
        ln = math.sqrt(lx * lx + lz * lz)
        if ln > 1e-9:
            ux, uz = lx / ln, lz / ln
        else:
            ux, uz = 0.0, 0.0
        eps = ln - l0
        epsd = elongation_rate(M.kind, e, t, x, M, ln, l0, ux * (es[2] - er[2]) + uz * (es[3] - er[3]))
        me = mu * l0
        wg = 0.5 * me * g
        m6 = me / 6.0
        frx, _, frz, fsx, _, fsz = split_ends(-m6, er[4], 0.0, er[5], es[4], 0.0, es[5])
        frz += wg
        fsz += wg
        pgz = mu * g
        prx, prz = 0.0, pgz
        psx, psz = 0.0, pgz
        if caero is not None:
            w1, _, w3 = wind_point(er[0], 0.0, er[1], t, wf, s_mod, d_mod, M.gp, M.gv)
            ar1, _, ar3 = aero_load(w1 - er[2], 0.0, w3 - er[3], ux, 0.0, uz,
                                    density(-er[1], wf), dia, caero[0], caero[1])
            w1, _, w3 = wind_point(es[0], 0.0, es[1], t, wf, s_mod, d_mod, M.gp, M.gv)
            as1, _, as3 = aero_load(w1 - es[2], 0.0, w3 - es[3], ux, 0.0, uz,
                                    density(-es[1], wf), dia, caero[0], caero[1])
            c6 = ln / 6.0
            frx += c6 * (2.0 * ar1 + as1)
            frz += c6 * (2.0 * ar3 + as3)
            fsx += c6 * (ar1 + 2.0 * as1)
            fsz += c6 * (ar3 + 2.0 * as3)
            prx += ar1
            prz += ar3
            psx += as1
            psz += as3
        sig = element_tension(EA, DA, l0, ln, eps, epsd, sag is not None, (ux, 0.0, uz),
                              (prx, 0.0, prz), (psx, 0.0, psz))
        W.tension[e] = sig
        frx += sig * ux
        frz += sig * uz
        fsx -= sig * ux
        fsz -= sig * uz
        br = block_of(kr, ir, nw)
        bs = block_of(ks, is_, nw)
        if br >= 0:
            _add_end_force2(bv, br, nr, Tr, frx, frz)
            add_const_mass(D, br, nr, M.ekd, e, 0, 2.0 * m6)
        if bs >= 0:
            _add_end_force2(bv, bs, ns, Ts, fsx, fsz)
            add_const_mass(D, bs, ns, M.ekd, e, 1, 2.0 * m6)
        ch = M.echild[e]
        if ch == 0:
            _add_mass2(U[br], nr, Tr, ns, Ts, m6)
        elif ch == 1:
            _add_mass2(U[bs], ns, Ts, nr, Tr, m6)
    if not tree_solve(D, U, W.Y, W.piv, bv, M.order, M.parent, M.bsz):
        return 1
    for k in range(nw):
        o = C.B2_SIZE * k + C.B2_U
        dx[o], dx[o + 1], dx[o + 2] = bv[k, 0], bv[k, 1], bv[k, 2]
    for j in range(nn):
        o = base + C.N2_SIZE * j + C.N2_VEL
        dx[o], dx[o + 1] = bv[nw + j, 0], bv[nw + j, 1]
    return 0
