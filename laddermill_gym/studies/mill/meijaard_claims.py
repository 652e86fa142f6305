"""The paper's claims about its Figs. 6-8 (Meijaard, Ockels & Schwab 1999, "Examples of application") next to what
the Meijaard study (``studies/mill/meijaard.py``) measured: one row per claim with the paper's words, our numbers and
whether they agree (``"yes"``, ``"no"``, or ``"-"`` where the paper gives no yes/no claim to judge).

The criteria, fixed before the runs (the paper's words are qualitative):

* "the loop widens": the smallest loop width sampled at the higher V_c above the largest at the lower one;
* "smallest near the top": the element of the smallest period-mean tension has its midpoint in the upper
  :data:`TOP_FRACTION` of the loop's height above the station;
* "which value increases as the loop widens": that smallest tension is larger at the higher V_c;
* "a fair estimate of the power": (T_first - T_last) V_c within :data:`ESTIMATE_TOL` of the generator's mean power;
* "of the order of 200 kW": at least :data:`POWER_FLOOR_W` (issue 30 point 2's reading) in a periodic motion;
* "yaws over a large angle": node 40's yaw leaves its start by more than the fins' stall sideslip,
  ``MAX_ABS_BETA_DEG`` (the end of the wing's accurate data), before the run ends;
* "with a smaller step size, the simulation could be continued longer": of the fixed-step runs that did not end
  physically, the one with the smallest step reached a later time than the one with the largest;
* "the angles of attack, the side-slip angle ... come in a range for which the aerodynamic data ... are no longer
  accurate": some wing's alpha or beta leaves the band of accurate data before the reference run ends.
"""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.sim.recording import MAX_ABS_BETA_DEG

#: [-] "near the top": the upper tenth of the loop's height above the station (chosen; the paper: "near the top")
TOP_FRACTION = 0.9
#: [-] relative agreement of (T_first - T_last) V_c with the generator's mean power ("a fair estimate"; chosen: 3 %)
ESTIMATE_TOL = 0.03
#: [W] "of the order of 200 kW": at least 150 kW (issue 30 point 2)
POWER_FLOOR_W = 150e3
PAPER_END_S = 40.0  # [s] "the calculations break down after some 40 seconds"


def min_tension_place(shape: np.ndarray, ground: tuple[np.ndarray, np.ndarray], tension_mean: np.ndarray) -> dict:
    """The element with the smallest mean tension (n_e = n_wings + 1, one element per piece), its tension [N] and
    the height of its midpoint over the loop's height above the station [-] (shape (n_wings, 3) [m], z down)."""
    pts = np.vstack([ground[0], shape, ground[1]])
    h = -pts[:, 2]
    if len(tension_mean) != len(pts) - 1:
        raise ValueError(f"min_tension_place: {len(tension_mean)} elements for {len(shape)} wings; the claim needs "
                         f"one element per piece ({len(pts) - 1})")
    k = int(np.argmin(tension_mean))
    base = 0.5 * (h[0] + h[-1])
    frac = (0.5 * (h[k] + h[k + 1]) - base) / (h.max() - base)
    return {"element": k, "tension_N": float(tension_mean[k]), "height_fraction": float(frac),
            "near_top": bool(frac >= TOP_FRACTION), "loop_height_m": float(h.max() - base)}


def yaw_excursion_deg(rows: list[dict], until_s: float) -> float:
    """Largest |yaw - yaw at the first sample| [deg] (yaw unwrapped) of the samples up to ``until_s`` after the step."""
    t = np.array([r["t_after_step_s"] for r in rows])
    yaw = np.degrees(np.unwrap(np.radians([r["yaw_deg"] for r in rows])))
    keep = t <= until_s + 1e-9
    return float(np.max(np.abs(yaw[keep] - yaw[0])))


def _yn(ok: bool | None) -> str:
    return "-" if ok is None else ("yes" if ok else "no")


def _periodic(row: dict) -> str:
    return "" if row["periodic"] else " (NOT periodic: the end of the search)"


def fig6_7_claims(lo: dict, hi: dict, places: dict) -> list[dict]:
    """Claims of Figs. 6 and 7 from the rows of the lower and higher V_c (``meijaard.case_row``) and the
    :func:`min_tension_place` of each (keyed by V_c)."""
    v_lo, v_hi = lo["V_c_m_s"], hi["V_c_m_s"]
    widens = hi["width_min_m"] > lo["width_max_m"]
    out = [{"figure": "6", "paper": f"legs almost parallel at low V_c ({v_lo:g} m/s)",
            "ours": f"loop {lo['loop_width_m']:.0f} m wide on average for a top {places[v_lo]['loop_height_m']:.0f} m "
                    f"above the station (width / height {lo['loop_width_m'] / places[v_lo]['loop_height_m']:.3f})"
                    f"{_periodic(lo)}", "agrees": "-"},
           {"figure": "6", "paper": f"the loop widens with V_c ({v_lo:g} -> {v_hi:g} m/s)",
            "ours": f"loop width {lo['width_min_m']:.0f}-{lo['width_max_m']:.0f} m at {v_lo:g} m/s{_periodic(lo)}; "
                    f"{hi['width_min_m']:.0f}-{hi['width_max_m']:.0f} m at {v_hi:g} m/s{_periodic(hi)}",
            "agrees": _yn(widens)}]
    for row in (lo, hi):
        p = places[row["V_c_m_s"]]
        out.append({"figure": "7", "paper": f"tension smallest near the top (V_c = {row['V_c_m_s']:g} m/s)",
                    "ours": f"smallest mean tension {p['tension_N'] / 1e3:.1f} kN in element {p['element']}, at "
                            f"{p['height_fraction']:.2f} of the loop's height{_periodic(row)}",
                    "agrees": _yn(p["near_top"])})
    t_lo, t_hi = places[v_lo]["tension_N"], places[v_hi]["tension_N"]
    out.append({"figure": "7", "paper": "the smallest tension increases as the loop widens",
                "ours": f"{t_lo / 1e3:.1f} kN at {v_lo:g} m/s -> {t_hi / 1e3:.1f} kN at {v_hi:g} m/s",
                "agrees": _yn(t_hi > t_lo)})
    return out


def power_claims(rows: list[dict]) -> list[dict]:
    """The power claims per case row: the estimate (T_first - T_last) V_c against the generator's mean power, and
    the power against "of the order of 200 kW"."""
    out = []
    for r in rows:
        p, est = r["mean_power_kW"], r["tension_estimate_kW"]
        rel = abs(est - p) / max(abs(p), 1e-9)
        out.append({"figure": "7", "paper": f"power ~ (T_first - T_last) V_c ({r['case']})",
                    "ours": f"({r['T_first_kN']:.1f} - {r['T_last_kN']:.1f}) kN x {r['V_c_m_s']:g} m/s = {est:.1f} kW;"
                            f" generator {p:.1f} kW ({100 * rel:.2f} %)", "agrees": _yn(rel <= ESTIMATE_TOL)})
        late = "" if r["periodic"] else (f"; the last {r['late_periods']} period means {r['late_power_min_kW']:.0f} "
                                         f"to {r['late_power_max_kW']:.0f} kW, mean {r['late_power_mean_kW']:.1f} kW")
        out.append({"figure": "7", "paper": f"power of the order of 200 kW ({r['case']})",
                    "ours": f"{p:.1f} kW{_periodic(r)}{late}",
                    "agrees": _yn(bool(r["periodic"]) and p * 1e3 >= POWER_FLOOR_W)})
    return out


def fig8_claims(runs: list[dict]) -> list[dict]:
    """Claims of Fig. 8 from the direction-step runs (``meijaard.direction_step``; the first is the reference, RK4
    at the scene's step with the physical end criteria): node 40's yaw before the physical end and over the longest
    run, and when the runs end against the paper's ~40 s breakdown."""
    ref = runs[0]
    end = ref["end"]
    yaw_end = yaw_excursion_deg(ref["rows"], end.t_after_step_s)
    longest = max(runs, key=lambda r: r["t_reached_s"])
    yaw_long = yaw_excursion_deg(longest["rows"], longest["t_reached_s"])
    slot = ref["slot"]
    out = [{"figure": "8", "paper": f"node {slot} yaws over a large angle",
            "ours": f"|yaw change| up to {yaw_end:.0f} deg before the end at {end.t_after_step_s:.1f} s "
                    f"({ref['label']}); {yaw_long:.0f} deg over {longest['t_reached_s']:.1f} s ({longest['label']})",
            "agrees": _yn(max(yaw_end, yaw_long) > MAX_ABS_BETA_DEG)}]
    ends = "; ".join(f"{r['label']}: {r['end'].outcome} at {r['end'].t_after_step_s:.1f} s" for r in runs)
    phys = [r["end"].t_after_step_s for r in runs if r["end"].physical]
    out.append({"figure": "8", "paper": f"the calculation breaks down after some {PAPER_END_S:g} s",
                "ours": ends + (f"; physical end first at {min(phys):.1f} s" if phys else ""), "agrees": "-"})
    free = sorted((r for r in runs if r.get("method") == "rk4" and not r["end"].physical), key=lambda r: r["dt_s"])
    if len(free) >= 2 and free[0]["dt_s"] < free[-1]["dt_s"]:
        small, large = free[0], free[-1]
        out.append({"figure": "8", "paper": "with a smaller step the simulation could be continued longer",
                    "ours": f"{large['label']}: {large['end'].outcome} at {large['t_reached_s']:.1f} s; "
                            f"{small['label']}: {small['end'].outcome} at {small['t_reached_s']:.1f} s",
                    "agrees": _yn(small["t_reached_s"] > large["t_reached_s"])})
    exits = [ref[k] for k in ("alpha_exit_any_s", "beta_exit_any_s") if math.isfinite(ref[k])]
    out.append({"figure": "8", "paper": "alpha and sideslip leave the range of accurate wing data",
                "ours": f"some wing leaves it in alpha at {ref['alpha_exit_any_s']:.1f} s, in beta at "
                        f"{ref['beta_exit_any_s']:.1f} s; slot {slot} at {ref['alpha_exit_slot_s']:.1f} / "
                        f"{ref['beta_exit_slot_s']:.1f} s (nan: never; {ref['label']})",
                "agrees": _yn(any(t <= end.t_after_step_s + 1e-9 for t in exits))})
    return out


def all_claims(rows2d: dict, places: dict, runs: list[dict], lo: float = 1.0, hi: float = 5.0) -> list[dict]:
    """Every claim row: Figs. 6-7 where both ``lo`` and ``hi`` [m/s] were run in plane (``rows2d`` keyed by V_c),
    the power claims of every 2D row, and Fig. 8 where direction-step runs are given."""
    out = fig6_7_claims(rows2d[lo], rows2d[hi], places) if lo in rows2d and hi in rows2d else []
    out += power_claims([rows2d[v] for v in sorted(rows2d)])
    return out + (fig8_claims(runs) if runs else [])


def claims_text(claims: list[dict]) -> str:
    """The printed table: one line per claim."""
    w = max((len(c["paper"]) for c in claims), default=0)
    return "\n".join(f"Fig. {c['figure']} | {c['paper']:<{w}} | {c['agrees']:<3} | {c['ours']}" for c in claims)

