"""3D pictures of a task copy with matplotlib: each wing as its span and body axis, the cable elements as
lines, the ground points as markers. Axes: x north (upwind), y east, altitude up [m]."""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_SIZE, N3_POS, N3_SIZE
from laddermill_gym.model.params import END_FIXED, END_NODE, END_WING
from laddermill_gym.model.states import rotations_from_quaternions


def scene_geometry(asm, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(CG positions (n, 3) [m], rotations (n, 3, 3) body -> global, cable segments (n_e, 2, 3) [m]) of a 3D
    state ``x`` of the assembly ``asm`` (element ends: wing attachment points, free nodes, ground points)."""
    nw = asm.n_wings
    w = x[: B3_SIZE * nw].reshape(nw, B3_SIZE)
    pos = w[:, B3_POS: B3_POS + 3]
    rot = rotations_from_quaternions(w[:, B3_QUAT: B3_QUAT + 4])
    nodes = x[B3_SIZE * nw: B3_SIZE * nw + N3_SIZE * asm.n_nodes].reshape(-1, N3_SIZE)[:, N3_POS: N3_POS + 3]
    el = asm.elements
    seg = np.zeros((el.count, 2, 3))
    for e in range(el.count):
        for r in range(2):
            kind, idx = el.end_kind[e, r], el.end_index[e, r]
            if kind == END_WING:
                seg[e, r] = pos[idx] + rot[idx] @ el.attach[e, r]
            elif kind == END_NODE:
                seg[e, r] = nodes[idx]
            else:
                assert kind == END_FIXED
                seg[e, r] = asm.fixed_points[idx]
    return pos, rot, seg


def set_view_box(ax, box: tuple[np.ndarray, np.ndarray]) -> None:
    """Limits and axis labels of the 3D axes ``ax`` on the view ``box`` (low, high corners (3,) in world axes [m]:
    x north, y east, z down): x as the box, y widened by half the box's x extent on each side, altitude (plotted up)
    from max(0, -high z) to -low z."""
    lo, hi = box
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1] - 0.5 * (hi[0] - lo[0]), hi[1] + 0.5 * (hi[0] - lo[0]))
    ax.set_zlim(max(0.0, -hi[2]), -lo[2])
    ax.set_xlabel("x north [m]")
    ax.set_ylabel("y east [m]")
    ax.set_zlabel("altitude [m]")


class FigureRenderer:
    """A matplotlib figure of ``size_px`` (width, height) drawn into an RGB array (H, W, 3) uint8 or, with
    ``interactive=True`` (the ``human`` render mode), into a window: what every renderer of the envs shares (a
    subclass draws into ``fig`` and returns :meth:`frame`)."""

    def __init__(self, interactive: bool = False, size_px: tuple[int, int] = (640, 480)):
        import matplotlib

        if not interactive:
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure

            self.fig = Figure(figsize=(size_px[0] / 80, size_px[1] / 80), dpi=80)
            FigureCanvasAgg(self.fig)
            self._plt = None
        else:
            import matplotlib.pyplot as plt

            if matplotlib.get_backend().lower() in ("agg", "pdf", "svg", "ps", "cairo", "template"):
                from gymnasium import logger

                logger.warn(f"render_mode='human': matplotlib backend {matplotlib.get_backend()!r} cannot open a "
                            "window; frames are drawn but not shown (set MPLBACKEND, e.g. TkAgg or QtAgg)")
            self._was_interactive = plt.isinteractive()
            plt.ion()
            self.fig = plt.figure(figsize=(size_px[0] / 80, size_px[1] / 80), dpi=80)
            self._plt = plt

    def frame(self):
        """Draw the figure; the RGB frame (H, W, 3) uint8, or None in interactive mode (shown instead)."""
        self.fig.canvas.draw()
        if self._plt is not None:
            self._plt.pause(1e-3)
            return None
        return np.asarray(self.fig.canvas.buffer_rgba())[:, :, :3].copy()

    def close(self) -> None:
        """Close the window; pyplot's interactive mode is left as the renderer found it."""
        if self._plt is not None:
            self._plt.close(self.fig)
            if not self._was_interactive:
                self._plt.ioff()
            self._plt = None


class SceneRenderer(FigureRenderer):
    """Draws copy ``b`` of a :class:`~laddermill_gym.envs.task.WingTask` into an RGB array (H, W, 3) uint8, or
    into a window (``interactive=True``, the ``human`` render mode)."""

    def __init__(self, task, interactive: bool = False, size_px: tuple[int, int] = (640, 480)):
        super().__init__(interactive, size_px)
        self.ax = self.fig.add_subplot(projection="3d")
        self.task = task
        asm = task.scene.assembly
        self.asm = asm
        # fixed view box around the nominal configuration
        nodes = (task.x_trim[B3_SIZE * asm.n_wings:].reshape(-1, N3_SIZE)[:, N3_POS: N3_POS + 3] if asm.n_nodes
                 else np.zeros((0, 3)))
        pts = np.vstack([task.nominal, nodes, asm.fixed_points])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        pad = 0.15 * float(np.max(hi - lo)) + max(w.span for w in asm.wing_types)
        self.box = self.start_box = (lo - pad, hi + pad)
        self.pad = pad
        # per copy: its view box and the time of its last frame drawn (an earlier one is a new episode's)
        self.views: dict[int, tuple] = {}

    def follow(self, points: np.ndarray) -> None:
        """Widen the view box (never narrow it within an episode: the view stays still while the bodies are inside)
        so that it holds the finite ``points`` (k, 3) [m] with the start's margin: a kite reeling out, a wing swinging
        wide stay in view (a broken-down state's non-finite points are left out)."""
        points = points[np.all(np.isfinite(points), axis=1)]
        if points.size == 0:
            return
        lo, hi = self.box
        if np.all(points >= lo) and np.all(points <= hi):
            return
        self.box = (np.minimum(lo, points.min(axis=0) - self.pad), np.maximum(hi, points.max(axis=0) + self.pad))

    def draw(self, b: int = 0):
        """Redraw copy ``b``; returns the RGB frame (H, W, 3) uint8 (or None in interactive mode)."""
        ax = self.ax
        ax.cla()
        t = float(self.task.batch.t[b])
        box, drawn_t = self.views.get(b, (self.start_box, -np.inf))
        # a reset (or the same state again): the view starts from the start's box; each copy keeps its own view
        self.box = self.start_box if t <= drawn_t else box
        pos, rot, segments = scene_geometry(self.asm, self.task.batch.states[b])
        up = np.array([1.0, 1.0, -1.0])  # plot altitude = -z
        for p, q in segments:
            seg = np.array([p, q]) * up
            ax.plot(seg[:, 0], seg[:, 1], seg[:, 2], color="0.35", lw=1.0)
        self.draw_bodies(pos, rot, up)
        fp = self.asm.fixed_points * up
        ax.scatter(fp[:, 0], fp[:, 1], fp[:, 2], color="k", marker="^", s=30)
        self.follow(np.vstack([pos, segments.reshape(-1, 3)]))
        self.views[b] = (self.box, t)
        set_view_box(ax, self.box)
        ax.set_title(f"{self.task.scene.name}  t = {self.task.batch.t[b]:6.2f} s")
        return self.frame()

    def draw_bodies(self, pos: np.ndarray, rot: np.ndarray, up: np.ndarray) -> None:
        """Draw the bodies (CG positions pos (n, 3) [m], rotations rot (n, 3, 3)); a wing is its span (blue)
        and fuselage line (red). ``up`` flips z to altitude."""
        ax = self.ax
        for k in range(len(pos)):
            wt = self.asm.wing(k)
            half = 0.5 * wt.span
            span = np.array([pos[k] - half * rot[k][:, 1], pos[k] + half * rot[k][:, 1]]) * up
            body = np.array([pos[k] + wt.chord * rot[k][:, 0], pos[k] - 3.0 * wt.chord * rot[k][:, 0]]) * up
            ax.plot(span[:, 0], span[:, 1], span[:, 2], color="tab:blue", lw=2.0)
            ax.plot(body[:, 0], body[:, 1], body[:, 2], color="tab:red", lw=1.5)


class TaskRendering:
    """``render`` and ``close`` of a single env over a task (copy 0; ``self.task.renderer(interactive)`` draws):
    "rgb_array" returns the frame, "human" shows it; without a render mode a warning and None."""

    def render(self):
        if self.render_mode is None:
            from gymnasium import logger

            logger.warn("render() called without a render_mode; pass render_mode='rgb_array' or 'human'")
            return None
        if self._renderer is None:
            self._renderer = self.task.renderer(interactive=self.render_mode == "human")
        frame = self._renderer.draw(0)
        return frame if self.render_mode == "rgb_array" else None

    def close(self):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
