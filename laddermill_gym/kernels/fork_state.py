"""Whether this process was forked from one whose numba threads run on GNU OpenMP.

GNU OpenMP's thread pool is not fork-safe: numba ends such a child (SIGTERM) at its first parallel loop. Code
that can work without numba's pool asks :func:`forked_after_gnu_openmp` first: the vector envs' copies then run
on Python threads (``envs/copy_threads.py``), the point-mass kernels on their serial twins or with a clear error
(``sim/pointmass.check_fork_safe``). Processes started by ``spawn`` or ``forkserver`` start their own pool.
"""

from __future__ import annotations

import os
import sys

import numba

__all__ = ["forked_after_gnu_openmp"]

#: True in a process forked after numba started its threads on GNU OpenMP (set by :func:`_note_fork`)
FORKED_AFTER_GNU_OPENMP = False


def _note_fork() -> None:
    """In a forked child: note whether the parent's numba threads run on GNU OpenMP."""
    global FORKED_AFTER_GNU_OPENMP
    try:
        layer = numba.threading_layer()
    except ValueError:  # numba's threads not started: the child starts its own
        return
    omp = sys.modules.get("numba.np.ufunc.omppool")
    if layer == "omp" and getattr(omp, "openmp_vendor", "GNU") == "GNU":
        FORKED_AFTER_GNU_OPENMP = True


os.register_at_fork(after_in_child=_note_fork)


def forked_after_gnu_openmp() -> bool:
    """True in a process forked (multiprocessing's "fork") from one whose numba threads run on GNU OpenMP, where a
    parallel loop of numba would end the process."""
    return FORKED_AFTER_GNU_OPENMP
