"""Long groups (:data:`docsite.long_figures.LONG`) for the craft and wind pages (rotor, rotor design, pumping,
power curve, wind, reeling tether, benchmarks, controllers, quasi-steady): mostly tests that print the values they
assert (``pytest -s``), and a few study commands whose printed lines or written CSV / JSON (``reads``) hold a
quoted number, each quick enough to run on its own, so that a quoted number has a command that prints it."""

from __future__ import annotations

from docsite.long_group import Long

CRAFT_TESTS = {
    # rotor.md: the closed forms against the blade-element integration, the ideal variant against the actuator disk
    # and the best collective within the blade limit against a scan (each test prints its differences), the inflow
    # solver's residual evaluations per solve
    "rotor_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_rotor.py -k "closed_forms_against or '
                        'near_axial or best_power_within or inflow_satisfies"', "3 s", "rotor.md"),
    # rotor.md: section_aoa over the disk against the blade's vector geometry (the largest angles at the chart's
    # tip limit) and the blade-element torque at mu = 0.3 (each test prints what it compares)
    "rotor_disk_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_rotor_disk.py', "4 s", "rotor.md"),
    # reeling_tether.md: the hanging tether of 5 and 10 elements against the elastic catenary
    "reel_tether_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_reel_tether.py -k hanging_tether',
                              "2 s", "reeling_tether.md"),
    # power_curve.md: the depower rule's trims against their closed-form targets
    "depower_rule_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_power_curve_mill.py -k '
                               'depower_rule_trims', "2 s", "power_curve.md"),
    # rotorcraft.md: the default craft's eq. (6) blocks at its 10 m/s trim, eq. (6)'s modes, the LQR gain
    "craft_lqr": Long("laddermill lqr --config configs/agents/lqr_rotorcraft.yaml", "2 s", "rotorcraft.md"),
    # rotorcraft.md: the config's step, the craft's fastest eigenvalue at its trim and RK4's stable step there
    "craft_stable_step": Long("laddermill stable-step roberts_flying_model", "2 s", "rotorcraft.md"),
    # rotorcraft_design.md: Roberts' 35 m crafts trimmed in the simulator (altitude, incidence, power, the wind met)
    "craft_trim_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_craft.py -k 35m_crafts_trim',
                             "7 s", "rotorcraft_design.md"),
    # wind.md: LadderMill-v0's loop extent against the NTM_IB grid (the slow test flies the scenario to the mill's
    # failure first: 224 s and 123 s at a load of 5-7, 2026-11-30)
    "mill_loop_extent_test": Long('python -m pytest -m "slow or not slow" -s tests/test_gusts_v2.py -k '
                                  'grid_covers_every_point', "2-4 min", "wind.md"),
    # wind.md: LadderMill-v0's slot heights at the operating point, the EWS_IA grid's rows against IEC eq. 26, and
    # slot 0's roll in the open loop's first second of NTM_IB seed 0 (two 1 s runs; about 2 min with compiling)
    "mill_gust_slots_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_mill_gust_slots.py',
                                  "12 s-2 min", "wind.md"),
    # wing_data.md: the v0 mill in plane at descending elevators 0 and -1 deg, 170 s each from rest (the last
    # element's tension: slack at 0 deg near 160 s, taut at -1 deg)
    "mill_v0_slack_test": Long('python -m pytest -m "slow or not slow" -s tests/test_mill_v0_slack.py', "75 s (load 5)",
                               "wing_data.md"),
    # pumping.md: the scene's reel-out trim elevator and the reel-in elevator (moment balance at alpha_in)
    "pumping_elevator_tests": Long('python -m pytest -m "slow or not slow" -s tests/test_pumping_cycle.py -k '
                                   '"phases_from or reel_in_elevator"', "10 s", "pumping.md"),
    # pumping.md: PumpingKite-v1's hour of crosswind cycles under NTM IB turbulence, seed 0 (the slow test)
    "pumping_ntm_hour_test": Long('python -m pytest -m slow -s tests/test_pumping_v1.py -k an_hour_of_crosswind',
                                  "121 s (load 5, 2026-11-30)", "pumping.md"),
    # reeling_tether.md: the static LQR-assisted cycle on the reeling tether (its first two cycles' power and
    # reel-out tension)
    "reeling_lqr_cycle": Long("laddermill pumping-cycle --config pumping_kite_reeling --controller lqr --cycles 2",
                              "25-80 s (load 3-5, 2026-11-30)", "reeling_tether.md"),
    # rotor.md: Roberts' Fig. 3 chart with its CSV (per mu and alpha_c: C_p, the collective, C_T, C_H, C_Q, lam, nu)
    "rotor_chart_csv": Long("python -m laddermill_gym.studies.rotorcraft.rotor_chart --out "
                            "results/long/rotor_chart/chart.png --csv results/long/rotor_chart/chart.csv", "5 s",
                            "rotor.md", ("results/long/rotor_chart/chart.csv",)),
    # power_curve.md: the v2 wing's trim against the elevator (attached at 1.3 and 4 deg, post-stall at 7 and 8)
    "trim_slope_v2_elevators": Long("python -m laddermill_gym.studies.mill.trim_slope --variants v2 --elevators 1.3 4 "
                                    "&& python -m laddermill_gym.studies.mill.trim_slope --variants v2 --elevators 7 8",
                                    "6 s", "power_curve.md"),
    # where the v2 wing's attached trim is lost, per air speed (power_curve.md)
    "trim_lost_v2": Long("python -m laddermill_gym.studies.mill.trim_slope --variants v2 --lost", "1 s (2026-12-01)",
                         "power_curve.md"),
}
