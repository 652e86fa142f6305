"""The reeling multi-element tether of a winch (``kernels/reel.py``): its parameters, the strict reader of a
pumping config's ``reeling:`` section, the assembly with the reeling tether and the packing into the kind marker.

The winch's station parameters (``model/winch.py``) become a :class:`ReelStation`: the same winch (mode, speeds,
efficiency; ``piece_length`` is the drum element's rest length at t = 0) plus the nominal element length, the split
and merge thresholds, the nodes in the air at t = 0 and the ground contact of a tether node. ``model.packing``
gives an assembly whose station is a ``ReelStation`` the kind ``ReelWinch3D``.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.reel import ReelWinch3D
from laddermill_gym.model.configio import ConfigError, Section
from laddermill_gym.model.params import N_CONTROLS, Assembly
from laddermill_gym.model.station import StationParams, station_slots


@dataclass(frozen=True)
class ReelSpec:
    """The reeling tether of a pumping config (``reeling:`` section).

    element_length [m] : l_n, the nominal element length (the start tether in whole elements of about l_n).
    max_length [m] : the longest tether the element chain carries in elements of l_n (the drum element grows
        beyond it without splitting).
    split_fraction, merge_fraction [-] : split the drum element at split_fraction l_n (default 1.75), merge it below
        merge_fraction l_n (0.5); split_fraction - 1 > merge_fraction, so that a split is not undone at once.
    contact_frequency [rad/s], contact_damping_ratio [-] : the ground's penalty spring on a node's lumped mass m:
        stiffness m omega^2, damping 2 zeta m omega (a node resting on the ground sinks g / omega^2).
    friction [-], slip_speed [m/s] : Coulomb friction coefficient of a node on the ground, viscous below the slip
        speed.
    dt [s] : the RK4 step of the reeling scene (None: the scene's); :func:`stable_dt` gives the rule.
    """

    element_length: float
    max_length: float
    split_fraction: float = 1.75
    merge_fraction: float = 0.5
    contact_frequency: float = 20.0
    contact_damping_ratio: float = 1.0
    friction: float = 0.5
    slip_speed: float = 0.1
    dt: float | None = None

    def __post_init__(self):
        for name in ("element_length", "max_length", "contact_frequency", "slip_speed"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"reeling.{name} = {v!r}: must be a finite number > 0")
        if self.dt is not None and not (math.isfinite(self.dt) and self.dt > 0):
            raise ValueError(f"reeling.dt_s = {self.dt!r}: must be a finite step > 0 s")
        for name in ("contact_damping_ratio", "friction"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v >= 0):
                raise ValueError(f"reeling.{name} = {v!r}: must be a finite number >= 0")
        if not 0 < self.merge_fraction < self.split_fraction - 1.0:
            raise ValueError(f"reeling.merge_fraction = {self.merge_fraction!r}: must be in (0, split_fraction - 1 "
                             f"= {self.split_fraction - 1.0!r}) (a split must not be undone at once)")

    def layout(self, start_length: float) -> tuple[int, int, float]:
        """(elements in all, nodes in the air at t = 0, the drum element's rest length l_p [m]) for a tether of
        ``start_length`` [m]: the start in n elements, the upper n - 1 of l_n and the drum element l_p in
        (merge_fraction, merge_fraction + 1] l_n (n at least two); in all the elements of ``max_length`` in l_n
        (at least the start's)."""
        ln = self.element_length
        n_air = max(2, int(math.ceil((start_length - self.merge_fraction * ln) / ln - 1e-9)))
        lp = start_length - (n_air - 1) * ln
        if not lp > self.merge_fraction * ln:
            raise ValueError(f"reeling.element_length = {ln!r}: the start tether ({start_length} m) leaves a drum "
                             f"element of {lp} m, not above merge_fraction l_n")
        total = max(n_air, int(math.ceil(self.max_length / ln - 1e-9)))
        return total, n_air - 1, lp


def stable_dt(element_length: float, EA: float, mu: float, steps=(0.005, 0.0025, 0.002, 0.001, 0.0005)) -> float:
    """The largest of ``steps`` [s] (divisors of the envs' 0.05 s control period) at which RK4 resolves the highest
    axial mode of a taut chain of elements of ``element_length`` [m] with consistent mass: omega_max = (2 / l)
    sqrt(3 EA / mu) (alternate nodes moving apart: stiffness 4 EA / l against the mass mu l / 3), omega_max dt <= 2
    (RK4's stability limit on the imaginary axis is 2.83). Raises ValueError below the smallest step."""
    limit = 2.0 / (2.0 / element_length * math.sqrt(3.0 * EA / mu))
    for dt in steps:
        if dt <= limit:
            return dt
    raise ValueError(f"stable_dt: elements of {element_length} m need a step below {limit:.2e} s")


@dataclass(frozen=True)
class ReelStation(StationParams):
    """A winch (``model.winch.winch_params``) with a reeling tether: ``reel`` the spec, ``nodes_in_air`` the free
    nodes in the air at t = 0, ``ground_height`` [m] the ground of the node contact."""

    reel: ReelSpec | None = None
    nodes_in_air: int = 1
    ground_height: float = 0.0


def read_reeling(s: Section) -> ReelSpec:
    """The ``reeling:`` section (errors name the file and field): element_length_m, max_length_m, split_fraction,
    merge_fraction, contact_frequency_rad_s, contact_damping_ratio, friction, slip_speed_m_s."""
    kw = dict(element_length=s.number("element_length_m", positive=True),
              max_length=s.number("max_length_m", positive=True),
              split_fraction=s.number("split_fraction", 1.75, positive=True),
              merge_fraction=s.number("merge_fraction", 0.5, positive=True),
              contact_frequency=s.number("contact_frequency_rad_s", 20.0, positive=True),
              contact_damping_ratio=s.number("contact_damping_ratio", 1.0),
              friction=s.number("friction", 0.5),
              slip_speed=s.number("slip_speed_m_s", 0.1, positive=True),
              dt=s.number("dt_s", None, positive=True))
    s.done()
    try:
        return ReelSpec(**kw)
    except ValueError as err:
        raise ConfigError(f"{s.file}: {err}") from None


def with_reel(asm: Assembly, winch: StationParams, spec: ReelSpec, ground_height: float) -> Assembly:
    """The assembly ``asm`` (a chain from one ground point to one wing, with every element of its
    ``layout(...)[0]`` elements) with the winch ``winch`` (its ``piece_length`` is replaced by the drum element's
    start length) on a reeling tether: the elements above the drum element l_n long."""
    el = asm.elements
    start = float(np.sum(el.l0))
    total, air, lp = spec.layout(start)
    if el.count != total or asm.n_nodes != total - 1 or asm.n_wings != 1:
        raise ValueError(f"with_reel: need one wing on a chain of {total} elements, got {asm.n_wings} wings and "
                         f"{el.count} elements")
    if el.end_kind[0][0] != C.END_FIXED:
        raise ValueError("with_reel: element 0 must start at a ground point (the winch)")
    l0 = np.full(total, spec.element_length)
    elements = dataclasses.replace(el, l0=l0)
    fields = {f.name: getattr(winch, f.name) for f in dataclasses.fields(StationParams)}
    fields["piece_length"] = lp
    station = ReelStation(**fields, reel=spec, nodes_in_air=air, ground_height=float(ground_height))
    return dataclasses.replace(asm, elements=elements, station=station)


def is_reel(st: StationParams | None) -> bool:
    """Whether station parameters describe a winch with a reeling tether."""
    return isinstance(st, ReelStation)


def pack_reel(st: ReelStation) -> np.ndarray:
    """The reel's slots (``RL_*``)."""
    r = st.reel
    p = np.zeros(C.RL_SIZE)
    p[C.RL_LNOM], p[C.RL_SPLIT], p[C.RL_MERGE] = r.element_length, r.split_fraction, r.merge_fraction
    p[C.RL_ACTIVE0] = st.nodes_in_air
    p[C.RL_OMEGA], p[C.RL_ZETA] = r.contact_frequency, r.contact_damping_ratio
    p[C.RL_MU], p[C.RL_VSLIP], p[C.RL_GROUND] = r.friction, r.slip_speed, st.ground_height
    return p


def reel_kind(asm: Assembly) -> ReelWinch3D:
    """The kind marker of an assembly with a reeling winch (:func:`with_reel`)."""
    if not is_reel(asm.station) or asm.dim != 3:
        raise ValueError("reel_kind: a 3D assembly with a reeling winch (with_reel) is needed")
    sp = station_slots(asm.station, asm.body_state_size, N_CONTROLS * asm.n_wings)
    return ReelWinch3D(sp, pack_reel(asm.station))


def nodes_in_air(asm: Assembly, x: np.ndarray) -> int:
    """Free nodes in the air in state ``x`` (the start's plus those paid out, ``SX_TRANSFERS``)."""
    return station_nodes_in_air(asm.station, x, asm.body_state_size)


def station_nodes_in_air(st: ReelStation, x: np.ndarray, xoff: int) -> int:
    """:func:`nodes_in_air` from the station ``st`` and its state entries at ``xoff``."""
    return int(st.nodes_in_air + round(float(x[xoff + C.SX_TRANSFERS])))


def drum_rest_length(st: ReelStation, x: np.ndarray, xoff: int) -> float:
    """Rest length l_d [m] of the drum element, l_p + s - m l_n (``kernels/reel.drum_rest_length``), from the
    station ``st`` and its state entries at ``xoff``."""
    return float(st.piece_length + x[xoff + C.SX_MOVED] - x[xoff + C.SX_TRANSFERS] * st.reel.element_length)


def ground_contacts(asm: Assembly, x: np.ndarray) -> int:
    """Nodes in the air at or below the ground in state ``x`` (touching: the ground pushes them up)."""
    n = asm.n_nodes
    k = n - nodes_in_air(asm, x)
    base = C.B3_SIZE * asm.n_wings
    z = x[base + C.N3_SIZE * np.arange(k, n) + C.N3_POS + 2]
    return int(np.sum(-z <= asm.station.ground_height))
