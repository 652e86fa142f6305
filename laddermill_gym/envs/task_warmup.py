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

__all__ = ["compile_wing", "compile_craft", "stand_in_wing_trim", "stand_in_craft_trim"]


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


def _build_and_step(cls, task_kwargs: dict) -> None:
    """Build ``cls(**task_kwargs)``, then reset every copy and take one step with the zero action; a ValueError
    of the constructor (the stand-in's read-outs) ends it."""
    try:
        task = cls(**task_kwargs)
    except ValueError:
        return
    B = task.n_copies
    task.reset(np.ones(B, dtype=bool), [np.random.default_rng(0) for _ in range(B)])
    task.step(np.zeros((B, task.n_actions)))


def compile_wing(task_kwargs: dict) -> None:
    """The wing task's kernels, compiled around :func:`stand_in_wing_trim` (this process's ``scene_trim`` replaced)."""
    from laddermill_gym.envs import task as wing_task

    wing_task.scene_trim = stand_in_wing_trim
    _build_and_step(wing_task.WingTask, task_kwargs)


def compile_craft(task_kwargs: dict) -> None:
    """The craft task's kernels, compiled around :func:`stand_in_craft_trim` (this process's ``craft_trim``
    replaced)."""
    from laddermill_gym.envs.rotorcraft import task as craft_task

    craft_task.craft_trim = stand_in_craft_trim
    _build_and_step(craft_task.CraftTask, task_kwargs)
