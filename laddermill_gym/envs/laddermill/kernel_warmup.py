"""Compile the mill env's 3D kernels in a second process while this one computes the operating point (issue 32
point 1: LadderMill-v0's cold start).

A cold LadderMill start does two long things one after the other on one core: it runs the in-plane mill to its
periodic motion (``operating_point.py``, about 30 s of CPU for the 101-wing mills) and then compiles the 3D
step-and-observe kernel at the first reset (about 35 s of CPU, numba). Neither needs the other's result: the
kernel's compiled code depends on the types of its arguments only, not on the operating point's values. So when
the operating point has to be computed (not memoised in this process, no entry on disk), :func:`start` launches
``python -m laddermill_gym.envs.laddermill.warmup_child`` with the task's arguments. The in-plane part is split
too: the second process first compiles the static equilibrium's right-hand side (:func:`compile_statics`) while
this one compiles the in-plane mill's kernels (:meth:`Warmup.before_search`, called by the search through
``operating_point.SEARCH_HOOK``); then the static equilibrium loads its kernel from the cache. Then it builds the
same
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
process only costs its time: this process then compiles as before.
"""

from __future__ import annotations

import os
import pickle
import select
import subprocess
import sys

import numpy as np

__all__ = ["SWITCH", "STATICS_DONE", "Warmup", "compile_in_plane", "compile_statics", "enabled", "start"]

#: the environment variable that switches the warm-up off (value ``off``)
SWITCH = "LADDERMILL_KERNEL_WARMUP"
#: the module the second process runs (``python -m``)
CHILD_MODULE = "laddermill_gym.envs.laddermill.warmup_child"
#: the line the second process prints when it has compiled the static equilibrium's kernel
STATICS_DONE = "statics kernel compiled"
#: the longest wait for the second process [s] (a cold compile takes 30-80 s of CPU on a loaded machine; past this
#: it is stopped and this process compiles what it still needs)
WAIT_LIMIT_S = 900.0


class Warmup:
    """A running warm-up process; :meth:`wait` (idempotent) waits for it, at most :data:`WAIT_LIMIT_S`."""

    def __init__(self, proc: subprocess.Popen):
        self.proc = proc
        self.returncode: int | None = None
        self.statics_ready = False

    def before_search(self, scene: str, options: tuple) -> None:
        """Before the operating point's search: compile the in-plane mill's kernels here
        (:func:`compile_in_plane`) while the second process compiles the static equilibrium's, then wait (at most
        :data:`WAIT_LIMIT_S`) until it has (its line :data:`STATICS_DONE`) or has ended; once."""
        if self.statics_ready or self.proc is None:
            return
        self.statics_ready = True
        compile_in_plane(scene, options)
        ready, _, _ = select.select([self.proc.stdout], [], [], WAIT_LIMIT_S)
        if ready:
            self.proc.stdout.readline()

    def wait(self) -> int | None:
        """Wait for the process; its exit code (None if it had to be stopped)."""
        if self.returncode is None and self.proc is not None:
            try:
                self.returncode = self.proc.wait(timeout=WAIT_LIMIT_S)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
            self.proc.stdout.close()
            self.proc = None
        return self.returncode


def enabled(kernels) -> bool:
    """Whether a warm-up can help: not switched off, numba's JIT on, and none of ``kernels`` (dispatchers)
    compiled in this process yet."""
    from numba.core import config

    if os.environ.get(SWITCH, "").strip().lower() == "off" or config.DISABLE_JIT:
        return False
    return not any(k.signatures for k in kernels)


def start(task_kwargs: dict, kernels) -> Warmup | None:
    """Launch the warm-up process for a :class:`MillTask` built with ``task_kwargs`` (without ``operating_point``)
    when :func:`enabled`; None when not (or when the arguments do not pickle)."""
    if not enabled(kernels):
        return None
    try:
        payload = pickle.dumps(dict(task_kwargs))
    except Exception:  # an argument that does not pickle: compile here as before
        return None
    proc = subprocess.Popen([sys.executable, "-m", CHILD_MODULE], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, env=dict(os.environ))
    try:
        proc.stdin.write(payload)
        proc.stdin.close()
    except OSError:
        pass
    return Warmup(proc)


def _discard_failures(*calls) -> None:
    """Run each of ``calls`` (no arguments) for the kernels they compile, discarding what a stand-in state makes
    them raise (a non-finite derivative, a failed step)."""
    from laddermill_gym.sim.simulator import SimulationError

    for call in calls:
        try:
            call()
        except (SimulationError, ValueError, FloatingPointError):
            pass


def compile_in_plane(scene: str, options: tuple) -> None:
    """Compile the in-plane mill's kernels that the operating point's search calls (``Simulator``'s right-hand
    side and fixed-step stepper) for the in-plane ``scene`` with ``options``, on a zero stand-in state in a
    simulator of its own: the kernels compile for the argument types, what they compute on the stand-in is
    discarded."""
    from laddermill_gym.envs.laddermill.operating_point import mill_scene
    from laddermill_gym.sim.simulator import Simulator

    sc2 = mill_scene(scene, options, 2)
    x = np.zeros(sc2.assembly.state_size)
    sim = Simulator(sc2.assembly, x, sc2.settings)
    _discard_failures(lambda: sim.rhs(0.0, x), sim.step)


def compile_statics(scene: str, options: tuple) -> None:
    """Compile the right-hand side of the in-plane scene's static equilibrium (its cable without the station:
    ``ladder/initial.initial_state``) on a zero stand-in state, as :func:`compile_in_plane` does."""
    import dataclasses

    from laddermill_gym.envs.laddermill.operating_point import mill_scene
    from laddermill_gym.sim.simulator import Simulator

    sc2 = mill_scene(scene, options, 2)
    asm = dataclasses.replace(sc2.assembly, station=None)
    x = np.zeros(asm.state_size)
    sim = Simulator(asm, x, sc2.settings)
    _discard_failures(lambda: sim.rhs(0.0, x))
