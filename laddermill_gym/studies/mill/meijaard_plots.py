"""Figures of the Meijaard study (``studies/mill/meijaard.py``): Figs. 6, 7 and 8 of Meijaard, Ockels & Schwab (1999)
redone, each with the paper's words about its figure and our measured numbers beside them (the paper's figures
exist for us only as its text), and the panel of every claim (:mod:`laddermill_gym.studies.mill.meijaard_claims`).
"""

from __future__ import annotations

import io
import textwrap
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from laddermill_gym.sim.recording import ALPHA_RANGE_DEG, MAX_ABS_BETA_DEG

#: the paper's words about each figure (Meijaard et al. 1999, "Examples of application")
PAPER_TEXT = {
    "6": "Paper, Fig. 6 (stationary shapes, V_c = 1 and 5 m/s): \"For low cable velocities, the ascending and "
         "descending part are almost parallel ... For larger cable velocities, the loop widens\".",
    "7": "Paper, Fig. 7 (tension in the elements, same cases): \"The tensile force is smallest near the top, which "
         "value increases as the loop widens ... A fair estimate of the power is obtained by the product of this "
         "difference and the cable speed ... of the order of 200 kW\".",
    "8": "Paper, Fig. 8 (node 40, 0.01 rad wind-direction step, V_c = 2 m/s, 3D): \"The wing yaws over a large "
         "angle before the calculations breaks down after some 40 seconds\".",
}


def save_small(fig: Figure, path: Path, **kwargs) -> None:
    """Save ``fig`` as a PNG with a 256-colour palette (line plots lose nothing visible; the file is about half the
    size: the docs ship these figures). Pillow comes with matplotlib."""
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=80, **kwargs)
    buf.seek(0)
    # fast octree keeps the line colours apart (median cut, the default, merges the blue and orange lines into grey
    # and red)
    Image.open(buf).convert("RGB").quantize(colors=256, method=Image.Quantize.FASTOCTREE).save(path, optimize=True)


def _title(row: dict, res) -> str:
    state = f"periodic at t = {res.t_s:.0f} s" if res.converged else f"NOT PERIODIC within t = {res.t_s:.0f} s"
    return f"V_c = {row['V_c_m_s']:g} m/s ({state})"


def _beside(fig: Figure, figure: str, claims: list[dict] | None, bottom: float) -> None:
    """The paper's words and our numbers for ``figure`` in the band below ``bottom`` (figure fraction)."""
    width = int(150 * fig.get_figwidth() / 10)  # characters per line at 7 pt monospace
    lines = textwrap.wrap(PAPER_TEXT[figure], width)
    for c in claims or []:
        if c["figure"] == figure:
            lines += textwrap.wrap(f"Ours [{c['agrees']}]: {c['paper']}: {c['ours']}", width)
    fig.text(0.01, bottom - 0.01, "\n".join(lines), fontsize=7, va="top", family="monospace")


def plot_shapes(cases: list, path: Path, slot: int, scene: str, claims: list[dict] | None = None) -> None:
    """Fig. 6: wing CGs (x against height [m]) at the last transfer, ascending and descending legs; the shape at
    the end of the search (said in the title) where the motion is not periodic."""
    fig = Figure(figsize=(5 * len(cases) + 1, 8.5))
    axs = fig.subplots(1, len(cases), sharey=True, squeeze=False)
    for ax, (res, row, (g0, g1)) in zip(axs[0], cases, strict=True):
        s, n = res.shape_m, len(res.shape_m)
        up = np.vstack([g0, s[: n // 2 + 1]])
        down = np.vstack([s[n // 2:], g1])
        ax.plot(up[:, 0], -up[:, 2], "o-", ms=2, color="tab:red", label=f"ascending (slots 0-{n // 2})")
        ax.plot(down[:, 0], -down[:, 2], "o-", ms=2, color="tab:blue", label=f"descending ({n // 2}-{n - 1})")
        ax.plot(s[slot, 0], -s[slot, 2], "k*", ms=9, label=f"slot {slot}")
        ax.set_title(f"{_title(row, res)}\nmean loop width {row['loop_width_m']:.0f} m (sampled after: "
                     f"{row['width_min_m']:.0f}-{row['width_max_m']:.0f} m)", fontsize=9)
        ax.set_xlabel("x [m] (wind blows towards -x)")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
    axs[0, 0].set_ylabel("height [m]")
    axs[0, 0].legend(fontsize=8)
    fig.suptitle(f"Fig. 6 (Meijaard et al. 1999) redone, scene {scene}: shape of the in-plane mill at a transfer")
    fig.tight_layout(rect=(0, 0.16, 1, 1))
    _beside(fig, "6", claims, 0.16)
    save_small(fig, path)


def plot_tensions(cases: list, path: Path, scene: str, claims: list[dict] | None = None) -> None:
    """Fig. 7: mean tension per element [kN] with the min-max band over the last period."""
    fig = Figure(figsize=(10, 7))
    ax = fig.subplots()
    for (res, row, _), c in zip(cases, ("tab:green", "tab:orange", "tab:purple", "tab:grey"), strict=False):
        k = np.arange(len(res.tension_mean_N))
        ax.fill_between(k, res.tension_min_N / 1e3, res.tension_max_N / 1e3, color=c, alpha=0.25)
        ax.plot(k, res.tension_mean_N / 1e3, color=c, label=f"{_title(row, res)}: mean, min-max band")
        j = int(np.argmin(res.tension_mean_N))
        ax.plot(j, res.tension_mean_N[j] / 1e3, "v", color=c, ms=8)
    ax.set_xlabel("element (0: veered ground point -> slot 0; last: last slot -> hauled ground point; "
                  "triangles: the smallest mean)", fontsize=8)
    ax.set_ylabel("tension [kN]")
    ax.set_title(f"Fig. 7 redone, scene {scene}: tension in the elements over the last period", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout(rect=(0, 0.3, 1, 1))
    _beside(fig, "7", claims, 0.3)
    save_small(fig, path)


def _zoom_s(runs: list[dict]) -> float:
    """The left column's span after the step [s]: three times the latest physical end (at least 10 s), or all."""
    phys = [r["end"].t_after_step_s for r in runs if r["end"].physical]
    return max(10.0, 3.0 * max(phys)) if phys else max(r["t_reached_s"] for r in runs)


def plot_step(runs: list[dict], path: Path, scene: str, claims: list[dict] | None = None) -> None:
    """Fig. 8: yaw, roll, pitch and alpha / beta of the followed wing after the 0.01 rad wind-direction step, each
    run to its end (a physical criterion, a numerical breakdown or the time limit), the end marked; left up to a
    little after the physical end, right the whole of every run."""
    fig = Figure(figsize=(14, 12))
    axs = fig.subplots(4, 2, sharex="col", width_ratios=(1, 1.6))
    zoom = _zoom_s(runs)
    for run in runs:
        r = {k: np.array([x[k] for x in run["rows"]]) for k in run["rows"][0]}
        end, t = run["end"], r["t_after_step_s"]
        yaw = np.degrees(np.unwrap(np.radians(r["yaw_deg"])))
        for col, keep in enumerate((t <= zoom + 1e-9, np.ones(t.size, dtype=bool))):
            line = axs[0, col].plot(t[keep], yaw[keep], label=f"{run['label']}: {end.outcome} at "
                                    f"{end.t_after_step_s:.1f} s")[0]
            for row, key in ((1, "roll_deg"), (2, "pitch_deg"), (3, "alpha_deg")):
                axs[row, col].plot(t[keep], r[key][keep], color=line.get_color())
            axs[3, col].plot(t[keep], r["beta_deg"][keep], ":", color=line.get_color())
            if end.t_after_step_s <= (zoom if col == 0 else np.inf):
                for ax in axs[:, col]:
                    ax.axvline(end.t_after_step_s, color=line.get_color(), lw=0.8, ls="-." if end.physical else ":")
    slot = runs[0]["slot"]
    for col in (0, 1):
        for y in (*ALPHA_RANGE_DEG, MAX_ABS_BETA_DEG, -MAX_ABS_BETA_DEG):
            axs[3, col].axhline(y, color="grey", lw=0.6, ls="--")
        for ax, name in zip(axs[:, col], (f"yaw (unwrapped), slot {slot}", "roll phi", "pitch theta",
                                          "alpha (solid), beta (dotted)"), strict=True):
            ax.set_ylabel(f"{name} [deg]", fontsize=8)
            ax.grid(alpha=0.3)
        axs[3, col].set_xlabel("time after the 0.01 rad wind-direction step [s]", fontsize=8)
    axs[0, 0].set_title(f"the first {zoom:.0f} s (vertical lines: the end of each run; dash-dot: a physical end)",
                        fontsize=8)
    axs[0, 1].set_title("every run to its end (dashed: range of accurate wing data)", fontsize=8)
    axs[0, 1].legend(fontsize=7)
    fig.suptitle(f"Fig. 8 redone, scene {scene}: wing in slot {slot}, 3D, V_c = 2 m/s, after a 0.01 rad "
                 "wind-direction step", fontsize=10)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    _beside(fig, "8", claims, 0.1)
    save_small(fig, path)


def plot_claims(claims: list[dict], path: Path, scene: str) -> None:
    """The panel of claims: the paper's words, our numbers and whether they agree, one row per claim."""
    cells = [[f"Fig. {c['figure']}", "\n".join(textwrap.wrap(c["paper"], 40)), "\n".join(textwrap.wrap(c["ours"], 90)),
              c["agrees"]] for c in claims]
    heights = [max(cell.count("\n") for cell in row) + 1 for row in cells]
    fig = Figure(figsize=(14, 0.9 + 0.19 * (sum(heights) + len(cells))))
    ax = fig.subplots()
    ax.axis("off")
    table = ax.table(cellText=cells, colLabels=["", "the paper", f"ours (scene {scene})", "agrees"],
                     colWidths=[0.05, 0.27, 0.6, 0.06], loc="upper center", cellLoc="left")
    table.auto_set_font_size(False)
    table.set_fontsize(7.5)
    unit = 1.0 / (sum(heights) + len(cells) + 1.5)
    for (i, _), cell in table.get_celld().items():
        cell.set_height(unit * (1.2 if i == 0 else heights[i - 1] + 1))
        if i > 0 and cells[i - 1][3] in ("yes", "no"):
            cell.set_facecolor("#e6f4e6" if cells[i - 1][3] == "yes" else "#fbe3e3")
    fig.suptitle("Meijaard et al. (1999), Figs. 6-8: the paper's claims and ours", fontsize=10)
    save_small(fig, path, bbox_inches="tight")
