"""The ground station of the moving cable (Meijaard et al. 1999, "Boundary conditions"): typed parameters and
their packing into the kind marker's ``station`` array (slots ``SP_*`` of ``kernels/contract.py``).

Both cable ends are fixed points at the generator. The first element (from the veered-side ground point up to
wing slot 0) and the last element (from wing slot n-1 down to the hauled-side ground point) change their
unstretched length at the cable speed V_c; when the cable has moved one piece length a wing is transferred
(``kernels/moving_cable.py``). The generator either holds a prescribed speed schedule V_c(t) or is a drum
whose speed is a state, driven by the tension difference against the generator torque (a control input).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels import contract as C

MODES = ("prescribed", "drum", "commanded")
#: Insertion rules of a transferred wing (``station.insertion``): "paper" (Meijaard et al. 1999: position and
#: velocity interpolated between the ground point at rest and the neighbour's attachment) or "cable" (the velocity
#: interpolated between the cable's own velocity at the ground point, V_c l / l0 along the element, and the
#: neighbour's: the new wing moves with the cable it joins). docs/moving_cable.md, "Wing transfer".
INSERTIONS = ("paper", "cable")


@dataclass(frozen=True)
class StationParams:
    """Ground station of the moving cable.

    piece_length : l0 [m], the cable between two wings.
    first_fraction, last_fraction : unstretched lengths of the first (veered) and last (hauled) elements as
        fractions of l0 right after a transfer [-]; Meijaard: 1/10 and 11/10.
    mode : 'prescribed' (the generator holds V_c(t)), 'drum' (V_c is a state driven by the tension difference
        against the generator torque, a control) or 'commanded' (V_c is a state that follows a commanded speed, a
        control: dV_c/dt = (V_cmd - V_c) / tau, the generator's speed controller; the drum's inertia is then the
        controller's business and the generator takes P = (T_first - T_last) V_c).
    speed_times [s], speed_values [m/s] : piecewise-linear schedule V_c(t), held constant outside; with a drum
        only ``speed_values[0]`` is used, as the initial speed.
    drum_radius [m], drum_inertia [kg m^2] : the drum (and generator rotor) the cable drives; its equation is
        (J / r^2) dV_c/dt = T_first - T_last - Q / r with the generator torque Q [N m] (a control input).
    torque_limits : (min, max) generator torque [N m] accepted as a control.
    speed_time_constant : tau [s] of the commanded-speed mode.  speed_limits : (min, max) commanded speed [m/s].
    efficiency : electrical over mechanical generator power [-].
    insertion : the transferred wing's velocity rule, one of :data:`INSERTIONS` ("paper": the paper's
        interpolation from the ground point at rest; "cable": it moves with the cable it joins).
    """

    piece_length: float
    first_fraction: float = 0.1
    last_fraction: float = 1.1
    mode: str = "prescribed"
    speed_times: tuple[float, ...] = (0.0,)
    speed_values: tuple[float, ...] = (0.0,)
    drum_radius: float = 1.0
    drum_inertia: float = 0.0
    torque_limits: tuple[float, float] = (0.0, 0.0)
    speed_time_constant: float = 1.0
    speed_limits: tuple[float, float] = (0.0, 0.0)
    efficiency: float = 1.0
    insertion: str = "paper"

    def __post_init__(self):
        def bad(field, value, why):
            raise ValueError(f"station.{field} = {value!r}: {why}")

        if not (math.isfinite(self.piece_length) and self.piece_length > 0):
            bad("piece_length", self.piece_length, "must be a finite length > 0 m")
        if not 0 < self.first_fraction < self.last_fraction:
            bad("first_fraction", self.first_fraction, f"must be in (0, last_fraction = {self.last_fraction})")
        if not self.last_fraction > 1.0:
            bad("last_fraction", self.last_fraction, "must be > 1 (the hauled element absorbs one piece)")
        if self.mode not in MODES:
            bad("mode", self.mode, f"must be one of {MODES}")
        t = np.asarray(self.speed_times, float)
        v = np.asarray(self.speed_values, float)
        if t.ndim != 1 or t.shape != v.shape or t.size < 1:
            bad("speed_times", self.speed_times, f"need one time per speed value ({len(self.speed_values)})")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))):
            bad("speed_values", self.speed_values, "times and speeds must be finite")
        if np.any(np.diff(t) <= 0):
            bad("speed_times", self.speed_times, "must increase strictly")
        if self.mode == "drum":
            if not (self.drum_radius > 0 and math.isfinite(self.drum_radius)):
                bad("drum_radius", self.drum_radius, "must be a finite radius > 0 m")
            if not (self.drum_inertia > 0 and math.isfinite(self.drum_inertia)):
                bad("drum_inertia", self.drum_inertia, "must be a finite inertia > 0 kg m^2 with a drum")
            lo, hi = self.torque_limits
            if not (math.isfinite(lo) and math.isfinite(hi) and lo <= hi):
                bad("torque_limits", self.torque_limits, "need finite min <= max [N m]")
        if self.mode == "commanded":
            if not (self.speed_time_constant > 0 and math.isfinite(self.speed_time_constant)):
                bad("speed_time_constant", self.speed_time_constant, "must be a finite time > 0 s")
            lo, hi = self.speed_limits
            if not (math.isfinite(lo) and math.isfinite(hi) and lo <= hi):
                bad("speed_limits", self.speed_limits, "need finite min <= max [m/s]")
        if not 0 < self.efficiency <= 1:
            bad("efficiency", self.efficiency, "must be in (0, 1]")
        if self.insertion not in INSERTIONS:
            bad("insertion", self.insertion, f"must be one of {INSERTIONS}")

    @property
    def n_controls(self) -> int:
        """Controls the station adds after the wings' (the generator torque of a drum, or the commanded speed)."""
        return 0 if self.mode == "prescribed" else 1

    def speed(self, t: float) -> float:
        """The scheduled cable speed V_c(t) [m/s] (numpy; the kernel evaluates the same schedule)."""
        return float(np.interp(t, self.speed_times, self.speed_values))


def pack_station(st: StationParams, n_elements: int, state_offset: int, control_offset: int) -> np.ndarray:
    """The station's slots (``SP_*``) for a cable whose station state block starts at ``state_offset`` and generator
    torque (drum) at ``control_offset``. The kernels take element 0 as the first and element n_e - 1 as the last
    (``n_elements`` is checked: at least two)."""
    if n_elements < 2:
        raise ValueError(f"a moving cable needs at least two elements, got {n_elements}")
    return station_slots(st, state_offset, control_offset)


def station_slots(st: StationParams, state_offset: int, control_offset: int) -> np.ndarray:
    """The ``SP_*`` slots of station parameters (the moving cable's or a winch's): piece length and fractions, the
    offsets of the state block and the control, mode, drum, tau and the schedule."""
    n = len(st.speed_times)
    p = np.zeros(C.SP_SCHED + 2 * n)
    p[C.SP_PIECE], p[C.SP_F_FIRST], p[C.SP_F_LAST] = st.piece_length, st.first_fraction, st.last_fraction
    p[C.SP_XOFF] = state_offset
    p[C.SP_MODE] = {"prescribed": C.MODE_PRESCRIBED, "drum": C.MODE_DRUM, "commanded": C.MODE_COMMANDED}[st.mode]
    p[C.SP_RADIUS], p[C.SP_INERTIA], p[C.SP_UOFF] = st.drum_radius, st.drum_inertia, control_offset
    p[C.SP_TAU] = st.speed_time_constant
    p[C.SP_INSERT] = C.INSERT_CABLE if st.insertion == "cable" else C.INSERT_PAPER
    p[C.SP_NSCHED] = n
    p[C.SP_SCHED:C.SP_SCHED + n] = st.speed_times
    p[C.SP_SCHED + n:] = st.speed_values
    return p


def station_initial(st: StationParams) -> np.ndarray:
    """The station block of an initial state (``SX_*``): nothing moved, no transfer, the schedule's speed at
    t = 0 (or the drum's or commanded mode's initial speed, ``speed_values[0]``), no energy."""
    x = np.zeros(C.SX_SIZE)
    x[C.SX_SPEED] = st.speed(0.0) if st.mode == "prescribed" else float(st.speed_values[0])
    return x


def station_initial_controls(st: StationParams) -> np.ndarray:
    """The station's controls at the start, shape (``st.n_controls``,): a commanded station commands its initial speed
    ``speed_values[0]`` [m/s] (the reader keeps it within ``speed_limits``); a drum's generator torque [N m] starts
    at 0, or at the end of ``torque_limits`` nearest 0 when they exclude it; nothing for a prescribed schedule."""
    if st.mode == "commanded":
        return np.array([float(st.speed_values[0])])
    if st.mode == "drum":
        return np.array([min(max(0.0, st.torque_limits[0]), st.torque_limits[1])])
    return np.zeros(0)


def electrical_power(mechanical, efficiency: float):
    """The generator's electrical power [W] from the mechanical power the cable delivers to it [W] (a float or an
    array of any shape): ``efficiency`` times it while generating, divided by ``efficiency`` while motoring
    (mechanical power below 0: the machine then draws more than it gives the cable). Applied to a mean over an
    interval, exact while the mechanical power keeps its sign over it."""
    if isinstance(mechanical, np.ndarray):
        return np.where(mechanical >= 0.0, efficiency * mechanical, mechanical / efficiency)
    return efficiency * mechanical if mechanical >= 0.0 else mechanical / efficiency
