"""Output of ``laddermill work-precision``: the CSV table, the log-log figure (error against wall time) and
the printed summary."""

from __future__ import annotations

import csv
import math
from pathlib import Path

COLUMNS = ("forcing", "method", "dt_s", "tol", "wall_s", "cpu_s", "real_time_factor", "err_final_pos_m",
           "err_rms_pos_m", "err_max_pos_m", "err_max_pos_rel", "err_final_state", "err_rms_state", "err_tension_rel",
           "err_power_rel", "err_lateral_m", "err_attitude_rad", "meets_controller", "status")
_STYLE = {"rk4": ("C0", "o", "-"), "rk4-all": ("C2", "+", "--"), "rk4-off": ("C3", "x", ":"),
          "dp54": ("C1", "s", "-"), "ros2": ("C4", "v", "-"), "ros34pw2": ("C5", "D", "-"),
          "ros34pw2a": ("C6", "*", "--"), "explicit": ("C0", "o", "-"), "implicit": ("C4", "v", "-")}
#: the accuracy of the summary's "fastest within" table: largest position error / the scene's extent
TARGET_REL = 1e-3


def fastest_within(res: dict, rel: float = TARGET_REL) -> list[dict]:
    """Per forcing and method, the fastest run whose largest position error relative to the scene's extent is at
    most ``rel``, and its speed-up over the fastest such run of the baseline (``res["baseline"]``, default RK4
    with breakpoints "inside"; the point-mass string's: its explicit method)."""
    out = []
    for f in res["references"]:
        best: dict[str, dict] = {}
        for r in res["rows"]:
            if r["forcing"] == f and r["status"] == "ok" and r.get("err_max_pos_rel", math.inf) <= rel:
                if r["method"] not in best or r["wall_s"] < best[r["method"]]["wall_s"]:
                    best[r["method"]] = r
        base = best.get(res.get("baseline", "rk4"))
        for m, r in best.items():
            out.append({"forcing": f, "method": m, "dt_s": r["dt_s"], "tol": r["tol"], "wall_s": r["wall_s"],
                        "real_time_factor": r["real_time_factor"], "err_max_pos_rel": r["err_max_pos_rel"],
                        "speedup_vs_rk4": base["wall_s"] / r["wall_s"] if base else math.nan})
    return out


def save_rows(res: dict, path: Path) -> Path:
    """One line per run, the columns of ``COLUMNS`` (units in the names; errors of the state are scaled)."""
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=["scene", *COLUMNS], extrasaction="ignore")
        w.writeheader()
        for r in res["rows"]:
            w.writerow({"scene": res["scene"], **r})
    return path


def plot_work_precision(res: dict, path: Path) -> Path:
    """Wall time against error, log-log: one column per forcing, rows the largest position error over the samples
    (over the extent) and the RMS state error; the references' agreement as a dotted line (errors below it are not
    resolved)."""
    from laddermill_gym.figure_files import subplots

    forcings = list(res["references"])
    fig, axes = subplots(2, len(forcings), figsize=(3.6 * len(forcings), 6.0), squeeze=False)
    for j, f in enumerate(forcings):
        rows = [r for r in res["rows"] if r["forcing"] == f and r["status"] == "ok"]
        for i, (key, label) in enumerate((("err_max_pos_rel", "largest position error / extent [-]"),
                                          ("err_rms_state", "RMS scaled state error [-]"))):
            ax = axes[i, j]
            for m in dict.fromkeys(r["method"] for r in rows):
                pts = [(r[key], r["wall_s"]) for r in rows if r["method"] == m and r[key] > 0]  # in step order
                if pts:
                    c, mk, ls = _STYLE.get(m, (None, "^", "-"))
                    ax.loglog(*zip(*pts, strict=True), marker=mk, ls=ls, color=c, label=m, ms=4)
            if key == "err_rms_state":
                ax.axvline(res["references"][f]["reference_agreement_state"], color="k", ls=":", lw=0.8)
            else:
                ax.axvline(TARGET_REL, color="0.5", ls="--", lw=0.8)
            ax.set_xlabel(label)
            ax.grid(True, which="both", lw=0.3)
            if j == 0:
                ax.set_ylabel("wall time [s]")
            if i == 0:
                ax.set_title(f"{res['scene']}: {f}", fontsize=9)
        axes[0, j].legend(fontsize=7)
    sep = "\n" if len(forcings) == 1 else "; "  # one column is too narrow for the title on one line
    fig.suptitle(f"{res['scene']}, {res['duration_s']:g} s simulated{sep}{res.get('baseline', 'rk4')} stable step "
                 f"{res['dt_stable_s']:.4g} s (estimate)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    return path


def _fmt(v, spec):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else format(v, spec)


def print_summary(res: dict, echo=print) -> None:
    """The table of runs and, per forcing and method, the fastest run within :data:`TARGET_REL` of the extent."""
    base = res.get("baseline", "rk4")
    lam = res["limiting_eigenvalue"]
    echo(f"\n== {res['scene']}: {res['duration_s']:g} s, {base} stable step {res['dt_stable_s']:.4g} s (eigenvalue "
         f"{lam[0]:.3g} +- {abs(lam[1]):.4g}i 1/s)")
    for f, ref in res["references"].items():
        names = " and ".join(f"{k[:-5]} at {v:g}" for k, v in ref.items() if k.endswith("_rtol"))
        echo(f"-- {f}: references ({names}) agree to {ref['reference_agreement_state']:.1e}"
             + "".join(f", {k[4:-20]} {v:.1e}" for k, v in ref.items() if k.endswith("_reference_agreement"))
             + (f"; extent {ref['extent_m']:.1f} m" if "extent_m" in ref else ""))
        echo(f"   {'method':9s} {'dt [s]':>9s} {'tol':>7s} {'wall [s]':>9s} {'x real':>8s} {'pos T [m]':>10s} "
             f"{'pos RMS':>9s} {'state T':>9s} {'state RMS':>9s}" + _CONTROLLER_HEAD)
        for r in (r for r in res["rows"] if r["forcing"] == f):
            if r["status"] != "ok":
                echo(f"   {r['method']:9s} {_fmt(r['dt_s'], '9.5f')} {_fmt(r['tol'], '7.0e')}  {r['status']}")
                continue
            echo(f"   {r['method']:9s} {_fmt(r['dt_s'], '9.5f')} {_fmt(r['tol'], '7.0e')} {r['wall_s']:9.3f} "
                 f"{r['real_time_factor']:8.1f} {r['err_final_pos_m']:10.2e} {r['err_rms_pos_m']:9.2e} "
                 f"{r['err_final_state']:9.2e} {r['err_rms_state']:9.2e}" + _controller_cells(r))

    echo(f"\n-- fastest run of each method with the largest position error <= {TARGET_REL:g} of the extent "
         f"(speed-up against the fastest such {base} run):")
    for r in fastest_within(res):
        echo(f"   {r['forcing']:7s} {r['method']:9s} {_fmt(r['dt_s'], '9.5f')} {_fmt(r['tol'], '7.0e')} "
             f"{r['real_time_factor']:8.1f}x real time  err/extent {r['err_max_pos_rel']:.2e}  "
             f"{_fmt(r['speedup_vs_rk4'], '.2f')}x {base}")
    print_controller_summary(res, echo)


#: the controller columns of the table of runs (``studies/numerics/controller_errors.py``)
_CONTROLLER_HEAD = f" {'tension':>8s} {'power':>8s} {'lat [m]':>8s} {'att [rad]':>9s} ctl"


def _controller_cells(r: dict) -> str:
    if "err_tension_rel" not in r:
        return ""
    return (f" {r['err_tension_rel']:8.1e} {r['err_power_rel']:8.1e} {r['err_lateral_m']:8.1e} "
            f"{r['err_attitude_rad']:9.1e} {'yes' if r['meets_controller'] else 'no'}")


def print_controller_summary(res: dict, echo=print) -> None:
    """Per forcing and method the fastest run meeting the controller tolerances, its errors and its speed-up over
    the fastest such baseline run (whose step it names); nothing for a study without the controller errors."""
    from laddermill_gym.studies.numerics.controller_errors import TOLERANCES, fastest_meeting

    if not any("meets_controller" in r for r in res["rows"]):
        return
    base = res.get("baseline", "rk4")
    tol = TOLERANCES
    echo(f"\n-- fastest run of each method meeting the controller tolerances (tension {tol['err_tension_rel']:g} and "
         f"power {tol['err_power_rel']:g} of their largest value, lateral offset {tol['err_lateral_m']:g} m, "
         f"attitude {tol['err_attitude_rad']:g} rad; speed-up against the fastest such {base} run in CPU time, one "
         "thread, and in wall time):")
    for f in res["references"]:
        rows = [r for r in fastest_meeting(res) if r["forcing"] == f]
        if not any(r["method"] == base for r in rows):
            echo(f"   {f:7s} no {base} run meets them")
        for r in rows:
            echo(f"   {r['forcing']:7s} {r['method']:9s} {_fmt(r['dt_s'], '9.5f')} {_fmt(r['tol'], '7.0e')} "
                 f"{r['real_time_factor']:8.1f}x real time  tension {r['err_tension_rel']:.1e} power "
                 f"{r['err_power_rel']:.1e} lat {r['err_lateral_m']:.1e} m att {r['err_attitude_rad']:.1e} rad  "
                 f"{_fmt(r['speedup_vs_rk4'], '.2f')}x {base} at {_fmt(r['rk4_dt_s'], '.5f')} s (wall "
                 f"{_fmt(r['speedup_wall'], '.2f')}x)")


def replot(json_path: Path, png_path: Path) -> Path:
    """Redraw the figure of a saved ``SCENE.json`` (no rerun)."""
    import json

    return plot_work_precision(json.loads(Path(json_path).read_text()), Path(png_path))
