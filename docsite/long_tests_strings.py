"""Long groups (:data:`docsite.long_figures.LONG`) for the string and mill pages (pointmass, wing data, moving
cable, mill_fast, features): mostly tests that print the values they assert (``pytest -s``), each quick enough to run
on its own, so that a quoted number has a command that prints it."""

from __future__ import annotations

from docsite.long_group import Long

STRING_TESTS = {
    # pointmass.md: the chunked solver's agreements and the catenary oracle (tests printing what they assert)
    "pointmass_solver_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_pointmass_threads.py '
                                   'tests/test_pointmass_oracles.py -k "backward or chunks_match or second_order"',
                                   "4-16 s", "pointmass.md"),
    # pointmass.md: PointMassChain-v0 open loop through the direction step
    "pointmass_chain_open_loop": Long("laddermill evaluate --env laddermill_gym/PointMassChain-v0 --controllers "
                                      "open_loop --episodes 1 --episode-time 120 --out "
                                      "results/long/pointmass_chain_open_loop", "5 s", "pointmass.md"),
    # mill_fast.md: LadderMill-v1 under random actions after the paper's step (the test prints the median of 10 seeds)
    "mill_v1_random_actions": Long('python -m pytest -m "slow or not slow" -s tests/test_laddermill_v1.py -k '
                                   'random_actions', "35 s", "mill_fast.md"),
    # wing_data.md: the v1 mill's steps (the slow test prints both) and its power curve
    "mill_v1_steps": Long("python -m pytest -m slow -s tests/test_mill_v1.py -k step", "3 min",
                          "wing_data.md"),
}
