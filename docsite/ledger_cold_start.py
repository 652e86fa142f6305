"""The ledger entry (:mod:`docsite.page_ledger`) of docs/cold_start.md (moved out of docs/benchmarks.md on
2026-12-02): start-up timings throughout, each dated on the page (a date or the commits measured, with the load where
it was recorded), the targets given. LadderMill's sections moved to docs/cold_start_mill.md on 2026-12-03
(:mod:`docsite.ledger_cold_start_mill`)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered

COLD_START = Covered(
    given=(
        # the targets, in the page's opening paragraph
        "Issue 32 point 1's targets: TetheredWing-v0 and Rotorcraft-v0 at most 20 s cold and 1 s warm, "
        "LadderMill-v0 at most 60 s cold.",
        '## TetheredWing-v0 and Rotorcraft-v0: the step kernel compiled beside the trim (issue 32 point 1)',
        # the link to the later machines' page
        "The same code on other machines and days, from 2026-12-05 on:",
    ),
    timings=(  # each dated on the page (date or commit, machine, load where recorded)
        '( runs it for these two and LadderMill-v0): make + reset + one step in a fresh process, cold with a new '
        'empty , warm from the cache that run left (median of 3). This 2-core machine was shared with four other '
        'jobs (load average 4-6), so wall seconds are 2-3x the CPU seconds; compare the CPU seconds. On '
        '2026-11-29 before: c5200bb, after: 417ed18, run one after the other:',
        'cold, CPU [s] | 80.4 | 66.6 (-17 %) | 67.1 | 54.5 (-19 %) | | cold, wall [s] (load 4-6) | 203.4 | 165.1 '
        '| 139.1 | 140.1 | | functions numba compiles | 92 | 67 | 96 | 74 | | warm, CPU / wall [s] | 1.44 / 4.55 '
        '| 1.68 / 5.32 | 1.22 / 2.14 | 1.64 / 5.30',
        'After d5da070 (the craft observation inlined too) the same command for Rotorcraft-v0 alone printed cold '
        "102.4 s wall, 57.6 s CPU, 73 functions compiled, warm 1.63 s CPU (load 3.9): one cold start's CPU "
        'seconds move by about 10 % with the load, so compare the functions compiled (96 before). (load 4): cold '
        '146.3 s wall, 109.7 s CPU, 74 functions; warm 86.1 s wall, 47.6 s CPU: its operating point, computed in '
        'every process and cached nowhere, was most of it (now kept on disk: [cold start: '
        'LadderMill]).',
        "On 2026-11-30 the warm-ups compile the step kernel's callees ahead (the wing's in two processes, from both "
        'ends of the list: ). , caches empty, cfa815b and the final code alternated twice (load 1.3-1.6): '
        "TetheredWing-v0 39.7 / 38.0 -> 33.0 / 33.8 s wall (warm-ups' CPU 37.9 / 36.9 -> 39.0 / 39.1 s), "
        'Rotorcraft-v0 32.7 / 34.1 -> 29.0 / 28.9 s; warm 0.89-1.02 s. 20 s is still not met.',
        'The 20 s target is not met, and not reachable this way. One cold TetheredWing-v0 start '
        'profiled by CPU seconds of its own ( , at 47a8b53, 71.8 s CPU): the step-and-observe kernel 10.9 s, the '
        '3D assembly 7.6 s, 6.1 s, the W method 5.9 s, the in-plane right-hand side of the static start 4.1 s '
        '(plus its entry 2.0 s), then the Jacobian parts 1-3 s each. Fewer layers do not help (tried 2026-11-30, '
        'branch , not merged): inlined into the wing\'s and craft\'s step kernels kept the bits (reset + 200 random '
        'steps) but TetheredWing-v0 took 50.5 / 47.9 -> 54.1 / 50.5 s CPU and Rotorcraft-v0 40.8 -> 40.4 s (startup '
        'command, warm-up off, caches empty, alternated, load 2.5-3.2): re-linking a callee costs little, each '
        "function's own compile is the cost (the observation inlined cost 8.9 s against 2.6 s compiled alone). What "
        'would reach 20 s: kernels compiled ahead of time and shipped, or fewer and smaller compiled functions (a new '
        'env version if the last bits change).',
        "The warm start misses 1 s. In the table the after-run's warm starts ran under more load; right after, "
        "twice, from the same tree's cache: 1.30 / 1.23 s CPU (2.46 / 2.31 s wall) for TetheredWing-v0, 1.23 / "
        '1.32 s CPU (2.11 / 2.38 s wall) for Rotorcraft-v0, as before these changes. Most of it is importing the '
        'package: prints 0.84-0.89 s (scipy.interpolate for the aero splines and numba among it).',
        "(c27a42a, load 0.5-3): 60.8 s CPU, 69 functions; the step kernel's nest 45.9 s (own CPU: 10.3, 6.8, 5.4,"
        " its callees 23.2), the static start's in-plane right-hand side 11.1 s, the read-outs at the first step "
        '1.6 s. The same second process now serves every env ( , ): the wing and craft tasks start it first thing'
        " when their step kernels are neither compiled in the process nor in numba's on-disk cache (a warm start "
        "starts none); its targets ( ) build the same task around a stand-in trim of the real one's shapes, "
        'dtypes and flags and reset and step it, while the first process solves the real trim, then loads the '
        'kernels from the cache just before its first kernel call: the same machine code, the same bits ( , slow,'
        ' both ids, fresh processes, empty caches: with and without, a reset and 8 random steps equal bit for '
        'bit, nothing compiled in the process from the first kernel call on; 2 passed in 657 s). switches it off '
        'for every env. The startup command for both ids, both caches empty, on (21:02-21:11, load 10-14) then '
        'off (21:11-21:17, load 10-13), 0ea7506; the wall seconds (on / off: TetheredWing-v0 361.6 / 139.2 s, '
        'Rotorcraft-v0 146.2 / 149.0 s) are mostly waiting:',
        'CPU of the process (+ the second) [s] | 54.5 | **14.6** (+ 44.9) | 51.2 | **16.6** (+ 41.1) | | cold: '
        'functions compiled in the process | 69 | 33 | 77 | 46 | | warm: CPU / wall [s] (median of 3, nothing '
        'compiled) | 1.16 / 3.76 | 1.20 / 3.85 | 1.15 / 3.53 | 1.20 / 3.93',
        '**The second process helps the wall time only when a second core is free.** Later, on then off: quiet '
        '(21:29, load 0.8-2.1) on: TetheredWing-v0 **38.0 s wall** (CPU 11.5 + 36.2 s), Rotorcraft-v0 **47.9 s** '
        '(15.2 + 36.6 s); off, the load up to 2-3 by then: 78.1 s (55.0 s) and 59.1 s (47.1 s); with one core '
        'busy elsewhere (load 2.4-2.6) TetheredWing-v0 off 63.8 s (62.2 s), on 61.2 s (15.2 + 45.4 s): nothing '
        'gained. Warm 1.12-1.52 s CPU either way. **20 s is not met, nor reachable by splitting on two cores**: '
        "48-62 s of CPU is 24-31 s on two at best, and the step kernel's top three layers take 22.5 s in a row. "
        "(cold, no warm-up): 62.3 s CPU against 60.8 s, a 200-step rollout's bits changed: rejected.",
        # the scheduling of 2026-12-02 (await_callees): timelines, alternated runs and bench --startup after
        "## The trim's compile beside the step kernel's chain (2026-12-02)",
        "now also prints a timeline: when each process of the cold start compiled what (the first process's top-level"
        ' compiles and those of its kernel warm-up processes, ). At cfff897, one cold TetheredWing-v0 start on this '
        "2-core AMD EPYC (2026-12-02 13:30, load about 1): the two warm-ups compiled the step kernel's callees until "
        "21.3 and 21.4 s while the first process compiled its trim's in-plane kernels (until 20.9 s), three compiling"
        ' processes on two cores; then one warm-up compiled the step-and-observe kernel alone (21.5 to 37.5 s; its '
        'layers one after the other, each needs the one below) and the read-outs (to 38.9 s), the other core idle for'
        ' the last 17 s. So on fewer than three cores the first process now waits for both warm-ups to print that '
        "their callees are done before it solves its trim ( ): the callees get both cores, and the trim's compile "
        "runs beside the step kernel's chain. The timeline after: callees done at 13.1 s, the step kernel 13.1 to "
        "27.0 s, the trim's right-hand side 13.6 to 19.8 s beside it. (Reading the warm-up's lines also no longer "
        'misses one that arrives with another: reads the pipe itself instead of a buffered .)',
        ', caches empty, cfff897 and the new code alternated three times (2026-12-02 14:06-14:10, load 1.1-1.7): '
        "**33.2 / 29.8 / 29.8 -> 27.5 / 26.7 / 28.8 s** wall; the first process's CPU 10.8 / 9.6 / 9.2 -> 6.3 / 5.9 /"
        ' 6.7 s (23 -> 6 functions compiled in it: the wind and aerodynamics its trim shares with the 3D kernels now '
        "load from the cache), the warm-ups' 39.6 / 35.7 / 34.2 -> 38.4 / 37.1 / 39.7 s; warm 0.81-1.13 s either way."
        " The same kernels compile, elsewhere or later: the same bits (the slow , both ids, passed). Rotorcraft-v0's "
        "one warm-up waits for the trim's assembly instead (its trim compiles the 3D kernels the step shares) and is "
        'unchanged. right after (14:11-14:13, load 1.1-1.6): TetheredWing-v0 29.8 s cold, 0.95 s warm; Rotorcraft-v0 '
        '27.2 s, 1.16 s; LadderMill-v0 43.7 s, 1.11 s.',
        '**20 s is still not met.** The floor of this split is the callees on two cores (11.6 s) plus the step '
        "kernel's chain on one (14 s), about 27 s here. Inlining into the step kernel, tried again (2026-12-02): the "
        "same bits (400 random steps of the single env, and gusts-v1's NTM_IB, EOG_IA and ECD_IA under the LQR, "
        'hashed) and no gain (warm-up off, 62.8 s CPU against 60.9 s), as on 2026-11-30.',
        # the same code on the evening's slower AVX2 machine (bench --startup, --profile, two tries not kept)
        '## The same code on a slower machine (2026-12-02 evening)',
        "The evening's machine was another 2-core AMD EPYC, with AVX2 only (numpy's AVX2 loops, OpenBLAS's Haswell "
        'kernels: the znver3 profile) and about half as fast at compiling. at ba5f8e6 (18:27-18:31, load 1.2-1.5): '
        'TetheredWing-v0 64.8 s cold, 2.06 s warm; Rotorcraft-v0 62.0 s, 2.27 s; LadderMill-v0 89.0 s, 2.06 s, so the'
        " mill's 60 s and the 1 s warm start are not met there either. Its timeline ( , 17:43): the callees done at "
        "28-29 s, the step kernel's chain 29.2 to 52.0 s, the trim 30.3 to 40.4 s beside it, the read-outs to 54.3 s;"
        " with the warm-up off, 100.4 s (the chain's own compiles: 11.6 s, 9.5 s, 7.7 s). The warm start's 1.5 s "
        "inside the process is mostly imports: numba's checks for BLAS when it loads, which imports (0.28 s with what"
        ' it pulls in), numba itself 0.35 s, gymnasium 0.22 s ( ).',
        'Tried, not kept, both alternated with the code before (e6b027c) with the caches empty: the second warm-up '
        "compiling the observation's callee and then the read-outs (the actions' pass and clip, the reward's read-"
        'outs, from a task built around a stand-in step kernel) after its share of the callees, so that the chain '
        'starts earlier and its process ends with it: one pair (18:11-18:14) 59.1 -> 67.1 s; its timeline showed the '
        "chain starting at 28.3 s all the same (the second warm-up's right-hand side compiled the assembly's nested "
        "callees a second time beside the first's). The read-outs alone moved there: the step kernel's process then "
        'ends with the chain (60.5 s, nothing after), but three alternations (18:17-18:25) gave 59.8 / 69.0 / 61.8 s '
        "before and 67.2 / 61.1 / 66.3 s after: the 2 s it moves is within this machine's scatter (the chain's own "
        'compile took 23 to 30 s from run to run).',
        # the vector envs' prange kernel replaced by the single env's kernel on threads (2026-12-03)
        '## The vector envs: no second step kernel (2026-12-03)',
        'The native vector envs ( , what an RL run steps) used to run a kernel of their own from 32 copies on (2 for '
        "the 101-wing scenes): a numba loop around the same copy step as the single env's kernel. Compiling it cost "
        'more than everything else together. After a single TetheredWing-v0 had compiled its kernels in the same '
        "process (warm-up off, 2-core AVX2 EPYC, load about 1), the vector env's first reset and step at 64 copies "
        "took 165 s of CPU, 165.0 of them in that one kernel: numba's parallel lowering analyses the inlined step and"
        ' LLVM optimises and emits it five times over (the loop body, its gufunc, two wrappers, the kernel), 24,000 '
        "instructions each time. Rotorcraft-v0's took 216 s and PumpingKite-v0's 225 s (in a process that had made "
        'the single env first).',
        "Now the vector envs have no kernel of their own: they call the single env's (compiled ) on contiguous "
        "ranges of copies, as many as numba's thread count ( ; the kernel takes the range as its last two "
        "arguments). Until 2026-12-04 the ranges ran on a few Python threads (only the calling thread's range "
        "went through numba's dispatcher, which types the 21 arguments under the GIL in 12-18 us, the others "
        "called the compiled entry point it chose, 2-3 us); since then numba's pool runs them through a launcher "
        'beside each step kernel, a prange loop over the ranges that calls the kernel by its address ( ), and the '
        'Python threads only in a process forked after GNU OpenMP ([benchmarks] has the 16-core figures that led '
        'there). The launcher is all a threaded vector env compiles after the single env: 7.0 s for '
        "TetheredWing-v0's and 6.9 s for Rotorcraft-v0's on this 2-core AVX-512 machine (2026-12-04, empty "
        'cache), LLVM working through the some 500 values the kernel takes, then loaded from the cache ( counts '
        "numba's compiles). Every copy is the single env's arithmetic: the threaded vector env equals single envs "
        "bit for bit on either way ( , , ; the former prange kernel's last bits depended on what the process had "
        'compiled before, and those tests allowed 1e-6). TetheredWing-v0, Rotorcraft-v0 and PumpingKite-v0 give '
        'the same hashes of 400 steps of the single env and 50 of a 64-copy vector env as before.',
        "The warm-ups first missed the launcher: they find the step kernel's arguments by a stand-in for it, "
        "which the launcher bypassed, so they listed no callees, and the vector env's first step compiled the W "
        "method's loop itself. , caches empty, on this 2-core AVX-512 machine (2026-12-04, one run each): "
        'TetheredWing-v0 60.5 s with the launcher and that miss (33.0 s of CPU in the first process), 33.8 s once '
        'the stand-in covers the launcher too (6.6 s; ), Rotorcraft-v0 32.2 s and 24.3 s; warm 0.91 s and 0.90 s.',
        '(new: times of N copies), caches empty, on the 2-core AVX2 EPYC (load 1-2), the new code then 0a1ac39 (warm-'
        "up on, its default): TetheredWing-v0 2026-12-03 08:26-08:34, Rotorcraft-v0 08:50-08:58 (at d7ed9e0's parent:"
        ' the same kernels):',
        '| make_vec (64 copies) + reset + one step | TetheredWing-v0 0a1ac39 (prange) | now | Rotorcraft-v0 0a1ac39 |'
        ' now | |---|---|---|---|---| | cold: wall [s] | 221.9 | **45.5** | 219.8 | **43.3** | | cold: CPU of the '
        'process + its warm-ups [s] | 12.2 + 242.7 | 10.5 + 65.1 | 18.9 + 199.7 | 17.8 + 40.5 | | warm: wall [s] | '
        '1.80 | 1.63 | 1.73 | 1.45 |',
        "The threads cost nothing in throughput. TetheredWing-v0's native vector env at 512 copies, zero actions, 40 "
        "steps after 5, on 1 and 2 numba threads three times per process, the two codes' processes alternated three "
        'times (08:34-08:45, load 1-2; a script, not a package command): 0a1ac39 median 79,778 steps/s on one thread '
        "and 147,655 on two, now 81,113 and 152,395. So the 20 s target for is as before, but an RL run's first "
        "vector step no longer waits minutes more than a single env's: 45.5 s and 43.3 s here against 221.9 s and "
        '219.8 s.',
        # kernels without a CPython wrapper (callee_jit), the chain's linking cost (2026-12-03 afternoon)
        '## Kernels compiled without a CPython wrapper (2026-12-03, afternoon)',
        'numba compiles every function with a CPython wrapper, the code that unboxes each argument from a Python '
        'object so that Python can call it. For the rigid-body kernels, whose model and workspace arguments are '
        'namedtuples of some 50 arrays, that wrapper is a large function, and LLVM optimised and emitted it with '
        "every kernel although only compiled code calls most of them. numba's own timings ( , each compile result's )"
        ' over a cold TetheredWing-v0 make + reset + one step in one process (warm-up off, caches empty; a /tmp '
        "script, not a package command): the wrappers' function passes took 6.8 s of 76.1 s of CPU (12:44, load about"
        " 0.5; 's 0.54 s against 0.61 s for its own), 7.2 s and 5.8 s of 77.0 s and 67.4 s in two more (12:50-12:55, "
        'load 0.5-1.0). Now compiles 15 kernels that only compiled code calls (the 3D assembly and right-hand side, '
        "the bodies' loads and load Jacobian, the cable's stiffness and its parts, the W step's stage increment and "
        "mass product, the post-step check, the craft's loads and air) with numba's ; a call from Python (a test, a "
        "timing study) goes through a small jitted entry built on the first such call. The kernels' and their "
        "callers' machine code is what gave: TetheredWing-v0 (reset and 200 random steps; 40 copies, 20 steps), "
        'Rotorcraft-v0 (100; 40 copies, 20), LadderChain-v0 (20), LadderMill-v0 (20) and LadderMill-v3 (10) hash to '
        'the same SHA-256 as at 1473b0f, each in a fresh process with empty caches. checks the missing wrapper '
        'against a plain of the same function, and the results from compiled code and from Python against the Python '
        'function.',
        "The same one-process runs after, alternated with those: 63.5 s and 62.0 s of CPU, the wrappers' passes 1.6 s"
        ' (those of the kernels Python calls). , caches empty, the new code and 1473b0f alternated twice '
        '(13:16-13:23, load 0.9-1.5):',
        '| make + reset + one step | TetheredWing-v0 new | 1473b0f | Rotorcraft-v0 new | 1473b0f | '
        '|---|---|---|---|---| | cold: wall [s] | 45.2 / 51.7 | 50.6 / 44.7 | **41.7 / 44.9** | 55.3 / 56.9 | | cold:'
        ' CPU of the process + its warm-ups [s] | 10.1 + 60.4 / 12.6 + 71.9 | 11.1 + 72.0 / 10.5 + 63.5 | 17.6 + 39.8'
        ' / 18.7 + 43.0 | 20.6 + 53.3 / 23.3 + 54.9 | | warm: wall [s] (median of 3) | 1.73 / 1.63 | 1.55 / 1.81 | '
        '1.69 / 1.87 | 1.99 / 2.02 |',
        "Rotorcraft-v0 gains about 12 s (its one warm-up compiles the callees one after the other). TetheredWing-v0's"
        " wall time moved within this machine's scatter: its two warm-ups share the callees, and its end is set by "
        "the step kernel's chain. In its timelines ( , 13:24-13:27, alternated twice) the chain started at 20.4 / "
        '23.3 s against 24.1 / 24.5 s and took 25.8 / 25.5 s against 28.3 / 22.6 s. LadderMill-v0 (13:28-13:34, '
        'alternated twice): 75.6 / 74.7 s against 77.4 / 72.2 s; its path is the in-plane compiles and the periodic '
        "search, which this does not touch. This machine compiled more slowly than in the morning: the mill's cold "
        'start at 1473b0f took 72.2-77.4 s here against 56.0-62.7 s then.',
        'Seven more kernels then (7cf0472), for the mill: in a cold LadderMill-v0 in one process (132.5 s of CPU) the'
        " wrappers' function passes took 8.0 s, among them the in-plane right-hand side 's (0.62 and 0.83 s, two "
        "signatures) and the moving cable's ( 0.70 s, 0.52 s); these, the in-plane check, the moving cable's checks "
        'and its in-plane transfer are now compiled without one (the same hashes: TetheredWing-v0, LadderChain-v0, '
        'LadderMill-v0, -v1 and -v3 against the kernels before). LadderMill-v0 cold, alternated twice with the code '
        "before (14:10-14:16, load 0.8-1.5): 72.4 / 72.2 s against 72.5 / 72.5 s, the warm-up's CPU 52.4 / 49.9 s "
        "against 55.1 / 52.3 s: its wall time does not move (the first process, its operating point's in-plane "
        'compiles and search, sets it).',
        'after the first fifteen (13:34-13:38, load 0.8 at its start): TetheredWing-v0 48.5 s cold, 2.07 s warm; '
        'Rotorcraft-v0 47.1 s, 1.96 s; LadderMill-v0 73.1 s, 1.56 s.',
        "**What the chain costs is linking.** numba links each callee's optimised module into its caller's and runs "
        "LLVM's module passes and code generation over the whole again ( ). With every callee cached, a jitted "
        'function whose one statement calls compiled in 3.23 s (module passes 2.24 s, code generation 1.31 s), more '
        "than itself then (2.62 s). In the 76.1 s one-process run above the chain's three layers spent 5.71 + 3.50 s "
        '( ), 3.21 + 1.76 s ( ) and 2.74 + 1.53 s ( ) in module passes and code generation, against 1.55, 0.60 and '
        '1.87 s in their own function passes. This corrects the reading of 2026-11-30 above ("re-linking a callee '
        'costs little"), which came from inlining . The lever left is a call that does not link (numba\'s first-class '
        "functions link the callee too): an intrinsic on numba's calling the callee's compiled address; a one-call "
        'function calling so compiled in 0.88 s against 2.98 s linked, with the same derivative bits (13:50, a /tmp '
        'script; every callee cached). Done the same evening: next section.',
        '## Kernels called through their addresses (2026-12-03, evening)',
        "is that call: the call site's pointer cell is filled on the first call by a C callback that compiles for the"
        " call's types (or loads it from numba's cache); the caller caches as before ( : results as linked, a fresh "
        'process, exceptions, a wrong return type, six threads at once).',
        "Tried first: all under the step kernels by address (the W step's parts, the 3D kind's assembly, right-hand "
        'side and check, the integrator, the fixed-step driver): cold TetheredWing-v0 49.9 / 47.7 s against 71.2 / '
        '67.9 s, Rotorcraft-v0 51.7 / 48.0 s against 66.8 / 68.8 s (startup command, alternated, 17:13-17:22, load '
        '1.3-1.6). But the driver by address changed 3 of 800 rewards of a 40-copy TetheredWing-v0 by 7e-15 to 1e-10 '
        '(cause not found), and a call by address passes every field of the model and workspace (some 500 values; '
        "LLVM drops a linked callee's unused ones): the W step's 23 calls per step so made gave 60,532 / 64,054 "
        'steps/s against 72,745 at 512 TetheredWing-v0 copies, 24,564 / 26,906 against 28,212 for Rotorcraft-v0 ( , '
        '17:26-17:29, load 1.2-1.6). So only rare calls go by address now: the integrator under the driver, the '
        "observation's element loop. Same bits against c763a66 (fresh processes, empty caches): TetheredWing-v0 (200 "
        'steps; 40 copies, 20), Rotorcraft-v0 (100; 40 copies, 20), LadderChain-v0 (20), LadderMill-v0 (20), -v3 '
        '(10). The same bench-envs, 17:53-17:57, one run each: TetheredWing-v0 44,607 / 74,188 steps/s at 64 / 512 '
        'copies against 47,393 / 73,858, Rotorcraft-v0 19,736 / 26,999 against 19,868 / 28,361.',
        '| make + reset + one step, 17:43-17:53 (load 1.4-2.0), alternated twice | new (9976157) | c763a66 | '
        '|---|---|---| | TetheredWing-v0 cold / warm [s] | **61.6 / 61.8** / 2.91 / 2.99 | 71.9 / 68.7 / 2.70 / 2.52 '
        '| | Rotorcraft-v0 cold / warm [s] | **59.6 / 59.5** / 2.93 / 2.94 | 65.2 / 64.9 / 2.86 / 2.90 |',
        'About 9 s and 6 s less cold (a slow hour: c763a66 took 48 s at 13:34), less than the first try: the W '
        "method's loop links its parts again. The wing's warm start is about 0.3 s longer (two more cache entries to "
        'load).',
        # one compile of the W method's loop (2026-12-03, night): timelines, alternated runs, the warm start's exit
        "## One compile of the W method's loop, beside the step kernel (2026-12-03, night)",
        "This session's machine was the 2-core AMD EPYC with AVX-512 ( : znver4). Its timelines (19:15-19:25,"
        " load about 0.5) showed the W method's loop ( , which links the W step's parts) compiled twice in a "
        'TetheredWing-v0 cold start, by both warm-ups at the same time (15.1 to 20.5 s, some 5.3 s of CPU '
        "each, since both lists ended with it), and Rotorcraft-v0's one warm-up compiling the loop and then "
        'the step kernel one after the other (14.6 to 21.0 and 21.1 to 27.6 s) while the first process, its '
        "trim done at 13.0 s, waited. Now one process compiles the loop, beside the step kernel: the wing's "
        "tail warm-up after it prints its line (so the trim no longer waits for the loop either), the craft's"
        " first process after its trim and its warm-up's line, with the bodies' load Jacobian, which only the"
        " loop links ( , the loop's call built from the batch's own arrays). The warm-ups compile the read-"
        'outs with a step that selects no copy, so no physics step runs there and only the process that '
        "compiles the loop asks for it. The slow counts the loop's compiles over every process of a cold "
        "start (numba's compile events in each, ): one, in the named process (two for the wing before); with "
        'and without the warm-ups, a reset and 8 random steps are the same bits (15 passed).',
        '| make + reset + one step, 20:02-20:09 (load 1.5-1.9), alternated three times | new (c01562c) | '
        '07285c3 | |---|---|---| | TetheredWing-v0 cold [s] | **22.6 / 24.6 / 24.6** | 30.9 / 25.2 / 30.4 | |'
        ' TetheredWing-v0 cold: CPU of the process + its warm-ups [s] | 7.0 + 36.2 / 7.2 + 39.8 / 7.7 + 39.1 '
        '| 9.2 + 49.4 / 6.5 + 41.8 / 7.6 + 51.0 | | Rotorcraft-v0 cold [s] | **19.5 / 20.0 / 20.1** | 26.4 / '
        '24.0 / 27.3 | | Rotorcraft-v0 cold: CPU of the process + its warm-up [s] | 18.9 + 18.0 / 19.3 + 18.1'
        ' / 19.3 + 18.5 | 11.9 + 25.1 / 11.2 + 22.8 / 13.0 + 25.8 | | warm [s] (median of 3): '
        'TetheredWing-v0, Rotorcraft-v0 | 1.04-1.32, 1.21-1.25 | 1.15-1.50, 1.11-1.46 |',
        'Timelines after ( , 20:09, load about 1.5): Rotorcraft-v0 22.3 s, the trim 1.1 to 13.1 s and the '
        'loop 13.2 to 21.4 s in the first process, the step kernel 12.8 to 18.4 s and the read-outs to 19.8 s'
        " in the warm-up; TetheredWing-v0 29.0 s, both warm-ups' lines at about 17.5 s, then the trim (18.7 "
        "to 28.4 s) beside the tail's loop (17.2 to 25.5 s) and the other's step kernel and read-outs (17.7 "
        "to 26.2 s). **Rotorcraft-v0's 20 s is met in one of these three runs** (19.5 s; 20.0 and 20.1 s in "
        'the others): each of its two processes now compiles about 18-19 s of CPU, one after the other on its'
        " own core, so little is left to move. **TetheredWing-v0's is not**: its processes compile 43-47 s of"
        " CPU (the trim's in-plane kernels, which the craft's trim does not need, and the observation's own "
        "assembly among it), at least 22 s on two cores. The warm start's time inside the process was 0.8-1.0"
        " s; most of the rest is the interpreter's exit: the same make + reset + step in a script (warm "
        'caches, 20:10, three runs each) took 1.07-1.61 s from the outside when it ended normally and '
        '0.97-1.25 s when it ended with , 0.03-0.04 s more than its own clock.',
        'after (20:10, load about 1.5): TetheredWing-v0 29.3 s cold, 1.35 s warm; Rotorcraft-v0 19.9 s, 1.23 '
        "s; LadderMill-v0 48.9 s, 0.99 s ([cold start: LadderMill]). The wing's cold starts of the night ran "
        'from 22.6 to 29.3 s.',
        'The two wing warm-ups still met at the 3D right-hand side and compiled it side by side (13.6 to 17.1'
        ' s and 15.8 to 17.6 s in the 20:09 timeline). Now each compile of their lists holds a file lock '
        "named for the function and its types beside numba's cache, and a callee whose lock the other process"
        ' holds is left to it ( ; : a held lock leaves the dispatcher without the signature, where the '
        "unshared call compiles it). The timeline after ( , 20:15): the wing's warm-up went on to the step "
        'kernel at 13.0 s while the tail compiled (10.8 to 14.6 s); 24.5 s. Alternated with 9f7e804, '
        'TetheredWing-v0 only (20:15-20:19, load 1.4-2.1): 26.0 / 23.4 / 27.2 s against 24.6 / 31.5 / 29.4 s,'
        " one code's CPU moving by 13 s from run to run: within the hour's scatter.",
        # the launch-to-step clock and the trims' right-hand side by address (2026-12-04)
        "## Launch to first step; the trims' right-hand side by address (2026-12-04) now times each start from the "
        "process's launch to its first step done (the wall clock the child reads after its step against the one read "
        "before its launch): what the targets judge. Beside it it prints the whole process's seconds, which also hold"
        " the interpreter's exit (in a warm start about a quarter of a second of CPython collecting the objects "
        "numba's typing registries made; not the user's wait, so not counted against the target), and the "
        'imports-to-step seconds the child counted itself.',
        'What Python calls for a derivative ( : the static equilibria and trims, the reports) went through , which '
        "links the kind's right-hand side: a cold TetheredWing-v0's trim compiled its in-plane right-hand side on its"
        ' own and again linked into that entry. Now reaches and through their addresses ( ; each rigid kind registers'
        ' its entry with , a kind that does not, the winch, is linked as before). checks the derivative and tensions '
        "bit for bit against the linked entry's, and that the entry's compiled library links neither right-hand side."
        ' A call from Python costs the same (warm caches, median of three minima of 2,000 calls: 8.49 against 8.54 us'
        ' in 3D, 8.26 against 8.18 us in the plane). , caches empty, the new code and 18a9c9e alternated five times '
        "(16:26-16:33, load 0.4-1.8; at 16:25 showed the entry's compile at 0.71 s of CPU):",
        '| TetheredWing-v0, make + reset + one step | new (a92dead) | 18a9c9e | |---|---|---| | cold, launch to first'
        ' step [s] | 25.0 / 23.8 / 24.2 / 22.2 / 21.3 (median 23.8) | 24.7 / 21.0 / 25.0 / 25.2 / 21.5 (median 24.7) '
        '| | cold: CPU of the first process [s] | 5.3 / 5.8 / 6.7 / 5.9 / 5.4 (median 5.8) | 7.8 / 6.9 / 7.0 / 7.3 / '
        '7.2 (median 7.2) | | cold: CPU of its warm-ups [s] | 41.9 / 40.1 / 39.8 / 37.4 / 35.7 | 39.5 / 34.2 / 41.7 /'
        ' 41.0 / 34.7 | | warm, launch to first step [s] (median of 3) | 1.42 / 0.93 / 0.95 / 1.10 / 0.81 | 0.97 / '
        '0.84 / 0.82 / 0.91 / 0.87 |',
        "The first process compiles about 1.4 s of CPU less; the wall time moves within the warm-ups' scatter (their "
        'CPU varies by 6 s from run to run of the same code). Rotorcraft-v0, whose trim calls the 3D entry, '
        'alternated twice on 2026-12-04 08:27-08:33 (load 0-1.2): cold 16.9 / 16.4 s against 17.6 / 18.2 s, warm 1.01'
        ' / 0.92 s against 0.85 / 1.00 s. Same bits: a reset (seed 0) and seeded random actions, the observations and'
        ' rewards hashed with SHA-256, each in a fresh process with empty caches, equal for the new code and 18a9c9e '
        '(16:34-16:38): TetheredWing-v0 200 steps, Rotorcraft-v0 100, LadderChain-v0 20, LadderMill-v0 17 (its '
        'episode ends there), PumpingKite-v1 50.',
        '(16:23-16:25, load 0.5-1.5): TetheredWing-v0 25.9 s cold, 1.31 s warm; Rotorcraft-v0 18.1 s, 0.97 s; '
        'LadderMill-v0 45.4 s, 0.97 s. **Rotorcraft-v0 now meets 20 s and 1 s** on this machine; the mill meets its '
        "60 s. **TetheredWing-v0 does not**: its timeline (16:25, 24.6 s) ends with the tail warm-up's W method loop "
        "(15.4 to 23.4 s) and the first process's trim (16.5 to 23.5 s: 5.8 s of wall on a core it shares with two "
        'others) together, and the three processes compile 47 s of CPU, 23.5 s on two cores at best. Of that the '
        "observation's own assembly ( for the vehicle of no loads, 3.4 s) and the trim's in-plane right-hand side "
        "(4.0 s) are what the craft does not compile; both are the registered env's arithmetic (the observation's "
        "tensions and the static start), so cutting them changes its bits: a new env version's choice, not made here.",
        '(new) takes N cold starts, each from empty caches, and prints their median and range: (17:49-17:52, load '
        '1.3-1.7) printed TetheredWing-v0 22.4 s cold (22.3-22.4 s), 0.94 s warm; Rotorcraft-v0 17.7 s (15.9-21.7 '
        's), 1.23 s warm.',
    ),
)
