"""The ledger entries (:mod:`docsite.page_ledger`) of docs/moving_cable.md and (partly) docs/features.md. The first:
the insertion study at 0.5 and 5 m/s, the in-plane mill's run to periodic motion (the page's own command), the mill
LQR's check over the period and the v1 mill's powers (:mod:`docsite.mill_figures`,
:func:`docsite.page_figures.meijaard_v1`)."""

from __future__ import annotations

from docsite.host_cpu import CPU
from docsite.ledger_kinds import Covered, History, Printed

IN, PE, LQ = "{insertion_study[%s]}", "{mill_periodic_2d[%s]}", "{mill_lqr_check[%s]}"
N = r"([\d.]+)"
SC, ON = "{gusts_v1_%s[scorecard][%s]}", r"(\d+ / \d+)"  # a gust scorecard, exact (docsite/gust_scorecards.py)
#: features.md's gusts-v1 table: each env's scorecard per controller (long groups gusts_v1_<env>)
GUSTS_V1_TABLE = (
    # the LQR's count and the scenarios it loses, quoted per CPU (docsite/host_cpu.py): the group's CPU's are compared
    (rf"\| TetheredWing-v0 \| {ON} \|", (SC % ("tethered_wing", "open_loop"),)),
    (rf"\| TetheredWing-v0 \| \d+ / \d+ \| [^|]*?{ON} on {CPU} \(AVX\w+; lost: ([^)]*)\)[^|]*",
     (SC % ("tethered_wing", "lqr"), "@{gusts_v1_tethered_wing[lost][lqr]}")),
    (rf"{ON}(?= \((?:`ppo_tethered_wing`| ), 40 min with a critic)", (SC % ("tethered_wing", "ppo_tethered_wing"),)),
    (r"NTM IB seed (\d+) and Dryden moderate lost\)",
     ("{gusts_v1_tethered_wing[lost_seeds][ppo_tethered_wing][NTM_IB]}",)),
    (rf"\| LadderChain-v0 \| {ON} \| {ON} \(turbulence brings the 101-wing chain down under both\)",
     (SC % ("ladder_chain", "open_loop"), SC % ("ladder_chain", "lqr"))),
    (rf"\| Rotorcraft-v0 \| {ON} \| {ON} \(turbulence survived on every seed\)",
     (SC % ("rotorcraft", "open_loop"), SC % ("rotorcraft", "lqr"))),
    (rf"{ON}(?= \((?:`ppo_rotorcraft`| ): ECD lost, as by the LQR\))", (SC % ("rotorcraft", "ppo_rotorcraft"),)),
    (rf"\| LadderMill-v0 \| {ON} \| {ON} \|", (SC % ("laddermill", "open_loop"), SC % ("laddermill", "lqr"))),
    # the scenarios the notes name, as sets of gust_bench.json's scenario ids (docsite/gust_scorecards.py)
    (r"(Dryden moderate) on every seed; the count depends",
     ("@{gusts_v1_tethered_wing[lost_every_seed][lqr]}",)),
    (r"critic warm-up and validation: (NTM IB seed \d+ and Dryden moderate) lost\)",
     ("@{gusts_v1_tethered_wing[lost][ppo_tethered_wing]}",)),
    (r"(?=(ECD) lost)(ECD) lost, as by the LQR\)", ("@{gusts_v1_rotorcraft[lost][ppo_rotorcraft]}",
                                                   "@{gusts_v1_rotorcraft[lost][lqr]}")),
)
RG = "{pointmass_mill[rigid][%s]}"
MOVING_CABLE = Covered(
    groups=("insertion_study", "mill_periodic_2d", "mill_lqr_check", "meijaard_v1", "pointmass_mill",
            "simulate_laddermill_half"),
    checks=(
        # laddermill simulate laddermill --start periodic --dt 0.005 (267 s at nice 15, load 6, 2026-11-29)
        (r"Halving the step changes nothing in the periodic motion \(mean power ([\d.]+) kW",
         ("{simulate_laddermill_half[periodic_kW]}",)),
        (rf"prints dv = {N} m/s, a jump of {N} kN \(closed form {N} kN\) and a dip of {N} kN at {N} ms \({N} kN at {N} "
         rf"ms\) from {N} kN", tuple(IN % f"v0.5][paper][{k}" for k in ("dv", "jump", "jump_closed", "dip", "dip_ms",
                                                                        "spring", "quarter_ms", "before"))),
        (rf"dv = {N} m/s and a spring estimate of {N} kN against a tension of {N} kN: the element goes slack and "
         rf"rebounds to {N} kN within (\d+) ms", tuple(("~" if k == "before" else "") + IN % f"v5][paper][{k}"
                                                 for k in ("dv", "spring", "before", "largest", "window_ms"))),
        (rf", dv = {N} m/s \({N} m/s at 5 m/s\), the tension moves by {N} kN \({N} kN\) at the insertion",
         ("~" + IN % "v0.5][cable][dv", "~" + IN % "v5][cable][dv", "~" + IN % "v0.5][cable][jump",
          "~" + IN % "v5][cable][jump")),
        (rf"a quarter period \({N} ms\) later", (IN % "v0.5][paper][quarter_ms",)),
        (rf"along a first element of l1 = {N} m", (IN % "v0.5][paper][l1",)),
        (rf"repeats itself to {N}e-4 l0 in shape and {N}e-4 in power per period after about (\d+) s",
         ("~" + PE % "shape_e4", "~" + PE % "power_change_e4", "~" + PE % "t")),
        (rf"in 2D and 3D alike: mean generator power {N} kW", (PE % "power_kW",)),
        (rf"smallest mean tension {N} kN at the top of the loop \(slot (\d+)\), the first element at {N} kN and the "
         rf"last at {N} kN", tuple(("~" if k.endswith("kN") else "") + RG % k
                                   for k in ("min_kN", "min_element", "first_kN", "last_kN"))),
        (rf"\(open-loop growth {N}-{N} 1/s at the phases checked below\)",
         ("~" + LQ % "growth_min", "~" + LQ % "growth")),
        (rf"max \|z\| between {N} and {N} \(two phases, s / l0 = {N} and {N}, have",
         ("~" + LQ % "z_min", LQ % "max_z", "{mill_lqr_check[z_above_1][0]}", "{mill_lqr_check[z_above_1][1]}")),
        (rf"the 700 control steps, has spectral radius {N}; with the transfer's own Jacobian",
         ("~" + LQ % "flow_radius",)),
        (rf"lateral offset and speed\) it is {N}\.", ("~" + LQ % "radius",)),
        (rf"v1 periodic at 1 and 2 m/s \({N} and {N} kW\)",
         ("~{meijaard_v1[2D_1][mean_power_kW]}", "~{meijaard_v1[2D_2][mean_power_kW]}"))),
    given=("Meijaard, Ockels & Schwab (1999)", "initially 1/10 l0 and 11/10 l0", "through wing slots 0, 1, ..., n-1",
           "element 0 is the first", "0 <= s < l0", "V_c > 0 when", "(f_first = 1/10, f_last = 11/10: the paper)",
           "eps = l / l0 - 1", "DP5(4)", "the wing in slot n-1", "enters slot 0", "(the 11-wing mill in plane, slowed "
           "to 0.5 m/s for its first transfer, stepped through it at 0.1 ms)", "(rates 0). s < 0",
           "(a wing leaves slot 0, one enters slot n-1", "(v_r + v_s) / 2", "l0 / 10 =", "on a 54 kg wing",
           "at dt = 12.5 ms, beyond RK4's 2.83", "the chain's 12.5 ms", "The scene's dt is therefore 10 ms",
           "where the 12.5 ms runs", "\"Meijaard et al. (1999) reproduced\"", "The default mill (101 wings, V_c ramped "
           "to 2 m/s in 30 s, elevator -4 deg ascending and -1 deg descending)", "\"of the order of 200 kW\"",
           "At a descending elevator of 0 deg (and +1 deg,", "With 11 or 21 wings", "at its 10 ms step",
           "at the earlier 12.5 ms", "all 101 slots", "per slot: 606 states", "per slot: 202 inputs",
           "at the control period 0.05 s", "the operating point's 2 m/s", "at 8 phases", "the 8 frozen closed loops",
           "f = 1/11 of", "Below 1 is", "(two phases,", "the paper's 0.01 rad direction step it keeps",
           "The paper's figures 6-8 and the power at 1, 2 and 5 m/s", "not at 5 m/s; after the 0.01 rad",
           "(1,616 right-hand sides",
           # a test's tolerance, and the earlier measurement that set the old step
           "coupling blocks below 1e-6", "(to 1e-9 m over 60 s of", "had found 0.0176 s",
           "prints it at its start, 2026-11-30;",  # the day of the printed stable step below
           "(found by a review, 2026-12-07)", "where the new wing in slot 0 is"),
    timings=(", 0.3 s)", "the 3D mill at 48x real time on one thread", "(57x", "(About 4 minutes.)",
             "(1 min on a quiet machine: 30 s for the operating point, 15 s for the Riccati equation)", "(about 30 s)"),
    # closed forms from the page's inputs and the printed figures: ln |z| / 0.05 s of the two phases above 1, 1/11 of
    # V_c, EA / 7 m on the 54 kg wing, omega dt, the 70 m / 2 m/s period
    derived=("growing at about 0.03 1/s", "at about V_c / 11", "dv of about 0.9 V_c", "(k1 = EA / l1 = 3.1 MN/m)",
             "= 7 m long", "EA / 7 m = 3.1e6 N/m", "near 240 rad/s (omega dt = 3.0", "(omega dt = 2.4)",
             "one piece per 35 s period",
             "(8 transfers)"),  # 300 s at one transfer per 35 s period: 8.6, 8 whole transfers
    # runs the page figures do not repeat: the stable-step estimate at the 3D periodic state, the halved step, the
    # tail-setting and small-mill runs (1500-4000
    # s), the 2D / 3D comparison (tests/test_moving_cable_modes.py), the LQR's per-phase table and its 300 s run, the 3D
    # direction step of the meijaard study
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        Printed('mill_transfer_transient', (
            "each of the period's first 70 control steps:",
            "slot 0's own block grows at up to 27.628 1/s (s / l0 = 0.0143);",
            "the frozen closed loop reaches max |z| 1.5699 and is at or above 1 at 36 of the 70 steps",
            "(1.0052 at s / l0 = 0.09,",
            "and those 70 steps' transition matrix has a 2-norm of 30.9:",
            "With these per-step models and 40 frozen phases after them, the period's transition matrix with the "
            "transfer has spectral radius 0.106, against 0.0988 from the 8 phases:")),
        # tests/test_moving_cable_modes.py -s -k in_plane (the page's 4e-8 m of 2026-11-23 a History record)
        Printed('test_figures_quick', ('agree to 9.7e-9 m in every wing position over 100 s (2 transfers)',)),
        Printed('mill_v0_paper_step', (
            'within 0.08 m for 300 s', 'where the open loop leaves the aerodynamic range at 8.7 s',
        )),
        Printed('meijaard_v1_printed', (
            'ends physically 6.4 s after the step',
        )),
        # the stable-step estimate at the periodic start (laddermill simulate prints it before it runs: "estimated
        # stability limit at the start 0.01221 s (eigenvalue -30.28+240.4j 1/s)", --long, 52 s, 2026-11-30; until
        # then not_rerun, the page's 0.01223 s of 2026-11-24 a History record)
        Printed('simulate_laddermill_periodic', ('-30 +- 240i 1/s, limit 0.01221 s',)),
        # tests/test_mill_periodic_variants.py: the 2D periodic motion at 10 and 5 ms, "period-mean tensions at 10 ms
        # against 5 ms: within 14.6 N (element 0) of the first element's 160.0 kN" (2026-12-01, 658 s; until then
        # not_rerun, the page's "within 4 N" of 2026-11-29 not what the two runs give)
        Printed('mill_half_step_test', ('period-mean element tensions within 15 N of 160 kN,',)),
        # the same file's 11 and 21 wings: "NOT converged" after max_time 1500 s (2026-12-01; until then not_rerun)
        Printed('mill_small_test', ('no periodic motion within 1500 s',)),
    ),
    # the first 2D / 3D comparison, before today's printed 9.7e-9 m (issue 33 point 6, 2026-11-30)
    history=(History('2026-11-23', 'run_to_periodic of the in-plane laddermill scene with initial.elevator_down_deg '
                     '0, +1 and -2 deg (ef94d23, RK4 at the then 12.5 ms step)',
                     'the tail-setting runs of 2026-11-23 (1500-4000 s each, not kept; re-running them at today\'s '
                     '10 ms is an hour or more of this machine, and no command prints the descending wings\' angle '
                     'of attack and pitch-rate ranges; until 2026-12-01 not_rerun)',
                     ('not settle within 1500-4000 s (runs of 2026-11-23 at the then 12.5 ms step)',
                      'between -90 and +66 deg at t = 300 s, pitch rates up to 3.5 rad/s) and the mean power per '
                      'period swings between -100 and +280 kW. At -2 deg it settles with 24 kW')),
             History('2026-11-23', 'pytest tests/test_moving_cable_modes.py (ef94d23)',
                     'the 2D and 3D runs from the same in-plane start over 100 and 200 s',
                     ('2026-11-23: 4e-8 m, and 2e-8 m over 200 s)',)),
             History('2026-11-24', 'the stable-step estimate at the periodic state of the day (2f2b941, when the '
                     'scene moved from 12.5 to 10 ms)', 'the laddermill scene just after a transfer',
                     ('0.01223 s as first measured on 2026-11-24',))),
)

FEATURES = Covered(  # a summary of the other pages: their groups check what it repeats
    groups=("mill_periodic_2d", "pointmass_benchmark", "simulate_laddermill", "craft_stability", "pointmass_mill",
            "gusts_v2_pumping", "gusts_v2_mill"),
    checks=((r"periodic after about (\d+) s, (\d+) kW mean generator power", ("~" + PE % "t", "~" + PE % "power_kW")),
            (r"5 km at 1 cm, ([\d,]+) elements, ([\d.]+) MB held on two threads",
             ("{pointmass_benchmark[elements]}", "{pointmass_benchmark[held_MB]}")),
            (r"against the rigid mill's ([\d.]+) kW", ("{simulate_laddermill[periodic_kW]}",)),
            (r"periodic with ([\d.]+) kW at 1 m elements and ([\d.]+) kW at 70 m",
             ("{pointmass_mill[l1][power_kW]}", "{pointmass_mill[l70][power_kW]}")),
            (r"the critical wind speed \(([\d.]+) m/s for the flying model", ("~{craft_stability[critical]}",)),
            *GUSTS_V1_TABLE,
            # --long stress_all's summary (docsite/printed_ratios.py's stress_counts; 2026-11-24: all 128 pass; the
            # first run of 2026-11-30: 127, the mill's bang-bang case before its end was named a model limit)
            (r"10,000 env episodes: (\d+) of (\d+) cases pass on 2026-11-30, the mill under bang-bang controls "
             r"ending at a limit of the quasi-steady model",
             ("{stress_all[passed]}", "{stress_all[total]}")),
            # a bound over wind.md's gusts-v2 mill table: every seed lost, the last at 14.8 s (2026-11-30; until then a
            # derived entry)
            (r"controller keeps the mill through turbulence or EWS beyond (\d+) s \(its lowest slots fail by "
             r"sideslip\)\.", ("{gusts_v2_mill[end_bound]}",)),
            (r"LQR survives every discrete event and (\d+) of (\d+) NTM seeds",  # gusts-v2, as wind.md's table
             ("{gusts_v2_pumping[lqr/NTM_IB][kept]}", "{gusts_v2_pumping[lqr/NTM_IB][seeds]}")),
            # the rigid in-plane mill's smallest period-mean tension, as pointmass_mill's rigid run prints it (the
            # same run as moving_cable.md's "smallest mean tension"; until 2026-11-30 not_rerun)
            (r"the smallest tension \(([\d.]+) kN\) at the top of the loop", ("{pointmass_mill[rigid][min_kN]}",))),
    given=(
        'On the 101-wing chain 10 s after a direction step, ROS34PW2 at 0.2 s',  # wp_chain's scene, forcing, step
        '1999, eqs.',
        '1-25;',
        'rigid bodies with unit-quaternion attitude (3-2-1 Euler angles on request), quasi-steady aerodynamics, '
        'nonlinear in angle of attack through post-stall with alpha-rate terms, lateral derivatives linear in '
        'sideslip, roll and yaw rate with alpha-dependent coefficients;',
        'and Dormand-Prince 5(4)',
        "the paper's 54 m^2 wing (coefficients by a DATCOM-style component build-up evaluated strip by strip, "
        'with lifting-line downwash;',
        '[docs/wing_data.md], regenerated by ), a 2.5 cm Dyneema cable ([docs/cable_data.md]).',
        "(one wing on a 100 m cable), (the paper's 101 wings on 70 m pieces between two ground points, cable not "
        'moving)',
        'Measured (2D, V_c = 2 m/s):',
        'the paper\'s "of the order of 200 kW" is not reached with our wing data at tail settings for which the '
        'moving mill is periodic (details and what is still open:',
        'A wing or free cable node reaching the ground ( , default 0 m)',
        'recordings flag every wing outside -14..18 deg angle of attack or 21 deg sideslip, the range where the '
        "wing data are accurate ( ), and every cable element whose tension exceeds its cable's (or a of it)",
        '- **Environments** (Gymnasium 1.x):',
        'actions per wing or per group of wings (elevator, rudder, aileron, or a commanded angle of attack with '
        'an optional servo lag), normalised to [-1, 1];',
        '2008:',
        "wind disturbances (the paper's direction step, 1-cosine gust, Ornstein-Uhlenbeck speed and direction "
        'perturbations, user schedules)',
        'the moving-cable mill (101 wings)',
        '- **Point-mass fidelity** (Podgaets & Ockels 2007;',
        "runs Meijaard's mill with point-mass kites on a 7070-node string;",
        'The implicit string solve is a partitioned block-Thomas elimination on P threads (P = 2, the two-sided '
        'one, on this 2-core machine;',
        'IEC 61400-1 NTM / ETM (Kaimal spectra, IEC coherence)',
        'runs any controllers on the same seeded episodes of (direction and speed steps, ramps, 1-cosine gusts, '
        'IEC EOG / EDC / ECD / EWS, NTM and Dryden turbulence faded in over 10 s)',
        'Scenarios survived on every seed, of all (PPO (11 min):',
        'the configs as they were before 2026-11-29, from random weights, 11 min each, then ):',
        'env | open loop | LQR | PPO (11 min)',
        'shipped PPO (LQR-started, 10 min)',
        "No PPO has been trained for the chain, and the mill's policy predates its 10 ms step.",
        '(version 2)',
        'repeats every gusts-v1 scenario and adds PumpingKite-v0 (direction and speed steps, 1-cos gusts, IEC EOG'
        " / EDC at the kite's 296.3 m, NTM turbulence;",
        "200 s pumping cycles), LadderMill-v0's grid scenarios (EWS, NTM, Dryden light and moderate over the "
        'whole loop, 0-3700 m)',
        'plots error against warm wall time for RK4 over a step grid up to its stability limit and DP5(4)',
        'our DP5(4)',
        'runs the stress suite (largest stable step by bisection and an energy bound, hour-long runs, wind to '
        'zero and back, 0-40 m/s, bang-bang and random controls, short and long elements, injected NaN / inf / '
        'huge states, 10,000 env episodes:',
        'RK4 and DP5(4)',
        "the integrators step onto the wind schedule's breakpoints (a 1 ms direction ramp inside a 5 ms step:",
        'the linearly implicit Rosenbrock-W methods (order 2)',
        'and (order 3, fixed step;',
        '![Work-precision of the 101-wing chain:',
        'error against warm wall time for RK4, DP5(4)',
        'thrust, H-force, flapping, torque by the energy identity, Glauert inflow solved consistently, the 13 deg'
        ' blade-incidence check;',
        '3 (C_p against craft incidence at the blade limit, the ideal curve to Betz 16/27)',
        'one rigid body with two contra-rotating rotors (per-hub Glauert inflow, so roll rate gives differential '
        'thrust), fins, frame drag and a speed-holding generator (95 % electrical efficiency), on three tethers '
        "built from the core's cable elements;",
        'the flying model (twin 3.7 m rotors)',
        'and the 35 m design at 15,000 and 30,000 ft in .',
        '(6)',
        '(100 kites, 5 km at 1 cm,',
        "the 101-wing at the point-mass fidelity, the kites' pitch and roll offsets as actions (per kite), one 70"
        ' m element per piece, the implicit point-mass step of 25 ms, 20 Hz control, 120 s episodes from the '
        'chain settled for 600 s',
        'the 0.01 rad direction step at 1 s; reward', "Open loop with the paper's 0.01 rad direction step",
        'At 2 m/s it is periodic with',
        "the rigid mill's 66.1 kW (no tail",
        "The one-stage (linearly implicit Euler at the step's mid-time, order 1)",  # the method's published order
    ),
    timings=(
        # dated on docs/benchmarks.md and the pages they summarise
        # work_precision.md's tables' CPU figures (the runs of 2026-11-24): --long wp_chain printed 342.9x real time
        # and 4.22x for the chain on 2026-11-30 (nice 15, load 1-2)
        'runs 465x real time on one thread', '4.2x faster than the fastest RK4 run within 1e-3 (the rotorcraft '
        '9.7-12.6x, the mill over 5 s 6.1x with ROS34PW2 and 9.8x with ROS2, over 10 s 3.4x with the error-controlled '
        'at rtol 3e-3).',
        # work_precision_closed_loop.md's every-period runs (2026-12-06, --long wp_every_period)
        'under the LQR it meets the controller tolerances on the chain 6.10x faster than RK4 in CPU time (its matrix '
        'kept 8 steps), on the mill 5.34x (kept 2)',
        'from its periodic stationary operating point, found in plane once per process (about 20-30 s)',
        'trains through the same harness (20 min:',
        '7.5x real time at 1 m and 207x at 70 m on one thread ( );',  # pointmass_mill.md's run of 2026-12-07
        'the first build takes 30-60 s for the periodic start).',
        '40 minutes, the critic alone first, the kept policy chosen by survival on drawn validation episodes, '
        'never on gusts-v1):',
        'two threads were 9.6x (PPO)',
        'to 60x (SAC)',
        'slower per step on this 2-core machine ( ).',
        'Each worker warms numba once (a cold compile costs 94 s, a cache load 0.43 s;',
        '40 min with a critic warm-up and validation',  # the shipped policy's training (its folder's README)
    ),
    derived=(
        # docs/wind.md's worked bound, checked there
        'and sampled at every wing and cable node, the alpha-rate term included (4.4 MB for the 3.5 km chain over'
        ' 600 s);',
    ),
    printed=(  # long groups (docsite/long_figures.py)
        # tests/test_pointmass_env.py -s -k settled_chain: 178.51 kN (the page's 178.7 kN until 2026-11-30)
        Printed('test_figures_quick', ('(base tension 178.5 kN)',)),
        Printed("breakpoint_tests", ('error 3.5e-8 against 1.0e-5 without).',)),  # the batch copy's (test prints)
        Printed("mill_v0_paper_step", ('the loop diverges laterally and the episode ends at 8.7 s',
                                       'holds it for 300 s through every disturbance of the harness '
                                       '([controllers.md]).')),
        Printed("pointmass_fidelity", ("against the rigid the tensions agree within 1 % once each kite is pitched "
                                       "to the rigid wing's lift ( ).",)),
        Printed("wp_podgaets", ('the implicit one 9x faster at 1e-3);',)),
        # --long wp_chain (first run 2026-11-30, nice 15, load 1-2, 375 s): the step forcing's ROS34PW2 at 0.2 s
        # within 1.90e-04 of the extent, as written; its speeds are CPU timings (below)
        Printed("wp_chain", ("within 1.9e-4 of the chain's extent,",)),
        # tests/test_mill_open_loop_end.py prints the env's failure sentence (laddermill evaluate prints the time and
        # cause only; until 2026-12-01 not_rerun)
        Printed("mill_open_loop_end_test", ('(beta 61 deg near the top)',)),
    ),
    history=(
        History("2026-11-24", "laddermill train of the PPO configs of the day (from random weights, 11 min each), "
                "then laddermill gust-bench --suite gusts-v1 --env ID --controllers open_loop lqr runs/ppo_...",
                "the unshipped PPO runs of 2026-11-24 (f1d21dd, 30708d3) and TetheredWing-v0's row at RK4 50 ms",
                ('6 / 12 (it flies about 90 m to the side, where it pulls more)', '5 / 9 (the same with RK4 at 2 ms)',
                 'with RK4 at 50 ms it read 3 / 12, 8 / 12, 6 / 12:')),
        History("2026-11-29", "laddermill train with configs/agents/ppo_tethered_wing.yaml from random weights",
                "the wing's PPO runs without the LQR start (832ef5a)",
                ('from random weights PPO did not stabilise the wing in that budget, and with a larger learning rate '
                 'and no critic warm-up it drifts away from the LQR (7 / 12;',)),
    ),
)
