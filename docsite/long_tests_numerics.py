"""Long groups (:data:`docsite.long_figures.LONG`) for numerics.md, work_precision.md and
work_precision_closed_loop.md: mostly tests that print the values they assert (``pytest -s``), each quick enough to
run on its own, so that a quoted number has a command that prints it."""

from __future__ import annotations

from docsite.long_group import Long

NUMERICS_TESTS = {
    # numerics.md: tests whose measured values are printed beside their assertions (pytest -s; 2026-11-30, nice 15)
    "initial_elements_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_initial_elements.py -k '
                                   '"catenary or converges"', "5-14 s", "numerics.md"),
    "moving_end_jacobian_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_moving_end_jacobian.py '
                                      '-k finite_differences', "17 s", "numerics.md"),
    # the polished starts of ladder_chain at n = 2, 4, 8 (their mass-weighted RMS; n = 8 alone about 155 s)
    "initial_elements_at_rest": Long('python -m pytest -m "slow or not slow" -s tests/test_initial_elements.py -k '
                                     '"at_rest and ladder_chain"', "175-319 s (2026-11-30, nice 15, load 1-6)",
                                     "numerics.md"),
    # TetheredWing-v0 on RK4 through a 5x wind step: the env's warning names the estimate and its eigenvalue
    "rk4_wind_step_test": Long('python -m pytest -m "slow or not slow" -s tests/test_env_substeps.py -k '
                               'rk4_past_its_stable', "27 s (2026-11-30, nice 15, load 6)", "numerics.md"),
    # the observed order of ros2, ros2t, ros34pw2 on the tethered wing, one halving from 0.01 s
    "rosenbrock_order_test": Long('python -m pytest -m "slow or not slow" -s tests/test_rosenbrock.py -k '
                                  'observed_order_on_the_tethered_wing', "6 s (2026-11-30, nice 15, load 5)",
                                  "numerics.md"),
    # ROS2's order reduction: the chain's in-plane errors over one period, and Prothero-Robinson's problem
    "ros2_order_reduction": Long('python -m pytest -m "slow or not slow" -s tests/test_fast_ids.py -k order_one && '
                                 'python -m pytest -s tests/test_rosenbrock.py -k stiff_coupling', "about 40 s",
                                 "numerics.md"),
    # the correction: ROS2 with the dense Jacobian, the chain's fastest modes (tests/test_chain_pitch_modes.py)
    "chain_pitch_modes": Long('python -m pytest -m "slow or not slow" -s tests/test_chain_pitch_modes.py',
                              "about 15 s", "numerics.md"),
    "alpha_rate_pole_test": Long('python -m pytest -m "slow or not slow" -s tests/test_alpha_rate_limit.py -k '
                                 'names_the_alpha', "26 s", "numerics.md"),
    # work_precision.md: the stress suite's small version on the tethered wing (2 s horizon, 5 bisections) and its
    # injection report
    "stress_quick_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_stress.py -k '
                               '"injections_are_reported or bisection_agrees"', "16 s (2026-11-30, nice 15, load 5)",
                               "work_precision.md"),
    # work_precision.md, features.md: RK4 across a wind kink, split and unsplit (the batched case alone compiles for
    # minutes, so it is left out)
    "breakpoint_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_breakpoints.py '
                             'tests/test_batch_breakpoints.py -k "across_a_ramp or (aligned_kinks and single) or '
                             'splits_a_step"', "4 s", "work_precision.md, features.md"),
    # numerics.md: the one-element tethered wing's stable RK4 step at its trimmed start
    "stable_step_wing_1": Long("laddermill stable-step tethered_wing --elements-per-piece 1", "3 s", "numerics.md"),
    # numerics.md: the rotorcraft's stable RK4 step at its trim (its tethers' mode; 2026-12-06, 3 s)
    "stable_step_rotorcraft": Long("laddermill stable-step roberts_flying_model", "3 s", "numerics.md"),
    # numerics.md: the chain's v0 wing trimmed at rest at ladder_chain's elevators -4 / +1 deg, and at +2 deg falling
    "trim_chain_wing": Long("python -m laddermill_gym.studies.mill.trim_slope --variants v0 && python -m "
                            "laddermill_gym.studies.mill.trim_slope --variants v0 --elevators -4 2", "2 s (2026-12-01)",
                            "numerics.md"),
    # cold_start_mill.md: the operating point's search lengths of LadderMill-v0, v1, v2 (OperatingPoint.t_settle_s)
    "operating_point_settle_test": Long(
        'python -m pytest -m "slow or not slow" -s tests/test_operating_point_settle.py',
        "537 s with a cold operating-point cache (2026-12-01, nice 15, load 4-5); seconds from a warm one",
        "cold_start_mill.md"),
    # work_precision.md: breakpoints "all" on the golden direction-step runs, against "inside" and a tight DP5(4)
    "breakpoints_golden_test": Long('python -m pytest -m "slow or not slow" -s tests/test_breakpoints_golden.py',
                                    "21 s, 162 s compiling (2026-12-01, nice 15, load 4-5)", "work_precision.md"),
    # work_precision.md: the tethered wing's extent, the scale of the relative position errors (each forcing's
    # reference; the extent does not depend on the timing repeats)
    "wp_tethered_wing_extent": Long(
        "NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.numerics.work_precision tethered_wing --time 5 "
        "--samples 25 --repeats 1 --quiet --out results/long/wp_tethered_wing", "103 s (2026-12-01, nice 15)",
        "work_precision.md"),
    # benchmarks.md: the mill's stable RK4 step just after its first wing transfer (5000 RK4 steps to t = 50 s)
    "stable_step_mill_transfer": Long("laddermill stable-step laddermill --after-transfer",
                                      "5 s (2026-11-30, nice 15)", "benchmarks.md, work_precision.md"),
    # work_precision_closed_loop.md: the study's closed loop against the harness rollout (tethered wing, chain)
    "closed_loop_rollout_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_closed_loop_precision.py '
                                      '-k harness_rollout', "25 s", "work_precision_closed_loop.md"),
    # work_precision.md: the stability functions of ROS3Pw, ROS34PW3 (Rang & Angermann 2005) and the shipped tableaux
    "stability_functions_test": Long('python -m pytest -m "slow or not slow" -s tests/test_stability_functions.py -k '
                                     '"damping_figures or whip_mode"', "4 s (2026-11-30, nice 15)",
                                     "work_precision.md"),
    # work_precision.md: the mill's fastest unstable mode at 7.6 s and ROS34PW2's |R| / |exp| at 0.2 s on it (the
    # study's whole spectrum: --top 2000)
    "whip_mode_mill": Long("NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.numerics.whip_spectrum laddermill "
                           "--at 7.6 --top 2000 --methods ros34pw2:0.2", "14 s (2026-11-30, load 2.6)",
                           "work_precision.md"),
}
