"""Which number of which docs page is checked against a command, and what every other number on a page is.

Every page of ``laddermill_gym/docs/`` is in :data:`LEDGER`: either a :class:`Covered` page, whose every quoted
number (:mod:`docsite.page_numbers`) is accounted for by one of its entries, or a :class:`NotYet` page with the reason
its numbers are not all checked yet (with the checks it has already). ``tests/test_page_figures.py`` enforces both
in the fast set (a page not in the ledger, a number on a covered page that no entry accounts for, or an entry that
matches nothing fails it); the slow set re-runs the checks (``python -m docsite.readme_figures --pages``).

A covered page's entries:

* ``checks``: (a regular expression over the page's flattened text, its groups' expected texts as ``str.format``
  templates over the measured figures, ``{group[key]...}``): the groups are re-run and compared exactly, to the
  printed digits;
* ``given``: snippets whose numbers are inputs (a command's settings, a scene's size), the papers' own figures,
  equation and figure numbers, dates and versions: nothing to re-run;
* ``timings``: snippets whose numbers are machine timings (durations, real-time factors, memory of a process):
  dated measurements, each with its machine and load on the page, not compared;
* ``derived``: snippets whose numbers are worked by hand from checked ones or read off a picture (no command
  prints them): listed so that a reader of this file sees them;
* ``not_rerun``: snippets whose numbers a command prints that the page figures do not re-run (too long for the
  slow set): the gap, stated.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Covered:
    groups: tuple = ()
    checks: tuple = ()
    given: tuple = ()
    timings: tuple = ()
    derived: tuple = ()
    not_rerun: tuple = field(default=())


@dataclass(frozen=True)
class NotYet:
    """A page whose numbers are not all accounted for yet: why, and the checks it has already (compared as a
    covered page's are; the rest of its numbers unchecked)."""

    reason: str
    groups: tuple = ()
    checks: tuple = ()


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
INDEX = Covered(given=("Schwab (1999)", "Schwab 1999", "Figs. 6-8", "Ockels 2007", "5 km string at 1 cm",
                       "Lansdorp et al. 2008", "his Fig. 3, eq. (6), the 35 m design", "after its 0.01 rad"))
ABOUT_DOCS = Covered(given=("MkDocs 1.6)", "MkDocs 1.6.1 (2024) is the last 1.x release", "May 2027", "MkDocs 1.x"),
                     timings=("about 1.5-3 minutes here",))

DEMO_ROW = r"{} +(\S+) +(\S+) +(\S+) +{}"
GETTING_STARTED = Covered(
    groups=("main_job", "simulate_laddermill", "simulate_tethered_wing"),
    checks=((DEMO_ROW.format("open_loop", r"(aerodynamic range exceeded: t = [\d.]+ s: slot \d+ alpha = [-\d.]+ deg, "
                                          r"beta = [-\d.]+ deg outside the aerodynamic range)"),
             tuple(f"{{main_job[open_loop][{i}]}}" for i in range(4))),
            (DEMO_ROW.format("lqr", "(ran to the end)"), tuple(f"{{main_job[lqr][{i}]}}" for i in range(4))),
            (DEMO_ROW.format("ppo_mill", "(ran to the end)"), tuple(f"{{main_job[ppo_mill][{i}]}}" for i in range(4))),
            (r"\((\d+\.\d+) s simulated, the step at 1 s\)", ("{simulate_laddermill[simulated]}",)),
            (r"wings (\d+)-(\d+) beyond the (\d+) m/s speed guard",
             ("{simulate_laddermill[first_wing]}", "{simulate_laddermill[last_wing]}", "{simulate_laddermill[guard]}")),
            (r"at the start \((0\.\d{4}) s, above the scene's (0\.\d+) s\)",
             ("{simulate_laddermill[stable_step]:.4f}", "{simulate_laddermill[dt]}")),
            (r"The run stops at ([\d.]+) s, when", ("{simulate_tethered_wing[contact_t]}",)),
            (r"ground contact at t = ([\d.]+) s: node (\d+) at height ([-\d.e]+) m",
             tuple(f"{{simulate_tethered_wing[contact_{k}]}}" for k in ("t", "node", "height")))),
    given=("at V_c = 2 m/s", "the paper's 0.01 rad wind-direction step (at 1 s) three times, 60 s after the step",
           "the paper's laddermill (101 wings", "generator at 2 m/s", "then 60 s of the 3D mill after the paper's 0.01 "
           "rad", "after some 40 seconds", "the step at 1 s", "exits 0", "exits 3", "after a 0.01 rad wind-direction",
           "A 0.01 rad turn"),
    timings=("113 s on the 2-core machine with numba's cache filled (2026-11-29)",
             "(base install, numba's and the operating-point caches empty, load 0.5, 2026-11-29)",
             "3 min 30 s (the demo 183 s of it)", "(about 30 s of compute)", "(about a minute, plus numba's",
             "(about 35 minutes on a 2-core machine from a fresh clone, 31 of them"),
    derived=("stops about 20 s after the step", "stops, about 20 s after", "(period about 20 s: zero crossings of "
             "the lateral position 9-12 s apart; the linear model's 23 s)", "dive after about 52 s"),
)

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

SCALE_OUT = Covered(  # every figure a dated timing on the shared 2-core machine (the page gives the load)
    given=("cores / N, at least 1 |", "one big machine) | 1 |", "of this node) | 1 |", "that cluster ( ) | 1 |",
           "a 0.5 s episode per environment", "two seeds, a 1 - cos gust, 120 s episodes", "a 2-core machine shared",
           "on 2 local workers", "| 2 workers [s] |", "lqr (3 repeats)", "open_loop (1 repeat; )", "1. **The same code",
           "a SHA-256", "2. **A filled numba cache", "3. **Shared paths**", "Ray 2.60 turns on", "(Ray 2.60 here"),
    timings=("about 30 kB per 60 s scenario", "load average 5.2-5.7 throughout", "medians of 3 fresh processes",
             "| **94.4** (the compile) | 0.197 |", "| 0.632 (the cache load) | 0.191 |", "| 0.450 | 0.200 | 0.198 |",
             "would pay 94 s of compile without a cache and 0.43 s of cache load with one, for 0.2 s of simulation",
             "| 4.62 | 13.05 | 0.35 | 8.38 | 3.69 (the LQR", "| 41.6 | 32.2 | 1.29 | 7.19 | 2.99 |",
             "(4.6 s serially)", "about 7-8 s (spawning and importing the workers, about 4-5 s under this load",
             "(42 s serially) gains 1.29x", "This takes 37 s here with a filled cache: LadderMill-v0's operating point "
             "costs 26 s", "(6.0 s against 1.6 s serially", "a 79 MB wheel, 240 MB installed", "take about 20 s here"),
)

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

MODEL = Covered(given=(  # the model's equations: their constants and the state layout, nothing measured
    "Schwab 1999", "3-2-1 Euler", "wing k (13 floats at offset 13 k): x (3, global CG position), q (4), v (3,",
    "w (3, body-frame", "free node j (6 floats at offset 13 n_w + 6 j): position (3, global), velocity (3, global)",
    "q' = 1/2 q (x) (0, w)", "per wing (6 dof) and the node velocity (3 dof)", "(C_L_de > 0, C_m_de < 0)",
    "(C_n_dr < 0, C_Y_dr > 0)", "C_l_da > 0)", "for 0 < h < h0 (n = 0.2)", "0 for h <= 0", "phi_inf (1 - exp",
    "(1 - 2.2558e-5 h)", "if V < 1e-9", "V^2 / 2", "from -180 to 180 deg", "g = (-w_a, 0, u_a)", "the 6-vector",
    "(sin a, 0, -cos a) ; r_ref x (CLad (sin a, 0, -cos a)) + (0, c Cmad, 0)", "the node velocity, or 0",
    "(e = 0 if l < 1e-9)", "mu g (0, 0, 1)", "C_N0 = 1.1, C_T0 = 0.02", "F_r = l (2 f_r + f_s)/6",
    "F_s = l (f_r + 2 f_s)/6", "+ 7/360 p_r", "- EA eps_p/l0 = 0", "(EA eps_p/l0)^(1/3))", "below 1e-13 of s (at most "
    "60 steps)", "l0 <= 1e-300 or l < 1e-9: sigma = max(sigma0, 0)", "sigma = max(sigma0, 0) if eps > 0 else 0",
    "R^T (0, 0, m g)", "J = [[Jxx, 0, -Jxz], [0, Jyy, 0], [-Jxz, 0, Jzz]]", "State per wing (6)", "per node (4)",
    "y = 0, v = 0, p = r = 0, phi = psi = 0", "sin(phi_s(h) + delta(t)), 0)"))

RL_ZOO3 = Covered(
    groups=("tethered_wing_lqr",),
    checks=((r"lqr +(\d+\.\d\d) +(\d+\.\d) +(\d\.\d{4}) +(\d+\.\d) +(-)",
             tuple(f"{{tethered_wing_lqr[{k}]}}" for k in ("return", "length", "dy", "power", "failures"))),),
    given=("(Python 3.11, torch 2.13 CPU)", "moviepy 2.2 wants and replaced pillow 13.0 by 11.3", "rl-zoo3 2.9 (",
           "(300 s episodes, the paper's 0.01 rad step), not the file's 60 s episodes",
           "| 1 thread [s / 1000 steps] | 2 threads", "(16 x 256 steps per rollout, 2 rollouts a run)",
           "(4 x 256 steps, 4 gradient steps per 4 transitions)", "(64 x 64)", "the 200,000-step run above",
           "200,000 steps are a demonstration", "the README's PPO took 12 M steps", "(20 frames/s, 640 x 480",
           "moviepy 2.x", "(11 frames at 20 frames/s come out as 10)",
           "For the 200,000-step run it printed (two 300 s episodes of the 0.01 rad step)", "rl-zoo3 (2.x)",
           "PPO (4096 steps) and SAC (200 steps)", "along 40 steps, and the same return of a 2 s episode"),
    timings=("165 MB of the 270 MB added", "wall time per 1000 env steps, median), on this project's 2-core machine "
             "while the other engineers' jobs kept its load average at 2.7 to 5.9",
             "| 5 | 0.124 (0.085 to 0.137) | 1.59 (0.59 to 4.39) | 12.9x |",
             "| 7 | 0.094 (0.076 to 0.119) | 0.90 (0.46 to 6.03) | 9.6x |",
             "| 3 | 3.98 (2.68 to 13.9) | 239 (189 to 262) | 60x |", "The issue reported 4.7x"),
    not_rerun=("(25 s of the 60 s episodes",  # an rl-zoo3 training run of 200,000 steps, not shipped
               "laddermill_gym-TetheredWing-v0_1 933.89 32.2 49.8734 7563.6"),
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

#: Every docs page: covered, or why not yet.
LEDGER = {
    "about_docs.md": ABOUT_DOCS,
    "architecture.md": Covered(),
    "command_line.md": Covered(given=("does about 40 s after the direction step",)),
    "getting_started.md": GETTING_STARTED,
    "index.md": INDEX,
    "layout.md": Covered(given=("eq. (6)",)),
    "paper_roberts.md": ROBERTS,
    "usage.md": Covered(given=("a pole at 0 for",)),
    "benchmarks.md": NotYet("machine timings almost throughout (env steps/s, real-time factors, cold and warm starts;"
                            " each dated with machine and load): to be listed as timings; helper T edits its cold-"
                            "start section this session"),
    "cable_data.md": NotYet("material data and worked numbers (given and derived) to list; no command"),
    "controllers.md": NotYet("README's TetheredWing-v0 rows are checked by readme_figures; the other tables "
                             "(LadderMill-v0 with a PPO run not shipped, the chain, the rotorcraft, the wing's PPO "
                             "scenarios) not yet; helper P edits the wing section this session"),
    "features.md": NotYet("a summary of the other pages' figures: to be checked through them"),
    "lateral_stability.md": LATERAL,
    "learned_mill.md": LEARNED_MILL,
    "mill_fast.md": MILL_FAST,
    "model.md": MODEL,
    "moving_cable.md": NotYet("insertion study, stable-step and LQR figures (minutes) and timings: not yet listed"),
    "numerics.md": NotYet("stable steps, error tables and timings: not yet listed"),
    "paper_lansdorp2008.md": NotYet("site and pumping-cycle figures (README's rows check the tether and Schmehl "
                                    "ratios): the page's own not yet listed"),
    "paper_meijaard1999.md": MEIJAARD,
    "paper_podgaets2007.md": PODGAETS,
    "pointmass.md": NotYet("pointmass_benchmark / pointmass_fidelity tables (timings and figures) not yet listed"),
    "pointmass_mill.md": NotYet("pointmass_mill (a rigid run to periodic, then three point-mass runs) not re-run yet"),
    "power_curve.md": NotYet("checked by its own replay test (tests/test_power_curve*: the printed replay against the"
                             " page); the prose figures not yet listed"),
    "pumping.md": NotYet("pumping-cycle and power-curve figures (minutes): not yet listed"),
    "quasisteady.md": NotYet("`laddermill site` / `design` figures and Lansdorp's tables: not yet listed"),
    "reeling_tether.md": NotYet("tether_convergence table (2 minutes; README's row checks two of its powers): not yet"
                                " listed"),
    "rl_zoo3.md": RL_ZOO3,
    "rotor.md": NotYet("rotor_chart and Gessow & Myers' figures: not yet listed"),
    "rotorcraft.md": ROTORCRAFT,
    "rotorcraft_design.md": NotYet("rotor_design's printed blocks (42 s; paper_roberts.md's four are checked): not "
                                   "yet listed"),
    "scale_out.md": SCALE_OUT,
    "wind.md": NotYet("wind-model constants (given) and turbulence cost timings: not yet listed"),
    "wing_data.md": NotYet("wing derivation figures (derive_wing) and the papers' data: not yet listed"),
    "work_precision.md": NotYet("work-precision tables (about 15 minutes, one thread each) and timings; helper R "
                                "edits it this session"),
}
