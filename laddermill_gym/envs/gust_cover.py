"""Whether a frozen gust grid (turbulence) covers the points an env's wind is sampled at.

A :class:`~laddermill_gym.atmosphere.turbulence.Turbulence` field lives on an (along-wind xi, height h) grid whose
extent the scenario gives (``heights`` [m], ``along_wind`` [m] = the range of p . e the grid must cover, e the
downwind unit vector). Outside the grid the kernels hold the edge values, so a grid that ends below some wings gives
them the edge row's gust: a silent defect. :func:`extent` gives a set of points' height and along-wind ranges for a
grid heading, :func:`check_turbulence_cover` warns (RuntimeWarning) about each turbulence disturbance whose grid does
not cover them, :func:`point_positions` reads the wing and node positions of batch states and :func:`start_points`
the points of a start state every task checks (the mill checks its whole loop: ``envs/laddermill/gust_extent.py``).
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, N3_POS
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["LoopExtent", "extent", "point_positions", "check_turbulence_cover", "start_points", "LOOP", "START"]


class LoopExtent(NamedTuple):
    """Height range ``heights`` (low, high) [m] (h = -z) and along-wind range ``along_wind`` (low, high) [m]
    (p . e, e = (-cos heading, -sin heading, 0) the downwind unit vector of a grid's ``heading``) of a set of
    points."""

    heights: tuple[float, float]
    along_wind: tuple[float, float]


def point_positions(assembly, states: np.ndarray) -> np.ndarray:
    """Wing CG and free cable node positions (B, n_wings + n_nodes, 3) [m], global frame (z down), of the 3D
    states ``states`` (B, n_state) (a batch's ``states``) of ``assembly``."""
    a = assembly
    x = np.atleast_2d(np.asarray(states, dtype=float))
    nw = a.n_wings * a.wing_state_size
    wings = x[:, :nw].reshape(x.shape[0], a.n_wings, a.wing_state_size)[:, :, B3_POS: B3_POS + 3]
    nodes = x[:, nw: a.body_state_size].reshape(x.shape[0], a.n_nodes, a.node_state_size)[:, :, N3_POS: N3_POS + 3]
    return np.concatenate([wings, nodes], axis=1)


def start_points(assembly, state: np.ndarray) -> np.ndarray:
    """Points (m, 3) [m] a scene's turbulence must cover at its start ``state`` (n_state,): every wing or body CG,
    every free cable node and the fixed points (``assembly.fixed_points``, where the cable is anchored)."""
    return np.concatenate([point_positions(assembly, state)[0],
                           np.asarray(assembly.fixed_points, dtype=float).reshape(-1, 3)])


def extent(points: np.ndarray, heading: float = 0.0) -> LoopExtent:
    """The :class:`LoopExtent` of ``points`` (m, 3) [m] for a grid of ``heading`` [rad]."""
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    h = -p[:, 2]
    s = -math.cos(heading) * p[:, 0] - math.sin(heading) * p[:, 1]
    return LoopExtent((float(h.min()), float(h.max())), (float(s.min()), float(s.max())))


def _uncovered(lo_hi: tuple[float, float], need: tuple[float, float]) -> bool:
    return lo_hi[0] > need[0] or lo_hi[1] < need[1]


#: What the mill's points are, in the warning's text
LOOP = "the laddermill's loop ({lo:.1f} to {hi:.1f} m: wings over a transfer period, cable nodes and ground stations)"
#: What a single craft's or a chain's points are, in the warning's text (they start there; an episode moves them)
START = "the start's bodies and cable nodes ({lo:.1f} to {hi:.1f} m)"


def check_turbulence_cover(disturbances, points: np.ndarray, where: str = "disturbances",
                           what: str = LOOP) -> list[str]:
    """Warn (RuntimeWarning) for each turbulence disturbance (one with ``heights``, ``along_wind`` and ``heading``)
    whose grid does not cover ``points`` (m, 3) [m]; returns the warning texts (empty: all covered). The text names
    the disturbance, its field and value, and the range ``what`` (a format with ``lo``, ``hi`` [m]) needs."""
    texts = []
    for i, d in enumerate(disturbances):
        if not all(hasattr(d, f) for f in ("heights", "along_wind", "heading")):
            continue
        need = extent(points, d.heading)
        for field, have, req in (("heights", d.heights, need.heights), ("along_wind", d.along_wind, need.along_wind)):
            if _uncovered(tuple(have), req):
                texts.append(f"{where}[{i}].{field} = [{have[0]:g}, {have[1]:g}] m does not cover "
                             f"{what.format(lo=req[0], hi=req[1])}; outside the grid the edge values of the "
                             "turbulence hold")
    for t in texts:
        warnings.warn(t, RuntimeWarning, stacklevel=user_stacklevel())
    return texts
