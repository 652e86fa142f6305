"""The ledger entries (:mod:`docsite.page_ledger`) of the pages on papers: Roberts, Podgaets & Ockels, Meijaard
et al."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, NotYet

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
    groups=("pointmass_benchmark", "simulate_laddermill"),
    checks=((r"scene (?:`podgaets_5km`)?\s?: ([\d,]+) elements, (\d+\.\d\d) MB of arrays held on two threads",
             ("{pointmass_benchmark[elements]}", "{pointmass_benchmark[held_MB]}")),
            (r"held to ([\d.e-]+) s steps by the Voigt damping", ("{pointmass_benchmark[explicit_dt]}",)),
            (r"\(the rigid mill: ([\d.]+) kW\)", ("{simulate_laddermill[periodic_kW]}",))),
    given=("Podgaets & Ockels (2007)", "laddermill*, 2007.", "(5 km of cable at 1 cm with 100 kites in 82 MB)",
           "| 5 km at 1 cm with 100 kites in 82 MB", "steps at the kites' 10 ms", "on the 5 km string"),
    timings=("the process peaks at 216 MB with numba's cache warm", "0.18x real time on one thread on the 2-core "
             "machine", "8.7x real time at 1 m, 335x at 70 m", "measured on this project's 2-core machine"),
    not_rerun=("tensions within 1 % of the rigid",  # pointmass_fidelity; pointmass_mill (a rigid run, 3 point-mass):
               "periodic at 2 m/s with 88.2 kW at 1 m elements and 82.4 kW at 70 m"),
)


MJ = "~{meijaard_v1[%s]}"
MEIJAARD = NotYet(
    "the v1 table's powers, tensions, widths, periods and overloads are checked against the study's power.csv; its "
    "claims' wording, the direction step's times and the v0 section not yet listed",
    groups=("meijaard_v1",),
    checks=((r"at 1 m/s \(periodic at (\d+) s\) the loop is (\d+) m wide",
             (MJ % "2D_1][t_end_s", MJ % "2D_1][loop_width_m")),
            (r"(\d+)-(\d+) m at 1 m/s; (\d+)-(\d+) m at 5 m/s, \*\*not periodic\*\* within ([\d,]+) s",
             (MJ % "2D_1][width_min_m", MJ % "2D_1][width_max_m", MJ % "2D_5][width_min_m", MJ % "2D_5][width_max_m",
              MJ % "2D_5][t_end_s")),
            (r"1 m/s: ([\d.]+) kN in element (\d+); 5 m/s: ([\d.]+) kN in element (\d+)",
             (MJ % "2D_1][T_min_kN", MJ % "2D_1][T_min_element", MJ % "2D_5][T_min_kN", MJ % "2D_5][T_min_element")),
            (r"1 m/s: \(([\d.]+) - ([\d.]+)\) kN x 1 m/s = ([\d.]+) kW, generator ([\d.]+) kW; 2 m/s: \(([\d.]+) - "
             r"([\d.]+)\) x 2 = ([\d.]+) kW, generator ([\d.]+) kW; 5 m/s: ([\d.]+) vs ([\d.]+) kW",
             tuple(MJ % f"2D_{v}][{k}" for v in (1, 2) for k in ("T_first_kN", "T_last_kN", "tension_estimate_kW",
                                                                "mean_power_kW"))
             + (MJ % "2D_5][tension_estimate_kW", MJ % "2D_5][mean_power_kW")),
            (r"\*\*([\d.]+) kW at 2 m/s\*\* \(3D: ([\d.]+) kW\)",
             (MJ % "2D_2][mean_power_kW", MJ % "3D_2][mean_power_kW")),
            (r"period means ([-\d,.]+) to ([\d,.]+) kW over the last (\d+) periods \(mean ([\d.]+) kW\)",
             (MJ % "2D_5][late_power_min_kW", MJ % "2D_5][late_power_max_kW", MJ % "2D_5][late_periods",
              MJ % "2D_5][late_power_mean_kW")),
            (r"element 0 at ([\d.]+) s, ([\d.]+) times it; at 2 m/s at ([\d.]+) s, ([\d.]+) times",
             (MJ % "2D_5][overload_s", MJ % "2D_5][peak_tension_ratio", MJ % "2D_2][overload_s",
              MJ % "2D_2][peak_tension_ratio")),
            (r"peak tension ([\d.]+) of the breaking load", (MJ % "3D_2][peak_tension_ratio",))))
