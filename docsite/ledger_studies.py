"""The ledger entries (:mod:`docsite.page_ledger`) of the study pages: the learned mill, lateral stability, the fast
mill (the rotorcraft: :mod:`docsite.ledger_craft`)."""

from __future__ import annotations

import re

from docsite.ledger_kinds import ROW_END, Covered, History


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
GL = "{gain_locality[%s]}"
GAIN_CHECKS = tuple((rf"(?<=\| )\| {d} \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|{ROW_END}",
                     tuple(GL % f"rows][{d}][{k}" for k in ("mean", "largest", "share"))) for d in range(6)) + (
    (r"\| 6-10 \| ([\d.-]+) \|", (GL % "far",)), (r"\| beyond 10 \| \| \| ([\d.]+) \|", (GL % "beyond",)),
    (r"\| spectral radius of the design model's closed loop \| " + r"([\d.]+) \| " * 6,
     tuple(GL % f"bands][k{k}" for k in range(5)) + (GL % "tail",)),
    (r"every 5th slot: ([\d. ]+?)\.\)", (GL % "own",)))
#: docs/learned_mill.md's checks (its entry: docsite/ledger_learned.py).
LEARNED_MILL_CHECKS = (_curve_rows("ppo_mill", DAGGER + ("PPO 1.00", "PPO 1.14"), True)
                       + _curve_rows("ppo_chain", DAGGER + ("PPO 1.00", "PPO 1.73"), False) + GAIN_CHECKS)

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


W = LS % "weathercock][rows][5][%s"  # the default wing's row


def _prose_checks() -> tuple:
    """docs/lateral_stability.md's prose figures that restate lateral_study's printed rows and crossings."""
    row = "~" + LS % "%s][rows][%d][%s"
    return (
        (r"the tether is at ([\d.]+) deg elevation, the tension is 1\.33 kN and the elevator sits at ([-\d.]+) deg",
         ("~" + W % "elevation", "~" + W % "elevator")),
        (r"period 23\.4 s, amplitude doubles every ([\d.]+) s", ("~" + W % "t2x",)),
        (r"With Cnb at ([\d.]+) of its default", ("~" + LS % "weathercock][max_re_zero",)),
        (r"stable beyond ([\d.]+) x the default Clb", ("~" + LS % "dihedral][max_re_zero",)),
        (r"the growth rate peaks at ([\d.]+) 1/s near ([\d.]+) x", (row % ("fin", 4, "re"), row % ("fin", 4, "value"))),
        (r"comes close to neutral \(\+([\d.]+) 1/s\)", (row % ("fin", 0, "re"),)),
        (r"removes the oscillation \(([\d.]+) to ([\d.]+) 1/s\)",
         (row % ("attach_z", 6, "re"), row % ("attach_z", 0, "re"))),
        (r"between z = ([\d.]+) and ([\d.]+) m\.", (row % ("attach_z", 1, "value"), row % ("attach_z", 2, "value"))),
        (r"between x = ([\d.]+) and ([\d.]+) m\.", (row % ("attach_x", 4, "value"), row % ("attach_x", 5, "value"))),
        (r"period falls from (\d+) s to ([\d.]+) s at 16 m/s",
         (row % ("wind", 1, "period"), row % ("wind", 6, "period"))),
        (r"At 5 m/s the trim drops to (\d+) deg elevation and a real mode \(\+([\d.]+)\)",
         (row % ("wind", 0, "elevation"), row % ("wind", 0, "re"))),
        (r"sets the period \(([\d.]+) s at 10 m, (\d+) s at 400 m\)",
         (row % ("tether", 0, "period"), row % ("tether", 6, "period"))),
        (r"short tether \(below ([\d.]+) m\)", ("~" + LS % "tether][osc_zero",)),
        (r"slow drift \(\+([\d.]+) 1/s at 10 m\)", (row % ("tether", 0, "re"),)),
        (r"small ones: ([\d.]+) \+- ([\d.]+)j and ([\d.]+) 1/s, next to ([-\d.]+) and ([-\d]+) 1/s",
         tuple("~" + LS % f"eigenvalues][{i}][{j}" for i, j in ((3, 0), (3, 1), (5, 0), (1, 0), (0, 0)))),
        (r"weaker weathercock moment \(<= ([\d.]+) x Cnb\)", ("~" + LS % "weathercock][max_re_zero",)),
        (r"dihedral effect \(>= ([\d.]+) x Clb\)", ("~" + LS % "dihedral][max_re_zero",)),
        (r"the largest stable value \(([\d.]+) x\)", ("~" + LS % "weathercock][max_re_zero",)))


LATERAL = Covered(
    groups=("lateral_study", "wing_controllers"),
    checks=_sweep_cells() + _prose_checks() + (
        (r"\| (-\d+\.\d\d) \| roll subsidence", ("~" + LS % "eigenvalues][0][0",)),
        (r"\| (-\d\.\d\d) \+- (\d\.\d\d)j \| fast", ("~" + LS % "eigenvalues][1][0", "~" + LS % "eigenvalues][1][1")),
        (r"\| \*\*\+(\d\.\d{3}) \+- (\d\.\d{3})j\*\* \| \*\*sideways oscillation: period (\d+\.\d) s",
         ("~" + LS % "eigenvalues][3][0", "~" + LS % "eigenvalues][3][1", "~" + LS % "weathercock][rows][5][period")),
        (r"\| \*\*\+(0\.\d{3})\*\* \| slow sideways drift", ("~" + LS % "eigenvalues][5][0",)),
        (r"max Re = 0 at \*\*(\d\.\d\d) x Cnb\*\*; oscillation neutral at (\d\.\d\d) x Cnb",
         ("~" + LS % "weathercock][max_re_zero", "~" + LS % "weathercock][osc_zero")),
        (r"max Re = 0 at \*\*(\d\.\d) x Clb\*\*", ("~" + LS % "dihedral][max_re_zero",)),
        (r"oscillation neutral at (\d+\.\d) m; the drift", ("~" + LS % "tether][osc_zero",)),
        # laddermill lqr (the wing's default config): its discrete closed loop's largest |z|
        (r"the largest closed-loop discrete eigenvalue has \|z\| = ([\d.]+) at 0\.05 s", ("~{wing_controllers[z]}",))),
    given=("on a 100 m Dyneema tether in the paper's 8 m/s wind", "Schwab (1999)", "runs 4 points per sweep",
           "angle of attack (8 deg, elevator", "of the 6-state lateral model", "the wing 1 micrometre sideways",
           "with RK4 for 60 s", "variant with 8 x Clb", "better than 1e-3 1/s", "| column | x 0 | x 2 |",
           "(Clb = -0.36 /rad at 8 deg)", "(0.021 instead of 0.057 /rad at 8 deg)", "between 4 x and 6 x",
           "From 6 m/s up", "After a 0.01 rad", "wing 40 of the 101-wing laddermill", "after some 40 s (their Fig. 8)",
           "among others [8, 9]", "[8] is Bryant, Brown & Sweeting (1950)", "[9] is DeLaurier (1972)",
           "the paper's 40 s", "moving 101-wing chain on 70 m pieces", "3 deg dihedral, fin volume 0.024, bridle 1.5 m",
           "at the 0.05 s control period", "peaks near the default 100 m", "on this same 6-state model",
           "for 300 s after the paper's 0.01 rad"),
    timings=("(24 s on the shared 2-core machine at a load of 5-6, 2026-11-29;",),
    # the trim's tension, the Jacobian's entries, the eigenvector's phases and the single-column checks: worked in
    # a Python session with design_tethered_wing (the page says they are not part of the tool's output); the
    # doubling time of the drift and the growth-time estimate are ln 2 / 0.0134 and ln(100) / 0.111
    derived=("tension is 1.33 kN", "1 m of sideways CG displacement comes with 1.8 deg of yaw, leading the "
             "displacement by 52 deg, and 0.45 deg of roll, leading by 45 deg", "leads the displacement by 67 deg",
             "0.032 rad of yaw per m, against vy/V = 0.036 rad per m, and 15 deg behind it",
             "dvy/dy = -0.206 1/s^2, close to T / (L (m + m_cable/3)) = 0.208 1/s^2, which would give a 13.8 s period",
             "is -1.31 1/s", "dvy/dphi = 29.9 m/s^2", "dvy/dpsi = 7.8 m/s^2", "dr/dvy = +0.157 rad/s^2",
             "(dp/dr = 5.6 1/s)", "dvy/dr = 7.1 m/s^2", "(0.22 + 0.24 + 0.04)", "(0.38 + 0.08 + 0.01)",
             "The net 0.03", "(0.111 1/s x 0.29 m/s per m)", "reproduces the Clr x 0 entry",
             "| Cnb | -0.032 (stable) | +0.231 |", "| Clr | +0.022 | +0.152 |", "| Cnr | +0.249 | +0.028 |",
             "| CYb | +0.266 | +0.048 |", "doubles every 52 s", "(about -0.022 1/s per default Clb)",
             "(about 0.014 1/m x v0)", "shorter than about 11 m", "growing from 0.01 rad to about 1 rad at 0.111 1/s "
             "takes ln(100)/0.111 = 41 s", "2.7 times the largest", "about 1/6 of what",
             "a continuous equivalent of -0.89 1/s"),  # ln|z| / 0.05 s of the checked |z|
    # explored while choosing the sweep ranges (outside the tool's ranges: lateral_study prints no row for them)
    history=(History("2026-11-23", "python -m laddermill_gym.studies.lateral.lateral_study with wider sweep ranges",
                     "the trials that chose the sweep ranges (da759e2)",
                     ("trims failed at x = -1, -1.5, -2, -3 m and at +3 m",
                      "Trims failed at 4.5 m/s and below (4.8 m/s", "Trims failed for 600 m")),),
)

def v2_rows() -> tuple:
    """docs/mill_fast.md's rows of the in-plane v2 mill at 1-5 m/s (ramp 100 V_c s), against fast_mill case."""
    keys = ("t", "period", "P", "dT_P", "T_min", "T_max", "peak", "lo", "hi")
    return tuple((rf"\| {v} \| {100 * v} \| ([\d,.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) / ([\d.]+) \| "
                  r"([\d.]+) \| ([-\d.]+) \.\. ([-\d.]+)", tuple(f"~{{fast_mill_v2[v{v}][{k}]}}" for k in keys))
                 for v in range(1, 6))
