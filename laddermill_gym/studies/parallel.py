"""Run independent tasks serially, in local worker processes or on a Ray cluster, with the same results.

A task is a plain picklable pair ``(function, kwargs)``: a module-level function (pickled by its module and
name, so every worker must have the same package installed) and a dict of picklable arguments. Every way of
running returns the results in the order of the tasks:

* serial (``workers=0``, the default): in this process, one after the other;
* local processes (``workers=N``): :class:`concurrent.futures.ProcessPoolExecutor` with N workers started by
  ``spawn`` (a fresh interpreter, never a fork of a process whose numba threads are running);
* Ray (``ray="local"|"auto"|ADDRESS``): N Ray actors (one CPU each; N = ``workers`` or the cluster's CPUs).

Warm-up. A fresh process pays numba's compile of every kernel a task reaches on its first call (94 s of wall
time for one environment on a loaded 2-core machine with an empty cache), or a load from the on-disk cache
(``__pycache__`` or ``NUMBA_CACHE_DIR``, 0.43 s; measured by
``python -m laddermill_gym.studies.benchmarks.parallel_cost``).
Each worker therefore runs the caller's ``warmup`` tasks once, when it starts, before its first task (a short
episode of every environment and controller the tasks use): the compile or cache load happens once per worker,
never per task, and the worker's numba thread count is set to its share of the cores. A worker with another
laddermill_gym, numba or numpy version than the caller refuses to start; one whose package source differs (a
digest of its ``.py`` files: an edited file) is reported as a RuntimeWarning.
Measured figures and the cluster set-up: ``laddermill_gym/docs/scale_out.md``.

    laddermill workers warm   # compile or load every gusts-v1 env's kernels; prints the time
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import hashlib
import multiprocessing
import os
import socket
import sys
import time
import uuid
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

from tqdm import tqdm

__all__ = ["Task", "Pool", "TasksFailed", "run_tasks", "worker_report", "source_digest", "add_arguments",
           "check_arguments", "RAY_HINT"]

#: One task: a module-level function and its keyword arguments (both picklable).
Task = tuple[Callable[..., Any], dict]

#: What to install for ``--ray``.
RAY_HINT = 'Ray is an optional extra: pip install "laddermill_gym[ray]" (or "ray[default]") on every node'

# The state of this process as a worker: the run it warmed up for, how often it warmed up for that run and the
# warm-up's wall time [s].
_STATE: dict[str, Any] = {"run": None, "warmups": 0, "warmup_s": 0.0}


def source_digest() -> str:
    """SHA-256 (first 16 hex digits) over the relative paths and contents of the package's ``.py`` files: two
    processes with the same digest run the same code (computed afresh at every call: about 15 ms; an edit
    between the caller's start of a run and a worker's start is caught)."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        h.update(path.relative_to(root).as_posix().encode())
        h.update(path.read_bytes())
    return h.hexdigest()[:16]


def _versions() -> dict[str, str]:
    import numba
    import numpy

    import laddermill_gym

    return {"laddermill_gym": laddermill_gym.__version__, "source": source_digest(), "numba": numba.__version__,
            "numpy": numpy.__version__}


def _init_worker(run_id: str, warmup: tuple, threads: int | None, versions: dict) -> None:
    """Per-worker start: check the versions against the caller's, set numba's thread count, run the warm-up.

    Another package version, numba or numpy raises RuntimeError; other package source (an edited file) only
    leaves a note that the caller turns into a warning (a shared working tree changes under a run)."""
    here = _versions()
    bad = {k: (v, here.get(k)) for k, v in versions.items() if here.get(k) != v}
    text = ", ".join(f"{k} {w!r} here, {v!r} at the caller" for k, (v, w) in bad.items())
    where = f"worker on {socket.gethostname()} (pid {os.getpid()})"
    if set(bad) - {"source"}:
        raise RuntimeError(f"{where} runs other code than the caller: {text}; install the same laddermill_gym on "
                           "every node")
    if threads:
        import numba

        numba.set_num_threads(min(int(threads), numba.config.NUMBA_NUM_THREADS))
    t0 = time.perf_counter()
    for fn, kw in warmup:
        fn(**kw)
    if _STATE["run"] != run_id:
        _STATE.update(run=run_id, warmups=0, warmup_s=0.0)
    _STATE["warmups"] += 1
    _STATE["warmup_s"] += time.perf_counter() - t0
    _STATE["note"] = f"{where} runs other package source than the caller ({text})" if bad else ""


def _call(index: int, fn: Callable, kwargs: dict) -> tuple[int, Any, str]:
    """(index, the task's result, the worker's version note: given once, then "")."""
    result = fn(**kwargs)
    return index, result, _STATE.pop("note", "")


def worker_report() -> dict:
    """A task that describes the process running it: host, pid, run id, warm-ups done for that run and their
    wall time [s], numba's thread count."""
    import numba

    return {"host": socket.gethostname(), "pid": os.getpid(), "run": _STATE["run"], "warmups": _STATE["warmups"],
            "warmup_s": _STATE["warmup_s"], "numba_threads": numba.get_num_threads()}


def _warn(note: str) -> None:
    if note:
        warnings.warn(note, RuntimeWarning, stacklevel=3)


def _label(index: int, task: Task) -> str:
    """A task's default name in a failure's report: its index, function and argument names."""
    fn, kw = task
    return f"task {index} ({fn.__module__}.{fn.__qualname__}, {sorted(kw)})"


def _first_line(err: BaseException) -> str:
    """An exception's message without a remote traceback (a Ray task's error carries the worker's)."""
    cause = getattr(err, "cause", None)  # RayTaskError: the worker's own exception
    lines = [x for x in str(cause if isinstance(cause, BaseException) else err).splitlines() if x.strip()]
    return lines[0] if lines else ""


class TasksFailed(RuntimeError):
    """Tasks of a :meth:`Pool.run` batch failed (the message names each; the first one's exception is the cause)."""


def _failed(failures: list, labels: list[str], done: int, total: int) -> TasksFailed:
    """The error of a batch whose tasks ``failures`` ((index, exception), in the order they failed) failed; ``done``
    of the ``total`` tasks completed."""
    text = "; ".join(f"{labels[i]} failed: {type(err).__name__}: {_first_line(err)}" for i, err in failures)
    return TasksFailed(f"{text} ({done} of {total} tasks completed; the others were not started)" if done < total
                       - len(failures) else text)


def _ray_module():
    try:
        import ray
    except ImportError:
        raise RuntimeError(f"--ray: {RAY_HINT}") from None
    return ray


class _RayWorker:
    """The Ray actor: one worker process that warms up once (in ``__init__``) and then runs tasks."""

    def __init__(self, *init_args):
        _init_worker(*init_args)

    def call(self, index: int, fn: Callable, kwargs: dict) -> tuple[int, Any, str]:
        return _call(index, fn, kwargs)


class Pool:
    """Workers that warm up once and then run any number of batches of tasks::

        with Pool(workers=2, warmup=[(fn, kwargs)]) as pool:
            first = pool.run(tasks)             # results in the order of tasks
            second = pool.run(more_tasks)       # the same warmed-up workers

    Parameters
    ----------
    workers : int        0: serially in this process; N >= 1: N local worker processes (``spawn``), or N Ray
                         actors with ``ray`` (0 with ``ray``: one per CPU of the cluster)
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
        self._init = (uuid.uuid4().hex, warm, threads if (workers or ray) else None, _versions())
        self._ex = self._ray = None
        self._actors: list = []
        self._started_ray = False

    def __enter__(self) -> Pool:
        if self.ray is not None:
            self._ray = _ray_module()
            if not self._ray.is_initialized():
                if self.ray == "local":
                    self._ray.init(num_cpus=self.workers or os.cpu_count(), include_dashboard=False,
                                   logging_level="warning")
                else:
                    self._ray.init(address=self.ray, logging_level="warning")
                self._started_ray = True
            cpus = int(self._ray.cluster_resources().get("CPU", 0))
            if self.workers > cpus:  # an actor takes one CPU: those beyond the cluster's would never start
                self.__exit__()
                from laddermill_gym.studies.commands import UsageError

                raise UsageError(f"--workers {self.workers}: the Ray cluster ({self.ray}) has {cpus} CPUs, one per "
                                 "worker")
            n = self.workers or max(1, cpus)
            n = max(1, min(n, self.cap)) if self.cap is not None else n
            actor = self._ray.remote(num_cpus=1)(_RayWorker)
            self._actors = [actor.remote(*self._init) for _ in range(n)]
        elif self.workers:
            self._ex = cf.ProcessPoolExecutor(self.workers, mp_context=multiprocessing.get_context("spawn"),
                                              initializer=_init_worker, initargs=self._init)
        else:
            _init_worker(*self._init)
        return self

    def __exit__(self, *exc) -> None:
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
        finish (and reach ``on_result``); then RuntimeError names every failed task by its ``labels`` entry
        (default: index, function and argument names)."""
        tasks = [(fn, dict(kw)) for fn, kw in tasks]
        labels = [_label(i, t) for i, t in enumerate(tasks)] if labels is None else [str(x) for x in labels]
        out: list = [None] * len(tasks)
        failures, done = [], 0
        with tqdm(total=len(tasks), desc=desc, unit=unit, disable=not progress, smoothing=0.0) as bar:
            for i, result, note, err in self._completed(tasks):
                if err is not None:
                    failures.append((i, err))
                    continue
                _warn(note)
                out[i] = result
                done += 1
                bar.update()
                if on_result is not None:
                    on_result(i, result)
        if failures:
            raise _failed(failures, labels, done, len(tasks)) from failures[0][1]
        return out

    def _completed(self, tasks):
        """(index, result, note, None) of every task as it completes, (index, None, "", exception) of a failed one;
        after a failure no task starts. Local processes and Ray actors get a task when one is free (so none waits
        in a queue that a failure or Ctrl-C could not empty); serially, a failure ends the batch."""
        if not (self._actors or self._ex is not None):
            for i, task in enumerate(tasks):
                try:
                    yield (*_call(i, *task), None)
                except Exception as err:
                    yield i, None, "", err
                    return
            return
        queue, running, failed = list(range(len(tasks)))[::-1], {}, False
        free = list(self._actors) if self._actors else [None] * self.workers
        while queue or running:
            while queue and free and not failed:
                i, slot = queue.pop(), free.pop()
                ref = (slot.call.remote(i, *tasks[i]) if slot is not None else
                       self._ex.submit(_call, i, *tasks[i]))
                running[ref] = (i, slot)
            if not running:
                return
            done = (self._ray.wait(list(running), num_returns=1)[0] if self._actors else
                    cf.wait(running, return_when=cf.FIRST_COMPLETED)[0])
            for ref in done:
                i, slot = running.pop(ref)
                free.append(slot)
                try:
                    yield (*(self._ray.get(ref) if self._actors else ref.result()), None)
                except Exception as err:
                    failed = True
                    yield i, None, "", err


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
