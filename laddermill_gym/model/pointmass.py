"""Parameters of the point-mass fidelity (Podgaets & Ockels 2007) and their packing for
``kernels/pointmass/``: a string of ``n_nodes`` equal elements from a start anchor (and optionally to an end
anchor) carrying point-mass kites on given nodes, plus the quasi-static start of a kite chain."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from laddermill_gym.atmosphere.field import pack_wind_field
from laddermill_gym.kernels import contract as P
from laddermill_gym.kernels.contract import N3_SIZE, PMModel, PMWork
from laddermill_gym.kernels.pointmass import partitioned as PT
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.packing import wind_fields
from laddermill_gym.model.params import AERO_INDEX, WindParams, WingType

#: Nodes per segment of the checkpointed block elimination (``kernels/pointmass/implicit.py``).
SOLVER_SEGMENT = 1024


@dataclass(frozen=True)
class PointMassKite:
    """A kite as a point mass: mass [kg], wing area [m^2], lift and drag coefficients [-] on the uniform
    grid ``alpha`` [rad] (from -pi to pi)."""

    name: str
    mass: float
    area: float
    alpha: np.ndarray
    cl: np.ndarray
    cd: np.ndarray

    @classmethod
    def from_wing(cls, wt: WingType) -> PointMassKite:
        """The point-mass kite of a rigid wing type: its mass, area and the C_L, C_D columns of its table
        (controls at zero: the tail's contribution at its rigging angle)."""
        if wt.aero is None:
            raise ValueError(f"wing type {wt.name!r} has no aerodynamic table")
        v = wt.aero.values
        return cls(name=wt.name, mass=wt.mass, area=wt.area, alpha=np.asarray(wt.aero.alpha, dtype=float),
                   cl=np.ascontiguousarray(v[:, AERO_INDEX["CL"]]), cd=np.ascontiguousarray(v[:, AERO_INDEX["CD"]]))


@dataclass(frozen=True)
class PointMassString:
    """An elastic string of ``n_nodes`` free nodes on elements of unstretched length ``element_length`` [m]
    from ``anchor`` [m] (and to ``end`` [m] when not None), kites on ``kite_nodes`` (ascending)."""

    wind: WindParams
    gravity: float
    cable: CableSpec
    element_length: float
    n_nodes: int
    anchor: np.ndarray
    end: np.ndarray | None = None
    kite: PointMassKite | None = None
    kite_nodes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    ground_height: float = -math.inf
    max_speed: float = 1.0e3

    def __post_init__(self):
        kn = np.asarray(self.kite_nodes, dtype=np.int64)
        if self.n_nodes < 1:
            raise ValueError(f"n_nodes = {self.n_nodes}: must be >= 1")
        if kn.size and (self.kite is None or np.any(np.diff(kn) <= 0) or kn[0] < 0 or kn[-1] >= self.n_nodes):
            raise ValueError("kite_nodes must be ascending node indices below n_nodes, with a kite type")
        object.__setattr__(self, "kite_nodes", kn)

    @property
    def n_kites(self) -> int:
        return int(self.kite_nodes.size)

    @property
    def n_elements(self) -> int:
        return self.n_nodes + (self.end is not None)

    @property
    def state_size(self) -> int:
        return N3_SIZE * self.n_nodes


def pack(s: PointMassString) -> PMModel:
    """The packed model (``kernels/contract.py``, point-mass section)."""
    c = s.cable
    par = np.zeros(P.PP_SIZE)
    par[P.PP_GRAVITY], par[P.PP_L0], par[P.PP_MU] = s.gravity, s.element_length, c.mass_per_length
    par[P.PP_EA], par[P.PP_DA], par[P.PP_DIAM] = c.EA, c.DA, c.diameter
    par[P.PP_CN0], par[P.PP_CT0], par[P.PP_N] = c.cn0, c.ct0, s.n_nodes
    par[P.PP_END_FIXED] = 0.0 if s.end is None else 1.0
    par[P.PP_ANCHOR:P.PP_ANCHOR + 3] = s.anchor
    par[P.PP_END:P.PP_END + 3] = s.anchor if s.end is None else s.end
    par[P.PP_GROUND], par[P.PP_MAX_SPEED] = s.ground_height, s.max_speed
    par[P.PP_L_FIRST], par[P.PP_L_LAST] = s.element_length, s.element_length  # a moving cable resets these
    kt = np.zeros(P.KT_SIZE)
    if s.kite is not None:
        a = s.kite.alpha
        step = np.diff(a)
        if np.ptp(step) > 1e-9 or abs(a[0] + math.pi) > 1e-9 or abs(a[-1] - math.pi) > 1e-9:
            raise ValueError(f"kite {s.kite.name!r}: alpha grid must be uniform from -pi to pi")
        kt[P.KT_MASS], kt[P.KT_AREA], kt[P.KT_ALPHA0], kt[P.KT_DALPHA] = s.kite.mass, s.kite.area, a[0], step[0]
        kcl, kcd = s.kite.cl, s.kite.cd
    else:
        kcl, kcd = np.zeros(2), np.zeros(2)
    kflag = np.zeros(s.n_nodes, dtype=np.uint8)
    kflag[s.kite_nodes] = 1
    tmod, ms, md, gp, gv = pack_wind_field(s.wind.field)
    knode = s.kite_nodes if s.kite_nodes.size else np.full(1, -1, dtype=np.int64)
    return PMModel(wf=wind_fields(s.wind), tmod=tmod, ms=ms, md=md, gp=gp, gv=gv, par=par,
                   knode=np.ascontiguousarray(knode), kflag=kflag, kt=kt,
                   kcl=np.ascontiguousarray(kcl, dtype=float), kcd=np.ascontiguousarray(kcd, dtype=float))


def make_work(s: PointMassString, segment: int = SOLVER_SEGMENT, parts: int | None = None) -> PMWork:
    """The workspace: tensions (n_e,) and, for the partitioned elimination on up to ``parts`` chunks (default:
    numba's thread count, capped at one chunk per ``MIN_PART`` nodes and at least 2; ``kernels/pointmass/
    partitioned.py``), checkpoints (n / seg + parts + 1, 15), one segment per chunk (parts, seg, 9) and the
    chunks' and separators' data (parts, 48). seg = min(segment, sqrt(n)) (at least 64) keeps the checkpoints
    and buffers small (1 MB at 500,000 nodes and 16 parts); it depends on n only, because a middle chunk's
    spike restarts at every checkpoint (roundoff-level changes with seg from three chunks on)."""
    if parts is None:
        parts = min(numba.config.NUMBA_NUM_THREADS, s.n_nodes // PT.MIN_PART)
    parts = max(2, int(parts))
    seg = max(1, min(int(segment), s.n_nodes, max(64, math.isqrt(s.n_nodes))))
    rows = (s.n_nodes + seg - 1) // seg + parts + 1
    return PMWork(tension=np.zeros(s.n_elements), ckpt=np.zeros((rows, P.CKPT_COLS)),
                  seg=np.zeros((parts, seg, P.BUF_COLS)), mid=np.zeros((parts, P.MID_COLS)))


def held_bytes(M: PMModel, W: PMWork, x: np.ndarray, u: np.ndarray) -> dict[str, int]:
    """Bytes of every array the simulation holds: state, controls, workspace and packed parameters."""
    params = sum(a.nbytes for a in M if isinstance(a, np.ndarray))
    work = sum(a.nbytes for a in W)
    out = {"state": int(x.nbytes), "controls": int(u.nbytes), "workspace": int(work), "parameters": int(params)}
    out["total"] = sum(out.values())
    return out


def attitude_controls(n_kites: int, roll: float, pitch: float, yaw: float) -> np.ndarray:
    """Controls (n_k * 3,) [rad] giving every kite the same commanded roll, pitch, yaw."""
    u = np.zeros((max(1, n_kites), P.PU_SIZE))
    u[:, P.PU_ROLL], u[:, P.PU_PITCH], u[:, P.PU_YAW] = roll, pitch, yaw
    return u.ravel()
