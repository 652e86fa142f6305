"""The timing rule the studies share: the least CPU time of repeated calls (other load on the machine only adds to
a call's time, so the least is the best estimate of the code's own cost)."""

from __future__ import annotations

import time

import numpy as np


def least_cpu(f, rounds: int = 7) -> float:
    """The least CPU time [s] of this process over ``rounds`` calls of ``f`` (after one warm call that compiles or
    loads it)."""
    f()
    best = np.inf
    for _ in range(rounds):
        t0 = time.process_time()
        f()
        best = min(best, time.process_time() - t0)
    return best
