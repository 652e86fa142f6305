"""The ledger entry (:mod:`docsite.page_ledger`) of docs/benchmarks.md: machine timings almost throughout (each
dated on the page: a date or the commit measured, with the load where it was recorded; the undated ones dated
from ``git log -S`` of README.md, where they were first written), the point-mass scene's size and explicit step
checked against ``pointmass_benchmark``, the stable-step row against ``laddermill bench`` and ``laddermill
stable-step``, the mill's stable steps and the W-method accuracy table not re-run (their commands named), the
settings and targets given."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, Printed

SA10, SA40 = "{step_accuracy_10[%s]}", "~{step_accuracy_40[LadderMill-v2][%s]}"
#: the accuracy runs' figures worked from their printed lines (docsite/printed_ratios.py, compared by --long
#: step_accuracy_10 / step_accuracy_40; until 2026-11-30 derived entries): the mill's ROS2 error 0.06437 m in cm; the
#: 40 s run's ends, (periods + 1) x the 50 ms control period, and the mill's ROS34PW2 error 0.02623 m in cm; the 1e-3
#: bound: the next power of ten above the steps' printed shares over 10 s (3.2e-4, 4.5e-4 and 7.0e-7, 1.9e-5)
STEP_CHECKS = (
    (r"50 ms \| (\d+\.\d+) cm \|", ("~" + SA10 % "LadderMill-v2][ros2][cm",)),
    (r"\((\d+\.\d+) and (\d+\.\d+) s\), within (\d+\.\d+) cm", (SA40 % "ros34pw2][end_s", SA40 % "reference][end_s",
                                                                 SA40 % "ros34pw2][cm")),
    (r"ROS2 ends it after \d+ \((\d+\.\d+) s\)", (SA40 % "ros2][end_s",)),
    (r"ROS34PW2 is the step of choice: within (1e-\d) of the extent on both", (SA10 % "share_bound][ros34pw2",)),
    (r"ROS2 is cheaper again and also within (1e-\d) over 10 s", (SA10 % "share_bound][ros2",)),
)

BENCHMARKS = Covered(
    groups=('pointmass_benchmark', 'bench_stable_dt', 'stable_steps'),
    checks=((r"largest stable RK4 dt \(bisection against DP5; eigenvalue estimate\) \| ([\d.]+) s; ([\d.]+) s \| "
             r"([\d.]+) s; ([\d.]+) s",  # laddermill bench (the bisection) and laddermill stable-step (the estimate)
             ("{bench_stable_dt[tethered_wing]}", "~{stable_steps[tethered_wing][rk4]}",
              "{bench_stable_dt[ladder_chain]}", "~{stable_steps[ladder_chain][rk4]}")),
            (r"at 1 cm \(([\d,]+) elements\)\. The simulation holds ([\d.]+) MB of arrays on two threads",
             ("{pointmass_benchmark[elements]}", "{pointmass_benchmark[held_MB]}")),
            (r"Voigt damping to ([\d.e-]+) s steps", ("{pointmass_benchmark[explicit_dt]}",)),
            *STEP_CHECKS),
    given=(
        'wings / nodes / elements / states | 1 / 1 / 2 / 19 | 101 / 0 / 102 / 1313',
        # the accuracy table's physics steps (the envs' registered steps and the command's --steps)
        'registered: RK4 4 x 12.5 ms', 'registered: RK4 5 x 10 ms', ': 1 x 50 ms |',
        'and in the same run over 40 s ( )',  # the command's --time 40
        "the scene's step is therefore 10 ms, no longer the chain's 12.5 ms. From a lateral disturbance the 3D mill "
        'diverges within a second and DP5(4) stalls',  # the scenes' steps
        "and ROS2 at 17-50 ms diverges in the mill's apex whip",  # docs/work_precision.md's steps
        'Targets: chain at least 30x real time, kernels at least 50x the reference, cost linear within 25 %, warm'
        ' start-up at most 3 s.',
        'The moving-cable laddermill (same run, ; timed after the cable is at 2 m/s, against the fixed chain with'
        ' the same wings and state, interleaved):',
        '(Podgaets & Ockels 2007;',
        '100 kites on 5 km of Dyneema at 1 cm',
        "target at most 40 MB; the paper's whole program 82 MB",
        'SyncVectorEnv over single envs measured in the same run; 20 Hz control, TetheredWing-v0 and '
        'Rotorcraft-v0 with one linearly implicit ROS34PW2 step of 0.05 s per control period (docs/numerics.md), '
        'LadderChain-v0 with four RK4 steps of 0.0125 s). TetheredWing-v0 and Rotorcraft-v0 measured on '
        '2026-11-24 (30708d3; load not recorded; ), the chain before:',
        'measures those two at 512 copies only (the copy counts of for every env named); measures the native env '
        'of TetheredWing-v0 and Rotorcraft-v0 at 512 copies ( ) for each numba thread count in one process ( ; '
        'counts above NUMBA_NUM_THREADS or the cpu count are left out with a note) and prints steps/s and the '
        'speed-up over the first count.',
        '### The 101-wing envs on both cores, one W-method step per control period (issue 32 point 3)',
        '### Where a single-craft copy-step goes (issue 32 point 2, 2026-12-03)',
        '### LadderChain-v1: three RK4 steps per control period, 3,000 steps/s at 8 copies (2026-12-05)',
        # the pointer to scorecard_physics_step.md's section (its ledger checks the figures): targets and labels
        '(2026-12-05): every wing step past 400,000 steps/s changes the scenarios the LQR loses; the rotorcraft passes '
        "150,000 with ROS2 and its matrix kept 4 steps, its LQR's lost episode ending later.",
        "that divides the 50 ms period within the env's stability margin (0.9 x RK4's estimated stable step",
        'two steps of 25 ms are past it', 'Over 10 s of the study\'s seeded actions', "so is v0's 12.5 ms)",
        'against RK4 at 3.125 ms', 'ROS34PW2 at 50 ms', 'over 200 periods of actions of 0.3 amplitude',
        'holds the rows of its 6 x 6 solves (the coupling blocks Y = D^-1 U,',
        '(SHA-256 of seeded single and vector episodes',
        'the code before (2db3288, a worktree with this study file)',
        '| env, copies | before | after |', 'three runs (12:35 UTC, right after): | env, 8 copies |',
        '### Thread scaling on a 16-core machine (issue 32 point 2, 2026-12-04)',
        "the wing's 12x needs its Python and numpy work per vector step halved as well.",
        '- **Both cores across copies.** A task of 500 states or more (the 101-wing chain, 1313; the mills) steps '
        "its copies on several threads from 2 copies on ( ; the single-wing envs from 32 copies), so each copy's "
        'arithmetic is the same on one thread or two (bit for bit, ). Until 2026-12-03 the threads were a numba '
        "kernel over copies; since then the single env's kernel runs on ranges of copies ( , [cold start]). keeps "
        'one thread. - **The env argument ** ( ): steps the physics with one linearly implicit ROS34PW2 step per 50'
        ' ms control period instead of the registered RK4 (LadderChain-v0 four steps of 12.5 ms, the mills five of '
        "10 ms); and (with [s]) too. The operating point, spaces and rewards are the id's. Default: the registered "
        'step ( ).',
        'Accuracy, against an independent reference, RK4 at a quarter of the registered step: the largest '
        "position error of the wings' CGs and cable nodes over a 10 s episode (the 0.01 rad direction step at 1 "
        's; the open-loop action plus seeded uniform noise of 0.3 every period), as a share of the extent (the '
        'largest distance of a point from the origin), and the CPU cost of one copy on one thread ( , and the '
        'same for ; the CPU columns on the loaded machine, below):',
        # the new section's heading, settings and the command's labels and episode lengths
        'The fastest step within 1e-3: 3,000 steps/s at 8 copies (2026-11-30)',
        'is kept for 4 steps', "The target is **met** with (bold), **but that step moves the rewards**",
        "(200 periods of actions of 0.3 amplitude, seed 3, against RK4 at a quarter step; )", "**Met on the mill**",
        'and every W step at 50 ms gives the chain',  # the control period
        'the largest position error as a share of the extent (periods run, of 200):',
        'on the mill alone K = 5 and 6 do too, 4 % faster on one copy', 'One seeded action sequence per env',
        'runs both envs through within 1e-3', 'Over 40 s ( )', '(its 101-wing rows now measure too)',
    ),
    timings=(  # each dated on the page (date or commit, machine, load where recorded)
        # the 16-core machine's thread scaling (2026-12-04, 5d94126) and this machine's two-thread runs
        'A 16-core virtual machine was lent for one run (Intel Xeon, one socket, no SMT, Python 3.12, numba '
        '0.68.0, numpy 2.5.2; 5d94126, the copies then on Python threads only; , then and ), in env steps/s and '
        'the speed-up over one thread: | env, copies | 1 thread | 2 | 4 | 8 | 16 | serial share, Amdahl at 16 | '
        '|---|---|---|---|---|---|---| | TetheredWing-v0, 512 | 102,467 | 95,442 (0.93x) | 146,893 (1.43x) | '
        '178,633 (1.74x) | 188,347 (1.84x) | 3.9 %, 10.1x | | Rotorcraft-v0, 512 | 17,396 | 29,464 (1.69x) | '
        '55,807 (3.21x) | 98,085 (5.64x) | 152,591 (8.77x) | 1.8 %, 12.6x | | TetheredWing-v0, 4096 | 75,674 | '
        '112,110 (1.48x) | 214,851 (2.84x) | 406,552 (5.37x) | 630,344 (8.33x) | 2.0 %, 12.3x | | Rotorcraft-v0, '
        '2048 | 23,406 | 31,452 (1.34x) | 62,150 (2.66x) | 108,735 (4.65x) | 191,599 (8.19x) | 0.8 %, 14.2x | So '
        'the 12x target is **not met** (8.2-8.8x where the copies outweigh the overhead, 1.84x for the wing at '
        '512). Each vector step on several threads took 1.5-3 ms longer than its one-thread time over the thread '
        'count plus its serial part, about the same at 2 and at 16 threads: a cost per call, not per copy, which '
        "the wing's 5 ms step at 512 copies cannot hide. The Python threads pay it (a future, a queue and the GIL "
        "handed over twice per range); numba's own pool had given the same kind of machine 4.4x at 512 copies "
        "with the former prange kernel. Since then the copies run on numba's pool through a launcher per step "
        'kernel (a prange loop over the ranges that calls the kernel by its address, ): the same bits, 7 s to '
        "compile on a vector env's first parallel step (cached). The second device run, which was to measure it, "
        'was refused (no machine lent), so its many-core speed-up is not measured; the study now prints both ways '
        'per thread count. On this 2-core machine (19:00-19:02 UTC, load 0.7-1.6) they tie within its scatter: '
        "TetheredWing-v0 at 512 copies on two threads 137,490 / 157,356 / 182,927 steps/s through numba's pool "
        "against 154,292 / 153,176 / 183,175 on Python threads (three runs). With numba's spinning workers took "
        'the cores from the Python threads measured right after them (95,882 and 83,706 against 182,707 and '
        '204,942 for the pool): the active wait suits a machine with a core per thread and one parallel user ( ; '
        'the package sets the passive wait unless the user chose).',
        # the chain at 8 copies re-measured against the code of 2026-11-30 (2026-12-04)
        'On 2026-12-04 (the 2-core AVX-512 EPYC) the same 8 copies ran slower than the figures above: printed '
        '1,415 / 1,169 / 1,242 steps/s for the registered step at 86aab88 and 1,089 / 1,458 / 1,116 at 11cffdc '
        '(the code of the 2026-11-30 runs above), alternated (17:15-17:23, load 0-1.1): no regression, the '
        'machine and hour of 2026-11-30 were faster.',
        # the accuracy table's CPU column, on the loaded machine the page describes below it (step_accuracy_10 on
        # 2026-11-30 at load 1-3: 754, 1,338, 2,023 and 575, 1,100, 1,440 steps/s)
        '| 373 steps/s |', '| 597 steps/s (1.6x) |', '| 786 steps/s (2.1x) |', '| 391 steps/s |',
        '| 731 steps/s (1.9x) |', '| 1,091 steps/s (2.8x) |',
        # dated by git log -S of README.md (eb9be00, 904b335, 30708d3, 3950f04); the load was not recorded then
        "on this project's 2-core machine, one thread, medians of repeated runs; the numpy reference is timed in "
        'the same run (2026-11-24, eb9be00; the load was not recorded).',
        "right-hand side | 1.10 us | 48.7 us | | RK4 step | 4.5 us | 198 us | | real-time factor at the scene's "
        'dt | 1113x (dt 0.005 s) | 63x (dt 0.0125 s) | | speed-up over the numpy reference | 488x | 1873x',
        'saving with sag off / cable aero off / both / in-plane | 12% / 10% / 21% / 21% | 11% / 6% / 15% / 29% | '
        '| start-up, empty numba cache / warm cache | 26.6 s / 1.0 s | 27.4 s / 1.5 s',
        'Cost per wing for 10, 100 and 1000 wings: 549, 494 and 476 ns (1000 vs 10 wings: 0.87 of linear). Peak '
        'resident memory of the benchmark process: 401 MiB.',
        '(16b454f: chain full 77 us, sag off 65, cable aero off 63;',
        "(cable aerodynamics about 3 of the chain's 49 us, against 14 of 77).",
        'RK4 step at dt 0.01 s | 195 us (fixed chain 197 us: -1.0 %) | 138 us (fixed chain 137 us: +0.4 %) | | '
        'real-time factor | 51.2x (target 30x: met) | 72.6x (1.4x faster than 3D) | | post-step check / with a '
        'wing transfer | 4.3 us / 4.9 us (once per l0 / V_c = 35 s)',
        "the process peaks at 216 MB with numba's cache warm (about 143 MB of it imports).",
        "steps at the kites' 10 ms: 0.18x real time on one thread here (2026-11-24, 904b335; target 0.1x), 0.275x"
        ' on an idle 16-core machine. Cost per element from 10k to 500k elements within 4 % (implicit, 106-109 '
        'ns) and 5 % (explicit, 55-58 ns) in the run above;',
        '1 | 9,300 steps/s | 8,000 | 1.2x | 926 steps/s | 962 | 1.0x | | 8 | 43,500 | 9,100 | 4.8x | 1,020 | 922 '
        '| 1.1x | | 64 | 151,000 | 8,700 | 17.4x | | | | | 512 | 198,000 | 8,300 | 23.8x',
        '1 | 7,320 steps/s | 6,310 | 1.2x | | 16 | 27,600 | 7,040 | 3.9x | | 64 | 62,200 | 6,420 | 9.7x',
        "Re-measured on 2026-11-29 evening (load 0.4, both cores free; numba's default two threads): printed "
        'TetheredWing-v0 7,955 / 129,407 / 170,647 steps/s (SyncVectorEnv 6,650 / 9,250 / 8,253; 20.7x at 512) '
        'and Rotorcraft-v0 6,935 / 47,237 / 54,410 (SyncVectorEnv 5,936 / 6,788 / 6,893). Six alternated runs of '
        "TetheredWing-v0 at 512 copies on this session's last commit and its first (0644ebb) scattered from "
        '107,000 to 184,000 steps/s with medians of about 160,000 and 166,000: the tables above are one quiet '
        "day's figures, not a floor.",
        'Targets: at least 100,000 env steps/s for TetheredWing-v0 and at least 20x the SyncVectorEnv at 512 '
        'copies (met); Rotorcraft-v0 at least 20,000 at 64 copies (met: 62,200, against 6,580 with its former 25 '
        "RK4 steps of 2 ms per control period). TetheredWing-v0's one ROS34PW2 step costs about 1.9x its former "
        'RK4 step (382,000 steps/s at 512 copies then), the price of a step that stays stable in a stiffening '
        'wind.',
        'The chain is kernel-bound (101 wings, 1313 states): batching it saves only the Python overhead. '
        'LadderMill-v0 (101 wings, moving cable; 2026-11-23, 3950f04): 894 steps/s with one copy and 964 with '
        'eight (SyncVectorEnv 867 and 861), one thread, measured at the earlier 12.5 ms physics step (four RK4 '
        "steps per control period); at today's 10 ms (five) expect about a fifth fewer.",
        'Throughput on the pool, SyncVectorEnv as the baseline ( ) on a quieter machine (2026-11-29 12:53 UTC, '
        'load average 1-2: one light job beside it), where the pool got both cores ("cpu" 1.9-2.0):',
        'env, copies | native (pool from 2 copies) | one thread | pool and | SyncVectorEnv | '
        '|---|---|---|---|---| | LadderChain-v0, 1 | 433 steps/s, 1.0x (cpu 1.00) | 526, 1.2x (1.00) | 975, 2.2x '
        '(1.00) | 443 (1.00) | | LadderChain-v0, 8 | 964, 1.5x (1.99) | 610, 0.9x (1.00) | **1,517**, 2.4x (2.00)'
        ' | 642 (1.00) | | LadderMill-v2, 1 | 373, 1.2x (0.99) | 311, 1.0x (0.98) | 564, 1.9x (0.97) | 303 (0.99)'
        ' | | LadderMill-v2, 8 | **622**, 2.1x (1.93) | 398, 1.3x (0.98) | 505, 1.7x (1.00) | 296 (1.00)',
        'So the target is **not met**: the chain reaches 1,517 env steps/s at 8 copies (half of 3,000), the mill '
        '622. The pool scales the chain 1.6x from one thread to two (964 / 610) and the mill 1.6x (622 / 398); '
        'ROS34PW2 gives the chain 1.6x more on the pool (1,517 / 964) but read "cpu" 1.00 for the mill\'s 8 copies'
        " (found below: the machine's load, not the kernel), and both envs are slower per copy than the earlier "
        "rows' quiet machine (SyncVectorEnv 642 against 922 for the chain). (2.1x and 2.8x cheaper, within 1e-3 "
        'over 10 s) leaves room;',
        '**The mill\'s ROS34PW2 step does use the pool.** The "cpu" figure is the process\'s CPU seconds per wall '
        'second, which other work on the machine lowers as much as a kernel that keeps to one thread does; the '
        '1.00 above was not reproduced. Linux keeps a CPU clock per thread, which other work does not change, so '
        'now also prints "threads" for every native rate: the threads\' CPU seconds over the busiest thread\'s '
        "(1.00: one thread did all the work; 2.00: two shared it evenly; OpenMP's workers spin briefly after each"
        ' parallel region, which counts a little). LadderMill-v2 with ROS34PW2 at 8 copies split its CPU 0.23 / '
        "0.23 s between two threads over 50 vector steps (0.19 / 0.18 s with numba's workqueue layer, whose "
        'workers do not spin; LadderMill-v1 0.45 / 0.44 s over 60), and checks that 16 copies of a small v2 mill '
        "share their ROS34PW2 steps between both threads and that the mill's results are bit for bit the same on "
        'one thread, two threads and the serial kernel. on a quiet machine (2026-11-29 16:47 UTC, load 0.8, 29 s):',
        'env, 8 copies | native (pool) | one thread | pool and | SyncVectorEnv | |---|---|---|---|---| | '
        'LadderChain-v0 | 1,309 steps/s (cpu 1.99, threads 1.99) | 699 (1.00, 1.00) | **1,522** (1.99, 1.99) | '
        '623 (1.00) | | LadderMill-v1 | 731 (1.98, 1.99) | 413 (1.00, 1.00) | **1,569**, 4.9x the SyncVectorEnv '
        '(1.99, 1.99) | 318 (1.00)',
        'Both cores busy, ROS34PW2 included; the 3,000 steps/s target was **not met** there (about half of it).',
        # the fastest step's section (2026-11-30, quiet machine): one copy's CPU rates of the accuracy runs, the
        # throughput table's three runs and their medians
        "One copy's thread in the same runs (load 2.4-2.6): 2,208 and 1,458 steps/s against ROS34PW2's 1,279 and 940.",
        'three runs, 2026-11-30 12:29-12:30 UTC, load 0.75-0.93 (nothing else running):',
        'env, 8 copies | registered step (pool) | one thread | | | SyncVectorEnv | |---|---|---|---|---|---| | '
        'LadderChain-v0 | 1,658 / 1,644 / 1,596 | 869 / 879 / 820 | 3,107 / 3,159 / 3,096 | **6,584** / 6,631 / '
        '6,374 | 810 / 808 / 761 | | LadderMill-v2 | 1,280 / 1,283 / 1,276 | 671 / 669 / 675 | 2,556 / 2,694 / '
        '2,690 | 4,505 / **4,854** / 4,912 | 554 / 574 / 577',
        # the single-craft copy-step's parts (env_step_cost, 2026-12-03, a6edb17, AVX2 EPYC, load 0.7-1.0); derived:
        # 0.86 + 3.68 = 4.54, 3.12 + 13.08 = 16.20; 12.32 / 12.86 = 96 %, 37.56 / 38.05 = 99 %; Jacobians and linear
        # algebra (2.07 + 0.67 + 0.15 + 0.49) / 12.86 = 26 %, (7.28 + 1.48 + 0.78 + 1.30) / 38.05 = 28 %
        "(4 min) times each part of the compiled step in a compiled loop over one copy of the env's own "
        'batch, so no Python dispatch enters a part ( calls each part from Python: about 10 us each, most of '
        'a one-wing part), and the whole vector step and its kernel per copy at 512 copies, all on one numba '
        'thread (CPU time, least of 5 rounds). Run on 2026-12-03 (a6edb17, a 2-core AVX2 EPYC, load 0.7-1.0),'
        ' in us per copy and control period:',
        '| part | TetheredWing-v0 | Rotorcraft-v0 | |---|---|---| | vector step | 12.86 | 38.05 | | step '
        'kernel | 12.32 | 37.56 | | ROS34PW2 step | 8.41 | 31.08 | | its assembly, 3 right-hand sides | 0.86,'
        ' 3.68 | 3.12, 13.08 | | its body and cable Jacobians | 2.07, 0.67 | 7.28, 1.48 | | its '
        'factorisation, 4 eliminations | 0.15, 0.49 | 0.78, 1.30 | | the observation after it | 1.38 | 5.07 |'
        ' | rest of the kernel | 2.53 | 1.41 | | Python and numpy (actions, rewards, infos) | 0.54 | 0.49 |',
        "The rest of the kernel was read then as its own work (the wind's kinks, the copy's views) and what the "
        "parts, timed on one copy's state again and again, do not pay over 512 different copies (caches, branch "
        "predictors); it was mostly the W step's own cost in the kernel's call (corrected in the next section). "
        '400,000 env steps/s on two threads that share the copies perfectly allow 5.00 us of one'
        " thread per copy-step, 0.39 of today's; 150,000 allow the rotorcraft 13.33 us, 0.35 of today's. The "
        'four model evaluations of a ROS34PW2 step (one assembly, three right-hand sides) alone cost 4.54 us '
        "of the wing's 5.00 and 16.20 us of the rotorcraft's 13.33: with the Jacobians, the linear algebra, "
        "the observation, the kernel's own work and Python free, the wing would just fit and the rotorcraft "
        'not. So point 2 cannot be met by trimming around the physics (the step kernel is 96-99 % of the '
        'vector step, the Jacobians and linear algebra 26-28 %): it needs fewer model evaluations per control'
        ' period (one ROS2 step makes two; a kept iteration matrix, in docs/numerics.md, saves the Jacobians '
        "on most steps) and a right-hand side itself about half as costly. Either moves the registered ids' "
        "bits, on which the gust scorecards and the shipped policies' figures are measured: a new id's work, "
        "not TetheredWing-v0's or Rotorcraft-v0's.",
        # LLVM's straight-line vectoriser tried (2026-12-07): a dated record of a hash comparison, not a timing
        '(the SHA-256 of their observations and rewards under seeded actions)',
        'hashed differently; without it, alike with an empty cache and a filled one (2026-12-07). It was not timed.',
        # the W step compiled without its loop (2026-12-05, znver5): the A/B timings, the bench-envs runs, env_step_cost
        '### The W step compiled without its loop (issue 32 point 2, 2026-12-05)',
        'The rest of the kernel in the table above was mostly the W step itself. The study timed the step in '
        'a loop of its own, where numba linked with n = 1 and LLVM compiled the inlined step as straight-line'
        " code; the env's kernel calls through its address ( ), compiled on its own with the step inside its "
        "loop over n, and LLVM compiled that step worse. Timed on TetheredWing-v0's 512 copies, one step "
        'each, one thread (znver5, 2026-12-05): 10.3 us per step through , 6.8 us with linked and n = 1 a '
        'constant, 10.1 us linked with n a variable, 0.34 us for a call by address of a function that does '
        'nothing with the same arguments. is now a loop that calls , the step compiled on its own as '
        'straight-line code, through its address: 7.5 us per step, the same bits (the states of all 512 '
        "copies; SHA-256 of TetheredWing-v0's, Rotorcraft-v0's and LadderMill-v3's single and vector episodes"
        ' under seeded actions, before and after). The loop itself compiles in a fraction of a second; '
        "compiles what did, and the warm-ups name it instead ( ). RK4's loop showed no such effect "
        "(LadderChain-v0's four steps per period: 785 against 784 us).",
        ', the code before (a84603c, a worktree) and after alternated twice (2026-12-05 07:16-07:17, load '
        '1.2-1.3, znver5), steps/s:',
        '| env, copies | before | after | |---|---|---| | TetheredWing-v0, 64 | 136,989 / 144,346 | 185,820 /'
        ' 186,021 | | TetheredWing-v0, 512 | 178,154 / 179,376 | **252,359** / 246,330 | | Rotorcraft-v0, 64 '
        '| 73,605 / 70,605 | 73,956 / 71,576 | | Rotorcraft-v0, 512 | 81,910 / 79,339 | 82,497 / 81,800 |',
        "The whole quick run after (07:15, load about 1; README's figures): TetheredWing-v0 21,781 / 83,140 /"
        ' 192,337 / 249,499 steps/s at 1 / 8 / 64 / 512 copies, Rotorcraft-v0 15,866 / 37,896 / 74,368 at 1 /'
        ' 16 / 64. TetheredWing-v0 gains 1.39x; the craft, whose step is 20.5 us of heavier physics, and '
        'LadderMill-v3 (5,035 before, 5,255 after at 8 copies) gain nothing measurable. now times the step '
        "through as the kernel calls it (2026-12-05 07:14, one thread): TetheredWing-v0's vector step 7.79 us"
        ' per copy (W step 6.90, of which the assembly 0.66, three right-hand sides 2.70, the body Jacobian '
        '1.28, the cable Jacobian 0.50; observation 0.58; rest of the kernel 0.20; Python and numpy 0.11), '
        "Rotorcraft-v0's 24.17 us (W step 20.51; observation 3.08; rest 0.23; Python 0.36). 400,000 and "
        "150,000 steps/s on two threads need 5.00 and 13.33 us: **not met** (0.64 and 0.55 of today's). The "
        'conclusion above stands: fewer model evaluations per period and a cheaper right-hand side, a new '
        "id's work.",
        "Three of the stage's small parts, , and , each called three or four times per step with the model "
        "and workspace (some 500 values per call), are now inlined into the step (numba's ). (07:40-07:44, "
        'one run each): the W step 7.09 -> 6.30 us for the wing, 22.12 -> 20.32 us for the craft; inlining '
        "too made the craft's step 23.94-26.57 us, so it stays linked. Same bits (the hashes above). "
        'Alternated five times with the code before it (07:45-07:46, load 1.2-1.6, ): TetheredWing-v0 a '
        'median 245,752 against 231,802 steps/s (241,083-255,528 and 225,242-243,187), Rotorcraft-v0 77,812 '
        'against 75,178 (75,542-81,923 and 71,528-76,048): 6 % and 3.5 %. Cold starts alike ( , 07:48-07:50: '
        '16.8 and 13.7 s against 16.6 and 13.6 s).',
        # LadderMill-v3's three runs (lead, 2026-11-30 19:29 UTC, load 0.9-1.4; as printed; the first run's "cpu" 1.00)
        '3 runs (19:29 UTC, load 0.9-1.4): 2,003 (one core), 3,628, **3,593** (median);',
        # LadderChain-v1's section (2026-12-05, znver5): env_step_cost's parts and bench-envs, before (2db3288) / after
        'alternated twice ( ; 12:34-12:35 UTC, load 1.1-1.3, znver5): factorisation 15.73 / 15.72 -> 9.94 / 10.32 us, '
        'three right-hand sides 144.09 / 143.66 -> 123.73 / 123.59 us, the W step 369.20 / 371.32 -> 341.83 / 344.17 '
        'us.',
        'the code before and after alternated three times (12:32-12:34 UTC, load 1.1-1.3, znver5; , then ), steps/s:',
        '| LadderChain-v0, 8 | 2,236 / 2,167 / 2,398 | 2,581 / 2,595 / 2,705 | | LadderMill-v3, 8 | 5,601 / 5,042 / '
        '5,458 | 5,340 / 5,645 / 5,862 | | TetheredWing-v0, 512 | 249,262 / 259,640 / 246,284 | 278,118 / 200,573 / '
        '262,129 | | Rotorcraft-v0, 512 | 85,548 / 80,513 / 87,082 | 61,795 / 81,680 / 83,515 |',
        'The two low "after" figures came with a lower "cpu" (1.77 and 1.74 against 1.91-1.97); five more alternated '
        'runs of the single-craft envs (12:35-12:36, load 0.9-1.0) give Rotorcraft-v0 a median of 82,536 before and '
        '82,570 after, TetheredWing-v0 260,610 and 266,158.',
        '| LadderChain-v0 | 2,668 / 2,703 / 2,380 | 1,441 / 1,429 / 1,237 | 1,298 / 1,349 / 1,155 | | LadderChain-v1 | '
        '**3,343** / 3,375 / 3,049 | 1,878 / 1,865 / 1,606 | 1,649 / 1,703 / 1,483 |',
        '**Met on the chain** (median 3,343 steps/s,',
        'alternated twice (12:37-12:38 UTC, load 0.3-0.8): the right-hand side 46.52 / 46.91 -> 40.23 / 40.11 us, the '
        'RK4 step 185.98 / 186.40 -> 163.50 / 159.56 us; the tethered wing\'s right-hand side 1.85 / 1.75 -> 1.84 / '
        '1.74 us.',
    ),
    derived=(
        '(-2.0 %;',  # 111.19 / 113.44 - 1 = -1.98 %
        # LadderChain-v1's medians: 2,595 / 2,236 = 1.16; 3,343 / 2,668 = 1.25; RK4's estimated stable step at the
        # chain's equilibrium, the stable_steps group's ladder_chain rk4 (0.0246 s) in ms
        'The chain gains 16 % (medians)', '1.25x v0 in the same runs)', "at the chain's equilibrium, 24.6 ms:",
        # the single-craft thread-scaling model from the copy-step table's rows (env_step_cost prints it since):
        # 0.54 / 12.86 = 0.0420, 0.49 / 38.05 = 0.0129; 1 / (s + (1 - s) / 16) = 9.82, 13.41; 12x: s <= 1/45 = 2.2 %
        'their share of the step (0.54 / 12.86 = 4.2 % for the wing, 0.49 / 38.05 = 1.3 % for the rotorcraft) bounds '
        'the speed-up on 16 threads to 1 / (s + (1 - s) / 16): 9.8x and 13.4x (the study prints it; 12x needs s at '
        'most 2.2 %).',
    ),
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        # laddermill stable-step laddermill --after-transfer (2026-11-30): "after the first wing transfer, at t = 50.00
        # s: rk4: largest stable step 0.01224 s (set by the eigenvalue -30.47 +- 239.8i 1/s)" (were not_rerun)
        Printed('stable_step_mill_transfer', (
            '0.0122 s just after a transfer',
            "The bisection's in-plane disturbance later in the period misses the short first element's axial mode "
            "right after a transfer (-30 +- 240i 1/s), which the eigenvalue estimate finds (",
            "at the first transfer, t = 50 s, 0.01224 s); the scene's step")),
        Printed('fast_step_rewards', (  # the slow tests' printed figures; -2.0 % = 111.19 / 113.44 - 1
            "the mill's mean power 111.19 kW against 113.44", "largest reward error 0.177, RK4's 0.0065)",
            'a mean reward of 0.5185-0.5216 against 0.5458', '(0.0052, 113.44 kW)',
        )),
        Printed('chain_v1_figures', (  # LadderChain-v1's accuracy study and its slow reward test
            'is 0.4508 m, 0.000125 of the 3612.8 m extent (v0\'s RK4 0.188 m;', '1.158 m). What an agent is given,',
            'the largest reward error 0.0041 (v0\'s RK4 0.0016) and the mean reward 0.5458 as the reference\'s, where '
            'one ROS34PW2 step per period gives 0.5216.',
            'holds v1 for 120 s with a return of 2399.17, a largest lateral offset of 0.0803 m and 237.9 kW,',
        )),
        Printed('mill_benchmark', (
            '| largest stable RK4 dt (in-plane disturbance, against DP5; eigenvalue estimate) | 0.0177 s (error at '
            '0.01 s: 1.2 mm);',
        )),
        Printed('pointmass_accuracy', (
            'implicit against explicit over 0.2 s: 3.0e-3 m at dt 0.01 s, first order.',
        )),
        Printed('step_accuracy_10', (  # the accuracy table's extents and errors (its steps given, its CPU timings)
            'LadderChain-v0 (3612.8 m)', '| 0.188 m | 5.2e-5 |', '| 1.158 m | 3.2e-4 |', '| 1.628 m | 4.5e-4 |',
            'LadderMill-v2 (3477.4 m)', '| 3.2e-5 m | 9.1e-9 |', '| 2.4 mm | 7.0e-7 |', '| 1.9e-5 |',
        )),
        Printed('fast_step_accuracy_10', (  # the fastest step's table (labels and steps given)
            'LadderChain-v0 | 3.2e-4 (200) | 4.3e-4 (200) | 1.04e-3 (200) | 5.66e-4 (185) | 5.93e-4 (175) | 7.02e-4 '
            '(167) | 5.86e-4 (190) | 6.02e-4 (184)',
            'LadderMill-v2 | 7.01e-7 (200) | 1.93e-5 (200) | 5.59e-5 (200) | 8.44e-5 (200) | 9.14e-5 (19) | 8.56e-5 '
            '(20) | 3.78e-5 (200) | 2.7e-5 (7)',
        )),
        Printed('fast_step_accuracy_40', (
            "it ends the open-loop chain's whip after 244 periods against the reference's 245 (ROS34PW2 223), 15.35 m "
            '(4.25e-3 of the extent) off just before, and the mill after 320 against 321, 0.47 m off.',
        )),
        Printed('fast_step_closed_loop', (  # the LQRs' runs with ros2:4 against the registered step's
            "seed 0): both LQRs hold 300 s with",
            "lateral offset -6.69e-09 (relative) and -1.49e-08 m from RK4's, the mill's -9.16e-04 and -9.21e-06 m "
            '(102.701 kW against 102.795 kW).',  # 70e387a, 2026-12-02 (36fe05f printed -9.09e-04, -9.16e-06, 102.702)
        )),
        Printed('step_accuracy_40', (
            "the episode ends after 322 periods against the reference's 321", '(7.5e-6 of the extent) until then;',
            'ROS2 ends it after 317', "over 40 s they end the episode after 223 (ROS34PW2) and 221 (ROS2) periods "
            "against the reference's 245, 5.2-5.4 m (1.4e-3 and 1.5e-3 of the extent) off just before;",
        )),
    ),
)
