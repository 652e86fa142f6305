"""How a batch's workers start (a review of 2026-12-07, eighth session): a Ray actor waiting for a CPU that another
job holds was handed tasks it could never run (the batch hung); an address that does not answer made ``ray.init``
retry without end; a worker that could not start (another numpy, a failing warm-up) was reported as its tasks
failing with "BrokenProcessPool" or "ActorDiedError", the cause only in the worker's log; a task's ``sys.exit``
escaped a serial batch unnamed; ``rllib_train`` waited for env runners beyond the cluster's CPUs.

Oracles: call counts of stand-in actors, a TCP port the test itself listens on (or leaves closed), a worker
process's own numpy version against a caller's that differs, and tasks that return their own index after uneven
sleeps."""

from __future__ import annotations

import os
import re
import socket
import subprocess
import sys
import time

import pytest

from laddermill_gym.studies import parallel, pool_workers, ray_start
from laddermill_gym.studies.commands import UsageError


def sleep_and_return(v: int, s: float) -> int:
    """A task: sleep ``s`` seconds, return ``v``."""
    time.sleep(s)
    return v


def exits(code: int) -> None:
    """A task that calls sys.exit."""
    raise SystemExit(code)


class _Ref:
    def __init__(self, fn):
        self.fn, self.done = fn, fn is not None


class _Actor:
    """A stand-in actor: ``ready`` answers (or raises) when ``starts`` is True (or an exception), never when False;
    ``call`` runs the task at once and counts it."""

    def __init__(self, starts):
        self.starts, self.calls = starts, 0
        actor = self

        class _Method:
            def __init__(self, fn):
                self.fn = fn

            def remote(self, *args):
                return self.fn(*args)

        def ready():
            if actor.starts is False:
                return _Ref(None)
            return _Ref(lambda: (_ for _ in ()).throw(actor.starts) if isinstance(actor.starts, Exception) else True)

        def call(i, fn, kw):
            actor.calls += 1
            result = pool_workers.call_task(i, fn, kw)
            return _Ref(lambda: result)

        self.ready, self.call, self.stop = _Method(ready), _Method(call), _Method(lambda: _Ref(lambda: 0))


class _FakeRay:
    """A stand-in for Ray's module: a cluster of ``cpus`` CPUs, ``free`` of them free, whose actors start as
    ``starts`` says (one entry per actor, in order)."""

    def __init__(self, cpus, free, starts):
        self.cpus, self.free, self.starts, self.actors = cpus, free, list(starts), []

    def is_initialized(self):
        return True

    def cluster_resources(self):
        return {"CPU": float(self.cpus)}

    def available_resources(self):  # as Ray: no "CPU" entry when none is free
        return {"CPU": float(self.free)} if self.free else {"memory": 1e9}

    def remote(self, num_cpus=1, max_concurrency=1):
        def wrap(cls):
            fake = self

            class Handle:
                def remote(self, *args):
                    actor = _Actor(fake.starts[len(fake.actors)])
                    fake.actors.append(actor)
                    return actor

            return Handle()

        return wrap

    def wait(self, refs, num_returns=1, timeout=None):
        done = [r for r in refs if r.done]
        return done, [r for r in refs if not r.done]

    def get(self, ref):
        return ref.fn()

    def kill(self, actor):
        pass


def test_tasks_go_only_to_actors_that_have_started(monkeypatch):
    """Two actors on a cluster where another job holds one CPU: the one that never starts gets no task, the other
    runs all four, in the tasks' order (it used to be given half of them and the batch never ended)."""
    fake = _FakeRay(cpus=2, free=1, starts=[True, False, True])
    monkeypatch.setattr(parallel, "_ray_module", lambda: fake)
    with parallel.Pool(2, "auto") as pool:
        assert pool.run([(sleep_and_return, dict(v=i, s=0.0)) for i in range(4)], progress=False) == [0, 1, 2, 3]
    assert [a.calls for a in fake.actors] == [4, 0]
    with parallel.Pool(0, "auto"):  # workers 0: one actor per free CPU (1), not per CPU of the cluster (2)
        pass
    assert len(fake.actors) == 3
    held = _FakeRay(cpus=3, free=0, starts=[True])  # every CPU held: one actor, which starts when one is freed
    monkeypatch.setattr(parallel, "_ray_module", lambda: held)
    with parallel.Pool(0, "auto"):
        pass
    assert len(held.actors) == 1


def test_actors_that_cannot_start_name_their_cause(monkeypatch):
    err = RuntimeError("worker on node-7 runs other code than the caller: numpy '2.4' here, '2.3' at the caller")
    fake = _FakeRay(cpus=2, free=2, starts=[err, err])
    monkeypatch.setattr(parallel, "_ray_module", lambda: fake)
    with parallel.Pool(2, "auto") as pool, pytest.raises(parallel.TasksFailed) as got:
        pool.run([(sleep_and_return, dict(v=0, s=0.0))], progress=False)
    assert str(got.value) == f"no Ray worker could start (2 tried): {err}"
    fake = _FakeRay(cpus=2, free=2, starts=[err, True])  # one node wrong: the other runs the tasks, and the one
    monkeypatch.setattr(parallel, "_ray_module", lambda: fake)  # left out is named with its cause (it was silent)
    with parallel.Pool(2, "auto") as pool, pytest.warns(RuntimeWarning) as got_warnings:
        assert pool.run([(sleep_and_return, dict(v=i, s=0.0)) for i in range(3)], progress=False) == [0, 1, 2]
    assert [a.calls for a in fake.actors] == [0, 3]
    assert [str(w.message) for w in got_warnings] == [f"a Ray worker could not start and gets no tasks (1 of 2 so "
                                                      f"far): {err}"]


def test_the_slow_start_warning_names_a_worker_that_could_not_start(monkeypatch):
    """One actor failed to start, the other waits for a CPU: after SLOW_START_S the warning names the failure's cause
    (it said "(warned)" of a failure no warning had named: those are warned of once an actor has started)."""
    err = RuntimeError("worker on node-7 runs other code than the caller")
    fake = _FakeRay(cpus=2, free=0, starts=[err, False])
    actors = [fake.remote()(object).remote() for _ in range(2)]
    starting = ray_start.Starting(fake, actors)
    starting.admit([])
    monkeypatch.setattr(ray_start, "SLOW_START_S", 0.0)
    with pytest.warns(RuntimeWarning) as got:
        starting.warn_if_slow()
    assert [str(w.message) for w in got] == [
        "none of the 2 Ray workers has started after 0 s; 1 could not start (worker on node-7 runs other code than "
        "the caller): the cluster has 0 CPUs free of 2 (other jobs hold the rest); the tasks start when a worker does"]


def test_a_local_worker_that_cannot_start_names_its_cause(monkeypatch):
    """The caller says numpy '0.0-other'; each spawned worker reads its own numpy version, refuses, and every task
    reports that (it was "BrokenProcessPool: A process in the process pool was terminated abruptly")."""
    real = pool_workers.versions()
    monkeypatch.setattr(parallel, "versions", lambda: dict(real, numpy="0.0-other"))
    with parallel.Pool(2) as pool, pytest.raises(parallel.TasksFailed) as got:
        pool.run([(sleep_and_return, dict(v=i, s=0.0)) for i in range(2)], progress=False, labels=["a", "b"])
    text = str(got.value)  # the failures in the order they were noticed: either task first
    for label in ("a", "b"):
        assert f"{label} failed: RuntimeError: the worker could not start: RuntimeError: worker on " in text
    assert f"runs other code than the caller: numpy '{real['numpy']}' here, '0.0-other' at the caller" in text


@pytest.mark.parametrize("workers", [0, 2])
def test_a_task_that_calls_sys_exit_is_named(workers):
    with parallel.Pool(workers) as pool, pytest.raises(parallel.TasksFailed, match=r"^seed 4 failed: RuntimeError: "
                                                       r"the task called sys.exit\(3\)"):
        pool.run([(exits, dict(code=3))], progress=False, labels=["seed 4"])


def dies() -> None:
    """A task that ends its process at once."""
    os._exit(7)


def test_a_local_worker_that_dies_is_said_to_have_died():
    """A worker process ended by its task: the failure says a worker process ended abruptly, where it read as if
    each task running then had raised an error of its own."""
    with pytest.raises(parallel.TasksFailed) as got:  # the task beside it may be named first
        parallel.run_tasks([(dies, {}), (sleep_and_return, dict(v=1, s=2.0))], workers=2, progress=False)
    assert re.search(r"task 0 \(\S*dies, \[\]\) failed: BrokenProcessPool: a local worker process ended abruptly",
                     str(got.value))


def test_results_keep_the_task_order_whatever_order_they_end_in():
    """Uneven sleeps on two workers: task 0 ends last, yet the results are 0..5 in the tasks' order."""
    sleeps = [0.9, 0.0, 0.3, 0.0, 0.2, 0.0]
    assert parallel.run_tasks([(sleep_and_return, dict(v=i, s=s)) for i, s in enumerate(sleeps)], workers=2,
                              progress=False) == list(range(6))


def test_an_address_that_does_not_answer_is_refused_in_seconds(monkeypatch):
    with socket.socket() as closed:  # a port nothing listens on: bound, then released
        closed.bind(("127.0.0.1", 0))
        port = closed.getsockname()[1]
    t0 = time.monotonic()
    with pytest.raises(UsageError, match=rf"--ray 127.0.0.1:{port}: no Ray cluster answers at 127.0.0.1:{port}"):
        ray_start.probe(f"127.0.0.1:{port}")
    with pytest.raises(UsageError, match=rf"--ray ray://127.0.0.1:{port}: no Ray cluster answers"):
        ray_start.probe(f"ray://127.0.0.1:{port}")
    monkeypatch.setenv("RAY_ADDRESS", f"127.0.0.1:{port}")
    with pytest.raises(UsageError, match=rf"--ray auto \(RAY_ADDRESS=127.0.0.1:{port}\): no Ray cluster answers"):
        ray_start.probe("auto")
    assert time.monotonic() - t0 < 3 * ray_start.PROBE_TIMEOUT_S
    with socket.socket() as server:  # a port that listens: accepted
        server.bind(("127.0.0.1", 0))
        server.listen()
        ray_start.probe(f"127.0.0.1:{server.getsockname()[1]}")
    monkeypatch.delenv("RAY_ADDRESS")
    for left_to_ray in ("auto", "local", "head-node"):
        ray_start.probe(left_to_ray)


@pytest.mark.slow
def test_on_a_real_cluster_with_a_cpu_taken_the_batch_ends_and_runners_are_checked():
    """A 2-CPU local Ray, one CPU held by another job's actor: a batch on every CPU's actor ends with its results in
    order (it hung); RLlib's env runners beyond the cluster's 2 CPUs are refused by name."""
    ray = pytest.importorskip("ray")
    from laddermill_gym.harness.rllib_train import check_runner_cpus

    started = not ray.is_initialized()
    if started:
        ray.init(num_cpus=2, include_dashboard=False, logging_level="warning", runtime_env={
            "env_vars": {"PYTHONPATH": os.pathsep.join([os.path.dirname(__file__), os.environ.get("PYTHONPATH", "")])}})
    try:
        holder = ray.remote(num_cpus=1)(type("Holder", (), {"ping": lambda self: 1})).remote()
        ray.get(holder.ping.remote())
        with parallel.Pool(2, "auto") as pool:
            assert pool.run([(sleep_and_return, dict(v=i, s=0.05)) for i in range(4)], progress=False) == [0, 1, 2, 3]
        assert check_runner_cpus(2) is None
        assert check_runner_cpus(3) == ("--env-runners 3: the Ray cluster has 2 CPUs, one per env runner (the runners "
                                        "beyond them would never start)")
        ray.kill(holder)
    finally:
        if started:
            ray.shutdown()


def test_a_failed_task_is_named_in_a_fresh_interpreter():
    """A serial batch's failure report in a process where no local pool ever ran: it used to end in an
    AttributeError (``concurrent.futures.process`` is a submodule that ``import concurrent.futures`` does not load,
    and only a local pool loaded it), so a serial or Ray run's failed task went unnamed unless another test had
    made a local pool first (review of 2026-12-08)."""
    script = ("from laddermill_gym.studies import parallel\n"
              "def boom():\n    raise ValueError('bad input')\n"
              "try:\n    parallel.run_tasks([(boom, {})], progress=False)\n"
              "except parallel.TasksFailed as e:\n    print('TasksFailed', e)\n")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert re.search(r"^TasksFailed task 0 \(__main__\.boom, \[\]\) failed: ValueError: bad input", out.stdout), out
