"""Animation of a recording: the loop of wings and cable in side and top view, the cable coloured by tension,
written as a GIF (Pillow, which matplotlib already needs; no ffmpeg)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.animation import FuncAnimation, PillowWriter
from matplotlib.cm import ScalarMappable

from laddermill_gym.figure_files import subplots
from laddermill_gym.plotting import cable_segments, draw_loop, tension_norm
from laddermill_gym.sim.recording import Recording


def _limits(points: np.ndarray, axis_a: int, axis_b: int, sign_b: float, pad: float = 0.05):
    """View limits (a range, b range) [m] of ``points`` (k, 3) on the axes ``axis_a`` and ``axis_b`` (the latter
    times ``sign_b``: -1 plots altitude from z down), padded by ``pad`` of their spread (at least 1 m), b from 0."""
    a, b = points[:, axis_a], sign_b * points[:, axis_b]
    da, db = max(np.ptp(a), 1.0), max(np.ptp(b), 1.0)
    return (a.min() - pad * da, a.max() + pad * da), (min(b.min(), 0.0) - pad * db, b.max() + pad * db)


def drawn_points(rec: Recording, asm, frames: np.ndarray) -> np.ndarray:
    """Every point a frame of ``frames`` draws (k, 3) [m]: the wings and the cable's element ends (ground points,
    nodes, attachment points), so that the view holds the whole cable, not the wings alone."""
    v = rec.views
    segs = [cable_segments(asm, v["wing_position_m"][i], v["wing_euler_rad"][i], v["node_position_m"][i]).reshape(-1, 3)
            for i in frames]
    return np.vstack([v["wing_position_m"][frames].reshape(-1, 3), *segs])


def animate_loop(rec: Recording, asm, path: Path, max_frames: int = 120, fps: int = 12, title: str = "",
                 progress: bool = True) -> Path:
    """Write a GIF of the recorded loop (at most ``max_frames`` frames, evenly spread over the recording; ``fps``
    frames per second of the GIF). The tension colour scale [kN] is fixed over the whole recording."""
    n = len(rec.t)
    if n == 0:
        raise ValueError(f"animate_loop: the recording has no samples (nothing to draw into {path})")
    frames = np.unique(np.linspace(0, n - 1, min(n, max_frames)).round().astype(int))
    norm = tension_norm(rec.views["element_tension_N"] / 1e3)
    fig, (ax1, ax2) = subplots(1, 2, figsize=(11, 5))
    points = drawn_points(rec, asm, frames)
    (xl, hl), (_, yl) = _limits(points, 0, 2, -1.0), _limits(points, 0, 1, 1.0)
    y_half = max(abs(yl[0]), abs(yl[1]), 0.05 * (xl[1] - xl[0]))
    ax1.set(xlim=xl, ylim=hl, xlabel="x (into the wind) [m]", ylabel="altitude h [m]", title="side view")
    ax2.set(xlim=xl, ylim=(-y_half, y_half), xlabel="x [m]", ylabel="y (east) [m]", title="top view (y stretched)")
    fig.colorbar(ScalarMappable(norm=norm, cmap="viridis"), ax=[ax1, ax2], label="tension [kN]",
                 shrink=0.8)
    text = fig.suptitle(title)
    state = {"arts": []}
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=len(frames), desc="animation", unit="frame", leave=False)

    def update(j):
        for a in state["arts"]:
            a.remove()
        i = int(frames[j])
        state["arts"] = draw_loop(ax1, ax2, asm, rec.views, i, norm)
        text.set_text(f"{title}  t = {rec.t[i]:.1f} s")
        if bar is not None:
            bar.update(1)
        return state["arts"]

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    FuncAnimation(fig, update, frames=len(frames), init_func=list, blit=False).save(  # init: no extra frame 0
        path, writer=PillowWriter(fps=fps), dpi=70)
    if bar is not None:
        bar.close()
    return path
