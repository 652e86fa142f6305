"""The moving cable (Meijaard et al. 1999, "Boundary conditions") at the point-mass fidelity (docs/pointmass.md,
"The moving cable").

The string runs from the veered-side ground point (start anchor) through free nodes 0..n-1 to the hauled-side
ground point (end anchor). Its first element (anchor -> node 0) has the unstretched length a + s and the last one
(node n-1 -> end anchor) b - s, with s the cable moved since the last node transfer (``SX_MOVED``). When s reaches
the element length l_e a node transfer relabels the material: node n-1 leaves (its two elements merge, which the
rest lengths already say), every node moves up one index, and a node enters at index 0 on the first element at
the unstretched distance a + s - l_e from the anchor (position and velocity interpolated linearly between the
anchor at rest and the old node 0: the paper's rule). The kite flags travel with the nodes and the one leaving
re-enters at index 0: the loop is endless, the kites ride on it at fixed material positions, and the k-th kite
from the veered end takes control row k (slots, as the rigid mill's wings). s < 0 transfers the other way. The
state keeps its size; a transfer moves 6 n numbers once per l_e of cable (nothing is allocated).

Station array ``sp``: the ``SP_*`` slots of ``kernels/contract.py`` with ``SP_PIECE`` = l_e [m] and
``SP_F_FIRST``, ``SP_F_LAST`` = a / l_e, b / l_e [-], prescribed speed schedule in ``SP_NSCHED``/``SP_SCHED``.
Station state ``sx`` (``MX_SIZE``,): the rigid mill's ``SX_*`` block (moved [m], node transfers, V_c [m/s],
generator energy [J]) plus ``MX_KITE_TRANSFERS``, the kites that have gone round the station.
"""

from numba import njit

from laddermill_gym.kernels.contract import (  # noqa: F401 (read as attributes of this module)
    INSERT_CABLE,
    MX_KITE_TRANSFERS,
    MX_SIZE,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    PM_LIMIT,
    PM_OK,
    PP_ANCHOR,
    PP_DA,
    PP_EA,
    PP_END,
    PP_L_FIRST,
    PP_L_LAST,
    PP_N,
    PP_RATE_FIRST,
    PP_RATE_LAST,
    SP_F_FIRST,
    SP_F_LAST,
    SP_INSERT,
    SP_NSCHED,
    SP_PIECE,
    SP_SCHED,
    SX_ENERGY,
    SX_MOVED,
    SX_SIZE,
    SX_SPEED,
    SX_TRANSFERS,
)
from laddermill_gym.kernels.pointmass.forces import element_geometry, element_tension, node_mass, rest_length

_FM = {"contract", "nsz", "arcp"}



@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def schedule_speed(sp, t):
    """V_c(t) [m/s] of the piecewise-linear schedule, held constant outside it (the rigid mill's
    ``kernels/station.scheduled_speed``, without the rate)."""
    n = int(sp[SP_NSCHED])
    ot, ov = SP_SCHED, SP_SCHED + n
    if n == 1 or not t > sp[ot]:
        return sp[ov]
    if t >= sp[ot + n - 1]:
        return sp[ov + n - 1]
    k = 0
    while t >= sp[ot + k + 1]:
        k += 1
    return sp[ov + k] + (sp[ov + k + 1] - sp[ov + k]) / (sp[ot + k + 1] - sp[ot + k]) * (t - sp[ot + k])


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def set_ends(par, sp, s, v):
    """The end elements' unstretched lengths a + s, b - s [m] and their rates +-V_c [m/s] into ``par``."""
    le = sp[SP_PIECE]
    par[PP_L_FIRST] = sp[SP_F_FIRST] * le + s
    par[PP_L_LAST] = sp[SP_F_LAST] * le - s
    par[PP_RATE_FIRST] = v
    par[PP_RATE_LAST] = -v


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def end_tensions(x, M):
    """Tensions [N] of the first and the last element (Voigt damping on the material strain rate included)."""
    return element_tension(x, 0, M.par, True), element_tension(x, int(M.par[PP_N]), M.par, True)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def pay_out_rhs(x, M, dt):
    """The end elements' terms of the implicit step that their changing rest length adds, as forces F on nodes 0
    and n-1, added as dt F to their right-hand sides r = m v + dt F_ext(x, v) once the step has assembled them
    (``x``'s velocity slots hold r then; ``implicit.mill_implicit_step``):

    * the matrix damps the whole elongation rate DA l'/l0; the material strain rate subtracts (l/l0) dl0/dt;
    * the step takes the elastic force at its end, EA (l+ - l0+)/l0+, linearised about the start in l only; the
      rest length grows by dl0/dt dt within the step, which changes it by -EA (l/l0^2) dl0/dt dt.

    Together a tension -(DA + dt EA) (l/l0) (dl0/dt) / l0 along the element (positions only: the assembly has not
    moved them). Without the second term a short first element (0.1 l_e) resists the pay-out as if its rest length
    stood still and the cable near the veered ground point goes slack (measured on a straight moving string: three
    slack elements, the rest at ten times the strain the ground points impose). Until 2026-12-07 this was added to
    the velocities as dt F / m before the assembly, so that the kites' aerodynamics, the cable drag and the
    gravity of nodes 0 and n-1 were taken at a velocity kicked by 10-450 m/s (docs/pointmass_mill.md)."""
    par = M.par
    n = int(par[PP_N])
    for side in range(2):
        e = 0 if side == 0 else n
        j = 0 if side == 0 else n - 1
        tx, ty, tz, ln = element_geometry(x, e, par)
        rate = par[PP_RATE_FIRST] if side == 0 else par[PP_RATE_LAST]
        l0 = rest_length(e, par)
        tc = -(par[PP_DA] + dt * par[PP_EA]) * ln / l0 * rate / l0  # tension of the correction [N]
        sign = -1.0 if side == 0 else 1.0  # the element pulls its upper node down, its lower node up
        h = sign * dt * tc
        o = N3_SIZE * j + N3_VEL
        x[o] += h * tx
        x[o + 1] += h * ty
        x[o + 2] += h * tz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _move_node(x, src, dst):
    for i in range(N3_SIZE):
        x[N3_SIZE * dst + i] = x[N3_SIZE * src + i]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _sheave_velocity(x, e, par, sp, v, l0):
    """Velocity [m/s] of the cable material passing the ground point of end element e (unstretched length l0 [m]
    now): V_c (l / l0) along the element (node e - 1 -> node e), the pay-out at the element's strain; zero with
    the paper's insertion rule (``SP_INSERT``: the ground point at rest)."""
    tx, ty, tz, ln = element_geometry(x, e, par)
    w = v * ln / l0 if sp[SP_INSERT] == INSERT_CABLE else 0.0
    return w * tx, w * ty, w * tz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _new_node(x, j, par, g, f, src, ux, uy, uz):
    """Node j at the fraction f of the way from the ground point par[g:g+3] to node ``src``; its velocity
    interpolated the same way between the material velocity at the ground point (ux, uy, uz) and node src's."""
    o, q = N3_SIZE * j, N3_SIZE * src
    u = (ux, uy, uz)
    for i in range(3):
        x[o + N3_POS + i] = par[g + i] + f * (x[q + N3_POS + i] - par[g + i])
        x[o + N3_VEL + i] = u[i] + f * (x[q + N3_VEL + i] - u[i])


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def transfer_up(x, M, sp, s, v):
    """The cable has moved one element forwards (s >= l_e) at V_c = v [m/s]: node n-1 leaves, nodes and kite flags
    move up one index, a node enters at 0. Returns +1 if a kite went round the station, else 0."""
    par, kflag, knode = M.par, M.kflag, M.knode
    n = int(par[PP_N])
    old = sp[SP_F_FIRST] * sp[SP_PIECE] + s
    f = (old - sp[SP_PIECE]) / old
    ux, uy, uz = _sheave_velocity(x, 0, par, sp, v, old)
    # node 0 moves to index 1 first, so the new node is interpolated towards index 1
    for j in range(n - 1, 0, -1):
        _move_node(x, j - 1, j)
    _new_node(x, 0, par, PP_ANCHOR, f, 1 if n > 1 else 0, ux, uy, uz)
    last = kflag[n - 1]
    for j in range(n - 1, 0, -1):
        kflag[j] = kflag[j - 1]
    kflag[0] = last
    nk = knode.size
    if knode[0] < 0:  # no kites
        return 0
    wrapped = knode[nk - 1] == n - 1
    for k in range(nk):
        knode[k] += 1
    if wrapped:
        for k in range(nk - 1, 0, -1):
            knode[k] = knode[k - 1]
        knode[0] = 0
        return 1
    return 0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def transfer_down(x, M, sp, s, v):
    """The cable has moved backwards past a node (s < 0) at V_c = v < 0: node 0 leaves, nodes and kite flags move
    down one index, a node enters at n-1 on the last element. Returns -1 if a kite went round the station, else 0."""
    par, kflag, knode = M.par, M.kflag, M.knode
    n = int(par[PP_N])
    old = sp[SP_F_LAST] * sp[SP_PIECE] - s
    f = (old - sp[SP_PIECE]) / old
    ux, uy, uz = _sheave_velocity(x, n, par, sp, v, old)
    for j in range(n - 1):
        _move_node(x, j + 1, j)
    _new_node(x, n - 1, par, PP_END, f, n - 2 if n > 1 else 0, ux, uy, uz)
    first = kflag[0]
    for j in range(n - 1):
        kflag[j] = kflag[j + 1]
    kflag[n - 1] = first
    nk = knode.size
    if knode[0] < 0:
        return 0
    wrapped = knode[0] == 0
    for k in range(nk):
        knode[k] -= 1
    if wrapped:
        for k in range(nk - 1):
            knode[k] = knode[k + 1]
        knode[nk - 1] = n - 1
        return -1
    return 0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _transfer(x, M, sp, sx):
    """At most one node transfer for the cable moved; PM_LIMIT if the cable moved more than one element (which the
    simulator refuses when it is built: max |V_c| dt >= l_e, ``sim/pointmass_mill.py``)."""
    s = sx[SX_MOVED]
    le = sp[SP_PIECE]
    if s >= le:
        sx[MX_KITE_TRANSFERS] += transfer_up(x, M, sp, s, sx[SX_SPEED])
        sx[SX_MOVED] -= le
        sx[SX_TRANSFERS] += 1.0
    elif s < 0.0:
        sx[MX_KITE_TRANSFERS] += transfer_down(x, M, sp, s, sx[SX_SPEED])
        sx[SX_MOVED] += le
        sx[SX_TRANSFERS] -= 1.0
    s = sx[SX_MOVED]
    return PM_LIMIT if (s >= le or s < 0.0) else PM_OK


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def mill_before(t, x, M, sp, sx):
    """Before a step at t [s]: the end elements' lengths from s and V_c(t) and their start-of-step tensions (the
    implicit step then adds :func:`pay_out_rhs` to its right-hand side). Returns (T_first [N], T_last [N], V_c
    [m/s])."""
    v = schedule_speed(sp, t)
    set_ends(M.par, sp, sx[SX_MOVED], v)
    t0, tn = end_tensions(x, M)
    return t0, tn, v


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def schedule_integral(sp, t, dt, v, v1):
    """Cable paid out over [t, t + dt] [m]: the integral of the piecewise-linear schedule, exact (a trapezoid per
    linear piece, split at the breakpoints inside the step; the trapezoid 0.5 dt (v + v1) when none is inside).
    ``v``, ``v1``: V_c at t and t + dt [m/s]."""
    n = int(sp[SP_NSCHED])
    ot, ov = SP_SCHED, SP_SCHED + n
    t1 = t + dt
    total, a, va, split = 0.0, t, v, False
    for k in range(n):
        tk = sp[ot + k]
        if t < tk < t1:
            total += 0.5 * (tk - a) * (va + sp[ov + k])
            a, va, split = tk, sp[ov + k], True
    if not split:
        return 0.5 * dt * (v + v1)
    return total + 0.5 * (t1 - a) * (va + v1)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def mill_after(t, x, M, sp, sx, dt, t0, tn, v, status):
    """After the string's step from t [s]: the generator power (T_first - T_last) V_c [W] of the step's start into
    the energy, s += the schedule's pay-out over the step (:func:`schedule_integral`, exact), V_c(t + dt), then
    (if the step went well) at most one node transfer, and the end lengths for the new s. Returns the status."""
    v1 = schedule_speed(sp, t + dt)
    sx[SX_ENERGY] += dt * (t0 - tn) * v
    sx[SX_MOVED] += schedule_integral(sp, t, dt, v, v1)
    sx[SX_SPEED] = v1
    if status == PM_OK:
        status = _transfer(x, M, sp, sx)
    set_ends(M.par, sp, sx[SX_MOVED], v1)
    return status


@njit(cache=True, error_model="numpy", _nrt=True, fastmath=False)
def node_masses(M, out):
    """Lumped mass [kg] of every free node (n,) into ``out`` (the kernels' own ``node_mass``)."""
    for j in range(out.size):
        out[j] = node_mass(j, M)
