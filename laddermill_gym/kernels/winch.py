"""The winch of a pumping kite (Lansdorp et al. 2008) as two model kinds: one tether whose ground end is wound on a
drum, so that its first element (element 0, from the ground point up) changes unstretched length with the drum.

``Winch3D`` and ``Winch2D`` are the rigid kinds (``kernels/rigid/kinds.py``) plus the winch, packed with the
ground station's slots (``SP_*`` of ``kernels/contract.py``, written by ``model/winch.py``) and carrying the same
state block (``SX_*``):

* element 0 has the unstretched length f_first l_p + s, with l_p = ``SP_PIECE`` its length at s = 0, f_first =
  ``SP_F_FIRST`` (1 for a winch) and s = ``SX_MOVED`` the tether paid out since t = 0 (ds/dt = V, the winch
  speed, > 0 reeling out). Every other element keeps its packed length; there is no last moving element and no
  wing transfer (``SX_TRANSFERS`` stays 0). The tether's mass follows the rest length (mu l0), and the damping
  acts on the material strain rate, l0 d(eps)/dt = dl/dt - (l / l0) dl0/dt, as for the moving cable.
* Winch: a prescribed speed schedule V(t); a drum, (J / r^2) dV/dt = T_0 - Q / r with the generator torque Q [N m]
  the control after the wings'; or a commanded speed, dV/dt = (V_cmd - V) / tau with V_cmd that control.
  ``SX_ENERGY`` integrates the mechanical power at the drum: (Q / r) V with a drum, T_0 V otherwise (> 0 when the
  tether is reeled out under tension: energy to the generator; < 0 reeling in: energy the motor spends).
* The post-step check is the rigid one; it returns LIMIT when element 0 has been reeled in below
  ``MIN_FRACTION`` of l_p (the drum cannot swallow the wing).
"""

from collections import namedtuple

from numba import njit

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.moving_cable import register_station_kinds
from laddermill_gym.kernels.rigid.kinds import rigid2d_check, rigid3d_check
from laddermill_gym.kernels.station import cable_speed, first_rest_length

_FM = {"contract", "nsz", "arcp"}

#: Kind markers of the winch; ``station`` is the packed winch (``model/winch.py``, ``SP_*`` slots).
Winch3D = namedtuple("Winch3D", ["station"])
Winch2D = namedtuple("Winch2D", ["station"])

#: Shortest rest length of the winch element, as a fraction of its length at s = 0 [-]: below it the step
#: returns LIMIT (a reel-in that would pull the wing into the drum).
MIN_FRACTION = 0.05


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def winch_rest_length(kind, e, t, x, M):
    """Unstretched length [m] of element e: f_first l_p + s for element 0, the packed length otherwise."""
    if e == 0:
        return first_rest_length(kind.station, x)
    return M.ef[e, C.EF_L0]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def winch_elongation_rate(kind, e, t, x, M, ln, l0, ld):
    """Material elongation rate [m/s] of element e: dl/dt - (l / l0) V for element 0 (tether paid out at V)."""
    if e != 0:
        return ld
    return ld - ln / l0 * cable_speed(kind.station, t, x)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def first_tension(tension):
    """The winch's drive [N]: the tension of element 0 (no hauled side)."""
    return tension[0]


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _checked(sp, x, status):
    """LIMIT when an OK step left the winch element shorter than MIN_FRACTION of its start length, else status."""
    if status == C.OK and first_rest_length(sp, x) < MIN_FRACTION * sp[C.SP_PIECE]:
        return C.LIMIT
    return status


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def winch3d_check(kind, x, M, limits):
    """The rigid check; LIMIT when the winch element is shorter than MIN_FRACTION of its start length."""
    return _checked(kind.station, x, rigid3d_check(kind, x, M, limits))


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def winch2d_check(kind, x, M, limits):
    """The in-plane rigid check; LIMIT as :func:`winch3d_check`."""
    return _checked(kind.station, x, rigid2d_check(kind, x, M, limits))


# The right-hand sides are the station kinds' of kernels/moving_cable.py, driven by T_0 (first_tension).
register_station_kinds(Winch3D, Winch2D, winch3d_check, winch2d_check, winch_rest_length, winch_elongation_rate,
                       first_tension)
