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
ROTOR_DESIGN = NotYet(
    "the study's whole printed output (craft estimates, both altitudes' tables, summaries, sensitivities) is checked "
    "against rotor_design (54 s); the prose's figures and the simulator's trim table not yet listed",
    groups=("rotor_design",),
    checks=((r"(Craft estimate \(drive rated .*?) wrote runs/rotor_design/design_study\.csv", (RDS % "printed",)),))
