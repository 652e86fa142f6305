"""The native vector environment of the pumping kite: all copies stepped by one compiled kernel (registered as the
``vector_entry_point`` of ``laddermill_gym/PumpingKite-v0``: ``gymnasium.make_vec(id, n,
vectorization_mode="vector_entry_point")``), like :class:`~laddermill_gym.envs.vector.WingVectorEnv`."""

from __future__ import annotations

import numpy as np
from gymnasium.vector import AutoresetMode

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.env import check_task_arguments
from laddermill_gym.envs.pumping.settings import PUMPING_FAILURES
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.vector import TaskVectorEnv, check_vector_arguments

__all__ = ["PumpingKiteVectorEnv"]


class PumpingKiteVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`~laddermill_gym.envs.pumping.env.PumpingKiteEnv` in one batch
    (:class:`~laddermill_gym.envs.vector.TaskVectorEnv` over a :class:`~laddermill_gym.envs.pumping.task.PumpingTask`;
    copy i runs the same kernel code as a single env seeded seed + i; NextStep or SameStep autoreset).

    Observations (num_envs, 20) float32; ``info`` holds (num_envs,) arrays of every reward term, the net electrical
    and mechanical power [W], winch speed [m/s], paid out [m], tensions [N], lowest altitude [m], t [s], n_clipped
    and the failure code (:data:`~laddermill_gym.envs.pumping.settings.PUMPING_FAILURES`), each with its ``_name``
    mask.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: copy 0), ``autoreset_mode``, ``parallel`` (numba
    thread pool; default from 32 copies on) and the arguments of the single env; others raise ValueError.
    """

    def __init__(self, num_envs: int, render_mode: str | None = None,
                 autoreset_mode: AutoresetMode | str = AutoresetMode.NEXT_STEP, **task_kwargs):
        mode = check_vector_arguments(num_envs, render_mode, autoreset_mode)
        task_kwargs.pop("max_episode_steps", None)
        check_task_arguments(task_kwargs)
        super().__init__(PumpingTask(int(num_envs), **task_kwargs), render_mode, mode)
        self.failure_names = dict(PUMPING_FAILURES)

    def lateral_offsets(self, obs: np.ndarray) -> np.ndarray:
        """Lateral CG offsets dy [m], shape (num_envs, 1), of batched observations (num_envs, 20) (the evaluation
        harness's lateral read-out)."""
        return np.asarray(obs, dtype=float)[:, OBS_INDEX["dy"]: OBS_INDEX["dy"] + 1]
