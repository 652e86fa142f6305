"""Pickling of a single env that is a task with one copy (``self.task``: a task over a ``BatchSimulator``): the
constructor arguments, the random generator, the batch's states, controls, times and air, and the task's step
counters and last actions. Unpickling rebuilds the env from its arguments and restores those arrays."""

from __future__ import annotations


class TaskPickling:
    """Mixin for envs with ``_kwargs``, ``render_mode``, ``_np_random``, ``_needs_reset`` and ``task`` (with
    ``batch``, ``steps``, ``last_action`` and ``observe()``)."""

    def __getstate__(self):
        b, task = self.task.batch, self.task
        return {"kwargs": self._kwargs, "render_mode": self.render_mode, "np_random": self._np_random,
                "arrays": (b.states.copy(), b.controls.copy(), b.t.copy(), task.steps.copy(), task.last_action.copy()),
                "air": tuple(None if a is None else a.copy() for a in b.air), "needs_reset": self._needs_reset}

    def __setstate__(self, state):
        self.__init__(render_mode=state["render_mode"], **state["kwargs"])
        self._np_random = state["np_random"]
        b, task = self.task.batch, self.task
        b.states[:], b.controls[:], b.t[:], task.steps[:], task.last_action[:] = state["arrays"]
        for mine, saved in zip(b.air, state["air"], strict=True):
            if mine is not None:
                mine[:] = saved
        self._needs_reset = state["needs_reset"]
        if not self._needs_reset:
            task.observe()
