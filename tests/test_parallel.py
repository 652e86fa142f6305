"""The executor layer (laddermill_gym/studies/parallel.py) and the gust benchmark on it: a small suite gives the
same rows serially, in two local worker processes and on a local Ray with two workers (the serial run is the
reference: the same episodes computed in this process, whose metrics test_gust_bench.py checks against a plain
Gymnasium rollout); every worker warms up exactly once, before its tasks; failures and bad options are named.
The Ray tests are slow tests (``-m slow``) and skip when Ray (the optional extra ``ray``) is not installed."""

from __future__ import annotations

import csv
import math
import os
import sys

import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.studies import parallel
from laddermill_gym.studies.gusts import gust_bench as gb
from laddermill_gym.studies.gusts.gust_suite import load_suite

TW = "laddermill_gym/TetheredWing-v0"
# One env, two scenarios (a gust and a small turbulence grid, so the warm-up covers both kernel variants), two
# seeds, 3 s episodes.
SUITE = f"""
version: 1
envs:
  {TW}:
    env_kwargs: {{}}
    scenarios:
      - {{name: gust, start: 0.5, duration: 3.0, seeds: [0, 1],
         disturbances: [{{type: OneMinusCosineGust, amplitude: 0.3, duration: 2.0, time: 0.5,
                          direction_amplitude: 0.05}}]}}
      - {{name: turbulence, start: 0.0, duration: 3.0, seeds: [0, 1],
         disturbances: [{{type: Turbulence, model: NTM, wind_class: IB, wind_speed: 8.08, hub_height: 100.5,
                          heights: [0.0, 250.0], dh: 10.0, along_wind: [-100.0, 100.0], dxi: 10.0}}]}}
"""
CONTROLLERS = ["open_loop", "lqr"]


def _same(a, b) -> bool:
    """Rows equal value for value (floats bit for bit; nan equals nan)."""
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    return type(a) is type(b) and a == b


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    path = tmp_path_factory.mktemp("suite") / "tiny.yaml"
    path.write_text(SUITE)
    return load_suite(path)


@pytest.fixture(scope="module")
def serial_rows(suite):
    rows = gb.run_suite(suite, [], CONTROLLERS, progress=False)
    assert len(rows) == 2 * 2 * 2 and {r["controller"] for r in rows} == set(CONTROLLERS)
    return rows


def test_two_local_workers_give_the_serial_rows(suite, serial_rows, tmp_path):
    assert gb.main(["--suite", str(suite.path), "--controllers", *CONTROLLERS, "--workers", "2",
                    "--out", str(tmp_path)]) == 0
    with open(tmp_path / "gust_bench.csv") as f:
        written = list(csv.DictReader(f))
    # the CSV holds repr-exact floats: compare as text against the serial rows written the same way
    assert [{k: str(v) for k, v in r.items()} for r in serial_rows] == written


@pytest.mark.slow  # Ray: the ray extra, which CI does not install (README, slow tests)
def test_local_ray_with_two_workers_gives_the_serial_rows(suite, serial_rows):
    pytest.importorskip("ray", reason="Ray is the optional extra [ray]: pip install 'laddermill_gym[ray]'")
    rows = gb.run_suite(suite, [], CONTROLLERS, progress=False, workers=2, ray="local")
    assert _same(rows, serial_rows)


def _warmups(reports: list[dict], serial: bool) -> None:
    assert len({r["run"] for r in reports}) == 1 and reports[0]["run"] is not None
    pids = {r["pid"] for r in reports}
    assert (pids == {os.getpid()}) if serial else (os.getpid() not in pids and 1 <= len(pids) <= 2)
    assert all(r["warmups"] == 1 for r in reports)  # once per worker, not per task
    assert all(r["warmup_s"] > 0.0 for r in reports)


@pytest.mark.parametrize("workers", [0, 2])
def test_each_worker_warms_up_once_before_its_tasks(workers):
    warm = [(gb.episodes_task, dict(env_id=TW, env_kwargs={}, spec="open_loop", seeds=(0,), duration=0.2,
                                    disturbances=()))]
    reports = parallel.run_tasks([(parallel.worker_report, {})] * 6, workers=workers, warmup=warm, progress=False)
    _warmups(reports, serial=workers == 0)
    if workers:
        assert all(r["numba_threads"] == max(1, (os.cpu_count() or 1) // 2) for r in reports)
    again = parallel.run_tasks([(parallel.worker_report, {})] * 2, workers=workers, warmup=warm, progress=False)
    assert again[0]["run"] != reports[0]["run"]  # a new run warms up anew


@pytest.mark.slow  # Ray: the ray extra, which CI does not install (README, slow tests)
def test_each_ray_worker_warms_up_once_before_its_tasks():
    pytest.importorskip("ray", reason="Ray is the optional extra [ray]: pip install 'laddermill_gym[ray]'")
    reports = parallel.run_tasks([(parallel.worker_report, {})] * 6, workers=2, ray="local",
                                 warmup=[(parallel.source_digest, {})], progress=False)
    _warmups(reports, serial=False)
    assert all(r["numba_threads"] == 1 for r in reports)


def test_a_failing_task_is_named_and_results_keep_the_task_order():
    squares = parallel.run_tasks([(pow, {})] * 0, progress=False)
    assert squares == []
    with pytest.raises(RuntimeError, match=r"task 1 \(laddermill_gym.studies.gusts.gust_bench.episodes_task"):
        parallel.run_tasks([(parallel.worker_report, {}),
                            (gb.episodes_task, dict(env_id="laddermill_gym/NoSuchEnv-v0", env_kwargs={},
                                                    spec="open_loop", seeds=(0,), duration=1.0, disturbances=()))],
                           progress=False)
    digests = parallel.run_tasks([(parallel.source_digest, {})] * 3, workers=2, progress=False)
    assert digests == [parallel.source_digest()] * 3  # the workers run the caller's code


@pytest.mark.parametrize("argv, text", [(["--workers", "-1"], "--workers -1: must be >= 0"),
                                        (["--ray", " "], "--ray '': give auto, local or a cluster address")])
def test_bad_parallel_options_exit_2_naming_the_option(argv, text, capsys):
    with pytest.raises(SystemExit) as err:
        gb.main(["--suite", "gusts-v1", *argv])
    assert err.value.code == 2 and text in capsys.readouterr().err


def test_ray_without_ray_installed_and_bad_training_options_exit_2(monkeypatch, capsys, tmp_path):
    from laddermill_gym.harness import train_seeds

    (tmp_path / "ppo_tethered_wing_seed3").mkdir()
    (tmp_path / "ppo_tethered_wing_seed3" / "config.yaml").write_text("an earlier run\n")

    monkeypatch.setitem(sys.modules, "ray", None)  # import ray now raises ImportError
    with pytest.raises(SystemExit) as err:
        gb.main(["--suite", "gusts-v1", "--ray", "auto"])
    assert err.value.code == 2 and 'pip install "laddermill_gym[ray]"' in capsys.readouterr().err
    for argv, text in ((["--seeds", "0", "0"], "--seeds [0, 0]: must be distinct"),
                       (["--seeds", "0", "--timesteps", "0"], "--timesteps = 0: must be a whole number > 0"),
                       # a seed numpy refuses (the first seed trained, then the pool failed on a traceback), and a
                       # NaN time limit (it passed "<= 0" and trained two steps)
                       (["--seeds", "0", "4294967296"], "--seeds [0, 4294967296]: must be distinct whole numbers "
                                                         "0 .. 2**32 - 1"),
                       (["--seeds", "3", "--minutes", "nan"], "--minutes = nan: must be a finite number > 0"),
                       (["--seeds", "3"], "the run folders")):
        with pytest.raises(SystemExit) as err:
            train_seeds.main(["configs/agents/ppo_tethered_wing.yaml", "--out-root", str(tmp_path), *argv])
        assert err.value.code == 2 and text in capsys.readouterr().err


@pytest.mark.slow
def test_lateral_study_on_two_workers_gives_the_serial_eigenvalues():
    import numpy as np

    from laddermill_gym.studies.lateral.lateral_analysis import run_sweeps
    from laddermill_gym.studies.lateral.lateral_variants import base_scene, sweep_specs

    specs = sweep_specs(base_scene(), quick=True)
    (r0, c0), (r2, c2) = (run_sweeps(specs, ["dihedral"], workers=w, progress=False) for w in (0, 2))
    assert c0 == c2 and c0["dihedral"]["max_real"]  # the dihedral sweep crosses the stability boundary
    for a, b in zip(r0[0].variants, r2[0].variants, strict=True):
        assert a.error == b.error and np.array_equal(a.eigenvalues, b.eigenvalues, equal_nan=True)


@pytest.mark.slow
def test_two_training_seeds_on_two_workers_give_the_serial_runs(tmp_path):
    from laddermill_gym.harness.train_seeds import train_seeds

    config = "configs/agents/ppo_tethered_wing.yaml"
    # one rollout of 4 x 256 steps, the config's minibatch of 1024; no critic warm-up (400,000 steps: beyond the run)
    over = {"total_timesteps": 1024, "n_envs": 4, "eval_episodes": 2, "critic_warmup": None}
    runs = {w: train_seeds(config, [0, 1], tmp_path / f"w{w}", over, workers=w) for w in (0, 2)}
    for a, b in zip(runs[0], runs[2], strict=True):
        assert a["seed"] == b["seed"] and a["steps"] == b["steps"] == 1024
        assert a["best_eval_return"] == b["best_eval_return"] and a["last_eval_return"] == b["last_eval_return"]
        assert a["references"] == b["references"]
    assert runs[0][0]["last_eval_return"] != runs[0][1]["last_eval_return"]  # the seeds differ
