"""The ledger entry (:mod:`docsite.page_ledger`) of docs/scorecard_physics_step.md: the step study's tables, the
wing's accuracy, the rotorcraft's two steps and the held-out counts (long group ``scorecard_step``; the counts per
profile where they move with it), TetheredWing-v1's gusts-v4 scorecard (long group ``gusts_v4_tethered_wing_v1``,
checked from its CSV), its throughput and start-up timings dated, its settings given."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, Printed

V1_CARD = "{gusts_v4_tethered_wing_v1[scorecard][%s]}"

SCORECARD_STEP = Covered(
    checks=(
        (r"selects one\): the LQR (\d+ / \d+) and the policy (\d+ / \d+), the same episodes lost",
         (V1_CARD % "lqr", V1_CARD % "ppo_tethered_wing")),
    ),
    given=(
        '# The gust scorecard and the physics step: TetheredWing-v1 Issue 31 point 4 asks',
        'is decided by its seed 0, an episode on a knife edge.',
        "v0's physics step, one ROS34PW2 step of 50 ms per control period,",
        'That step is registered as (2026-12-05).',
        'compares the episodes lost with those on the first, RK4 at 3.125 ms (2026-12-05,',
        '| physics step | LQR | | against RK4 at 3.125 ms |',
        'RK4 at 25 ms loses the same episodes but one:',
        'A coarse step does not favour one controller: RK4 at 50 ms and ROS2 at 50 ms take a scenario from both, and '
        'ROS34PW2 at 12.5 ms gives the policy one more. (RK4 at 50 ms is past its stable step in the strongest wind '
        'of one scenario, where the env steps at 25 ms with a warning:',
        'runs the wing open loop for 10 s under its trim action plus seeded uniform noise of 0.3 every control '
        'period, against RK4 at 3.125 ms',
        "v1's RK4 takes two steps of 25 ms per control period, the W-methods one of 50 ms:",
        'A linearly implicit step of 50 ms damps', 'where RK4 at 25 ms carries it',
        # numerics.md's figures (its ledger checks them): RK4's stable step and the damping eigenvalue at the trim
        "the aerodynamic damping's eigenvalue is about -24 1/s at the trim",
        "RK4's stable step at the trim is about 0.11 s;",
        '(2026-12-05; selects one)', 'On 200 held-out NTM-IB fields',
        'with RK4 at 12.5 ms, runs to the end;',
        '## Faster steps for the single craft (issue 32 point 2) Point 2 asks TetheredWing-v0 for 400,000 env steps/s '
        'at 512 copies on two threads and Rotorcraft-v0 for 150,000.',
        "measures each step's throughput at 512 copies", 'Every wing step fast enough for 400,000 steps/s',
        'The rotorcraft passes 150,000 with ROS2 and its matrix kept 4 steps,', 'point 2 stays open.',
        "the LQR lost NTM_IB's seed 0 under znver3's kernels only;",
    ),
    timings=(
        # the study commands' wall times and the bench / start-up runs (2026-12-05, znver5, load 1.4)
        '(2026-12-05, 40 s;', '( , 11 s)', ' (25 s) ', '(40 s) measures',
        # craft_step_options' throughput column (one quick run, 2026-12-05 17:45 UTC, load 0.6-0.7, znver5)
        'Throughput, one run each (2026-12-05 17:45 UTC, load 0.6-0.7): the wing 289,993 steps/s with '
        "TetheredWing-v1's RK4, 278,397 with v0's ROS34PW2, 455,579 with RK4 at 50 ms, 403,799 with ROS2, 449,519 "
        "kept 2 and 490,379 kept 4; the rotorcraft 86,709 with v0's ROS34PW2, 124,872 with ROS2, 141,257 kept 2, "
        '164,977 kept 4 and 172,478 kept 8.',
        'three runs (2026-12-05 17:27 UTC, load 1.4, two threads), 279,017 / 280,821 / 278,013 env steps/s against '
        "v0's 269,347 / 252,452 / 261,537 in the same runs. Its cold start took 13.6 s and its warm start 0.64 s ( , "
        '2026-12-05).',
        # the bit-preserving right-hand side attempts (2026-12-06, znver4): perf's libm share, the stack stores
        # counted in w_advance_one's machine code, env_step_cost alternated with a worktree (one thread)
        "keeping v0's bits (2026-12-06, AMD EPYC, znver4).", "vector env at 512 copies on one thread put 11 % of the "
        "process's samples (its start included) in libm (sincos 5.3 %, atan2 2.6 %, pow 1.5 %, exp 1.1 %)",
        'holds about 1,500 stack stores for '
        'them per step (about 0.25 us at two stores per cycle; the 450 that inlining removes,',
        "gave the wing's vector step 7.59 / 7.72 / 7.29 us per copy against 7.55 / 7.58 / 7.81 before, the "
        "rotorcraft's 27.20 / 26.11 / 25.86 against 25.88 / 25.49 / 25.24; not kept.",
    ),
    derived=(
        '(h lambda = -0.6 at the trim)',  # -24 1/s x 0.025 s
        # the closed-loop run's printed power differences (+2.08e-09 and +6.48e-08 relative), bounded
        'agree to 1e-7 in mean power',
        'the same episodes lost at the same times to 0.01 s',  # the gust-bench CSVs of the three profiles, compared
    ),
    printed=(
        Printed('scorecard_step', (
            '| RK4, 3.125 ms (reference) | 10 / 12 | 10 / 12 |', '| RK4, 12.5 ms | 10 / 12 | 10 / 12 |',
            '| RK4, 25 ms (TetheredWing-v1) | 10 / 12 | 10 / 12 | the same scenarios lost; ends within 0.15 s |',
            '| RK4, 50 ms | 9 / 12 | 9 / 12 |', '| ROS34PW2, 6.25 ms | 10 / 12 | 10 / 12 |',
            '| ROS34PW2, 12.5 ms | 10 / 12 | 11 / 12 |', '| ROS34PW2, 50 ms (TetheredWing-v0) | 11 / 12 | 10 / 12 |',
            '| ROS2, 50 ms | 9 / 12 | 9 / 12 |',
            'On the reference both controllers lose NTM_IB (on seed 2: the LQR at 32.20 s, the policy at 31.30 s)',
            "the LQR's NTM_IB seed 1, lost at 54.80 s on the reference and at 59.10 s",
            'the episodes lost on both end within 0.15 s.',
            "loses the policy's NTM_IB seed 0 at 22.95 s,",
        ), cpu="znver4"),
        Printed('scorecard_step', (
            '(extent 101.5 m, mean reward 0.9188)',
            '| RK4 (TetheredWing-v1) | 5.808e-05 m | 0.0002665 | 0.9188 |',
            '| ROS34PW2 (TetheredWing-v0) | 0.01043 m | 0.05591 | 0.9188 |',
            '| ROS2, one step per period | 0.01439 m | 0.1182 | 0.9185 |',
            'gives both controllers 8 / 9 on', 'ECD_IA lost (the LQR at 34.85 s, the policy at 14.65 s), and the same '
            'on RK4 at 1.5625 ms (34.85 s and 14.15 s).',
        )),
        Printed('scorecard_step', (
            'the policy survives 150 and the LQR 111 (only the LQR 6, only the policy 45, neither 44; sign test p = '
            '1.83e-08) on znver4',), cpu="znver4"),
        Printed('scorecard_step', ('150 and 114 on znver3 (p = 1.01e-07)',), cpu="znver3"),
        Printed('craft_step_options', (  # the LQR's scorecards per step (v0's wing row moves with the profile)
            '| TetheredWing | RK4, 25 ms (TetheredWing-v1) | 10 / 12 | the same scenarios lost, ends within 0.15 s |',
            '| TetheredWing | ROS34PW2, 50 ms (TetheredWing-v0) | 11 / 12 |', '| TetheredWing | RK4, 50 ms | 9 / 12 |',
            '| TetheredWing | ROS2, 50 ms; kept 2; kept 4 | 9 / 12 |',
            '| Rotorcraft | ROS34PW2, 50 ms (Rotorcraft-v0) | 8 / 9 | the same scenarios lost, ends within 0.00 s |',
            '| Rotorcraft | ROS2, 50 ms | 8 / 9 | the same scenarios lost, ends within 0.65 s |',
            '| Rotorcraft | ROS2 kept 2; kept 4 | 8 / 9 | the same scenarios lost, ends within 4.20 s; 3.70 s |',
            '| Rotorcraft | ROS2 kept 8 | 9 / 9 |', 'its LQR losing the same scenario 3.70 s later',
        ), cpu="znver4"),
    ),
)
