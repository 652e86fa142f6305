"""The ledger entries (:mod:`docsite.page_ledger`) of the pages on papers: Roberts, Podgaets & Ockels, Meijaard
et al., Lansdorp et al."""

from __future__ import annotations

import re

from docsite.host_cpu import only_on
from docsite.ledger_kinds import ROW_END, Covered, History, Printed

RD = r"(\d+\.\d) m/s at 15,000 ft and at (\d+\.\d) m/s at 30,000 ft"
ROBERTS = Covered(
    groups=("rotor_design",),
    checks=((r"The study reaches that rating at " + RD, ("{rotor_design[15kft][wind]}", "{rotor_design[30kft][wind]}")),
            (r"disks at only (\d+)-(\d+) deg to the wind", ("{rotor_design[30kft][alpha_c]:.0f}",
                                                            "{rotor_design[15kft][alpha_c]:.0f}")),
            (r"rotor at C_p (0\.\d\d) and (0\.\d\d) \(Betz: 0\.593\)", ("{rotor_design[15kft][ideal_cp]:.2f}",
                                                                    "{rotor_design[30kft][ideal_cp]:.2f}"))),
    given=("eq. 1,", "Fig. 3", "(eqs. 2-3)", "eq. (6)", "Eq. (6)", "the 35 m design", "Table 1", "The 35 m design",
           "Roberts' 35 m design", "twin 35 m rotors on three 0.23 kg/m tethers", "Table 1's 3.13 MW",
           "3.13 MW x 8760 h x 48 %", "his 13.3 GWh", "(Betz: 0.593)"),
    derived=("is 13.2 GWh",),
)

PODGAETS = Covered(
    groups=("pointmass_benchmark", "simulate_laddermill", "pointmass_mill"),
    checks=((r"scene (?:`podgaets_5km`)?\s?: ([\d,]+) elements, (\d+\.\d\d) MB of arrays held on two threads",
             ("{pointmass_benchmark[elements]}", "{pointmass_benchmark[held_MB]}")),
            (r"held to ([\d.e-]+) s steps by the Voigt damping", ("{pointmass_benchmark[explicit_dt]}",)),
            (r"\(the rigid mill: ([\d.]+) kW\)", ("{simulate_laddermill[periodic_kW]}",)),
            (r"periodic at 2 m/s with ([\d.]+) kW at 1 m elements and ([\d.]+) kW at 70 m",
             ("{pointmass_mill[l1][power_kW]}", "{pointmass_mill[l70][power_kW]}"))),
    given=("Podgaets & Ockels (2007)", "laddermill*, 2007.", "(5 km of cable at 1 cm with 100 kites in 82 MB)",
           "| 5 km at 1 cm with 100 kites in 82 MB", "steps at the kites' 10 ms", "on the 5 km string",
           "the moving cable's row again on 2026-12-07", "That row changed on 2026-12-07"),
    # the pay-out bug's cost: 90.0 - 88.2 and 90.1 - 82.4 kW (pointmass_mill.md's record of 2026-11-24)
    derived=("which had cost the mill 2-8 kW",),
    timings=("the process peaks at 216 MB with numba's cache warm", "0.18x real time on one thread on the 2-core "
             "machine", "7.5x real time at 1 m, 207x at 70 m", "measured on this project's 2-core machine"),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        Printed('pointmass_fidelity', (
            'tensions within 1 % of the rigid',
        )),
    ),  # pointmass_fidelity
)


MJ = "~{meijaard_v1[%s]}"
Z3 = only_on("znver3")  # the 5 m/s search is chaotic: the page's table is znver3's, znver4's beside it
MEIJAARD_CHECKS = (  # the checks of docsite/ledger_meijaard.py's entry
    ((r"at 1 m/s \(periodic at (\d+) s\) the loop is (\d+) m wide",
             (MJ % "2D_1][t_end_s", MJ % "2D_1][loop_width_m")),
            (Z3 + r"(\d+)-(\d+) m at 1 m/s; (\d+)-(\d+) m at 5 m/s, \*\*not periodic\*\* within ([\d,]+) s",
             (MJ % "2D_1][width_min_m", MJ % "2D_1][width_max_m", MJ % "2D_5][width_min_m", MJ % "2D_5][width_max_m",
              MJ % "2D_5][t_end_s")),
            (Z3 + r"1 m/s: ([\d.]+) kN in element (\d+); 5 m/s: ([\d.]+) kN in element (\d+)",
             (MJ % "2D_1][T_min_kN", MJ % "2D_1][T_min_element", MJ % "2D_5][T_min_kN", MJ % "2D_5][T_min_element")),
            (Z3 + r"1 m/s: \(([\d.]+) - ([\d.]+)\) kN x 1 m/s = ([\d.]+) kW, generator ([\d.]+) kW; 2 m/s: "
             r"\(([\d.]+) - ([\d.]+)\) x 2 = ([\d.]+) kW, generator ([\d.]+) kW; 5 m/s: ([\d.]+) vs ([\d.]+) kW",
             tuple(MJ % f"2D_{v}][{k}" for v in (1, 2) for k in ("T_first_kN", "T_last_kN", "tension_estimate_kW",
                                                                "mean_power_kW"))
             + (MJ % "2D_5][tension_estimate_kW", MJ % "2D_5][mean_power_kW")),
            (r"\*\*([\d.]+) kW at 2 m/s\*\* \(3D: ([\d.]+) kW\)",
             (MJ % "2D_2][mean_power_kW", MJ % "3D_2][mean_power_kW")),
            (Z3 + r"period means ([-\d,.]+) to ([\d,.]+) kW over the last (\d+) periods \(mean ([\d.]+) kW\)",
             (MJ % "2D_5][late_power_min_kW", MJ % "2D_5][late_power_max_kW", MJ % "2D_5][late_periods",
              MJ % "2D_5][late_power_mean_kW")),
            (Z3 + r"search stays below the cable's breaking load \(peak ([\d.]+) times it\) and the 2 m/s one passes "
             r"it in the transient from rest \(element 0 at ([\d.]+) s, ([\d.]+) times it\)",
             (MJ % "2D_5][peak_tension_ratio", MJ % "2D_2][overload_s", MJ % "2D_2][peak_tension_ratio")),
            (r"lowest wing CG [\d.]+ m, peak tension ([\d.]+) of the breaking load",  # v1's, not v0's 57.9 m one
             (MJ % "3D_2][peak_tension_ratio",))))


ST, PC = "{site_tables[%s]}", "{pumping_cycle_lqr[%s]}"
T2 = r"\| {} \| {} \| ([\d.]+) \| ([\d.]+) \|"
PE = "{pumping_evaluate[%s]}"
EVAL_ROW = r"\| {} \| ([-\d]+) \| ([\d.]+) s{} \| ([\d.]+) m \| ([\d.]+ k?W) \|"


def _evaluate_rows() -> tuple:
    """docs/paper_lansdorp2008.md's evaluation table: the open loop's, the scripted cycle's and the LQR's rows."""
    out = []
    for label, key, failed in (("open loop", "open_loop", True), ("scripted cycle", "scripted", True),
                               ("scripted cycle \\+ lateral LQR", "lqr", False)):
        out.append((EVAL_ROW.format(label, r" \(([a-z ]+)\)" if failed else ""),
                    ("~" + PE % f"{key}][return", "~" + PE % f"{key}][length",
                     *((PE % f"{key}][failure",) if failed else ()), "~" + PE % f"{key}][dy",
                     PE % f"{key}][power_text")))
    return tuple(out)


LANSDORP = Covered(
    groups=("site_tables", "pumping_cycle_lqr", "pumping_evaluate"),
    checks=tuple((T2.format(re.escape(label), paper), (ST % f"weather2010][{key}", ST % f"cabauw][{key}"))
                 for label, paper, key in (("altitude [m]", "272.3", "altitude"), ("cable angle [deg]", "57", "angle"),
                                           ("cable diameter [mm]", "32.43", "diameter"),
                                           ("kite area [m^2]", "168.8", "area"), ("mean C_L", "1.01", "cl")))
    + ((r"The Cabauw clusters cover ([\d.]+) % of the time", (ST % "cabauw][covered_pct",)),
       (r"80 m hub: ([\d.]+) % against ([\d.]+) % \((\S+)\) on the 2010 data \(the kite at ([\d.]+) m, on extrapolated "
        r"wind\), but ([\d.]+) % against ([\d.]+) % \((\S+)\) on Cabauw",
        tuple(ST % f"weather2010][{k}" for k in ("kite_cf", "turbine_cf", "turbine", "altitude_m"))
        + tuple(ST % f"cabauw][{k}" for k in ("kite_cf", "turbine_cf", "turbine"))),
       (r"with the lateral LQR: ([\d.-]+) kW per cycle after the first \(which starts from the trim\), against "
        r"([\d-]+) kW from Lansdorp's eqs\. 1-14 and ([\d-]+) kW from Schmehl's model",
        (PC % "sim", PC % "lansdorp", PC % "schmehl")),
       (r"the static-kite form of eq\. 9 gives ([\d.-]+) kW; eqs\. 10-14 fed the simulated mean tension and speed "
        r"([\d.-]+) kW\)", (PC % "static", PC % "fed")))
    + _evaluate_rows(),
    given=("(2008): the pumping laddermill", "for site selection*, 2008.", "(eqs. 1-15)", "(eqs. 16-20, Tables 1-2)",
           "(eqs. 1-20)", "sizes a 1 MW pumping kite", "the paper's eqs. 1-20. It writes Tables 1-2", "Figs. 10-20",
           "and 2010 hourly wind at 10 and 80 m, extrapolated above 80 m", "| Table 2 (eq. 20) |",
           "| 2010 hourly wind, daily means (extrapolated above 80 m) |",
           "design 2 comes close, and design 1 (Table 1) climbs to the 600 m cap", "so a 1 MW mean",
           "The paper's \"over 50 % against 22 %\"", "![Table 2 design",
           "(Figs. 10-13)", "(Lansdorp et al. 2008, simulated)", "on a 300 m tether", "(efficiency 0.92 each way)",
           "Delta L = 200 m", "eq. 9, is", "eq. 9 gives", "eqs. 10-14 fed",
           "(reel-in at 5 m/s, not 16.7; a 10 m/s wind; one tether element)",
           "(400 s, the registered 0.01 rad direction step;", "| 400 s |", "the 240 m drum"),
    timings=("optimised in 0.6-2.6 s on the development machines (median of 5;", "15 min;", "| PPO (15 min) |"),
    derived=("needs 1.8 MW while flying",),  # 1 MW / 0.566 of the time
    # a PPO run of `laddermill train configs/agents/ppo_pumping_kite.yaml` (15 min; not shipped) and its 1200 s run
    history=(
        History('2026-11-24', 'laddermill train --config configs/agents/ppo_pumping_kite.yaml (15 min), then '
                'laddermill evaluate '
                '--env laddermill_gym/PumpingKite-v0',
                'the PumpingKite-v0 PPO run, not kept (492976c)', (
            '| 232005 | 400 s | 336.5 m | 29.1 kW |',
            "(9.1 kW mean over 1200 s against the LQR cycle's 1.8 kW)",
        )),
    ),
)

T1 = r"\| {} \| {} \| ([\d.]+){} \| ([\d.]+) \|"
KR, TR = "{site_tables[%s][kite_row][%d]}", "{site_tables[%s][turbine_row][%d]}"
CAP = r"\| {} \| {} \| ([\d.]+) \| (\d+){} \| ([\d.]+) \| ([\d.]+) % \| ([\d.]+) \|"
QUASISTEADY_CHECKS = (  # the checks of docsite/ledger_quasisteady.py's entry
    tuple((T1.format(re.escape(label), re.escape(paper), r" \(upper bound\)" if key == "altitude" else ""),
                  (ST % f"weather2010][{key}_1", ST % f"cabauw][{key}_1"))
                 for label, paper, key in (("altitude [m]", "353.6", "altitude"), ("cable angle [deg]", "45", "angle"),
                                           ("cable diameter [mm]", "29.68", "diameter"),
                                           ("kite area [m^2]", "312.4", "area"), ("mean C_L", "0.5", "cl")))
    + LANSDORP.checks[:5]
    + tuple((CAP.format(data, machine, extra), tuple((KR if kite else TR) % (source, i) for i in range(5)))
            for data, source, machine, extra, kite in (
                ("2010 hourly", "weather2010", r"laddermill design 2 \(f <= 1/2\)", r" \(extrapolated wind\)", True),
                ("2010 hourly", "weather2010", "E-70/2300", "", False),
                ("Cabauw clusters", "cabauw", r"laddermill design 2 \(f <= 1/2\)", "", True),
                ("Cabauw clusters", "cabauw", "E-126/4200", "", False)))
    + ((r"The Cabauw bins cover ([\d.]+) % of the time", (ST % "cabauw][covered_pct",)),
       (r"comes close: ([\d.]+) % against ([\d.]+) %\.", (ST % "weather2010][kite_cf", ST % "weather2010][turbine_cf")),
       (r"f <= 1/2 gives ([\d.]+) MW, with peaks of ([\d.]+) MW", ("~" + KR % ("weather2010", 2),
                                                                  "~" + ST % "weather2010][peak_MW")),
       (r"\(peak ([\d.]+) MW for a ([\d.]+) MW mean\)", ("~" + ST % "cabauw][peak_MW", "~" + KR % ("cabauw", 2))),
       (r"the Schmehl model gives ([\d.]+)-([\d.]+) of Lansdorp's power at 8-25 m/s and ([\d.]+) at 6 m/s\. Below "
        r"([\d.]+) m/s it gives none", (ST % "cabauw][models_lo", ST % "cabauw][models_hi", ST % "cabauw][models_6",
                                        ST % "cabauw][models_from"))))

CYCLE_ROW = r"\| {} \| ([\d.]+) \| " + r"(\d+) \| " * 6 + r"([\d.]+) \| (\d+) \| ([\d.]+) \|" + ROW_END  # not the
# crosswind table's longer rows
CYCLE_KEYS = ("t_cycle", "sim", "lansdorp", "schmehl", "static", "fed", "tension_out", "speed_out", "tension_in",
              "max_dy")
PUMPING_CHECKS = (  # the checks of docsite/ledger_pumping.py's entry
    tuple((CYCLE_ROW.format(label), tuple(("~" if k == "max_dy" else "") + PC % f"rows][{i}][{k}"
                                                 for k in CYCLE_KEYS))
                 for i, label in enumerate((r"0 \(from the trim\)", "1", "2")))
    + ((r"gives ([\d.-]+) kW, still 1\.8 times the simulated power", (PC % "static_all",)),
       (r"reeled length\) give ([\d.-]+) kW, 12-13 %", (PC % "fed_all",))))

TC = "{tether_convergence[%s]}"
TC_KEYS = ("dt_ms", "start", "elements", "power", "T_out", "v_out", "T_in", "cycle", "alpha", "ground")
REELING_CHECKS = (  # the checks of docsite/ledger_reeling.py's entry
    tuple((rf"\| {label} \| " + r"([\d.-]+) \| " * 10, tuple(("~" if k == "start" else "") + TC % f"l{n}][{k}"
                                                                  for k in TC_KEYS))
                 for n, label in ((300, r"300 \(single element, shipped\)"), (100, "100"), (60, "60"), (40, "40"),
                                  (30, "30")))
    + ((r"The power settles: (\d+), (\d+), (\d+), (\d+) W", tuple(TC % f"l{n}][power" for n in (100, 60, 40, 30))),))
