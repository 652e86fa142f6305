"""The ledger entry (:mod:`docsite.page_ledger`) of docs/numerics.md: RK4's stability limits, the asymptotic error
ratios and a residual's displacement worked in closed form (:mod:`docsite.numerics_figures`); the methods' published
constants and the solver settings given; per-step costs dated timings; the measured accuracy, stability and
reproducibility figures (from studies and tests that no page group re-runs) listed as not re-run."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, History, Printed

G = "{numerics_data[%s]}"
NUMERICS = Covered(
    groups=("numerics_data",),
    checks=((r"\|h lambda\| <= ([\d.]+) on the imaginary axis", (G % "rk4_imag",)),
            (r"with the limit ([\d.]+) on the real axis", (G % "rk4_real",)),
            (r"approaching (\d) and (\d) from below", (G % "ratio_ros2", G % "ratio_ros34pw2")),
            (r"1e-6 m/s\^2 at omega\^2 = 7e5 s\^-2 is ([\d.e-]+) m", (G % "node_offset",))),
    given=(  # the equations and methods as published, the solvers' settings, counts of unknowns
        "the string's closed-form limit (the damped highest mode's, below l0 / c and mu l0^2 / (2 DA);",
        "Until 2026-12-06 the last did not",  # the day the warm-up's bits were fixed (their cause found)
        "and its 3-copy vector env's",  # the test's copy count (tests/test_cache_reproducibility.py)
        # the chain's reward check: its settings and step sizes (tests/test_fast_ids.py)
        "**What an agent is given: the chain's rewards** (2026-11-30; , )",
        'Over 200 control periods of actions of 0.3 amplitude on LadderChain-v0, open loop, the largest per-step '
        'reward error against RK4 at 3.125 ms', 'at 50, 12.5, 6.25 ms)',
        'against RK4 at 50/128 ms',  # jacobian_reuse's reference step (an input, printed as 0.05 s / 128)
        # ROS2's order reduction (2026-12-05): the steps and reference of tests/test_fast_ids.py -k order_one, and the
        # orders tests/test_rosenbrock.py -k stiff_coupling asserts (its bounds, not measured figures)
        'against RK4 at 50/256 ms', 'at 12.5 ms to only', 'at 3.125 ms, about order 1, where ROS34PW2 at 3.125 ms',
        'Rang & Angermann (2005)', 'order 1 without it, 2 with it;', 'order 2 either way',
        # its correction (tests/test_chain_pitch_modes.py): the day, the paper, the steps (50 ms / 1, 4, 16, 64, 256)
        # and the orders it names; "order 3": ROS34PW2's published order
        'The cause (corrected later on 2026-12-05;', 'from Verwer et al. (1999) with', 'at 50, 12.5 and 3.125 ms',
        'A step of 12.5 ms does not resolve', '3.125 ms only partly', 'and its order 2 shows below 1 ms',
        'over the halvings from 3.125 to 0.78 and 0.195 ms', 'ROS34PW2, of order 3', 'Any step near 50 ms',
        'which RK4 at 12.5 ms',
        # the option's settings
        "(opt-in: , the wing and rotorcraft envs' ; default 1, the registered ids' bits)",
        'The registered ids keep k = 1.',
        'With k > 1',
        'still a W-method of order 3',
        "Eq. (25) of Meijaard", "6 velocity unknowns per wing", "3 per free cable node", "6 x 6 blocks",
        "a precomputed 6 x 6 shape times m_e/3", "f(s) = s^3 - s0 s^2 - c", "c = EA eps_p/l0 >= 0",
        "when c > 0 (f(0) = -c < 0", "The start value of eq. (21), max(s0, c^(1/3))", "inflection point s0/3",
        "For s0 > 0", "-s0 c^(2/3)", "for s0 <= 0", "below 1e-13 of the iterate (60 steps at most;", "With c = 0",
        "max(s0, 0)", "Dormand-Prince 5(4)", "step factor 0.9 err^(-1/5) clipped to [0.2, 5]", "sect. IV.7; Steihaug & "
        "Wolfbrandt 1979)", "one-stage method (s = 1, gamma = 1), its right-hand side", "Order 1 for any J (the local "
        "error is h^2 (f_y / 2 - J) f + O(h^3):", "L-stable with R(z) = 1/(1 - z);", "order 1 for any J, R(z), the "
        "mill's pay-out against a t^2 / 2.",
        # the study's first ros1 run (work_precision_closed_loop.md: 1.2e-2 every step at 0.05 s, 2026-12-06) and
        # the lag h a t / 2 derived there
        "lagged the mill's ramp by h a t / 2 and cost 1 % of the generator power at 0.05 s",
        "caps every step at 0.05 s",
        "(Verwer, Spee, Blom & Hundsdorfer 1999, SIAM J. Sci. Comput. 20): 2 stages, order 2, "
        "gamma = 1 + 1/sqrt 2,", "at gamma = 1/4, order 2 for any J, A-stable with R(z) = ((1 + z/4)/(1 - z/4))^2",
        "(|R(iy)| = 1)", "(Rang & Angermann 2005, BIT 45): 4 stages, order 3,", "transformed form (7.4')",
        "the small rotation 2 vec(conj(q) dq)", "(h gamma)^2 K", "1. the cable", "2. the bodies' own loads",
        "the body's 6 velocities and 3 small rotations", "(9 extra evaluations per body and step)",
        "(10 s, 0.1 rad direction step; position error against DP5(4) at 1e-10)", "h gamma lambda = 1",
        "(l_p / 10 after a transfer)", "l0 = l_p / 10 + s", "at wing 0", "U_t,i = h gamma (1 + sum_j c_ij U_t,j / h)",
        "(2 s, disturbed start)", "omega_max of about 2 sqrt(k/m)", "-4 DA/(mu l^2)",
        "falls like 1/n", "DP5(4) reference", "below 0.9 of it", "rerun at dt / 4, then dt / 16",
        "0 or 1, C_N0 = C_T0 = 0", "3 unknowns per wing and 2 per node", "1. **Layout.**", "C_N0 sin^3 a_c + C_T0",
        "L (1 + T/EA)", "w_perp^2 L^3 / (24 T^2)", "2. **Newton.**", "in-plane (2D) model", "the 2D equilibrium is the "
        "3D one", "**Ground points 100 m apart,", "**Elevators -4 deg rising", "and +1 deg falling",
        "the float32 ulp", "three times the floor", "(issue 13:", "at n = 4 and 8, at n = 2)", "1e-6 m/s^2, the RMS",
        "at n <= 8:", "(8 -> 4 -> 2 -> 1,", "the start tension (2 unknowns)", "absolute steps of 1e-7 m (rad)",
        "up to 10 damped Newton steps", "(1.5e-8 |z|,", "below 1e-4 m/s^2, unbalanced forces below 1e-8",
        "at n = 2, 4, 8", "from n = 1 to 16", "and RK4 / ROS34PW2 runs from the states stay below 1e-3 m/s",
        "(C_L_alphadot, C_m_alphadot; Meijaard et al. 1999, eq. 6)", "(sideslip near 90 deg)", "The 101-wing mill",
        "RK4 at the scene's 10 ms step", "acceleration above 1e4", "D_c^-1 b_c; Y_c = D_c^-1 U_c",
        "J = [[0, A], [M^-1 K P, M^-1 C]]", "(|h lambda| >> 1)", "below 1/|lambda|", "With n > 1", "with 1 / V_xz",
        "(DP5(4) and ROS34PW2)", "reaches 3.5 km",
        # jacobian_reuse's default --offset (added to every trim control); the golden chain run's length (40 RK4
        # steps of 12.5 ms, tests/test_golden_trajectories.py); the scenes' n beside figures printed per scene
        'controls 0.01 off the trim', 'relative over 0.5 s', "at n = 4 the measure's own round-off", 'at n = 4 and',
        '= 8 ( , 2026-11-30;',
        # bounds the fast set's tests assert, not measurements: tests/test_kernels_vs_reference.py (err < 1e-10
        # against the numpy reference; the in-plane kernel against the 3D one to 1e-9), the 1e-12 normwise
        # bound of tests/test_golden_trajectories.py
        'to 1e-10 and the in-plane 3D run still equals the 2D run to 1e-9', 'to 1e-12 normwise relative',
        # tests/test_jacobian_reuse.py's bound and settings (what it asserts, not a figure the study prints; was a
        # Printed entry of jacobian_reuse, whose first run here, 2026-12-02, named its 6 as printed by nothing)
        'error ratio per halving above 6 with the matrix kept 3 and 8 steps',
        # Bits and machines: the machine, the profiles' names and days (docsite/host_cpu.py, 2026-12-02)
        "What differs was measured on 2026-12-02 (an AMD EPYC with AVX-512, LLVM's", "has the AVX-512 code's bits",
        "LLVM's generic x86-64, which has no fused multiply-add,",
        "These are the bits of the AMD EPYC with AVX2 of 2026-12-01", "this machine prints its 200-field held-out",
        "With numpy's AVX-512 loops these are the bits of the AMD EPYC of 2026-11-30",
        "on a CPU with AVX-512), and the start caches", "read the trim an AVX-512 process had stored",
        "This machine's own profile (AVX-512 loops, Haswell kernels: its environment",
        "(znver4 where it has AVX-512, znver3 on any with AVX2;"),
    timings=(  # one thread, medians on the shared 2-core machine (the page gives no date: measured when written)
        # the kept matrix's CPU per step (jacobian_reuse, 2026-11-30 03:33, load 7.4-7.8; the 4000-step
        # figures were the study's measuring error, corrected in c-batchgap)
        'a 50 ms step cost 7.28 us of CPU every step, 6.20 us kept 2, 5.71 us kept 4, 5.47 us kept 8 (-15, -22, -25 '
        '%; the 4.66 / 4.01 / 3.71 / 3.57 us printed before timed 4000 steps, of which the wing flies about 2550 '
        'before',
        '1000 steps timed; 2026-11-30 03:33, load 7.4-7.8',
        "On the mill a ROS34PW2 step went from 432 to 399 us; the rest of it is the three stage right-hand sides (50 us"
        " each,", "(85 us) and the cable's (15 us)", "assembly 31 us, full right-hand side 53 us, cable Jacobian "
        "15 us, "
        "body Jacobian 86 us, one elimination 23 us; a step about 1.4 RK4 steps, a step about 2.4",
        "about 30 % *slower* than the full model on the chain (right-hand side 63.4 against 49.9 us,",
        "made every variant about 45 us", "full 49.4 us, cable aerodynamics off 46.7 us, sag off 44.0 us, both off "
        "39.7 "
        "us", "savings 7 %, 12 %, 16 % on the chain; 7 %, 14 %, 22 % on the tethered wing",
        "chain RK4 step 297-305 us against 304-332 us with it, tethered wing 6.45-6.64 us against 6.15-6.41 us (three "
        "interleaved process pairs", "Cost: 0.2 s at any n <= 16; 1.5, 13 and 85 s at n = 2, 4, 8 (dense "
        "difference Jacobians of 507, 915 and 1731 "
        "unknowns)"),
    derived=(  # worked by hand from the page's own inputs
        # dyneema_25mm.yaml: 0.3 kg/m x 12.5 m (the tethered wing's 100 m piece at n = 8) = 3.75 kg (half of each of
        # two elements); EA 2.16e7 N / 12.5 m = 1.73e6 N/m (the page said 2.5 kg until 2026-11-30: worked by hand)
        '(half of each neighbouring element, 3.75 kg at 12.5 m) against an element stiffness EA / l0 of 1.7e6 N/m',
        # benchmarks.md's closed-loop chain with ros2:4: power -6.69e-09 (relative), offset -1.49e-08 m
        "Closed loop the chain's LQR sees within 1e-8 of RK4",
        "omega^2 ~ 1e6 s^-2, a wing's pendulum g / L ~ 0.1 s^-2", "outweigh the wing rows 1e7 to one",
        "some 200 ulps of a 50 m coordinate", ": O(1/n^2);", "as h^0.4 under", "n^-1.4",
        # the largest |H, V error| x n^2 that initial_elements_tests prints (3.82e-3, V at n = 8), rounded up
        "H and V at the station within 4e-3 / n^2",
        # MINPACK hybrd's forward differences with scipy's default epsfcn (machine epsilon): a relative step of
        # sqrt(2.2e-16) = 1.5e-8; at the chain's 3.5 km (given) 1.49e-8 x 3500 m = 5.2e-5 m = 0.05 mm
        '(1.5e-8 |z|, 0.05 mm)',
        'needs a CPU with AVX-512 for the last row, about 7 minutes)'),  # machine_bits, 2026-12-02 (7 min 16 s)
    printed=(  # long groups: python -m docsite.readme_figures --long NAME (docsite/long_figures.py)
        Printed('test_figures_quick', ("today's code by 1.01e-10 and 1.51e-10", '(measured at most 5.1e-14;',
                                       # the componentwise differences (tethered_wing, ladder_chain, _2d)
                                       '(the golden runs against 16b454f: 1.72e-10 on the chain, 2.73e-12 on the wing,',
                                       'by up to 1.72e-10', "the in-plane chain's by 1.83e-10")),
        # tests/test_initial_elements.py -s -k "at_rest and ladder_chain": "306 nodes: ... mass-weighted RMS 5.1e-08"
        # (n = 4), "714 nodes: ... 2.4e-07" (n = 8; the scenes' n given)
        Printed('initial_elements_at_rest', ('a mass-weighted RMS of 5.1e-8 m/s^2', '2.4e-7 at n')),
        # tests/test_env_substeps.py -s -k rk4_past_its_stable: the env's warning, "RK4's estimated stable step
        # 0.0228 s (eigenvalue -122.1 + 0i 1/s) ... (speed factor 5)"
        Printed('rk4_wind_step_test', ('-122 1/s, 0.023 s, after a 5x wind step)',)),
        # tests/test_rosenbrock.py -s -k observed_order: "ros2: ... at 0.01, 0.005 s: ratio per halving 3.96",
        # "ros34pw2: ... 7.32" (the page's 3.4 of 2026-11-24 corrected, issue 33 point 6)
        Printed('rosenbrock_order_test', ('the error ratio per halving from 0.01 to 0.005 s is 3.96 for ros2 and 7.32 '
                                          'for ros34pw2',)),
        Printed('fast_step_rewards', (  # the slow test's printed errors (its settings given)
            'shrinks with the ROS34PW2 step (0.1269, 0.0390, 0.0044 at',
            "but hardly with ROS2's (0.1443, 0.1336, 0.1259)",
        )),
        Printed('ros2_order_reduction', ('fall from 3.09e-02 m/s (vx), 2.70e-02 rad/s (q) and 92.3 N',
                                         '6.30e-03, 8.04e-03 and 30.1', 'is off by 2.29e-05, 3.45e-05 and 0.387')),
        Printed('chain_pitch_modes', ('(largest state error 7.25e-02, 2.44e-02 and', '8.00e-03 at 50',
                                      "against the kernel's 7.22e-02, 3.43e-02 and 8.04e-03)",
                                      'modes, 111-119 rad/s with damping ratios 0.037-0.043',
                                      '(h |lambda| = 1.48)', '(error ratios 10.5 and 16.0')),
        Printed('jacobian_reuse', (
            'over 60 s the largest position error', 'was 3.44, 3.60, 3.96, 4.84 m',
        )),
        Printed('wp_chain', ('(about -5 +- 119i 1/s on',)),  # "eigenvalue -5.09 +- 118.6i 1/s"
        Printed('wp_small_scenes', ('ROS34PW2 at 0.2 s 5.9x RK4 on the mill over 5 s',)),  # laddermill 5 s: 5.87x rk4
        # tests printing their measured values beside the assertions (pytest -s)
        Printed('moving_end_jacobian_tests', ('to 2.4e-5',)),
        Printed('initial_elements_tests', ('within 3.6e-4, 8.6e-5, 2.1e-5 m', '(slope -2.0)',
                                           'lies 1.35 m from the limit',
                                           'moves by 1.12, 0.175, 0.0421 m from n = 1 to 8 (ratio 4.16')),
        Printed('alpha_rate_pole_test', ('at t = 0.3836 s (wing 46', 'at -74.5 deg sideslip)',
                                         'is 3.73e9 rad/s^2 at the last accepted state and -3.06e11, with the other '
                                         'sign, 1e-4 s later', 'removed, -127 rad/s^2')),
        # the one-element wing at its trimmed start: "rk4: largest stable step 0.1141 s (... -24.4 + 0i 1/s)"
        Printed('stable_step_wing_1', ('-24 1/s, a 0.11 s limit,',)),
        # "rk4: largest stable step 0.00619 s (set by the eigenvalue -110.7 +- 457.1i 1/s)"
        Printed('stable_step_rotorcraft', ("(its tethers' mode, -110.7 +- 457.1i 1/s at the trim, limits RK4 to "
                                           '0.00619 s)',)),
        # the v0 wing's trims at rest at the chain's elevators, 8 m/s: "-4.00 ... 13.64/1.28", "+1.00 ... 5.36/0.72",
        # "+2.00 ... 2.87/0.50" (were not_rerun; the page's 13.7 deg, the 2026-11-22 layout's, is today's 13.6)
        Printed('trim_chain_wing', ('(trim alpha 13.6 deg at 8 m/s)', '(alpha 5.4 deg).**',
                                    'At +2 deg (alpha 2.9 deg)')),
        # Bits and machines: the study's rows, and the held-out counts each profile prints (docsite/host_cpu.py)
        Printed('machine_bits', ("(seed 0's largest excursion 80.14 m against 48.38 m)",
                                 "numpy's AVX2 loops lose seed 0 at 42.05 s",
                                 "OpenBLAS's SkylakeX kernels give 64.83 m")),
        Printed('paired_survival_shipped', ('counts again (the policy 82, the LQR 72;',), cpu="znver3"),
        Printed('paired_survival_shipped', ('held-out counts again (84 and 70)',), cpu="znver4"),
    ),
    history=(  # the page's earlier figures, replaced by today's printed ones (issue 33 point 6, 2026-11-30)
        History('2026-12-07', "a review's scripts: the rigid J blocks against central differences of the assembled "
                "forces (model_assemble), with sag and without", "the Jacobian review's repro scripts (4ddc82a)",
                ('length too: a review of 2026-12-07 found 3.36 and 4.29 times the true d sigma / d l on the tethered '
                 "wing's two elements, 693 times at ladder_chain's apex)",
                 'stiffness blocks within 0.3 %, off-diagonal damping 3.9 %)')),
        History('2026-12-02', "laddermill gust-bench --suite gusts-v1 --env laddermill_gym/TetheredWing-v0 "
                "--controllers lqr --scenarios NTM_IB under NPY_DISABLE_CPU_FEATURES='X86_V4 AVX512_ICL' (b0d09ba)",
                'the start cache filled by a process with AVX-512 loops, before the key carried the kernels',
                ("Until 2026-12-02 they did not: a process with numpy's AVX2 loops", 'lost seed 0 at 45.40 s,')),
        History('2026-11-24', 'the series beside tests/test_rosenbrock.py (e770ec3; the test halves once, from 0.01 s)',
                'the tethered wing over 2 s from 0.04 to 0.005 s, as first measured',
                ('2026-11-24, from 0.04 s: ros2 2.9, 3.1, 3.4 and ros34pw2 6.1, 6.8, 7.3)',)),
        History('2026-11-24', 'pytest -s tests/test_initial_elements.py (569de48)',
                'the converging wing from n = 1 to 16 elements per piece (the test today stops at n = 8)',
                ('2026-11-24 quoted 1.10, 0.17, 0.041, 0.010 m from n = 1 to 16',)),
        History('2026-11-24', 'the failed ros34pw2 run of the 101-wing mill under bang-bang controls (9f0397d)',
                "the pole's accelerations from another evaluation than today's test's",
                ('(2026-11-24, another evaluation of the pole: -74 deg, -4.5e6, 3.9e9, -129 rad/s^2)',)),
        History('2026-11-24', 'pytest -s tests/test_golden_trajectories.py (42b5686, 6943b61, e9de291)',
                'the golden runs against 16b454f as first measured',
                ('2026-11-24: 9.8e-11 and 2.1e-12)', '(2026-11-24: 1.1e-10;', '4.6e-14 on 2026-11-24)')),
        History('2026-11-24', 'the scaled solve of ladder_chain (569de48)',
                'the first polished start, its n not recorded', ('4.7e-8 m/s^2 as written on 2026-11-24',)),
        History('2026-11-30', "the review R2's /tmp/r2/conv3.py (not kept; aef5b41)",
                'LadderChain-v0 open loop: ros2 0.0146 at 0.78 ms, ros2t 0.0255 / 0.0019 at 12.5 / 3.125 ms',
                ('show ROS2 converging only below 1 ms and ROS2T from 12.5 ms.',)),
        History('2026-11-24', "the W-methods' design runs on ladder_chain (e770ec3; 10 s, 0.1 rad direction step)",
                'variants the code no longer has: ros2 without the body Jacobian, the implicit sag derivative',
                ('unstable at 0.05 s on the chain', 'met explicitly); with it, at 0.2 s', '(3.6x softer',
                 'error at 0.05 s halves (0.028 against 0.058 m), but its largest stable step falls from 0.2 to 0.1 s '
                 '(the apex wings diverge at 7.8 s)')),
        History('2026-11-24', 'the mill\'s W-method runs before the station column (03bc65a)',
                'the moving end left explicit (the code no longer has it)', ('broke the mill down at 0.2 s',)),
        History('2026-11-22', "the layout's grid search for ladder_chain (596e2f4)",
                'ground points a few metres apart (no scene has them now)',
                ("(the rising leg, stretched by 160 kN against the falling leg's 40 kN, is 20 m longer)",)),
        History('2026-11-24', 'tests/test_cache_reproducibility.py by elimination, fastmath flags off (6943b61)',
                'kernels with contract / reassoc switched off, not the shipped ones; the golden in-plane start then',
                ('(from step 16)', "the in-plane chain's equilibrium by 8.5e-13 at the start,")),
        History('2026-11-24', 'tests/data/ulp_floor_16b454f.py on a checkout of 16b454f (e9de291)',
                "16b454f's own output with its start moved by one ulp per entry (earlier code)",
                ('by 0.9-1.2e-10 on the chains', '(single wing and rotorcraft 1.2-2.3e-12;')),
        History('2026-11-24', "an RK4 run of TetheredWing-v0 past its stable step after a 5x wind step (9a9cc8d)",
                "a one-off diagnosis (the env's warning names the limit: --long rk4_wind_step_test)",
                ('and RK4 past it grows the state about 30-fold per step',)),
        History('2026-11-22', "the layout's trial of +2 deg falling elevators at three steps (596e2f4)",
                'elevators no scene has now', ('within 15 s (the same growth at dt = 0.01, 0.005 and 0.0025 s,',)),
        History('2026-11-24', "issue 13's diagnosis of the initial states (569de48)",
                "one-off runs of the unscaled solve from straight chords, the layout's guess at n = 8, MINPACK's "
                "relative steps and the measure's one-ulp round-off",
                ('at n = 8 (RMS 0.105 m/s^2), and the trim stalls at n = 4 and 8 with the angle of attack off by 0.008 '
                 'rad', 'is 2.5e-7 m/s^2', '(100-230 N against 160 kN at the ground)',
                 '(apex wing 115 N and 580 N m out of balance at n = 8; Newton stalls at 0.13 m/s^2)',
                 'stop at 1e-5 m/s^2', 'by a factor 2')),
    ),
)
