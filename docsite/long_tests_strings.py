"""Long groups (:data:`docsite.long_figures.LONG`) for the string and mill pages (pointmass, wing data, moving
cable, mill_fast, features): mostly tests that print the values they assert (``pytest -s``), each quick enough to run
on its own, so that a quoted number has a command that prints it."""

from __future__ import annotations

from docsite.long_group import Long

STRING_TESTS = {
    # moving_cable.md: the stable-step estimate at the 3D periodic state just after a transfer (simulate prints it at
    # its start: "RK4 step 0.01 s; estimated stability limit at the start ... (eigenvalue ... 1/s)")
    "simulate_laddermill_periodic": Long("laddermill simulate laddermill --start periodic --time 1 --quiet --out "
                                         "results/long/simulate_laddermill",
                                         "52 s (2026-11-30, nice 15, load 3-5; its periodic start cached)",
                                         "moving_cable.md"),
    # wing_data.md: derive_wing --check's lines that its page group does not parse (the wing-alone C_L,max, the booms'
    # cross-flow drag, the v0 wing's C_L at elevator 0), its table written under results/long
    "derive_wing_printed": Long("python -m laddermill_gym.derivations.derive_wing --check --out-dir "
                                "results/long/derive_wing", "6 s (2026-11-30, nice 15, load 4-5)", "wing_data.md"),
    # pointmass.md: the chunked solver's agreements and the catenary oracle (tests printing what they assert)
    "pointmass_solver_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_pointmass_threads.py '
                                   'tests/test_pointmass_oracles.py -k "backward or chunks_match or second_order or '
                                   'one_centimetre"', "4-16 s (with the 1 cm catenary's 4 s, 2026-11-30)",
                                   "pointmass.md"),
    # pointmass.md: the point-mass mill env's start (the rigid run to periodic motion, then one point-mass period):
    # the reward's reference power, as the test prints it
    "pointmass_mill_env_start": Long('python -m pytest -m "slow or not slow" -s tests/test_pointmass_mill_env.py -k '
                                     'power_term', "79 s (2026-11-30, nice 15, load 5-6)", "pointmass.md"),
    # pointmass.md, wing_data.md: the point-mass mill study (the page group pointmass_mill of pointmass_mill.md runs
    # the same command and parses its table), for the figures the other pages repeat from its printed lines
    "pointmass_mill_study": Long("NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.pointmass.pointmass_mill",
                                 "186 s (2026-11-30, nice 15, load 4-5)", "pointmass.md, wing_data.md"),
    # pointmass.md: the rigid tethered wing's sideways growth (lateral_stability.md's default row, its doubling time)
    "lateral_weathercock": Long("python -m laddermill_gym.studies.lateral.lateral_study --sweeps weathercock --out "
                                "results/long/lateral_weathercock.png", "12 s (2026-11-30, nice 15)", "pointmass.md"),
    # pointmass.md: PointMassChain-v0 open loop through the direction step
    "pointmass_chain_open_loop": Long("laddermill evaluate --env laddermill_gym/PointMassChain-v0 --controllers "
                                      "open_loop --episodes 1 --episode-time 120 --out "
                                      "results/long/pointmass_chain_open_loop", "5 s", "pointmass.md"),
    # mill_fast.md: LadderMill-v1 under random actions after the paper's step (the test prints the median of 10 seeds)
    "mill_v1_random_actions": Long('python -m pytest -m "slow or not slow" -s tests/test_laddermill_v1.py -k '
                                   'random_actions', "35 s", "mill_fast.md"),
    # mill_fast.md: v1's LQR and open loop after the paper's step (the open loop's end, as the test prints it)
    "mill_v1_lqr": Long("python -m pytest -m slow -s tests/test_laddermill_v1.py -k lqr_holds",
                        "135-421 s (2026-11-30, 2026-12-01; nice 15, load 5-6)", "mill_fast.md"),
    # mill_fast.md: the v1 wing's trims at the near-top rule's -4 deg and the descending -0.5 deg (the study's table)
    "trim_v1_top_rule": Long("python -m laddermill_gym.studies.mill.trim_slope --variants v1 --elevators -4 -0.5",
                             "5 s (2026-11-30)", "mill_fast.md"),
    # pointmass.md: one step of podgaets_5km at 500,000 nodes on P = 2, 8, 16 chunks against one chunk (roundoff of the
    # elimination order; the test prints it); most of the cost is the partitioned kernels' compile
    "pointmass_roundoff_500k": Long('python -m pytest -m slow -s tests/test_pointmass_threads.py -k 500000_nodes',
                                    "10 s, 222 s with a cold compile (2026-12-01, nice 15)", "pointmass.md"),
    # pointmass.md: the point-mass tethered wing after the 0.01 rad direction step (offset, overshoot, settling, node
    # speeds at 120 s)
    "pointmass_lateral_test": Long('python -m pytest -m "slow or not slow" -s tests/test_pointmass_lateral.py',
                                   "7 s (2026-12-01, nice 15)", "pointmass.md"),
    # pointmass_mill.md: the first two elements' tensions just after a transfer on the straight string, the paper's
    # insertion rule against the cable's
    "pointmass_insertion_test": Long('python -m pytest -m "slow or not slow" -s tests/test_pointmass_mill.py -k '
                                     'insertion_rule', "3 s (2026-12-01)", "pointmass_mill.md"),
    # controllers.md: the shipped tethered-wing policy's actions, one observation alone against 512 at once, through
    # torch (float32) and the fixed-order float64 actor
    "exact_actor_batch_test": Long('python -m pytest -m "slow or not slow" -s tests/test_exact_actor.py -k '
                                   'one_observation', "5 s (2026-12-01)", "controllers.md"),
    # controllers.md: v0's design model (just after a transfer) on the v1 mill, its phases' |z|, the period's radius
    # and its LadderMill-v0 episode on the v1 scene (the test's operating point about 100 s of it)
    "mill_v1_transfer_phase": Long('python -m pytest -m slow -s tests/test_laddermill_v1.py -k transfer_phase_design',
                                   "547 s (2026-12-01, nice 15, load 6)", "controllers.md"),
    # features.md: LadderMill-v0's open loop after the paper step, the env's failure sentence (the wing, its beta)
    "mill_open_loop_end_test": Long('python -m pytest -m slow -s tests/test_mill_open_loop_end.py',
                                    "11 s, its operating point cached (2026-12-01)", "features.md"),
    # moving_cable.md: the 2D mill's periodic motion at 10 and 5 ms (the period-mean tensions' largest difference)
    "mill_half_step_test": Long('python -m pytest -m slow -s tests/test_mill_periodic_variants.py -k halving',
                                "658 s (2026-12-01, nice 15, load 6)", "moving_cable.md"),
    # moving_cable.md: the default settings on 11 and 21 wings, 1500 s of search each
    "mill_small_test": Long('python -m pytest -m slow -s tests/test_mill_periodic_variants.py -k small_mills',
                            "192 s (2026-12-01, nice 15, load 6)", "moving_cable.md"),
    # wing_data.md: the v1 mill's steps (the slow test prints both) and its power curve
    "mill_v1_steps": Long("python -m pytest -m slow -s tests/test_mill_v1.py -k step", "3 min",
                          "wing_data.md"),
}
