"""Figures of a recording: the 3D shape of wings and cable, and time histories."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from laddermill_gym.sim.recording import Recording


def save_figure(fig, path, dpi: int = 120) -> Path:
    """Lay out ``fig``, write it to ``path`` (creating the folder) and close it. Returns the path."""
    path = Path(path)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
    return path


def plot_shape(rec: Recording, path: Path, title: str = "") -> Path:
    """Side view (x, h) and top view (x, y) of wings and cable nodes at the first and last sample."""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5))
    for i, style, label in ((0, "--", f"t = {rec.t[0]:.1f} s"), (-1, "-", f"t = {rec.t[-1]:.1f} s")):
        w = rec.views["wing_position_m"][i]
        n = rec.views["node_position_m"][i]
        pts = np.vstack([w, n]) if n.size else w
        ax1.plot(pts[:, 0], -pts[:, 2], ".", ms=2, color="0.5")
        ax1.plot(w[:, 0], -w[:, 2], "o" + style, ms=3, label=label)
        ax2.plot(w[:, 0], w[:, 1], "o" + style, ms=3, label=label)
    ax1.set(xlabel="x (north, into the wind) [m]", ylabel="altitude h [m]", title="side view")
    ax2.set(xlabel="x [m]", ylabel="y (east) [m]", title="top view")
    ax1.axis("equal")
    ax1.legend()
    ax2.legend()
    fig.suptitle(title)
    return save_figure(fig, path, dpi=110)


def plot_histories(rec: Recording, path: Path, title: str = "", wings: list[int] | None = None) -> Path:
    """Lateral position, Euler angles, angle of attack and sideslip of selected wings, and element tensions."""
    nw = rec.views["wing_position_m"].shape[1]
    wings = wings if wings is not None else sorted({0, nw // 2, nw - 1})
    fig, axs = plt.subplots(3, 2, figsize=(12, 9), sharex=True)
    t = rec.t
    names = ("roll phi", "pitch theta", "yaw psi")
    for k in wings:
        axs[0, 0].plot(t, rec.views["wing_position_m"][:, k, 1], label=f"wing {k}")
        axs[0, 1].plot(t, -rec.views["wing_position_m"][:, k, 2], label=f"wing {k}")
        axs[1, 0].plot(t, np.degrees(rec.views["wing_alpha_rad"][:, k]), label=f"wing {k}")
        axs[1, 1].plot(t, np.degrees(rec.views["wing_beta_rad"][:, k]), label=f"wing {k}")
        for j, ls in enumerate(("-", "--", ":")):
            axs[2, 0].plot(t, np.degrees(rec.views["wing_euler_rad"][:, k, j]), ls,
                           label=f"wing {k} {names[j]}")
    ten = rec.views["element_tension_N"]
    for e in sorted({0, ten.shape[1] // 2, ten.shape[1] - 1}):
        axs[2, 1].plot(t, ten[:, e] / 1e3, label=f"element {e}")
    labels = [("lateral position y [m]", "altitude h [m]"), ("angle of attack [deg]", "sideslip [deg]"),
              ("Euler angles [deg]", "tension [kN]")]
    for i in range(3):
        for j in range(2):
            axs[i, j].set_ylabel(labels[i][j])
            axs[i, j].legend(fontsize=7)
            axs[i, j].grid(alpha=0.3)
    axs[2, 0].set_xlabel("t [s]")
    axs[2, 1].set_xlabel("t [s]")
    if rec.error:
        fig.text(0.01, 0.005, "stopped: " + rec.error[:150], fontsize=7, color="red")
    fig.suptitle(title)
    return save_figure(fig, path, dpi=110)
