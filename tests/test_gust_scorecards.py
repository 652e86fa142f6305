"""The gusts-v1 scorecards the docs pages quote ("Rotorcraft-v0 8 / 9") as exact checks of gust-bench's JSON summary
(docsite/gust_scorecards.py, docsite/long_checks.py; issue 33, point 6).

Oracles: a hand-written gust_bench.json (three scenarios, five episodes per controller) whose scorecards are counted
by hand; the pages' own scorecards as gust-bench wrote them (gusts_v1_rotorcraft on 2026-11-30,
gusts_v1_tethered_wing on 2026-12-01's AVX2 CPU, where the LQR loses NTM_IB seed 0; nice 15), and one survival
fewer, which must be named on every page that quotes it.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.gust_scorecards import scorecards  # noqa: E402
from docsite.long_checks import long_check_differences  # noqa: E402
from docsite.page_figures import long_differences, pages_differences  # noqa: E402

# (controller, scenario, seed, survived): open loop holds the step only and NTM seed 1; the LQR loses NTM seed 0
EPISODES = [("open_loop", "direction_step", 0, True), ("open_loop", "EDC_IA", 0, False),
            ("open_loop", "NTM_IB", 0, False), ("open_loop", "NTM_IB", 1, True), ("open_loop", "NTM_IB", 2, False),
            ("lqr", "direction_step", 0, True), ("lqr", "EDC_IA", 0, True), ("lqr", "NTM_IB", 0, False),
            ("lqr", "NTM_IB", 1, True), ("lqr", "NTM_IB", 2, True)]
SHARES = {("open_loop", "direction_step"): (1, 1.0), ("open_loop", "EDC_IA"): (1, 0.0),
          ("open_loop", "NTM_IB"): (3, 1 / 3), ("lqr", "direction_step"): (1, 1.0), ("lqr", "EDC_IA"): (1, 1.0),
          ("lqr", "NTM_IB"): (3, 2 / 3)}


def _bench(path: Path, env: str = "laddermill_gym/Rotorcraft-v0", more: tuple = ()) -> Path:
    rows = [{"env": env, "controller": c, "scenario": s, "seed": k, "survived": ok} for c, s, k, ok in EPISODES]
    summary = [{"env": env, "controller": c, "scenario": s, "n": n, "survived": share}
               for (c, s), (n, share) in SHARES.items()] + list(more)
    path.write_text(json.dumps({"suite": "gusts-v1", "rows": rows, "summary": summary}))
    return path


def test_a_scorecard_counts_the_scenarios_survived_on_every_seed(tmp_path):
    found = scorecards(_bench(tmp_path / "gust_bench.json"))
    assert found["scorecard"] == {"open_loop": "1 / 3", "lqr": "2 / 3"}
    assert found["lost_seeds"] == {"open_loop": {"EDC_IA": "0", "NTM_IB": "0, 2"}, "lqr": {"NTM_IB": "0"}}
    assert found["seeds_survived"]["lqr"] == {"direction_step": "1 of 1", "EDC_IA": "1 of 1", "NTM_IB": "2 of 3"}
    assert found["seeds_survived"]["open_loop"]["NTM_IB"] == "1 of 3"


def test_a_file_of_several_envs_or_no_summary_is_named(tmp_path):
    other = {"env": "laddermill_gym/LadderChain-v0", "controller": "lqr", "scenario": "EDC_IA", "n": 1, "survived": 1}
    with pytest.raises(ValueError, match="2 envs"):
        scorecards(_bench(tmp_path / "gust_bench.json", more=(other,)))
    (tmp_path / "empty.json").write_text(json.dumps({"rows": []}))
    with pytest.raises(ValueError, match="empty.json: no 'summary'"):
        scorecards(tmp_path / "empty.json")


def _long(rotor: dict, wing: dict) -> dict:
    """The two groups' figures, their scenario sets as gust-bench wrote them (the pages' lists)."""
    return {"gusts_v1_rotorcraft": {"printed": "", "scorecard": rotor, **ROTOR_SETS},
            "gusts_v1_tethered_wing": {"printed": WING_CSV, "scorecard": wing, **WING_SETS, "cpu": "znver3",
                                       "lost_seeds": {"ppo_tethered_wing": {"NTM_IB": "0"}, "lqr": {"NTM_IB": "0"}}}}


# the NTM_IB seed 0 rows of gust_bench.csv that controllers.md quotes (controller, scenario, seed, survived, t_end_s)
WING_CSV = "ppo_tethered_wing,NTM_IB,0,False,22.95\nlqr,NTM_IB,0,False,42.05\n"
ROTOR_SETS = {"held": {"open_loop": "EOG_IA, EWS_IA, speed_step_20pct"},
              "lost": {"lqr": "ECD_IA", "ppo_rotorcraft": "ECD_IA"}}
WING_SETS = {"held": {"open_loop": "EOG_IA, EWS_IA, direction_ramp_0.1, direction_step, one_cos_20s, one_cos_4s, "
                                   "speed_step_20pct"},
             "held_beyond": {"lqr": "ECD_IA, EDC_IA, dryden_light"}, "lost_by_both": "NTM_IB, dryden_moderate",
             "lost_every_seed": {"lqr": "dryden_moderate"},
             "lost": {"lqr": "NTM_IB, dryden_moderate", "ppo_tethered_wing": "NTM_IB, dryden_moderate"}}


ROTOR = {"open_loop": "3 / 9", "lqr": "8 / 9", "ppo_rotorcraft": "8 / 9"}
WING = {"open_loop": "7 / 12", "lqr": "10 / 12", "ppo_tethered_wing": "10 / 12"}  # 2026-12-01, AVX2 (znver3)


def test_the_pages_scorecards_are_checked_exactly():
    """features.md's table, controllers.md's shipped-policy sentence and wind.md's table against the counts
    gust-bench wrote; an LQR that lost one more scenario (7 / 9; the old loose rule let a printed 7 stand
    for a quoted 8) is named on each page; a seed of the policy's loss that changed is named."""
    assert long_check_differences(_long(ROTOR, WING)) == []
    assert long_differences(_long(ROTOR, WING)) == []
    bad = long_check_differences(_long({**ROTOR, "lqr": "7 / 9"}, WING))
    assert {b.split(":")[0] for b in bad} == {"docs/features.md", "docs/controllers.md", "docs/wind.md"}, bad
    assert all("7 / 9" in b for b in bad)
    seed = _long(ROTOR, WING)
    seed["gusts_v1_tethered_wing"]["lost_seeds"]["ppo_tethered_wing"]["NTM_IB"] = "1"
    assert ["features.md" in b and "'1'" in b for b in long_check_differences(seed)] == [True]


def test_a_long_check_waits_for_its_group():
    """``--pages`` leaves a check of a long group out; ``--long`` names one whose group ran but gave no scorecard
    (a crashed bench)."""
    assert [b for b in pages_differences({"checked_pages": ["features.md", "controllers.md"]})
            if "gusts_v1" in b] == []
    crashed = long_check_differences({"gusts_v1_rotorcraft": {"printed": ""}})
    assert crashed and all("gave no '" in b for b in crashed) and any("gave no 'scorecard'" in b for b in crashed)


TW_SCENARIOS = ("direction_step", "speed_step_20pct", "direction_ramp_0.1", "one_cos_4s", "one_cos_20s", "EOG_IA",
                "EDC_IA", "ECD_IA", "EWS_IA", "NTM_IB", "dryden_light", "dryden_moderate")
OPEN_HELD = {"direction_step", "speed_step_20pct", "direction_ramp_0.1", "one_cos_4s", "one_cos_20s", "EOG_IA",
             "EWS_IA"}  # wind.md: "direction step, speed step, ramp, 1-cos 4 s, 1-cos 20 s, EOG, EWS"


def _wing_bench(path: Path, open_held: set = OPEN_HELD, moderate_lqr: tuple = (False, False, False)) -> dict:
    """A hand-written TetheredWing-v0 gust_bench.json, three seeds a scenario: the open loop holds ``open_held``;
    the LQR all but NTM IB seed 0 and Dryden moderate (its seeds ``moderate_lqr``), as on 2026-12-01's AVX2 CPU
    (znver3, so the pages' znver3 figures are compared: docsite/host_cpu.py); the
    policy all but NTM IB seed 0 and Dryden moderate. Returns the long groups' figures as --long gives them."""
    seeds = {"open_loop": {s: (s in open_held,) * 3 for s in TW_SCENARIOS},
             "lqr": {**{s: (True,) * 3 for s in TW_SCENARIOS}, "NTM_IB": (False, True, True),
                     "dryden_moderate": moderate_lqr},
             "ppo_tethered_wing": {**{s: (True,) * 3 for s in TW_SCENARIOS}, "NTM_IB": (False, True, True),
                                   "dryden_moderate": (False,) * 3}}
    env = "laddermill_gym/TetheredWing-v0"
    rows = [{"env": env, "controller": c, "scenario": s, "seed": k, "survived": ok}
            for c, by in seeds.items() for s, oks in by.items() for k, ok in enumerate(oks)]
    summary = [{"env": env, "controller": c, "scenario": s, "n": 3, "survived": sum(oks) / 3}
               for c, by in seeds.items() for s, oks in by.items()]
    path.write_text(json.dumps({"suite": "gusts-v1", "rows": rows, "summary": summary}))
    return {"gusts_v1_tethered_wing": {"printed": "", "cpu": "znver3", **scorecards(path)}}


def test_the_pages_scenario_names_are_one_to_one_with_the_suites_ids():
    """Oracle: configs/benchmarks/gusts-v1.yaml's scenario names, every env's."""
    import yaml

    from docsite.gust_scorecards import SCENARIO_NAMES, scenario_key

    suite = yaml.safe_load((ROOT / "configs" / "benchmarks" / "gusts-v1.yaml").read_text())
    ids = {s["name"] for env in suite["envs"].values() for s in env["scenarios"]}
    assert len(set(SCENARIO_NAMES.values())) == len(SCENARIO_NAMES) and set(SCENARIO_NAMES.values()) == ids
    assert scenario_key("EDC, ECD (72 deg in 10 s), NTM IB, Dryden light") == "ECD_IA, EDC_IA, NTM_IB, dryden_light"
    assert scenario_key("NTM IB seed 0 and Dryden moderate") == "NTM_IB, dryden_moderate"
    assert scenario_key("ECD and the random perturbation") == "ECD_IA, random_perturbation"
    assert scenario_key("the steps, the ramp") == "unknown scenario name 'steps'"


def test_a_scenario_moved_between_held_and_lost_is_named(tmp_path):
    """The hand-written bench agrees with wind.md's, features.md's and controllers.md's tethered-wing lists; the open
    loop holding EDC instead of EWS (7 / 12 still) is named on wind.md's list and its LQR's "+ ..." list; the LQR
    surviving one seed of Dryden moderate (10 / 12 still) is named on features.md's "Dryden moderate on every
    seed"."""
    assert long_check_differences(_wing_bench(tmp_path / "a.json")) == []
    swapped = OPEN_HELD - {"EWS_IA"} | {"EDC_IA"}
    bad = long_check_differences(_wing_bench(tmp_path / "b.json", open_held=swapped))
    assert len(bad) == 2 and all(b.startswith("docs/wind.md") for b in bad), bad
    assert any("'@EDC_IA, EOG_IA, " in b for b in bad) and any("'@ECD_IA, EWS_IA, dryden_light'" in b for b in bad)
    bad = long_check_differences(_wing_bench(tmp_path / "c.json", moderate_lqr=(False, True, False)))
    assert ["docs/features.md" in b and "on every seed" in b for b in bad] == [True], bad
