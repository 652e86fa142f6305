"""The rigid model kinds (3D and in-plane) and the winged-body vehicle, registered with ``kernels/dispatch.py``.

``RIGID_3D`` and ``RIGID_2D`` are the ``kind`` of a packed rigid model (``model/packing.py`` sets it);
``WING`` is the ``vehicle`` of a model whose bodies are laddermill wings (quasi-steady aerodynamics from the
wing type's tables). Another vehicle (the rotorcraft) registers its own loads from its own package.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit, types

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.dispatch import (
    register_assemble,
    register_kind,
    register_rhs_far,
    register_tensions,
    register_vehicle,
)
from laddermill_gym.kernels.far_call import far_call
from laddermill_gym.kernels.rigid.aero import wing_aero
from laddermill_gym.kernels.rigid.rhs2d import rhs2d
from laddermill_gym.kernels.rigid.rhs3d import assemble3d, rhs3d
from laddermill_gym.kernels.wind import density, wind_point, wind_point_rate

_FM = {"contract", "nsz", "arcp"}

# The markers hold a small array rather than a scalar: numba's parallel (prange) lowering passes the packed
# model to its worker function field by field and accepts arrays, not scalars, inside a nested tuple.
Rigid3D = namedtuple("Rigid3D", ["dim"])
Rigid2D = namedtuple("Rigid2D", ["dim"])
WingVehicle = namedtuple("WingVehicle", ["n_controls"])
#: Kind markers (``dim``: [3.0] or [2.0]) and the winged-body vehicle (``n_controls``: [3.0] per body).
RIGID_3D = Rigid3D(np.array([3.0]))
RIGID_2D = Rigid2D(np.array([2.0]))
WING = WingVehicle(np.array([float(C.N_CONTROLS)]))
#: the vehicle of no loads: ``assemble3d`` for it is the element loop alone (:func:`rigid3d_tensions`)
NoLoads = namedtuple("NoLoads", [])
NO_LOADS = NoLoads()


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def wing_loads(vehicle, k, t, x, R, u, M, W, Dk, env):
    """Aerodynamic force and moment (body axes, about the CG) on wing k, and its alpha-rate (apparent mass)
    terms added to the diagonal block Dk. Zero in vacuum. ``env`` = (s_mod, d_mod, sd_mod, dd_mod, zd)."""
    s_mod, d_mod, sd_mod, dd_mod, zd = env
    o = C.B3_SIZE * k
    wf = M.wf
    rho = density(-x[o + C.B3_POS + 2], wf)
    if not rho > 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    ov, orr = o + C.B3_VEL, o + C.B3_RATE
    vx, vy, vz = x[ov], x[ov + 1], x[ov + 2]
    p, q, r = x[orr], x[orr + 1], x[orr + 2]
    px, py, pz = x[o + C.B3_POS], x[o + C.B3_POS + 1], x[o + C.B3_POS + 2]
    wgx, wgy, wgz = wind_point(px, py, pz, t, wf, s_mod, d_mod, M.gp, M.gv)
    wbx = R[0, 0] * wgx + R[1, 0] * wgy + R[2, 0] * wgz
    wby = R[0, 1] * wgx + R[1, 1] * wgy + R[2, 1] * wgz
    wbz = R[0, 2] * wgx + R[1, 2] * wgy + R[2, 2] * wgz
    ua, va, wa = vx - wbx, vy - wby, vz - wbz
    # known part of the alpha rate: g . (w x w_b - R^T dw/dt)
    vgx = R[0, 0] * vx + R[0, 1] * vy + R[0, 2] * vz
    vgy = R[1, 0] * vx + R[1, 1] * vy + R[1, 2] * vz
    dwx, dwy, dwz = wind_point_rate(px, py, pz, vgx, vgy, zd, t, wf, s_mod, d_mod, sd_mod, dd_mod, M.gp, M.gv)
    ex_ = (q * wbz - r * wby) - (R[0, 0] * dwx + R[1, 0] * dwy + R[2, 0] * dwz)
    ez_ = (p * wby - q * wbx) - (R[0, 2] * dwx + R[1, 2] * dwy + R[2, 2] * dwz)
    d2 = ua * ua + wa * wa
    ad0 = (-wa * ex_ + ua * ez_) / d2 if d2 > 1e-18 else 0.0
    ao = W.aout
    c = C.N_CONTROLS * k
    wing_aero(M.wtype[k], M.tf, M.ac, M.glob[C.GL_ALPHA0], M.glob[C.GL_DALPHA], rho, ua, va, wa, p, q, r,
              u[c + C.CTRL_ELEVATOR], u[c + C.CTRL_RUDDER], u[c + C.CTRL_AILERON], ad0, W.coef, ao)
    for i in range(6):
        ki = ao[C.AO_KAPPA + i]
        if ki != 0.0:
            for j in range(3):
                Dk[i, j] -= ki * ao[C.AO_G + j]
    return (ao[C.AO_FORCE], ao[C.AO_FORCE + 1], ao[C.AO_FORCE + 2], ao[C.AO_MOMENT], ao[C.AO_MOMENT + 1],
            ao[C.AO_MOMENT + 2])


# the observation's element loop (once per env step) called through its address, not linked into the step kernel
# (kernels/far_call.py, issue 32 point 1); the integrators' calls stay linked: a call by address passes every field
# of the model and workspace namedtuples (some 500 values), which LLVM strips from a linked callee's unused ones,
# and 23 such calls per W step cost the wing's and the craft's vector envs 5-17 % of their steps/s at 512 copies
_assemble3d_far = far_call(assemble3d, types.none)


# The three wrappers below are inlined (no arithmetic of their own, callers with the same flags): numba links a
# compiled function's every callee into its library and optimises it all again, so each wrapper compiled on its own
# cost seconds of a cold start for nothing (issue 32).
@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid3d_rhs(kind, t, x, u, dx, M, W):
    return rhs3d(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid3d_assemble(kind, t, x, u, dx, M, W):
    assemble3d(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)
    return 0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def no_loads(vehicle, k, t, x, R, u, M, W, Dk, env):
    return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0


# What an observation reads of a state (tensions, rotations) without the bodies' loads: assemble3d compiled for the
# vehicle of no loads runs the same element loop (the same operations and uses, so the same fused multiply-adds: a
# copy of the loop written for the tensions alone differed from it by a few ulps in 15 % of the tethered wing's
# states) and skips the wings' aerodynamics, about two thirds of an observation (issue 32 point 2)
@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid3d_tensions(kind, t, x, u, dx, M, W):
    _assemble3d_far(t, x, u, dx, M, W, M.sag, M.caero, NO_LOADS)
    return 0


def rigid3d_calls(t, x, u, dx, M, W, limits) -> dict:
    """The kernels a rigid 3D model compiles for the integrators and the step kernels' observation, as (dispatcher,
    arguments) pairs with the numba types those pass (t [s], state x, controls u, derivative scratch dx, model M
    with its markers, workspace W, limits): ``assemble`` and ``rhs`` (:func:`rigid3d_assemble`,
    :func:`rigid3d_rhs`), ``check`` (:func:`rigid3d_check`) and ``tensions`` (:func:`rigid3d_tensions`). For the
    kernel warm-up (``envs/task_warmup.py``, issue 32): ``dispatcher.compile`` of the arguments' types compiles
    the specialisation the step kernel calls, without running it."""
    return {"assemble": (assemble3d, (t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)),
            "rhs": (rhs3d, (t, W.xt, u, dx, M, W, M.sag, M.caero, M.vehicle)),
            "check": (rigid3d_check, (M.kind, x, M, limits)),
            "tensions": (assemble3d, (t, x, u, dx, M, W, M.sag, M.caero, NO_LOADS))}


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid2d_rhs(kind, t, x, u, dx, M, W):
    return rhs2d(t, x, u, dx, M, W, M.sag, M.caero)


# The right-hand sides that Python calls (``integrate.rhs_entry``: the static equilibria and trims, thousands of
# calls, each some microseconds of Python around it) reach rhs3d and rhs2d through their addresses: the entry then
# compiles as a small function of its own instead of linking the whole right-hand side once more (the step kernels
# link rhs3d anyway; a cold TetheredWing-v0's trim compiled its entry's link of rhs2d in 1.7 s of CPU, issue 32)
_rhs3d_far = far_call(rhs3d, types.int64)
_rhs2d_far = far_call(rhs2d, types.int64)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid3d_rhs_far(kind, t, x, u, dx, M, W):
    return _rhs3d_far(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def rigid2d_rhs_far(kind, t, x, u, dx, M, W):
    return _rhs2d_far(t, x, u, dx, M, W, M.sag, M.caero)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _all_finite(x):
    for i in range(x.size):
        if not math.isfinite(x[i]):
            return False
    return True


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def _check_bounds(M, limits):
    """(wings, free nodes, squared speed limit [m^2/s^2], squared rate limit [rad^2/s^2], ground height [m]): what
    the post-step checks compare a state with (``limits``: ``LIM_SPEED``, ``LIM_RATE``, ``LIM_GROUND``)."""
    return (M.wtype.size, M.node_mass.size, limits[C.LIM_SPEED] * limits[C.LIM_SPEED],
            limits[C.LIM_RATE] * limits[C.LIM_RATE], limits[C.LIM_GROUND])


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always", _nrt=False)
def check_wings3d(x, nw, vmax2, wmax2, hg):
    """The wings' part of a 3D post-step check (the first ``nw`` body blocks of ``x``): renormalise each quaternion
    (NONFINITE if it vanished or overflowed), LIMIT for a squared speed over ``vmax2`` [m^2/s^2] or squared rate over
    ``wmax2`` [rad^2/s^2], GROUND for a CG height -z at or below ``hg`` [m]; else OK."""
    for k in range(nw):
        o = C.B3_SIZE * k
        oq, ov, orr = o + C.B3_QUAT, o + C.B3_VEL, o + C.B3_RATE
        n = math.sqrt(x[oq] ** 2 + x[oq + 1] ** 2 + x[oq + 2] ** 2 + x[oq + 3] ** 2)
        if not (n > 1e-100 and n < 1e100):  # a vanished or overflowing quaternion: the attitude is lost
            return C.NONFINITE
        for i in range(4):
            x[oq + i] /= n
        if x[ov] ** 2 + x[ov + 1] ** 2 + x[ov + 2] ** 2 > vmax2:
            return C.LIMIT
        if x[orr] ** 2 + x[orr + 1] ** 2 + x[orr + 2] ** 2 > wmax2:
            return C.LIMIT
        if -x[o + C.B3_POS + 2] <= hg:
            return C.GROUND
    return C.OK


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def rigid3d_check(kind, x, M, limits):
    """Renormalise every body's quaternion and check speeds [m/s] and rates [rad/s] against ``limits``, and the
    heights -z [m] of the body CGs and free nodes against the ground height ``limits[LIM_GROUND]`` (GROUND at or
    below it)."""
    nw, nn, vmax2, wmax2, hg = _check_bounds(M, limits)
    if not _all_finite(x):
        return C.NONFINITE
    st = check_wings3d(x, nw, vmax2, wmax2, hg)
    if st != C.OK:
        return st
    base = C.B3_SIZE * nw
    for j in range(nn):
        o = base + C.N3_SIZE * j + C.N3_VEL
        if x[o] ** 2 + x[o + 1] ** 2 + x[o + 2] ** 2 > vmax2:
            return C.LIMIT
        if -x[base + C.N3_SIZE * j + C.N3_POS + 2] <= hg:
            return C.GROUND
    return C.OK


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def rigid2d_check(kind, x, M, limits):
    """Check in-plane speeds [m/s] and pitch rates [rad/s] against ``limits``, and the heights -z [m] of the body
    CGs and free nodes against the ground height ``limits[LIM_GROUND]`` (GROUND at or below it)."""
    nw, nn, vmax2, wmax2, hg = _check_bounds(M, limits)
    if not _all_finite(x):
        return C.NONFINITE
    for k in range(nw):
        o = C.B2_SIZE * k
        if x[o + C.B2_U] ** 2 + x[o + C.B2_W] ** 2 > vmax2 or x[o + C.B2_Q] ** 2 > wmax2:
            return C.LIMIT
        if -x[o + C.B2_Z] <= hg:
            return C.GROUND
    base = C.B2_SIZE * nw
    for j in range(nn):
        o = base + C.N2_SIZE * j + C.N2_VEL
        if x[o] ** 2 + x[o + 1] ** 2 > vmax2:
            return C.LIMIT
        if -x[base + C.N2_SIZE * j + C.N2_POS + 1] <= hg:
            return C.GROUND
    return C.OK


register_kind(Rigid3D, rigid3d_rhs, rigid3d_check)
register_kind(Rigid2D, rigid2d_rhs, rigid2d_check)
register_rhs_far(Rigid3D, rigid3d_rhs_far)
register_rhs_far(Rigid2D, rigid2d_rhs_far)
register_assemble(Rigid3D, rigid3d_assemble)
register_tensions(Rigid3D, rigid3d_tensions)
register_vehicle(WingVehicle, wing_loads)
register_vehicle(NoLoads, no_loads)
