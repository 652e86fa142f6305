"""``laddermill_gym/LadderMill-v3``: LadderMill-v2 stepped by one linearly implicit ROS2 step per control period (issue
32 point 3). The same scene, operating point, task, observations, actions and rewards as ``LadderMill-v2``
(:class:`~laddermill_gym.envs.laddermill.task.MillTask`); what differs is registered with the id (``envs.ENV_IDS``):
``physics_step="ros2"`` instead of the scene's RK4 at 10 ms. These classes carry the id's own page (docstring) and
version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

from laddermill_gym.envs.laddermill.env import LadderMillVectorEnv
from laddermill_gym.envs.laddermill.env_v2 import LadderMillV2Env

__all__ = ["LadderMillV3Env", "LadderMillV3VectorEnv"]


class LadderMillV3Env(LadderMillV2Env):
    """LadderMill-v2 on one ROS2 step per control period: faster, its rewards as close to RK4's as v2's.

    ## Description

    LadderMill-v2's mill, task and disturbance (scene ``laddermill_v2``: 101 v2 wings on the endless cable at
    V_c = 2 m/s, 102.2 kW; the paper's 0.01 rad wind-direction step at t = 1 s), stepped by one linearly implicit
    ROS2 step (a Rosenbrock-W method of order 2 with its iteration matrix formed every step, docs/numerics.md) per
    50 ms control period, where v2 takes five RK4 steps of 10 ms. Judged against RK4 at 2.5 ms over 10 s of seeded
    actions of 0.3 amplitude after the step (2026-11-30; tests/test_fast_ids.py, slow): the largest reward error
    0.0052 (v2's RK4: 0.0065), the mean generator power 113.44 kW as the reference's, the positions within 1e-3 of
    the loop's extent. On 8 copies on two threads it stepped a median 3,593 env steps/s over three runs at load
    0.9-1.4 (issue 32's 3,000 met; v2's RK4: 1,280 on a quiet machine in another run, so about 2.8x; ``laddermill
    bench-envs --quick --envs LadderMill-v2 LadderMill-v3 --copies 8``, docs/benchmarks.md). The faster
    ``jacobian_every=4`` (the matrix kept 4 periods) is not registered: it biased the mean power by -2 % with a
    sawtooth of period 4 in the reward (docs/benchmarks.md), and in runs of 2026-11-30 without a command of their own
    (the review's scripts) it ended the mill at 5 m/s and mills of 11 or 21 wings on the breaking load, from the
    station's first element, whose rest length moves with the cable. The
    operating point is v2's (found with the scene's own integrator and cached alike). Many copies:
    ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    LadderMill-v2's (Box [-1, 1]^(n_groups x n_surfaces (+1)) float32 by slot, ``authority=0.2``).

    ## Observation Space

    LadderMill-v2's: Box (15 n + 4,) float32, per slot the 15 entries of the wing now in that slot, then the
    station's 4 (:class:`~laddermill_gym.envs.laddermill.env_v2.LadderMillV2Env`).

    ## Rewards

    LadderMill-v2's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated]; every
    term is in ``info``.

    ## Starting State

    LadderMill-v2's periodic stationary motion (the same cached operating point), mapped to 3D just after a
    transfer; ``initial_noise`` and the wind disturbances as v2.

    ## Episode End

    LadderMill-v2's: ``terminated`` on a physical failure (``info["failure"]``), ``truncated`` at ``episode_time``
    (120 s).

    ## Arguments

    LadderMill-v0's (:class:`~laddermill_gym.envs.laddermill.env.LadderMillEnv`); registered: scene
    ``laddermill_v2``, control_dt 0.05 s, episode_time 120 s, authority 0.2, physics_step ``"ros2"``.
    ``physics_step=None`` steps it as LadderMill-v2.

    ## Version History

    * v3: the physics step ``physics_step="ros2"`` (issue 32 point 3); scene, spaces and rewards as v2.
    * v2: the v2 wing (scene ``laddermill_v2``; ``laddermill_gym/LadderMill-v2``, unchanged).
    * v1: the v1 wing (scene ``laddermill_v1``) and ``authority=0.2`` (``laddermill_gym/LadderMill-v1``, unchanged).
    * v0: initial version (``laddermill_gym/LadderMill-v0``, unchanged).
    """

    registered_id = "laddermill_gym/LadderMill-v3"


class LadderMillV3VectorEnv(LadderMillVectorEnv):
    """``num_envs`` copies of :class:`LadderMillV3Env` in one batch (LadderMill-v0's
    :class:`~laddermill_gym.envs.laddermill.env.LadderMillVectorEnv` with LadderMill-v3's registered defaults)."""

    registered_id = "laddermill_gym/LadderMill-v3"
