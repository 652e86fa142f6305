"""The wind's variation in time and space on top of the steady profile: one object, :class:`WindField`, set the
same way on a single simulator (:meth:`laddermill_gym.sim.simulator.Simulator.set_wind`), on one copy of a batch
(:meth:`laddermill_gym.sim.batch.BatchSimulator.set_wind`) or at build time (:meth:`WindParams.with_field
<laddermill_gym.model.params.WindParams.with_field>`).

A field has two parts (formulas in ``kernels/wind.py``):

* a **time modulation** of the profile: a speed factor s(t) [-] and a direction offset delta(t) [rad], sampled
  on the grid t0 + k dt and interpolated linearly (the disturbances of ``atmosphere/disturbances.py``);
* an optional **frozen gust grid** (:class:`GustGrid`): three velocity components (u downwind, v to the right
  looking downwind, w up) [m/s] on a regular grid over the along-wind coordinate xi [m] and the height h [m],
  advected downwind at a constant speed (Taylor's hypothesis), so wings and cable points at different heights
  and along-wind places meet different, partly coherent gusts. The kernels interpolate it bilinearly and use
  its time derivative along each wing's path in the alpha-rate term.

Pure numpy; the packed form follows the ``TM_*``, ``GP_*`` and ``GV_*`` slots of ``kernels/contract.py``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from laddermill_gym.kernels import contract as C

__all__ = ["GridGeometry", "GustGrid", "WindField", "pack_wind_field", "sum_grids", "union_geometry"]


def _finite(name: str, value, positive: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"{name} = {value!r}: must be a number")
    v = float(value)
    if not math.isfinite(v) or (positive and not v > 0):
        raise ValueError(f"{name} = {value!r}: must be a finite number{' > 0' if positive else ''}")
    return v


@dataclass(frozen=True, eq=False)
class GustGrid:
    """A frozen three-component gust field on a regular (xi, h) grid, advected downwind.

    Attributes
    ----------
    values : ndarray, shape (n_xi, n_h, 3)
        Gust velocity [m/s] at xi = xi0 + i dxi, h = h0 + j dh: components u (downwind), v (to the right
        looking downwind), w (up). Outside the grid the edge values hold.
    xi0, dxi : float
        Along-wind coordinate of the first column [m] and the column spacing [m] (> 0). xi = p . e - U t for a
        point p, e the downwind unit vector (``heading``), U the advection speed.
    h0, dh : float
        Height of the first row [m] and the row spacing [m] (> 0).
    advection : float
        Speed U [m/s] at which the frozen field moves downwind (usually the mean wind speed at hub height).
    heading : float
        Direction the grid's u axis points to [rad], measured like the wind direction of
        ``WindParams``: 0 is the undisturbed wind (blowing towards -x), so e = (-cos heading, -sin heading).
    fade_in : float
        Fade-in time T_f [s] (>= 0): the grid's gust is scaled by 0.5 (1 - cos(pi t / T_f)) for 0 <= t < T_f
        (0 before t = 0), so a field does not switch on at full strength at the start; 0: no fade.
    """

    values: np.ndarray
    xi0: float = 0.0
    dxi: float = 1.0
    h0: float = 0.0
    dh: float = 1.0
    advection: float = 0.0
    heading: float = 0.0
    fade_in: float = 0.0

    def __post_init__(self):
        v = np.ascontiguousarray(self.values, dtype=np.float64)
        if v.ndim != 3 or v.shape[2] != C.GV_SIZE or v.shape[0] < 1 or v.shape[1] < 1:
            raise ValueError(f"GustGrid.values: expected shape (n_xi >= 1, n_h >= 1, 3), got {np.shape(self.values)}")
        if not np.all(np.isfinite(v)):
            bad = np.argwhere(~np.isfinite(v))[0]
            raise ValueError(f"GustGrid.values{tuple(int(i) for i in bad)} = {v[tuple(bad)]!r}: must be finite")
        object.__setattr__(self, "values", v)
        for name in ("xi0", "h0", "advection", "heading"):
            object.__setattr__(self, name, _finite(f"GustGrid.{name}", getattr(self, name)))
        for name in ("dxi", "dh"):
            object.__setattr__(self, name, _finite(f"GustGrid.{name}", getattr(self, name), positive=True))
        object.__setattr__(self, "fade_in", _finite("GustGrid.fade_in", self.fade_in))
        if self.fade_in < 0:
            raise ValueError(f"GustGrid.fade_in = {self.fade_in!r}: must be >= 0 s")

    def geometry(self) -> GridGeometry:
        """The grid's nodes, advection and heading as a :class:`GridGeometry`."""
        nx, nh = self.values.shape[:2]
        return GridGeometry(self.xi0, self.dxi, nx, self.h0, self.dh, nh, self.advection, self.heading, self.fade_in)

    @property
    def size(self) -> int:
        """Number of packed floats (n_xi n_h 3)."""
        return int(self.values.size)

    def header(self) -> np.ndarray:
        """The packed header ``gp`` (GP_SIZE,) (slots ``GP_*``)."""
        gp = np.zeros(C.GP_SIZE)
        gp[C.GP_XI0], gp[C.GP_DXI], gp[C.GP_H0], gp[C.GP_DH] = self.xi0, self.dxi, self.h0, self.dh
        gp[C.GP_NXI], gp[C.GP_NH] = self.values.shape[0], self.values.shape[1]
        gp[C.GP_ADVECTION] = self.advection
        gp[C.GP_EX], gp[C.GP_EY] = -math.cos(self.heading), -math.sin(self.heading)
        gp[C.GP_FADE] = self.fade_in
        return gp


class GridGeometry(NamedTuple):
    """The nodes of a gust grid: xi = xi0 + i dxi (i < n_xi), h = h0 + j dh (j < n_h) [m], with its advection
    speed [m/s], heading [rad] and fade-in time [s] (see :class:`GustGrid`). ``floats`` = n_xi n_h 3, ``bytes`` =
    8 floats."""

    xi0: float
    dxi: float
    n_xi: int
    h0: float
    dh: float
    n_h: int
    advection: float
    heading: float
    fade_in: float = 0.0

    @property
    def floats(self) -> int:
        return int(self.n_xi * self.n_h * C.GV_SIZE)

    @property
    def bytes(self) -> int:
        return 8 * self.floats


def union_geometry(geoms) -> GridGeometry | None:
    """One grid covering all of ``geoms`` (their union of extents at their finest spacings); None for none.
    Raises ValueError if their advection speeds or headings differ (frozen fields moving differently cannot
    share one grid)."""
    geoms = [g for g in geoms if g is not None]
    if not geoms:
        return None
    g0 = geoms[0]
    for g in geoms[1:]:
        if not (math.isclose(g.advection, g0.advection) and math.isclose(g.heading, g0.heading)
                and g.fade_in == g0.fade_in):
            raise ValueError(f"gust grids advected at {g0.advection} m/s, heading {g0.heading} rad, fade-in "
                             f"{g0.fade_in} s and at {g.advection} m/s, heading {g.heading} rad, fade-in {g.fade_in} s "
                             "cannot be combined: give every spatial disturbance the same wind_speed, heading and "
                             "fade_in")
    if len(geoms) == 1:
        return g0
    dxi, dh = min(g.dxi for g in geoms), min(g.dh for g in geoms)
    x0, h0 = min(g.xi0 for g in geoms), min(g.h0 for g in geoms)
    x1 = max(g.xi0 + (g.n_xi - 1) * g.dxi for g in geoms)
    h1 = max(g.h0 + (g.n_h - 1) * g.dh for g in geoms)
    return GridGeometry(x0, dxi, int(math.ceil((x1 - x0) / dxi - 1e-9)) + 1, h0, dh,
                        int(math.ceil((h1 - h0) / dh - 1e-9)) + 1, g0.advection, g0.heading, g0.fade_in)


def _interp_axis(u: np.ndarray, n: int):
    """Cell index, fraction and next index of fractional grid coordinates u on an axis of n nodes, held at
    the edges (as the kernels' ``_cell``)."""
    if n < 2:
        z = np.zeros(u.shape, dtype=np.int64)
        return z, np.zeros(u.shape), z
    uc = np.clip(u, 0.0, n - 1)
    k = np.minimum(np.floor(uc).astype(np.int64), n - 2)
    return k, uc - k, k + 1


def sum_grids(grids, geom: GridGeometry | None = None) -> GustGrid | None:
    """The sum of gust grids sampled (bilinearly, held at their edges, as the kernels do) on the nodes of
    ``geom`` (default: :func:`union_geometry` of theirs); a single grid on its own geometry is returned as it
    is. None for no grids."""
    grids = [g for g in grids if g is not None]
    if not grids:
        return None
    if geom is None:
        geom = union_geometry([g.geometry() for g in grids])
    if len(grids) == 1 and grids[0].geometry() == geom:
        return grids[0]
    xi = geom.xi0 + geom.dxi * np.arange(geom.n_xi)
    h = geom.h0 + geom.dh * np.arange(geom.n_h)
    out = np.zeros((geom.n_xi, geom.n_h, C.GV_SIZE))
    for g in grids:
        nx, nh = g.values.shape[:2]
        i, a, i1 = _interp_axis((xi - g.xi0) / g.dxi, nx)
        j, b, j1 = _interp_axis((h - g.h0) / g.dh, nh)
        a, b = a[:, None, None], b[None, :, None]
        v = g.values
        out += ((1.0 - a) * ((1.0 - b) * v[i][:, j] + b * v[i][:, j1])
                + a * ((1.0 - b) * v[i1][:, j] + b * v[i1][:, j1]))
    return GustGrid(out, geom.xi0, geom.dxi, geom.h0, geom.dh, geom.advection, geom.heading, geom.fade_in)


@dataclass(frozen=True, eq=False)
class WindField:
    """The wind's variation in time (modulation) and space (an optional :class:`GustGrid`).

    Attributes
    ----------
    t0, dt : float
        Time of the first modulation sample [s] and the sample spacing [s] (> 0).
    speed : ndarray, shape (n,)
        Speed factor samples [-] (>= 0; 1 is the undisturbed profile); held after the last sample.
    direction : ndarray, shape (n,)
        Direction offset samples [rad]; same length as ``speed``.
    grid : GustGrid or None
        The frozen gust grid added to the modulated profile; None for none (costs nothing in the kernels).
    """

    t0: float = 0.0
    dt: float = 1.0
    speed: np.ndarray = field(default_factory=lambda: np.ones(1))
    direction: np.ndarray = field(default_factory=lambda: np.zeros(1))
    grid: GustGrid | None = None

    def __post_init__(self):
        s = np.ascontiguousarray(self.speed, dtype=np.float64)
        d = np.ascontiguousarray(self.direction, dtype=np.float64)
        if s.ndim != 1 or d.shape != s.shape or s.size == 0:
            raise ValueError(f"WindField: speed {s.shape} and direction {d.shape} must be equal, non-empty 1-D")
        if not (np.all(np.isfinite(s)) and np.all(np.isfinite(d))):
            raise ValueError("WindField: speed and direction samples must be finite")
        if np.any(s < 0):
            i = int(np.argmin(s))
            raise ValueError(f"WindField.speed[{i}] = {s[i]!r}: a speed factor must be >= 0")
        object.__setattr__(self, "speed", s)
        object.__setattr__(self, "direction", d)
        object.__setattr__(self, "t0", _finite("WindField.t0", self.t0))
        object.__setattr__(self, "dt", _finite("WindField.dt", self.dt, positive=True))
        if self.grid is not None and not isinstance(self.grid, GustGrid):
            raise ValueError(f"WindField.grid = {self.grid!r}: must be a GustGrid or None")


def pack_wind_field(f: WindField, n_modulation: int | None = None, n_grid: int | None = None):
    """The packed arrays ``(tmod (TM_SIZE,), ms (n,), md (n,), gp (GP_SIZE,), gv (m,))`` of a field; gp and gv are
    None without a gust grid (and ``n_grid`` None or 0).

    ``n_modulation`` / ``n_grid`` pad the modulation and grid arrays to a batch's fixed widths (the modulation
    with its last sample, which the kernel holds anyway; the grid with zeros past its own size, which the kernel
    never reads). Raises ValueError if the field does not fit."""
    n = f.speed.size
    nm = n if n_modulation is None else int(n_modulation)
    if n > nm:
        raise ValueError(f"wind field: {n} modulation samples, but the simulator holds at most {nm}")
    tmod = np.zeros(C.TM_SIZE)
    tmod[C.TM_T0], tmod[C.TM_DT] = f.t0, f.dt
    ms = np.full(nm, f.speed[-1])
    ms[:n] = f.speed
    md = np.full(nm, f.direction[-1])
    md[:n] = f.direction
    g = f.grid
    size = 0 if g is None else g.size
    ng = size if n_grid is None else int(n_grid)
    if size > ng:
        raise ValueError(f"wind field: a gust grid of {g.values.shape} ({size} floats) does not fit the {ng} floats "
                         "the simulator holds (BatchSimulator(..., n_grid=...))")
    if ng == 0:
        return tmod, ms, md, None, None
    gp = np.zeros(C.GP_SIZE) if g is None else g.header()
    gv = np.zeros(ng)
    if g is not None:
        gv[:size] = g.values.reshape(-1)
    return tmod, ms, md, gp, gv
