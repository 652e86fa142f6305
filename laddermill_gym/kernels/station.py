"""The ground station's kernels, shared by the moving cable (``kernels/moving_cable.py``) and the winch
(``kernels/winch.py``): the speed schedule, the station block of the state derivative and the moving first
element's rest length.

Parameters ``sp``: slots ``SP_*``, state block ``SX_*`` (``kernels/contract.py``; packed by ``model/station.py``).
The station pays the cable out at V (ds/dt = V, the state ``SX_MOVED``), with V from

* a prescribed schedule V(t) (piecewise linear, held outside);
* a drum, (J / r^2) dV/dt = T_drive - Q / r with the generator torque Q [N m] the control after the wings';
* a commanded speed, dV/dt = (V_cmd - V) / tau with V_cmd that control;

and integrates the mechanical power at the drum, (Q / r) V with a drum and T_drive V otherwise, into
``SX_ENERGY`` [J]. The drive T_drive [N] is what pulls the cable off the drum: T_first - T_last for the moving cable
(veered minus hauled side), T_0 for the winch; each kind registers its own (:func:`register_drive`) and
:func:`station_drive` picks it by the kind's type when numba compiles.
"""

from numba import njit
from numba.core.errors import TypingError
from numba.extending import overload

from laddermill_gym.kernels import contract as C

_FM = {"contract", "nsz", "arcp"}

_DRIVE: dict[type, object] = {}


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def scheduled_speed(sp, t):
    """The schedule's cable speed V_c(t) [m/s] and its rate [m/s^2] (piecewise linear, held outside).

    At a knot the rate is the later piece's, and 0 at the first and the last knot, so an integrator's stage there
    takes the held side: the state ``SX_SPEED`` of a prescribed station trails the schedule by a dt / 6 per such knot
    on RK4 (a the ramp's slope; 1.1e-4 m/s on the scenes' 0-2 m/s ramp over 30 s at 10 ms), while the kernels'
    tensions and the generator read the schedule itself. Kept: the registered mills' starts are computed with it."""
    n = int(sp[C.SP_NSCHED])
    ot, ov = C.SP_SCHED, C.SP_SCHED + n
    if n == 1 or not t > sp[ot]:
        return sp[ov], 0.0
    if t >= sp[ot + n - 1]:
        return sp[ov + n - 1], 0.0
    k = 0
    while t >= sp[ot + k + 1]:
        k += 1
    a = (sp[ov + k + 1] - sp[ov + k]) / (sp[ot + k + 1] - sp[ot + k])
    return sp[ov + k] + a * (t - sp[ot + k]), a


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def cable_speed(sp, t, x):
    """Cable speed V_c [m/s] at time t [s] in state x: the state (drum, commanded) or the schedule."""
    if sp[C.SP_MODE] != C.MODE_PRESCRIBED:
        return x[int(sp[C.SP_XOFF]) + C.SX_SPEED]
    return scheduled_speed(sp, t)[0]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def first_rest_length(sp, x):
    """Unstretched length [m] of the first element (from the station up): f_first l_p + s."""
    return sp[C.SP_PIECE] * sp[C.SP_F_FIRST] + x[int(sp[C.SP_XOFF]) + C.SX_MOVED]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def station_rates(sp, t, x, u, dx, drive):
    """The station block of dx: ds/dt = V, the drum's acceleration (or the schedule's rate or the speed lag) and
    the mechanical power at the drum [W] (into the energy); ``drive`` [N] is the tension on the drum."""
    o = int(sp[C.SP_XOFF])
    if sp[C.SP_MODE] == C.MODE_DRUM:
        v = x[o + C.SX_SPEED]
        r = sp[C.SP_RADIUS]
        force = u[int(sp[C.SP_UOFF])] / r
        dx[o + C.SX_SPEED] = (drive - force) * r * r / sp[C.SP_INERTIA]
        power = force * v
    elif sp[C.SP_MODE] == C.MODE_COMMANDED:
        v = x[o + C.SX_SPEED]
        dx[o + C.SX_SPEED] = (u[int(sp[C.SP_UOFF])] - v) / sp[C.SP_TAU]
        power = drive * v
    else:
        v, a = scheduled_speed(sp, t)
        dx[o + C.SX_SPEED] = a
        power = drive * v
    dx[o + C.SX_MOVED] = v
    dx[o + C.SX_TRANSFERS] = 0.0
    dx[o + C.SX_ENERGY] = power


def register_drive(marker: type, drive) -> None:
    """Register the drum's drive of a station kind: ``drive(tension) -> T_drive`` [N] from the element tensions."""
    _DRIVE[marker] = drive


def station_drive(kind, tension):
    """The tension on the drum [N] of station kind ``kind`` (jitted code only)."""
    raise NotImplementedError("station_drive is resolved inside numba kernels")


@overload(station_drive, inline="always")
def _station_drive(kind, tension):
    cls = getattr(kind, "instance_class", None)
    if cls not in _DRIVE:
        raise TypingError(f"no station drive registered for {kind} (known: {[c.__name__ for c in _DRIVE]})")
    impl = _DRIVE[cls]
    return lambda kind, tension: impl(tension)

