"""The native vector environment of the point-mass fidelity (registered as the ``vector_entry_point`` of
``laddermill_gym/PointMassChain-v0``: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``): one
:class:`~laddermill_gym.envs.pointmass.task.PointMassTask` of ``num_envs`` copies behind Gymnasium's VectorEnv,
like :class:`~laddermill_gym.envs.vector.WingVectorEnv`. The copies are stepped one after another by the compiled
point-mass kernels within one Python call (no Python env object per copy, no batched kernel yet)."""

from __future__ import annotations

import numpy as np
from gymnasium.vector import AutoresetMode

from laddermill_gym.envs.pointmass.batch import POINTMASS_FAILURES
from laddermill_gym.envs.pointmass.env import check_task_arguments
from laddermill_gym.envs.pointmass.task import OBS_PER_KITE, PointMassTask
from laddermill_gym.envs.vector import TaskVectorEnv, check_vector_arguments
from laddermill_gym.kernels.contract import PKO_OFFSET

__all__ = ["PointMassVectorEnv"]


class PointMassVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.pointmass.env.PointMassEnv` in one task
    (:class:`~laddermill_gym.envs.vector.TaskVectorEnv`; copy i behaves exactly like a single env seeded
    seed + i; NextStep or SameStep autoreset).

    Observations (num_envs, 7 n_kites + n_ground) float32; ``info`` holds (num_envs,) arrays of every reward term,
    power [W], largest tension [N], lowest kite altitude [m], t [s], n_clipped and the failure code
    (:data:`~laddermill_gym.envs.pointmass.batch.POINTMASS_FAILURES`), each with its ``_name`` mask.

    Parameters: ``num_envs``, ``render_mode`` (None only: the point-mass env does not render), ``autoreset_mode``
    and the arguments of the single env; others raise ValueError.
    """

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode)
        if render_mode is not None:
            raise ValueError(f"render_mode = {render_mode!r}: the point-mass env does not render (None only)")
        task_kwargs.pop("max_episode_steps", None)
        check_task_arguments(task_kwargs)
        super().__init__(PointMassTask(int(num_envs), **task_kwargs), render_mode, mode)
        self.metadata = dict(self.metadata, render_modes=[])
        self.failure_names = dict(POINTMASS_FAILURES)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral offsets dy [m] of every kite, shape (num_envs, n_kites), of batched observations (the evaluation
        harness's and the gust benchmark's lateral read-out)."""
        nk = self.task.n_wings
        o = np.asarray(obs, dtype=float)[:, : OBS_PER_KITE * nk].reshape(self.num_envs, nk, OBS_PER_KITE)
        return o[:, :, PKO_OFFSET + 1]
