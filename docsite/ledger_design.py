"""The ledger entry (:mod:`docsite.page_ledger`) of docs/rotorcraft_design.md: the study's printed output and prose
results against ``rotor_design``, its inputs against the configs and its hand arithmetic in closed form
(:func:`docsite.design_figures.design_data`)."""

from __future__ import annotations

from docsite.ledger_kinds import NotYet

RDS = "{rotor_design[%s]}"
RP = "{rotor_design[prose][%s]}"
SENS = (("no profile drag", "no_drag"), ("weightless tethers", "weightless"), ("tethers at 20 deg", "elev20"),
        ("craft mass x0.7", "mass07"))
ROTOR_DESIGN = NotYet(
    "the study's whole printed output (craft estimates, both altitudes' tables, summaries, sensitivities) and the "
    "prose's results (peaks, rated winds, C_p, sensitivities, craft masses) are checked against rotor_design (54 s); "
    "the method's and choices' inputs and hand arithmetic and the simulator's trim table not yet listed",
    groups=("rotor_design",),
    checks=((r"(Craft estimate \(drive rated .*?) wrote runs/rotor_design/design_study\.csv", (RDS % "printed",)),
            (r"Result: ([\d.]+) t at 15,000 ft \(180 m/s\) and ([\d.]+) t at 30,000 ft \(230 m/s\)",
             (RP % "craft_t][tip180", RP % "craft_t][tip230")),
            (r"top of the range: ([\d.]+) MW at 15,000 ft and ([\d.]+) MW at 30,000 ft at 45 m/s",
             (RP % "15kft][peak_MW", RP % "30kft][peak_MW")),
            (r"reach their allowed tension at (\d+) m/s \(([\d.]+) MW\)",
             (RP % "15kft][stress_wind", RP % "15kft][stress_MW")),
            (r"\*\*3\.13 MW is reached at ([\d.]+) m/s at 15,000 ft and at ([\d.]+) m/s at 30,000 ft",
             (RDS % "15kft][wind", RDS % "30kft][wind")),
            (r"rated winds of ([\d.]+) m/s and ([\d.]+) m/s fit", (RDS % "15kft][wind", RDS % "30kft][wind")),
            (r"The power coefficient there is ([\d.]+) and ([\d.]+)\.",
             (RP % "15kft][cp_rated", RP % "30kft][cp_rated")),
            (r"The required C_p is ([\d.]+) at 20 m/s and ([\d.]+) at 25 m/s at 15,000 ft, and ([\d.]+) at 25 m/s "
             r"and ([\d.]+) at 30 m/s", (RP % "15kft][need_cp][at20", RP % "15kft][need_cp][at25",
                                         RP % "30kft][need_cp][at25", RP % "30kft][need_cp][at30")),
            (r"C_p = ([\d.]+) \(([\d.]+) deg\) and ([\d.]+) \(([\d.]+) deg\)\.",
             ("{rotor_design[15kft][ideal_cp]:.3f}", "{rotor_design[15kft][alpha_c]}",
              "{rotor_design[30kft][ideal_cp]:.3f}", "{rotor_design[30kft][alpha_c]}")),
            (r"3\.13 MW would still need ([\d.]+) m/s and ([\d.]+) m/s", (RP % "15kft][ideal_wind",
                                                                         RP % "30kft][ideal_wind")),
            (r"no stress limit: ([\d.]+) m/s at 15,000 ft", (RP % "15kft][sensitivity][no_limit",)),
            (r"is worse: ([\d.]+) / ([\d.]+) m/s", (RP % "15kft][sensitivity][solidity",
                                                  RP % "30kft][sensitivity][solidity")))
    + tuple((rf"{label}: ([\d.]+) / ([\d.]+) m/s", (RP % f"15kft][sensitivity][{key}",
                                                    RP % f"30kft][sensitivity][{key}")) for label, key in SENS))

DW, DC = "{design_data[worked][%s]}", "{design_data[config][%s]}"
DESIGN_CHECKS = (
    (r"13\.3 GWh / 6910 kWh/m\^2 = (\d+) m\^2 = 2 pi 17\.5\^2", (DW % "disk_m2",)),
    (r"3\.13 MW x 8760 h x 0\.48 = ([\d.]+) GWh and x 0\.67 = ([\d.]+) GWh", (DW % "energy48", DW % "energy67")),
    (r"rho = p/\(R T\): ([\d.]+) kg/m\^3 at (\d+) m and ([\d.]+) kg/m\^3 at (\d+) m",
     (DW % "15kft][rho", DW % "15kft][h", DW % "30kft][rho", DW % "30kft][h")),
    (r"ISA formula gives ([\d.]+) and ([\d.]+) kg/m\^3", (DW % "15kft][rho", DW % "30kft][rho")),
    (r"is ([\d.e-]+) m\^2 of fibre\. - EA = 112 GPa x [\d.e-]+ m\^2 = ([\d.e]+) N\.", (DW % "kevlar_m2", DW % "EA_N")),
    (r"- EA = 112 GPa x [\d.e-]+ m\^2 = ([\d.e]+) N\.", (DC % "cable][EA_N",)),
    (r"x 0\.67 = (\d+) kN, the same strength", (DW % "breaking_kN",)),
    (r"x 0\.67 = (\d+) kN, the same strength", (DC % "cable][breaking_kN",)),
    (r"at 2705 kg/m\^3 is ([\d.e-]+) m\^2\.", (DW % "alu_m2",)),
    (r"\*\*Diameter: (\d+) mm, not 10 mm\.\*\* The solid cross-section, ([\d.e-]+) m\^2, alone is a ([\d.]+) mm "
     r"circle\. At a fill factor of 0\.8 the cable is (\d+) mm", (DW % "cable_mm", DW % "solid_m2", DW % "solid_mm",
                                                         DW % "cable_mm")),
    (r"\*\*Diameter: (\d+) mm", (DC % "cable][cable_mm",)), (r"cable can weigh ([\d.]+) kg/m", (DC % "cable][mu",)),
    (r"aluminium of 10 mm is only ([\d.]+) kg/m", (DW % "alu10_kg_m",)),
    (r"Design factor 2: ([\d.]+) kN, which is (\d+) MPa", (DW % "allowed_kN", DW % "allowed_MPa")),
    (r"The aluminium has ([\d.e-]+) ohm/m", (DW % "ohm_m",)),
    (r"on ([\d.]+) km and 28 kV on ([\d.]+) km of tether", (DW % "15kft][length_km", DW % "30kft][length_km")),
    (r"beta = (\d+) deg at both altitudes", (DC % "15kft][elevation",)),
    (r"L = h / sin\(beta\): ([\d,]+) m at 15,000 ft and ([\d,]+) m at 30,000 ft",
     ("~" + DW % "15kft][length", "~" + DW % "30kft][length")),
    (r"L = h / sin\(beta\): ([\d,]+) m at 15,000 ft and ([\d,]+) m at 30,000 ft",
     ("~" + DC % "15kft][length", "~" + DC % "30kft][length")),
    (r"That is ([\d.]+) t and ([\d.]+) t per tether", (DW % "15kft][tether_t", DW % "30kft][tether_t")),
    (r"\(([\d.]+) rad/s\)\. 170 and 180", (DW % "15kft][omega",)), (r"\(([\d.]+) rad/s\)\. 170 and 180",
                                                                    (DC % "15kft][omega",)),
    (r"\(([\d.]+) rad/s\)\. At the thinner air", (DW % "30kft][omega",)),
    (r"\(([\d.]+) rad/s\)\. At the thinner air", (DC % "30kft][omega",)),
    (r"must lift ([\d.]+) t of tether", (DW % "30kft][tethers_t",)),
    (r"runs at about (\d+) m/s\.", (DW % "mi26_tip",)),
    (r"\(Omega R \+ V cos alpha_c\)/a = ([\d.]+) at 15,000 ft and ([\d.]+) at 30,000 ft",
     (DW % "15kft][mach", DW % "30kft][mach")),
    (r"3\.13 MW / 0\.95 / 2 = ([\d.]+) MW of shaft power", (DW % "drive_MW",)),
    (r"sigma pi R / 4 = ([\d.]+) m", (DW % "chord",)),
    (r"kg \(Fingersh, Hand & Laxson, NREL/TP-500-40566, 2006\), ([\d.]+) kg/kW", (DW % "gen_kg_kW",)),
    (r"SP260D aircraft motor is ([\d.]+) kg/kW", (DW % "motor_kg_kW",)),
    (r"Result: ([\d.]+) t at 15,000 ft \(180 m/s\) and ([\d.]+) t at 30,000 ft", (DC % "15kft][mass_t",
                                                                                  DC % "30kft][mass_t")),
    (r"\(17\.5/1\.85\)\^3 would weigh ([\d.]+) t", (DW % "scaled_t",)),
    (r"Scale k = 17\.5/1\.85 = ([\d.]+),", (DW % "scale",)),
    (r"fin area 0\.15 k\^2 = ([\d.]+) m\^2", (DW % "fin_area",)), (r"fin area 0\.15 k\^2 = ([\d.]+) m\^2",
                                                                  (DC % "15kft][fin_area",)),
    (r"fin position \(-1\.5, -0\.3\) k = \((-[\d.]+), (-[\d.]+)\) m", (DW % "fin_x", DW % "fin_z")),
    (r"fin position \(-1\.5, -0\.3\) k = \((-[\d.]+), (-[\d.]+)\) m", (DC % "15kft][fin_x", DC % "15kft][fin_z")),
    (r"frame drag area 0\.3 k\^2 = ([\d.]+) m\^2", (DW % "drag_area",)),
    (r"frame drag area 0\.3 k\^2 = ([\d.]+) m\^2", (DC % "15kft][drag_area",)),
    (r"\(v1 = 16/(\d+) = ([\d.e-]+) 1/s\)", (DW % "15kft][v1_den", DW % "15kft][v1")),
    (r"\(v1 = 16/\d+ = ([\d.e-]+) 1/s\)", (DC % "15kft][v1",)),
    (r"\(v1 = 23/(\d+) = ([\d.e-]+) 1/s\)", (DW % "30kft][v1_den", DW % "30kft][v1")),
    (r"\(v1 = 23/\d+ = ([\d.e-]+) 1/s\)", (DC % "30kft][v1",)),
    (r"\| \| 15,000 ft, 26 m/s, ([\d.]+) deg \| 30,000 ft, 33 m/s, ([\d.]+) deg \|",
     (DC % "15kft][collective", DC % "30kft][collective")))
ROTOR_DESIGN = NotYet(ROTOR_DESIGN.reason.replace("the method's and choices' inputs and hand arithmetic", "the "
                                                  "rest of the method's and choices' inputs")
                      + "; the choices' hand arithmetic and the configs' inputs are checked against the configs and "
                      "closed forms (design_data)", groups=ROTOR_DESIGN.groups + ("design_data",),
                      checks=ROTOR_DESIGN.checks + DESIGN_CHECKS)
