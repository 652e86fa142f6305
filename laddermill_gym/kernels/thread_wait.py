"""How numba's OpenMP workers wait between parallel kernels: passively, unless the user chose otherwise.

Why (issue 32 point 3): numba's default threading layer on Linux is OpenMP (GNU libgomp). By default libgomp's
workers spin-wait at the end of a parallel region and between regions before they sleep. The env step calls one
parallel kernel per control period with Python work around it, so on this 2-core machine, under load from other
processes, the spinning worker takes a core from the thread that still has copies to step (or from the Python
step). LadderChain-v0 at 8 copies with ``physics_step="ros34pw2"``, ``jacobian_every=4``, two threads, runs alternated
at load 6.7-7.2 (CPU ms per vector step, wall env steps/s): libgomp's default 8.9 ms / 297 and 8.7 ms / 309;
``OMP_WAIT_POLICY=passive`` 4.6 ms / 556; numba's ``workqueue`` layer 4.4 ms / 612; one thread 4.6 ms. The spin
doubled the CPU of a step and halved its rate, and so hid every saving in the kernel (``jacobian_every``).

:func:`passive_openmp_wait` sets ``OMP_WAIT_POLICY=passive`` at ``import laddermill_gym``, before numba's OpenMP
pool is started (libgomp reads it when it is loaded), unless the variable is already set: a user who wants the
spin (a quiet machine with a core per thread) sets ``OMP_WAIT_POLICY=active`` (or any value) before the import.
How a worker waits does not change what it computes: every copy's arithmetic is the same, bit for bit
(tests/test_thread_wait.py). Other OpenMP libraries loaded later in the process (torch's libgomp) read the same
variable; where one was loaded before ``import laddermill_gym``, or numba's pool already runs, nothing changes.
"""

from __future__ import annotations

import os

#: the OpenMP environment variable (the OpenMP specification: ACTIVE or PASSIVE, either case)
WAIT_VARIABLE = "OMP_WAIT_POLICY"
#: the value set when the user has set none
PASSIVE = "passive"


def passive_openmp_wait(environ=None) -> bool:
    """Set ``OMP_WAIT_POLICY`` to ``passive`` in ``environ`` (default ``os.environ``) unless it is set already (any
    value, even empty, is the user's choice and kept). Returns whether it was set here."""
    env = os.environ if environ is None else environ
    if WAIT_VARIABLE in env:
        return False
    env[WAIT_VARIABLE] = PASSIVE
    return True
