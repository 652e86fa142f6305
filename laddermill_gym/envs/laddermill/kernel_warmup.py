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

The in-plane part is split too: the first thing the operating point needs is the static equilibrium of the cable
without the station (the station-less in-plane right-hand side), the next the moving cable's in-plane kernels for
the search. The second process compiles the
first (:func:`compile_statics`) and prints :data:`STATICS_DONE` before the 3D kernels, while this process compiles
the second (:func:`before_search`, called by ``operating_point.compute_operating_point`` through
``operating_point.SEARCH_HOOK``) and then waits for that line; the static equilibrium then loads its kernel from
numba's cache. The callees both right-hand sides share (wind, aerodynamics, the block solve) are compiled in both
processes at the same time, so this moves only the station-less layers off this process (``python -m
laddermill_gym.studies.benchmarks.startup --envs laddermill_gym/LadderMill-v0``, two cold starts each way at load 5-7:
this process 52.9 / 54.5 -> 48.0 / 48.6 s of CPU, the second 29.2 / 30.1 -> 38.1 / 39.6 s).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from laddermill_gym.envs.kernel_warmup import SWITCH, Warmup, enabled, stopped_on_error, wait_all
from laddermill_gym.envs.kernel_warmup import start as start_target

__all__ = ["SWITCH", "STATICS_DONE", "TARGET", "Warmup", "before_search", "compile_in_plane", "compile_statics",
           "enabled", "start", "stopped_on_error", "wait_all"]

#: what the second process calls (``envs/warmup_run.py``) with the task's arguments
TARGET = "laddermill_gym.envs.laddermill.warmup_child:compile_for"
#: the line the second process prints once the static equilibrium's kernel is in numba's cache
STATICS_DONE = "statics kernel compiled"


def start(task_kwargs: dict, kernels) -> Warmup | None:
    """Launch the warm-up process for a :class:`MillTask` built with ``task_kwargs`` (without ``operating_point``)
    when :func:`enabled`; None when not (or when the arguments do not pickle)."""
    return start_target(TARGET, task_kwargs, kernels, signals=True)


def before_search(warmup: Warmup, scene: str, options: tuple) -> None:
    """Before the operating point's search: compile the in-plane mill's kernels here (:func:`compile_in_plane`)
    while the second process compiles the static equilibrium's, then wait until it has (its line
    :data:`STATICS_DONE`, or its end)."""
    compile_in_plane(scene, options)
    warmup.wait_for(STATICS_DONE)


def _discard_failures(*calls) -> None:
    """Run each of ``calls`` (no arguments) for the kernels it compiles, discarding what a stand-in state makes it
    raise (a non-finite derivative, a failed step)."""
    from laddermill_gym.sim.simulator import SimulationError

    for call in calls:
        try:
            call()
        except (SimulationError, ValueError, FloatingPointError):
            pass


def compile_in_plane(scene: str, options: tuple) -> None:
    """Compile the kernels the operating point's search calls on the in-plane ``scene`` with ``options`` (the
    moving cable's right-hand side and fixed-step driver), on a zero stand-in state in a simulator of its own: numba
    compiles for the argument types; what the right-hand side computes on the stand-in is discarded.

    The fixed-step driver is compiled for the types of the search's call (``sim/breakpoints.fixed_pieces_call``)
    without stepping: a step from the stand-in fails, and the failure's report compiled DP5(4) (about 4.5 s of
    CPU on the first process's path, 2026-12-03) for nothing the search runs. An error-controlled in-plane
    method is still compiled by a step."""
    from laddermill_gym.envs.laddermill.operating_point import mill_scene
    from laddermill_gym.envs.step_callees import compile_ahead
    from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS, fixed_pieces_call
    from laddermill_gym.sim.simulator import Simulator

    sc2 = mill_scene(scene, options, 2)
    x = np.zeros(sc2.assembly.state_size)
    sim = Simulator(sc2.assembly, x, sc2.settings)
    _discard_failures(lambda: sim.rhs(0.0, x))
    if sc2.settings.method in FIXED_STEP_METHODS:
        compile_ahead([fixed_pieces_call(sim, 1)])
    else:
        _discard_failures(sim.step)


def compile_statics(scene: str, options: tuple) -> None:
    """Compile the right-hand side of the in-plane scene's static equilibrium (its cable without the station, as
    ``ladder/initial.initial_state`` solves it) on a zero stand-in state, as :func:`compile_in_plane` does."""
    from laddermill_gym.envs.laddermill.operating_point import mill_scene
    from laddermill_gym.sim.simulator import Simulator

    sc2 = mill_scene(scene, options, 2)
    asm = dataclasses.replace(sc2.assembly, station=None)
    x = np.zeros(asm.state_size)
    _discard_failures(lambda: Simulator(asm, x, sc2.settings).rhs(0.0, x))
