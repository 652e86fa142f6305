"""Figures of a recording: the 3D shape of wings and cable, and time histories."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize

from laddermill_gym.figure_files import release, subplots
from laddermill_gym.sim.recording import Recording


def save_figure(fig, path, dpi: int = 120) -> Path:
    """Lay out ``fig``, write it to ``path`` (creating the folder) and, when pyplot made it, close it in pyplot.
    Returns the path."""
    path = Path(path)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi)
    release(fig)
    return path


def tension_norm(values_kN: np.ndarray) -> Normalize:
    """The colour scale of element tensions ``values_kN`` (any shape) [kN]: their range, widened to 1 % of the value
    on each side (at least 0.01 kN) where they are all alike, so that the colour bar reads the value itself (a
    range of 1e-9 kN printed only an offset label)."""
    lo, hi = float(np.min(values_kN)), float(np.max(values_kN))
    if hi - lo < 1e-6 * max(1.0, abs(hi)):
        half = max(0.01 * abs(hi), 0.01)
        lo, hi = lo - half, hi + half
    return Normalize(lo, hi)


def cable_segments(asm, wing_pos: np.ndarray, wing_euler: np.ndarray, node_pos: np.ndarray) -> np.ndarray:
    """End points of every cable element, shape (n_elements, 2, 3) [m] (global): ground points, free nodes, and
    wing attachment points (CG + R(euler) attachment) for the states of one sample (wing_pos (n_w, 3) [m],
    wing_euler (n_w, 3) [rad], node_pos (n_nodes, 3) [m])."""
    from laddermill_gym.model.params import END_NODE, END_WING
    from laddermill_gym.model.states import rotation_from_euler

    el = asm.elements
    seg = np.zeros((el.count, 2, 3))
    for e in range(el.count):
        for end in (0, 1):
            kind, idx = int(el.end_kind[e, end]), int(el.end_index[e, end])
            if kind == END_WING:
                seg[e, end] = wing_pos[idx] + rotation_from_euler(*wing_euler[idx]) @ el.attach[e, end]
            elif kind == END_NODE:
                seg[e, end] = node_pos[idx]
            else:
                seg[e, end] = asm.fixed_points[idx]
    return seg


def draw_loop(ax_side, ax_top, asm, views: dict, i: int, norm, cmap="viridis", faint: bool = False):
    """Draw sample ``i`` of the recorded ``views``: the cable (elements coloured by tension with ``norm``, or
    faint grey) and the wings, in a side view (x, altitude) and a top view (x, y). Returns the artists."""
    from matplotlib.collections import LineCollection

    seg = cable_segments(asm, views["wing_position_m"][i], views["wing_euler_rad"][i], views["node_position_m"][i])
    w = views["wing_position_m"][i]
    arts = []
    for ax, a, b in ((ax_side, 0, 2), (ax_top, 0, 1)):
        lines = np.stack([seg[:, :, a], -seg[:, :, b] if b == 2 else seg[:, :, b]], axis=-1)
        if faint:
            lc = LineCollection(lines, colors="0.75", linewidths=0.8, linestyles="--")
        else:
            lc = LineCollection(lines, cmap=cmap, norm=norm, linewidths=1.4)
            lc.set_array(views["element_tension_N"][i] / 1e3)
        arts.append(ax.add_collection(lc))
        arts += ax.plot(w[:, a], -w[:, b] if b == 2 else w[:, b], "o", ms=2.5, color="0.6" if faint else "k")
    return arts


def plot_shape(rec: Recording, path: Path, title: str = "", asm=None) -> Path:
    """Side view (x, h) and top view (x, y) of wings and cable at the first sample (faint) and the last (the cable
    coloured by element tension [kN]). Without ``asm`` (the assembly, for the element connectivity) only the wings
    and nodes are drawn."""
    if len(rec.t) == 0:
        raise ValueError(f"plot_shape: the recording has no samples (nothing to draw into {path})")
    fig, (ax1, ax2) = subplots(1, 2, figsize=(12, 5.5))
    if asm is not None:
        norm = tension_norm(rec.views["element_tension_N"][-1] / 1e3)
        draw_loop(ax1, ax2, asm, rec.views, 0, norm, faint=True)
        draw_loop(ax1, ax2, asm, rec.views, -1, norm)
        sm = ScalarMappable(norm=norm, cmap="viridis")
        fig.colorbar(sm, ax=[ax1, ax2], label=f"element tension at t = {rec.t[-1]:.1f} s [kN]", shrink=0.8)
        for ax in (ax1, ax2):
            ax.autoscale_view()
    else:
        for i, style, label in ((0, "--", f"t = {rec.t[0]:.1f} s"), (-1, "-", f"t = {rec.t[-1]:.1f} s")):
            w = rec.views["wing_position_m"][i]
            n = rec.views["node_position_m"][i]
            pts = np.vstack([w, n]) if n.size else w
            ax1.plot(pts[:, 0], -pts[:, 2], ".", ms=2, color="0.5")
            ax1.plot(w[:, 0], -w[:, 2], "o" + style, ms=3, label=label)
            ax2.plot(w[:, 0], w[:, 1], "o" + style, ms=3, label=label)
        ax1.legend()
        ax2.legend()
    ax1.set(xlabel="x (north, into the wind) [m]", ylabel="altitude h [m]",
            title=f"side view (dashed: t = {rec.t[0]:.1f} s)")
    ax2.set(xlabel="x [m]", ylabel="y (east) [m]", title="top view")
    ax1.set_aspect("equal", adjustable="datalim")
    fig.suptitle(title)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    return path


def plot_generator(rec: Recording, path: Path, title: str = "") -> Path:
    """Generator power (mechanical and electrical) [kW], the first and last elements' tensions [kN], the cable
    speed [m/s] and the cable paid out [m] of a moving-cable recording."""
    v = rec.views
    fig, axs = subplots(2, 2, figsize=(12, 7), sharex=True)
    axs[0, 0].plot(rec.t, v["generator_power_W"] / 1e3, label="mechanical")
    axs[0, 0].plot(rec.t, v["generator_electrical_power_W"] / 1e3, "--", label="electrical")
    span = rec.t[-1] - rec.t[0]
    if span > 0:
        mean = (v["generator_energy_J"][-1] - v["generator_energy_J"][0]) / span / 1e3
        axs[0, 0].axhline(mean, color="k", lw=0.8, label=f"mean {mean:.1f} kW (energy / time)")
    ten = v["element_tension_N"] / 1e3
    axs[0, 1].plot(rec.t, ten[:, 0], label="first element (veered)")
    axs[0, 1].plot(rec.t, ten[:, -1], label="last element (hauled)")
    axs[1, 0].plot(rec.t, v["cable_speed_m_s"])
    axs[1, 1].plot(rec.t, v["cable_paid_out_m"])
    for ax, lab in zip(axs.flat, ("generator power [kW]", "tension [kN]", "cable speed V_c [m/s]",
                                  "cable paid out [m]"), strict=True):
        ax.set_ylabel(lab)
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    axs[1, 0].set_xlabel("t [s]")
    axs[1, 1].set_xlabel("t [s]")
    fig.suptitle(title)
    return save_figure(fig, path, dpi=110)


def plot_histories(rec: Recording, path: Path, title: str = "", wings: list[int] | None = None) -> Path:
    """Lateral position, Euler angles, angle of attack and sideslip of selected wings, and element tensions."""
    nw = rec.views["wing_position_m"].shape[1]
    wings = wings if wings is not None else sorted({0, nw // 2, nw - 1})
    bad = [k for k in wings if not -nw <= k < nw]
    if bad:
        raise ValueError(f"plot_histories: wings {bad} do not exist (the recording has {nw} wings: 0 to {nw - 1})")
    fig, axs = subplots(3, 2, figsize=(12, 9), sharex=True)
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
