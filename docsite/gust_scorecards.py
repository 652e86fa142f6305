"""A gust benchmark's scorecard as the docs pages quote it, read from the ``gust_bench.json`` that ``laddermill
gust-bench`` writes (``laddermill_gym.studies.gusts.gust_bench``: its ``rows``, one per controller, scenario and seed,
and its ``summary``, one per controller and scenario with the share of seeds survived).

A page's "survives 8 / 9" counts the scenarios a controller survived on every seed (summary share 1) over the
scenarios of the suite for that env; "NTM IB seed 0 ... lost" names the seeds of a scenario it lost. These are exact
checks (:data:`docsite.page_ledger.LEDGER`'s ``checks`` whose templates name a long group, compared by
:func:`docsite.long_checks.long_check_differences`), not Printed snippets: small integers such as 8 and 9 would find a
match in almost any long output.
"""

from __future__ import annotations

import json
from pathlib import Path


def scorecards(path: Path) -> dict:
    """{"scorecard": {controller: "N / M"}, "lost_seeds": {controller: {scenario: "0" or "0, 2"}},
    "seeds_survived": {controller: {scenario: "k of n"}}} of one env's ``gust_bench.json`` at ``path``: N scenarios
    survived on every seed of M; the seeds of each scenario lost; the seeds of each scenario survived of those run
    (ValueError naming the file when it holds several envs or no summary)."""
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
    return {"scorecard": cards, "lost_seeds": lost, "seeds_survived": kept}
