"""The native vector environment of the laddermill: all copies stepped by one compiled kernel (registered as the
``vector_entry_point`` of ``laddermill_gym/LadderMill-v0``: ``gymnasium.make_vec(id, n,
vectorization_mode="vector_entry_point")``), like :class:`~laddermill_gym.envs.vector.WingVectorEnv`."""

from __future__ import annotations

import numpy as np
from gymnasium.vector import AutoresetMode

from laddermill_gym.envs.laddermill.env import check_task_arguments
from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, OBS_INDEX
from laddermill_gym.envs.laddermill.settings import MILL_FAILURES
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.envs.vector import TaskVectorEnv, check_vector_arguments

__all__ = ["LadderMillVectorEnv"]


class LadderMillVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.laddermill.env.LadderMillEnv` in one batch
    (:class:`~laddermill_gym.envs.vector.TaskVectorEnv` over a :class:`~laddermill_gym.envs.laddermill.task.MillTask`;
    copy i runs the same kernel code as a single env seeded seed + i; NextStep or SameStep autoreset).

    Observations (num_envs, 15 n + 4) float32; ``info`` holds (num_envs,) arrays of every reward term, the powers
    [W], cable speed [m/s], tensions [N], lowest altitude [m], transfers, t [s], n_clipped, n_aero_out_of_band and
    the failure code (:data:`~laddermill_gym.envs.laddermill.settings.MILL_FAILURES`), each with its ``_name`` mask.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: copy 0), ``autoreset_mode``, ``parallel`` (numba
    thread pool; default from 32 copies on) and the arguments of the single env; others raise ValueError.
    """

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode)
        task_kwargs.pop("max_episode_steps", None)
        check_task_arguments(task_kwargs)
        super().__init__(MillTask(int(num_envs), **task_kwargs), render_mode, mode)
        self.failure_names = dict(MILL_FAILURES)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m] per slot, shape (num_envs, n), of batched observations (num_envs, 15 n + 4)
        (the evaluation harness's lateral read-out)."""
        n = self.task.n_wings
        o = np.asarray(obs, dtype=float)[:, : N_OBS_PER_SLOT * n].reshape(len(obs), n, N_OBS_PER_SLOT)
        return o[:, :, OBS_INDEX["dy"]]
