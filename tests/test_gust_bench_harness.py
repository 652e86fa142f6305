"""The gust benchmark's harness (studies/gusts/gust_bench.py, gust_results.py, gust_suite.py, gust_scorecard.py) on the
points of a review: labels, a folder's runs merged, strict JSON, the scorecard's failure time, a suite's env argument
values, frozen suites, the settling time of a drift and an unreachable Ray cluster.

Oracles: hand-made rows and their hand-computed medians; the CSV and JSON read back with the csv module and with
``json.loads`` whose ``parse_constant`` raises (NaN, Infinity are not JSON); each suite file's SHA-256 computed here
with hashlib; the parsed turbulence of the frozen suites; settling times of closed forms (a steady drift has no final
value; an exponential decay to a new level settles at tau ln(1 / band)); the commands' exit status and one-line
errors, with the episode runners replaced by ones that fail if called.
"""

from __future__ import annotations

import csv
import hashlib
import json
import math
import shutil

import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.cli import main as cli_main
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.gusts.gust_results import summarise
from laddermill_gym.studies.gusts.gust_scorecard import cell_text
from laddermill_gym.studies.gusts.gust_suite import SHIPPED_SHA256, load_suite

TW, TW1 = "laddermill_gym/TetheredWing-v0", "laddermill_gym/TetheredWing-v1"
SCENARIO = "- {name: dstep, start: 0.5, duration: 1.0, seeds: [0, 1], disturbances: [{type: DirectionStep, step: 0.3}]}"
SUITE = f"""version: 1
envs:
  {TW}:
    env_kwargs: {{}}
    scenarios:
      {SCENARIO}
  {TW1}:
    env_kwargs: {{}}
    scenarios:
      {SCENARIO}
"""


def _no_episode(*args, **kwargs):
    raise AssertionError("an episode ran")


def _one_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    return lines[0]


@pytest.fixture
def suite_file(tmp_path):
    path = tmp_path / "tiny.yaml"
    path.write_text(SUITE)
    return path


def _row(env, controller, seed, survived=True, t_end=1.0, lateral=0.5, settling=math.nan):
    return {"env": env, "controller": controller, "scenario": "dstep", "seed": seed, "survived": survived,
            "t_end_s": t_end, "failure": "" if survived else "LATERAL", "cause": "", "max_lateral_m": lateral,
            "rms_lateral_m": lateral / 2, "energy_J": 1.0, "energy_ratio": 1.0, "peak_tension_ratio": 0.5,
            "settling_time_s": settling, "control_effort": 0.1}


def test_colliding_labels_are_refused_before_any_episode(tmp_path, monkeypatch, capsys, suite_file):
    """Two LQR configs of one stem, two run folders of one name: one line naming both specs, exit 2, nothing built
    or written (both commands)."""
    from laddermill_gym.harness import evaluate as ev

    other = tmp_path / "other"
    other.mkdir()
    shutil.copyfile(CONFIG_DIR / "agents" / "lqr_tethered_wing.yaml", other / "lqr_tethered_wing.yaml")
    (tmp_path / "runs_a" / "ppo").mkdir(parents=True)
    (tmp_path / "runs_b" / "ppo").mkdir(parents=True)
    monkeypatch.setattr(gb, "build_suite_controllers", _no_episode)
    monkeypatch.setattr(ev, "build_controllers", _no_episode)
    pairs = [(f"lqr:{CONFIG_DIR / 'agents' / 'lqr_tethered_wing.yaml'}", f"lqr:{other / 'lqr_tethered_wing.yaml'}",
              "lqr:lqr_tethered_wing"), (str(tmp_path / "runs_a" / "ppo"), str(tmp_path / "runs_b" / "ppo"), "ppo")]
    for a, b, label in pairs:
        for command, extra in (("gust-bench", ["--suite", str(suite_file)]), ("evaluate", ["--episodes", "1"])):
            out = tmp_path / f"out_{command}"
            assert cli_main([command, *extra, "--controllers", a, b, "--out", str(out)]) == 2
            line = _one_line(capsys.readouterr().err)
            assert line.startswith(f"laddermill {command}: error: --controllers {a!r} and {b!r}: ")
            assert f"labelled {label!r}" in line and not out.exists()
    assert cli_main(["evaluate", "--controllers", "open_loop", "open_loop", "--out", str(tmp_path / "e")]) == 2
    assert "--controllers ['open_loop']: named twice" in _one_line(capsys.readouterr().err)


def _fake_run(monkeypatch, rows_of_env: dict):
    """gust-bench's controllers and episodes replaced: run_suite returns the hand-made rows of the envs asked for."""
    monkeypatch.setattr(gb, "build_suite_controllers", lambda *a, **k: None)
    monkeypatch.setattr(gb, "run_suite", lambda suite, env_ids, *a, **k: [r for e in env_ids for r in rows_of_env[e]])


def test_runs_per_env_merge_when_one_env_names_a_file_and_an_edit_of_it_is_refused(tmp_path, monkeypatch, capsys):
    """The config digest covered the files the run's own envs name: a suite whose TetheredWing-v0 names a scene
    file refused the TetheredWing-v1 run into the same folder as "another config_digest" (review of 2026-12-08). It
    now covers the suite's envs, so the runs merge; an edit of the named file between them is still refused."""
    scene = tmp_path / "my_wing.yaml"
    scene.write_text((CONFIG_DIR / "scenes" / "tethered_wing.yaml").read_text().replace("../", f"{CONFIG_DIR}/"))
    suite = tmp_path / "named.yaml"
    suite.write_text(SUITE.replace("env_kwargs: {}", f"env_kwargs: {{scene: {scene}}}", 1))
    out = tmp_path / "bench"
    _fake_run(monkeypatch, {TW: [_row(TW, "open_loop", 0)], TW1: [_row(TW1, "open_loop", 0)]})
    for env in (TW, TW1):
        assert cli_main(["gust-bench", "--suite", str(suite), "--env", env, "--controllers", "open_loop",
                         "--out", str(out)]) == 0, capsys.readouterr().err
    assert sorted(_strict(out / "gust_bench.json")["env_arguments"]) == [TW, TW1]
    scene.write_text(scene.read_text() + "\n# edited\n")
    capsys.readouterr()
    assert cli_main(["gust-bench", "--suite", str(suite), "--env", TW1, "--controllers", "open_loop",
                     "--out", str(out)]) == 2
    assert "holds results of config_digest" in _one_line(capsys.readouterr().err)


def _strict(path):
    def refuse(name):
        raise ValueError(f"not JSON: {name}")

    return json.loads(path.read_text(), parse_constant=refuse)


def test_runs_per_env_into_one_folder_merge(tmp_path, monkeypatch, capsys, suite_file):
    """wind.md's workflow, the command once per env into one --out: every env's rows, summaries and scorecard stay;
    a rerun replaces its own rows in place; another suite's results are refused before any episode; --force
    replaces them (and the scorecards they had)."""
    out = tmp_path / "bench"
    first = {TW: [_row(TW, "open_loop", 0), _row(TW, "open_loop", 1, survived=False, t_end=0.4)],
             TW1: [_row(TW1, "open_loop", 0, lateral=0.7), _row(TW1, "open_loop", 1, lateral=0.9)]}
    _fake_run(monkeypatch, first)
    for env in (TW, TW1):
        assert cli_main(["gust-bench", "--suite", str(suite_file), "--env", env, "--controllers", "open_loop",
                         "--out", str(out)]) == 0
    with open(out / "gust_bench.csv", newline="") as f:
        got = [(r["env"], int(r["seed"]), float(r["max_lateral_m"])) for r in csv.DictReader(f)]
    assert got == [(TW, 0, 0.5), (TW, 1, 0.5), (TW1, 0, 0.7), (TW1, 1, 0.9)]
    data = _strict(out / "gust_bench.json")
    assert sorted(data["env_arguments"]) == [TW, TW1] and len(data["rows"]) == 4
    assert {(s["env"], s["max_lateral_m"]) for s in data["summary"]} == {(TW, 0.5), (TW1, 0.8)}  # medians by hand
    assert (out / "scorecard_TetheredWing-v0.png").is_file() and (out / "scorecard_TetheredWing-v1.png").is_file()
    # a rerun of v0 replaces its two rows where they were
    _fake_run(monkeypatch, {TW: [_row(TW, "open_loop", 0, lateral=0.1), _row(TW, "open_loop", 1, lateral=0.3)]})
    assert cli_main(["gust-bench", "--suite", str(suite_file), "--env", TW, "--controllers", "open_loop",
                     "--out", str(out)]) == 0
    assert [r["max_lateral_m"] for r in _strict(out / "gust_bench.json")["rows"]] == [0.1, 0.3, 0.7, 0.9]
    # another suite's file (one number changed) is refused, naming the field, before any controller is built
    other = tmp_path / "tiny_other.yaml"
    other.write_text(SUITE.replace("step: 0.3", "step: 0.2"))
    monkeypatch.setattr(gb, "build_suite_controllers", _no_episode)
    capsys.readouterr()
    assert cli_main(["gust-bench", "--suite", str(other), "--env", TW, "--controllers", "open_loop",
                     "--out", str(out)]) == 2
    line = _one_line(capsys.readouterr().err)
    assert "holds results of suite 'tiny', not this run's 'tiny_other'" in line and "--force" in line
    _fake_run(monkeypatch, {TW: [_row(TW, "lqr", 0)]})
    assert cli_main(["gust-bench", "--suite", str(other), "--env", TW, "--controllers", "lqr", "--out", str(out),
                     "--force"]) == 0
    data = _strict(out / "gust_bench.json")
    assert [(r["env"], r["controller"]) for r in data["rows"]] == [(TW, "lqr")] and data["suite"] == "tiny_other"
    assert sorted(p.name for p in out.glob("scorecard_*.png")) == ["scorecard_TetheredWing-v0.png"]


def test_the_json_is_strict_and_records_the_suite_file(tmp_path, suite_file):
    """A row without a settling time (nan) and an infinite ratio: null in a file json.loads takes without NaN; the
    suite's SHA-256 as hashlib computes it from the file."""
    rows = [_row(TW, "open_loop", 0), dict(_row(TW, "open_loop", 1, settling=2.5), energy_ratio=math.inf)]
    suite = load_suite(suite_file)
    gb.write_outputs(rows, suite, tmp_path / "out")
    data = _strict(tmp_path / "out" / "gust_bench.json")
    assert [r["settling_time_s"] for r in data["rows"]] == [None, 2.5]
    assert data["rows"][1]["energy_ratio"] is None and data["summary"][0]["settling_time_s"] == 2.5
    assert data["suite_sha256"] == hashlib.sha256(suite_file.read_bytes()).hexdigest()


def test_the_scorecard_fails_at_the_failed_seeds_median():
    """One seed of three failed at 12 s: the cell reads 12.0 s (the failed seeds' median), the summary's t_end_s stays
    the median over every seed (60 s), and a cell without a failure has no time."""
    rows = [_row("E", "c", 0, survived=False, t_end=12.0), _row("E", "c", 1, t_end=60.0),
            _row("E", "c", 2, t_end=60.0), _row("E", "d", 0, survived=False, t_end=10.0),
            _row("E", "d", 1, survived=False, t_end=20.0), _row("E", "d", 2, t_end=60.0)]
    c, d = summarise(rows)
    assert (c["t_end_s"], c["t_fail_s"], c["survived"]) == (60.0, 12.0, pytest.approx(2 / 3))
    assert (d["t_end_s"], d["t_fail_s"]) == (20.0, 15.0)
    assert cell_text(c).splitlines()[0] == "fails 12.0 s" and cell_text(d).splitlines()[0] == "fails 15.0 s"
    ok = summarise([_row("E", "c", 0)])[0]
    assert math.isnan(ok["t_fail_s"]) and "fails" not in cell_text(ok)


@pytest.mark.parametrize("kwargs, field, text", [
    ("{scene: nosuch_scene}", "scene", "'nosuch_scene': .*no such file"),
    ("{control_dt: -1}", "control_dt", "-1: must be > 0"),
    ("{control_dt: 0}", "control_dt", "0: must be > 0"),
    ("{physics_step: bogus}", "physics_step", "'bogus': must be None .*'rk4'"),
    ("{scene_options: {nope: 1}}", "scene_options.nope", "1: not an argument of load_scene"),
])
def test_a_suites_env_argument_values_are_named(tmp_path, kwargs, field, text):
    path = tmp_path / "bad.yaml"
    path.write_text(SUITE.replace("env_kwargs: {}", f"env_kwargs: {kwargs}", 1))
    with pytest.raises(ConfigError, match=rf"^{path}: field 'envs\.{TW}\.env_kwargs\.{field}' = {text}"):
        load_suite(path)


def test_shipped_suites_are_pinned_by_their_files_sha256(tmp_path):
    """The pins are the files' SHA-256 (hashlib here); a changed copy under a shipped name is refused naming the file
    and both hashes; a suite of its own name is not."""
    for name, pinned in SHIPPED_SHA256.items():
        path = CONFIG_DIR / "benchmarks" / f"{name}.yaml"
        assert hashlib.sha256(path.read_bytes()).hexdigest() == pinned == load_suite(name).sha256, name
    assert sorted(SHIPPED_SHA256) == sorted(p.stem for p in (CONFIG_DIR / "benchmarks").glob("gusts-v*.yaml"))
    changed = (CONFIG_DIR / "benchmarks" / "gusts-v1.yaml").read_text().replace("seeds: [0, 1, 2]", "seeds: [0, 1]")
    copy = tmp_path / "gusts-v1.yaml"
    copy.write_text(changed)
    digest = hashlib.sha256(copy.read_bytes()).hexdigest()
    with pytest.raises(ConfigError, match=rf"^{copy}: SHA-256 {digest}, not the frozen suite gusts-v1's "
                                          rf"{SHIPPED_SHA256['gusts-v1']}"):
        load_suite(copy)
    (tmp_path / "mine.yaml").write_text(changed)
    assert load_suite(tmp_path / "mine.yaml").name == "mine"


def test_the_frozen_suites_turbulence_is_the_rescale_synthesis():
    """gusts-v1 to v5 leave low_frequencies to the code's default: every turbulence field they hold is synthesised
    with 'rescale' (gusts-v6's with 'offset', tests/test_gusts_v6.py), so changing the default changes them."""
    from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_spec

    for version in range(1, 6):
        suite = load_suite(f"gusts-v{version}")
        fields = [disturbance_from_spec(dict(d)) for _, (_, scen) in suite.envs.items() for s in scen
                  for d in s.disturbances if d["type"] == "Turbulence"]
        assert fields and {f.low_frequencies for f in fields} == {"rescale"}, version
        assert not any("low_frequencies" in d for _, (_, scen) in suite.envs.items() for s in scen
                       for d in s.disturbances), version


def test_a_steady_drift_is_not_settled():
    """e = 0.01 t stays within 10 % of its largest deviation from the tail's mean over the last 10 % (it read 51.3 s)
    but has no final value; a decay to a new level e = 1 + exp(-t / tau) settles at tau ln(1 / band)."""
    dt, tau = 0.05, 3.0
    t = dt * np.arange(int(60.0 / dt) + 1)
    assert math.isnan(gb.settling_time(0.01 * t, dt, 0.0, 60.0))
    assert math.isnan(gb.settling_time(0.002 * t, dt, 0.0, 60.0))
    assert gb.settling_time(1.0 + np.exp(-t / tau), dt, 0.0, 60.0) == pytest.approx(tau * math.log(10.0), abs=2 * dt)
    # a drift small against the band after a decay: 1 mm over the episode, the band 0.1: settled as the decay
    drift = np.exp(-t / tau) + 1e-3 * t / 60.0
    assert gb.settling_time(drift, dt, 0.0, 60.0) == pytest.approx(tau * math.log(10.0), abs=2 * dt)


def test_an_unreachable_ray_cluster_is_one_line(monkeypatch, capsys, tmp_path, suite_file):
    pytest.importorskip("ray")  # an optional extra: without it --ray is refused before any connection (test_parallel)

    def refused(*args, **kwargs):
        raise ConnectionError("Failed to connect to Ray cluster at 10.255.255.1:6379")

    monkeypatch.setattr(gb, "build_suite_controllers", lambda *a, **k: None)
    monkeypatch.setattr(gb, "run_tasks", refused)
    code = cli_main(["gust-bench", "--suite", str(suite_file), "--env", TW, "--controllers", "open_loop",
                     "--ray", "10.255.255.1:6379", "--out", str(tmp_path / "out")])
    assert code == 2
    assert _one_line(capsys.readouterr().err) == ("laddermill gust-bench: error: --ray '10.255.255.1:6379': Failed to "
                                                  "connect to Ray cluster at 10.255.255.1:6379")


def test_a_folder_of_results_flown_on_other_configs_is_refused(tmp_path, monkeypatch, capsys):
    """Rows flown on an edited scene file do not merge with those flown before the edit (the merge compared the
    Python sources only; a review of 2026-12-07): gust_bench.json's config_digest covers the files an env argument
    names, and the package's configs."""
    for part in ("scenes", "wings", "cables"):
        shutil.copytree(CONFIG_DIR / part, tmp_path / part)
    scene = tmp_path / "scenes" / "tethered_wing.yaml"
    suite = tmp_path / "mine.yaml"
    suite.write_text(SUITE.replace("env_kwargs: {}", f"env_kwargs: {{scene: {scene}}}", 1))
    out = tmp_path / "bench"
    _fake_run(monkeypatch, {TW: [_row(TW, "open_loop", 0), _row(TW, "open_loop", 1)]})
    args = ["gust-bench", "--suite", str(suite), "--env", TW, "--controllers", "open_loop", "--out", str(out)]
    assert cli_main(args) == 0
    assert cli_main(args) == 0  # the same files: the rerun merges
    first = _strict(out / "gust_bench.json")["config_digest"]
    scene.write_text(scene.read_text() + "# edited\n")
    monkeypatch.setattr(gb, "build_suite_controllers", _no_episode)
    capsys.readouterr()
    assert cli_main(args) == 2
    assert "holds results of config_digest" in capsys.readouterr().err
    assert _strict(out / "gust_bench.json")["config_digest"] == first  # nothing was written
