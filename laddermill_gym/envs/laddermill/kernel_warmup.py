"""Compile the mill env's 3D kernels in a second process while this one computes the operating point (issue 32
point 1: LadderMill-v0's cold start).

A cold LadderMill start does two long things one after the other on one core: it runs the in-plane mill to its
periodic motion (``operating_point.py``, about 30 s of CPU for the 101-wing mills) and then compiles the 3D
step-and-observe kernel at the first reset (about 35 s of CPU, numba). Neither needs the other's result: the
kernel's compiled code depends on the types of its arguments only, not on the operating point's values. So when
the operating point has to be computed (not memoised in this process, no entry on disk), :func:`start` launches
``python -m laddermill_gym.envs.laddermill.warmup_child`` with the task's arguments: it builds the same
:class:`~laddermill_gym.envs.laddermill.task.MillTask` around a stand-in operating point of the right shapes
(``warmup_child.stand_in_point``: every value a placeholder, never used for a result), resets it and takes one step, so
numba compiles exactly the kernels (and signatures) this process will call and writes them to its on-disk cache
(``NUMBA_CACHE_DIR``, inherited). :meth:`Warmup.wait`, called once the real task is built and before its first
kernel call, waits for that process; the kernels are then loaded from the cache as in any warm start: the same
machine code, so the same bits as compiling them here (numba's cache is keyed by the signature, the source and the
CPU; a signature the second process did not compile is compiled here as before).

This moves CPU seconds to the other core; it does not remove them (the figures in docs/benchmarks.md give the
second process's CPU seconds too). ``LADDERMILL_KERNEL_WARMUP=off`` (:data:`SWITCH`) switches it off; it is also off
when numba's JIT is disabled or the kernels are already compiled in this process. Any failure of the second
process only costs its time: this process then compiles as before. The machinery is shared with the wing and craft
envs (``envs/kernel_warmup.py``); this module names the mill's target (``warmup_child.compile_for``).
"""

from __future__ import annotations

from laddermill_gym.envs.kernel_warmup import SWITCH, Warmup, enabled
from laddermill_gym.envs.kernel_warmup import start as start_target

__all__ = ["SWITCH", "TARGET", "Warmup", "enabled", "start"]

#: what the second process calls (``envs/warmup_run.py``) with the task's arguments
TARGET = "laddermill_gym.envs.laddermill.warmup_child:compile_for"


def start(task_kwargs: dict, kernels) -> Warmup | None:
    """Launch the warm-up process for a :class:`MillTask` built with ``task_kwargs`` (without ``operating_point``)
    when :func:`enabled`; None when not (or when the arguments do not pickle)."""
    return start_target(TARGET, task_kwargs, kernels)
