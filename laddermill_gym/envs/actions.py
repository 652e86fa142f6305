"""Actions: normalised group commands in [-1, 1] mapped to per-wing control surface angles.

Wings are split into groups that share one command each (``groups``). Each group takes three entries:

* ``action_mode="tail"``: elevator, rudder, aileron;
* ``action_mode="alpha"``: commanded angle of attack, rudder, aileron. The commanded angle passes through
  an optional first-order servo lag and is turned into an elevator setting by a static map
  (:class:`ElevatorFromAlpha`). Rudder and aileron stay direct commands: the elevator only sets the
  longitudinal trim, and the lateral instability of a wing on a cable needs the lateral surfaces.

A normalised entry ``a`` maps linearly to a physical value ``mid + a * half_range`` over that quantity's
range (each wing's own control limits, or the angle-of-attack range of the map).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels.action_pass import clip_count, grouped_controls
from laddermill_gym.kernels.contract import CTRL_ELEVATOR
from laddermill_gym.model.params import AERO_INDEX, CONTROL_NAMES, N_CONTROLS, Assembly, WingType

ACTION_MODES: tuple[str, ...] = ("tail", "alpha")
GROUPINGS: tuple[str, ...] = ("per_wing", "all", "halves")


class ActionError(ValueError, TypeError):
    """An action that is not a finite real array of the action space's shape. Both a ValueError and a TypeError:
    numpy raises either for such input, so code that catches either still catches this."""


def _shown(action) -> str:
    text = " ".join(repr(action).split())
    return text if len(text) <= 60 else text[:57] + "..."


def _need(shape: tuple[int, ...]) -> str:
    return (f"an action must be a finite real array of shape {shape} (the action space is Box(-1, 1, {shape}, "
            "float32); entries outside [-1, 1] are clipped and counted in info['n_clipped'])")


def _real_array(action, shape: tuple[int, ...]) -> np.ndarray:
    """``action`` as a numpy array of integer or float dtype; :class:`ActionError` otherwise."""
    if action is None or isinstance(action, (str, bytes)):
        raise ActionError(f"action = {_shown(action)}: {_need(shape)}")
    try:
        a = np.asarray(action)
    except (ValueError, TypeError) as err:  # ragged nested lists
        raise ActionError(f"action = {_shown(action)}: {_need(shape)} ({err})") from None
    if a.dtype.kind not in "iuf":
        kind = {"c": "complex numbers", "b": "booleans", "U": "strings", "S": "bytes", "O": "Python objects"}.get(
            a.dtype.kind, "not real numbers")
        raise ActionError(f"action = {_shown(action)} has dtype {a.dtype} ({kind}): {_need(shape)}")
    return a


def _finite(a: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """float64 ``a`` reshaped to ``shape``; :class:`ActionError` naming the non-finite entries if any."""
    a = a.astype(float).reshape(shape)
    bad = ~np.isfinite(a)
    if bad.any():
        where = [tuple(int(i) for i in ix) for ix in np.argwhere(bad)[:4]]
        raise ActionError(f"action has non-finite entries at {where} ({a[bad][:4]}): {_need(shape)}")
    return a


def action_array(action, shape: tuple[int, ...], also: tuple[tuple[int, ...], ...] = ()) -> np.ndarray:
    """``action`` as a float64 array of ``shape`` (an array of one of the shapes ``also`` is reshaped to it). Raises
    :class:`ActionError` saying what an action must be (a real array of that shape, entries in [-1, 1], outside
    clipped) and what it got: None, a string, a complex, boolean or object array, another shape, a non-finite entry.
    Nothing is rounded away: a complex action is refused, not cut to its real part."""
    a = _real_array(action, shape)
    if a.shape != shape and a.shape not in also:
        raise ActionError(f"action = {_shown(action)} has shape {a.shape}: {_need(shape)}")
    return _finite(a, shape)


def single_action(action, n_actions: int, needs_reset: bool) -> np.ndarray:
    """A single env's action, shape (n_actions,) (or (1, n_actions)), as the task's batch of one, (1, n_actions)
    float64; RuntimeError when the episode needs a reset, :class:`ActionError` (see :func:`action_array`)."""
    if needs_reset:
        raise RuntimeError("step() called before reset() or after the episode ended; call reset()")
    return action_array(action, (n_actions,), also=((1, n_actions),))[None]


def clip_actions(action, n_copies: int, n_actions: int) -> tuple[np.ndarray, np.ndarray]:
    """The task's actions as (n_copies, n_actions) float64 clipped to [-1, 1], and the number of entries clipped per
    copy (B,); :class:`ActionError` (see :func:`action_array`) unless the action is a finite real array of
    n_copies x n_actions entries (of any shape, taken in row order)."""
    shape = (n_copies, n_actions)
    a = _real_array(action, shape)
    if a.size != n_copies * n_actions:
        raise ActionError(f"action = {_shown(action)} has shape {a.shape} ({a.size} entries): {_need(shape)}")
    # one compiled signature (float64, C order) whatever the caller passes: no further compile at a first step
    a = np.ascontiguousarray(a, dtype=float).reshape(shape)
    out, n_clipped = np.empty(shape), np.empty(n_copies, dtype=np.intp)
    if clip_count(a, out, n_clipped) < 0:  # compiled: np.clip and the count, bit for bit
        return out, n_clipped
    _finite(a, shape)  # raises, naming the non-finite entries
    raise AssertionError("clip_count found a non-finite entry that _finite did not")  # pragma: no cover


def resolve_groups(groups, n_wings: int, two_ended: bool, unit: str = "wing",
                   names: tuple[str, ...] = GROUPINGS) -> tuple[tuple[int, ...], ...]:
    """Wing index groups from a grouping name or an explicit list of index lists.

    ``"per_wing"``: one group per wing; ``"all"``: one group; ``"halves"``: the ascending half
    (wings 0 .. ceil(n/2) - 1) and the descending half of a chain between two ground points. An explicit
    list must hold every wing exactly once. Raises ValueError naming the field ``groups``, the groupings ``names``
    and the indexed ``unit`` ("wing"; the mill's "slot") the caller offers.
    """
    if isinstance(groups, str):
        if groups == "per_wing":
            return tuple((k,) for k in range(n_wings))
        if groups == "all":
            return (tuple(range(n_wings)),)
        if groups == "halves":
            if not two_ended or n_wings < 2:
                raise ValueError(f"groups = 'halves' needs a chain between two ground points with >= 2 wings "
                                 f"(this scene has {n_wings} wing(s), {'two' if two_ended else 'one'} ground end)")
            half = (n_wings + 1) // 2
            return (tuple(range(half)), tuple(range(half, n_wings)))
        raise ValueError(f"groups = {groups!r}: must be one of {names} or a list of {unit} index lists")
    try:
        out = tuple(tuple(int(k) for k in g) for g in groups)
    except TypeError:
        raise ValueError(f"groups = {groups!r}: must be one of {names} or a list of {unit} index lists") from None
    flat = sorted(k for g in out for k in g)
    if any(len(g) == 0 for g in out) or flat != list(range(n_wings)):
        raise ValueError(f"groups = {groups!r}: every {unit} 0..{n_wings - 1} must appear in exactly one non-empty "
                         "group")
    return out


class ElevatorFromAlpha:
    """Static map from a commanded angle of attack to the elevator angle that trims it, for one wing type.

    The map is the pitch-moment balance of :func:`laddermill_gym.sim.statics.pitch_trim_alpha` (no weight):
    a wing at rest in horizontal wind (pitch angle = alpha) has no pitching moment about its cable
    attachment point,

        Cm(alpha) + Cmde(alpha) de + [a_z X(alpha, de) - a_x Z(alpha, de)] / c = 0,
        X = CL sin(alpha) - CD cos(alpha),  Z = -CL cos(alpha) - CD sin(alpha),  CL = CL(alpha) + CLde(alpha) de,

    with (a_x, a_z) the aerodynamic reference point seen from the attachment point [m] and c the chord [m].
    The balance is linear in the elevator de, so de(alpha) is solved in closed form on a 0.05 deg grid from
    -30 to 30 deg. The usable range is the interval of alpha around ``alpha_centre`` [rad] on which de(alpha)
    lies within the elevator limits.
    """

    def __init__(self, wing_type: WingType, alpha_centre: float):
        from scipy.interpolate import CubicSpline
        grid = np.radians(np.arange(-30.0, 30.0 + 1e-9, 0.05))
        spline = CubicSpline(wing_type.aero.alpha, wing_type.aero.values, bc_type="periodic", axis=0)
        c = spline(grid)
        cl, cd, cm = c[:, AERO_INDEX["CL"]], c[:, AERO_INDEX["CD"]], c[:, AERO_INDEX["Cm"]]
        cl_de, cm_de = c[:, AERO_INDEX["CLde"]], c[:, AERO_INDEX["Cmde"]]
        ax = wing_type.r_ref[0] - wing_type.attachment[0]
        az = wing_type.r_ref[2] - wing_type.attachment[2]
        sa, ca = np.sin(grid), np.cos(grid)
        # moment coefficient about the attachment point = m0 + m_de * de
        m0 = cm + (az * (cl * sa - cd * ca) - ax * (-cl * ca - cd * sa)) / wing_type.chord
        m_de = cm_de + (az * cl_de * sa + ax * cl_de * ca) / wing_type.chord
        with np.errstate(divide="ignore", invalid="ignore"):
            de = -m0 / m_de
        lo, hi = wing_type.control_limits[0]
        ok = np.isfinite(de) & (de >= lo) & (de <= hi)
        i0 = int(np.argmin(np.abs(grid - alpha_centre)))
        if not ok[i0]:
            raise ValueError(f"wing type {wing_type.name!r}: no elevator within [{math.degrees(lo):.3g}, "
                             f"{math.degrees(hi):.3g}] deg trims alpha = {math.degrees(alpha_centre):.3g} deg")
        i_lo, i_hi = i0, i0
        while i_lo > 0 and ok[i_lo - 1]:
            i_lo -= 1
        while i_hi < grid.size - 1 and ok[i_hi + 1]:
            i_hi += 1
        self.alpha_grid = grid[i_lo: i_hi + 1]
        self.elevator_grid = de[i_lo: i_hi + 1]

    @property
    def alpha_range(self) -> tuple[float, float]:
        """Angles of attack [rad] the map covers (low, high)."""
        return float(self.alpha_grid[0]), float(self.alpha_grid[-1])

    def range_with_offset(self, offset: float, limits: tuple[float, float], centre: float) -> tuple[float, float]:
        """Angles of attack [rad] (low, high) around ``centre`` on which the map plus a wing's own elevator
        ``offset`` [rad] stays within its elevator ``limits`` [rad] (the grid point nearest ``centre`` always in:
        there the sum is the wing's trim elevator)."""
        e = self.elevator_grid + offset
        ok = (e >= limits[0]) & (e <= limits[1])
        i0 = int(np.argmin(np.abs(self.alpha_grid - centre)))
        ok[i0] = True
        i_lo, i_hi = i0, i0
        while i_lo > 0 and ok[i_lo - 1]:
            i_lo -= 1
        while i_hi < ok.size - 1 and ok[i_hi + 1]:
            i_hi += 1
        return float(self.alpha_grid[i_lo]), float(self.alpha_grid[i_hi])

    def __call__(self, alpha):
        """Elevator angle(s) [rad] trimming the given angle(s) of attack [rad] (held at the range ends)."""
        return np.interp(alpha, self.alpha_grid, self.elevator_grid)


@dataclass(frozen=True)
class ActionLayout:
    """Names and physical ranges of the action entries (n_actions = 3 n_groups).

    names : labels like ``'group 0 elevator [rad]'``; low, high : physical value at a = -1 and a = +1
    (the range of the group's first wing for tail surfaces) [rad].
    """

    names: tuple[str, ...]
    low: np.ndarray
    high: np.ndarray


class ActionMap:
    """Maps normalised actions (B, 3 n_groups) in [-1, 1] to the controls (B, 3 n_wings) [rad] of B copies.

    Parameters
    ----------
    assembly : Assembly
    groups : tuple of tuples of int
        Wing indices per group (see :func:`resolve_groups`).
    mode : "tail" or "alpha"
    nominal_controls : ndarray, shape (3 n_wings,)
        Equilibrium controls [rad]; the nominal action reproduces them (see Notes).
    nominal_alpha : ndarray, shape (n_wings,)
        Equilibrium angles of attack [rad] (used by the alpha mode).
    control_dt : float
        Control period [s] (for the servo lag).
    alpha_servo_tau : float
        Time constant [s] of the first-order lag between commanded and realised angle of attack
        (alpha mode); 0 = ideal servo.

    Notes
    -----
    Alpha mode: for group g with nominal command alpha_g (mean equilibrium alpha of its wings), wing k's
    elevator is ``de_k = E(alpha_s) + (de_k_eq - E(alpha_g))`` clipped to its limits, where E is the wing
    type's :class:`ElevatorFromAlpha` and alpha_s the realised command, which follows the commanded
    alpha_c as ``alpha_s += (1 - exp(-control_dt / tau)) (alpha_c - alpha_s)`` once per control period
    (exact for a command held over the period). The offset anchors the static map at the equilibrium,
    so the nominal action gives exactly the equilibrium controls.
    """

    def __init__(self, assembly: Assembly, groups, mode: str, nominal_controls: np.ndarray,
                 nominal_alpha: np.ndarray, control_dt: float, alpha_servo_tau: float = 0.0):
        if mode not in ACTION_MODES:
            raise ValueError(f"action_mode = {mode!r}: must be one of {ACTION_MODES}")
        if not (alpha_servo_tau >= 0.0 and math.isfinite(alpha_servo_tau)):
            raise ValueError(f"alpha_servo_tau = {alpha_servo_tau!r}: must be a finite number >= 0 s")
        self.mode = mode
        self.groups = tuple(tuple(g) for g in groups)
        n_wings = assembly.n_wings
        self.n_wings = n_wings
        limits = np.array([assembly.wing(k).control_limits for k in range(n_wings)])  # (n, 3, 2)
        self._mid = 0.5 * (limits[:, :, 0] + limits[:, :, 1])
        self._half = 0.5 * (limits[:, :, 1] - limits[:, :, 0])
        self._lo, self._hi = limits[:, :, 0], limits[:, :, 1]
        self._group_of = np.zeros(n_wings, dtype=np.int64)
        for g, members in enumerate(self.groups):
            self._group_of[list(members)] = g
        u_eq = np.asarray(nominal_controls, dtype=float).reshape(n_wings, N_CONTROLS)
        self.servo_gain = 1.0 if alpha_servo_tau == 0.0 else 1.0 - math.exp(-control_dt / alpha_servo_tau)
        names, low, high = [], [], []
        nominal = np.zeros((len(self.groups), N_CONTROLS))
        for g, members in enumerate(self.groups):
            k0 = members[0]
            for j in range(N_CONTROLS):
                nominal[g, j] = np.mean((u_eq[list(members), j] - self._mid[list(members), j])
                                        / self._half[list(members), j])
                names.append(f"group {g} {CONTROL_NAMES[j]} [rad]")
                low.append(self._lo[k0, j])
                high.append(self._hi[k0, j])
        if mode == "alpha":
            maps: dict[int, ElevatorFromAlpha] = {}
            self._alpha_lo = np.zeros(len(self.groups))
            self._alpha_hi = np.zeros(len(self.groups))
            self._nominal_alpha = np.zeros(len(self.groups))
            self._elevator_offset = np.zeros(n_wings)
            self._maps = []
            for g, members in enumerate(self.groups):
                alpha_g = float(np.mean(np.asarray(nominal_alpha)[list(members)]))
                lo, hi = -math.inf, math.inf
                for k in members:
                    ti = int(assembly.wing_type_index[k])
                    if ti not in maps:
                        maps[ti] = ElevatorFromAlpha(assembly.wing(k), alpha_g)
                    self._elevator_offset[k] = u_eq[k, 0] - float(maps[ti](alpha_g))
                    # the range on which the map plus this wing's offset needs no clip (the map's own range
                    # alone let a = -1 ask for more than the elevator's limit: a silent clip)
                    a_lo, a_hi = maps[ti].range_with_offset(self._elevator_offset[k],
                                                            (self._lo[k, 0], self._hi[k, 0]), alpha_g)
                    lo, hi = max(lo, a_lo), min(hi, a_hi)
                self._alpha_lo[g], self._alpha_hi[g] = lo, hi
                self._nominal_alpha[g] = alpha_g
                nominal[g, 0] = (alpha_g - 0.5 * (lo + hi)) / (0.5 * (hi - lo))
                names[N_CONTROLS * g] = f"group {g} alpha [rad]"
                low[N_CONTROLS * g], high[N_CONTROLS * g] = lo, hi
            types = np.asarray(assembly.wing_type_index, dtype=np.int64)
            self._maps = [(maps[ti], np.flatnonzero(types == ti)) for ti in sorted(maps)]
        self.layout = ActionLayout(names=tuple(names), low=np.array(low), high=np.array(high))
        self.nominal_action = np.clip(nominal.reshape(-1), -1.0, 1.0)
        self.alpha_servo = None
        self.reset()

    @property
    def n_actions(self) -> int:
        return N_CONTROLS * len(self.groups)

    def reset(self, n_copies: int = 1, mask: np.ndarray | None = None) -> None:
        """Put the servo (alpha mode) of all ``n_copies`` copies, or of the copies in the boolean ``mask``
        (B,), back at the nominal command."""
        if self.mode != "alpha":
            return
        if mask is None or getattr(self, "alpha_servo", None) is None or len(self.alpha_servo) != len(mask):
            self.alpha_servo = np.tile(self._nominal_alpha, (n_copies if mask is None else len(mask), 1))
        else:
            self.alpha_servo[mask] = self._nominal_alpha

    def apply(self, action: np.ndarray, sel: np.ndarray, controls: np.ndarray, last_action: np.ndarray) -> None:
        """Write the controls [rad] of normalised actions (B, 3 n_groups) already within [-1, 1] into the rows of
        ``controls`` (B, 3 n_wings) of the copies in the boolean ``sel`` (B,), and those actions into
        ``last_action``'s rows: :meth:`controls` then the masked writes, in one compiled pass in tail mode (bit for
        bit the same; ``kernels/action_pass.py``); in alpha mode :meth:`controls`, whose servo advances every copy
        (the caller keeps those outside ``sel``)."""
        if self.mode == "tail":
            grouped_controls(action, self._group_of, self._mid, self._half, self._lo, self._hi, sel, controls,
                             last_action)
            return
        u = self.controls(action)
        controls[sel] = u[sel]
        last_action[sel] = action[sel]

    def controls(self, action: np.ndarray) -> np.ndarray:
        """Controls (B, 3 n_wings) [rad] for normalised actions (B, 3 n_groups) already within [-1, 1].

        In alpha mode this advances each copy's servo by one control period (B must match the servo's)."""
        per_group = np.asarray(action, dtype=float).reshape(-1, len(self.groups), N_CONTROLS)
        u = self._mid + per_group[:, self._group_of] * self._half  # (B, n_wings, 3)
        if self.mode == "alpha":
            cmd = (0.5 * (self._alpha_lo + self._alpha_hi)
                   + per_group[:, :, 0] * 0.5 * (self._alpha_hi - self._alpha_lo))  # (B, n_groups)
            self.alpha_servo = self.alpha_servo + self.servo_gain * (cmd - self.alpha_servo)
            realised = self.alpha_servo[:, self._group_of]  # (B, n_wings)
            for elevator_map, wings in self._maps:
                u[:, wings, CTRL_ELEVATOR] = elevator_map(realised[:, wings]) + self._elevator_offset[wings]
        return np.clip(u, self._lo, self._hi).reshape(len(u), -1)
