"""The vector envs' copies on several threads: one compiled step kernel (``nogil``) called on contiguous ranges of
copies from a small pool of Python threads (issue 32).

Why not numba's ``prange``: a prange kernel around the copy step compiled the whole step a second time, and its
parallel lowering analyses and optimises the inlined step five times over (the loop body, its gufunc and its two
wrappers): 165 s of CPU for TetheredWing-v0's on a 2-core AVX2 machine, on top of the single env's 55 s. Calling the
single env's kernel on ranges of copies compiles nothing more, and each copy's arithmetic is that kernel's, so the
vector envs give the single env's bits whatever the thread count.

The thread count is numba's (``numba.get_num_threads()``, as ``numba.set_num_threads`` and ``NUMBA_NUM_THREADS``
set it), read at each call, so the existing controls of a run's parallelism keep working.

Each range is a call from Python, and a numba dispatcher types every argument before it releases the GIL: about
12-18 us for the wing kernel's 21 arguments (two model namedtuples of some 100 arrays), one after another across
the threads. So only the calling thread goes through the dispatcher; the other ranges call the compiled entry
point it chose (about 3 us), but only when every argument is the object of that typed call or a float or array of
the same numba type (dtype, dimensions, layout, writeable, alignment): otherwise every range goes through the
dispatcher, and the next call's types are kept.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np

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
    ``numba.get_num_threads()`` ranges (:func:`copy_ranges`), one in the calling thread and the others on a pool of
    threads kept for the next call. The kernel must release the GIL (``nogil=True``) and write only its copies'
    rows. An exception in any range is raised here after all ranges have ended."""

    def __init__(self, kernel, n_copies: int, parallel: bool):
        self.kernel = kernel
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
