"""How numba's OpenMP workers wait between parallel kernels: passively, unless the user chose otherwise.

Why (issue 32 point 3): numba's default threading layer on Linux is OpenMP (GNU libgomp). By default libgomp's
workers spin-wait at the end of a parallel region and between regions before they sleep. The env step calls one
parallel kernel per control period with Python work around it, so on this 2-core machine, shared with other
processes, the spinning worker takes a core from the thread that still has copies to step (or from the Python
step). ``laddermill bench-envs --envs LadderChain-v0 LadderMill-v2 --copies 8`` (two threads), three runs each
alternated with the variable removed again after the import (libgomp's default), load 1.4-5.0, medians of CPU ms
per env step (the process's CPU over its steps): LadderChain-v0 1.96 -> 1.29, with ``physics_step="ros34pw2"``
0.94 -> 0.66; LadderMill-v2 2.04 -> 1.59, with ROS34PW2 1.07 -> 0.75; env steps/s 477 -> 494, 708 -> 1,008,
340 -> 426, 673 -> 909. The spin also hid the saving of a kept Jacobian: LadderChain-v0 with ROS34PW2 (8 copies,
two threads) at ``jacobian_every`` 1 / 4 ran 747 / 749 env steps/s before and 1,096 / 1,231 after (medians of
three alternated runs, load 3.5).

The cost (issue 32 point 5): with both cores free the spin wins at mid batch sizes. ``laddermill bench-envs --quick
--envs TetheredWing-v0 --copies 64``, load 0.1-1.5, alternated twice: 167,299 / 157,997 env steps/s with
``OMP_WAIT_POLICY=active`` against 143,009 / 143,465 passive (-11 %); at 512 copies and one copy they tie. A short
spin before the sleep (``GOMP_SPINCOUNT=10000``, libgomp's own default is 300,000) recovered that on the quiet
machine (165,000 / 162,000) but loses on a loaded one: the same command beside a training run (load 3.8-4.5), three
alternated rounds, passive against passive with ``GOMP_SPINCOUNT=10000``: TetheredWing-v0 at 64 copies 64,051 /
54,855 / 47,588 against 39,417 / 47,478 / 43,796; LadderChain-v0 at 8 copies (``--envs LadderChain-v0 --copies 8``)
479 / 486 / 530 against 492 / 503 / 493, its ROS34PW2 row 1,012 / 1,020 / 1,052 against 892 / 944 / 946. On the
shared machines this package is run on, the passive wait stays the default; a user with a core per thread sets
``OMP_WAIT_POLICY=active`` (or ``GOMP_SPINCOUNT``) before the import.

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
