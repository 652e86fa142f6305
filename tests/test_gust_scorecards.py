"""The gusts-v1 scorecards the docs pages quote ("Rotorcraft-v0 8 / 9") as exact checks of gust-bench's JSON summary
(docsite/gust_scorecards.py, docsite/long_checks.py; issue 33, point 6).

Oracles: a hand-written gust_bench.json (three scenarios, five episodes per controller) whose scorecards are counted
by hand; the pages' own scorecards as gust-bench wrote them on 2026-11-30 (gusts_v1_rotorcraft and
gusts_v1_tethered_wing, nice 15), and one survival fewer, which must be named on every page that quotes it.
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
    return {"gusts_v1_rotorcraft": {"printed": "", "scorecard": rotor},
            "gusts_v1_tethered_wing": {"printed": "", "scorecard": wing,
                                       "lost_seeds": {"ppo_tethered_wing": {"NTM_IB": "0"}}}}


ROTOR = {"open_loop": "3 / 9", "lqr": "8 / 9", "ppo_rotorcraft": "8 / 9"}
WING = {"open_loop": "7 / 12", "lqr": "11 / 12", "ppo_tethered_wing": "10 / 12"}


def test_the_pages_scorecards_are_checked_exactly():
    """features.md's table, controllers.md's shipped-policy sentence and wind.md's table against the counts
    gust-bench wrote on 2026-11-30; an LQR that lost one more scenario (7 / 9; the old loose rule let a printed 7 stand
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
    assert crashed and all("gave no 'scorecard'" in b for b in crashed)
