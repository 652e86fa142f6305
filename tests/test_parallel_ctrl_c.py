"""Ctrl-C at the terminal during a batch on local worker processes or Ray actors (``studies/parallel``), and during
``laddermill train-seeds``.

Before (2026-12-07): the terminal's SIGINT reached every local worker, and one that was importing, warming up, waiting
for a task or sending a result died of it, which broke the process pool and ended the other workers with their unsaved
training; Ray killed its actors at once (no seed saved); and the command said only "interrupted". Now the workers
ignore the terminal, the caller passes a first Ctrl-C on as a stop (each running training saves its model and
returns; other tasks run to their end), starts no other task, names what each did and exits with 130; a second Ctrl-C
aborts at once.

Oracles: real commands in a process group of their own, SIGINT sent to the whole group as a terminal does, marker
files the tasks write, the run folders' files (``model.zip`` is written only when a training ends) and the process
table (no worker left behind).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

# The smallest training of TetheredWing-v0 that runs until stopped: two copies, episodes of 5 s, no evaluation after
# the first, no validation or warm-up (the options every PPO config of configs/agents has, at their least).
CONFIG = """algorithm: PPO
env: laddermill_gym/TetheredWing-v0
n_envs: 2
env_kwargs: {episode_time: 5.0}
seed: 0
total_timesteps: 100000000
time_limit_minutes: 60.0
checkpoint_every: 100000000
eval: {every: 100000000, episodes: 1}
"""


# A batch of three tasks that each write a marker and sleep, on two local workers, as a command (exit status 130 on
# Ctrl-C through run_guarded); the task's module is importable by the spawned workers through PYTHONPATH.
SNOOZE = """import time
from pathlib import Path

def snooze(folder, name, seconds):
    (Path(folder) / name).write_text("started")
    time.sleep(seconds)
    return name
"""
BATCH = """import sys
from laddermill_gym.studies.commands import run_guarded
from laddermill_gym.studies.parallel import Pool
import snooze

def batch():
    with Pool(2) as pool:
        names = sys.argv[3]
        done = pool.run([(snooze.snooze, dict(folder=sys.argv[1], name=n, seconds=float(sys.argv[2]))) for n in names],
                        progress=False, labels=[f"task {n}" for n in names])
        print(" ".join(done), flush=True)
        for n in sys.argv[4:]:  # later batches on the same workers, one task each
            print(*pool.run([(snooze.snooze, dict(folder=sys.argv[1], name=n, seconds=0.1))], progress=False))

if __name__ == "__main__":  # a spawned worker imports this file as __mp_main__
    raise SystemExit(run_guarded("batch", batch))
"""


def _batch(tmp_path: Path, seconds: float, names: str = "abc", *later: str) -> subprocess.Popen:
    (tmp_path / "snooze.py").write_text(SNOOZE)
    (tmp_path / "batch.py").write_text(BATCH)
    (tmp_path / "marks").mkdir()
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]))
    return subprocess.Popen([sys.executable, str(tmp_path / "batch.py"), str(tmp_path / "marks"), str(seconds), names,
                             *later],
                            start_new_session=True, env=env, stdout=open(tmp_path / "stdout.txt", "w"),
                            stderr=open(tmp_path / "stderr.txt", "w"))


def _marks(tmp_path: Path) -> list[str]:
    return sorted(p.name for p in (tmp_path / "marks").iterdir())


def test_a_first_ctrl_c_lets_running_tasks_end_and_starts_no_other(tmp_path):
    proc = _batch(tmp_path, seconds=4.0)
    _wait_for(proc, lambda: len(_marks(tmp_path)) == 2, 120, tmp_path)
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path)
    assert rc == 130, err[-2000:]
    assert _marks(tmp_path) == ["a", "b"]  # c never started
    assert err.strip().endswith("laddermill batch: interrupted (Ctrl-C): stopped by Ctrl-C, 2 of 3 tasks completed; "
                                "1 not started")


def test_a_ctrl_c_after_the_last_task_started_keeps_every_result(tmp_path):
    """Every task ran to its end: the batch returns their results (the first version threw them away)."""
    proc = _batch(tmp_path, seconds=3.0, names="ab")
    _wait_for(proc, lambda: len(_marks(tmp_path)) == 2, 120, tmp_path)
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path)
    assert rc == 0 and (tmp_path / "stdout.txt").read_text().split() == ["a", "b"], err[-2000:]


def test_a_ctrl_c_during_one_batch_starts_no_task_of_the_next_on_the_same_workers(tmp_path):
    """Every task of the first batch ended after the Ctrl-C, so it returned; the next batch on the same pool then
    started its tasks, on workers that kept the stop (a training would have ended at its first check), although the
    message said no new task starts (review of 2026-12-08)."""
    proc = _batch(tmp_path, 3.0, "ab", "c")
    _wait_for(proc, lambda: len(_marks(tmp_path)) == 2, 120, tmp_path)
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path)
    assert rc == 130 and _marks(tmp_path) == ["a", "b"], err[-2000:]  # c never started
    assert (tmp_path / "stdout.txt").read_text().split() == ["a", "b"]
    assert err.strip().endswith("stopped by Ctrl-C during an earlier batch on these workers: none of this batch's 1 "
                                "tasks started")


def snooze_here(seconds: float) -> float:
    time.sleep(seconds)
    return seconds


def test_serially_the_first_ctrl_c_interrupts_at_once():
    """Serially Ctrl-C stays the running task's: a KeyboardInterrupt at once (a first version of the stop request
    swallowed it and ran every task to its end)."""
    import threading

    from laddermill_gym.studies.parallel import run_tasks

    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    t0 = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        run_tasks([(snooze_here, {"seconds": 1.0})] * 3, progress=False)
    timer.join()
    assert time.monotonic() - t0 < 1.0


def test_a_second_ctrl_c_aborts_at_once_and_leaves_no_worker(tmp_path):
    proc = _batch(tmp_path, seconds=300.0)
    _wait_for(proc, lambda: len(_marks(tmp_path)) == 2, 120, tmp_path)
    _ctrl_c(proc)
    time.sleep(1.0)  # two signals at once are one for the receiver
    t0 = time.monotonic()
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path, seconds=60)
    assert rc == 130 and time.monotonic() - t0 < 30, err[-2000:]
    assert err.strip().endswith("laddermill batch: interrupted (Ctrl-C)")
    while not _group_gone(proc.pid) and time.monotonic() - t0 < 30:
        time.sleep(0.2)
    assert _group_gone(proc.pid), "a worker outlived the aborted batch"


def _start(tmp_path: Path, *options: str) -> tuple[subprocess.Popen, Path]:
    """``laddermill train-seeds`` of three seeds in a new session (its own process group, as a shell's job)."""
    config = tmp_path / "tiny.yaml"
    config.write_text(CONFIG)
    out = tmp_path / "runs"
    proc = subprocess.Popen([sys.executable, "-m", "laddermill_gym", "train-seeds", str(config), "--seeds", "0", "1",
                             "2", "--out-root", str(out), *options], start_new_session=True,
                            stdout=subprocess.DEVNULL, stderr=open(tmp_path / "stderr.txt", "w"))
    return proc, out


def _wait_for(proc: subprocess.Popen, ready, seconds: float, tmp_path: Path) -> None:
    t0 = time.monotonic()
    while not ready():
        assert proc.poll() is None, (tmp_path / "stderr.txt").read_text()[-2000:]
        assert time.monotonic() - t0 < seconds, "the command did not get there in time"
        time.sleep(0.2)


def _ctrl_c(proc: subprocess.Popen) -> None:
    os.killpg(proc.pid, signal.SIGINT)  # the terminal sends SIGINT to every process of the foreground group


def _finish(proc: subprocess.Popen, tmp_path: Path, seconds: float = 180.0) -> tuple[int, str]:
    try:
        rc = proc.wait(timeout=seconds)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    return rc, (tmp_path / "stderr.txt").read_text()


def _group_gone(pgid: int) -> bool:
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return True
    return False


def _training(out: Path, seed: int) -> bool:
    return (out / f"tiny_seed{seed}" / "config.yaml").exists()  # written when the training starts


@pytest.mark.parametrize("ray", [False, pytest.param(True, marks=pytest.mark.slow)], ids=["local", "ray"])
def test_ctrl_c_saves_every_running_seed_and_starts_no_other(tmp_path, ray):
    if ray:
        pytest.importorskip("ray", reason="Ray is the optional extra [ray]: pip install 'laddermill_gym[ray]'")
    proc, out = _start(tmp_path, "--workers", "2", *(["--ray", "local"] if ray else []))
    _wait_for(proc, lambda: _training(out, 0) and _training(out, 1), 240, tmp_path)
    time.sleep(2.0)
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path)
    assert rc == 130, err[-2000:]
    for seed in (0, 1):
        assert (out / f"tiny_seed{seed}" / "model.zip").is_file()
        assert f"seed {seed} (run folder {out / f'tiny_seed{seed}'}): TrainingInterrupted: stopped by Ctrl-C" in err
    assert not (out / "tiny_seed2").exists() and "1 not started" in err
    assert "interrupted: stopped by Ctrl-C, 0 of 3 tasks completed" in err


def test_ctrl_c_while_the_workers_warm_up_stops_their_first_seeds_at_once(tmp_path):
    """Before, a worker hit during its warm-up died and broke the pool; now its seed starts, stops at its first check
    and saves."""
    proc, out = _start(tmp_path, "--workers", "2")
    _wait_for(proc, lambda: (tmp_path / "stderr.txt").read_text().count("train tiny") > 0, 120, tmp_path)
    time.sleep(1.0)  # the workers are importing or compiling now: the trainings start after 8 s or more
    assert not _training(out, 0)
    _ctrl_c(proc)
    rc, err = _finish(proc, tmp_path)
    assert rc == 130, err[-2000:]
    for seed in (0, 1):
        assert (out / f"tiny_seed{seed}" / "model.zip").is_file()
    assert "0 of 3 tasks completed" in err and "1 not started" in err and "BrokenProcessPool" not in err
