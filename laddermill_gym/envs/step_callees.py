"""The step kernel's callees as (dispatcher, arguments) lists, and their compile ahead of the first call (issue 32
point 1: cold starts): what the kernel warm-ups (``envs/task_warmup.py``, ``envs/laddermill/kernel_warmup.py``)
and the craft's first process (``envs/rotorcraft/task.py``, the W method's loop) compile from argument types
without running anything. Kernel-level only: nothing here imports an env or a task."""

from __future__ import annotations

import os
import time

import numpy as np

from laddermill_gym.envs.kernel_warmup import cache_directory, claim

__all__ = ["await_on_disk", "compile_ahead", "step_callees", "w_loop_call"]


def step_callees(args, observe: bool = True) -> list:
    """The kernels the step-and-observe kernel called with ``args`` calls (through their addresses,
    ``kernels/far_call.py``) or links, as (dispatcher, arguments) pairs (``kernels/rigid/rosenbrock.w_step_calls``,
    ``kernels/rigid/kinds.rigid3d_calls``) with the arguments of copy 0 (``kernels/batch.copy_views``): the
    assembly first, the fixed-step driver, the W method's loop and its step (``w_advance_one``, which links the W
    step's parts; each compiled on its own now) last, the observation's tensions (``observe``) before those; empty
    for a model that is not rigid 3D or a scene that steps with RK4 (its few callees compile in seconds). The
    wing's warm-ups (:func:`~laddermill_gym.envs.task_warmup.compile_wing`, ``compile_wing_tail``) compile them
    from either end; the W method's step, which links the W step's parts again, is left to one process: the wing's
    tail compiles it after its share, the craft's first process after its trim (:func:`w_loop_call`)."""
    from laddermill_gym.kernels.batch import row_or_none
    from laddermill_gym.kernels.contract import KWork
    from laddermill_gym.kernels.fixed_steps import advance_breaks, model_with_air
    from laddermill_gym.kernels.rigid.kinds import Rigid3D, rigid3d_calls
    from laddermill_gym.kernels.rigid.rosenbrock import w_advance, w_advance_one, w_step_calls

    t, X, U, dt, _, M, kind, vehicle, WB, AB, limits, tableau, _, DX = args[:14]
    if tableau is None or not isinstance(kind, Rigid3D):
        return []
    Mb = model_with_air.py_func(kind, vehicle, M, AB.tmod[0], AB.ms[0], AB.md[0], row_or_none(AB.gp, 0),
                                row_or_none(AB.gv, 0))
    Wb = KWork._make(getattr(WB, f)[0] for f in KWork._fields)
    t0, dt = float(t[0]), float(dt)
    kinds = rigid3d_calls(t0, X[0], U[0], Wb.k5, Mb, Wb, limits)  # the W step's derivative scratch: W.k5
    w = w_step_calls(t0, X[0], U[0], dt, Mb, Wb, tableau)
    observed = rigid3d_calls(t0, X[0], U[0], DX[0], Mb, Wb, limits)  # the observation's: the kernel's DX row
    n, breaks = args[4][0], args[12]
    chain = [(advance_breaks, (t0, X[0], U[0], dt, n, Mb, Wb, limits, tableau, breaks)),
             (w_advance, (t0, X[0], U[0], dt, n, Mb, Wb, limits, tableau)),
             (w_advance_one, (t0, X[0], U[0], dt, Mb, Wb, limits, tableau))]
    return [kinds["assemble"], *w[:4], kinds["rhs"], *w[4:], kinds["check"],
            *([observed["tensions"]] if observe else []), *chain]


def compile_ahead(calls, shared: bool = False) -> int:
    """Compile (or load from numba's on-disk cache) each (dispatcher, arguments) of ``calls`` for the arguments'
    types, in order, running none; a pair that does not compile is skipped (the step kernel then compiles what it
    needs). With ``shared`` (the wing's two warm-ups, which take one list from both ends), each compile holds a
    file lock named for the function and its types beside numba's cache (``kernel_warmup.claim``) and a pair whose
    lock another process holds is skipped: that process is compiling it and writes it to the cache, where they
    met the two compiled the same callee side by side before (2-4 s of CPU). Returns how many compiled or
    loaded."""
    from numba import typeof

    done = 0
    for disp, a in calls:
        sig = tuple(typeof(v) for v in a)
        lock = -1
        if shared:
            f = disp.py_func
            lock, _ = claim(f"{f.__module__}.{f.__qualname__}{sig}".encode(), cache_directory((disp,)))
            if lock is None:  # another process compiles it now
                continue
        try:
            disp.compile(sig)
            done += 1
        except Exception:  # noqa: BLE001 (a warm-up only saves time; the step kernel compiles what is missing)
            continue
        finally:
            if lock >= 0:
                os.close(lock)  # releases the lock
    return done


def await_on_disk(calls, limit_s: float) -> bool:
    """Wait, at most ``limit_s`` [s], until numba's on-disk cache holds every (dispatcher, arguments) of ``calls``
    for the arguments' types (another process compiling them); True when it does."""
    from numba import typeof

    left = [(d, tuple(typeof(v) for v in a)) for d, a in calls]
    end = time.monotonic() + limit_s
    while left:
        left = [(d, sig) for d, sig in left if d._cache.load_overload(sig, d.targetctx) is None]
        if not left or time.monotonic() >= end:
            break
        time.sleep(0.2)
    return not left


def w_loop_call(batch, dx) -> list:
    """The W method's step (``w_advance_one``, the heavy compile under the loop) as :func:`step_callees` lists it, a
    one-element list (dispatcher, arguments), for the
    step kernel's arguments from ``batch`` (:class:`~laddermill_gym.sim.batch.BatchSimulator`) and its derivative
    scratch ``dx`` (B, state size); empty where the step has no such loop (RK4, a model that is not rigid 3D). The
    craft's first process compiles it after its trim (``envs/rotorcraft/task.py``), beside its warm-up's compile
    of the step kernel, instead of the warm-up compiling both one after the other."""
    from laddermill_gym.kernels.rigid.rosenbrock import w_advance_one

    args = batch.kernel_head(batch.settings.dt, np.ones(len(batch.t), dtype=np.int64), dx)
    return [c for c in step_callees(args, observe=False) if c[0] is w_advance_one]
