"""Animation of a recording: the loop of wings and cable in side and top view, the cable coloured by tension,
written as a GIF (Pillow, which matplotlib already needs; no ffmpeg)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.animation import FuncAnimation, PillowWriter
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize

from laddermill_gym.figure_files import subplots
from laddermill_gym.plotting import draw_loop
from laddermill_gym.sim.recording import Recording


def _limits(rec: Recording, axis_a: int, axis_b: int, sign_b: float, pad: float = 0.05):
    w = rec.views["wing_position_m"]
    a, b = w[..., axis_a], sign_b * w[..., axis_b]
    da, db = max(np.ptp(a), 1.0), max(np.ptp(b), 1.0)
    return (a.min() - pad * da, a.max() + pad * da), (min(b.min(), 0.0) - pad * db, b.max() + pad * db)


def animate_loop(rec: Recording, asm, path: Path, max_frames: int = 120, fps: int = 12, title: str = "",
                 progress: bool = True) -> Path:
    """Write a GIF of the recorded loop (at most ``max_frames`` frames, evenly spread over the recording; ``fps``
    frames per second of the GIF). The tension colour scale [kN] is fixed over the whole recording."""
    n = len(rec.t)
    frames = np.unique(np.linspace(0, n - 1, min(n, max_frames)).round().astype(int))
    ten = rec.views["element_tension_N"] / 1e3
    norm = Normalize(float(ten.min()), float(max(ten.max(), ten.min() + 1e-9)))
    fig, (ax1, ax2) = subplots(1, 2, figsize=(11, 5))
    (xl, hl), (_, yl) = _limits(rec, 0, 2, -1.0), _limits(rec, 0, 1, 1.0)
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
    FuncAnimation(fig, update, frames=len(frames), blit=False).save(path, writer=PillowWriter(fps=fps), dpi=70)
    if bar is not None:
        bar.close()
    return path
