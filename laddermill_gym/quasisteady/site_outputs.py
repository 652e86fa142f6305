"""Tables and figures of the site study, like Lansdorp et al. (2008): Tables 1-2 beside the paper's values,
Figs. 10-13 (power series, histograms of power, C_L and tension), 14-18 (sensitivity), 19-20 (a fixed design run
through the data with the reeling factor up to 1/3 or 1/2), the two quasi-steady models side by side, and the
turbine comparison."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from laddermill_gym.figure_files import subplots
from laddermill_gym.quasisteady import lansdorp, schmehl
from laddermill_gym.quasisteady.site_optimise import PAPER, SiteResult

ROWS = (("Kite altitude", "m"), ("Cable angle", "deg"), ("Cable diameter", "mm"), ("Kite area", "m^2"),
        ("Average kite C_L", "-"))


def design_values(r: SiteResult, weight: np.ndarray) -> tuple[float, ...]:
    """(altitude [m], angle [deg], diameter [mm], area [m^2], time-mean C_L) of a result."""
    d = r.design
    cl = float(np.sum(weight * r.solution.cl) / np.sum(weight))
    return d.h, np.degrees(d.theta), 1e3 * d.d, d.S, cl


def table_markdown(case_name: str, results: dict[str, tuple[SiteResult, np.ndarray, str]]) -> str:
    """Markdown table of one case: the paper's value (De Bilt soundings) beside ours per data set; ``results``
    maps a data-set label to (result, weights, note)."""
    labels = list(results)
    head = "| parameter | unit | paper (De Bilt 1998-2007) | " + " | ".join(f"ours: {k}" for k in labels) + " |"
    lines = [head, "|" + "---|" * (3 + len(labels))]
    ours = {k: design_values(r, w) for k, (r, w, _) in results.items()}
    fmt = ("{:.1f}", "{:.1f}", "{:.2f}", "{:.1f}", "{:.2f}")
    for j, (name, unit) in enumerate(ROWS):
        cells = [fmt[j].format(ours[k][j]) for k in labels]
        lines.append(f"| {name} | {unit} | {fmt[j].format(PAPER[case_name][j])} | " + " | ".join(cells) + " |")
    extra = [("Cable length", "m", lambda r: f"{r.design.length:.0f}"),
             ("Mean power", "MW", lambda r: f"{r.solution.mean_power / 1e6:.3f}"),
             ("Mean tension", "kN", lambda r: f"{r.solution.mean_tension / 1e3:.1f}"),
             ("Cable strength F_max (eq. 15)", "kN", lambda r: f"{r.solution.f_max / 1e3:.1f}"),
             ("Power target met (eq. 19)", "-", lambda r: "yes" if r.feasible else "**NO** (infeasible)"),
             ("On a bound of the search", "-", lambda r: "; ".join(r.at_bounds) or "none"),
             ("Wind states", "-", lambda r: f"{r.states}"),
             ("Optimisation wall time", "s", lambda r: f"{r.wall_time:.2f}")]
    for name, unit, f in extra:
        lines.append(f"| {name} | {unit} | | " + " | ".join(f(results[k][0]) for k in labels) + " |")
    notes = [f"- {k}: {note}" for k, (_, _, note) in results.items() if note]
    return "\n".join(lines + [""] + notes) + "\n"


def time_histogram(ax, x, w, bins, xlabel) -> np.ndarray:
    """Histogram of ``x`` (n,) on ``ax``, each state weighted by its share of the whole time ``w`` (n,) [-]: the bars
    add up to the share the data cover (the Cabauw bins' 56.6 %; the time outside the data counts as no power, as
    in the time means), said on the axis when below 100 %. Returns the bar heights [% of the time]."""
    heights, _, _ = ax.hist(x, bins=bins, weights=100 * w, color="tab:blue", edgecolor="white")
    ax.set_xlabel(xlabel)
    cover = 100 * float(np.sum(w))
    ax.set_ylabel("share of time [%]" if cover > 99.95 else f"share of time [%] (bars: {cover:.1f} %, the data)")
    return heights


def plot_design(r: SiteResult, weight: np.ndarray, labels, path: Path, title: str) -> Path:
    """Figs. 10-13: power per state (in data order), histograms of power, C_L and tension / F_max."""
    s = r.solution
    fig, ax = subplots(2, 2, figsize=(11, 7))
    ax[0, 0].plot(np.arange(s.power.size), s.power / 1e6, lw=0.6)
    ax[0, 0].axhline(s.mean_power / 1e6, color="k", ls="--", lw=0.8, label=f"mean {s.mean_power / 1e6:.2f} MW")
    ax[0, 0].set_xlabel(f"wind state ({labels[0]} ... {labels[-1]})")
    ax[0, 0].set_ylabel("useful power [MW]")
    ax[0, 0].legend()
    time_histogram(ax[0, 1], s.power / 1e6, weight, 30, "useful power [MW] (Fig. 11)")
    time_histogram(ax[1, 0], s.cl, weight, np.linspace(0, 1.2, 25), "kite C_L (Fig. 12)")
    time_histogram(ax[1, 1], s.tension / s.f_max, weight, np.linspace(0, 1, 21), "tension / F_max (Fig. 13)")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def plot_operation(runs: dict[str, tuple[np.ndarray, np.ndarray]], weight, path: Path, title: str) -> Path:
    """Figs. 19-20: histograms of power and C_L of a fixed design, one row per reeling-factor bound; the mean in
    each title is the time mean, sum_i p_i P_i (time the weights do not cover counts as no power)."""
    fig, ax = subplots(len(runs), 2, figsize=(10, 3.2 * len(runs)), squeeze=False)
    for i, (label, (P, cl)) in enumerate(runs.items()):
        mean = np.sum(weight * P)
        time_histogram(ax[i, 0], P / 1e6, weight, 30, f"useful power [MW], {label}: mean {mean / 1e6:.2f} MW")
        time_histogram(ax[i, 1], cl, weight, np.linspace(0, 1.2, 25), f"kite C_L, {label}")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def plot_sweeps(sweeps: dict[str, tuple[np.ndarray, list[SiteResult], str]], path: Path, title: str) -> Path:
    """Figs. 15-18: mean power per cost (relative to the sweep's best), kite area, cable diameter and altitude
    against the swept parameter."""
    fig, ax = subplots(4, len(sweeps), figsize=(3.4 * len(sweeps), 10), squeeze=False)
    for j, (name, (values, res, unit)) in enumerate(sweeps.items()):
        ok = [r.feasible for r in res]
        ratio = np.array([r.solution.ratio for r in res])
        rows = (ratio / np.max(ratio[ok]) if any(ok) else ratio, [r.design.S for r in res],
                [1e3 * r.design.d for r in res], [r.design.h for r in res])
        for i, (y, lab) in enumerate(zip(rows, ("power / cost [rel.]", "kite area [m^2]", "cable diameter [mm]",
                                                 "altitude [m]"), strict=True)):
            ax[i, j].plot(values, y, "o-")
            ax[i, j].set_ylabel(lab)
        ax[-1, j].set_xlabel(f"{name} [{unit}]")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def plot_altitude_angle(hs, thetas, grid, path: Path, title: str) -> Path:
    """Fig. 14: power per cost, cable diameter and kite area over altitude x cable angle (blank: cable shorter
    than gamma Delta L)."""
    def field(f):
        return np.array([[np.nan if r is None else f(r) for r in row] for row in grid])

    ratio = field(lambda r: r.solution.ratio)
    panels = ((ratio / np.nanmax(ratio), "power / cost [rel.]"), (field(lambda r: 1e3 * r.design.d), "d [mm]"),
              (field(lambda r: r.design.S), "S [m^2]"))
    fig, ax = subplots(1, 3, figsize=(14, 4))
    for a, (z, lab) in zip(ax, panels, strict=True):
        m = a.pcolormesh(np.degrees(thetas), hs, z, shading="nearest")
        fig.colorbar(m, ax=a, label=lab)
        a.set_xlabel("cable angle from vertical [deg]")
        a.set_ylabel("altitude [m]")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def model_power_curves(case, design, speeds):
    """Best useful power [W] per wind speed of the design under both models: C_L on a grid up to C_L,max, the
    tension within eq. 15, reel-out 1/3 of the wind. Returns {model name: (n,) power}."""
    cls = np.linspace(0.005, case.cl_max, 240)
    f_max = lansdorp.max_cable_force(design.d, case.params)
    out = {}
    for name, mod in (("Lansdorp et al. 2008", lansdorp), ("Schmehl / van der Vlugt", schmehl)):
        best = np.zeros_like(speeds)
        for cl in cls:
            r = mod.cycle_power(speeds, design.h, design.theta, design.d, design.S, cl, case.kite_cd(cl),
                                case.params, case.reel_out_factor)
            best = np.maximum(best, np.where(r.tension_out <= f_max, r.power, 0.0))
        out[name] = best
    return out


def model_ratio_text(curves, speeds, at=(4.0, 6.0, 8.0, 12.0, 16.0, 20.0, 25.0)) -> str:
    """One line for ``model_power_curves``' result: Schmehl's best power over Lansdorp's at the winds ``at`` [m/s]
    (points of ``speeds``) and the lowest wind where Schmehl's kite can fly its whole loop (power above 0)."""
    lans, sch = curves["Lansdorp et al. 2008"], curves["Schmehl / van der Vlugt"]
    idx = [int(np.argmin(np.abs(speeds - v))) for v in at]
    ratios = " ".join(f"{sch[i] / lans[i]:.2f}" if lans[i] > 0 else "n/a" for i in idx)
    flown = speeds[sch > 0]
    start = f"from {flown[0]:g} m/s" if flown.size else "at none of them"
    return (f"Schmehl's best power / Lansdorp's at {', '.join(f'{speeds[i]:g}' for i in idx)} m/s: {ratios}; "
            f"Schmehl's loop flown {start} ({speeds[0]:g}-{speeds[-1]:g} m/s)")


def plot_models(curves, speeds, path: Path, title: str) -> Path:
    fig, ax = subplots(figsize=(7, 4))
    for name, P in curves.items():
        ax.plot(speeds, P / 1e6, label=name)
    ax.set_xlabel("wind speed at the kite [m/s]")
    ax.set_ylabel("useful cycle power [MW]")
    ax.legend()
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def plot_yields(yields, path: Path, title: str) -> Path:
    fig, ax = subplots(figsize=(7, 3.5))
    ax.barh([y.name for y in yields], [100 * y.capacity_factor for y in yields], color="tab:green")
    for i, y in enumerate(yields):
        ax.text(100 * y.capacity_factor + 0.5, i, f"{100 * y.capacity_factor:.1f} %", va="center")
    ax.set_xlabel("capacity factor [%]")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path
