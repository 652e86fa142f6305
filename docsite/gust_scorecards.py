"""A gust benchmark's scorecard as the docs pages quote it, read from the ``gust_bench.json`` that ``laddermill
gust-bench`` writes (``laddermill_gym.studies.gusts.gust_bench``: its ``rows``, one per controller, scenario and seed,
and its ``summary``, one per controller and scenario with the share of seeds survived).

A page's "survives 8 / 9" counts the scenarios a controller survived on every seed (summary share 1) over the
scenarios of the suite for that env; "NTM IB seed 0 ... lost" names the seeds of a scenario it lost. These are exact
checks (:data:`docsite.page_ledger.LEDGER`'s ``checks`` whose templates name a long group, compared by
:func:`docsite.long_checks.long_check_differences`), not Printed snippets: small integers such as 8 and 9 would find a
match in almost any long output. A page's list of scenarios in words ("speed step, EOG, EWS") is compared as a set of
the suite's scenario ids (:data:`SCENARIO_NAMES`, :func:`scenario_key`) with the sets :func:`scorecards` counts.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

#: the docs pages' names of gusts-v1's scenarios (configs/benchmarks/gusts-v1.yaml): one name per scenario id and one
#: id per name
SCENARIO_NAMES = {"direction step": "direction_step", "speed step": "speed_step_20pct", "ramp": "direction_ramp_0.1",
                  "1-cos 4 s": "one_cos_4s", "1-cos 20 s": "one_cos_20s", "EOG": "EOG_IA", "EDC": "EDC_IA",
                  "ECD": "ECD_IA", "EWS": "EWS_IA", "NTM IB": "NTM_IB", "Dryden light": "dryden_light",
                  "Dryden moderate": "dryden_moderate", "random perturbation": "random_perturbation"}


def scenario_key(text: str) -> str:
    """The scenario ids a page's list names ("the ramp, EOG (72 deg in 10 s) and NTM IB seed 0"), sorted and
    ", "-joined: a parenthesis and a "seed N" qualifier are left out, "the" dropped, items split at ", " and " and ";
    a name :data:`SCENARIO_NAMES` lacks gives "unknown scenario name 'NAME'"."""
    text = re.sub(r" seeds? \d+(?:(?:, | and )\d+)*", "", re.sub(r"\s*\([^)]*\)", "", text))
    ids = []
    for item in re.split(r", and |, | and ", text.strip()):
        name = item.removeprefix("the ").strip()
        if name not in SCENARIO_NAMES:
            return f"unknown scenario name {name!r}"
        ids.append(SCENARIO_NAMES[name])
    return ", ".join(sorted(ids))


def scorecards(path: Path) -> dict:
    """{"scorecard": {controller: "N / M"}, "lost_seeds": {controller: {scenario: "0" or "0, 2"}},
    "seeds_survived": {controller: {scenario: "k of n"}}, "held", "lost", "lost_every_seed", "held_beyond":
    {controller: "id, id"}, "lost_by_both": "id, id"} of one env's ``gust_bench.json`` at ``path``: N scenarios
    survived on every seed of M; the seeds of each scenario lost; the seeds of each scenario survived of those run;
    the scenarios survived on every seed, those not, those lost on every seed, those held beyond the open loop's, and
    those the open loop and the LQR both lose, as :func:`scenario_key` writes them (ValueError naming the file when
    it holds several envs or no summary)."""
    data = json.loads(Path(path).read_text())
    summary, rows = data.get("summary"), data.get("rows", [])
    if not summary:
        raise ValueError(f"{path}: no 'summary' rows (a gust_bench.json of laddermill gust-bench has them)")
    envs = sorted({s["env"] for s in summary})
    if len(envs) != 1:
        raise ValueError(f"{path}: {len(envs)} envs {envs}; a scorecard is read from one env's run")
    cards, lost, kept = {}, {}, {}
    for controller in dict.fromkeys(s["controller"] for s in summary):
        mine = [s for s in summary if s["controller"] == controller]
        cards[controller] = f"{sum(s['survived'] == 1.0 for s in mine)} / {len(mine)}"
        seeds: dict[str, list[int]] = {}
        for r in rows:
            if r["controller"] == controller and not r["survived"]:
                seeds.setdefault(r["scenario"], []).append(int(r["seed"]))
        lost[controller] = {scenario: ", ".join(str(s) for s in sorted(found)) for scenario, found in seeds.items()}
        kept[controller] = {s["scenario"]: f"{round(s['survived'] * s['n'])} of {s['n']}" for s in mine}
    sets = {c: {"held": {s["scenario"] for s in summary if s["controller"] == c and s["survived"] == 1.0},
                "lost": {s["scenario"] for s in summary if s["controller"] == c and s["survived"] < 1.0},
                "lost_every_seed": {s["scenario"] for s in summary if s["controller"] == c and s["survived"] == 0.0}}
            for c in cards}
    open_held, both = sets.get("open_loop", {}).get("held", set()), sets.get("open_loop", {}).get("lost", set())
    return {"scorecard": cards, "lost_seeds": lost, "seeds_survived": kept,
            **{kind: {c: ", ".join(sorted(s[kind])) for c, s in sets.items()}
               for kind in ("held", "lost", "lost_every_seed")},
            "held_beyond": {c: ", ".join(sorted(s["held"] - open_held)) for c, s in sets.items()},
            "lost_by_both": ", ".join(sorted(both & sets.get("lqr", {}).get("lost", set())))}
