"""The native vector environment of the rotorcraft: all copies of Roberts' craft stepped by one compiled kernel,
parallel over copies (registered as the ``vector_entry_point`` of ``laddermill_gym/Rotorcraft-v0``:
``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``), like
:class:`~laddermill_gym.envs.vector.WingVectorEnv` for the wing scenes.
"""

from __future__ import annotations

import inspect

import numpy as np
from gymnasium.vector import AutoresetMode

from laddermill_gym.envs.rotorcraft.observation import OBS_Y
from laddermill_gym.envs.rotorcraft.task import CRAFT_FAILURES, CraftTask
from laddermill_gym.envs.vector import TaskVectorEnv, check_vector_arguments

__all__ = ["RotorcraftVectorEnv"]

#: The CraftTask arguments the vector env passes on (all but the number of copies)
_TASK_ARGUMENTS: tuple[str, ...] = tuple(p for p in inspect.signature(CraftTask).parameters if p != "n_copies")


class RotorcraftVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` in one batch
    (:class:`~laddermill_gym.envs.vector.TaskVectorEnv` over a :class:`CraftTask`: copy i equals a single env
    seeded seed + i bit for bit; NextStep or SameStep autoreset).

    Observations (num_envs, 19) float32 (clipped to the bounds, as the single env's); ``info`` holds
    (num_envs,) arrays of every reward term, t [s], power_W [W], altitude_m [m], max_tip_incidence_rad [rad],
    n_clipped and failure (code of :data:`~laddermill_gym.envs.rotorcraft.task.CRAFT_FAILURES`), and
    thrust_N (num_envs, 2) [N] and tether_tension_N (num_envs, 3) [N], each with its ``_name`` mask.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: copy 0), ``autoreset_mode``, ``parallel``
    (numba thread pool; default from 32 copies on) and the arguments of
    :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv` (craft, wind_speed [m/s], control_dt [s],
    episode_time [s], disturbances, ...); others raise ValueError naming them.
    """

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode)
        task_kwargs.pop("max_episode_steps", None)
        unknown = sorted(set(task_kwargs) - set(_TASK_ARGUMENTS))
        if unknown:
            raise ValueError(f"{', '.join(f'{k} = {task_kwargs[k]!r}' for k in unknown)}: not arguments of the "
                             f"rotorcraft env (known: {', '.join(_TASK_ARGUMENTS)})")
        super().__init__(CraftTask(int(num_envs), **task_kwargs), render_mode, mode)
        self.failure_names = dict(CRAFT_FAILURES)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m], shape (num_envs, 1), of batched observations (num_envs, 19)."""
        return np.asarray(obs, dtype=float)[:, OBS_Y:OBS_Y + 1]
