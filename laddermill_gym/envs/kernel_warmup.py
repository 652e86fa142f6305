"""Compile an env's step kernels in a second process while this one computes its starting point (issue 32 point 1:
cold starts), for every env that has one: TetheredWing-v0 and the other wing ids, Rotorcraft-v0, LadderMill.

A cold start does two long single-threaded things one after the other: it computes the starting point (the wing's
static equilibrium and trim, the craft's trim, the mill's periodic operating point), compiling the kernels that
needs, and it then compiles the step-and-observe kernel at its first call. The step kernel's compiled code depends
on the types of its arguments only, not on the starting point's values. So :func:`start` launches ``python -m
laddermill_gym.envs.warmup_run`` with a target (``"module:function"``) and the task's arguments (pickled, on stdin):
the target builds the same task around a stand-in starting point of the right shapes and types (its values are
never used for a result) and calls the step kernel, so numba compiles exactly the kernels and signatures this
process will call and writes them to its on-disk cache (``NUMBA_CACHE_DIR``, inherited). :meth:`Warmup.wait`,
called before this process's first call of the step kernel, waits for that process; numba then loads the kernels
from its cache as in any warm start: the same machine code, so the same bits as compiling them here (numba's cache
is keyed by the signature, the source and the CPU; a signature the second process did not compile is compiled
here as before).

The wing and craft targets (``envs/task_warmup.py``) compile the step kernel's callees first, in the order the
step kernel's compile reaches them, from their argument types (``dispatcher.compile``, nothing run). The wing env
with a W-method step starts two processes (an RK4 step has no such list): the second takes that list from its
other end, so the two share it through numba's cache (a callee compiled by one is loaded by the other; the one they
reach together is compiled by the first to claim it, ``step_callees.compile_ahead(shared=True)``) while this process
solves the trim; without it the first process
compiled the whole step tree alone while this one waited. Each prints :data:`CALLEES_DONE` when its share is done;
on a machine with fewer than three cores this process waits for both lines before its trim (:func:`await_callees`),
so that the trim's compile runs beside the step kernel's own, whose nested layers compile one after the other on
one core, instead of slowing the callees that all three processes would otherwise share two cores for.
The craft's target leaves out the right-hand side's kernels, which this process compiles for its trim with the
same types: the step kernel's compile then loads them from the cache instead of compiling them again.

This moves CPU seconds to the other core; it removes none: the wall time shrinks only when a second core is free
(docs/cold_start.md). ``LADDERMILL_KERNEL_WARMUP=off`` (:data:`SWITCH`) switches it off for every
env; it is also off when numba's JIT is disabled, when the kernels are already compiled in this process or (for
:func:`start` with ``cached_check``) already in numba's on-disk cache. Any failure of the second process only
costs its time: this process then compiles what it still needs. Env processes started together (SB3's
``SubprocVecEnv``'s, Ray workers') start one warm-up per task and numba cache, not one each (:func:`claim`: a file
lock in the cache's directory that the warm-up process holds while it runs); the others solve their starting points
meanwhile, then wait for it to end (:class:`PeerWarmup`) and load what it compiled. The wing's third process is
chosen from the env's arguments (``physics_step``, ``scene_options``): a scene file of one's own whose integrator is
a W method gets the two-process warm-up.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import pickle
import select
import subprocess
import sys
import time
import warnings

__all__ = ["SWITCH", "CALLEES_DONE", "CHILD_MODULE", "PeerWarmup", "Warmup", "await_callees", "cache_directory",
           "claim", "enabled", "on_disk", "start", "stopped_on_error", "usable_cores", "wait_all"]

#: the environment variable that switches the warm-up off (value ``off``)
SWITCH = "LADDERMILL_KERNEL_WARMUP"
#: the module the second process runs (``python -m``)
CHILD_MODULE = "laddermill_gym.envs.warmup_run"
#: the longest wait for the second process [s], counted from its start (a cold compile takes 30-80 s of CPU on a
#: loaded machine; past this it is stopped and this process compiles what it still needs). The warm-ups a task
#: starts together share it: waiting for two costs at most this, not twice it.
WAIT_LIMIT_S = 900.0
#: the line a wing warm-up process prints once its share of the step kernel's callees is in numba's cache
#: (``envs/task_warmup.py``; :func:`await_callees`)
CALLEES_DONE = "callees compiled"
#: below this many usable cores the first process waits for the callees before compiling its own kernels
#: (:func:`await_callees`)
SHARED_CORES = 3


class Warmup:
    """A running warm-up process; :meth:`wait` (idempotent) waits for it, until :data:`WAIT_LIMIT_S` after its
    start."""

    def __init__(self, proc: subprocess.Popen):
        self.proc = proc
        self.returncode: int | None = None
        self.deadline = time.monotonic() + WAIT_LIMIT_S  # [s] on the monotonic clock
        self._unread = b""  # what the process printed after the last line :meth:`wait_for` found

    def _left(self) -> float:
        """Seconds left until :attr:`deadline` (0 past it)."""
        return max(0.0, self.deadline - time.monotonic())

    def wait_for(self, line: str) -> bool:
        """Wait (until :attr:`deadline`) until the process prints ``line`` on its standard output (started
        with ``signals``); False when it ended, was waited for or closed its output first. Reads the pipe's
        descriptor itself (``os.read``), keeping what follows the line for the next call: a buffered ``readline``
        after ``select`` would hold a second line in its buffer, unseen by ``select``, until the process ends."""
        out = None if self.proc is None else self.proc.stdout
        if out is None:
            return False
        want = line.encode()
        while True:
            while b"\n" in self._unread:
                got, self._unread = self._unread.split(b"\n", 1)
                if got.strip() == want:
                    return True
            if not select.select([out], [], [], self._left())[0]:
                return False
            chunk = os.read(out.fileno(), 65536)
            if not chunk:
                return False
            self._unread += chunk

    def wait(self) -> int | None:
        """Wait for the process; its exit code (None if it had to be stopped). A process that failed or was stopped
        costs only its time (this process compiles what it still needs) and is named in a RuntimeWarning."""
        if self.returncode is None and self.proc is not None:
            try:  # its output read to the end: a warm-up writing more than a pipe holds (numba's debug variables
                if self.proc.stdout is not None:  # print to it) would block until the limit
                    if self.proc.stdin is not None and self.proc.stdin.closed:  # its payload, sent at the start
                        self.proc.stdin = None  # (communicate would flush it)
                    self.proc.communicate(timeout=self._left())
                self.returncode = self.proc.wait(timeout=self._left())
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
            if self.proc.stdout is not None:
                self.proc.stdout.close()
            self.proc = None
            if self.returncode != 0:
                why = (f"was stopped {WAIT_LIMIT_S:.0f} s after its start" if self.returncode is None
                       else f"exited with code {self.returncode}")
                warnings.warn(f"the kernel warm-up process ({CHILD_MODULE}) {why}; this process compiles the "
                              f"kernels it still needs ({SWITCH}=off skips the warm-up)", RuntimeWarning, stacklevel=2)
        return self.returncode

    def stop(self) -> None:
        """Stop the process now and reap it (its caller failed before needing it); idempotent."""
        if self.proc is not None:
            self.proc.kill()
            self.proc.wait()
            if self.proc.stdout is not None:
                self.proc.stdout.close()
            self.proc = None


def usable_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system tells it, else ``os.cpu_count``)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def await_callees(warmups) -> None:
    """With fewer than :data:`SHARED_CORES` usable cores, wait until every warm-up process of ``warmups`` (started
    with ``signals``) has printed :data:`CALLEES_DONE` (or ended; a :class:`PeerWarmup` or None is not waited for).

    The wing's cold start with a W-method step (issue 32 point 1): two warm-up processes compile the step kernel's
    callees, then one of them compiles the step kernel itself, whose compile waits on each callee in turn and so
    runs on one core; this process compiles the in-plane kernels of its trim. On two cores three compiling
    processes share them, and the step kernel's chain, which decides when the env can step, starts only once
    the callees are done: called before the trim, this makes the trim's compile run beside that chain on the core
    it leaves free instead of slowing the callees. Where there are cores enough for all three it returns at once.
    The same kernels are compiled, in other processes or at other times: the same machine code, the same bits."""
    if usable_cores() >= SHARED_CORES:
        return
    for warmup in warmups:
        if isinstance(warmup, Warmup):
            warmup.wait_for(CALLEES_DONE)


@contextlib.contextmanager
def stopped_on_error(warmups):
    """Run the block; if it raises, stop every warm-up of ``warmups`` (:class:`Warmup` or None) first, so a task
    whose construction fails (a bad argument, a trim that does not converge) leaves no process compiling behind."""
    try:
        yield
    except BaseException:
        for warmup in warmups:
            if warmup is not None:
                warmup.stop()
        raise


def wait_all(warmups) -> None:
    """Wait for every warm-up of ``warmups`` (:class:`Warmup`, :class:`PeerWarmup` or None) before the first kernel
    call; if a wait raises (Ctrl-C, its warning turned into an error), stop the others first: the waits stood outside
    :func:`stopped_on_error`, and an interrupted construction left a warm-up compiling, holding its lock (a review of
    2026-12-08)."""
    with stopped_on_error(warmups):
        for warmup in warmups:
            if warmup is not None:
                warmup.wait()


def enabled(kernels) -> bool:
    """Whether a warm-up can help: not switched off, numba's JIT on, and none of ``kernels`` (dispatchers)
    compiled in this process yet."""
    from numba.core import config

    if os.environ.get(SWITCH, "").strip().lower() == "off" or config.DISABLE_JIT:
        return False
    return not any(k.signatures for k in kernels)


def on_disk(kernels) -> bool:
    """Whether numba's on-disk cache holds a current entry (any signature, compiled from today's source) of any of
    ``kernels``: then a start loads them in about a second and a second process would only cost its own start.
    False when it cannot tell (a dispatcher without a cache)."""
    for k in kernels:
        try:
            if k._cache._cache_file._load_index():  # numba's index: {(signature, target): file}, {} when stale
                return True
        except AttributeError:
            continue
    return False


class PeerWarmup:
    """A warm-up of the same task into the same numba cache that another process runs (:func:`claim` refused this
    one): :meth:`wait` waits, until :attr:`deadline`, for that process to end (its lock released), so that this
    process then loads what it compiled instead of compiling it a second time beside it. Same interface as
    :class:`Warmup`; what it does not do: read the other process's output (:meth:`wait_for` is False at once, so
    the mill's peer compiles the static equilibrium's kernel itself unless the other process has cached it)."""

    def __init__(self, path: str):
        self.path = path
        self.proc = None
        self.returncode: int | None = None
        self.deadline = time.monotonic() + WAIT_LIMIT_S  # [s] on the monotonic clock

    def wait_for(self, line: str) -> bool:
        """False: another process's output is not read (this process compiles what it needs before the wait)."""
        return False

    def wait(self) -> int | None:
        """Wait for the other process's warm-up to end; 0 when it did, None when the deadline passed first or the
        lock cannot be asked (named in a RuntimeWarning; this process then compiles what it still needs).
        Idempotent."""
        if self.returncode is None and self.path is not None:
            import fcntl

            why = f"still ran {WAIT_LIMIT_S:.0f} s after this env's construction began"
            try:
                fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o600)
            except OSError as e:
                fd, why = -1, f"cannot be waited for ({e})"
            try:
                while fd >= 0:
                    try:
                        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                        self.returncode = 0
                        break
                    except BlockingIOError:  # still held
                        if time.monotonic() >= self.deadline:
                            break
                        time.sleep(0.2)
                    except OSError as e:  # a file system without flock: no use waiting
                        why = f"cannot be waited for ({e})"
                        break
            finally:
                if fd >= 0:
                    os.close(fd)  # releases the lock if taken
            if self.returncode is None:
                warnings.warn(f"another process's kernel warm-up ({self.path}) {why}; this process compiles the "
                              f"kernels it still needs", RuntimeWarning, stacklevel=2)
            self.path = None
        return self.returncode

    def stop(self) -> None:
        """Nothing to stop (the other process's warm-up serves its own env); stops waiting."""
        self.path = None


def cache_directory(kernels) -> str | None:
    """The directory numba's on-disk cache of the first of ``kernels`` (dispatchers) uses (``NUMBA_CACHE_DIR``'s
    subfolder, the source's ``__pycache__`` or numba's user-wide fallback), or None when it has none."""
    for k in kernels:
        path = getattr(getattr(k, "_cache", None), "_cache_path", None)
        if isinstance(path, str) and path:
            return path
    return None


def claim(payload: bytes, directory: str | None) -> tuple[int | None, str | None]:
    """(descriptor, path): an open file descriptor holding an exclusive lock (``flock``) on the file ``path`` named
    for ``payload`` in ``directory`` (numba's cache directory of the task's kernels, :func:`cache_directory`: the
    same task into the same cache shares one file; the file stays beside the cache it guards), or descriptor None
    when another process holds it (a warm-up of the same task into the same cache is running: several env
    processes started together, e.g. by SB3's ``SubprocVecEnv``, start one, not one each). (-1, None), no lock,
    where there is no directory, no ``flock`` (not POSIX), the file cannot be opened or the file system refuses
    ``flock``."""
    try:
        import fcntl
    except ImportError:
        return -1, None
    if directory is None:
        return -1, None
    path = os.path.join(directory, f"laddermill-warmup-{hashlib.sha256(payload).hexdigest()[:20]}.lock")
    try:
        os.makedirs(directory, exist_ok=True)
        fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o600)
    except OSError:
        return -1, None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:  # held by another process
        os.close(fd)
        return None, path
    except OSError:  # ENOLCK, ENOSYS: a file system without flock
        os.close(fd)
        return -1, None
    return fd, path


def start(target: str, task_kwargs: dict, kernels, cached_check: bool = False,
          signals: bool = False) -> Warmup | PeerWarmup | None:
    """Launch the warm-up process that calls ``target`` (``"module:function"``, a function of one dict) with
    ``task_kwargs`` when :func:`enabled` (and, with ``cached_check``, ``kernels`` are not :func:`on_disk`); None
    when not or when the arguments do not pickle; a :class:`PeerWarmup` (which waits for it) when a warm-up of the
    same target and arguments into the same cache runs in another process (:func:`claim`: the warm-up process holds
    the lock until it ends). With ``signals`` its standard output is a pipe the target prints lines on
    (:meth:`Warmup.wait_for`); else it is discarded."""
    if not enabled(kernels) or (cached_check and on_disk(kernels)):
        return None
    try:
        payload = pickle.dumps((str(target), dict(task_kwargs)))
    except Exception:  # an argument that does not pickle: compile here as before
        return None
    lock, path = claim(payload, cache_directory(kernels))
    if lock is None:
        return PeerWarmup(path)
    try:
        proc = subprocess.Popen([sys.executable, "-m", CHILD_MODULE], stdin=subprocess.PIPE,
                                stdout=subprocess.PIPE if signals else subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, env=dict(os.environ),
                                pass_fds=() if lock < 0 else (lock,))
    finally:
        if lock >= 0:
            os.close(lock)  # the child's inherited descriptor holds the lock until it ends
    try:
        proc.stdin.write(payload)
        proc.stdin.close()
    except OSError:
        pass
    return Warmup(proc)
