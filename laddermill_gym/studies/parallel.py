"""Run independent tasks serially, in local worker processes or on a Ray cluster, with the same results.

A task is a plain picklable pair ``(function, kwargs)``: a module-level function (pickled by its module and
name, so every worker must have the same package installed) and a dict of picklable arguments. Every way of
running returns the results in the order of the tasks:

* serial (``workers=0``, the default): in this process, one after the other;
* local processes (``workers=N``): :class:`concurrent.futures.ProcessPoolExecutor` with N workers started by
  ``spawn`` (a fresh interpreter, never a fork of a process whose numba threads are running);
* Ray (``ray="local"|"auto"|ADDRESS``): N Ray actors (one CPU each; N = ``workers`` or the cluster's free
  CPUs); an actor gets tasks once it has started, so one waiting for a CPU holds none
  (:mod:`laddermill_gym.studies.ray_start`, which also refuses an address that does not answer).

Warm-up. A fresh process pays numba's compile of every kernel a task reaches on its first call (94 s of wall
time for one environment on a loaded 2-core machine with an empty cache), or a load from the on-disk cache
(``__pycache__`` or ``NUMBA_CACHE_DIR``, 0.43 s; measured by
``python -m laddermill_gym.studies.benchmarks.parallel_cost``).
Each worker therefore runs the caller's ``warmup`` tasks once, when it starts, before its first task (a short
episode of every environment and controller the tasks use): the compile or cache load happens once per worker,
never per task, and the worker's numba thread count is set to its share of the cores. A worker with another
laddermill_gym, numba or numpy version than the caller refuses to start; one whose package source differs (a
digest of its ``.py`` files: an edited file) is reported as a RuntimeWarning. The worker side (and how a worker
hears its caller's Ctrl-C instead of the terminal's) is :mod:`laddermill_gym.studies.pool_workers`.

Ctrl-C. On workers the first Ctrl-C starts no new task and asks the running ones to stop: a training
(``harness/train``) saves its model and returns, as it does serially; other tasks run to their end. Once they
ended, :class:`TasksInterrupted` (a KeyboardInterrupt: exit status 130) names what each did (unless every task had
completed: then their results are returned as usual). Serially Ctrl-C is the running task's, as before. A second
Ctrl-C aborts at once (the local workers end, Ray's actors are killed).
Measured figures and the cluster set-up: ``laddermill_gym/docs/scale_out.md``.

    laddermill workers warm   # compile or load every gusts-v1 env's kernels; prints the time
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import multiprocessing
import os
import sys
import uuid
import warnings
from collections.abc import Callable
from concurrent.futures.process import BrokenProcessPool  # a submodule `import concurrent.futures` does not load
from contextlib import nullcontext
from typing import Any

from tqdm import tqdm

from laddermill_gym.sim.interrupt import children_ignore_interrupts, stop_requests
from laddermill_gym.studies.pool_workers import (
    RayWorker,
    call_task,
    init_worker,
    source_digest,
    start_worker,
    versions,
    worker_report,
)
from laddermill_gym.studies.ray_start import Starting, probe

__all__ = ["Task", "Pool", "TasksFailed", "TasksInterrupted", "STOP_MESSAGE", "run_tasks", "worker_report",
           "source_digest", "add_arguments", "check_arguments", "RAY_HINT"]

#: One task: a module-level function and its keyword arguments (both picklable).
Task = tuple[Callable[..., Any], dict]

#: What to install for ``--ray``.
RAY_HINT = 'Ray is an optional extra: pip install "laddermill_gym[ray]" (or "ray[default]") on every node'

def _warn(note: str) -> None:
    if note:
        warnings.warn(note, RuntimeWarning, stacklevel=3)


def _label(index: int, task: Task) -> str:
    """A task's default name in a failure's report: its index, function and argument names."""
    fn, kw = task
    return f"task {index} ({fn.__module__}.{fn.__qualname__}, {sorted(kw)})"


def _own(err: BaseException) -> BaseException:
    """The task's own exception (a Ray task's error wraps the worker's as its ``cause``)."""
    cause = getattr(err, "cause", None)
    return cause if isinstance(cause, BaseException) else err


def _first_line(err: BaseException) -> str:
    """An exception's type and message without a remote traceback (a broken local pool: what that means, since the
    executor cannot tell which of the tasks running then ended its worker)."""
    if isinstance(err, BrokenProcessPool):
        return ("BrokenProcessPool: a local worker process ended abruptly (a crash, os._exit, the out-of-memory "
                "killer) while this task ran; each task running then is named, the one that ended it among them")
    lines = [x for x in str(_own(err)).splitlines() if x.strip()]
    return f"{type(_own(err)).__name__}: {lines[0] if lines else ''}"


class TasksFailed(RuntimeError):
    """Tasks of a :meth:`Pool.run` batch failed (the message names each; the first one's exception is the cause)."""


class TasksInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped a :meth:`Pool.run` batch of local processes or Ray actors: no task started after it, the running
    ones were asked to stop (a training saves its model) and ended; the message names what each task did."""


#: What the caller prints at the first Ctrl-C of a batch on workers.
STOP_MESSAGE = ("Ctrl-C: no new task starts; the running tasks are asked to stop (a training saves its model and "
                "returns; other tasks run to their end). Ctrl-C again to abort them")


def _interrupted(labels: list[str], outcomes: dict, total: int) -> TasksInterrupted:
    """The error of a batch that Ctrl-C stopped: ``outcomes`` maps a task's index to None (completed) or its
    exception (a stopped training's, or a failure)."""
    ended = [f"{labels[i]}: {_first_line(err)}" for i, err in outcomes.items()
             if err is not None]
    text = f"stopped by Ctrl-C, {sum(e is None for e in outcomes.values())} of {total} tasks completed"
    rest = "" if len(outcomes) == total else f"; {total - len(outcomes)} not started"
    return TasksInterrupted("; ".join([text, *ended]) + rest)


def _failed(failures: list, labels: list[str], done: int, total: int) -> TasksFailed:
    """The error of a batch whose tasks ``failures`` ((index, exception), in the order they failed) failed; ``done``
    of the ``total`` tasks completed."""
    text = "; ".join(f"{labels[i]} failed: {_first_line(err)}" for i, err in failures)
    return TasksFailed(f"{text} ({done} of {total} tasks completed; the others were not started)" if done < total
                       - len(failures) else text)


def _ray_module():
    try:
        import ray
    except ImportError:
        raise RuntimeError(f"--ray: {RAY_HINT}") from None
    return ray


class Pool:
    """Workers that warm up once and then run any number of batches of tasks::

        with Pool(workers=2, warmup=[(fn, kwargs)]) as pool:
            first = pool.run(tasks)             # results in the order of tasks
            second = pool.run(more_tasks)       # the same warmed-up workers

    Parameters
    ----------
    workers : int        0: serially in this process; N >= 1: N local worker processes (``spawn``), or N Ray
                         actors with ``ray`` (0 with ``ray``: one per free CPU of the cluster)
    ray : str or None    None (no Ray), ``"local"`` (start a one-node Ray here with ``workers`` CPUs),
                         ``"auto"`` (join the running cluster: ``RAY_ADDRESS`` or ``ray start`` on this node) or
                         a cluster address (``HOST:6379`` or ``ray://HOST:10001``)
    warmup : sequence    tasks each worker runs once before its first task (serially: once, here)
    threads : int        numba threads per worker (default: this machine's cores / workers, at least 1; Ray
                         actors 1, their CPU share); serially numba's setting stays as it is
    cap : int or None    at most this many Ray actors (the number of tasks: ``workers`` 0 with ``ray`` starts
                         no more actors than there are tasks), None: no cap. More ``workers`` than the cluster has
                         CPUs is refused (an actor beyond them would never start, and its tasks would wait forever).
    """

    def __init__(self, workers: int = 0, ray: str | None = None, warmup=(), threads: int | None = None,
                 cap: int | None = None):
        if not isinstance(workers, int) or isinstance(workers, bool) or workers < 0:
            raise ValueError(f"workers = {workers!r}: must be a whole number >= 0 (0: serial)")
        self.cap = cap
        if threads is None and ray is not None:
            threads = 1
        elif threads is None and workers:
            threads = max(1, (os.cpu_count() or 1) // workers)
        self.workers, self.ray = workers, ray
        warm = tuple((fn, dict(kw)) for fn, kw in warmup)
        self._init = (uuid.uuid4().hex, warm, threads if (workers or ray) else None, versions())
        self._ex = self._ray = None
        self._actors: list = []
        self._starting: Starting | None = None  # the actors' start (ray_start.py), asked at the first batch
        self._started_ray = False
        self._events: tuple = ()
        self._stopped = False  # a Ctrl-C stopped a batch: the workers keep the stop, no later batch starts

    def __enter__(self) -> Pool:
        if self.ray is not None:
            self._ray = _ray_module()
            if not self._ray.is_initialized():
                if self.ray == "local":
                    self._ray.init(num_cpus=self.workers or os.cpu_count(), include_dashboard=False,
                                   logging_level="warning")
                else:
                    probe(self.ray)  # ray.init retries an address that does not answer without end
                    self._ray.init(address=self.ray, logging_level="warning")
                self._started_ray = True
            cpus = int(self._ray.cluster_resources().get("CPU", 0))
            if self.workers > cpus:  # an actor takes one CPU: those beyond the cluster's would never start
                self.__exit__()
                from laddermill_gym.studies.commands import UsageError

                raise UsageError(f"--workers {self.workers}: the Ray cluster ({self.ray}) has {cpus} CPUs, one per "
                                 "worker")
            # workers 0: one actor per CPU free now (other jobs' actors hold the rest), at least one (Ray leaves
            # "CPU" out of the available resources when none is free)
            n = self.workers or max(1, int(self._ray.available_resources().get("CPU", 0)))
            n = max(1, min(n, self.cap)) if self.cap is not None else n
            actor = self._ray.remote(num_cpus=1, max_concurrency=2)(RayWorker)  # a thread for stop() beside call()
            self._actors = [actor.remote(*self._init) for _ in range(n)]
        elif self.workers:
            spawn = multiprocessing.get_context("spawn")
            self._events = (spawn.Event(), spawn.Event())  # the caller's stop and abort (pool_workers)
            self._ex = cf.ProcessPoolExecutor(self.workers, mp_context=spawn, initializer=start_worker,
                                              initargs=(*self._init, self._events))
        else:
            init_worker(*self._init)
        return self

    def __exit__(self, kind=None, *exc) -> None:
        aborted = kind is not None and issubclass(kind, KeyboardInterrupt) and not issubclass(kind, TasksInterrupted)
        if self._events and aborted:  # a second Ctrl-C (or one in the caller's own code): end the local workers
            for event in self._events:
                event.set()
        if self._ex is not None:
            self._ex.shutdown(wait=True, cancel_futures=True)
        for a in self._actors:
            self._ray.kill(a)
        if self._started_ray:
            self._ray.shutdown()

    def run(self, tasks, desc: str = "tasks", unit: str = "task", progress: bool = True, labels=None,
            on_result: Callable[[int, Any], None] | None = None) -> list:
        """Run ``tasks`` (a sequence of :data:`Task`); their results in the order of ``tasks``, a progress bar
        over completed tasks; ``on_result(index, result)`` is called as each completes (a line per task that
        stays on screen whatever the rest does). A failed task stops the start of new ones; the tasks running then
        finish (and reach ``on_result``); then TasksFailed names every failed task by its ``labels`` entry
        (default: index, function and argument names). On local processes or Ray actors the first Ctrl-C stops the
        start of new tasks and asks the running ones to stop (:data:`STOP_MESSAGE`); once they ended,
        TasksInterrupted names each (where every task had completed, their results are returned), and a later
        batch on the same pool raises TasksInterrupted before any task starts; a second Ctrl-C raises
        KeyboardInterrupt at once and ends the workers. Serially Ctrl-C is the running task's (a training saves and
        raises; other tasks raise KeyboardInterrupt)."""
        tasks = [(fn, dict(kw)) for fn, kw in tasks]
        labels = [_label(i, t) for i, t in enumerate(tasks)] if labels is None else [str(x) for x in labels]
        if self._stopped:  # the workers keep the stop (a task would end at its first check), and the user asked it
            raise TasksInterrupted(f"stopped by Ctrl-C during an earlier batch on these workers: none of this "
                                   f"batch's {len(tasks)} tasks started")
        out: list = [None] * len(tasks)
        failures, done, outcomes = [], 0, {}
        serial = not (self._actors or self._ex is not None)
        # on workers the first Ctrl-C is a stop request; serially it stays the running task's (a KeyboardInterrupt)
        with (tqdm(total=len(tasks), desc=desc, unit=unit, disable=not progress, smoothing=0.0) as bar,
              nullcontext() if serial else stop_requests(STOP_MESSAGE) as stop):
            for i, result, note, err in self._completed(tasks, None if serial else stop):
                outcomes[i] = err
                if err is not None:
                    failures.append((i, err))
                    continue
                _warn(note)
                out[i] = result
                done += 1
                bar.update()
                if on_result is not None:
                    on_result(i, result)
        if not serial and stop.requested:  # no later batch starts on these workers (they keep the stop)
            self._stopped = True
            if failures or len(outcomes) < len(tasks):
                raise _interrupted(labels, outcomes, len(tasks))  # (every task completed: their results stand)
        if failures:
            raise _failed(failures, labels, done, len(tasks)) from failures[0][1]
        return out

    def _completed(self, tasks, stop=None):
        """(index, result, note, None) of every task as it completes, (index, None, "", exception) of a failed one;
        after a failure or a ``stop`` request (the caller's Ctrl-C: the running tasks are asked to stop) no task
        starts. Local processes and Ray actors get a task when one is free (so none waits in a queue that a failure
        or Ctrl-C could not empty); serially (``stop`` None), a failure ends the batch."""
        if stop is None:
            for i, task in enumerate(tasks):
                try:
                    yield (*call_task(i, *task), None)
                except Exception as err:
                    yield i, None, "", err
                    return
            return
        queue, running, failed, asked = list(range(len(tasks)))[::-1], {}, False, False
        if self._actors and self._starting is None:
            self._starting = Starting(self._ray, self._actors)
        free = list(self._starting.ready) if self._actors else [None] * self.workers
        while queue or running:
            if self._actors:  # an actor gets tasks once it has started (one waiting for a CPU would hold them)
                try:
                    self._starting.admit(free)
                except RuntimeError as err:
                    raise TasksFailed(str(err)) from err.__cause__
            while queue and free and not failed and not stop.requested:
                i, slot = queue.pop(), free.pop()
                with children_ignore_interrupts():  # a submit may start a local worker (interrupt.py)
                    ref = (slot.call.remote(i, *tasks[i]) if slot is not None else
                           self._ex.submit(call_task, i, *tasks[i]))
                running[ref] = (i, slot)
            if stop.requested and not asked:
                asked = True
                self._ask_to_stop([slot for _, slot in running.values()])
            if not running:
                if not (self._actors and queue and self._starting.refs and not failed and not stop.requested):
                    return
                self._starting.warn_if_slow()  # tasks wait for an actor to start
                self._ray.wait(list(self._starting.refs), num_returns=1, timeout=0.25)
                continue
            done = (self._ray.wait(list(running), num_returns=1, timeout=0.25)[0] if self._actors else
                    cf.wait(running, timeout=0.25, return_when=cf.FIRST_COMPLETED)[0])  # a Ctrl-C noticed in 0.25 s
            for ref in done:
                i, slot = running.pop(ref)
                free.append(slot)
                try:
                    yield (*(self._ray.get(ref) if self._actors else ref.result()), None)
                except Exception as err:
                    failed = True
                    yield i, None, "", err

    def _ask_to_stop(self, busy: list) -> None:
        """Pass the caller's Ctrl-C on to the workers as a stop: every local process (an idle one stops its next
        task at once; none is given one), or the ``busy`` Ray actors."""
        if self._events:
            self._events[0].set()
        for actor in busy:
            if actor is not None:  # a local process's slot is None
                actor.stop.remote()


def run_tasks(tasks, *, workers: int = 0, ray: str | None = None, warmup=(), threads: int | None = None,
              desc: str = "tasks", unit: str = "task", progress: bool = True) -> list:
    """Run ``tasks`` (a sequence of :data:`Task`) on a :class:`Pool` of its own (arguments as there; local
    processes: at most one per task) and return their results in the order of ``tasks``."""
    tasks = list(tasks)
    if not tasks:
        return []
    if ray is None and workers > len(tasks):
        threads = threads or max(1, (os.cpu_count() or 1) // workers)
        workers = len(tasks)
    with Pool(workers, ray, warmup, threads, cap=len(tasks)) as pool:
        return pool.run(tasks, desc, unit, progress)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """``--workers N`` and ``--ray local|auto|ADDRESS`` on a command's parser."""
    p.add_argument("--workers", type=int, default=0, metavar="N",
                   help="local worker processes (0: serial, the default); with --ray: Ray actors (0: one per CPU)")
    p.add_argument("--ray", metavar="ADDRESS", default=None,
                   help="run on Ray: 'auto' (the running cluster), 'local' (start one here) or HOST:PORT / "
                        "ray://HOST:10001; needs the optional extra [ray]")


def check_arguments(args, prog: str) -> None:
    """Refuse a negative ``--workers``, an empty ``--ray`` and ``--ray`` without Ray installed: one line
    ``PROG: error: ...`` naming the option and value on stderr, exit status 2 (as argparse)."""
    msg = None
    if args.workers < 0:
        msg = f"--workers {args.workers}: must be >= 0 (0: serial)"
    elif args.ray is not None and not args.ray.strip():
        msg = "--ray '': give auto, local or a cluster address"
    elif args.ray is not None:
        try:
            _ray_module()
        except RuntimeError as err:
            msg = str(err)
    if msg:
        sys.stderr.write(f"{prog}: error: {msg}\n")
        raise SystemExit(2)
