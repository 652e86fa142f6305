"""The one single-copy Gymnasium environment of every env family: a task (``envs/task_base.py``) with one copy.

A family's env is a subclass that names its task and carries its docs::

    class PumpingKiteEnv(TaskEnv):
        \"\"\"<Gymnasium-style docs: Description, Action Space, Observation Space, Rewards, ...>\"\"\"
        task_class = PumpingTask

Everything else is here, written once: the argument and render-mode checks, the spaces, seeding, reset and
step with their info keys (the task's info, ``failure_name``, ``failure_reason``), the action checks, rendering
and pickling. Copy i of the family's native vector env (``envs/vector.py``) seeded ``seed + i`` runs the same
kernel code as this env seeded ``seed``, so they agree bit for bit.
"""

from __future__ import annotations

import inspect
from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs import registered_arguments
from laddermill_gym.envs.actions import single_action
from laddermill_gym.envs.render import TaskRendering
from laddermill_gym.envs.task_base import refuse_reset_options

__all__ = ["TaskEnv", "task_arguments", "check_task_arguments", "check_render_mode"]


def task_arguments(task_class: type, vector: bool) -> tuple[str, ...]:
    """The keyword arguments an env over ``task_class`` takes: the task's but the number of copies, and the thread
    pool switch ``parallel`` in the vector env only."""
    names = [p for p in inspect.signature(task_class).parameters if p != "n_copies"]
    return tuple(p for p in names if vector or p != "parallel")


def check_task_arguments(task_class: type, kwargs: dict, vector: bool) -> None:
    """ValueError naming the arguments (and values) that the env over ``task_class`` does not take."""
    allowed = task_arguments(task_class, vector)
    unknown = sorted(set(kwargs) - set(allowed))
    if unknown:
        raise ValueError(f"{', '.join(f'{k} = {kwargs[k]!r}' for k in unknown)}: not arguments of "
                         f"{task_class.env_name} (known: {', '.join(allowed)})")
    check_scene_options(kwargs.get("scene_options"))


#: why an env takes no ``scene_options['fidelity']`` (the env and a training config's check say it alike)
FIDELITY_IS_THE_ENVS = ("each env sets its scene's fidelity ('pointmass' is PointMassEnv's, "
                        "laddermill_gym/PointMassChain-v0; 'rigid' the wing, chain and mill envs'): choose the env "
                        "instead")


def check_scene_options(options) -> None:
    """ValueError naming the entry unless ``scene_options`` is None or a dict of ``load_scene``'s keyword options
    (an unknown key was a TypeError from deep inside the scene loader) other than ``fidelity``, which the env sets."""
    if options is None:
        return
    if not isinstance(options, dict):
        raise ValueError(f"scene_options = {options!r}: must be a dict of load_scene options")
    import inspect

    from laddermill_gym.ladder.scene import load_scene

    if "fidelity" in options:  # the env passes its own: a TypeError ("multiple values") or another family's error
        raise ValueError(f"scene_options['fidelity'] = {options['fidelity']!r}: {FIDELITY_IS_THE_ENVS}")
    known = [p.name for p in inspect.signature(load_scene).parameters.values() if p.kind is p.KEYWORD_ONLY]
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise ValueError(f"{', '.join(f'scene_options[{k!r}] = {options[k]!r}' for k in unknown)}: not an option of "
                         f"load_scene (known: {', '.join(known)})")


def check_render_mode(render_mode, modes, env_name: str) -> None:
    """ValueError unless ``render_mode`` is None or one of ``modes``."""
    if render_mode is None or render_mode in modes:
        return
    if not modes:
        raise ValueError(f"render_mode = {render_mode!r}: the {env_name} env does not render (None only)")
    raise ValueError(f"render_mode = {render_mode!r}: must be one of {list(modes)} or None")


class TaskEnv(TaskRendering, gym.Env):
    """A task with one copy as a Gymnasium env (subclasses set ``task_class`` and their docs).

    Parameters: ``render_mode`` ("rgb_array", "human" where the task renders, or None) and the task's arguments
    (all but ``n_copies`` and ``parallel``; others raise ValueError naming them). ``max_episode_steps`` is ignored:
    the episode ends at the task's ``episode_time``. An action is a finite real array (n_actions,) (or (1,
    n_actions)); anything else (None, a scalar, a string, a complex or boolean array, another shape, NaN)
    raises :class:`~laddermill_gym.envs.actions.ActionError` (a ValueError and a TypeError) before the env moves.
    """

    task_class: type
    #: the id whose registered defaults the class itself applies (a versioned class: ``LadderMillV1Env()`` is
    #: LadderMill-v1, as ``gymnasium.make`` builds it), or None (a family's class, shared by several ids)
    registered_id: str | None = None
    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 20}

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        task = cls.__dict__.get("task_class")
        if task is not None:
            modes = list(task.render_modes)
            cls.metadata = {"render_modes": modes, "render_fps": 20} if modes else {"render_modes": []}

    def __init__(self, render_mode: str | None = None, **task_kwargs):
        check_render_mode(render_mode, self.metadata["render_modes"], self.task_class.env_name)
        if "n_copies" in task_kwargs:  # was dropped without a word: the env built one copy
            n = task_kwargs["n_copies"]
            raise ValueError(f"n_copies = {n!r}: a single env has one copy; for copies use gymnasium.make_vec(id, "
                             f"num_envs={n!r}, vectorization_mode='vector_entry_point')")
        task_kwargs.pop("max_episode_steps", None)
        if self.registered_id is not None:
            task_kwargs = registered_arguments(self.registered_id, task_kwargs)
        check_task_arguments(self.task_class, task_kwargs, vector=False)
        single = {"parallel": False} if "parallel" in task_arguments(self.task_class, True) else {}
        self.task = self.task_class(1, **single, **task_kwargs)
        self._kwargs = self.task.env_kwargs(task_kwargs)
        self.render_mode = render_mode
        if self.metadata["render_modes"]:
            # frames per second of simulated time: one frame per control period (a float, as Gymnasium allows:
            # a rounded int was 0 for control periods of 2.5 s and more, and 3 for 0.3 s)
            self.metadata = dict(self.metadata, render_fps=1.0 / self.task.control_dt)
        self.observation_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                                self.task.obs_high.astype(np.float32), dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self._renderer = None
        self._needs_reset = True

    def __getattr__(self, name: str):
        # the read-only task attributes the family shows on its env (``task_class.env_attributes``)
        task = self.__dict__.get("task")
        if task is not None and name in getattr(type(task), "env_attributes", ()):
            return getattr(task, name)
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    # ------------------------------------------------------------------ Gymnasium API
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        refuse_reset_options(options, self.spec.id if self.spec is not None else type(self).__name__)
        super().reset(seed=seed)
        self.task.reset(np.ones(1, bool), [self.np_random])
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), {"t": 0.0, **self.task.reset_info()}

    def step(self, action):
        a = single_action(action, self.task.n_actions, self._needs_reset)
        reward, terminated, truncated, info = self.task.step(a)
        code = int(info["failure"][0])
        out = {k: (v[0].item() if v.ndim == 1 else v[0].copy()) for k, v in info.items()}
        out["failure_name"] = self.task.failure_names[code]
        out["failure_reason"] = self.task.failure_text(0, code)
        if terminated[0] or truncated[0]:
            self._needs_reset = True
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), float(reward[0]), bool(terminated[0]), bool(truncated[0]), out

    # ------------------------------------------------------------------ pickling
    def __getstate__(self):
        # the generator with its seed (Gymnasium's np_random_seed reseeds a generator whose seed is None) and the spec
        return {"kwargs": self._kwargs, "render_mode": self.render_mode, "np_random": self._np_random,
                "np_random_seed": self._np_random_seed, "spec": self.spec, "task": self.task.snapshot(),
                "needs_reset": self._needs_reset}

    def __setstate__(self, state):
        self.__init__(render_mode=state["render_mode"], **state["kwargs"])
        self._np_random, self._np_random_seed = state["np_random"], state["np_random_seed"]
        self.spec = state["spec"]
        self.task.restore(state["task"])
        self._needs_reset = state["needs_reset"]
        if not self._needs_reset:
            self.task.observe()
