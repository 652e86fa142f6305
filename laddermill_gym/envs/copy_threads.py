"""The vector envs' copies on several threads: one compiled step kernel (``nogil``) called on contiguous ranges of
copies from a small pool of Python threads (issue 32).

Why not numba's ``prange``: a prange kernel around the copy step compiled the whole step a second time, and its
parallel lowering analyses and optimises the inlined step five times over (the loop body, its gufunc and its two
wrappers): 165 s of CPU for TetheredWing-v0's on a 2-core AVX2 machine, on top of the single env's 55 s. Calling the
single env's kernel on ranges of copies compiles nothing more, and each copy's arithmetic is that kernel's, so the
vector envs give the single env's bits whatever the thread count.

The thread count is numba's (``numba.get_num_threads()``, as ``numba.set_num_threads`` and ``NUMBA_NUM_THREADS``
set it), read at each call, so the existing controls of a run's parallelism keep working.
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numba

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

    def __call__(self, *args) -> None:
        n = numba.get_num_threads() if self.parallel else 1
        ranges = copy_ranges(self.n_copies, n)
        if len(ranges) == 1:
            self.kernel(*args, 0, self.n_copies)
            return
        pool = self._workers(len(ranges) - 1)
        futures = [pool.submit(self.kernel, *args, first, last) for first, last in ranges[1:]]
        error = None
        try:
            self.kernel(*args, *ranges[0])
        except BaseException as e:  # noqa: BLE001 (raised below, once the other ranges have ended)
            error = e
        for f in futures:
            e = f.exception()
            if error is None and e is not None:
                error = e
        if error is not None:
            raise error

    def _workers(self, n: int) -> ThreadPoolExecutor:
        if self._pool is None or self._pool_size < n:
            if self._pool is not None:
                self._pool.shutdown(wait=True)
            self._pool = ThreadPoolExecutor(max_workers=n, thread_name_prefix="laddermill-copies")
            self._pool_size = n
        return self._pool

    def close(self) -> None:
        """Stop the pool's threads (a later call starts them again)."""
        if self._pool is not None:
            self._pool.shutdown(wait=True)
            self._pool, self._pool_size = None, 0

    def __getstate__(self) -> dict:  # threads do not pickle: a copy starts its own pool when it needs one
        state = dict(self.__dict__)
        state["_pool"], state["_pool_size"] = None, 0
        return state
