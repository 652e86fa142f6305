"""The ledger entry (:mod:`docsite.page_ledger`) of docs/work_precision.md: RK4's and DP5(4)'s stability limits
worked from their tableaux and the stable-step table against ``laddermill stable-step`` for its four scenes
(:mod:`docsite.precision_figures`); the work-precision, controller-measure (:mod:`docsite.ledger_controller_measure`),
whip-spectrum and stress studies' printed figures Printed snippets of their long groups (``python -m
docsite.readme_figures --long NAME``, each run once on 2026-11-30); the methods' settings given; the CPU speed-ups and
durations timings under the page's dates; what no command prints not re-run, each with its reason."""

from __future__ import annotations

from docsite import ledger_controller_measure as controller_measure
from docsite.ledger_kinds import Covered, History, Printed
from docsite.precision_figures import SCENES

P, S = "{precision_data[%s]}", "{stable_steps[%s][%s]}"

#: --long stress_all's summary and the mill's bang-bang case's end (docsite/printed_ratios.py's stress_counts;
#: 2026-11-30: 128 passed, 0 failed, that case terminated at a limit of the quasi-steady model at 5.46 s)
STRESS_CHECKS = ((r"re-run on 2026-11-30: \*\*(\d+) pass, (\d+) fail\*\*; the mill under bang-bang controls ends at "
                  r"t = ([\d.]+) s at a limit of the quasi-steady model",
                  ("{stress_all[passed]}", "{stress_all[failed]}",
                   "~{stress_all[end_t][laddermill/bang-bang controls]}")),
                 (r"On 2026-11-30 the run at the scene's step ended at ([\d.]+) s instead",
                  ("~{stress_all[end_t][laddermill/bang-bang controls]}",)))

#: --long stress_all's case rows (2026-11-30, 1217 s at nice 15, load 4.5-6.4): the holds' drifts and energies,
#: the bisected steps beside the estimates, the env episodes' ends; each snippet within one scene's rows
STRESS_PRINTED = (
    'With the LQR the hour completes: height drift 7.105e-15 m, tension drift 1.904e-11 N, kinetic energy 1.482e-24 '
    'J in the first tenth and 4.154e-24 J in the last',
    'tethered wing height drift -6e-13 m, tension drift -1.6e-9 N, kinetic energy 4.5e-20 J -> 9.7e-24 J;',
    'chain height drift 4.6e-9 m, tension drift 2.7e-4 N, kinetic energy 3.0e-11 J -> 1.713e-17 J',
    "ladder_chain ROS2 0.3471 s (14.2x RK4's limit;", ', ROS34PW2 stable at the cap 1 s (41x);',
    'roberts_flying_model both stable at the cap 0.40 s (64x);',
    'laddermill ROS2 0.42 s (27x), ROS34PW2 stable at the cap 0.99 s (64x)',
    'tethered wing 0.01922 / 0.01901 s,', 'chain 0.02458 / 0.02445 s', 'craft 0.00626 / 0.00619 s,',
    'mill 0.0161 / 0.0154 s',
    # the elements cases: tethered_wing at 8 "dt_scene_s=0.005, dt_estimate_s=0.001353, scene_dt_flagged=True",
    # laddermill at 8 "dt_estimate_s=2.846e-06"
    '(its 5 ms step is flagged above the estimated 1.35 ms limit for 8 elements;',
    "(the mill's RK4 limit at 8 elements is 2.8 us).",
    'the mill, from rest with its cable moving, settles (height +0.045 m, tension -8.3 kN, kinetic',
    'energy 1.1e5 J to 1.2e4 J).',
    '- Env episodes: TetheredWing-v0 10,048 episodes (all to the 5 s limit), Rotorcraft-v0 10,000 (8,154 to the '
    'limit, 1,846',
)

#: the craft's open-loop mode at its trim, as craft_stability's 10 m/s scan row prints it
CRAFT_MODE_CHECK = ((r"The craft is open-loop unstable at its trim \(\+([\d.]+) \+- ([\d.]+)i 1/s",
                     ("~{craft_stability[scan][v10][growth]}", "~{craft_stability[scan][v10][frequency]}")),)

WORK_PRECISION = Covered(
    # craft_stability: the craft's lateral mode at 10 m/s in the stress section (its scan's "growth +0.1267 1/s
    # frequency 0.497 rad/s"; until 2026-12-01 in a not_rerun snippet)
    groups=('precision_data', 'stable_steps', 'craft_stability'),
    checks=STRESS_CHECKS + ((r"RK4: ([\d.]+) on the negative real axis, 2 sqrt 2 = ([\d.]+) on the imaginary axis; "
             r"DP5\(4\): ([\d.]+) on the real axis but only ([\d.]+) on the imaginary axis",
             tuple(P % k for k in ("rk4_real", "rk4_imag", "dp5_real", "dp5_imag"))),
            *((rf"\| {scene} \| (\d+) \| ([-\d.]+) \+- ([\d.]+)i \| ([\d.]+) \|",
               (S % (scene, "states"), "~" + S % (scene, "re"), "~" + S % (scene, "im"), S % (scene, "rk4")))
              for scene in SCENES),
            *((rf"(?<= )([\d.]+) \| ([\d.]+) \| {after}", ("~" + S % (scene, "dp5"), S % (scene, "dt")))
              for scene, after in zip(SCENES, ("\\| ladder_chain", "\\| roberts_flying_model", "\\| laddermill",
                                               "The estimate holds"), strict=True))) + CRAFT_MODE_CHECK,
    given=(
        'DP5(4): a step ends on it);',  # the breakpoints table: a method's name
        'and DP5(4) alike:',  # the pole's paragraph: the same name
        # the craft's hold: eq. (6) (Roberts'), the holder's control period, the craft's state size (rotorcraft.md)
        "(6) LQR** ( : the differential collective dtheta = -K (y, phi, y', p) every 50 ms from the simulator's "
        'state, ; the collective at the trim).', 'finite differences of the 31-state right-hand side; rotorcraft.md):',
        controller_measure.WHIP_MODE_STEP,  # whip_mode_mill's --methods ros34pw2:0.2
        'at dt = 0.025 s gives "dt = 0.025 s',  # the stable-step test's step (its message Printed)
        'an injected 1e12 m/s node speed',  # stress_cases.INJECTIONS' "node velocity 1e12 m/s"
        # the stress cases' settings (stress_cases.stable_step_rows; the holds' control period), README's chain step
        '- Largest stable step of the linearly implicit methods (added this session; the same bisection and test, 4 s '
        "from the disturbed start, between RK4's estimated limit and 64 times it, capped at a quarter of the "
        'horizon; ):', '2 s horizon).', "(the README's 0.025 s is past it)",
        # stress.wind_rows' winds and the cases' 20 s; stress.ELEMENT_RUN_STEPS
        'for at most 20,000 steps',
        '- Winds 0 to 40 m/s, wind to zero and back, the unloading gust, random controls: every scene runs 20 s or',
        "- **The tethered wing and the chain are held by their envs' lateral LQR** ( , designed on the scene itself, "
        "applied every 50 ms to the env observation of the simulator's state, ):",
        *controller_measure.GIVEN,  # the controller-measure section (docsite/ledger_controller_measure.py)
        'Result of the full run (four scenes, 1 h held, 10,000 episodes per env; ), re-run on',
        # whip_spectrum's step forcing and its methods' steps (the commands' inputs)
        'The reading above (the W-methods damp lightly damped cable modes) is wrong. runs the step forcing (10 s)',
        'ROS34PW2 0.0667 s: error, damped part, slow part | 0.0667 s | RK4 (0.0222 / 0.0154 s) |',
        '(re-run on 2026-11-30;',  # --long wp_podgaets's day
        'up to 200 states, the 20 largest in magnitude',
        'The pumping kite and the two 35 m crafts ( , 2026-11-24) keep RK4:',  # the scenes and the run's date
        'the first h with |R(h lambda)| > 1,',
        '(issue 13, point 4)',
        'DP5(4) limit [s]',
        'our DP5(4) and',
        'a 0.1 rad direction step ramped over 1 ms at 0.3037 T, inside an RK4 step; : a 1-cosine +30 % speed gust'
        ' sampled every 0.1 s',
        'DP5(4) at rtol = atol from 1e-3 to 1e-10, the linearly implicit Rosenbrock-W methods and '
        '(docs/numerics.md) at the sample period divided by 1, 2, 3, 4, 6, 8, 12, 16, and the error-controlled '
        'from 1e-2 to 1e-8 (its error estimate is that of the embedded order-2 solution, while the order-3 one',
        'both at 1e-12 and both stepping onto the kinks;',
        'by max(1, |x_ref|). Wall time: median of 3 warm runs,',
        'the least of the same 3 runs',
        'is at most 1e-3 of the extent',
        'The fastest run within 1e-3 of the extent, as a multiple of real time (2026-11-24; speed-up over the '
        'fastest such RK4 run in the same study; for the tolerance; the shared machine was loaded, '
        'so compare within a row):',
        # the pictures' names
        '![ladder_chain] ![tethered_wing] ![roberts_flying_model] ![laddermill] ![laddermill, 10 s] '
        '![podgaets_5km] ![pumping_kite] ![roberts_35m_15kft] ![roberts_35m_30kft]',
        'at 25 m elements: 200 nodes, 100 kites;',
        'DOP853 at 1e-10 and RK45 at 1e-11',
        '### Judged by what a controller sees (issue 32 point 4)',
        "### The apex whip's modes (issue 32 point 4, 2026-11-29)",
        'Rotorcraft and TetheredWing-v0 step ROS34PW2 at 50 ms (one step per control period), the scenes , , and '
        'keep RK4.',
        'The cases: the largest stable RK4 step by bisection (a run passes if it completes, stays within 1 % of a'
        " piece length of a DP5(4) reference at 1e-9 and keeps its kinetic energy below 1.5x the reference's "
        "largest + 1 J) beside the estimate; DP5(4)'s mean step at rtol 1e-6 beside its estimated limit; 1 h held"
        ' by a controller (the tethered wing and the chain by their lateral LQR, the rotorcraft by its eq. (6) '
        'LQR, the mill at its equilibrium controls; drift of mean wing height, largest tension and kinetic energy'
        ' between the first and last tenth); the wind to zero and back; a gust unloading the cable to 30 %; mean '
        'winds of 0, 5, 10, 20, 30, 40 m/s (ramped over 5 s); bang-bang and random controls; 1 and 8 elements per'
        " piece (the scene's step checked against the estimate, a run at half the estimate); NaN, inf and 1e12 "
        'written into wing and node states mid-run, with RK4 and DP5(4); 10,000 reset-and-run episodes with '
        "random actions of TetheredWing-v0 and Rotorcraft-v0 (an end by the env's integration or rotor-inflow "
        'failure code fails the case).',
        # tests/test_breakpoints.py's setting, the 1 ms ramp (its printed errors: breakpoint_tests below)
        'The fixed-step methods split their steps in one compiled stepper ( , ) that the single simulator, the and '
        "the envs' step-and-observe kernels all run, each copy on its own wind's kinks, so an env whose is not a "
        'multiple of its physics step is split like a single run (bit for bit: ; a batch copy across the 1 ms ramp:',
        "RK4's error across the CLI's 1 ms direction ramp ( , tethered wing, 0.05 rad, DOP853 reference run piece by "
        'piece):',
    ),
    derived=(
        # the least and largest of --long stress_all's four printed ratios: bisection / estimate 1.011, 1.005, 1.011,
        # 1.044; DP5(4)'s mean step / its estimate 0.9837, 0.9779, 0.974, 0.9865 (rtol 1e-6: the case's setting)
        '(ratios 1.005 to 1.044)',
        # read off --long stress_all's rows (2026-11-30): roberts_flying_model's winds 0 and 5 m/s, bang-bang and
        # random controls end in ground contact, its 10 m/s and above and every other scene's cases run; 60 injection
        # rows, 40 of them with method rk4 or dp54 (the other 20 ros34pw2)
        'ends in a documented ground contact (the craft below 10 m/s and under bang-bang or random controls).',
        '- Injections: all 40 (NaN, inf, 1e12 in wing and node positions, quaternions, velocities, rates; RK4 and '
        'DP5(4); four scenes)',
        "DP5(4)'s mean step at rtol 1e-6 is 0.974-0.9865 of its estimated limit on every scene",
        *controller_measure.DERIVED,  # the controller-measure section (docsite/ledger_controller_measure.py)
        # readings over whip_spectrum's printed shares (each scene's modes by share, |exp(h l)| and |R(h l)| to 4
        # digits): no one printed figure
        'The damped modes hold under 1 % of the error; the largest shares are in slow (|lambda| < 0.25 1/s, '
        'mostly unstable) or resolved modes, where |R| = |exp(h lambda)| to 4 digits for ROS34PW2 and RK4 alike:',
        # the page's reading of wp_rk4_scenes' printed CPU costs on the pumping kite (a bound, no printed figure)
        'RK4 and the W-methods are within 10 % of one another).',
    ),
    timings=(
        *controller_measure.TIMINGS,  # the controller-measure section (docsite/ledger_controller_measure.py)
        # the work-precision table and its reading: real-time factors and CPU speed-ups of the runs of 2026-11-24
        # (until 2026-11-30 listed as --long work_precision_all's Printed snippets; its first run, nice 15, load 3,
        # 722 s, printed e.g. the chain's ros2 at 0.1 s 272.9x real time, 3.57x RK4, ros34pw2 at 0.2 s 332.9x, 4.35x)
            'forcing | RK4 | DP5(4) | ros2 | ros34pw2 | ros34pw2a | |---|---|---|---|---|---|---| | ladder_chain (10 '
            's) | step | 110x (0.0222 s) | 47x (0.42) | 394x (0.1 s; 3.57) | **465x (0.2 s; 4.22)** | 445x (1e-2; '
            '4.04) | | | smooth | 112x (0.0222 s) | 49x (0.43) | fails | fails | 27x (1e-4; 0.24) | | | gust | 108x '
            '(0.0222 s) | 45x (0.42) | 573x (0.2 s; 5.32) | 354x (0.2 s; 3.29) | 338x (1e-3; 3.14) | | tethered_wing '
            '(5 s) | step | 3097x (0.0182 s) | 1463x (0.47) | 9442x (0.2 s; 3.05) | 7782x (0.2 s; 2.51) | 6822x '
            '(1e-3; 2.20) | | roberts_flying_model (5 s) | step | 559x (0.0061 s) | 300x (0.54) | 7024x (0.2 s; '
            '12.6) | 5394x (0.2 s; 9.65) | 4976x (1e-2; 8.90) | | laddermill (5 s) | step | 72x (0.0154 s) | 29x '
            '(0.40) | 709x (0.2 s; 9.80) | 441x (0.2 s; 6.09) | 406x (3e-3; 5.61) | | laddermill (10 s) | step | 74x '
            '(0.0154 s) | 30x (0.41) | none (0.0667-0.2 s run, 1.5-3.8e-3; 4 steps diverge) | 164x (0.0667 s; 2.20) '
            '| **253x (3e-3; 3.40)** | | pumping_kite (5 s) | step | **8170x (0.0667 s)** | 7126x (1e-4; 0.87) | '
            '8842x (0.2 s; 1.08) | 8337x (0.2 s; 1.02) | 7466x (1e-3; 0.91) | | roberts_35m_15kft (5 s) | step | '
            '**9079x (0.2 s)** | 6644x (1e-6; 0.73) | 7442x (0.2 s; 0.82) | 6337x (0.2 s; 0.70) | 5778x (1e-4; 0.64) '
            '| | roberts_35m_30kft (5 s) | step | **9310x (0.2 s)** | 6589x (1e-6; 0.71) | 7585x (0.2 s; 0.81) | '
            '6386x (0.2 s; 0.69) | 5729x (1e-3; 0.62)',
            '- **The stiff cable no longer sets the step.** On the chain after a direction step, ROS34PW2 at 0.2 s '
            "(eight times RK4's limit) stays within 0.69 m (1.9e-4 of the extent) and runs 465x real time on one "
            "thread, 4.2x the fastest RK4 run within 1e-3 (issue 13's targets: 3x, aim 5x; 150x real time). On the "
            'rotorcraft the W-methods are 9-13x faster than RK4, whose 6 ms limit is set by a rotor-tether mode; on '
            'the mill over 5 s ROS2 9.8x, ROS34PW2 6.1x, over 10 s the error-controlled 3.4x (below). All W-method '
            'figures include the factorisation of the iteration matrix once per step, shared by the stages ( ; '
            'before, each stage factored it again: 8 % of a step on the mill). - **RK4 is stability-bound and very '
            'accurate where it runs.** At its largest grid step (chain 0.0222 s) the final position error after the '
            'step is 6e-5 m; no tolerance buys DP5(4) a larger step (its cost is flat from 1e-3 to 1e-7). - **The '
            "W-methods' error at large steps is the cable vibration they damp.** They are L-stable: axial and "
            'transverse cable modes that a step does not resolve are damped, not carried (docs/numerics.md, "Energy '
            'behaviour"). On the gust the chain\'s error sits at 0.12 m for every step from 0.0125 to 0.2 s (3.3e-5 '
            "of the extent), and the tethered wing's at about 1 mm, until the step resolves the excited modes: from "
            '5 ms down the observed orders are 2.0 (ROS2) and 3.0 (ROS34PW2) ( ). - **Where the fixed-step W-methods '
            "fail: the chain's apex whip.** From the disturbed start ( ) the chain's apex wings are physically "
            'unstable: their speed grows from 0.2 m/s to 36 m/s over 10 s and slack pieces there snap taut. ROS2 and '
            'ROS34PW2 with a Jacobian frozen over a step diverge there (t = 7.7-9.8 s) at every step from 12.5 ms to '
            '0.2 s (ROS2 at 25 ms and ROS34PW2 at 12.5-25 ms get through, with 7-44 m of error); RK4 follows it from '
            '22 ms (2.1 m) but its error stays at 0.5-0.8 m down to 3.9 ms (0.09 m at 2.8 ms). The error-controlled '
            'follows it (2.1e-4 of the extent at rtol 1e-4; 1.2-2.6e-3 at 1e-3 to 1e-2) by shrinking its steps '
            "there, at a quarter of RK4's speed. This is why keeps RK4 by default. - **The mill's station.** The "
            "mill's first element is short (l_p / 10 after a transfer) and its rest length moves with the station's "
            'pay-out s(t); its rate with the cable speed V_c(t). Until this session the W-methods left that '
            "dependence (on the station's states and on time) out of their Jacobian: harmless for their order in "
            'theory, but it left a stiff element driven explicitly, and wing 0 next to the station drifted (its '
            'angle of attack 13.5 -> -1.7 deg in 2.4 s at 0.2 s, local errors nearly independent of the step) and '
            "broke down. With the column ( : dsigma/dl0 and dsigma/d(rate) along the stages' pay-out and time "
            'increments, checked against finite differences of the assembled forces to 2.4e-5, ) wing 0 holds to '
            '2e-4 deg and over 5 s ROS34PW2 at 0.2 s runs 441x real time (6.1x RK4, was 1.5x), ROS2 709x (9.8x). '
            'Positions plateau at about 0.1 m (the damped cable vibration) and the scaled full-state error stays '
            "0.05 (ROS34PW2) to 0.35 (ROS2) against RK4's 1.7e-4 at 15 ms, so the mill keeps RK4 by default. - "
            '**Over 10 s the mill meets the 3x target with error control: at rtol 3e-3 is 253x real time, 3.4x RK4** '
            '(74x at 0.0154 s), within 0.44 m (1.4e-4 of the extent); the fixed-step ROS34PW2 at best 164x (0.0667 '
            's, 2.2x). The 0.1 rad direction step at 3.04 s sets off a whip of the apex wings that the 5 s run ends '
            'before (fastest wing, near slot 50 of 101: 1.3 m/s at 5 s, 33 m/s at 10 s in the reference, whose two '
            'solutions agree to 2.8e-9; without the step 1.9 m/s). The fixed-step methods fail only in that whip, as '
            'on the disturbed chain: ROS2 at 0.0167-0.05 s (t = 7.9-8.9 s) and ROS34PW2 at 0.1 and 0.2 s (t = '
            "7.7-7.8 s) diverge there, and ROS2's runs at 0.0667-0.2 s finish 5.2-13.7 m off (1.5-3.8e-3 of the "
            'extent); none fail next to the station (before the station column: slots 0-4 from t = 2.4 s). The '
            "whip's local errors converge at the method's order (ratios 11 and 21 per halving of a single step at t "
            "= 7 s from 10 to 5 ms): the frozen Jacobian's stability limits a fixed step there, not a missing term. "
            'The error control takes what each phase allows: one step per 0.2 s output until 7.4 s (it proposes up '
            'to 1 s), then 0.04-0.14 s steps through the whip (81 accepted, 13 rejected steps in all). Until this '
            'session it paid 1.2x RK4 for the same: every restarted from (10 ms) and a step cut short to land on an '
            'output time was handed on as the next proposal, so it took three steps per output where one sufficed; '
            "the kernels now hand on the controller's proposal and keeps it between calls ( ). 's error is not "
            'monotone in rtol here (0.44 m at 3e-3, 2.5 m at 1e-3, 5.4 m at 1e-2): the whip amplifies where each '
            "run's steps happen to fall. Command: (2 min). - **The point-mass string: the implicit method is 9x the "
            'explicit one at 1e-3, and the kites set its step.** Both converge at first order ( ). The explicit '
            "method's fastest run, at its stability limit, is already within 1.3e-6 of the extent; the implicit one "
            'runs 17 times that step (0.05 s) within 3e-5, beyond it it fails with "speed limit exceeded" (0.1 s at '
            "t = 8.6-8.9 s, 0.2 s at 2.2 s): the kites' aerodynamics are explicit in it, and their rate (rho S C_L V "
            '/ m, about 20 1/s, ) bounds the step, which is why the scene steps 10 ms. Its scaled state error stays '
            "near 1e-2 at every step (the cable's axial vibration, damped rather than carried, as with the "
            'W-methods), against 1e-4 to 6e-4 for the explicit runs. - **Breakpoints matter on non-smooth forcing.** '
            'Chain, direction step, same steps: 6.0e-5 m against 0.11 m at 0.0222 s.',
        # real-time factors and speed-ups of the run of 2026-12-07 (the table's caption; --long wp_podgaets, load about
        # 2 beside other work): timings, not figures; the run of 2026-11-24's implicit speed-ups 8.94 / 9.36 / 9.23
        'The run of 2026-12-07 (that of 2026-11-24 began at l0 / c, 0.00294 s, and gave the implicit 8.9-9.4x): '
        '| scene (T) | forcing | explicit | implicit | |---|---|---|---| | podgaets_5km, '
        '200 nodes (10 s) | smooth | 136x (0.00211 s) | **1710x (0.05 s; 12.60)** | | | step | 134x (0.00211 s) | '
        '**1695x (0.05 s; 12.62)** | | | gust | 134x (0.00211 s) | **1667x (0.05 s; 12.43)**',
        # the page's blanket date (the first work-precision runs, ec22606) and machine
        'Figures below were measured on a shared 2-core machine (from 2026-11-24; four other engineers running at'
        ' the same time, load not recorded): compare ratios within one run, not absolute times.',
        'It costs one Jacobian (5 ms on the tethered wing, 34 ms on the chain with ARPACK, 41 ms on the mill)',
        '(about 15 minutes).',
        # the commands' durations as written
        '--samples 25 --out results/work_precision --samples 50 --out /tmp/wp_mill10 # 2 min; figure: '
        'work_precision_laddermill_10s.png --out results/work_precision # 1 min; the point-mass string, below',
        '--samples 50 # 6 min --samples 50 # 9 min --samples 25 # 4 min --samples 25 # 3 min',
        '--methods ros34pw2:0.0666666666666667 ros2t:0.0666666666666667 rk4:0.0222222222222222 # 4 min --methods '
        'ros34pw2:0.0666666666666667 ros2t:0.0666666666666667 rk4:0.0153846153846154 # 7 min',
    ),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        Printed('stress_all', STRESS_PRINTED),
        # the tethered wing's extent: work-precision prints each reference's (2026-12-01; until then not_rerun; the
        # chain's 3613 m: step_accuracy_10, above)
        Printed('wp_tethered_wing_extent', ('101 m for the tethered wing',)),
        # breakpoints "all" against "inside" on the golden runs: "componentwise 1.2e-06" (tethered wing), "7.4e-05"
        # (chain), each nearer DP5(4) at 1e-10 (2026-12-01; until then not_rerun, the test had no print)
        Printed('breakpoints_golden_test', (
            'Changes such runs, toward a tight DP5(4) run (the golden direction-step cases by 1.2e-6 (tethered wing) '
            'and 7.4e-5 (chain) componentwise relative; ).',)),
        # the mill's RK4 limit just after a transfer: "at t = 50.00 s: rk4: largest stable step 0.01224 s"
        Printed('stable_step_mill_transfer', ("beyond RK4's 12.2 ms limit right after a transfer)",)),
        # tests/test_stress.py -s -k bisection_agrees: stable_step_rows('tethered_wing', horizon=2.0, iters=5)
        # prints "stable at the bracket's top, 0.5 s", ratio_to_rk4_limit 26.29 (the horizon given)
        Printed('stress_quick_tests', ('tethered_wing both at the cap 0.5 s (26x,',)),
        # tests/test_alpha_rate_limit.py -s -k names_the_alpha: "stopped at t = 0.3836 s: wing 46 at ... sideslip
        # -74.502 deg", "3.73e+09 rad/s^2, without the alpha-rate columns -127", "1e-4 s later: -3.06e+11"
        Printed('alpha_rate_pole_test', (
            # "DP5(4)" is the method's name, not a figure (the page's `given`)
            'The error-controlled methods stop on it at 0.3836 s,', 'there wing 46 has tumbled to -74.5 deg sideslip',
            'passes through a pole: 3.73e9 rad/s^2 at the last accepted state, -3.06e11 with the other sign 1e-4 s '
            'later, -127 with the two alpha-rate columns removed;',
        )),
        # tests/test_stress.py -s -k injections_are_reported prints the report it holds, "integration failed at t =
        # 0.05 s (non-finite state); the state: node 0 x [m] is nan (state entry 13): a non-finite state" (the
        # simulator's own message inside the stress row's wording); the injected 1e12 m/s is an input (given)
        Printed('stress_quick_tests', (
            'Fixed on the way: a non-finite state entry is now named as such (time, body, quantity: "t = 0.05 s: '
            'node 0 x [m] is nan (state entry 13)")',
        )),
        # tests/test_stable_step.py -k past_its_stable's message (-5.092 until 2026-11-30); its step is given
        Printed('test_figures_quick', (
            'is above the estimated stability limit of RK4 at this state, 0.02445 s (eigenvalue -5.093+118.6j 1/s)',
        )),
        Printed('stress_all', (
            '| 0.01922 |',
            '| 0.02458 |',
            '| 0.00626 |',
            '| 0.0161 |',
        )),
        Printed('work_precision_all', (
            'their agreement (1e-11 to 2e-7 in the scaled state)',
        )),
        Printed('wp_podgaets', (
            'stable below 0.002111 s, its damped highest mode',
            'agree to 3.3e-8',
        )),
        Printed('wp_rk4_scenes', (
            # the crafts' stable steps are printed a table apart (1.813 s, 2.319 s), more than a window
            "it is the fastest within 1e-3 on all three (the crafts' slow modes, RK4's stable step 1.8", 'and 2.3 s,',
            "put the grid's largest step, 0.2 s, within 2e-10 of the extent;", 'on the pumping kite, stable to 0.092 s '
            'at the start,',
        )),
        controller_measure.PRINTED,  # docsite/ledger_controller_measure.py
        *controller_measure.PER_PROFILE,  # the same group's figures per numeric profile (docsite/host_cpu.py)
        controller_measure.STABILITY,  # |R(inf)|, |R(4i)|: tests/test_stability_functions.py
        controller_measure.WHIP_MODE,  # the mill's mode at 7.6 s: whip_spectrum --top 2000
        # split to the printed lines they come from (--long whip_spectrum, 2026-11-30, 63 s: every cell as written)
        Printed('whip_spectrum', (
            "by RK4 at 2 ms to each time , forms the full Jacobian (central differences, LAPACK ), writes each run's "
            "error in its eigenvectors and prints the part of the wings' lateral error in the modes the method damps "
            "(|R(h lambda)| < 0.9 |exp(h lambda)|) and with |lambda| < 1 1/s (a badly conditioned basis: parts can "
            'exceed the whole):',
            'ladder_chain, 6 s (100, 0.550 1/s) | 0.0046 m, 3.5e-6, 0.0014 (168 of 1313 damped)',
            '| 0.0019 m, 0, 0.0046 |', '| 2.6e-7 m, 6.7e-9, 2.5e-7 |',
            'ladder_chain, 8 s (99, 0.157 1/s) | 0.032 m, 1.1e-4, 0.019', '| 0.081 m, 0, 0.066 |',
            '| 1.3e-6 m, 6.9e-8, 9.9e-7 |', 'laddermill, 7.6 s (92, 6.405 1/s) | 0.031 m, 6.2e-5, 0.041',
            '| 0.0115 m, 0, 0.038 |', '| 4.7e-4 m, 9.8e-9, 4.6e-4', "(the mill's 6.4 1/s mode",
        )),
        # physics_step_accuracy: "LadderChain-v0: 10 s, extent 3612.8 m" (a body's largest distance from the origin)
        Printed('step_accuracy_10', ('3613 m for the chain,',)),
        Printed('breakpoint_tests', (  # tests/test_breakpoints.py, test_batch_breakpoints.py print what they assert
            '3.5e-8 from DOP853 against 1.0e-5 unsplit, and fourth order on a gust on the step grid with ).',
            '3.5e-8 at dt 5 ms with against 1.0e-5 with ,',
            'against none. On a gust sampled on the step grid, gives the ratio 16.3 per halving and 5.4.',
            'and fourth order (ratios 20.8, 23.7 per halving;',
        )),
    ),
    history=(History('2026-11-24', 'laddermill stress tethered_wing ladder_chain roberts_flying_model laddermill '
                     '(c36a6ae, ec22606, e6bbf77, a314800)', "the stress runs' figures before --long stress_all's "
                     'run of 2026-11-30 (issue 33 point 6)',
                     ('(2026-11-24: -7e-15 m, -3e-12 N, 1.5e-24 and 2.2e-24 J).', '(2026-11-24: 1.6e-17 J;',
                      '2026-11-24: 0.33 s, 13.6x)', '(2026-11-24: 0.98-0.99).')),
             # runs that are not kept: earlier code's stress runs and side runs (issue 33 point 6, dated on the page)
             # the rotorcraft's hour at its open-loop equilibrium controls and the two side runs beside it (until
             # 2026-12-01 not_rerun; the stress suite holds the craft by its LQR since, so no command repeats them)
             History('2026-11-24', 'laddermill stress roberts_flying_model with the hour held at the equilibrium '
                     'controls, and the same hour with RK4 at 5 ms and ROS34PW2 at 10 ms (5c6f0b4)',
                     "the craft's open-loop hour (earlier code's holder)",
                     ('held at its open-loop equilibrium controls, as the run of 2026-11-24 did (5c6f0b4), roundoff '
                      '(kinetic energy 1e-25 to 5e-24 J for 1900-3400 s) grows into a ground contact (node 2) at 3511 '
                      's with its own ROS34PW2 at 50 ms, at 2255 s with RK4 at 5 ms and at 1960 s with ROS34PW2 at 10 '
                      'ms: the physics, not the integrator.',)),
             # the mill's bang-bang case before and after the 10 ms step (d612dc8, 9f0397d); today's run at 10 ms
             # ends at a pole inside the step (the page says so: stress_all's check); until 2026-12-01 not_rerun
             History('2026-11-24', 'laddermill stress laddermill at the 12.5 ms step, then stress_cases.run_for with '
                     "stress.control_rows' bang-bang schedule at 10 and 2.5 ms (d612dc8, 9f0397d)",
                     "the mill's bang-bang runs of 2026-11-24 (earlier code)",
                     ('The mill under bang-bang controls on all 101 wings, which failed at t = 3.9 s in that run, was '
                      "a step past the loaded stability limit, not a physical manoeuvre: at the scene's present 10 ms "
                      'step (12.5 ms then,', 'it ran the 20 s on 2026-11-24, and so it did at 2.5 ms',
                      'RK4 at 10 ms stepped over it on 2026-11-24 without evaluating it.')),
             History('2026-11-24', 'laddermill stress on the four scenes before the fixes (5c6f0b4, ec22606)',
                     "earlier code's stress run: injections at the craft's 50 ms step, elements cases refused at load",
                     ("- Fixed by this run (2026-11-24, 5c6f0b4): the RK4 injections on the rotorcraft ran at the "
                      "craft's own 50 ms step (eight times RK4's limit) and raised before any injection; they now run "
                      "at half RK4's estimate. The elements cases on and at 8 elements per piece failed at load, where "
                      "the loader refuses the scene's step (beyond twice the stiffest element's closed-form bound); a "
                      "refusal now counts as detected, the case finds the equilibrium below the bound and runs at "
                      "half the estimate,",
                      'The mill under bang-bang controls ran its 20 s then (below). Before: 96 pass, 4 fail.')),
             History('2026-11-24', 'laddermill stress laddermill, stable-step rows before the station column (9382869)',
                     "the mill's W-methods before the moving end's Jacobian column (earlier code)",
                     ('since the station column (before: 0.19 s, 12.6x and 0.10 s, 6.6x);',)),
             History('2026-11-24', 'laddermill stress, 1 h held at the equilibrium controls (a314800)',
                     'the holds before the LQR holds (the stress suite now holds by LQR)',
                     ('- 1 h held (before the LQR holds, at their equilibrium controls; 2026-11-24, a314800): tethered '
                      'wing and chain stay at their equilibrium to roundoff (drift of the mean height below 1e-11 m, '
                      'of the tension below 1e-7 N;',)),
             History('2026-11-24', 'laddermill stress at 8 elements per piece before the catenary start (50ea5bc)',
                     "earlier code's initial states from straight chords",
                     ('- Fixed since: with 8 elements per piece no scene found its initial state',)),
             History('2026-11-24', 'a gust run of the tethered wing on RK4 (ec22606; not kept: laddermill stress '
                     'tethered_wing has no +30 % gust case, --long stress_tethered_wing of 2026-11-30 no gust at '
                     'RK4 0.0179 s)', 'TetheredWing scene, +30 % gust, RK4 at 0.0179 s',
                     ('a +30 % gust makes RK4 at 0.0179 s (0.94 of the estimate at rest) diverge at t = 1.6 s',)),
             History('2026-11-29', 'a side measurement of the DP5(4) reference on the mill over 10 s (0d6b39c)',
                     "the fastest wing's speed in the apex whip; no command prints a wing's speed",
                     ('On the mill over 10 s the whip is stronger (33 m/s; 2026-11-29, 0d6b39c):',)),
             History('2026-11-29', "whip_spectrum.factor('ros34pw2', 0.2 s x 6.405 1/s) (6e68f22)",
                     "the mill's fastest unstable mode at 7.6 s, its real part alone (z = 1.28)",
                     ("0.70 as written on 2026-11-29 is its real part's alone).",)),
             History('2026-11-24', 'the failed ros34pw2 run of the 101-wing mill under bang-bang controls (9f0397d)',
                     "the pole's accelerations from another evaluation than today's alpha_rate_pole_test's",
                     ('2026-11-24, another evaluation: -74 deg, -4.5e6, 3.9e9, -129).',)),
             History('2026-11-24', 'laddermill stress tethered_wing ladder_chain roberts_flying_model laddermill',
                     'the full stress run of 2026-11-24 (ec22606 and after)',
                     ('As written on 2026-11-24 (5.5 min; 6.5 min with the LQR holds): 128 pass, 0 fail (the run '
                      'before: 127 pass, 1 fails).',)),
             History('2026-11-30', 'laddermill stress tethered_wing ladder_chain roberts_flying_model laddermill',
                     "the day's first full run (--long stress_all, before c576da4 named a stage next to the "
                     "alpha-rate pole)", ("the day's first run: 127 pass, 1 fail",)),
             History('2026-11-24', 'NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.numerics.work_precision '
                     'podgaets_5km --time 10 --samples 50', "the point-mass string's first work-precision run "
                     "(c447a36); --long wp_podgaets printed 3.3e-08 on 2026-11-30 (not bisected)",
                     ('3.4e-8 as written on 2026-11-24',)),
             # the kink test's ratios before today's printed ones (issue 33 point 6, 2026-11-30)
             History('2026-11-24', 'pytest -s tests/test_breakpoints.py -k across_a_ramp (ec22606)',
                     'the 1 ms ramp case as first measured', ('20.7, 22.3 on 2026-11-24)',)),),
)
