"""The ledger entry (:mod:`docsite.page_ledger`) of docs/controllers.md: TetheredWing-v0's open-loop and LQR rows and
prose and the chain's controllers against their commands (:mod:`docsite.controllers_figures`), the wing's modes
against ``lateral_study``, the rotorcraft's against ``craft_stability`` and its trim power against
``rotorcraft_evaluate``; the mills' 300 s evaluations, period checks and the shipped policies' studies as Printed
entries of long groups (:mod:`docsite.long_figures`); the PPO runs (not kept) as dated History records
(:mod:`docsite.ledger_controllers_history`)."""

from __future__ import annotations

from docsite.host_cpu import CPU
from docsite.ledger_controllers_history import CONTROLLERS_HISTORY
from docsite.ledger_kinds import Covered, Printed

LS = "{lateral_study[eigenvalues][%d][%d]}"
W, C, CS = "~{wing_controllers[%s]}", "~{chain_controllers[%s]}", "~{craft_stability[%s]}"

CONTROLLERS = Covered(
    groups=('wing_controllers', 'chain_controllers', 'mill_v1_controllers', 'lateral_study', 'craft_stability',
            'rotorcraft_evaluate', 'simulate_laddermill'),
    checks=((r"open-loop lateral modes ([\d.]+) \+- ([\d.]+)j 1/s", ("~" + LS % (3, 0), "~" + LS % (3, 1))),
            (r"a slow real mode at ([\d.]+) 1/s", ("~" + LS % (5, 0),)),
            (r"wide swings \(([\d.]+) m to the side\)", (W % "open_loop][dy",)),
            (r"until it reaches the ground at ([\d.]+) s", (W % "open_loop][length",)),
            (r"closed-loop max \|z\| = ([\d.]+) at the (0\.05) s control period", (W % "z", "0.05")),
            (r"holds the wing within ([\d.]+) m for the whole (\d+) s", (W % "lqr][dy", W % "lqr][length")),
            (r"\| open loop \| (\d+) \| ([\d.]+) s \(([a-z ]+)\) \| ([\d.]+) m \| (\d+) W \|",
             (W % "open_loop][return", W % "open_loop][length", "{wing_controllers[open_loop][failures]}",
              W % "open_loop][dy", W % "open_loop][power")),
            (r"\| LQR \| (\d+) \| (\d+) s \| ([\d.]+) m \| (\d+) W \|",
             tuple(W % f"lqr][{k}" for k in ("return", "length", "dy", "power"))),
            (r"the full lateral model \((\d+) states\) has a real mode at \+([\d.]+) 1/s",
             ("{chain_controllers[states]}", C % "real_part")),
            (r"Open loop the chain leaves the aerodynamic model's range at ([\d.]+) s", (C % "open_loop][length",)),
            (r"on the full linear model the loop has max \|z\| = ([\d.]+), and in the simulation it fails at "
             r"([\d.]+) s",
             (C % "decentral_z", C % "lqr][length")),
            (r"closed loop max \|z\| = ([\d.]+)\) holds every wing within ([\d.]+) m for the (\d+) s",
             (C % "central_z", C % "central][dy", C % "central][length")),
            (r"The trimmed craft makes ([\d.]+) kW\.", ("{rotorcraft_evaluate[lqr][power_kW]}",)),
            # LadderMill-v0's start: the periodic motion simulate --start periodic finds (66.1 kW; was not_rerun)
            (r"from the periodic operating point, (\d+) kW;", ("~{simulate_laddermill[periodic_kW]}",)),
            (r"grows at ([\d.]+) 1/s, a period", (CS % "scan][v10][growth",)),
            (r"critical wind speed of ([\d.]+) m/s", (CS % "critical",)),
            # worked from craft_stability's printed lines (until 2026-11-30 derived entries): 2 pi / the 10 m/s
            # mode's frequency; the largest relative error's next whole percent; the failure after the 1 s step
            (r"grows at [\d.]+ 1/s, a period of ([\d.]+) s\.", (CS % "period_v10",)),
            (r"restricted Jacobian to (\d+) %\.", ("{craft_stability[rel_error_bound]}",)),
            (r"\((\d+) s after the step\) after the 0\.1 rad step", (CS % "open_01][after_step",)),
            (r"holds the craft within ([\d.]+) m for 120 s \(0\.1 rad step: ([\d.]+) m\), using at most ([\d.]+) deg",
             (CS % "lqr_001][y", CS % "lqr_01][y", CS % "lqr_01][dtheta")),  # the larger step's differential
            (r"The open loop crashes at ([\d.]+) s after the 0\.01 rad step and at ([\d.]+) s",
             (CS % "open_001][fail", CS % "open_01][fail")),
            (r"\| open loop \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([a-z ]+) \|",
             tuple(f"{{mill_v1_controllers[open_loop][{k}]}}"
                   for k in ("return", "length", "dy", "power", "failures"))),
            (r"\| LQR \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| - \|",
             tuple(f"{{mill_v1_controllers[lqr][{k}]}}" for k in ("return", "length", "dy", "power"))),
            # the shipped policies' gusts-v1 scorecards, exact (long groups gusts_v1_<env>: gust_bench.json's summary)
            (r"Rotorcraft-v0 (\d+ / \d+) \(the LQR (\d+ / \d+), open loop (\d+ / \d+)\),",
             tuple(f"{{gusts_v1_rotorcraft[scorecard][{c}]}}" for c in ("ppo_rotorcraft", "lqr", "open_loop"))),
            # the LQR's count, quoted per CPU (docsite/host_cpu.py): the figure of the CPU the group ran on
            (rf"TetheredWing-v0 (\d+ / \d+) \(the LQR [^;]*?(\d+ / \d+) on {CPU} \([^)]*\)[^;]*; open loop "
             r"(\d+ / \d+)\)\.",
             tuple(f"{{gusts_v1_tethered_wing[scorecard][{c}]}}" for c in ("ppo_tethered_wing", "lqr", "open_loop")))),
    given=(
        "past the rotor's 13 deg incidence limit,",  # configs/rotors/roberts_rotor.yaml (Roberts sec. 4)
        'on **TetheredWing-v1** (two RK4 steps of 25 ms)',  # the id's registered step
        # the profiles' names and the days each was this project's machine (docsite/host_cpu.py)
        "znver4 names numpy's AVX-512 loops with OpenBLAS's SkylakeX kernels (the AMD EPYC of 2026-11-30 and "
        "2026-12-02 before 07:00), znver3 AVX2 loops with Haswell kernels (the AMD EPYC with AVX2 of 2026-12-01); "
        "one AVX-512 machine computes either (2026-12-02).",
        "All numbers below come from (the commands are in the Makefile), on this project's 2-core machine. The "
        'return is the sum of the per-step rewards of the registered environment (about 1 per step at the trim '
        'power with no penalty; 6000 steps in 300 s).',
        "The paper's 0.01 rad wind-direction step at 1 s, 300 s. The wing on its 100 m tether",
        # the former row as it read, before the ROS34PW2 step
        "(the open-loop row changed with the env's ROS34PW2 step: it read 1224, 54.6 s, integration breakdown, "
        '32.9 m, 5506 W with RK4 at 50 ms)',
        '101 wings, 0.01 rad direction step, 120 s.',
        "Roberts' flying model, 10 m/s.",
        '(6) is derived',
        'An LQR on eq. (6)',
        "After the paper's 0.01 rad direction step",
        'after the 0.1 rad step',
        '(6)',
        '101 wings on the moving cable, 300 s (from the periodic operating point,',
        'Return, how long it flew (300 s = held) and the largest lateral offset of any slot; mean electrical power in'
        ' brackets:',
        'disturbance | open loop | LQR (centralised, 606 states) |',
        "direction step 0.01 rad (the paper's) |",
        'direction step -0.05 rad |',
        'direction step +0.1 rad |',
        '1-cosine gust, +30 % speed and 0.05 rad over 10 s |',
        'It is one gain on the lateral states of all 101 slots, linearised just after a transfer; checks it at 8 '
        "phases of the 35 s period and by the period's transition matrix with the transfer's own Jacobian",
        '; the reasoning is in [docs/moving_cable.md], "Lateral control").',
        "The v1 config ( ) keeps v0's weights and designs on the mean of the 8 phases' lateral models ( );",
        # the shipped folders' sizes (laddermill_gym/policies/: ppo_rotorcraft 117 kB .. ppo_mill_v3 647 kB)
        'Five trained policies come with the package ( , 100-650 kB each, with the command and seed that reproduce '
        "them in the folder's README), each flown by on the id it was trained on: on , on , on , on , on ; and the "
        "same names in and . The single-craft policies are PPO's linear"
        " actor started at the LQR's gains ( in / : the LQR controller's affine map, ), then trained under drawn "
        "disturbances of the gust suite's kinds (not its scenarios). On gusts-v1 ( , a scenario counted when every "
        'seed survives):',
        '(the LQR clips its action to [-1, 1],',
        'On 200 held-out NTM-IB fields (seeds 5000 to 5199, used by no selection; )',
        '**The mill and the chain.** and are shared per-wing policies (one set of weights for all 101 slots or wings,'
        ' each seeing its wing and 4 neighbours each side, per-slot gains; / : DAgger from the centralised LQR, then '
        "PPO). Each holds its env 300 s after the paper's step with the LQR's power (",
        'and the centralised one holds).',
    ),
    timings=(
        '(re-running them means training again, 25 min)',
    ),
    derived=(
        # the held-out survival rates 70 / 200 and 132 / 200 of the after-squash SAC's History record, cubed
        'At those rates (0.35 and 0.66 per field) the LQR holds three drawn fields with probability 0.35^3 = 0.04 and '
        'this policy with 0.29:',
        # tanh(atanh(a) + 0.2) - a at a = 0 and 0.9 (the residual SAC's bound before the squash; closed form)
        "the action can move by tanh(0.2) = 0.197 where the LQR acts 0, by 0.032 where it acts 0.9 and by nothing",
        # 2 pi / 0.268 and ln 2 / 0.111
        'a 23 s oscillation doubling every 6.2 s',
        # mill_v1_transfer_phase prints |z| at the 8 phases 0.0-0.875 (0.9984 at the transfer's 0.0, 1.0757 to 1.115
        # at the others): 8 - 1 (until 2026-12-01 matched only by a number of pytest's header)
        '7 other phases,',
        # the v1 mill's 2 m/s power, checked on docs/paper_meijaard1999.md
        "**LadderMill-v1** (the v1 wing, 152.9 kW at 2 m/s; actions at by default): (the paper's 0.01 rad step at"
        ' 1 s):',
    ),
    printed=(  # page and long groups (docsite/long_figures.py)
        Printed('mill_v0_paper_step', ('151, 8.7 s, 35.6 m (75.5 kW) | **6091, 300 s, 0.08 m** (67.2 kW) |',)),
        Printed('mill_v0_step_minus_0.05', ('109, 6.9 s, 36.7 m (72.7 kW) | **6046, 300 s, 0.40 m** (67.1 kW) |',)),
        Printed('mill_v0_step_0.1', ('93, 6.1 s, 34.0 m (70.6 kW) | **5907, 300 s, 0.80 m** (66.8 kW) |',)),
        Printed('mill_v0_gust', ('360, 12.6 s, 31.8 m (105.1 kW) | **6211, 300 s, 0.46 m** (68.5 kW) |',)),
        Printed('lqr_laddermill', ('(spectral radius 0.099;',)),
        # tests/test_laddermill_v1.py -k lqr_holds: "lqr: clipped fraction 0 (0 of 1818000 action entries)" over its
        # 300 s after the paper step (--long mill_v1_lqr, 421 s, 2026-12-01; until then not_rerun)
        Printed('mill_v1_lqr', ("No LQR command reaches the v1 authority's bound (clipped fraction 0).",)),
        # tests/test_laddermill_v1.py -k transfer_phase_design: the v1 config with design_model transfer_phase (the
        # config's own comment names the copy), "frozen |z| [0.9984, 1.115, ...]; the period's transition matrix
        # radius 4.5e+20" and "end 24.85 s t = 24.85 s: slot 49 alpha = 13.0 deg, beta = -63.9 deg" (2026-12-01;
        # until then not_rerun, the page's "about 4e20" then)
        Printed('mill_v1_transfer_phase', (
            "v0's design, the gain on the lateral model just after a transfer, does not hold this mill: it is stable "
            "at that phase only (frozen closed loop |z| up to 1.115 at the",
            "other phases, the period's transition "
            'matrix radius about 4.5e20: of the v1 config with ), and its episode (LadderMill-v0 given ) ended at t = '
            '24.85 s, slot 49 at beta -63.9 deg.',)),
        Printed('lqr_laddermill_v1', ('prints |z| at most 0.99909 at phases 0.125-0.875, 1.02093 just after the '
                                    "transfer, and the period's transition matrix radius 0.1667 with the transfer "
                                    '(0.3293 without).',)),
        # re-run 2026-12-01 on this AMD EPYC (AVX2): the hand-over at 22.5 s now survives (44.80 s on 2026-11-30's
        # AVX-512 CPU), the held-out counts 72 / 82 (70 / 84 there): History records below
        Printed('switch_ntm_ib_0', ('Why that one episode does not rank the two: handed over between them at several '
                                  'times ( ), the LQR flying first and the policy after survives with the hand-over '
                                  'at 20, 21.5 and 22.5 s and fails at 10, 18, 21 and 22 s (22.25 to 23.25 s); the '
                                  'policy first and the LQR after fails at every one of those times (22.20 to 23.00 '
                                  's).',)),
        # the held-out counts per CPU (docsite/host_cpu.py; znver4: 2026-11-30 and 2026-12-02, znver3: 2026-12-01)
        Printed('paired_survival_shipped', ('the LQR survives 70 and the shipped policy 84: both 45, only the LQR 25, '
                                          'only the policy 39, neither 91 (exact sign test of the discordant pairs, '
                                          'p = 0.103)',), cpu="znver4"),
        Printed('paired_survival_shipped', ('72 and 82 (only the LQR 27, only the policy 37, p = 0.26)',),
                cpu="znver3"),
        # gust_bench.csv's NTM_IB seed 0 rows: the policy's "t = 22.95 s" (znver3 and znver4), the LQR's "t = 42.05 s"
        # (znver3, 2026-12-01; it holds it on znver4)
        Printed('gusts_v1_tethered_wing', ("It loses gusts-v1's NTM_IB seed 0 at 22.95 s;",)),
        Printed('gusts_v1_tethered_wing', ('loses it at 42.05 s on znver3.',), cpu="znver3"),
        Printed('mill_claim', ('mill 0.0940 m, 154.0 kW;',)),
        # tests/test_exact_actor.py -k one_observation: "one observation alone against 512 at once: torch float32 up to
        # 1.4e-06 apart, float64 fixed order 0 (... CPU capability AVX2, MKL True)" (2026-12-01; until then not_rerun)
        Printed('exact_actor_batch_test', ('1.4e-6 on this AVX2 machine for 512 observations',)),
        Printed('chain_claim', ('chain 0.0813 m, 237.6 kW, where the default decentralised chain LQR fails at 9.0 s',)),
    ),
    history=CONTROLLERS_HISTORY,
)
