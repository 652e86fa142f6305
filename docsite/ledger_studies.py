"""The ledger entries (:mod:`docsite.page_ledger`) of the study pages: the learned mill, lateral stability, the
rotorcraft, the fast mill."""

from __future__ import annotations

import re

from docsite.ledger_kinds import NotYet


def _curve_rows(policy: str, labels: tuple, length: bool) -> tuple:
    """Checks of docs/learned_mill.md's training table of ``policy``: one per row label (DAgger rounds, then the PPO
    evaluations by their agent steps), against the shipped training_curve.csv."""
    cell = r"(\d+(?:\.\d)?) \| " if length else ""
    out = []
    for i, label in enumerate(labels):
        ppo = label.startswith("PPO")
        head = rf"\| PPO ({re.escape(label.split()[1])}) M" if ppo else rf"\| {re.escape(label)}"
        keys = (("million",) if ppo else ()) + ("held",) + (("length",) if length else ()) + ("power", "dy")
        out.append((rf"{head}[^|]*\| (\d) of 1 \| {cell}(\d+\.\d{{3}}) \| ([\d.]+) \|",
                    tuple(f"{{training_curves[{policy}][{i}][{k}]}}" for k in keys)))
    return tuple(out)


DAGGER = ("DAgger 1 (flies the LQR + noise)", "DAgger 2", "DAgger 3", "DAgger 4 (kept: `model.zip`)")
LEARNED_MILL = NotYet("evaluation tables (`laddermill evaluate` of ppo_mill / ppo_chain, minutes each) and timings "
                      "not yet listed; the two training tables are checked against the shipped training_curve.csv",
                      groups=("training_curves",),
                      checks=_curve_rows("ppo_mill", DAGGER + ("PPO 1.00", "PPO 1.14"), True)
                      + _curve_rows("ppo_chain", DAGGER + ("PPO 1.00", "PPO 1.73"), False))

LS = "{lateral_study[%s]}"
SWEEPS = (("weathercock", "weathercock Cnb scale"), ("dihedral", "dihedral effect Clb scale"),
          ("fin", "whole vertical tail (CYb, CYr, Cnb, Cnr)"), ("attach_x", "attachment x, ahead of CG [m]"),
          ("attach_z", "attachment z, below CG [m]"), ("wind", "wind speed v0 [m/s]"), ("tether", "tether length [m]"))
CELL = r"(?:\*\*)?([-\d.]+): ([-+]\d\.\d{3})(?: \((\d+(?:\.\d)?)\))?"  # value: largest Re (period), the default bold


def _sweep_cells() -> tuple:
    """docs/lateral_stability.md's sweep table: each of the 7 cells of each sweep (its value, largest real part and
    the period where quoted, each the printed figure rounded to the digits quoted)."""
    return tuple((rf"\| {re.escape(label)} \| (?:[^,|]*, ){{{i}}}{CELL}",
                  tuple("~" + LS % f"{name}][rows][{i}][{k}" for k in ("value", "re", "period")))
                 for name, label in SWEEPS for i in range(7))


LATERAL = NotYet(
    "the eigenvalue and sweep tables are checked against lateral_study (50 s); the prose's Jacobian entries, "
    "eigenvector phases and single-column checks are not printed by it (the page says so): not yet listed",
    groups=("lateral_study",),
    checks=_sweep_cells() + (
        (r"\| (-\d+\.\d\d) \| roll subsidence", ("~" + LS % "eigenvalues][0][0",)),
        (r"\| (-\d\.\d\d) \+- (\d\.\d\d)j \| fast", ("~" + LS % "eigenvalues][1][0", "~" + LS % "eigenvalues][1][1")),
        (r"\| \*\*\+(\d\.\d{3}) \+- (\d\.\d{3})j\*\* \| \*\*sideways oscillation: period (\d+\.\d) s",
         ("~" + LS % "eigenvalues][3][0", "~" + LS % "eigenvalues][3][1", "~" + LS % "weathercock][rows][5][period")),
        (r"\| \*\*\+(0\.\d{3})\*\* \| slow sideways drift", ("~" + LS % "eigenvalues][5][0",)),
        (r"max Re = 0 at \*\*(\d\.\d\d) x Cnb\*\*; oscillation neutral at (\d\.\d\d) x Cnb",
         ("~" + LS % "weathercock][max_re_zero", "~" + LS % "weathercock][osc_zero")),
        (r"max Re = 0 at \*\*(\d\.\d) x Clb\*\*", ("~" + LS % "dihedral][max_re_zero",)),
        (r"oscillation neutral at (\d+\.\d) m; the drift", ("~" + LS % "tether][osc_zero",))))


CS = "~{craft_stability[%s]}"
Y = r"\\\|y\\\|"  # the table's escaped |y|
ROTORCRAFT = NotYet(
    "the critical wind speed, the eq. (6) LQR's gain and the step table are checked against craft_stability (about "
    "35 s); the rest (trim, eq. (6) against the Jacobian, the open points) not yet listed",
    groups=("craft_stability",),
    checks=((r"\*\*The critical wind speed is (\d+\.\d\d) m/s\*\*", (CS % "critical",)),
            (r"K = \((-[\d.]+), (-[\d.]+), (-[\d.]+), (-[\d.]+)\)", tuple(CS % f"K][{i}" for i in range(4))),
            (r"Closed loop on eq\. \(6\): max \|z\| = (\d\.\d+)", (CS % "z",)),
            (rf"\| 0\.01 rad \(the paper's\) \| fails at ([\d.]+) s \({Y} (\d+) m\) \| holds, max {Y} ([\d.]+) m, "
             r"max dtheta ([\d.]+) deg \|", (CS % "open_001][fail", CS % "open_001][y", CS % "lqr_001][y",
                                             CS % "lqr_001][dtheta")),
            (rf"\| 0\.1 rad \| fails at ([\d.]+) s \| holds, max {Y} ([\d.]+) m, max dtheta ([\d.]+) deg \|",
             (CS % "open_01][fail", CS % "lqr_01][y", CS % "lqr_01][dtheta"))))

def _v2_rows() -> tuple:
    """docs/mill_fast.md's rows of the in-plane v2 mill at 1-5 m/s (ramp 100 V_c s), against fast_mill case."""
    keys = ("t", "period", "P", "dT_P", "T_min", "T_max", "peak", "lo", "hi")
    return tuple((rf"\| {v} \| {100 * v} \| ([\d,.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) / ([\d.]+) \| "
                  r"([\d.]+) \| ([-\d.]+) \.\. ([-\d.]+)", tuple(f"~{{fast_mill_v2[v{v}][{k}]}}" for k in keys))
                 for v in range(1, 6))


MILL_FAST = NotYet("the in-plane v2 table at 1-5 m/s is checked against fast_mill case (one run per speed); the v1 "
                   "drift and elevator tables, the 3D rows and timings not yet listed",
                   groups=("fast_mill_v2",), checks=_v2_rows())


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
