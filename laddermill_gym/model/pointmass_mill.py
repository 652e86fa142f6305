"""The ground station of the moving cable at the point-mass fidelity (docs/pointmass.md, "The moving cable"):
its parameters, the layout of kites and nodes on the string, and the packing for ``kernels/pointmass/mill.py``.

Layout (:func:`mill_layout`). The rigid mill has one element per piece l0: the first element f_first l0 + S, the
last f_last l0 - S (S in [0, l0)), wings l0 apart. At the point-mass fidelity every piece holds p = l0 / l_e
elements, the loop holds n = n_k p nodes (kites every p nodes, so the kite leaving at the hauled end re-enters at
the veered end one piece behind the first kite), the first element a + s and the last b - s with s in [0, l_e).
a = f_first l0 and b = f_last l0 - (p - 1) l_e = (f_last - 1) l0 + l_e: the string between the two ground points
holds the rigid mill's cable, the kites sit where its wings sit along it, a kite leaves the string (f_last - 1) l0
from the hauled ground point and enters f_first l0 from the veered one at the rigid mill's transfer instants, and
the end elements are as long as the rigid mill's shortest (7-8 m for the paper's mill at any l_e). One element per
piece (p = 1) is exactly the rigid layout. (A first kite deeper in the string, with end elements near l_e, lets a
kite enter 1 m from the ground point at 1 m elements: it swings round the ground point under its lift and the
mill broke down 35 s after its start.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.pointmass.mill import MX_SIZE
from laddermill_gym.model.station import INSERTIONS, StationParams


@dataclass(frozen=True)
class PointMassStation:
    """The moving cable's station at the point-mass fidelity.

    element_length : l_e [m], the cable moved between two node transfers.
    first_length, last_length : a, b [m], the first (veered) and last (hauled) elements' unstretched lengths right
        after a transfer (a + s and b - s in between, s the cable moved since).
    speed_times [s], speed_values [m/s] : the prescribed piecewise-linear schedule V_c(t), held outside.
    efficiency : electrical over mechanical generator power [-].
    insertion : a transferred node's velocity rule (``model.station.INSERTIONS``): "cable" (it moves with the
        cable it joins, the point-mass mill's default) or "paper" (interpolated from the ground point at rest).
    """

    element_length: float
    first_length: float
    last_length: float
    speed_times: tuple[float, ...] = (0.0,)
    speed_values: tuple[float, ...] = (0.0,)
    efficiency: float = 1.0
    insertion: str = "cable"

    def __post_init__(self):
        def bad(field, value, why):
            raise ValueError(f"station.{field} = {value!r}: {why}")

        if self.insertion not in INSERTIONS:
            bad("insertion", self.insertion, f"must be one of {INSERTIONS}")
        le = self.element_length
        if not (math.isfinite(le) and le > 0):
            bad("element_length", le, "must be a finite length > 0 m")
        t = np.asarray(self.speed_times, float)
        v = np.asarray(self.speed_values, float)
        if t.ndim != 1 or t.shape != v.shape or t.size < 1:
            bad("speed_times", self.speed_times, f"need one time per speed value ({len(self.speed_values)})")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v))) or np.any(np.diff(t) <= 0):
            bad("speed_times", self.speed_times, "times and speeds must be finite, times strictly increasing")
        # s stays in [0, l_e) between steps: a + s > 0 needs a > 0; b - s > 0, and a node inserted backwards at
        # b - s - l_e from the hauled ground point (s < 0), need b >= l_e once the cable moves
        need_b = le if np.any(v != 0) else 0.0
        if not (math.isfinite(self.first_length) and self.first_length > 0):
            bad("first_length", self.first_length, "must be a finite length > 0 m")
        if not (math.isfinite(self.last_length) and self.last_length > 0 and self.last_length >= need_b):
            bad("last_length", self.last_length, f"must be > 0 m (and >= l_e = {le} m for a moving cable)")
        if not 0 < self.efficiency <= 1:
            bad("efficiency", self.efficiency, "must be in (0, 1]")

    def speed(self, t: float) -> float:
        """The scheduled cable speed V_c(t) [m/s]."""
        return float(np.interp(t, self.speed_times, self.speed_values))


@dataclass(frozen=True)
class MillLayout:
    """Nodes and kites of the point-mass mill: n_nodes, kite_nodes (n_k,), the first kite's node j0 and a, b [m]."""

    n_nodes: int
    kite_nodes: np.ndarray
    first_node: int
    first_length: float
    last_length: float


def mill_layout(n_kites: int, piece: float, element_length: float, first_fraction: float,
                last_fraction: float) -> MillLayout:
    """The layout that holds the rigid mill's cable between the ground points (module docstring); ``piece`` l0
    must be a whole number of elements l_e."""
    per = piece / element_length
    if abs(per - round(per)) > 1e-6 * per or round(per) < 1:
        raise ValueError(f"element_length = {element_length!r} m must divide the piece length {piece} m into whole "
                         "elements")
    per = int(round(per))
    a = first_fraction * piece
    b = last_fraction * piece - (per - 1) * element_length
    kn = per * np.arange(n_kites, dtype=np.int64)
    return MillLayout(n_nodes=n_kites * per, kite_nodes=kn, first_node=0, first_length=a, last_length=b)


def station_from_rigid(st: StationParams, layout: MillLayout, element_length: float) -> PointMassStation:
    """The point-mass station of a rigid scene's ``station:`` section (prescribed speed only)."""
    if st.mode != "prescribed":
        raise ValueError(f"station.mode = {st.mode!r}: the point-mass mill has the prescribed speed schedule only")
    return PointMassStation(element_length=element_length, first_length=layout.first_length,
                            last_length=layout.last_length, speed_times=tuple(st.speed_times),
                            speed_values=tuple(st.speed_values), efficiency=st.efficiency,
                            insertion=st.insertion)


def pack_pm_station(st: PointMassStation) -> np.ndarray:
    """The station array of ``kernels/pointmass/mill.py`` (``SP_*`` slots: l_e, a / l_e, b / l_e, schedule)."""
    n = len(st.speed_times)
    p = np.zeros(C.SP_SCHED + 2 * n)
    p[C.SP_PIECE] = st.element_length
    p[C.SP_F_FIRST] = st.first_length / st.element_length
    p[C.SP_F_LAST] = st.last_length / st.element_length
    p[C.SP_MODE] = C.MODE_PRESCRIBED
    p[C.SP_INSERT] = C.INSERT_CABLE if st.insertion == "cable" else C.INSERT_PAPER
    p[C.SP_NSCHED] = n
    p[C.SP_SCHED:C.SP_SCHED + n] = st.speed_times
    p[C.SP_SCHED + n:] = st.speed_values
    return p


def station_state(st: PointMassStation, t0: float = 0.0, moved: float = 0.0) -> np.ndarray:
    """The station state (``MX_SIZE``,): cable moved [m], no transfers, V_c(t0) [m/s], no energy."""
    sx = np.zeros(MX_SIZE)
    sx[C.SX_MOVED], sx[C.SX_SPEED] = moved, st.speed(t0)
    return sx
