"""The worker side of a batch (:mod:`laddermill_gym.studies.parallel`): a worker's start (versions, numba's thread
count, the warm-up), its calls, its report, and how it hears its caller's Ctrl-C.

A worker process does not take the terminal's Ctrl-C as its own. The terminal sends SIGINT to its whole process group,
which holds the local worker processes (Ray's actors run in groups of their own); a worker ignores it
(:func:`~laddermill_gym.sim.interrupt.ignore_terminal_interrupts`), so that a Ctrl-C that reaches a worker while it
warms up, waits for a task or pickles a result cannot kill it (before, one such death broke the local pool, which
then ended every other worker with its unsaved training). The caller passes its first Ctrl-C on as a stop
(:func:`~laddermill_gym.sim.interrupt.request_stop`: a training saves its model and returns) and its second as an
abort: a local worker gets both through two events it listens to in a thread of its own (the abort ends the process),
a Ray actor the stop through :meth:`RayWorker.stop` (a second thread of the actor, while ``call`` runs) and the abort
as ``ray.kill``.
"""

from __future__ import annotations

import hashlib
import os
import socket
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from laddermill_gym.sim.interrupt import ignore_terminal_interrupts, request_stop

__all__ = ["source_digest", "versions", "init_worker", "start_worker", "call_task", "worker_report", "RayWorker",
           "ABORT_STATUS"]

#: A local worker's exit status when its caller aborts the batch (a second Ctrl-C): as a shell's for SIGINT.
ABORT_STATUS = 130

# The state of this process as a worker: the run it warmed up for, how often it warmed up for that run, the warm-up's
# wall time [s] and numba's thread count for the tasks (None: leave it).
_STATE: dict[str, Any] = {"run": None, "warmups": 0, "warmup_s": 0.0, "threads": None}


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


def versions() -> dict[str, str]:
    """The package's version and source digest, numba's and numpy's versions of this process."""
    import numba
    import numpy

    import laddermill_gym

    return {"laddermill_gym": laddermill_gym.__version__, "source": source_digest(), "numba": numba.__version__,
            "numpy": numpy.__version__}


def _listen(stop, abort) -> None:
    """A local worker's listener thread: the caller's stop event asks this process's trainings to stop; its abort
    event ends the process."""
    stop.wait()
    request_stop()
    abort.wait()
    os._exit(ABORT_STATUS)


def init_worker(run_id: str, warmup: tuple, threads: int | None, caller: dict, signals=None) -> None:
    """Per-worker start: check the versions against the ``caller``'s, set numba's thread count, run the warm-up.

    ``signals``: None in the caller's own process (a serial batch: Ctrl-C stays the caller's), ``"ray"`` in a Ray
    actor, or the (stop, abort) events of a local worker process (module docstring). Another package version, numba
    or numpy raises RuntimeError; other package source (an edited file) only leaves a note that the caller turns into
    a warning (a shared working tree changes under a run)."""
    if signals is not None:
        ignore_terminal_interrupts()
    if isinstance(signals, tuple):
        threading.Thread(target=_listen, args=signals, name="laddermill-stop", daemon=True).start()
    here = versions()
    bad = {k: (v, here.get(k)) for k, v in caller.items() if here.get(k) != v}
    text = ", ".join(f"{k} {w!r} here, {v!r} at the caller" for k, (v, w) in bad.items())
    where = f"worker on {socket.gethostname()} (pid {os.getpid()})"
    if set(bad) - {"source"}:
        raise RuntimeError(f"{where} runs other code than the caller: {text}; install the same laddermill_gym on "
                           "every node")
    if threads:
        import numba

        _STATE["threads"] = min(int(threads), numba.config.NUMBA_NUM_THREADS)
        numba.set_num_threads(_STATE["threads"])
    t0 = time.perf_counter()
    for fn, kw in warmup:
        fn(**kw)
    if _STATE["run"] != run_id:
        _STATE.update(run=run_id, warmups=0, warmup_s=0.0)
    _STATE["warmups"] += 1
    _STATE["warmup_s"] += time.perf_counter() - t0
    _STATE["note"] = f"{where} runs other package source than the caller ({text})" if bad else ""


def start_worker(*init_args) -> None:
    """:func:`init_worker` for a worker process or actor: an exception it raises (another version than the caller's,
    a failing warm-up) is kept instead of ending the worker, and every task given to the worker then raises it
    (:func:`call_task`), so that the batch's failure names the cause, where a local pool only said that a process
    ended abruptly and Ray that an actor died in its creation task."""
    _STATE["start_error"] = None
    try:
        init_worker(*init_args)
    except Exception as err:  # reported with every task this worker is given
        _STATE["start_error"] = err


def call_task(index: int, fn: Callable, kwargs: dict) -> tuple[int, Any, str]:
    """(index, the task's result, the worker's version note: given once, then ""). numba's thread count is per
    thread: it is set again here, since a Ray actor runs its calls in another thread than its start. A worker that
    could not start (:func:`start_worker`) raises its start's error; a task that calls ``sys.exit`` raises
    RuntimeError (the same on every path: a SystemExit would otherwise end a serial batch without naming the
    task)."""
    err = _STATE.get("start_error")
    if err is not None:
        raise RuntimeError(f"the worker could not start: {type(err).__name__}: {err}") from err
    if _STATE["threads"]:
        import numba

        numba.set_num_threads(_STATE["threads"])
    try:
        result = fn(**kwargs)
    except SystemExit as exit_:
        raise RuntimeError(f"the task called sys.exit({exit_.code!r})") from None
    return index, result, _STATE.pop("note", "")


def worker_report() -> dict:
    """A task that describes the process running it: host, pid, run id, warm-ups done for that run and their
    wall time [s], numba's thread count."""
    import numba

    return {"host": socket.gethostname(), "pid": os.getpid(), "run": _STATE["run"], "warmups": _STATE["warmups"],
            "warmup_s": _STATE["warmup_s"], "numba_threads": numba.get_num_threads()}


class RayWorker:
    """The Ray actor: one worker process that warms up once (in ``__init__``) and then runs tasks; started with two
    threads, so that :meth:`stop` runs while :meth:`call` does."""

    def __init__(self, *init_args):
        start_worker(*init_args, "ray")

    def ready(self) -> bool:
        """True once the actor has started (its warm-up done); raises its start's error (:func:`start_worker`). The
        pool gives an actor tasks only after this returned: an actor still waiting for a CPU gets none."""
        err = _STATE.get("start_error")
        if err is not None:
            raise RuntimeError(f"the worker could not start: {type(err).__name__}: {err}") from err
        return True

    def call(self, index: int, fn: Callable, kwargs: dict) -> tuple[int, Any, str]:
        return call_task(index, fn, kwargs)

    def stop(self) -> int:
        """The caller's Ctrl-C: the running task's training stops and saves (the number of its open stop blocks)."""
        return request_stop()
