"""The winch of a pumping kite: its parameters (a :class:`~laddermill_gym.model.station.StationParams` with the
first element's fraction 1 and no transfers), a strict reader of the ``winch:`` section of a pumping config and
the packing into the kind marker (``kernels/winch.py``, slots ``SP_*`` of ``kernels/contract.py``).

The winch reuses the moving cable's station parameters and state block because its drum, commanded-speed and
schedule modes are the station's (same equations, same controls, same ``Assembly.station`` bookkeeping: state size,
control count, control labels and limits); what differs is the kind: only element 0 changes length (its rest
length is l_p + s, l_p the scene's length of element 0) and the drum feels T_0 alone (no hauled side).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.winch import Winch2D, Winch3D
from laddermill_gym.model.configio import ConfigError, Section
from laddermill_gym.model.params import N_CONTROLS, Assembly
from laddermill_gym.model.station import MODES, StationParams, station_slots

#: The first element's rest length is f l_p + s with f = 1 for a winch; ``last_fraction`` must pass the
#: station's check (> f) but no last element moves (kernels/winch.py).
_FIRST, _UNUSED_LAST = 1.0, 1.1


def winch_params(first_length: float, *, mode: str = "commanded", initial_speed: float = 0.0,
                 speed_times: tuple[float, ...] = (0.0,), speed_values: tuple[float, ...] | None = None,
                 drum_radius: float = 1.0, drum_inertia: float = 0.0,
                 torque_limits: tuple[float, float] = (0.0, 0.0), speed_time_constant: float = 1.0,
                 speed_limits: tuple[float, float] = (0.0, 0.0), efficiency: float = 1.0) -> StationParams:
    """A winch as station parameters.

    first_length : l_p [m], the unstretched length of element 0 when nothing is paid out (s = 0)
    mode : 'commanded' (V follows the commanded speed, a control), 'drum' (torque control) or 'prescribed'
    initial_speed : V at t = 0 [m/s] (drum, commanded); the schedule's first value when prescribed
    speed_times [s], speed_values [m/s] : the prescribed schedule V(t)
    drum_radius [m], drum_inertia [kg m^2], torque_limits [N m] : the drum (mode 'drum')
    speed_time_constant [s], speed_limits [m/s] : the speed controller (mode 'commanded')
    efficiency : electrical over mechanical power in both directions [-] (Lansdorp eq. 13's eta)
    """
    if mode not in MODES:
        raise ValueError(f"winch.mode = {mode!r}: must be one of {MODES}")
    values = (initial_speed,) if speed_values is None else tuple(speed_values)
    times = speed_times if speed_values is not None else (0.0,)
    return StationParams(piece_length=first_length, first_fraction=_FIRST, last_fraction=_UNUSED_LAST, mode=mode,
                         speed_times=tuple(times), speed_values=values, drum_radius=drum_radius,
                         drum_inertia=drum_inertia, torque_limits=tuple(torque_limits),
                         speed_time_constant=speed_time_constant, speed_limits=tuple(speed_limits),
                         efficiency=efficiency)


def read_winch(s: Section, first_length: float) -> StationParams:
    """The ``winch:`` section (errors name the file and field): mode, efficiency, initial_speed_m_s, and per mode
    drum_radius / drum_inertia / torque_limits, speed_time_constant / speed_limits, or speed_times_s / speed_m_s."""
    mode = s.text("mode", "commanded", choices=MODES)
    kw = dict(mode=mode, efficiency=s.number("efficiency", 1.0, positive=True),
              initial_speed=s.number("initial_speed_m_s", 0.0))
    if mode == "drum":
        kw.update(drum_radius=s.number("drum_radius", positive=True),
                  drum_inertia=s.number("drum_inertia", positive=True),
                  torque_limits=tuple(s.vector("torque_limits", 2)))
    elif mode == "commanded":
        kw.update(speed_time_constant=s.number("speed_time_constant", positive=True),
                  speed_limits=tuple(s.vector("speed_limits", 2)))
        low, high = kw["speed_limits"]
        if not low <= kw["initial_speed"] <= high:  # the first command is the initial speed: refused at the build
            raise s.error("initial_speed_m_s", kw["initial_speed"], f"must lie within speed_limits [{low}, {high}] "
                                                                      "m/s (the winch's first command)")
    else:
        kw.update(speed_times=tuple(s.vector("speed_times_s")), speed_values=tuple(s.vector("speed_m_s")))
    s.done()
    try:
        return winch_params(first_length, **kw)
    except ValueError as err:
        raise ConfigError(f"{s.file}: {err}") from None


def with_winch(asm: Assembly, winch: StationParams) -> Assembly:
    """The assembly with its tether's ground end on ``winch`` (checked: one free-ended tether from a ground point,
    element 0 starting there, and ``winch.piece_length`` equal to element 0's length)."""
    if asm.station is not None and not is_winch(asm.station):
        raise ValueError("with_winch: the assembly already has a moving-cable station")
    el = asm.elements
    if el.end_kind[0][0] != C.END_FIXED:
        raise ValueError("with_winch: element 0 must start at a ground point (the winch)")
    if int(np.sum(np.asarray(el.end_kind) == C.END_FIXED)) != 1:
        raise ValueError("with_winch: a winch needs a tether with one ground end (chain 'end: null')")
    if abs(el.l0[0] - winch.piece_length) > 1e-9 * winch.piece_length:
        raise ValueError(f"with_winch: winch first length {winch.piece_length} m != element 0's {el.l0[0]} m")
    return dataclasses.replace(asm, station=winch)


def is_winch(st: StationParams | None) -> bool:
    """Whether station parameters describe a winch (first fraction 1, the placeholder last fraction)."""
    return st is not None and st.first_fraction == _FIRST and st.last_fraction == _UNUSED_LAST


def pack_winch(st: StationParams, state_offset: int, control_offset: int) -> np.ndarray:
    """The winch's slots (``SP_*``): l_p, f = 1, the offsets of its state block and control, mode, drum, tau and
    the schedule."""
    return station_slots(st, state_offset, control_offset)


def winch_kind(asm: Assembly):
    """The kind marker (``Winch3D`` / ``Winch2D``) of an assembly with a winch (:func:`with_winch`)."""
    if not is_winch(asm.station):
        raise ValueError("winch_kind: the assembly has no winch (use with_winch)")
    sp = pack_winch(asm.station, asm.body_state_size, N_CONTROLS * asm.n_wings)
    return Winch3D(sp) if asm.dim == 3 else Winch2D(sp)
