"""Failures, Ctrl-C and cluster sizes in the executor layer and ``laddermill train-seeds`` (a review of 2026-12-07,
sixth session).

Before: local processes queued one task more than they had workers, so a failure or Ctrl-C could not stop it; a
failure named "task 1" with argument names, not the seed; a Ctrl-C in a serial train-seeds went on to the next seed
and exited 0; a Ray pool of more actors than the cluster's CPUs waited forever; ``--ray`` with ``--workers 0`` started
one actor per CPU of the cluster for a single seed; a relative path inside a config was read from a Ray worker's own
working directory. Oracles: marker files the tasks write when they start, call counts, and a stand-in Ray cluster of
a known size.
"""

from __future__ import annotations

import os
import time
import warnings
from pathlib import Path

import pytest

from laddermill_gym.harness import train_seeds as ts
from laddermill_gym.studies import parallel, pool_workers
from laddermill_gym.studies.commands import UsageError


def mark_and_wait(folder: str, name: str, seconds: float, fail: bool = False) -> str:
    """A task: write a marker file ``name`` in ``folder``, wait ``seconds``, then fail or return ``name``."""
    (Path(folder) / name).write_text("started")
    time.sleep(seconds)
    if fail:
        raise ValueError(f"{name} fails on purpose")
    return name


@pytest.mark.parametrize("workers", [0, 2])
def test_a_failure_stops_new_tasks_lets_running_ones_finish_and_names_the_task(tmp_path, workers):
    tasks = [(mark_and_wait, dict(folder=str(tmp_path), name="a", seconds=0.0, fail=True)),
             (mark_and_wait, dict(folder=str(tmp_path), name="b", seconds=1.5)),
             (mark_and_wait, dict(folder=str(tmp_path), name="c", seconds=0.0))]
    seen = []
    with parallel.Pool(workers) as pool, pytest.raises(parallel.TasksFailed) as err:
        pool.run(tasks, progress=False, labels=["seed 7", "seed 3", "seed 5"],
                 on_result=lambda i, r: seen.append(r))
    assert str(err.value).startswith("seed 7 failed: ValueError: a fails on purpose")
    started = sorted(p.name for p in tmp_path.iterdir())
    if workers:  # b ran beside a and finished; c, queued behind them, never started
        assert started == ["a", "b"] and seen == ["b"] and "1 of 3 tasks completed" in str(err.value)
    else:  # serially the failure ends the batch
        assert started == ["a"] and seen == []


class _FakeRay:
    """A stand-in for Ray's module: a cluster of ``cpus`` CPUs whose actors run their calls at once."""

    def __init__(self, cpus: int):
        self.cpus, self.actors, self.killed = cpus, [], 0

    def is_initialized(self):
        return True

    def cluster_resources(self):
        return {"CPU": float(self.cpus)}

    def available_resources(self):  # every CPU free (tests/test_parallel_start.py: some held)
        return {"CPU": float(self.cpus)}

    def remote(self, num_cpus=1, max_concurrency=1):
        fake = self

        def wrap(cls):
            class Handle:
                def remote(self, *args):
                    worker = cls(*args)
                    fake.actors.append(worker)
                    return worker

            return Handle()

        return wrap

    def kill(self, actor):
        self.killed += 1


def test_more_ray_workers_than_cluster_cpus_is_refused_and_the_pool_is_capped(monkeypatch):
    fake = _FakeRay(cpus=4)
    monkeypatch.setattr(parallel, "_ray_module", lambda: fake)
    monkeypatch.setattr(pool_workers, "init_worker", lambda *a, **k: None)  # the stand-in actors run here: keep
    # numba's threads and Ctrl-C
    with pytest.raises(UsageError, match=r"--workers 6: the Ray cluster \(auto\) has 4 CPUs"):
        parallel.Pool(6, "auto").__enter__()
    assert fake.actors == []
    with parallel.Pool(0, "auto", cap=1):  # one task: one actor, not one per CPU
        assert len(fake.actors) == 1
    with parallel.Pool(0, "auto"):
        assert len(fake.actors) == 1 + 4
    with parallel.Pool(0, "auto", cap=0):  # no tasks: one actor, not one per CPU
        assert len(fake.actors) == 1 + 4 + 1


def test_a_worker_reads_relative_paths_in_the_callers_folder(tmp_path, monkeypatch):
    caller = tmp_path / "caller"
    caller.mkdir()
    monkeypatch.chdir(tmp_path)
    ts.in_callers_folder(str(caller))
    assert os.getcwd() == str(caller)
    with pytest.warns(RuntimeWarning, match="is not on this node"):
        ts.in_callers_folder(str(tmp_path / "elsewhere"))
    assert os.getcwd() == str(caller)


def test_ctrl_c_in_one_seed_stops_the_batch_with_130(tmp_path, monkeypatch, capsys):
    import laddermill_gym.harness.train as train_module

    calls = []

    def interrupted(cfg, out, command=None):
        calls.append(cfg.seed)
        return {"steps": 1234, "interrupted": True}

    monkeypatch.setattr(train_module, "train", interrupted)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rc = ts.main(["configs/agents/ppo_tethered_wing.yaml", "--seeds", "4", "5", "--out-root", str(tmp_path)])
    assert rc == 130 and calls == [4]  # seed 5 never started
    err = capsys.readouterr().err
    assert "interrupted: seed 4" in err and "stopped by Ctrl-C after 1234 steps" in err


def test_an_out_root_that_is_a_file_is_refused_before_training(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("")
    with pytest.raises(SystemExit) as err:
        ts.main(["configs/agents/ppo_tethered_wing.yaml", "--seeds", "0", "--out-root", str(afile)])
    assert err.value.code == 2 and "--out-root" in capsys.readouterr().err
