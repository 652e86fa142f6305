"""Actions of ``laddermill_gym/LadderMill-v0``: tail commands by *slot*, optionally the generator torque.

Slot k is the position k along the loop (slot 0 the lowest on the ascending, veered side, slot n-1 the lowest on
the descending, hauled side). Wings move up one slot at every transfer, so a slot's command stays with the
position, not with the wing: the state is kept in slot order by the simulator (``kernels/moving_cable.py``), and
the controls are too.

Groups of slots share one command (``groups``): ``"per_slot"``, ``"all"``, ``"halves"`` (ascending slots
0 .. ceil(n/2) - 1, descending the rest), ``"bands"`` (each half split into ``n_bands`` bands of consecutive
slots: height bands, 2 n_bands groups) or an explicit list of slot lists. Each group takes one entry per tail
surface in ``surfaces`` (elevator, rudder, aileron, in that order); with ``generator_torque`` one last entry
commands the drum's generator torque or, with ``cable_speed_command``, the cable speed the generator's speed
controller holds (Q_op or V_c at a = 0, the same linear law with its own half range).

Mapping (a = 0 is the operating point, the paper's fixed tail settings): a surface of slot k is
clip(u_op[k] + a authority half_range, limits), with half_range the half width of the wing's control limits (the
scale of ``envs/actions.py``: 15 deg of elevator per unit for the default wing) and ``authority`` in (0, 1] the
share of it one unit of action commands (1: the whole range, LadderMill-v0; a smaller one makes a = +-1 a bounded
increment around the trim, so random actions do not tumble the wings within a second); the torque is
Q_op + a torque_half_range, clipped to the station's torque limits (the same range). Surfaces not in
``surfaces`` hold the operating point.
"""

from __future__ import annotations

import numbers

import numpy as np

from laddermill_gym.envs.actions import ActionLayout, resolve_groups
from laddermill_gym.envs.task_base import positive
from laddermill_gym.model.params import CONTROL_NAMES, N_CONTROLS, Assembly

__all__ = ["SLOT_GROUPINGS", "resolve_slot_groups", "action_count", "check_surfaces", "check_authority",
           "SlotActionMap"]

SLOT_GROUPINGS: tuple[str, ...] = ("per_slot", "all", "halves", "bands")


def resolve_slot_groups(groups, n_slots: int, n_bands: int = 4) -> tuple[tuple[int, ...], ...]:
    """Slot index groups (tuple of tuples) of a grouping name or an explicit list of slot lists (every slot exactly
    once). ValueError names ``groups`` or ``n_bands``."""
    if isinstance(groups, str) and groups not in SLOT_GROUPINGS:
        raise ValueError(f"groups = {groups!r}: must be one of {SLOT_GROUPINGS} or a list of slot index lists")
    if groups == "bands":
        if (isinstance(n_bands, bool) or not isinstance(n_bands, (int, float, np.integer, np.floating))
                or int(n_bands) != n_bands or not 1 <= n_bands <= n_slots // 2):
            raise ValueError(f"n_bands = {n_bands!r}: must be an integer in 1 .. n_slots // 2 = {n_slots // 2}")
        half = (n_slots + 1) // 2
        up = np.array_split(np.arange(half), int(n_bands))
        down = np.array_split(np.arange(half, n_slots), int(n_bands))
        return tuple(tuple(int(k) for k in g) for g in (*up, *down))
    return resolve_groups("per_wing" if groups == "per_slot" else groups, n_slots, True, "slot", SLOT_GROUPINGS)


def action_count(n_slots: int, groups="per_slot", n_bands: int = 4, surfaces=CONTROL_NAMES,
                 generator_torque: bool = False, cable_speed_command: bool = False) -> int:
    """Number of action entries of a layout (without building the env or its operating point): one per group and
    surface, and one for the station (the generator torque or the cable speed command) when either is on."""
    station = bool(generator_torque) or bool(cable_speed_command)
    return len(resolve_slot_groups(groups, n_slots, n_bands)) * len(check_surfaces(surfaces)) + int(station)


def check_surfaces(surfaces) -> tuple[str, ...]:
    """``surfaces`` as a tuple; ValueError naming it unless a non-empty subset of the tail surfaces without
    repeats."""
    surfaces = tuple(surfaces)
    if not surfaces or len(set(surfaces)) != len(surfaces) or not set(surfaces) <= set(CONTROL_NAMES):
        raise ValueError(f"surfaces = {surfaces!r}: a non-empty subset of {CONTROL_NAMES} without repeats")
    return surfaces


def check_authority(authority) -> float:
    """``authority`` as a float; ValueError naming it unless a number in (0, 1]."""
    if isinstance(authority, bool) or not isinstance(authority, numbers.Real) or not 0.0 < authority <= 1.0:
        raise ValueError(f"authority = {authority!r}: must be a number in (0, 1] (the share of each tail "
                         "surface's half range one unit of action commands)")
    return positive("authority", authority, "")  # np.float32(0.2) read as 0.2


class SlotActionMap:
    """Normalised actions (B, n_actions) in [-1, 1] -> controls (B, n_controls) of B copies (see the module doc).

    Parameters
    ----------
    assembly : Assembly                       the env's (its station decides whether a torque control exists)
    groups : tuple of tuples of int           slots per group (:func:`resolve_slot_groups`)
    surfaces : tuple of str                   tail surfaces commanded, a subset of ("elevator", "rudder", "aileron")
    u_op : ndarray (n_controls,)              operating-point controls [rad] (and the station's control last: the
                                              drum's torque [N m] or the commanded cable speed [m/s])
    torque_half_range : float or None         the station's control per unit action [N m or m/s] (needs a station
                                              in mode 'drum' or 'commanded'), None: no station action
    authority : float                         share (0, 1] of each surface's half range per unit action
    """

    def __init__(self, assembly: Assembly, groups, surfaces, u_op: np.ndarray, torque_half_range: float | None,
                 authority: float = 1.0):
        authority = check_authority(authority)
        surfaces = check_surfaces(surfaces)
        self.surface_index = np.array(sorted(CONTROL_NAMES.index(s) for s in surfaces), dtype=np.int64)
        self.groups = tuple(tuple(g) for g in groups)
        n = assembly.n_wings
        self.n_wings = n
        limits = np.array([assembly.wing(k).control_limits for k in range(n)])  # (n, 3, 2)
        self._lo, self._hi = limits[:, :, 0], limits[:, :, 1]
        self._half = 0.5 * (self._hi - self._lo) * float(authority)
        self.u_op = np.asarray(u_op, dtype=float).copy()
        self._group_of = np.zeros(n, dtype=np.int64)
        for g, members in enumerate(self.groups):
            self._group_of[list(members)] = g
        self.torque = torque_half_range is not None
        if self.torque and (assembly.station is None or assembly.station.mode == "prescribed"):
            raise ValueError("a station action needs the station in mode 'drum' (torque) or 'commanded' (speed)")
        self.station_label = ("generator torque [N m]" if self.torque and assembly.station.mode == "drum"
                              else "cable speed command [m/s]")
        self.torque_half_range = float(torque_half_range) if self.torque else 0.0
        self.n_surface_actions = len(self.groups) * len(self.surface_index)
        self.n_actions = self.n_surface_actions + int(self.torque)
        self.nominal_action = np.zeros(self.n_actions)
        self.layout = self._layout()

    def _layout(self) -> ActionLayout:
        """Names and the physical values at a = -1 and +1 (of the group's first slot) of every entry."""
        names, low, high = [], [], []
        u = self.u_op[: N_CONTROLS * self.n_wings].reshape(self.n_wings, N_CONTROLS)
        for g, members in enumerate(self.groups):
            k = members[0]
            for j in self.surface_index:
                names.append(f"group {g} (slots {members[0]}..{members[-1]}) {CONTROL_NAMES[j]} [rad]")
                low.append(max(self._lo[k, j], u[k, j] - self._half[k, j]))
                high.append(min(self._hi[k, j], u[k, j] + self._half[k, j]))
        if self.torque:
            names.append(self.station_label)
            low.append(self.u_op[-1] - self.torque_half_range)
            high.append(self.u_op[-1] + self.torque_half_range)
        return ActionLayout(names=tuple(names), low=np.array(low), high=np.array(high))

    def controls(self, action: np.ndarray) -> np.ndarray:
        """Controls (B, n_controls) for normalised actions (B, n_actions) already within [-1, 1]."""
        a = np.asarray(action, dtype=float).reshape(-1, self.n_actions)
        B, n = len(a), self.n_wings
        u = np.tile(self.u_op, (B, 1))
        tail = u[:, : N_CONTROLS * n].reshape(B, n, N_CONTROLS)  # a view of u
        per_group = a[:, : self.n_surface_actions].reshape(B, len(self.groups), len(self.surface_index))
        j = self.surface_index
        cmd = tail[:, :, j] + per_group[:, self._group_of] * self._half[:, j]
        tail[:, :, j] = np.clip(cmd, self._lo[:, j], self._hi[:, j])
        if self.torque:
            u[:, -1] = self.u_op[-1] + a[:, -1] * self.torque_half_range
        return u
