"""3D pictures of a point-mass task copy with matplotlib (``envs/render.py``'s figure and view box): the string as a
line from its start ground point through its nodes (to its end ground point, for a chain between two), the kites as
markers, the ground points as triangles. Axes: x north (upwind), y east, altitude up [m]; the view box is fixed
around the start."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.render import FigureRenderer, set_view_box
from laddermill_gym.kernels.contract import N3_POS, N3_SIZE

__all__ = ["PointMassRenderer"]

#: world z (down) to plot altitude (up)
_UP = np.array([1.0, 1.0, -1.0])


def _nodes(x: np.ndarray) -> np.ndarray:
    """Node positions (n, 3) [m] of a point-mass state (6 n,)."""
    return x.reshape(-1, N3_SIZE)[:, N3_POS:N3_POS + 3]


class PointMassRenderer(FigureRenderer):
    """Draws copy ``b`` of a :class:`~laddermill_gym.envs.pointmass.task.PointMassTask` into an RGB array (H, W, 3)
    uint8, or into a window (``interactive=True``, the ``human`` render mode)."""

    def __init__(self, task, interactive: bool = False, size_px: tuple[int, int] = (640, 480)):
        super().__init__(interactive, size_px)
        self.ax = self.fig.add_subplot(projection="3d")
        self.task = task
        s = task.string
        self.ground = np.array([s.anchor] + ([s.end] if s.end is not None else []), dtype=float)
        pts = np.vstack([_nodes(np.asarray(task.x_trim)), self.ground])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        pad = 0.15 * float(np.max(hi - lo)) + 1.0
        self.box = (lo - pad, hi + pad)

    def draw(self, b: int = 0):
        """Redraw copy ``b``; returns the RGB frame (H, W, 3) uint8 (or None in interactive mode)."""
        ax, task = self.ax, self.task
        ax.cla()
        line = np.vstack([self.ground[:1], _nodes(task.batch.states[b]), self.ground[1:]]) * _UP
        ax.plot(line[:, 0], line[:, 1], line[:, 2], color="0.35", lw=1.0)
        kites = task.batch.kite_positions()[b] * _UP
        ax.scatter(kites[:, 0], kites[:, 1], kites[:, 2], color="tab:blue", s=12)
        g = self.ground * _UP
        ax.scatter(g[:, 0], g[:, 1], g[:, 2], color="k", marker="^", s=30)
        set_view_box(ax, self.box)
        t = float(task.batch.t[b]) - (task.mill.t0 if task.mill is not None else 0.0)
        ax.set_title(f"{task.scene.name} (point mass)  t = {t:6.2f} s")
        return self.frame()
