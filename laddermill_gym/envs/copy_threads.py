"""The vector envs' copies on several threads: the single env's compiled step kernel (``nogil``) run on
contiguous ranges of copies, one range per thread (issue 32).

Two ways to run the ranges, the same bits either way (each copy's arithmetic is the kernel's own):

- **numba's thread pool** (the kernel's *launcher*, ``launch_step_observe`` beside each step kernel): a ``prange``
  loop over the ranges that calls the kernel through its address (``kernels/far_call.py``), so it compiles only the
  loop, not the step again. A prange kernel that linked the copy step took 165 s of CPU to compile on a 2-core
  AVX2 machine (its parallel lowering re-analyses and re-optimises the whole inlined step five times over).
- **a pool of Python threads**, for a kernel without a launcher and in a process forked from one whose numba
  threads run on GNU OpenMP (not fork-safe: numba would end the process at the first parallel loop,
  ``kernels/fork_state.py``). Each range is then a future and two handovers of the GIL: on a 16-core virtual
  machine (2026-12-04) TetheredWing-v0 at 512 copies ran 1.84x faster on 16 threads than on one (0.93x on two),
  so the launcher is the default.

The thread count is numba's (``numba.get_num_threads()``, as ``numba.set_num_threads`` and ``NUMBA_NUM_THREADS``
set it), read at each call, so the existing controls of a run's parallelism keep working.

On the Python threads, each range is a call from Python, and a numba dispatcher types every argument before it
releases the GIL: about 12-18 us for the wing kernel's 21 arguments (two model namedtuples of some 100 arrays), one
after another across the threads. So only the calling thread goes through the dispatcher; the other ranges call the
compiled entry point it chose (about 3 us), but only when every argument is the object of that typed call or a
float or array of the same numba type (dtype, dimensions, layout, writeable, alignment): otherwise every range goes
through the dispatcher, and the next call's types are kept.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np

from laddermill_gym.kernels.fork_state import forked_after_gnu_openmp

__all__ = ["CopyThreads", "copy_ranges"]


def copy_ranges(n_copies: int, n_threads: int) -> list[tuple[int, int]]:
    """``n_copies`` copies split into at most ``n_threads`` contiguous (first, last) ranges whose sizes differ by at
    most one, in order; none empty."""
    k = max(1, min(int(n_threads), int(n_copies)))
    q, r = divmod(int(n_copies), k)
    out, first = [], 0
    for i in range(k):
        last = first + q + (1 if i < r else 0)
        out.append((first, last))
        first = last
    return out


class CopyThreads:
    """Callable as the step kernel it wraps: ``runner(*args)`` runs ``kernel(*args, first, last)`` on the copies
    0..``n_copies``-1, in one call when ``parallel`` is False (or numba's thread count is 1), else on
    ``numba.get_num_threads()`` ranges (:func:`copy_ranges`): through ``launcher(bounds, *args)`` (numba's threads;
    ``bounds`` (n_ranges, 2) int64) where one is given and numba's pool can run in this process, else one range in
    the calling thread and the others on a pool of Python threads kept for the next call. The kernel must release
    the GIL (``nogil=True``) and write only its copies' rows. An exception in any range is raised here after all
    ranges have ended."""

    def __init__(self, kernel, n_copies: int, parallel: bool, launcher=None):
        self.kernel = kernel
        self.launcher = launcher
        self._bounds: dict[int, np.ndarray] = {}  # thread count -> the launcher's ranges
        self.n_copies = int(n_copies)
        self.parallel = bool(parallel)
        self._pool = None
        self._pool_size = 0
        self._pool_pid = 0
        self._typed = None  # (arguments, keys, entry point) of the last call typed by the dispatcher

    def __call__(self, *args) -> None:
        n = numba.get_num_threads() if self.parallel else 1
        ranges = copy_ranges(self.n_copies, n)
        if len(ranges) == 1:
            self.kernel(*args, 0, self.n_copies)
            return
        if self.launcher is not None and not forked_after_gnu_openmp():
            bounds = self._bounds.get(len(ranges))
            if bounds is None:
                bounds = self._bounds[len(ranges)] = np.array(ranges, dtype=np.int64)
            self.launcher(bounds, *args)
            return
        keys = [_type_key(a) for a in args]
        entry = self._entry_point(args, keys)
        pool = self._workers(len(ranges) - 1)
        futures = [pool.submit(entry, *args, first, last) for first, last in ranges[1:]]
        error = None
        try:
            self.kernel(*args, *ranges[0])  # typed by the dispatcher (compiled on a first call)
        except BaseException as e:  # noqa: BLE001 (raised below, once the other ranges have ended)
            error = e
        if entry is self.kernel and error is None:
            self._remember(args, keys)
        for f in futures:
            e = f.exception()
            if error is None and e is not None:
                error = e
        if error is not None:
            raise error

    def _entry_point(self, args, keys):
        """The compiled entry point of the last call typed by the dispatcher when ``args`` have its types (the same
        objects, or floats and arrays of the same numba type: ``keys``, :func:`_type_key`), else the dispatcher."""
        t = self._typed
        if t is not None and len(t[0]) == len(args) and all(
                k == kb if k is not None else a is b for a, b, k, kb in zip(args, t[0], keys, t[1], strict=True)):
            return t[2]
        return self.kernel

    def _remember(self, args, keys) -> None:
        """Keep the entry point of the specialisation the dispatcher just ran for ``args`` (typed once here, about
        a millisecond; None when none matches)."""
        sig = tuple(numba.typeof(a) for a in (*args, 0, 0))
        compiled = self.kernel.overloads.get(sig)
        self._typed = None if compiled is None else (args, keys, compiled.entry_point)

    def _workers(self, n: int) -> ThreadPoolExecutor:
        """A pool of at least ``n`` threads of this process: a pool inherited through ``fork`` has no threads in
        the child (its work would wait for ever), so a child starts its own."""
        if self._pool is not None and self._pool_pid != os.getpid():
            self._pool, self._pool_size = None, 0  # the parent's: nothing to shut down here
        if self._pool is None or self._pool_size < n:
            if self._pool is not None:
                self._pool.shutdown(wait=True)
            self._pool = ThreadPoolExecutor(max_workers=n, thread_name_prefix="laddermill-copies")
            self._pool_size, self._pool_pid = n, os.getpid()
        return self._pool

    def close(self) -> None:
        """Stop the pool's threads (a later call starts them again)."""
        if self._pool is not None and self._pool_pid == os.getpid():
            self._pool.shutdown(wait=True)
        self._pool, self._pool_size = None, 0

    def __getstate__(self) -> dict:  # threads do not pickle: a copy starts its own pool when it needs one
        state = dict(self.__dict__)
        state["_pool"], state["_pool_size"], state["_typed"] = None, 0, None
        return state


def _type_key(a):
    """What numba's type of ``a`` depends on, for a float or an array (None for anything else: those must be the
    very object of the typed call)."""
    if type(a) is float:
        return float
    if type(a) is np.ndarray:
        f = a.flags
        return a.dtype, a.ndim, f.c_contiguous, f.f_contiguous, f.writeable, f.aligned
    return None
