"""The wing and craft targets of the kernel warm-up (``envs/kernel_warmup.py``, issue 32 point 1): called in the
second process with the arguments of a :class:`~laddermill_gym.envs.task.WingTask` /
:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`, each builds that task around a stand-in starting point
(the scene's shapes and read-only flags, unit quaternions, no static equilibrium and no trim solved: its values are
placeholders, never used for a result) so that the constructor's call of the step-and-observe kernel compiles it
into numba's on-disk cache while the first process solves the real trim (and compiles what that needs).

The stand-in takes the place of the trim function in this (second) process only. A stand-in state may make the
constructor reject the trim read-outs (ValueError: no positive power): by then the kernel is compiled, and that is
all the second process is for; it then resets and steps the task when it can, so the read-out kernels are compiled
too."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.kernel_warmup import CALLEES_DONE
from laddermill_gym.envs.step_callees import await_on_disk, compile_ahead, step_callees

#: the longest wait of the craft's warm-up for the first process's trim to compile the right-hand side [s] (a cold
#: trim compiles it in about 12 s of CPU; past the wait, or when the trim was on disk and compiled nothing, this
#: process compiles it itself)
TRIM_WAIT_S = 20.0

__all__ = ["TRIM_WAIT_S", "compile_craft", "compile_wing", "compile_wing_tail", "craft_calls",
           "stand_in_craft_trim", "stand_in_wing_trim", "wing_calls"]


def stand_in_wing_trim(scene: str, options: tuple):
    """(scene, x, u) of the shapes and flags :func:`laddermill_gym.envs.task.scene_trim` returns: the state zero
    but for unit quaternions, the controls zero, both read-only."""
    from laddermill_gym.kernels.contract import B3_QUAT, B3_SIZE, N_CONTROLS
    from laddermill_gym.ladder.scene import load_scene, options_kwargs

    sc = load_scene(scene, **options_kwargs(options))
    a = sc.assembly
    x = np.zeros(a.state_size)
    x[B3_QUAT: B3_SIZE * a.n_wings: B3_SIZE] = 1.0
    u = np.zeros(N_CONTROLS * a.n_wings)
    x.setflags(write=False)
    u.setflags(write=False)
    return sc, x, u


def stand_in_craft_trim(craft: str, wind_speed=None, collective=None, physics_dt=None):
    """(craft, x, u) of the shapes and flags :func:`laddermill_gym.envs.rotorcraft.trim.craft_trim` returns: the
    craft's design pose (no equilibrium solved) and the trim controls, both read-only."""
    from laddermill_gym.envs.rotorcraft.trim import untrimmed_craft

    c, u = untrimmed_craft(craft, wind_speed, collective, physics_dt)
    x = np.array(c.design_state(), dtype=float)
    x.setflags(write=False)
    u.setflags(write=False)
    return c, x, u


class _Captured(Exception):
    """Raised by the stand-in step kernel once it holds the arguments of the task's first call."""


def _step_arguments(module, names: tuple, build, trim: tuple):
    """The arguments of the first step-kernel call of the task ``build()`` makes, with the kernels ``names`` of
    ``module`` (the attributes the task reads: the step kernel, then its launcher on numba's threads, whose first
    argument, the copy ranges, is dropped) replaced by a stand-in that records them and stops the constructor, and
    ``trim`` = (name, function): the module's trim function replaced by a stand-in trim; all restored after. None
    when the constructor ends otherwise."""
    saved = {n: getattr(module, n) for n in (*names, trim[0])}
    got = {}

    def stand_in(*args):
        got["args"] = args
        raise _Captured

    def launcher_stand_in(bounds, *args):
        got["args"] = (*args, int(bounds[0, 0]), int(bounds[0, 1]))
        raise _Captured

    for i, n in enumerate(names):
        setattr(module, n, stand_in if i == 0 else launcher_stand_in)
    setattr(module, trim[0], trim[1])
    try:
        build()
    except _Captured:
        pass
    except ValueError:
        return None
    finally:
        for n, k in saved.items():
            setattr(module, n, k)
    return got.get("args")


def _build_and_step(cls, task_kwargs: dict) -> None:
    """Build ``cls(**task_kwargs)``, then reset every copy and take one step with the zero action in which no copy
    is selected (``mask`` all False: the read-outs and the action map compile, no physics step runs, so the W
    method's loop, which the step kernel calls through its address and another process compiles, is not asked
    for here); a ValueError of the constructor (the stand-in's read-outs) ends it."""
    try:
        task = cls(**task_kwargs)
    except ValueError:
        return
    B = task.n_copies
    task.reset(np.ones(B, dtype=bool), [np.random.default_rng(0) for _ in range(B)])
    task.step(np.zeros((B, task.n_actions)), np.zeros(B, dtype=bool))


def wing_calls(task_kwargs: dict) -> list:
    """:func:`step_callees` of ``WingTask(**task_kwargs)``, its arguments taken from a task built around
    :func:`stand_in_wing_trim` (``scene_trim`` restored after)."""
    from laddermill_gym.envs import task as wing_task

    args = _step_arguments(wing_task, ("step_observe_serial", "launch_step_observe"),
                           lambda: wing_task.WingTask(**task_kwargs), ("scene_trim", stand_in_wing_trim))
    return [] if args is None else step_callees(args)


def craft_calls(task_kwargs: dict) -> tuple[list, list, bool]:
    """:func:`step_callees` of ``CraftTask(**task_kwargs)`` (not the observation's: the craft observes through its
    right-hand side), taken from a task built around :func:`stand_in_craft_trim` (``craft_trim`` restored after),
    split into (those the craft's trim does not compile, those it does with the same types: the assembly and the
    right-hand side, and the bodies' load Jacobian, whose compile needs the craft's loads that the assembly
    compiles; then the W method's loop, which links them), and whether the first process reads its trim from the
    on-disk start cache (:func:`~laddermill_gym.envs.rotorcraft.trim.trim_on_disk`: it then compiles none of
    them)."""
    from laddermill_gym.envs.rotorcraft import task as craft_task
    from laddermill_gym.envs.rotorcraft.trim import trim_on_disk
    from laddermill_gym.kernels.rigid.body_jacobian import add_body_jacobian
    from laddermill_gym.kernels.rigid.rhs3d import assemble3d, rhs3d
    from laddermill_gym.kernels.rigid.rosenbrock import w_advance_one

    asked = []

    def recording_stand_in(*args, **kwargs):
        asked.append((args, kwargs))
        return stand_in_craft_trim(*args, **kwargs)

    args = _step_arguments(craft_task, ("craft_step_observe_serial", "launch_craft_step_observe"),
                           lambda: craft_task.CraftTask(**task_kwargs), ("craft_trim", recording_stand_in))
    calls = [] if args is None else step_callees(args, observe=False)
    trims = (assemble3d, rhs3d, add_body_jacobian, w_advance_one)  # the W method's step links the first three
    on_disk = bool(asked) and trim_on_disk(*asked[0][0], **asked[0][1])
    return [c for c in calls if c[0] not in trims], [c for c in calls if c[0] in trims], on_disk


def compile_wing(task_kwargs: dict) -> None:
    """The wing task's kernels, compiled around :func:`stand_in_wing_trim` (this process's ``scene_trim`` replaced):
    the step kernel's callees first, in the order its compile reaches them (:func:`wing_calls`; a second process,
    :func:`compile_wing_tail`, takes them from the other end), but the last, the W method's loop, which the other
    compiles; then the task's own kernels."""
    from laddermill_gym.envs import task as wing_task

    calls = wing_calls(task_kwargs)
    compile_ahead(calls[:-1], shared=True)  # a callee the tail is compiling now is left to it
    print(CALLEES_DONE, flush=True)  # the first process may compile its trim now (kernel_warmup.await_callees)
    wing_task.scene_trim = stand_in_wing_trim
    _build_and_step(wing_task.WingTask, task_kwargs)


def compile_wing_tail(task_kwargs: dict) -> None:
    """The wing step kernel's callees (:func:`wing_calls`) from the last but one to the first, in a process beside
    :func:`compile_wing`'s: each compiles those the other has not written to numba's cache yet, so the two share
    them (the one both reach together is left to the process that claimed it first:
    ``compile_ahead(shared=True)``) while the first process solves the trim; then,
    after its line, the last (the W method's loop, which links the others), beside the other's step kernel and the
    first process's trim (compiled in both, it cost each 5 s of CPU)."""
    calls = wing_calls(task_kwargs)
    compile_ahead(calls[-2::-1], shared=True)
    print(CALLEES_DONE, flush=True)
    compile_ahead(calls[-1:])  # the W method's loop last: it links the others


def compile_craft(task_kwargs: dict) -> None:
    """The craft task's kernels, compiled around :func:`stand_in_craft_trim` (this process's ``craft_trim``
    replaced): first the step kernel's callees that the first process's trim does not compile
    (:func:`craft_calls`), then a wait (at most :data:`TRIM_WAIT_S`) until that trim has written the assembly (and
    with it the craft's loads) to numba's cache, then the rest of the step kernel's callees (the assembly and the
    right-hand side), which load what the trim compiled instead of compiling it a second time; then
    :data:`CALLEES_DONE`, on which the first process compiles the W method's loop
    (:func:`~laddermill_gym.envs.step_callees.w_loop_call`; with it the bodies' load Jacobian, which only the loop
    links) while this one compiles the task's own kernels. When the first process reads its trim from the start
    cache it compiles none of them, and this one compiles them all without waiting."""
    from laddermill_gym.envs.rotorcraft import task as craft_task
    from laddermill_gym.kernels.rigid.body_jacobian import add_body_jacobian
    from laddermill_gym.kernels.rigid.rosenbrock import w_advance_one

    own, trims, trim_read = craft_calls(task_kwargs)
    compile_ahead(own)
    if not trim_read:
        await_on_disk(trims[:1], TRIM_WAIT_S)  # the assembly, with the craft's loads
    compile_ahead([c for c in trims if c[0] not in (add_body_jacobian, w_advance_one)])  # the step kernel's
    print(CALLEES_DONE, flush=True)  # the first process compiles the W method's step (and its load Jacobian) now
    craft_task.craft_trim = stand_in_craft_trim
    _build_and_step(craft_task.CraftTask, task_kwargs)
