"""The gust benchmark's scorecard figure: scenarios x controllers, coloured by the share of seeds survived, each
cell annotated with the median energy ratio against the undisturbed run, the largest lateral excursion and
the peak tension over its limit, and where a seed failed the median time of failure over the failed seeds
(``t_fail_s``)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np


def cell_text(s: dict) -> str:
    """The text of one scorecard cell from a summary row (``gust_results.summarise``): where a seed failed, the median
    time of failure over the failed seeds (``t_fail_s``); the energy ratio (when finite), the largest lateral
    excursion and the peak tension over its limit."""
    lines = []
    if s["survived"] < 1.0:
        lines.append(f"fails {s['t_fail_s']:.1f} s")
    if math.isfinite(s["energy_ratio"]):
        lines.append(f"E x{s['energy_ratio']:.2f}")
    lines.append(f"lat {s['max_lateral_m']:.3g} m")
    lines.append(f"T/T_max {s['peak_tension_ratio']:.2f}")
    return "\n".join(lines)


def plot_scorecard(summary: list[dict], env_id: str, suite: str, path: Path) -> Path:
    """Write the scorecard of one environment's summary rows (``gust_results.summarise``) to ``path`` (PNG)."""
    from laddermill_gym.figure_files import subplots

    scenarios = list(dict.fromkeys(s["scenario"] for s in summary))
    controllers = list(dict.fromkeys(s["controller"] for s in summary))
    grid = np.full((len(scenarios), len(controllers)), np.nan)
    cells = {(s["scenario"], s["controller"]): s for s in summary}
    for (sc, c), s in cells.items():
        grid[scenarios.index(sc), controllers.index(c)] = s["survived"]
    fig, ax = subplots(figsize=(2.2 + 2.0 * len(controllers), 1.0 + 0.75 * len(scenarios)))
    im = ax.imshow(grid, cmap="RdYlGn", vmin=0.0, vmax=1.0, aspect="auto")
    for (sc, c), s in cells.items():
        ax.text(controllers.index(c), scenarios.index(sc), cell_text(s), ha="center", va="center", fontsize=7)
    ax.set_xticks(range(len(controllers)), controllers)
    ax.set_yticks(range(len(scenarios)), scenarios)
    ax.set_title(f"{suite}: {env_id}")
    fig.colorbar(im, ax=ax, label="share of seeds survived")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    return path
