"""gusts-v6 is gusts-v5 with every turbulence field synthesised with ``low_frequencies: offset`` and nothing else
changed (the oracle: gusts-v5's file, read with yaml itself). A frozen suite is changed only by a new version."""

from __future__ import annotations

from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
BENCH = ROOT / "configs" / "benchmarks"


def test_gusts_v6_is_v5_with_offset_turbulence():
    v5 = yaml.safe_load((BENCH / "gusts-v5.yaml").read_text())
    v6 = yaml.safe_load((BENCH / "gusts-v6.yaml").read_text())
    assert (v5["version"], v6["version"]) == (5, 6)
    assert list(v6["envs"]) == list(v5["envs"])
    n = 0
    for env_id, five in v5["envs"].items():
        six = v6["envs"][env_id]
        assert six["env_kwargs"] == five["env_kwargs"], env_id
        assert [s["name"] for s in six["scenarios"]] == [s["name"] for s in five["scenarios"]], env_id
        for a, b in zip(five["scenarios"], six["scenarios"], strict=True):
            assert {k: v for k, v in b.items() if k != "disturbances"} == {
                k: v for k, v in a.items() if k != "disturbances"}, (env_id, a["name"])
            for da, db in zip(a["disturbances"], b["disturbances"], strict=True):
                if da["type"] == "Turbulence":
                    n += 1
                    assert db == {**da, "low_frequencies": "offset"}, (env_id, a["name"])
                else:
                    assert db == da, (env_id, a["name"])
    assert n == 17  # every turbulence scenario of every env


def test_gusts_v6_loads_with_offset_fields():
    from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_spec
    from laddermill_gym.studies.gusts.gust_suite import load_suite

    suite = load_suite("gusts-v6")
    kinds = {disturbance_from_spec(dict(d)).low_frequencies for _, (_, scenarios) in suite.envs.items()
             for s in scenarios for d in s.disturbances if d["type"] == "Turbulence"}
    assert kinds == {"offset"}
