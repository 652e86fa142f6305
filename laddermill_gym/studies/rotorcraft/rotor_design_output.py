"""Files of the 35 m rotorcraft study: the CSV table of every operating point and the power-curve figure."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from laddermill_gym.studies.rotorcraft.rotor_design_data import ROBERTS_PEAK_POWER
from laddermill_gym.studies.rotorcraft.rotor_design_sweeps import AltitudeStudy

# ------------------------------------------------------------------------------------------ output
_CSV_HEAD = ["altitude_ft", "wind_m_s", "feasible", "power_MW", "cp", "alpha_c_deg", "theta0_deg", "mu",
             "tip_aoa_deg", "thrust_kN", "h_force_kN", "tension_kN", "stress_MPa", "utilisation",
             "anchor_angle_deg", "top_angle_deg", "chord_angle_deg", "tether_height_m", "binding"]


def write_csv(path: Path, studies: list[AltitudeStudy]) -> None:
    """One row per altitude and wind speed (columns ``_CSV_HEAD``; empty where no point is feasible)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(_CSV_HEAD)
        for st in studies:
            for v, p in zip(st.winds, st.points, strict=True):
                if p is None:
                    w.writerow([st.altitude_ft, f"{v:g}", 0] + [""] * (len(_CSV_HEAD) - 3))
                    continue
                t = p.tether
                vals = [p.power / 1e6, p.cp, math.degrees(p.alpha_c), math.degrees(p.theta0), p.mu,
                        math.degrees(p.tip_aoa), p.thrust / 1e3, p.h_force / 1e3, t.top_tension / 1e3,
                        p.stress / 1e6, p.utilisation, math.degrees(t.anchor_angle), math.degrees(t.top_angle),
                        math.degrees(t.chord_angle), t.height]
                w.writerow([st.altitude_ft, f"{v:g}", 1] + [f"{x:.6g}" for x in vals] + [p.binding or "none"])


def plot_power_curves(path: Path, studies: list[AltitudeStudy]) -> None:
    """Electrical power against wind speed at both altitudes with Roberts' 3.13 MW and the stress-limit onset."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    fig, ax = subplots(figsize=(8.0, 5.2))
    for st in studies:
        power = np.array([p.power / 1e6 if p is not None else np.nan for p in st.points])
        line, = ax.plot(st.winds, power, "-o", ms=3, lw=1.5, label=f"{st.altitude_ft:,} ft")
        if st.stress_onset is not None:
            ax.plot(st.stress_onset.wind, st.stress_onset.power / 1e6, "s", ms=8, mfc="none",
                    color=line.get_color(), label=f"{st.altitude_ft:,} ft: tether stress limit reached")
        if math.isfinite(st.wind_for_roberts):
            ax.axvline(st.wind_for_roberts, color=line.get_color(), ls=":", lw=1.0)
    ax.axhline(ROBERTS_PEAK_POWER / 1e6, color="k", ls="--", lw=1.0)
    ax.text(studies[0].winds[0], ROBERTS_PEAK_POWER / 1e6 + 0.15, "Roberts, Table 1: 3.13 MW peak", fontsize=9)
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xlabel("wind speed at the craft V [m/s]")
    ax.set_ylabel("electrical power 2 (-Q Omega) 0.95 [MW]")
    ax.set_title("Twin 35 m rotorcraft: best steady power within the blade limit, lift and tether stress\n"
                 "(dotted: wind at which 3.13 MW is reached; below zero the craft draws power to stay up)",
                 fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)
    save_figure(fig, path)
