"""The ledger entry (:mod:`docsite.page_ledger`) of docs/work_precision_closed_loop.md (merged 2026-11-30): the
closed-loop work-precision runs' steps and errors Printed snippets of their long groups (``--long wp_closed_loop``,
``wp_chain_kept_matrix``, ``wp_mill_kept_matrix``; first run 2026-11-30); the loop's settings given; the CPU costs
and speed-ups timings as the page dates them; the bounds worked from them derived; one-off runs beside the study and
a test's assertions not re-run."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed

WORK_PRECISION_CLOSED_LOOP = Covered(
    given=(
        # the one-off runs' steps (0.05 s / 2 on the chain, / 3 on the mill; their results not_rerun, below)
        '- On the chain RK4 at 0.025 s, 2 steps per period and just beyond', '- On the mill RK4 at 0.0167 s',
        '# Work precision with the wings held by the LQR (issue 32 point 4)',
        "The open-loop rows stay and are still what the issue's 5x target is checked against.",
        'Over 10 s the cable moves less than 4 m, so no wing is transferred.',
        "The controller runs at the envs' control period of 0.05 s with a zero-order hold.",
        "The W-methods run at 0.05 / k s, so their largest step is 0.05 s, not the open loop's 0.2 s.",
        '- The two references, our DP5(4)',
        "and scipy's DOP853 (both at 1e-12), run through the same loop.",
        'The tables give CPU speed-ups over the fastest RK4 run that meets the tolerances in the same run (1 % in'
        ' tension and power; 0.1 m and 0.01 rad).',
        'scene, 10 s, step | open loop: RK4 | best W (open)',
        'The error-controlled meets the tolerances closed loop at 1e-2:',
        'That is longer than a 10 s study run, but it is done once per study.',
        'A W step cannot be longer than the 0.05 s hold, while RK4 needs 3 (chain) or 4 (mill) steps per period.',
        'So the speed-up is 3 or 4 RK4 steps against the cost of one W step.',
        "The closed-loop grid puts the mill's RK4 at 0.0125 s, against 0.01538 s open loop.",
        # the every-period section (2026-12-06): the study's settings, the tables' heads, the method's order and
        # the refresh's period (the option's k)
        'Two changes on 2026-12-06. The errors are read at every control period ( over 10 s), not every 0.2 s as '
        'above.', 'order 1 for any J, L-stable', 'Closed loop only, one thread, the first three RK4 steps of the grid',
        '--controller lqr --jacobian-every 1 2 4 8 --time 10 --samples 200 --n-dt 3 --controller lqr '
        '--jacobian-every 1 2 4 8 --time 10 --samples 200 --n-dt 3',
        "(the chain's at 0.01667 s, the mill's at 0.0125 s), each method at its fastest step that meets them:",
        '| ladder_chain, 10 s, step+lqr | every step | kept 2 | kept 4 | kept 8 |',
        '| laddermill, 10 s, step+lqr | every step | kept 2 | kept 4 | kept 8 |',
        '**Read at every control period, a matrix kept over steps costs more than the 0.2 s samples showed.**',
        '| at 0.05 s, laddermill | tension | power | lateral offset | attitude |', 'On the mill at 0.05 s,',
        '| 2026-12-06, with its stage at t, at 0.05 s, laddermill | tension | power | lateral offset | attitude |',
        'A rate of time alone is now integrated by', "steps the 11-wing mill 2 s", 'SHA-256 of',
        'Samples every 4 steps fall on one phase of that swing.', 'Read every 0.2 s over 5 s (the section above),',
        '5.7x bound. (Read every 0.2 s. Read at every control period over 10 s, ros2t kept 8 at 0.05 s misses the 1 % '
        'in power: below.)',
        # the kept-matrix section (2026-11-30): the study's settings and the table's heads
        'Shorter runs than above (5 s, 25 samples, the first three RK4 steps of the grid), closed loop only,',
        '--controller lqr --jacobian-every 1 2 4 8 --time 5 --samples 25 --n-dt 3',
        '| ladder_chain, 5 s, step+lqr | every step | kept 2 | kept 4 | kept 8 |',
        "(the chain's at 0.01667 s, the mill's at 0.0125 s), every W run at 0.05 s unless marked:",
        '| laddermill, 5 s, step+lqr | every step | kept 2 | kept 4 | kept 8 |',
        'The wall-time ratios of these runs (the machine was loaded) are not the measure; the CPU times are, one '
        'numba thread.',
    ),
    timings=(
        # the table's CPU speed-ups and step costs (the run of f45b8d3, 2026-11-30 00:27). --long wp_closed_loop on
        # 2026-11-30 (load 3-3.7) printed open loop ROS34PW2 1.54x (ros2t 1.24x), mill ros2t 0.84x (ROS34PW2 0.52x);
        # closed loop ros2 / ros2t / ROS34PW2 2.40 / 2.33 / 1.53x (chain), 2.98 / 2.96 / 1.89x (mill); ros34pw2a 1.48x
        # at 1e-4, 1.83x at 1e-3 (the same runs as 1e-2): the page's re-run paragraph
        '**1.42x** (ros2t 1.13x) |', '**2.14x** | 0.05 s: **2.23x** | 0.05 s: 1.36x |', '**0.84x** (ROS34PW2 0.52x) |',
        '**2.89x** | 0.05 s: **2.77x** | 0.05 s: 1.78x |', '1.37x on the chain and 1.74x on the mill.',
        '**5x is not met closed loop either: 2.2x on the chain and 2.9x on the mill** (by the methods of order 2 and '
        '3; the one-stage , added on 2026-12-06, reaches 6.1x on the chain and 5.3x on the mill: [below]). '
        'Closed loop, accuracy is no '
        'longer what binds.',
        'A ros2 or ros2t step costs 1.3-1.4 RK4 steps, and a ROS34PW2 step about 2.2.',
        'Re-run on 2026-11-30 ( , 965 s at nice 15, load 3-3.7): every step and error above as written; the CPU '
        'speed-ups in the table\'s order 1.54x (ros2t 1.24x), 2.40x, 2.33x, 1.53x and 0.84x (ROS34PW2 0.52x), 2.98x, '
        '2.96x, 1.89x; 1.48x and 1.83x, listed at 1e-4 and 1e-3, which give the same runs as 1e-2 there.',
        # the chain's kept-matrix CPU speed-ups (the run committed in f45b8d3; --long wp_chain_kept_matrix on
        # 2026-11-30 at load 1-2 printed ros2 2.31 / 2.96 / 3.46 / 3.71x, ros2t 2.30 / 2.97 / 3.47 / 3.79x, ROS34PW2
        # 1.49 / 1.72 / 1.89 / 1.98x)
        '| ros2 | 2.24x | 2.79x | 3.53x | **3.93x** | | ros2t | 2.32x | 2.94x | 3.58x | 3.82x |',
        '| ROS34PW2 | 1.46x | 1.79x | 1.93x | 1.98x |', '**5x is not met on the chain: 3.9x at best**,',
        # the mill's kept-matrix CPU speed-ups (the run committed in f45b8d3; --long wp_mill_kept_matrix on
        # 2026-11-30 at load 1-7 printed ros2 3.12 / 3.97 / 4.62 / 2.25x, ros2t 3.15 / 3.94 / 4.62 / 5.03x, ROS34PW2
        # 2.00 / 2.33 / 2.52 / 2.63x: ros2t kept 8 above 5x in that run)
        '| ros2 | 3.02x | 3.77x | 4.28x | 2.62x (0.025 s) | | ros2t | 3.01x | 3.77x | 4.32x | **4.70x** |',
        '| ROS34PW2 | 1.91x | 2.13x | 2.39x | 2.45x |',
        '**5x is not met on the mill either: 4.7x at best** (ros2t kept 8), below the 5.7x bound.',
        'and misses the 1 %',  # the controller tolerance (power 0.01 of its largest value)
        # the page's own durations and CPU costs (committed in f45b8d3, 2026-11-30 00:27; one thread, load 4-7;
        # no date on the page)
        '0.03-0.08 s CPU per 10 s run, or 200 evaluations. and leave it out;',
        'one thread, load 4-7 on the two cores)',
        '--controller none lqr --time 10 --samples 50 # 12 min --controller none lqr --time 10 --samples 50 # 17 '
        'min',
        "The LQR's design took 30.0 s wall on the chain and 17.4 s on the mill ( in the JSON; the machine was "
        'loaded).',
        "**What a Jacobian reused over steps could give.** The W step's Jacobian and factorisation were measured "
        'at a 0.05 s step with . It printed "ladder_chain:',
        'CPU per step ROS34PW2 0.576 ms, RK4 0.274 ms (2.10 RK4 steps); one right-hand side 0.075 ms;',
        'body Jacobian 0.134 ms (23%), cable Jacobian 0.028 ms (5%), factorisation 0.026 ms (5%);',
        'W step without them 1.41 RK4 steps".',
        'For the mill it printed "ROS34PW2 0.585 ms, RK4 0.273 ms (2.14 RK4 steps); ...',
        'body Jacobian 0.137 ms (23%), cable Jacobian 0.032 ms (6%), factorisation 0.027 ms (5%);',
        'W step without them 1.42 RK4 steps".',
        # the every-period runs (2026-12-06 03:12-03:23, one thread, tests on the other core; the commit that added
        # ros1): the CPU speed-ups of the two tables and of the runs that missed the power by a little
        # (re-run 2026-12-06 05:18-05:29 with ros1's stage at the step's middle, --long wp_every_period, 644 s)
        '| ros1 | 0.05 s: 2.81x | 0.05 s: 3.94x | 0.05 s: **5.28x** | 0.05 s: **6.10x** |',
        '| ros2 | 0.05 s: 2.08x | 0.05 s: 2.64x | 0.05 s: 3.17x | 0.05 s: 3.39x |',
        '| ros2t | 0.05 s: 2.09x | 0.05 s: 2.64x | 0.05 s: 3.00x | 0.05 s: 3.48x |',
        '| ROS34PW2 | 0.05 s: 1.37x | 0.05 s: 1.60x | 0.05 s: 1.75x | 0.05 s: 1.85x |',
        '| ros1 | 0.05 s: 3.48x | 0.05 s: **5.34x** | 0.025 s: 3.90x | 0.025 s: 4.67x |',
        '| ros2 | 0.05 s: 2.73x | 0.05 s: 3.57x | 0.025 s: 2.27x | 0.025 s: 2.54x |',
        '| ros2t | 0.05 s: 2.76x | 0.05 s: 3.51x | 0.025 s: 2.27x | 0.025 s: 2.50x |',
        '| ROS34PW2 | 0.05 s: 1.74x | 0.05 s: 2.14x | 0.05 s: 2.31x | 0.05 s: 2.47x |',
        '**On the chain 5x is met closed loop: with its matrix kept 8 steps, 6.10x**,', '(kept 4: 5.28x,',
        '**On the mill 5x is met closed loop too: with its matrix kept 2 steps, 5.34x** at 0.05 s.',
        'the same ros2t kept 8 run was within 1 %, at 4.70x.',
        '2026-12-06 05:18-05:29, 644 s, nothing else running; CPU times are the measure):',
        # the same study on the mill with --jacobian-every 1 2 --repeats 7 (2026-12-06 06:13-06:24, one thread)
        "The mill's rows again with each run's CPU time the least of 7 (", ', otherwise the command above; 2026-12-06 '
        '06:13-06:24, nothing else running):', 'kept 2 at 0.05 s 5.18x (wall 5.03x), every step 3.73x.',
        # the kept-matrix runs (2026-11-30 04:05-04:13, one thread)
        'one thread, load 5.5-9:',
        '# 8 min',
        '# 4 min',
    ),
    derived=(
        # worked from the figures above
        "At the open-loop step the mill's ros2 ratio would be 2.89 x 0.0125 / 0.01538 = 2.35x.",
        "- The chain's ros2t step takes 0.39 ms (0.0785 s / 200 steps);",
        'without the 0.19 ms of parts, 0.175 / 0.041 = at most 4.3x.',
        "- The mill's ros2 step takes 0.40 ms;",
        'without the 0.20 ms of parts, 0.231 / 0.041 = at most 5.7x.',
        'Only then is 5x within reach, and only on the mill.',
        'below the 4.3x bound with a free Jacobian above.',
        # worked from the every-period figures: kept 2's 3.3e-3 against 1e-2; 5.34 / 5 = 1.068
        'kept 2 is a third of the power tolerance, but 5.34x is 7 % above 5x,',
        # the test's oracle: h a t / 2 = 0.05 x (2 / 30) x 2 / 2 = 3.3e-3 m; the method's local error and its tableau
        'paid out equal to a t^2 / 2; the stage at t leaves it 3.3 mm short).',
        'It is still order 1 for any J, for the local error is h^2 (f_y / 2 '
        '- J) f + O(h^3) whatever J;', '(alpha_1 = 1/2 for , 0 for every other method),',
    ),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        # --long wp_closed_loop (2026-11-30, 965 s, nice 15, load 3-3.7): every step and error as written
        Printed('wp_closed_loop', (
            '| ladder_chain | 0.0222 s | ROS34PW2 0.0667 s:', '| 0.01667 s | 0.05 s:',
            '| laddermill | 0.01538 s | ros2t 0.01667 s:', '| 0.0125 s | 0.05 s:',
            'Every W-method of this table meets the tolerances at its largest step, 0.05 s, with room to spare.',
            'On the chain ROS34PW2 at 0.05 s is 2.5e-4 m and 3.1e-4 rad off, and ros2t is 3.1e-4 m off.',
            'On the mill ros2t is 1.9e-4 m off and 0.07 % in power.',
            'The RK4 baseline meets them by orders of magnitude (3e-8 m on the chain).',
            'the stable-step estimate of 0.02445 s,',
            # the step+lqr sections' "references (dp54 ... and scipy_dop853 ...) agree to": the chain's and the mill's
            # lines are 166 lines apart, so one snippet each
            'The closed-loop references agree to 1.3e-9 (chain)', 'and 2.4e-9 (mill) in the scaled state.',
        )),
        # the mill's fastest unstable mode (whip_spectrum prints 6.405 1/s; until 2026-11-30 under wp_closed_loop)
        Printed('whip_spectrum', (
            "After the direction step the chain's and the mill's slow lateral modes are unstable (up to 6.4 1/s, "
            '"The apex whip\'s modes" there), so any integrator\'s local error grows by itself, and what separates '
            'the methods is how much error each step adds to those modes.',
        )),
        # tests/test_closed_loop_precision.py prints both agreements beside its assertions
        Printed('closed_loop_rollout_tests', (
            "At the scene's own integrator the wing paths agree to 8e-17 m and 3.5e-18 rad on the tethered wing (2 s). "
            'On the chain (4 s, slow test)', 'they agree to 5e-12 m and 1.3e-12 rad.',
        )),
        Printed('wp_chain_kept_matrix', (
            'Every kept-matrix run of these three methods still meets the tolerances with room: at most 2.0e-3 m in '
            'lateral offset (ros2, '
            'as every step), 3.0e-4 rad in attitude and 1.2e-4 in tension.',
        )),
        # --long wp_every_period (2026-12-06 05:18-05:29, ros1's stage at the step's middle): the steps and errors of
        # its two tables of runs
        Printed('wp_every_period', (
            'with room in every measure: 1.1e-4 in tension, 1.0e-4 in power, 6.6e-3 m and 8.6e-4 rad',
            'the same errors).',
            '| every step | 5.7e-4 | 2.8e-3 | 6.9e-3 m | 6.1e-4 rad |',
            '| kept 2 | 9.0e-4 | 3.3e-3 | 6.8e-3 m | 6.1e-4 rad |',
            '| kept 4 | 3.7e-3 | 1.6e-2, over | 6.8e-3 m | 6.1e-4 rad |',
            '| kept 8 | 9.2e-3 | 4.3e-2, over | 6.8e-3 m | 6.1e-4 rad |',
            'At 0.025 s the power error halves (1.5e-3 every step)',
            "At 0.05 s the mill's power error is now 2.8e-3 every step and 3.3e-3 kept 2",
            'ros2t kept 4 is 1.1 % off in power,', 'ros2t kept 8 1.7 %,', 'ros2 kept 4 1.2 %', 'and ros2 kept 8 3.1 %.',
            'their power errors stay at or below 1.0e-4 whatever the refresh.',
        )),
        Printed('wp_mill_kept_matrix', (  # its full table and its table of the fastest runs are far apart
            'On the mill the kept matrix costs accuracy in the generator power: ros2 kept 8 at 0.05 s is 2.0e-2 off '
            'in power', '(hence its 0.025 s), ros2 kept 4 is 8.5e-3 off, ros2t kept 8 1.7e-3.',
        )),
    ),
    history=(  # one-off runs beside the study (the page: "a one-off script"; their steps, 0.05 s / 2 and / 3, given):
        # the study's closed-loop grid starts at 3 RK4 steps per period on the chain (0.01667 s) and 4 on the mill
        # (0.0125 s), so no command prints these
        History('2026-11-30', 'a one-off script of the closed loop with RK4 at 2 / 3 steps per period (f45b8d3)',
                'ladder_chain at 0.025 s and laddermill at 0.0167 s under the LQR, 10 s',
                ('runs to the end but misses the tolerances: 4.6 % in tension and 0.075 rad in attitude (a growing '
                 'cable mode;', 'breaks down at 0.33 s (2026-11-30, f45b8d3).')),
        # the mill's pay-out under ros1 (/tmp scripts: the closed loop of the study, states against DP5(4) at 1e-10,
        # errors at every control period); h a t / 2 = 0.05 x (2 / 30) x 10 / 2 = 0.0167 m from the scene's schedule
        History('2026-12-06', 'one-off runs of the mill closed loop with ros1 and ros2 (0bff11b)',
                'laddermill under the LQR, 10 s: the station state at the end; ros1 with s reset to t^2 / 30 after '
                'every step; s swapped afterwards; a schedule held at 0.667 m/s',
                ("Most of it came from the station's pay-out.", '(ds/dt = V(t), on the schedule\'s ramp of 2/30 '
                 'm/s^2) by explicit Euler, and s lags by h a t / 2: 1.7 cm at 10 s.',
                 "The first element's rest length, 7 m plus s,",
                 'One-off runs of the same closed loop (2026-12-06, 0bff11b) found s off by 1.66e-2 m at 0.05 s and '
                 '8.3e-3 m at 0.025 s, where ROS2 is exact to 2e-15 m.',
                 'With s set to its exact value t^2 / 30 after every step (a script, not an option), at 0.05 s was '
                 '0.32 % off in power instead of 1.16 %, and at 0.025 s 0.049 %; its other errors barely moved '
                 '(1.5e-3 in tension, 6.9e-3 m, 6.1e-4 rad).',
                 "moves the power by 116 %,", 'a schedule held at 0.667 m/s from the start,',
                 'leaves even RK4 at 0.0125 s 1.3 % off in power.',
                 'With s exact and the matrix kept 2 steps it was 0.90 % off in power; kept 4 2.2 % and kept 8 4.8 %')),
        # the study's first run with ros1 (--long wp_every_period, 2026-12-06 03:12-03:23, 0bff11b), its stage at t
        # then: the code of the day, so a record
        History('2026-12-06', 'python -m docsite.readme_figures --skip-readme --long wp_every_period (0bff11b)',
                "the every-period study with ros1's stage at the step's start",
                ("it missed the mill's power tolerance at 0.05 s by a little,",
                 '| every step | 1.3e-3 | 1.2e-2 | 6.9e-3 m | 6.1e-4 rad |',
                 '| kept 2 | 1.4e-3 | 1.1e-2 | 6.9e-3 m | 6.1e-4 rad |',
                 '| kept 4 | 2.7e-3 | 1.0e-2, just over | 6.9e-3 m | 6.1e-4 rad |',
                 '| kept 8 | 8.3e-3 | 3.4e-2 | 6.9e-3 m | 7.5e-4 rad |',
                 'The first three took 3.7x, 5.4x and 6.9x less CPU time than the RK4 baseline; the mill\'s best was '
                 'then 4.61x (kept 8 at 0.025 s), the chain\'s 6.30x (kept 8).',
                 'At 0.025 s the power error was 0.59 %, half as large.',
                 '(1.2e-2 and 1.1e-2 with the stage at t, above);')),
    ),
)
