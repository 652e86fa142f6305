"""The ledger entry (:mod:`docsite.page_ledger`) of docs/rotorcraft.md: the craft's data against its configuration
file and the page's mass build-up reworked in closed form (:func:`docsite.config_figures.craft_data`), the study's
figures against ``craft_stability``."""

from __future__ import annotations

import re

from docsite.ledger_kinds import Covered, NotYet

CS = "~{craft_stability[%s]}"
SCAN = (7, 10, 13, 16, 18, 19, 20, 21, 22)  # [m/s] the page's columns of the wind scan
Y = r"\\\|y\\\|"  # the table's escaped |y|
CW, CC = "{craft_data[worked][%s]}", "{craft_data[config][%s]}"
CRAFT_DATA_CHECKS = (
    (r"The total is ([\d.]+) kg, with the CG at \((-[\d.]+), 0, ([\d.]+)\)", (CW % "mass", CW % "cg_x", CW % "cg_z")),
    (r"The total is ([\d.]+) kg", (CC % "mass",)),
    (r"Jxx = ([\d.]+), Jyy = ([\d.]+), Jzz = ([\d.]+) and Jxz = ([\d.]+) kg m\^2",
     (CW % "Jxx", CW % "Jyy", CW % "Jzz", CW % "Jxz")),
    (r"Jxx = ([\d.]+), Jyy = ([\d.]+), Jzz = ([\d.]+) and Jxz = ([\d.]+) kg m\^2",
     (CC % "Jxx", CC % "Jyy", CC % "Jzz", CC % "Jxz")),
    (r"The hubs sit ([\d.]+) m above the CG and ([\d.]+) m ahead of it\. The fins' centre of pressure is at "
     r"\((-[\d.]+), 0, (-[\d.]+)\) m", (CW % "hub_height", CW % "hub_x", CW % "fin_x", CW % "fin_z")),
    (r"The hubs sit ([\d.]+) m above the CG and ([\d.]+) m ahead of it\. The fins' centre of pressure is at "
     r"\((-[\d.]+), 0, (-[\d.]+)\) m", (CC % "hub_height", CC % "hub_x", CC % "fin_x", CC % "fin_z")),
    (r"Rotor speed ([\d.]+) rad/s", (CW % "rotor_speed",)), (r"Rotor speed ([\d.]+) rad/s", (CC % "rotor_speed",)),
    (r"Hub spacing ([\d.]+) m: a ([\d.]+) m clearance", (CC % "hub_spacing", CW % "clearance")),
    (r"rotor diameter \(([\d.]+) m\)", (CC % "diameter",)),
    (r"The fins are ([\d.]+) m\^2 together\. Their lift slope is ([\d.]+) /rad",
     (CC % "fin_area", CC % "fin_slope")),
    (r"Their lift slope is ([\d.]+) /rad", (CW % "fin_slope",)), (r"C_D A = ([\d.]+) m\^2", (CC % "drag_area",)),
    (r"A ([\d.]+) mm Kevlar 49 line: EA = (\d+) kN, ([\d.]+) g/m, breaking load ([\d.]+) kN",
     (CC % "cable_mm", CC % "EA_kN", CC % "g_per_m", CC % "breaking_kN")),
    (r"The rear tethers are L_c = (\d+) m long", (CC % "tether_length",)),
    (r"limit of 2\.78/473 = ([\d.]+) ms", (CW % "rk4_limit_ms",)),
    (r"Collective (-\d+) to (\d+) deg; differential \+-(\d+) deg\. The trim collective is (\d+) deg",
     (CC % "collective_min", CC % "collective_max", CC % "differential", CC % "trim_collective")),
    (r"design pose: pitch (\d+) deg and every tether at beta = (\d+) deg", (CC % "pitch", CC % "beta")),
    (r"attach side by side at y = \+-([\d.]+) m", (CC % "attach_y",)),
    (r"Each tether has (\d+) elements\.", (CC % "elements",)),
    (rf"\| rear tethers at y = \*\*\+-0\.3\*\* m \| \*\*([\d.]+)\*\* \| holds, max {Y} ([\d.]+) m, "
     r"dtheta up to ([\d.]+) deg \|", (CS % "scan][v10][growth", CS % "lqr_01][y", CS % "lqr_01][dtheta")),
    (r"\| fins 0 / 0\.05 / \*\*0\.15\*\* / 0\.4 m\^2 \| [\d.]+ / [\d.]+ / \*\*([\d.]+)\*\*",
     (CS % "scan][v10][growth",)))

ROTORCRAFT_GIVEN = (  # the paper's sections and equations, the model's choices and the study's settings
    "his eq. (6). This", "flying model, eq. (6) and", "The 35 m design", ": eq. (6).", "the core's 13-number state",
    "(Roberts eq. 1 and", "Roberts sec. 3;", "P = 0.95 sum(-Q Omega) when generating (divided by 0.95 when motoring) | "
    "Roberts sec. 6", "Side force 1/2 rho", "| 1/2 rho C_D A", "Meijaard et al. 1999", "the 13 deg blade-incidence "
    "limit and the 95 % electrical", "it gives mu = 0.15 at 10 m/s and 25 deg incidence", "= 10 cos 25 deg / (0.15 x "
    "1.85)", "| blades, each rotor | 2.0 | 0, +-2.0, 0 |", "| generators | 2 x 3.0 | 0, +-2.0, 0.25 |",
    "| cross beam (4 m) | 4.0 | 0, 0, 0.3 |", "| boom (2.5 m) | 3.0 | -0.25, 0, 0.4 |", "| fins | 1.0 | -1.5, 0, 0.1 |",
    "| electronics, bridle | 2.0 | 0.2, 0, 0.7 |", "aspect ratio 1.5: 2 pi A / (2 + sqrt(A^2 + 4))",
    "4 m of 30 mm tube at C_D 1.2", "At 10 m/s that puts the retreating tip at 10 deg, inside the 13 deg limit",
    "Roberts' Fig. 2", "With 4 elements the lightest nodes (80 g)", "at the 2 ms step", "With 2 elements",
    "The 2 ms step", "Nonlinear runs at 2 ms", "At 10 m/s the trim", "## Eq. (6)", "+ C_T/(2 r) = 0",
    "dc0/dtheta0 (1 - c1 / (2 r f_lam))", "beta = -2 s dT/dtheta0", "alpha = 0:", "At 10 m/s (SI units",
    "-M^-1 K, -M^-1 D and M^-1 b", "(the issue asks for 5 %)", "which eq. (6) leaves out. Eq. (6) on its own",
    "which eq. (6) freezes", "An LQR on eq. (6)", "collective: 4 deg, or lower where 4 deg would push the retreating "
    "tip past 13 deg", "(all 30 minimal coordinates)", "| v0 [m/s] | 7 | 10 | 13 | 16 | 18 | 19 | 20 | 21 | 22 |",
    "at 10 m/s and at 22 m/s, to 15 %", "measured at 10 m/s", "| eq. (6) LQR after a 0.1 rad direction step |",
    "Eq. (6), which keeps yaw", "## LQR on eq. (6)", "y 0.5 m, phi 3 deg, y' 0.5 m/s, p 10 deg/s and dtheta 5 deg",
    "the 20 Hz control", "at 10 m/s, half the critical speed, over 120 s", "| wind-direction step at 1 s | open loop "
    "| eq. (6) LQR |", "the tip exceeds 13 deg")
# worked in a Python session with the craft's API (trim, linearisation, eigenvectors); no command of the package prints
# them; the period is 2 pi / 0.497
ROTORCRAFT_DERIVED = (
    "eigenvalue of -1558 1/s", "the fastest eigenvalue is -473 1/s", "(60.9 m)",
    "has pitch 25.6 deg, tether tensions of 129 N (each rear) and 195 N (front), and 1.6 kW electrical power",
    "Its modes are -0.19 +- 0.84j and -3.7 +- 5.4j 1/s", "a period of 12.6 s", "roll (about 0.03 rad per m) and yaw "
    "(about 0.043 rad per m)", "That happens above 12.8 m/s", "above 12.8 m/s, which")
ROTORCRAFT_NOT_RERUN = (  # runs of the study on modified configs (fin areas, tether spacings) and beyond its scan
    "| fins 0 / 0.05 / **0.15** / 0.4 m^2 | 0.115 / 0.110 /", "/ 0.168 |",
    "| rear tethers at y = +-1.0 m | 0.134 | fails at 5.6 s (saturates at 5 deg) |",
    "| rear tethers at y = +-2.0 m | 0.099 | fails at 5.7 s (saturates at 5 deg) |",
    "Above about 23 m/s the blade-limited collective falls below -3 deg. There a fast mode (30 rad/s) goes unstable "
    "(growth +0.25 1/s at 25 m/s)")
ROTORCRAFT = Covered(
    groups=("craft_stability", "craft_data"),
    checks=CRAFT_DATA_CHECKS + ((r"\*\*The critical wind speed is (\d+\.\d\d) m/s\*\*", (CS % "critical",)),
            (r"K = \((-[\d.]+), (-[\d.]+), (-[\d.]+), (-[\d.]+)\)", tuple(CS % f"K][{i}" for i in range(4))),
            (r"Closed loop on eq\. \(6\): max \|z\| = (\d\.\d+)", (CS % "z",)),
            (rf"\| 0\.01 rad \(the paper's\) \| fails at ([\d.]+) s \({Y} (\d+) m\) \| holds, max {Y} ([\d.]+) m, "
             r"max dtheta ([\d.]+) deg \|", (CS % "open_001][fail", CS % "open_001][y", CS % "lqr_001][y",
                                             CS % "lqr_001][dtheta")),
            (rf"\| 0\.1 rad \| fails at ([\d.]+) s \| holds, max {Y} ([\d.]+) m, max dtheta ([\d.]+) deg \|",
             (CS % "open_01][fail", CS % "lqr_01][y", CS % "lqr_01][dtheta")),
            (r"M = \[\[([\d.]+), (0)\], \[(0), ([\d.]+)\]\] D = \[\[([\d.]+), ([\d.]+)\], \[([\d.]+), ([\d.]+)\]\] "
             r"K = \[\[([\d.]+), ([-\d.]+)\], \[([\d.]+), ([\d.]+)\]\] \(alpha, beta\) = \(0, ([-\d]+)\) per rad",
             tuple(CS % f"eq6_{m}][{i}" for m in "MDK" for i in range(4)) + (CS % "beta",)),
            (r"entry by entry to ([\d.]+) % at worst", (CS % "rel_error_pct",)),
            (r"unstable mode at 10 m/s \(([\d.]+) \+- ([\d.]+)j 1/s", (CS % "scan][v10][growth",
                                                                     CS % "scan][v10][frequency")),
            (r"\| collective \[deg\] \| " + " \\| ".join([r"([-\d.]+)"] * 9),
             tuple(CS % f"scan][v{v}][collective" for v in SCAN)),
            (r"\| growth \[1/s\] \| " + " \\| ".join([r"([-+\d.]+)"] * 9),
             tuple(CS % f"scan][v{v}][growth" for v in SCAN))),
    given=ROTORCRAFT_GIVEN, timings=("(14 s on the shared 2-core machine at a load of 5, 2026-11-29)",),
    derived=ROTORCRAFT_DERIVED, not_rerun=ROTORCRAFT_NOT_RERUN)

RC = "~{rotor_chart[%s]}"
ROTOR = NotYet(
    "the chart's table, the solidity finding and the autorotation angles against the blade-element oracle are "
    "checked against rotor_chart (2-25 s); the model's derivation figures, the blade-element checks' tolerances and "
    "the low-incidence exceptions not yet listed",
    groups=("rotor_chart",),
    checks=tuple((rf"\| {re.escape(mu)} \| ([\d.]+) \| ([\d.]+) \(([\d.]+) deg\) \| ([\d.]+) \|",
                  tuple(RC % f"m{mu}][{k}" for k in ("autorotation", "cp", "at", "collective")))
                 for mu in ("0.05", "0.075", "0.1", "0.15", "0.2"))
    + ((r"blade at the 13 deg tip limit \(collective ([\d.]+) deg\) \| \*\*([\d.]+)\*\*",
        (RC % "m0.1][collective", RC % "sigma_limit")),
       (r"at any collective \(best theta0 = ([\d.]+) deg\) \| ([\d.]+) \|", (RC % "best_theta", RC % "sigma_best")),
       (r"fixed collective theta0 = 0 / 2 / 4 / 6 deg \| ([\d.]+) / ([\d.]+) / ([\d.]+) / ([\d.]+) \|",
        tuple(RC % f"fixed][t{t}" for t in (0, 2, 4, 6))),
       (r"rises with sigma: ([\d.]+) deg per 0\.01 at the limit", (RC % "rise",)))
    + tuple((rf"\| {re.escape(sigma)} \| " + r"([\d.]+) / [\d.]+ \| " * 4,
             tuple(RC % f"s{sigma}][t{t}" for t in (0, 2, 4, 6))) for sigma in ("0.05", "0.08")))
