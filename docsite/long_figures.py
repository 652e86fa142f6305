"""The long tier of the page figures: the commands behind page numbers that take too long for the slow test set
(minutes to an hour each on the shared 2-core machine), each re-runnable on its own.

``python -m docsite.readme_figures --long --list`` lists them (name, the command as a user types it, its cost and
its page); ``python -m docsite.readme_figures --skip-readme --long NAME [NAME ...]`` runs those commands in fresh
processes, writes their whole printed output into the JSON under ``"long"`` and compares every
:class:`docsite.ledger_kinds.Printed` snippet of that group with it (:mod:`docsite.printed_numbers`: each quoted
number must be among the printed ones, by value at the quoted digits). The default run leaves them out; in the slow
set each is a test of its own (tests/test_long_tier.py, marked ``slow`` and ``long``). A long group's snippets are
the ones the ledgers listed as not re-run until 2026-11-30.
"""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
import time
from pathlib import Path

from docsite.gust_scorecards import scorecards
from docsite.host_cpu import host_cpu, quoted_profile
from docsite.long_group import Long
from docsite.long_tests_craft import CRAFT_TESTS
from docsite.long_tests_numerics import NUMERICS_TESTS
from docsite.long_tests_strings import STRING_TESTS

ROOT = Path(__file__).resolve().parent.parent
WP = "NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.numerics.work_precision"
CENTRAL = "lqr:configs/agents/lqr_ladder_chain_central.yaml"
STEPS = "python -m laddermill_gym.studies.gusts.step_convergence"
ACCURACY = "python -m laddermill_gym.studies.benchmarks.physics_step_accuracy laddermill_gym/TetheredWing-v1"
STEEP = " --elevators 1.3 3.35 --elevation 70"  # mill_fast.md: at 3.35 deg the rest layout needs a 70 deg first guess


def _bench(suite: str, env: str, controllers: str, page: str, cost: str = "minutes") -> Long:
    """``laddermill gust-bench`` of one env into results/long/<suite>_<env>: it prints only its files' names, so its
    CSV (energy [J], lateral excursions [m], end times [s] per controller, scenario and seed) is what is compared."""
    out = f"results/long/{suite}_{env}"
    env_arg = f" --env laddermill_gym/{env}"
    return Long(f"laddermill gust-bench --suite {suite}{env_arg} --controllers {controllers} --out {out}", cost, page,
                (f"{out}/gust_bench.csv",))


def _gusts(env: str, page: str, policy: str = "") -> Long:
    return _bench("gusts-v1", env, "open_loop lqr" + (f" {policy}" if policy else ""), page,
                  "minutes (7-12 scenarios x 3 seeds)")


def _table_of(name: str) -> tuple:
    """The ``$`` line of power_curve.md's block that shows run ``name``'s table: for v2 and v2_refine the table
    printed again from the run's JSON (``--table``; the runs themselves printed an earlier format), else none (the
    block of the command itself)."""
    out = f"results/power_curve_{name}"
    shown = f"laddermill power-curve --table {out}/power_curve.json --out {out}"
    return (shown,) if name in ("v2", "v2_refine") else ()


RUNS = ("v2", "v2_refine", "v2_depower", "v2_depower6", "v2_depower8", "v2_depower10")  # power_curve.md's six runs

#: Every long group: name -> its command.
LONG = {
    # learned_mill.md: the shipped shared policies beside their LQRs (laddermill evaluate)
    "mill_claim": Long("laddermill evaluate --env laddermill_gym/LadderMill-v1 --controllers ppo_mill lqr "
                       "--episodes 5 --episode-time 300", "about 12 min", "learned_mill.md"),
    "mill_step_01": Long("laddermill evaluate --env laddermill_gym/LadderMill-v1 --scenario step_0.1 --controllers "
                         "ppo_mill lqr --episodes 1 --episode-time 300", "about 3 min", "learned_mill.md"),
    "chain_central_lqr": Long("laddermill evaluate --env laddermill_gym/LadderChain-v0 --controllers "
                              f"{CENTRAL} open_loop --episodes 1 --episode-time 300", "about 1 min",
                              "learned_mill.md"),
    "chain_fit_21": Long("python -m laddermill_gym.harness.shared_fit --env laddermill_gym/LadderChain-v0 --teacher "
                         "lqr_ladder_chain_central --n-basis 21 --k 4 --episodes 1 --episode-time 300 --no-lqr",
                         "about 1 min", "learned_mill.md"),
    "chain_claim": Long(f"laddermill evaluate --env laddermill_gym/LadderChain-v0 --controllers ppo_chain {CENTRAL} "
                        "lqr --episodes 5 --episode-time 300", "about 13 min", "learned_mill.md"),
    "mill_v3_claim": Long("laddermill evaluate --env laddermill_gym/LadderMill-v3 --controllers ppo_mill_v3 lqr "
                          "--episodes 1 --episode-time 300", "about 1 min", "learned_mill.md"),
    "chain_step_01": Long("laddermill evaluate --env laddermill_gym/LadderChain-v0 --scenario step_0.1 --controllers "
                          f"ppo_chain {CENTRAL} --episodes 1 --episode-time 300", "about 3 min", "learned_mill.md"),
    # gusts-v1 per env (features.md's scorecard table, wind.md's, controllers.md's shipped policies)
    "gusts_v1_tethered_wing": _gusts("TetheredWing-v0", "features.md, wind.md", "ppo_tethered_wing"),
    "gusts_v1_ladder_chain": _gusts("LadderChain-v0", "features.md, wind.md"),
    "gusts_v1_rotorcraft": _gusts("Rotorcraft-v0", "features.md, wind.md", "ppo_rotorcraft"),
    # rotorcraft.md: Rotorcraft-v1 (the blade-incidence limit ends an episode) on v0's scenarios (gusts-v5)
    "gusts_v5_rotorcraft_v1": _bench("gusts-v5", "Rotorcraft-v1", "open_loop lqr lqr_guard "
                                     "lqr_guard:lqr_tip_hold_rotorcraft ppo_rotorcraft",
                                     "rotorcraft.md", "minutes (9 scenarios x 1-3 seeds)"),
    # wind.md: gusts-v6 (every field with low_frequencies: offset) on the single craft
    "gusts_v6_tethered_wing": _bench("gusts-v6", "TetheredWing-v0", "open_loop lqr ppo_tethered_wing", "wind.md",
                                     "minutes (12 scenarios x 1-3 seeds)"),
    "gusts_v6_rotorcraft": _bench("gusts-v6", "Rotorcraft-v0", "open_loop lqr ppo_rotorcraft", "wind.md",
                                  "minutes (9 scenarios x 1-3 seeds)"),
    "gusts_v6_rotorcraft_v1": _bench("gusts-v6", "Rotorcraft-v1", "open_loop lqr lqr_guard ppo_rotorcraft", "wind.md",
                                     "minutes (9 scenarios x 1-3 seeds)"),
    "gusts_v6_ladder_chain": _bench("gusts-v6", "LadderChain-v0", "open_loop lqr", "wind.md",
                                    "minutes (9 scenarios x 1-3 seeds)"),
    "gusts_v6_pumping": _bench("gusts-v6", "PumpingKite-v0", "open_loop lqr", "wind.md", "about a minute"),
    "gusts_v6_pumping_v1": _bench("gusts-v6", "PumpingKite-v1", "crosswind", "wind.md", "about a minute"),
    "gusts_v6_laddermill": _bench("gusts-v6", "LadderMill-v0", "open_loop lqr", "wind.md", "minutes"),
    # wind.md: how much of each turbulence model the gust suites' grids keep (closed forms, no draws)
    "turbulence_level": Long("python -m laddermill_gym.studies.gusts.turbulence_level", "seconds", "wind.md"),
    "grid_sampling_v1": Long("python -m laddermill_gym.studies.gusts.grid_sampling --seeds 1000 --env "
                             "laddermill_gym/TetheredWing-v0 laddermill_gym/LadderChain-v0", "40 s", "wind.md"),
    "grid_sampling_record": Long(" && ".join(f"python -m laddermill_gym.studies.gusts.grid_sampling --suite gusts-v6 "
                                             f"--seeds 1000{extra}" for extra in ("", " --record 4")), "40 s",
                                 "wind.md"),
    # rotorcraft.md: the blade-tip guard's prediction error in turbulence, which sets its margin
    "tip_guard_margin": Long("python -m laddermill_gym.studies.rotorcraft.tip_guard_margin --episodes 32",
                             "seconds", "rotorcraft.md"),
    "gusts_v1_laddermill": _gusts("LadderMill-v0", "features.md, wind.md"),
    "pointmass_fidelity": Long("python -m laddermill_gym.studies.pointmass.pointmass_fidelity", "minutes",
                               "features.md, paper_podgaets2007.md"),
    # pumping.md: the scripted cycle's deviations (each about 30 s), the power curve's prose, PumpingKite-v0 / v1
    **{name: Long(f"python -m laddermill_gym.studies.pumping.pumping_cycle --controller lqr --cycles 2{option}",
                  "about 30 s", "pumping.md")
       for name, option in (("pumping_reel_in_16_7", " --reel-in-speed 16.7"), ("pumping_alpha_in_m3",
                            " --alpha-in-deg -3"), ("pumping_cycle_lqr_2", ""), ("pumping_no_lqr", " --no-lqr"))},
    # the JSON it writes holds the cycle times the pages' derived ratios use (t_cycle / schmehl_matched_cycle_s)
    "pumping_power_curve_printed": Long("python -m laddermill_gym.studies.pumping.power_curve --out "
                                        "results/long/pumping_power_curve", "2-3.5 min", "pumping.md",
                                        ("results/long/pumping_power_curve/pumping_power_curve.json",)),
    "gusts_v3_pumping_v1": _bench("gusts-v3", "PumpingKite-v1", "crosswind lqr", "pumping.md", "about 4 min"),
    "pumping_v0_eval_1200": Long("laddermill evaluate --env laddermill_gym/PumpingKite-v0 --controllers crosswind lqr "
                                 "--episodes 1 --episode-time 1200", "minutes", "pumping.md"),
    "pumping_v1_eval": Long("laddermill evaluate --env laddermill_gym/PumpingKite-v1 --controllers crosswind lqr "
                            "--episodes 2", "minutes", "pumping.md"),
    # reeling_tether.md
    "reeling_cycle_40": Long("laddermill pumping-cycle --reel-element-length 40 --cycles 2", "minutes",
                             "reeling_tether.md"),
    "tether_200": Long("python -m laddermill_gym.studies.pumping.tether_convergence --start-length 200 --lengths 200 "
                       "40 --out results/tether_200", "2.5 min", "reeling_tether.md"),
    "reeling_power_curve_printed": Long("python -m laddermill_gym.studies.pumping.power_curve --reel-element-length 40 "
                                        "--out results/long/reeling_power_curve", "2-6 min", "reeling_tether.md",
                                        ("results/long/reeling_power_curve/pumping_power_curve.json",)),
    # power_curve.md: the six runs of 2026-11-29 (60 min on one core together), then their replay (2 s); costs as
    # measured on 2026-11-30 at nice 15, load 1.5-3.5
    **{f"power_curve_{name}": Long(f"laddermill power-curve --workers 1 {args}--out results/power_curve_{name}",
                                   cost, "power_curve.md", shows=_table_of(name))
       for name, args, cost in (("v2", "--tail-rule scene --wind-speeds 2 5 ", "8.2 min"),
                                ("v2_refine", "--tail-rule scene --speeds --winds 4 6 --wind-speeds 0.5 1 3 4 ",
                                 "5 min"),
                                ("v2_depower", "--tail-rule depower --speeds --winds 10 12 14 --wind-speeds 2 3 5 ",
                                 "3.7 min"),
                                ("v2_depower6", "--tail-rule depower --speeds --winds 10 12 14 --wind-speeds 6 ",
                                 "2.6 min"),
                                ("v2_depower8", "--tail-rule depower --speeds --winds 12 14 --wind-speeds 7 8 ",
                                 "2.9 min"),
                                ("v2_depower10", "--tail-rule depower --speeds --winds 14 --wind-speeds 9 10 ",
                                 "3 min"))},
    "power_curve_replay": Long("laddermill power-curve --replay " + " ".join(
        f"results/power_curve_{n}/power_curve.json" for n in ("v2", "v2_refine", "v2_depower", "v2_depower6",
                                                               "v2_depower8", "v2_depower10"))
        + " --out results/power_curve_replay", "2 s after the six power_curve_v2* groups", "power_curve.md"),
    # the six runs' rows printed again from their JSONs (2 s each), with their CSVs (the period-mean tensions
    # t_first_kN / t_last_kN and the strip's heights, which the table does not print): the scene-elevator rows the
    # replay drops, the refinement's breakdowns
    "power_curve_runs": Long(" && ".join(
        f"laddermill power-curve --table results/power_curve_{n}/power_curve.json --out results/power_curve_{n}"
        for n in RUNS), "9 s after the six power_curve_v2* groups", "power_curve.md",
        tuple(f"results/power_curve_{n}/power_curve.csv" for n in RUNS)),
    # the six runs' rows merged (the page's "All runs together" block, compared line for line by printed_blocks)
    "power_curve_merged": Long("laddermill power-curve --table " + " ".join(
        f"results/power_curve_{n}/power_curve.json" for n in RUNS) + " --out results/power_curve_v2_all",
        "2 s after the six power_curve_v2* groups", "power_curve.md"),
    "trim_slope": Long("python -m laddermill_gym.studies.mill.trim_slope", "seconds", "power_curve.md"),
    # wind.md
    "gusts_v2_mill_printed": _bench("gusts-v2", "LadderMill-v0", "open_loop lqr --scenarios EWS_IA NTM_IB "
                                    "dryden_light dryden_moderate", "wind.md", "7 min at nice 15"),
    # the pumping kite's prose beside its gusts-v2 table (the table itself: the slow set's page group gusts_v2_pumping)
    "gusts_v2_pumping_printed": _bench("gusts-v2", "PumpingKite-v0", "open_loop lqr", "wind.md",
                                       "105 s at nice 15"),
    # the work-precision studies (make work-precision; docs/work_precision*.md)
    "wp_closed_loop": Long(f"{WP} ladder_chain --forcing step --controller none lqr --time 10 --samples 50 && {WP} "
                           "laddermill --forcing step --controller none lqr --time 10 --samples 50",
                           "16 min at nice 15", "work_precision_closed_loop.md"),
    "wp_chain_kept_matrix": Long(f"{WP} ladder_chain --forcing step --controller lqr --jacobian-every 1 2 4 8 --time 5 "
                                 "--samples 25 --n-dt 3", "8 min", "work_precision_closed_loop.md"),
    "wp_mill_kept_matrix": Long(f"{WP} laddermill --forcing step --controller lqr --jacobian-every 1 2 4 8 --time 5 "
                                "--samples 25 --n-dt 3", "4 min", "work_precision_closed_loop.md"),
    # every control period sampled, ros1 among the methods (2026-12-06)
    "wp_every_period": Long(" && ".join(
        f"{WP} {scene} --forcing step --controller lqr --jacobian-every 1 2 4 8 --time 10 --samples 200 --n-dt 3"
        for scene in ("ladder_chain", "laddermill")), "11 min", "work_precision_closed_loop.md"),
    "wp_chain": Long(f"{WP} ladder_chain --time 10 --samples 50", "6-9 min", "work_precision.md"),
    "wp_small_scenes": Long(f"{WP} tethered_wing roberts_flying_model laddermill --time 5 --samples 25",
                            "about 7 min", "work_precision.md"),
    "wp_podgaets": Long(f"{WP} podgaets_5km --time 10 --samples 50", "minutes", "work_precision.md"),
    "wp_rk4_scenes": Long(f"{WP} pumping_kite roberts_35m_15kft roberts_35m_30kft --forcing step --time 5 "
                          "--samples 25", "minutes", "work_precision.md"),
    "stress_tethered_wing": Long("laddermill stress tethered_wing", "minutes", "work_precision.md"),
    "work_precision_all": Long(" && ".join((f"{WP} ladder_chain --time 10 --samples 50",
                                            f"{WP} tethered_wing roberts_flying_model laddermill --time 5 --samples 25",
                                            f"{WP} podgaets_5km --time 10 --samples 50",
                                            f"{WP} pumping_kite roberts_35m_15kft roberts_35m_30kft --forcing step "
                                            "--time 5 --samples 25")), "about 15 min (make work-precision)",
                               "work_precision.md"),
    "wp_controller_measure": Long(" && ".join(
        f"{WP} {scene} --forcing step --time {t} --samples {n}" for scene, t, n in (
            ("ladder_chain", 10, 50), ("laddermill", 10, 50), ("laddermill", 5, 25), ("ladder_chain", 5, 25))),
        "10 min at nice 15", "work_precision.md"),
    "whip_spectrum": Long(" && ".join(
        f"NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.numerics.whip_spectrum {scene} --at {at} --top 4 "
        f"--methods ros34pw2:0.0666666666666667 ros2t:0.0666666666666667 rk4:{rk4}" for scene, at, rk4 in (
            ("ladder_chain", "6 8", "0.0222222222222222"), ("laddermill", "6 7.6", "0.0153846153846154"))),
        "11 min", "work_precision.md"),
    "w_step_cost": Long("python -m laddermill_gym.studies.numerics.w_step_cost ladder_chain laddermill --dt-w 0.0667 "
                        "--dt-rk4 0.01", "minutes", "work_precision.md"),
    "jacobian_reuse": Long("python -m laddermill_gym.studies.numerics.jacobian_reuse --every 1 2 4 8", "minutes",
                           "numerics.md"),
    "stress_all": Long("laddermill stress tethered_wing ladder_chain roberts_flying_model laddermill",
                       "5.5 min (2026-11-24) to 20 min (1217 s "
                       "at nice 15, load 4.5-6.4, 2026-11-30)", "work_precision.md"),
    # benchmarks.md
    # the mill's part of laddermill bench (studies/mill/mill_benchmark.py has no command of its own: run alone it
    # printed nothing, 2026-11-30); the two scenes' part comes with it
    "mill_benchmark": Long("laddermill bench --no-pointmass", "minutes", "benchmarks.md"),
    "pointmass_accuracy": Long("python -m laddermill_gym.studies.pointmass.pointmass_benchmark", "minutes",
                               "benchmarks.md"),
    **{f"step_accuracy_{t}": Long(" && ".join(
        f"NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.benchmarks.physics_step_accuracy laddermill_gym/{env} "
        f"--time {t} --steps ros34pw2 ros2" for env in ("LadderChain-v0", "LadderMill-v2")), "minutes each",
        "benchmarks.md") for t in (10, 40)},
    # the fastest step within 1e-3 (ROS2 with its iteration matrix kept 4 steps) and the steps that keep it longer
    **{f"fast_step_accuracy_{t}": Long(" && ".join(
        f"NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.benchmarks.physics_step_accuracy laddermill_gym/{env} "
        f"--time {t} --steps {steps}" for env in ("LadderChain-v0", "LadderMill-v2")), "about a minute",
        "benchmarks.md") for t, steps in ((10, "ros34pw2 ros2:4 ros2:5 ros2:6 ros2:7 ros2:8 ros2t:4 ros2t:8"),
                                          (40, "ros34pw2 ros2 ros2:4"))},
    # the fastest step closed loop: each env's LQR over 300 s with the registered step and ros2:4
    "fast_step_closed_loop": Long(" && ".join(
        f"python -m laddermill_gym.studies.benchmarks.physics_step_accuracy laddermill_gym/{env} --controller {spec} "
        "--time 300 --steps ros2:4" for env, spec in (
            ("LadderChain-v0", "lqr:configs/agents/lqr_ladder_chain_central.yaml"), ("LadderMill-v2", "lqr"))),
        "about 3 min (2026-11-30)", "benchmarks.md"),
    # tests whose printed values D9 put on the pages (2026-11-30; 2-6 s each, about 20 s in all)
    "test_figures_quick": Long(" && ".join('python -m pytest -m "slow or not slow" -s ' + t for t in (
        "tests/test_golden_trajectories.py", "tests/test_pointmass_threads.py -k banded",
        "tests/test_pointmass_env.py -k settled_chain", "tests/test_stable_step.py -k past_its_stable",
        "tests/test_moving_cable_modes.py -k in_plane")), "about 20 s (2026-11-30)",
        "numerics.md, pointmass.md, work_precision.md, moving_cable.md, features.md"),
    # benchmarks.md's LadderChain-v1 section: its accuracy study (v0's RK4 and ROS34PW2 beside it), reward test, LQR
    "chain_v1_figures": Long("NUMBA_NUM_THREADS=1 python -m laddermill_gym.studies.benchmarks.physics_step_accuracy "
                             "laddermill_gym/LadderChain-v1 --time 10 --steps rk4 ros34pw2 && python -m pytest -m slow "
                             "-s tests/test_chain_v1.py -k rewards && laddermill evaluate --env "
                             "laddermill_gym/LadderChain-v1 --controllers "
                             "lqr:configs/agents/lqr_ladder_chain_central.yaml --episodes 1 --episode-time 120 "
                             "--out results/long/chain_v1_lqr", "about 15 s (2026-12-05)", "benchmarks.md"),
    # scorecard_physics_step.md: the scorecard against the step (TetheredWing-v1, then the rotorcraft), the wing's
    # accuracy open and closed loop, and the held-out fields on TetheredWing-v1
    "scorecard_step": Long(
        f"{STEPS} --suite gusts-v4 --env laddermill_gym/TetheredWing-v1 --controllers lqr ppo_tethered_wing "
        "--steps rk4:0.003125 rk4:0.0125 rk4:0.025 rk4:0.05 ros34pw2:0.00625 ros34pw2:0.0125 ros34pw2:0.05 "
        f"ros2:0.05 && {STEPS} --suite gusts-v1 --env laddermill_gym/Rotorcraft-v0 --controllers lqr ppo_rotorcraft "
        f"--steps rk4:0.0015625 ros34pw2:0.05 && NUMBA_NUM_THREADS=1 {ACCURACY} --time 10 --steps ros34pw2 ros2 && "
        f"{ACCURACY} --time 60 --steps ros34pw2 ros2 --controller lqr && python -m "
        "laddermill_gym.harness.paired_survival --config configs/agents/ppo_tethered_wing_severe.yaml --set ntm_ib "
        "--episodes 200 --seed 5000 --controllers lqr ppo_tethered_wing --env laddermill_gym/TetheredWing-v1",
        "about 2 min (2026-12-05)", "scorecard_physics_step.md"),
    "craft_step_options": Long("python -m laddermill_gym.studies.benchmarks.craft_step_options --quick",
                               "about 1 min (2026-12-05)", "scorecard_physics_step.md"),
    "gusts_v4_tethered_wing_v1": _bench("gusts-v4", "TetheredWing-v1", "lqr ppo_tethered_wing",
                                        "scorecard_physics_step.md", "about 10 s (2026-12-05)"),
    "fast_step_rewards": Long('python -m pytest -m slow -s tests/test_fast_ids.py -k rewards',
                              "about 2 min (2026-11-30)", "benchmarks.md"),
    # --tail-rule scene: the page's run (2026-11-29) flew the scene's elevators at every wind, the then default; today's
    # default (depower) changes the 10 m/s rows' elevators (first run 2026-11-30 without it: 130.9 / 194.0 kW there)
    "power_curve_v1": Long("laddermill power-curve --scene laddermill_v1 --ramp scene --tail-rule scene --speeds 0.5 1 "
                           "2 3 4 5 6 --winds 6 10 --wind-speeds 2 3 --max-time 1400 --workers 2", "7 min",
                           "wing_data.md"),
    # mill_fast.md: fast_mill's drift, the near-top rule (1,500 s from rest each), trim_slope, the v2 mill's runs
    "fast_mill_drift": Long("python -m laddermill_gym.studies.mill.fast_mill drift --speed 4 --time 400", "minutes",
                            "mill_fast.md"),
    "fast_mill_top_rule": Long(" && ".join(
        f"python -m laddermill_gym.studies.mill.fast_mill case --speed {v}{rule}" for v in (4, 5)
        for rule in ("", " --top-slots 7 --top-deg -4")), "minutes each", "mill_fast.md"),
    "fast_mill_top_rule_3000": Long("python -m laddermill_gym.studies.mill.fast_mill case --speed 4 --top-slots 7 "
                                    "--top-deg -4 --max-time 3000", "minutes", "mill_fast.md"),
    "trim_slope_v2": Long("python -m laddermill_gym.studies.mill.trim_slope && python -m "
                          "laddermill_gym.studies.mill.trim_slope --variants v2 --elevators 1.3 3.35", "seconds",
                          "mill_fast.md"),
    "fast_mill_v2_5_ramp200": Long("python -m laddermill_gym.studies.mill.fast_mill case --scene laddermill_v2 "
                                   "--speed 5 --start-ramp 200 --max-time 3000", "minutes", "mill_fast.md"),
    "fast_mill_v2_start_trials": Long(" && ".join(  # the v2 scene's start table: elevators, ramp from rest, V_c
        f"python -m laddermill_gym.studies.mill.fast_mill case --scene laddermill_v2{elevators} --start-ramp {ramp} "
        f"--speed {v}" for elevators, ramp, v in ((STEEP, 30, 5), (STEEP, 30, 2), (STEEP, 500, 5), ("", 30, 5),
                                                  ("", 30, 2))),
        "minutes each", "mill_fast.md"),
    "fast_mill_v2_step": Long(" && ".join(
        f"python -m laddermill_gym.studies.mill.fast_mill step --scene laddermill_v2 --speed 2 {step}"
        for step in ("--wind-factor 1.125", "--new-speed 3")), "minutes each", "mill_fast.md"),
    "fast_mill_v2_3d": Long(" && ".join(
        f"python -m laddermill_gym.studies.mill.fast_mill case --scene laddermill_v2 --dimension 3 --speed {v} "
        f"--start-ramp {100 * v} --max-time 3000" for v in (5, 1, 2)), "minutes each", "mill_fast.md"),
    "mill_v2_lqr": Long("python -m pytest -m slow -s tests/test_laddermill_v2.py", "5.5 min", "mill_fast.md"),
    # the mill pages
    "meijaard_v0": Long("python -m laddermill_gym.studies.mill.meijaard --scene laddermill --out results/meijaard_v0",
                        "11 min", "paper_meijaard1999.md, wing_data.md"),
    "meijaard_v1_printed": Long("python -m laddermill_gym.studies.mill.meijaard --out results/meijaard_v1 "
                                "--no-progress", "92 s with its searches saved, 11 min without",
                                "paper_meijaard1999.md, wing_data.md"),
    **{f"mill_v0_{scenario}": Long("laddermill evaluate --env laddermill_gym/LadderMill-v0 --controllers open_loop "
                                   f"lqr --episodes 1 --episode-time 300 --scenario {scenario}", "minutes",
                                   "features.md, controllers.md")
       for scenario in ("paper_step", "step_minus_0.05", "step_0.1", "gust")},
    # controllers.md: the mills' period checks, the hand-over at NTM_IB seed 0, the shipped policy held out
    "lqr_laddermill": Long("laddermill lqr --config configs/agents/lqr_laddermill.yaml", "minutes", "controllers.md"),
    "mill_transfer_transient": Long("python -m laddermill_gym.studies.mill.transfer_transient", "4 min",
                                    "moving_cable.md"),
    "lqr_laddermill_v1": Long("laddermill lqr --config configs/agents/lqr_laddermill_v1.yaml", "minutes",
                              "controllers.md"),
    "switch_ntm_ib_0": Long(" && ".join(  # each order of the hand-over (the page quotes both)
        "python -m laddermill_gym.studies.gusts.switch_controllers --scenario NTM_IB --seed 0 --controllers "
        f"{pair} --times 10 18 20 21 21.5 22 22.5" for pair in ("lqr ppo_tethered_wing", "ppo_tethered_wing lqr")),
        "seconds each", "controllers.md"),
    # numerics.md's Bits and machines: one knife-edge episode under each setting that may move the bits (needs a CPU
    # with AVX-512 for its SkylakeX row; 7 min 16 s on 2026-12-02)
    "machine_bits": Long("python -m laddermill_gym.studies.numerics.machine_bits", "7 min (a CPU with AVX-512)",
                         "numerics.md", avx512=True),
    "paired_survival_shipped": Long("python -m laddermill_gym.harness.paired_survival --config "
                                    "configs/agents/ppo_tethered_wing_severe.yaml --set ntm_ib --episodes 200 --seed "
                                    "5000 --controllers lqr ppo_tethered_wing", "25 s (400 episodes of 60 s)",
                                    "controllers.md"),
    **NUMERICS_TESTS, **STRING_TESTS, **CRAFT_TESTS,
}


def argv_env(command: str, settings: dict | None = None) -> tuple[list[str], dict]:
    """(the argument list of ``python -m`` for ``command``, its environment: this process's with ``settings``
    added): ``laddermill ...`` is ``laddermill_gym.cli ...``, a leading ``NAME=VALUE`` goes into the environment
    (over ``settings``)."""
    words, env = shlex.split(command), {**os.environ, **(settings or {})}
    while words and "=" in words[0] and not words[0].startswith("-"):
        name, _, value = words.pop(0).partition("=")
        env[name] = value
    if words[:2] == ["python", "-m"]:
        return words[2:], env
    if words and words[0] == "laddermill":
        return ["laddermill_gym.cli", *words[1:]], env
    raise ValueError(f"docsite/long_figures.py: a long group's command must start with 'python -m' or 'laddermill', "
                     f"not {command!r}")


def listing() -> str:
    """One line per long group: its name, cost, page and command."""
    return "\n".join(f"{name} ({g.cost}; {g.page}):\n    {g.command}" for name, g in LONG.items())


def _parsed(reads: tuple) -> dict:
    """The figures the pages check from a long group's files: a gust bench's scorecard and lost seeds, from the
    ``gust_bench.json`` beside its CSV (:func:`docsite.gust_scorecards.scorecards`); {} when none was written."""
    found = {}
    for path in reads:
        summary = (ROOT / path).with_name("gust_bench.json")
        if path.endswith("gust_bench.csv") and summary.exists():
            found.update(scorecards(summary))
    return found


def measure_long(names: list[str]) -> dict:
    """{"long": {name: {"printed": stdout, "exit": statuses, "stderr": each failed command's stderr tail, "seconds":
    wall, "cpu": the numeric profile of its commands (:func:`docsite.host_cpu.host_cpu`), and a gust bench's "scorecard"
    and "lost_seeds" (:func:`_parsed`)}}} for the named groups (ValueError naming an unknown one); a command exits 1
    where its study reports a failed case (a wing on the ground), so its output still counts. On a machine whose
    numeric profile no page quotes, the commands run under one it can select (:func:`docsite.host_cpu.quoted_profile`).
    """
    unknown = [n for n in names if n not in LONG]
    if unknown:
        raise ValueError(f"--long: no long group {unknown} in docsite/long_figures.py; see --long --list")
    profile, settings = quoted_profile()
    if settings:
        print(f"this machine's numeric profile ({host_cpu()}) is not one the pages quote: the long groups run under "
              f"{profile}'s kernels ({settings}; docsite/host_cpu.py)", flush=True)
    found = {}
    for name in names:
        t0, printed, status, errors = time.perf_counter(), [], [], []
        for path in LONG[name].reads:  # a file an earlier run left must not stand in for this run's
            (ROOT / path).unlink(missing_ok=True)
            if path.endswith("gust_bench.csv"):  # and the summary whose scorecard the pages check
                (ROOT / path).with_name("gust_bench.json").unlink(missing_ok=True)
        for command in LONG[name].command.split(" && "):
            argv, env = argv_env(command, settings)
            proc = subprocess.run([sys.executable, "-m", *argv], cwd=ROOT, env=env, capture_output=True, text=True)
            printed.append(proc.stdout)
            status.append(proc.returncode)
            errors.append(proc.stderr[-2000:] if proc.returncode else "")
        printed += [(ROOT / path).read_text() for path in LONG[name].reads if (ROOT / path).exists()]
        errors += [f"{path}: not written" for path in LONG[name].reads if not (ROOT / path).exists()]
        found[name] = {"printed": "\n".join(printed), "exit": status, "stderr": errors,
                       "seconds": round(time.perf_counter() - t0), "cpu": host_cpu(env),
                       **_parsed(LONG[name].reads)}
        print(f"{name}: exit {status}, {found[name]['seconds']} s", flush=True)
    return {"long": found}
