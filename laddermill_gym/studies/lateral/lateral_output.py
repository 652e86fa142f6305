"""Output of the lateral study: the text table of every variant and the figure of the sweeps."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from laddermill_gym.studies.lateral.lateral_analysis import SweepResult


def format_table(results: list[SweepResult], crossings: dict[str, dict[str, list[float]]] | None = None) -> str:
    """Text table: one line per variant (value, largest real part [1/s], period [s], growth rate of the
    oscillation [1/s], time to double [s], trim elevator [deg], tether elevation [deg]); ``crossings`` maps a
    sweep name to {quantity: parameter values where it is zero} (from :func:`sign_changes`)."""
    lines = ["(* default; ! trim elevator outside the wing's control limits)"]
    for res in results:
        lines.append(f"\n{res.spec.name}: {res.spec.label} (default {res.spec.default:.4g})")
        lines.append("     value   max Re [1/s]  period [s]  osc Re [1/s]  t2x [s]  elevator [deg]  elevation [deg]")
        for v in res.variants:
            mark = " *" if math.isclose(v.value, res.spec.default, rel_tol=1e-9, abs_tol=1e-12) else "  "
            if v.error:
                lines.append(f"{v.value:10.4g}{mark}  trim failed: {v.error[:80]}")
                continue
            t2 = math.log(2) / v.max_real if v.max_real > 0 else float("inf")
            flag = " " if v.elevator_in_limits else "!"
            lines.append(f"{v.value:10.4g}{mark} {v.max_real:12.4f} {v.period:11.2f} {v.osc_real:13.4f} {t2:8.1f} "
                         f"{v.elevator_deg:14.2f}{flag} {v.elevation_deg:16.1f}")
        for quantity, label in (("max_real", "max Re"), ("osc_real", "Re of the slow oscillation")):
            changes = (crossings or {}).get(res.spec.name, {}).get(quantity, [])
            if changes:
                lines.append(f"  {label} = 0 at {res.spec.name} = " + ", ".join(f"{c:.3g}" for c in changes))
    return "\n".join(lines)


def plot_sweeps(results: list[SweepResult], out: Path) -> Path:
    """One panel per sweep: largest real part of the lateral eigenvalues [1/s] versus the parameter, with
    the zero line and the default value marked. Saved to ``out`` (png, pdf or svg)."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    n = len(results)
    ncol = min(3, n)
    nrow = math.ceil(n / ncol)
    fig, axes = subplots(nrow, ncol, figsize=(4.2 * ncol, 3.3 * nrow), squeeze=False)
    for ax, res in zip(axes.flat, results, strict=False):
        x, y = res.values, res.max_real
        ax.axhline(0.0, color="k", lw=0.8)
        ax.plot(x, y, "o-", color="C0", label="max Re")
        osc = np.array([v.osc_real for v in res.variants])
        ax.plot(x, osc, "s--", color="C1", ms=3, lw=0.8, label="Re of slow oscillation")
        ax.axvline(res.spec.default, color="C3", ls=":", lw=1.2, label="default")
        at = np.isclose(x, res.spec.default, rtol=1e-9, atol=1e-12)
        ax.plot(x[at], y[at], "*", color="C3", ms=12)
        bad = ~np.isfinite(y)
        if bad.any():
            ax.plot(x[bad], np.zeros(bad.sum()), "x", color="C3", label="trim failed")
        ax.set_xlabel(res.spec.label)
        ax.set_ylabel("largest Re(lambda) [1/s]")
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("tethered_wing: open-loop lateral eigenvalues, one parameter at a time (> 0: unstable)")
    return save_figure(fig, out)
