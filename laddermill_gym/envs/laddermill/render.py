"""Pictures of a laddermill copy with matplotlib: a side view (x north / upwind against altitude) and a top view
(x against y east) of the loop, the cable drawn element by element between consecutive wings and the two ground
points, the wings as their chord line (side) and span (top), ascending slots blue and descending red."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.render import FigureRenderer, scene_geometry

__all__ = ["MillRenderer"]


class MillRenderer(FigureRenderer):
    """Draws copy ``b`` of a :class:`~laddermill_gym.envs.laddermill.task.MillTask` into an RGB array (H, W, 3)
    uint8, or into a window (``interactive=True``, the ``human`` render mode)."""

    def __init__(self, task, interactive: bool = False, size_px: tuple[int, int] = (640, 480)):
        super().__init__(interactive, size_px)
        self.side, self.top = self.fig.subplots(1, 2, gridspec_kw={"width_ratios": [3, 2]})
        self.task = task
        self.asm = task.batch.assembly
        ref = task.op.orbit_positions.reshape(-1, 3)
        pts = np.vstack([ref, self.asm.fixed_points])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        pad = 0.08 * float(np.max(hi - lo)) + max(w.span for w in self.asm.wing_types)
        self.box = (lo - pad, hi + pad)
        self.ascending = np.arange(self.asm.n_wings) < (self.asm.n_wings + 1) // 2

    def draw(self, b: int = 0):
        """Redraw copy ``b``; returns the RGB frame (H, W, 3) uint8 (or None in interactive mode)."""
        task = self.task
        pos, rot, seg = scene_geometry(self.asm, task.batch.states[b])
        side, top = self.side, self.top
        side.cla()
        top.cla()
        chord = np.array([w.chord for w in (self.asm.wing(k) for k in range(len(pos)))])
        half = np.array([0.5 * self.asm.wing(k).span for k in range(len(pos))])
        for k in range(len(pos)):  # side: the chord line (enlarged); top: the span, thin (y is stretched)
            c = "tab:blue" if self.ascending[k] else "tab:red"
            body = np.array([pos[k] + 3.0 * chord[k] * rot[k][:, 0], pos[k] - 6.0 * chord[k] * rot[k][:, 0]])
            span = np.array([pos[k] - half[k] * rot[k][:, 1], pos[k] + half[k] * rot[k][:, 1]])
            side.plot(body[:, 0], -body[:, 2], color=c, lw=1.5)
            top.plot(span[:, 0], span[:, 1], color=c, lw=0.6, alpha=0.5)
        for ax, j in ((side, 2), (top, 1)):
            ys = -seg[:, :, 2] if j == 2 else seg[:, :, 1]
            ax.plot(seg[:, :, 0].T, ys.T, color="0.25", lw=1.0)
            fp = self.asm.fixed_points
            ax.plot(fp[:, 0], -fp[:, 2] if j == 2 else fp[:, 1], "k^", ms=6)
        top.scatter(pos[:, 0], pos[:, 1], s=6, c=np.where(self.ascending, "tab:blue", "tab:red"), zorder=3)
        lo, hi = self.box
        side.set_xlim(lo[0], hi[0])
        side.set_ylim(max(0.0, -hi[2]), -lo[2])
        side.set_xlabel("x north [m]")
        side.set_ylabel("altitude [m]")
        side.set_title("side view", fontsize=9)
        reach = max(50.0, 1.2 * float(np.max(np.abs(seg[:, :, 1]))))
        top.set_xlim(lo[0], hi[0])
        top.set_ylim(-reach, reach)
        top.set_xlabel("x north [m]")
        top.set_ylabel("y east [m]")
        top.set_title("top view", fontsize=9)
        self.fig.suptitle(f"{task.scene.name}  t = {task.batch.t[b]:7.2f} s  P = {task.power[b] / 1e3:7.1f} kW  "
                          f"V_c = {task.cable_speed[b]:.2f} m/s", fontsize=10)
        self.fig.tight_layout()
        return self.frame()
