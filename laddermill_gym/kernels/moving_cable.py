"""The moving cable of the laddermill (Meijaard et al. 1999, "Boundary conditions") as two model kinds.

``MovingCable3D`` and ``MovingCable2D`` are the rigid kinds (``kernels/rigid/kinds.py``) plus a ground station
(parameters ``station``, slots ``SP_*``; state block ``SX_*``; both in ``kernels/contract.py``):

* The first element (veered-side ground point -> wing slot 0) has the unstretched length f_first l0 + s and the
  last one (wing slot n-1 -> hauled-side ground point) f_last l0 - s, with s the cable moved since the last
  transfer (a state, ds/dt = V_c). Their mass follows (mu l0); the damping acts on the material strain rate,
  so the elongation rate used is l0 d(eps)/dt = dl/dt - (l / l0) dl0/dt (zero for a cable paid out at constant
  strain), a choice where the paper only says the constitutive relation changes "accordingly".
* After every step, when s >= l0 a wing is transferred (:func:`transfer_up_3d`): the wing in the last slot leaves
  (its two elements merge, which the rest length above already says), every wing moves one slot up the cable,
  and a wing enters slot 0 at the point of the first element at the unstretched distance f_first l0 + s - l0
  from the ground (linear interpolation of position and velocity between the ground point and the attachment
  of the wing above, the paper's rule, ``station.insertion: paper``; with ``insertion: cable`` the velocity is
  interpolated from the cable material's at the ground point, V_c l / l0 along the element, instead of from
  rest, so that the new wing moves with the cable it joins). The paper leaves the new wing's attitude and rates
  open: it takes the attitude of the wing above it (the one it will follow up the cable) and no rotation. s < 0
  (the cable running backwards) transfers the other way. The state keeps its size: the leaving wing's slot is reused,
  nothing is allocated or repacked, and the count of transfers (a state) names which wing is in which slot.
* Generator: a prescribed schedule V_c(t); a drum, (J / r^2) dV_c/dt = T_first - T_last - Q / r with the
  generator torque Q the control after the wings'; or a commanded speed, dV_c/dt = (V_cmd - V_c) / tau with V_cmd
  that control. The state integrates the generator's mechanical power, (T_first - T_last) V_c (prescribed,
  commanded) or (Q / r) V_c (drum), into SX_ENERGY [J].
"""

import math
from collections import namedtuple

from numba import njit

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.dispatch import register_assemble, register_kind, register_moving_ends
from laddermill_gym.kernels.rigid.kinds import rigid2d_check, rigid3d_check
from laddermill_gym.kernels.rigid.rhs2d import rhs2d
from laddermill_gym.kernels.rigid.rhs3d import assemble3d, rhs3d
from laddermill_gym.kernels.station import cable_speed, first_rest_length, register_drive, station_drive, station_rates

_FM = {"contract", "nsz", "arcp"}

#: Kind markers of the moving cable; ``station`` is the packed station (``model/station.py``).
MovingCable3D = namedtuple("MovingCable3D", ["station"])
MovingCable2D = namedtuple("MovingCable2D", ["station"])


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def mill_rest_length(kind, e, t, x, M):
    if e != 0 and e != M.ef.shape[0] - 1:
        return M.ef[e, C.EF_L0]
    sp = kind.station
    if e == 0:
        return first_rest_length(sp, x)
    return sp[C.SP_PIECE] * sp[C.SP_F_LAST] - x[int(sp[C.SP_XOFF]) + C.SX_MOVED]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def mill_elongation_rate(kind, e, t, x, M, ln, l0, ld):
    if e != 0 and e != M.ef.shape[0] - 1:
        return ld
    v = cable_speed(kind.station, t, x)
    return ld - ln / l0 * v if e == 0 else ld + ln / l0 * v


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def veered_minus_hauled(tension):
    """The moving cable's drive [N]: the first (veered-side) element's tension less the last (hauled-side) one's."""
    return tension[0] - tension[tension.size - 1]


# The right-hand sides of every station kind (the moving cable, the winch: kernels/winch.py registers these too):
# the rigid model's, then the station block driven by the kind's registered drive (kernels/station.py).
@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def station3d_rhs(kind, t, x, u, dx, M, W):
    status = rhs3d(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)
    station_rates(kind.station, t, x, u, dx, station_drive(kind, W.tension))
    return status


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def station3d_assemble(kind, t, x, u, dx, M, W):
    assemble3d(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)
    station_rates(kind.station, t, x, u, dx, station_drive(kind, W.tension))
    return 0


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def station2d_rhs(kind, t, x, u, dx, M, W):
    status = rhs2d(t, x, u, dx, M, W, M.sag, M.caero)
    station_rates(kind.station, t, x, u, dx, station_drive(kind, W.tension))
    return status


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _rotation(q0, q1, q2, q3):
    """Rotation matrix (body -> global) of a quaternion as a row-major 9-tuple (the post-step check has no
    workspace; :func:`~laddermill_gym.kernels.small.quat_rotation` writes the same matrix into an array)."""
    n = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    a, b, c, d = q0 / n, q1 / n, q2 / n, q3 / n
    return (a * a + b * b - c * c - d * d, 2.0 * (b * c - a * d), 2.0 * (b * d + a * c),
            2.0 * (b * c + a * d), a * a - b * b + c * c - d * d, 2.0 * (c * d - a * b),
            2.0 * (b * d - a * c), 2.0 * (c * d + a * b), a * a - b * b - c * c + d * d)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _split(sp, x, M, up):
    """The element a transfer splits and where: (element, neighbour slot, its end on the neighbour, f, l0) with f
    the new wing's fraction of the way from the ground point to the neighbour's attachment and l0 [m] the element's
    unstretched length before the split."""
    s = x[int(sp[C.SP_XOFF]) + C.SX_MOVED]
    lp = sp[C.SP_PIECE]
    if up:  # split the first element; the neighbour is slot 0 (it moves to slot 1)
        old = sp[C.SP_F_FIRST] * lp + s
        return 0, 0, 1, (sp[C.SP_F_FIRST] * lp + s - lp) / old, old
    # split the last element; the neighbour is slot n-1 (it moves to slot n-2)
    old = sp[C.SP_F_LAST] * lp - s
    return M.ef.shape[0] - 1, M.wtype.size - 1, 0, (sp[C.SP_F_LAST] * lp - s - lp) / old, old


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _ground_speed(sp, x, up, length, l0):
    """Speed [m/s] of the cable material at the ground point of the split element, along it towards the wing, by
    the insertion rule (``SP_INSERT``): V_c l / l0 (forwards on the first element, backwards on the last) with the
    cable's rule, 0 (the ground point at rest) with the paper's. ``length`` [m] the element's length, ``l0`` [m]
    its unstretched length; V_c the state's cable speed (``SX_SPEED``, which follows a prescribed schedule)."""
    if sp[C.SP_INSERT] != C.INSERT_CABLE or not length > 0.0:
        return 0.0
    v = x[int(sp[C.SP_XOFF]) + C.SX_SPEED]
    return (v if up else -v) * length / l0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _shift_slots(x, nw, size, up):
    """Move every wing's block (``size`` entries) one slot up (``up``) or down the cable; the offset of the slot
    freed for the new wing."""
    if up:
        for k in range(nw - 1, 0, -1):
            for i in range(size):
                x[size * k + i] = x[size * (k - 1) + i]
        return 0
    for k in range(nw - 1):
        for i in range(size):
            x[size * k + i] = x[size * (k + 1) + i]
    return size * (nw - 1)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def transfer_3d(sp, x, M, up):
    """One wing transfer in a 3D state (``up``: the cable has moved one piece forwards, else backwards)."""
    e, nb, end, f, l0 = _split(sp, x, M, up)
    o = C.B3_SIZE * nb
    R = _rotation(x[o + C.B3_QUAT], x[o + C.B3_QUAT + 1], x[o + C.B3_QUAT + 2], x[o + C.B3_QUAT + 3])
    a0, a1, a2 = M.ea[e, end, 0], M.ea[e, end, 1], M.ea[e, end, 2]
    ax = x[o + C.B3_POS] + R[0] * a0 + R[1] * a1 + R[2] * a2
    ay = x[o + C.B3_POS + 1] + R[3] * a0 + R[4] * a1 + R[5] * a2
    az = x[o + C.B3_POS + 2] + R[6] * a0 + R[7] * a1 + R[8] * a2
    p, q, r = x[o + C.B3_RATE], x[o + C.B3_RATE + 1], x[o + C.B3_RATE + 2]
    bu = x[o + C.B3_VEL] + q * a2 - r * a1
    bv = x[o + C.B3_VEL + 1] + r * a0 - p * a2
    bw = x[o + C.B3_VEL + 2] + p * a1 - q * a0
    # the new wing's attachment: the fraction f of the way from the ground point; its velocity the same way between
    # the material's at the ground point (g: along the element, :func:`_ground_speed`) and the attachment's
    gi = M.ei[e, 1 - end]
    dx, dy, dz = ax - M.fixed[gi, 0], ay - M.fixed[gi, 1], az - M.fixed[gi, 2]
    ln = math.sqrt(dx * dx + dy * dy + dz * dz)
    g = _ground_speed(sp, x, up, ln, l0) / ln if ln > 0.0 else 0.0
    px, py, pz = M.fixed[gi, 0] + f * dx, M.fixed[gi, 1] + f * dy, M.fixed[gi, 2] + f * dz
    wx = f * (R[0] * bu + R[1] * bv + R[2] * bw)
    wy = f * (R[3] * bu + R[4] * bv + R[5] * bw)
    wz = f * (R[6] * bu + R[7] * bv + R[8] * bw)
    if g != 0.0:  # the cable's rule: plus (1 - f) times the material's velocity at the ground point (the paper's
        h = (1.0 - f) * g  # arithmetic untouched, bit for bit)
        wx, wy, wz = wx + h * dx, wy + h * dy, wz + h * dz
    o = _shift_slots(x, M.wtype.size, C.B3_SIZE, up)
    # the new wing keeps the neighbour's quaternion (still in its slot after the shift), turns not at all
    x[o + C.B3_POS] = px - (R[0] * a0 + R[1] * a1 + R[2] * a2)
    x[o + C.B3_POS + 1] = py - (R[3] * a0 + R[4] * a1 + R[5] * a2)
    x[o + C.B3_POS + 2] = pz - (R[6] * a0 + R[7] * a1 + R[8] * a2)
    x[o + C.B3_VEL] = R[0] * wx + R[3] * wy + R[6] * wz
    x[o + C.B3_VEL + 1] = R[1] * wx + R[4] * wy + R[7] * wz
    x[o + C.B3_VEL + 2] = R[2] * wx + R[5] * wy + R[8] * wz
    for i in range(3):
        x[o + C.B3_RATE + i] = 0.0


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def transfer_2d(sp, x, M, up):
    """One wing transfer in an in-plane state (see :func:`transfer_3d`)."""
    e, nb, end, f, l0 = _split(sp, x, M, up)
    o = C.B2_SIZE * nb
    th = x[o + C.B2_THETA]
    c, sn = math.cos(th), math.sin(th)
    a = M.ea[e, end]
    ax = x[o + C.B2_X] + c * a[0] + sn * a[2]
    az = x[o + C.B2_Z] - sn * a[0] + c * a[2]
    q = x[o + C.B2_Q]
    bu, bw = x[o + C.B2_U] + q * a[2], x[o + C.B2_W] - q * a[0]
    vx, vz = c * bu + sn * bw, -sn * bu + c * bw
    gp = M.fixed[M.ei[e, 1 - end]]
    dx, dz = ax - gp[0], az - gp[2]
    ln = math.sqrt(dx * dx + dz * dz)
    g = _ground_speed(sp, x, up, ln, l0) / ln if ln > 0.0 else 0.0
    o = _shift_slots(x, M.wtype.size, C.B2_SIZE, up)
    px, pz = gp[0] + f * dx, gp[2] + f * dz
    x[o + C.B2_X] = px - (c * a[0] + sn * a[2])
    x[o + C.B2_Z] = pz - (-sn * a[0] + c * a[2])
    x[o + C.B2_THETA] = th
    x[o + C.B2_U] = c * f * vx - sn * f * vz
    x[o + C.B2_W] = sn * f * vx + c * f * vz
    if g != 0.0:  # the cable's rule: plus (1 - f) times the material's velocity at the ground point, in body axes
        h = (1.0 - f) * g
        x[o + C.B2_U] += h * (c * dx - sn * dz)
        x[o + C.B2_W] += h * (sn * dx + c * dz)
    x[o + C.B2_Q] = 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _transfers_due(sp, x, status):
    """+1 (forwards), -1 (backwards) or 0: the transfer the moved cable s calls for after a step that ended with
    ``status`` (none unless OK)."""
    if status != C.OK:
        return 0
    s = x[int(sp[C.SP_XOFF]) + C.SX_MOVED]
    if s >= sp[C.SP_PIECE]:
        return 1
    if s < 0.0:
        return -1
    return 0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _book(sp, x, d, status):
    """Book the transfer d (made in x; none: ``status`` unchanged): s less d pieces, one more (or less) transfer.
    LIMIT if the cable still calls for one (it moved more than a piece in a step), else OK."""
    if d == 0:
        return status
    o = int(sp[C.SP_XOFF])
    x[o + C.SX_MOVED] -= d * sp[C.SP_PIECE]
    x[o + C.SX_TRANSFERS] += d
    return C.LIMIT if _transfers_due(sp, x, C.OK) != 0 else C.OK


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def mill3d_check(kind, x, M, limits):
    """The rigid check, then at most one wing transfer; LIMIT if the cable moved more than one piece in a step."""
    status = rigid3d_check(kind, x, M, limits)
    d = _transfers_due(kind.station, x, status)
    if d != 0:
        transfer_3d(kind.station, x, M, d > 0)
    return _book(kind.station, x, d, status)


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def mill2d_check(kind, x, M, limits):
    """The in-plane rigid check, then at most one wing transfer (see :func:`mill3d_check`)."""
    status = rigid2d_check(kind, x, M, limits)
    d = _transfers_due(kind.station, x, status)
    if d != 0:
        transfer_2d(kind.station, x, M, d > 0)
    return _book(kind.station, x, d, status)


def register_station_kinds(kind3d, kind2d, check3d, check2d, rest_length, elongation_rate, drive) -> None:
    """Register the 3D and in-plane markers of a station kind (the moving cable, the winch) with the station
    right-hand sides above, the kind's post-step checks, moving element ends and drum drive."""
    for marker, rhs, check in ((kind3d, station3d_rhs, check3d), (kind2d, station2d_rhs, check2d)):
        register_kind(marker, rhs, check)
        register_moving_ends(marker, rest_length, elongation_rate)
        register_drive(marker, drive)
    register_assemble(kind3d, station3d_assemble)


register_station_kinds(MovingCable3D, MovingCable2D, mill3d_check, mill2d_check, mill_rest_length,
                       mill_elongation_rate, veered_minus_hauled)
