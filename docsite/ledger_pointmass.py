"""The ledger entries (:mod:`docsite.page_ledger`) of docs/pointmass_mill.md (the rigid run and the point-mass mill's
periodic searches against ``pointmass_mill``, :func:`docsite.mill_figures.pointmass_mill`) and docs/pointmass.md (its
closed forms against :mod:`docsite.pointmass_figures`)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed

PM = "{pointmass_mill[%s]}"
RIGID = tuple(PM % f"rigid][{k}" for k in ("power_kW", "first_kN", "last_kN", "min_kN", "min_element", "t"))
PM_ROW = (r"\| point mass \(implicit, 10 ms\) \| {} \| ([\d.]+) kW \| ([\d.]+) kN \| ([\d.]+) kN \| ([\d.]+) kN "
          r"\(slot (\d+)\) \|")
PM_KEYS = ("power_kW", "first_kN", "last_kN", "min_kN", "min_slot")
POINTMASS_MILL = Covered(
    groups=("pointmass_mill",),
    checks=(
        (
            r"rigid: ([\d.]+) kW, first element ([\d.]+) kN, last ([\d.]+) kN, smallest mean tension ([\d.]+) kN "
            r"at slot (\d+), periodic at (\d+) s\)",
            RIGID,
        ),
        (
            r"\| rigid \(RK4, 10 ms\) \| 101 x 70 m \| ([\d.]+) kW \| ([\d.]+) kN \| ([\d.]+) kN \| ([\d.]+) kN \(slot "
            r"(\d+)\) \| (\d+) s \|",
            RIGID,
        ),
        (PM_ROW.format("101 x 70 m"), tuple(PM % f"l70][{k}" for k in PM_KEYS)),
        (PM_ROW.format(r"(\d+) x 1 m"), (PM % "l1][nodes",) + tuple(PM % f"l1][{k}" for k in PM_KEYS)),
        (r"\(slot 50\) \| (\d+) s \| 207", ("~" + PM % "l70][t",)),
        (r"\(slot 50\) \| (\d+) s \| 7\.5", ("~" + PM % "l1][t",)),
        # the table's ratios (docsite/mill_figures.py's vs_rigid; until 2026-11-30 derived entries); a figure the
        # page gives for both strings is read twice by a lookahead, once per string
        (r"delivers (?=(\d+) %)(\d+) % more power at both resolutions \(70 m and 1 m\), with the first element's "
         r"tension (?=(\d+) %)(\d+) % and the last one's (?=(\d+) %)(\d+) % higher; .*? \(slot 50\) and is "
         r"(?=(\d+) %)(\d+) % higher\.",
         tuple("~" + PM % f"vs_rigid][{n}][{k}" for k, n in (
             ("power_pct", "l70"), ("power_pct", "l1"), ("first_pct", "l70"), ("first_pct", "l1"),
             ("last_pct", "l70"), ("last_pct", "l1"), ("min_pct", "l70"), ("min_pct", "l1")))),
        (r"changes the mean power by ([-\d.]+) kW \(([-\d.]+) %\) and each end tension by (?=([\d.]+) kN)([\d.]+) kN",
         tuple("~" + PM % f"vs_rigid][resolution][{k}" for k in ("kW", "pct", "ends_lo", "ends_hi"))),
        (r"the rigid run the start came from \((\d+) s\)", (PM % "rigid][t",)),
    ),
    given=(
        "(Podgaets & Ockels 2007)",
        "(veered ground point to node 0)",
        "(node n-1 to the hauled ground point)",
        "0 <= s < l_e",
        "node n-1 leaves",
        "enters at index 0",
        "a transfer moves 6 n numbers",
        "(every 0.5 s at 1 m elements and 2 m/s)",
        "l_e and 0 for a fixed string",
        "s < 0 transfers the other way (node 0 leaves, one enters at n-1)",
        "re-enters at index 0",
        "the first 0.1 l0 + s, the last 0.1 l0 + l_e - s (7-8 m",
        "(n_k + 0.2) l0",
        "a kite leaves 7 m from the hauled ground point and enters 7 m",
        "(7 m and 77 m)",
        "the paper's 1/10 and 11/10",
        "(the end elements 0.1-1.1 l_e)",
        "at 1 m elements a kite then enters 1 m",
        "The price: the 7 m",
        "(1 m elements, 2 m/s), every 0.5 s at 1 m elements against every 35 s",
        "At V_c = 0 this",
        "steady state to 1e-7.",
        "Resolving the string at 1 m",
        "end elements of 0.1-1.1 m:",
        "on nodes 0 and n-1",
        "so nodes 0 and n-1",
        "the first element is 7 m and the 1.5 m from CG",
        "(2 m/s, 101 wings,",
        "| 101 x 70 m |",
        "(RK4, 10 ms)",
        "(implicit, 10 ms)",
        "(implicit, 10 ms) | 7070 x 1 m",
        "(slot 50) | 1590 s",
        "(slot 50) | 1555 s",
        "counts from t = 0",
        "(shape 1e-3 l0, power 1e-3, twice)",
        "tail takes 9.6 % of the ascending wings' lift (-4 deg) and its descending setting (-1 deg)",
        "V_c = 0 reproduces",
        "at 70 m elements with both",
        "the mill's own 7 m / 14 m ends",
        "moving at +-2 m/s",
        "V_c (1 + eps), the tension EA eps to 1e-7",
        "to 1e-12 through",
        "l0 (1 + eps) along the cable to 1e-9",
        "(n_k + 0.2) l0 with the kites at 0.1 l0 and 1.1 l0",
        "the slow test runs the 70 m",
        # the fix of 2026-12-07 (a review): dates, the tests' settings and tolerances
        "*Fixed 2026-12-07*", "right-hand side of nodes 0 and n-1 once", "velocities of nodes 0 and n-1 as dt F / m",
        "until 2026-12-07 one trapezoid per step", "until 2026-12-07 the run stopped", "run 2026-12-07 after the fix",
        "(fixed 2026-12-07,", "to 1e-9 of the largest velocity", "at 10 and 25 ms within 0.25 % of the explicit "
        "method's at 1 ms (slow)", "inside the steps to 1e-12",
    ),
    timings=(
        "about 30-45 s, done once per process",
        "| 48 (3D, docs/moving_cable.md) |",
        "| 207 (0.048 ms per step) |",
        "| 7.5 (1.34 ms per step) |",
        "this machine's 2 cores shared with other jobs, load average 3-3.6; the times are the steps' wall time over "
        "100 s simulated",
    ),
    # atan(2 / 10) = 11 deg; the 7 m element stretched by 1.5 m; the fix's gain: 90.1 - 82.4 and 90.0 - 88.2 kW
    derived=("stretch it by 20 %", "about 11 deg", "which cost 7.7 kW at 70 m and 1.8 kW at 1 m"),
    # the fixed implicit step's first period from the rigid operating point, by a Python session of 2026-12-07
    # (PointMassMillSimulator from periodic_mill_start, 35 s at each method and step; tests/test_pointmass_pay_out.py
    # -m slow -s prints the 10 and 25 ms and the explicit 1 ms figures)
    not_rerun=("Now: 110.25 kW at 10 ms, 110.19 kW at 25 ms and 110.09 kW at 50 ms against the explicit method's "
               "110.28 kW at 2.5, 1 and 0.25 ms (at 7 m and 1 m elements 109.85-110.03 kW over the same implicit "
               "steps); at 0.1 s the implicit step fails 27 s into the period",),
    # the paper's insertion rule on tests/test_pointmass_mill.py's straight string: the test prints the first two
    # elements' tensions just after the transfer, "element 1 39.3 kN over the steady 21.6 kN" (21.6 kN = EA eps,
    # that string's setting; until 2026-12-01 not_rerun); the rejected variants' runs (dated)
    printed=(Printed("pointmass_insertion_test", ("carries 39 kN over its 21.6 kN",)),),
    history=(History("2026-12-07", "the review's repro scripts (kick.py, kick_power.py: the code before the fix)",
                     "the implicit step with the pay-out term kicked into the velocities, from the 70 m periodic start",
                     ("kicked by 10-450 m/s.", "(70 m elements) was 102.62 kW at 10 ms and -190.45 kW at 25 ms where "
                      "the explicit method at 2.5 ms gives 110.28 kW (the review's runs of 2026-12-07)")),
             History("2026-11-24", "python -m laddermill_gym.studies.pointmass.pointmass_mill (e7aff00)",
                     "the point-mass mill's periodic searches before the fix of the pay-out term",
                     ("read 82.4 kW (70 m) and 88.2 kW (1 m), first element 175.8 and 178.0 kN, last 134.6 and 133.9 "
                      "kN (runs of 2026-11-24): 25 % to 33 % more power than the rigid mill, and the 1 m string 6 kW "
                      "(7 %) above the 70 m one.", "The real-time factors then, 335 and 8.7 (0.030 and 1.15 ms per "
                      "step), were measured at a load average of about 4.")),
             History("2026-11-24", "mill_simulator of the rejected layouts (the paper's 1/10 and 11/10 at the element "
                     "scale; the static start) in a Python session", "the rejected variants (d017924, e7aff00)",
                     ("broke down (speed limit) 35 s after its start",
                      "(measured -240 kW at t = 60 s, 30 s after the ramp, at 70 m elements)")),),
)


#: docs/pointmass.md: the paper's equations and data, the scene's settings, the method's constants, counts
PM_GIVEN = (
    "(Podgaets & Ockels 2007)", "(paper eqs. 2-19)", "This is eq. (14)-(15)", "eqs. (7)-(9) as printed",
    "as in eq. (14)", "on its 2 deg grid", "(eqs. 20-22)", "Meijaard et al. eqs. (23)-(24)", "at 1 cm the string",
    "element e joins node e - 1 to node e; node -1", "6 float64)", "the paper's eq. (22)", "a 3x3 inverse pivot",
    "(about 6 (n/1024 + 1024) numbers,", "(the chain's omega_max = 2c/l0, c = sqrt(EA/mu), damped by the Voigt "
    "damping at the rate 4 DA/(mu l0^2))", "(dt/t_c)^2 + dt/t_d < 1, with t_c = l0/c and t_d = mu l0^2/(2 DA)",
    "Until 2026-12-07", "at 17.5 m elements with the explicit method diverged at 0.9 of it", "a review found it, "
    "fixed 2026-12-07)", "a review found, fixed 2026-12-07", "a mean power <= 0", "a run at 0.9 of it bounded",
    "given or refuse it, since 2026-12-07)", "default of 1 m yields", "the cable's 1 ms "
    "retardation time", "the benchmark uses 0.9 of it", "(M + dt C + dt^2 K) v+", "a = dt DA/l0 + dt^2 EA/l0 - b, b = "
    "dt^2 T/l", "(Baraff & Witkin 1998)", "at dt = 0.01 s on 1 cm elements", "at 1 cm; they are implicit",
    "tension is 0,", "P - 1 single separator", "W_j = S_j q_{j-1} W_{j-1}", "3x3 blocks, size P - 1", "P = 2 is the "
    "two-sided", "the chunks of P = 4 at 100,000 and 500,000 nodes", "50 steps at 1,000 nodes", "The work on one "
    "thread against P = 2 (500,000 "
    "nodes, minimum of 12)", "one chunk per 4096 nodes", "at least 2", "both sides of P = 2", "Checkpoints (n / seg + "
    "P + 1) x 15 numbers, one segment buffer per chunk P x seg x 9 and the chunks' data P x 48", "in this one on 2",
    "between P = 1 and P = 2, 8 or 16", "P = 2, the two-sided elimination, differs from the one-sided P = 1",
    "1e-12 relative is therefore", "chunks of 2048 nodes", "100 kites on 5 km of cable at 1 cm (500,000 elements, "
    "500,000 free nodes), one every 50 m,", "a station 50 m high", "(54 kg, 54 m^2,", "the laddermill's 2.5 cm",
    "The paper gives 5 km, 1 cm and 100 kites", "the 50 m spacing", "holds 100 kites on 5 km", "the base tension is "
    "195 kN", "the top kite 5060 m high", "The paper's 82 MB", "the paper's whole program: 82 MB", "budget 40 MB",
    "at 1 m elements (7 m gives", "(-4 deg ascending, +1 deg descending)", "1.5 m from the CG and the aerodynamic "
    "centre 0.75 m ahead", "(1 m elements,", "turned by 0.01 rad", "ramped over 1 s", "checkpoint segments of 1, 3 "
    "and 1024 nodes", "omega = 2 sqrt(k/m) sin(kappa l0 / 2) (modes 1 and 17 of 20,", "1/sqrt(1 + (w dt)^2)",
    "at one 70 m element per piece, implicit step 25 ms", "Open loop over 120 s", "over 2400 steps", "(at 70 m "
    "elements:", "40 control periods (2 s)", "(35 s) from the start", "after 12 periods", "at 70 m elements)",
    "on a zigzag 1 cm string with 3 g nodes", "3x3 pivots", "(PointMassChain-v0", "at 1 m elements;", "about 20 "
    "1/s", "rerun the "
    "benchmark",
    "the 24 MB state once", "L = 1/2 rho S C_L(alpha) |V| (d x V), D = -1/2 rho S C_D(alpha)",
    "(clipped at 0)", "and DP5(4) seven", "at dt omega >> 1",
    "settled 600 s from the rigid equilibrium,",
    # test_catenary_at_one_centimetre's bound on H's relative error (its measured -3e-9 Printed below)
    "within the test's bound of 1e-6",
    "then the chunks of P = 4", "one step of (500,000 nodes)", "On a zigzag 1 cm Dyneema string with 3 g nodes",
    "S - S D'^{-1} S", "both are P = 2,", "runs 20 implicit steps", "must be 0 and", "numba 0.68,", "a 16-core "
    "Intel Xeon", ", settled 60 s)")
#: worked by hand from the page's inputs: 4 x 24 MB; 24 + 4 + 24 MB; sqrt(195 kN / 0.3 kg/m); 1 cm / 800 m/s
#: the explicit step's closed form (sim.pointmass.explicit_stable_dt) at 1 cm, 17.5 m and 70 m of the same cable
PM_DERIVED = ("RK4 would hold four stage vectors (96 MB)", "another 24 MB: 52 MB in all", "about 800 m/s",
              "would bind dt near 1e-5 s", "is t_d to 3.5e-7", "at 17.5 m elements t_c = 2.06 ms, t_d = 2.13 ms and "
              "the limit 1.29 ms", "min(t_c, t_d), 1.6x the limit there", "and with the Voigt damping below 7.31 ms")
#: medians and minima of the page's benchmark runs, each with its machine and load on the page
PM_TIMINGS = (
    "| 10,000 | implicit | 1 | 0.01 | 1.64 | 164 | 6.1 | | 100,000 | implicit | 1 | 0.01 | 14.2 | 142 | 0.70 | | "
    "500,000 | implicit | 1 | 0.01 | 55.6 | 111 | **0.18** | | 500,000 | implicit | 2 | 0.01 | 75.3 | 151 | 0.13 | | "
    "10,000 | explicit | 1 | 1.56e-6 | 0.95 | 95 | 1.6e-3 | | 100,000 | explicit | 1 | 1.56e-8 | 5.8 | 58 | 2.7e-6 | | "
    "500,000 | explicit | 1 | 6.25e-10 | 35.5 | 71 | 1.8e-8 | | 500,000 | explicit | 2 | 6.25e-10 | 45.7 | 91 | "
    "1.4e-8 |",
    "(2 cores shared by four engineers, load average 4-5 during the run: timings are medians of 5 repeats,",
    "over 10k / 100k / 500k: max/min 1.47 (implicit) and 1.64 (explicit) in that loaded run; 1.14 and 1.09 in a "
    "quieter quick run", "On the idle 16-core machine", "one thread 229 / 219 / 248 ns per element (implicit, max/min "
    "1.13) and 137 / 143 / 134 (explicit, 1.07); 16 threads 88 / 65 / 73 (implicit, 1.37) and 34 / 11 / 15 (explicit, "
    "2.96: at 10,000 elements a step of 0.3 ms", "Implicit at 500,000 elements on 16 threads: 0.275x real time",
    "(about 20 ms per step at 10,000 elements, where one thread needs 1-2 ms)", "500,000 elements):",
    "| 1 | 124.4 | 1.00 | 0.080 | 73.1 | 1.00 | | 2 | 66.2 | 1.88 | 0.151 | 38.2 | 1.92 | | 4 | 47.4 | 2.63 | 0.211 | "
    "18.8 | 3.89 | | 8 | 38.4 | 3.24 | 0.260 | 10.7 | 6.85 | | 16 | 37.9 | 3.28 | 0.264 | 5.2 | 14.12 |",
    "1.38x on 2 threads and 2.08x on 16", "Peak resident memory of the scene's process there: 219 MB",
    "(elimination 68 ms and the rest 65 ms on one thread), the model of \"Methods\" expects about 20 ms on 8 threads "
    "and 11 ms on 16 (0.9x real time), against 38 ms", "(2 cores shared by three engineers, load average 2-5; minimum "
    "of 15 single steps", "| 100,000 | 1 | 10.17 / 10.36 | 10.50 / 10.41 | 5.28 / 5.43 | 5.50 / 5.47 | | 100,000 | 2 "
    "| 9.31 / 13.11 | 13.45 / 13.23 | 2.71 / 2.74 | 2.78 / 2.79 | | 500,000 | 1 | 55.73 / 55.61 | 57.10 / 56.57 | "
    "31.32 "
    "/ 27.49 | 27.58 / 27.68 | | 500,000 | 2 | 74.49 / 82.42 | 83.20 / 88.77 | 37.67 / 39.83 | 38.17 / 44.06 |",
    "moved by up to 50 % between runs", "gave 12.4-14.4 ms at 100,000 and 71-76 ms at 500,000 on one thread",
    "216 MB with numba's on-disk cache warm (repeated runs 216-256 MB), 414 MB and 524 MB", "About 143 MB of it",
    "An end chunk costs 54 ns per node", "a middle one 90 ns", "take 1.70 and 1.72 ms at 100,000 nodes",
    "1.16x for P = 3, 1.26x for 4, 1.59x for 8, 1.70x for 16", "24 to 57 s on the shared two-core machine",
    "take 0.02 s", "which costs about three minutes", "takes about 3 min", "so end chunks are 5/3 the size")
#: figures the pointmass_benchmark (the full run: its held arrays and accuracy lines) and pointmass_fidelity studies
#: print: long groups (python -m docsite.readme_figures --long NAME)
PM_PRINTED = (
    # the footprint with workspaces for 16 and 128 chunks: "held in all with a workspace for 16 / 128 chunks [MB]:
    # 29.41 / 35.17" (printed since 2026-11-30; until then not_rerun)
    Printed("pointmass_accuracy", ('(29.41 MB with room for 16 chunks;',
                                   '29.41 MB with a workspace for 16 chunks, 35.17 MB for 128')),
    Printed("pointmass_accuracy", (
        'state 24.00 MB, workspace 4.19 MB, parameters 0.50 MB, **28.69 MB** in all on 2 threads',
        'holds 28.69 MB on 2 threads,',
        'over 0.2 s from the quasi-static start (10,000 elements, explicit dt 1.56e-6 s,',
        'largest kite-position difference 3.0e-3 m at dt = 0.01 s, 3.2e-4 m at 1e-3 s, 3.3e-5 m at 1e-4 s',
    )),
    Printed("pointmass_fidelity", (
        'within 0.1 kN',
        'first piece 161.0 kN (rigid) vs 178.9 kN (point mass,', 'last piece 71.8 vs 67.3 kN',
        "-9.6 % and +4.4 % of the wing's C_L",
        'within 0.9 % (first piece) and 0.01 % (last)',
        'up to 44 m (70 m with matched lift) on a 3.6 km high loop',
        'falls to 0.1-0.2 kN',
    )),
    # PointMassChain-v0 open loop over 120 s: "open_loop 1455.64 120.0 6.9404 ..." (return, length, max |dy| [m])
    Printed("pointmass_chain_open_loop", ('return 1456', 'up to 6.9 m sideways')),
    Printed("test_figures_quick", ('to 3.2e-15',  # -k banded's largest (n = 5003, P = 7)
                                   'base tension 178.5 kN')),  # -k settled_chain: 178.51 kN (2026-11-30)
    Printed("pointmass_fidelity", ('against 178.9 kN',)),  # the fidelity study's point-mass first piece
    # tests/test_pointmass_mill_env.py -s -k power_term prints the reward's reference power (the first period's)
    # the rigid wing's sideways oscillation (docs/lateral_stability.md's default wing: its doubling time)
    Printed("lateral_weathercock", ('doubles every 6.2 s',)),
    Printed("pointmass_mill_env_start", ('from the start, 110.2 kW', '(110.2 kW')),
    # the point-mass mill env's start: the rigid run's periodic time (periodic_mill_start's t0) and the 70 m string's
    # converged power, as the study prints them (pointmass_mill.md's page group pointmass_mill parses the same output)
    Printed("pointmass_mill_study", ('t0 = 1135 s', 'the converged point-mass motion gives 90.1 kW',
                                     "converged motion's 90.1 kW")),
    # -k backward: "condition number 3.3e+05" (eigvals_banded of the zigzag string's matrix, 2026-12-01)
    Printed("pointmass_solver_tests", ('(condition number 3.3e5)',)),
    # scipy's solve_banded (LAPACK) on the zigzag string, per CPU: "solve_banded's backward error 4.8e-17" on znver4
    # (2026-12-02), 7e-17 on znver3 (2026-12-01)
    Printed("pointmass_solver_tests", ("against solve_banded's 4.8e-17 on znver4",
                                       "against LAPACK's 4.8e-17 on znver4"), cpu="znver4"),
    Printed("pointmass_solver_tests", ('(7e-17 on znver3)',), cpu="znver3"),
    # tests/test_pointmass_threads.py -k 500000_nodes: "P = 2 against P = 1 at 500,000 nodes: velocities 2.5e-11 of
    # the largest (0.087 m/s), positions 9.1e-13 m" (the same for P = 8 and 16; 2026-12-01)
    # per CPU (docsite/host_cpu.py): 2.5e-11 on znver3 (2026-12-01), 2.1e-11 on znver4 (2026-12-02)
    Printed("pointmass_roundoff_500k", ('of the largest velocity (0.087 m/s) and 9e-13 m in position;',)),
    Printed("pointmass_roundoff_500k", ('by 2.1e-11 on znver4',), cpu="znver4"),
    Printed("pointmass_roundoff_500k", ('(2.5e-11 on znver3:',), cpu="znver3"),
    # tests/test_pointmass_lateral.py (2026-12-01; the page's "within about 10 s" and "1e-10 m/s" until then)
    Printed("pointmass_lateral_test", ('overshooting by 28 % 7.4 s after the step, within 10 % of it from 10.6 s and 1 '
                                       '% from 25.1 s, and stays (node speeds 8.7e-11 m/s after 120 s;',)),
    Printed("pointmass_solver_tests", (  # tests/test_pointmass_threads.py and _oracles.py print what they assert
        'by up to 3.1e-11 of the largest velocity', 'backward error of 3e-12 to 5.5e-12,',
        'its backward error is 5e-12',
        'agree to 1.1e-7', 'and 4.5e-13 m',  # P = 7's positions, 9e-17 of the largest (5 km)
        # -k one_centimetre: "1 cm (11,000 elements): relative error of H -3e-09" (2026-11-30)
        'and -3e-9 at 1 cm (11,000 elements)',
        "(H = 651.998593 N) with the oracle's -1.4e-3 and -8.9e-5 relative errors at 16 and 64 elements (second "
        "order)",
    )),
)
#: figures of runs the repository no longer makes (issue 33 point 6: until 2026-12-01 not_rerun)
PM_HISTORY = (
    # the implicit step with slack elements left out of its matrix: a variant tried while the method was written
    # (before a0790b0) and not kept; the page's text of it is b136f3d's
    History("2026-11-24", "the catenary relaxation of a 256-element string with the implicit step's slack elements "
            "dropped from the matrix (a variant of a0790b0's kernel, not committed)",
            "the rejected slack-element variant", ("(speeds over 1000 m/s within seconds at 256 elements,",)),
    # the slack element's damping in the implicit step's matrix, and the variant without it (a review's scripts)
    History("2026-12-07", "a review's scripts on the implicit step: one step of a 10-element podgaets_5km string with "
            "a slack element, and the moving mill's first period, with the slack element's damping dropped from "
            "kernels/pointmass/blocks.py (not committed)",
            "the slack-damping variant (4ddc82a's kernel and the variant)",
            ("10-element string of the cable's data with one element at 0.9 l0 closing at 2 m/s",
             "On the moving mill at 70 m elements", "power at 10 and 25 ms unchanged",
             "differed from the model's by 2931 and 4193 N at 1 ms and 0.1 ms against the limit DA/l0 x 2 m/s = "
             "4320 N.",
             "made that difference 47 N at 0.01 ms", "at 0.1 s",
             "it ran through with 129.76 kW against the explicit method's 110.28 kW")),
    # the two-sided elimination of b84856b against the partitioned one of f5e25de, both P = 2 on 1 and 2 threads
    History("2026-11-24", "the implicit step of b84856b (two-sided elimination) and of f5e25de (partitioned) on the "
            "same starts, NUMBA_NUM_THREADS 1 and 2 (8f8b734's before/after table)",
            "the partitioned elimination's before/after comparison",
            ("at 20,000 nodes (5 steps, 1 and 2 threads) and within 2.8e-17 m/s in 36 of 1,000 nodes",)),
)

PMD = "{pointmass_data[%s]}"  # docs/pointmass.md's closed forms
POINTMASS = Covered(
    groups=("pointmass_data",),
    checks=((r"For the 2\.5 cm Dyneema \(EA ([\d.e]+) N, DA ([\d.e]+) N s, mu ([\d.]+) kg/m\) at 1 cm the first is "
             r"([\d.e-]+) s and the second \*\*([\d.e-]+) s\*\*",
             tuple("~" + PMD % k for k in ("EA", "DA")) + (PMD % "mu",)
             + tuple("~" + PMD % k for k in ("wave_dt_1cm", "damp_dt_1cm"))),
            (r"48 bytes per node, (\d+) MB for 500,000 nodes", (PMD % "state_MB",)),
            (r"one float64 tension per element \((\d+) MB\) and one kite-flag byte per node \(([\d.]+) MB\)",
             (PMD % "tension_MB", PMD % "flag_MB")),
            (r"every min\(1024, sqrt\(n\)\) nodes \((\d+) at 500k\)", (PMD % "seg",)),
            (r"seg = min\(1024, sqrt\(n\)\) \((\d+) at 500,000 nodes\)", (PMD % "seg",)),
            (r"\(3P \+ 4\)/5 times faster than the one-sided one on one core: ([\d.]+) for P = 2 \(as the two-sided\), "
             r"([\d.]+) for 4, ([\d.]+) for 8, ([\d.]+) for 16", tuple(f"{{pointmass_data[speedup][{i}]}}"
                                                                     for i in range(4))),
            (r"the base tension is 195 kN \((\d+) % of the breaking load\)", (PMD % "base_share_pct",)),
            (r"Every kite is pitched to 6 deg \(C_L ([\d.]+), C_L/C_D ([\d.]+)\)", (PMD % "cl6", PMD % "ld6")),
            (r"the kite moves ([\d.]+) m sideways, the wind's turn of its 14\.3 m", (PMD % "sideways_m",)),
            (r"l0 / c = ([\d.]+) ms", (PMD % "wave_dt_70m_ms",)),
            # the fidelity study's printed tensions' ratios and the accuracy run's "kites travel up to 0.0302 m" in cm
            # (docsite/printed_ratios.py, --long pointmass_fidelity / pointmass_accuracy; until 2026-11-30 derived)
            (r"\(point mass, ([-+]\d+) %\); last piece [\d.]+ vs [\d.]+ kN \(([-+]\d+) %\)",
             ("~{pointmass_fidelity[first_pct]}", "~{pointmass_fidelity[last_pct]}")),
            (r"the kites move up to (\d+) cm\)", ("~{pointmass_accuracy[kites_cm]}",))),
    given=PM_GIVEN, timings=PM_TIMINGS, derived=PM_DERIVED, printed=PM_PRINTED,
    # the fixed implicit step's first period of the mill (pointmass_mill.md's not_rerun, the same session)
    not_rerun=("within 0.2 % up to 50 ms; a step that fails in it, 0.1 s,",),
    # the solver's agreements the page quoted before today's printed ones (issue 33 point 6, 2026-11-30)
    history=PM_HISTORY + (History("2026-11-24", "pytest tests/test_pointmass_threads.py (8f8b734)",
                     "the random and zigzag strings' agreements as first measured",
                     ("(2026-11-24: 3.4e-15)", "2026-11-24: 7e-17 and 1.5e-7)")),
             History("2026-11-24", "the point-mass mill env's start and the study (1ae2870, e7aff00), before the fix "
                     "of the pay-out term (2026-12-07)", "the env's power reference and the converged 70 m motion",
                     ("these read 102.6 kW and 82.4 kW (runs of 2026-11-24)",)),
             History("2026-11-24", "PointMassChain-v0's settled start (a92a31d)",
                     "the env's first settling run, 600 s from the rigid equilibrium", ("2026-11-24: 178.7 kN),",)),),
)
