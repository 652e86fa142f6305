"""``laddermill_gym/LadderChain-v1``: LadderChain-v0 stepped by the fastest fixed step within 1e-3 (issue 32 point
3). The same scene, equilibrium start, task, observations, actions and rewards as ``LadderChain-v0``
(:class:`~laddermill_gym.envs.task.WingTask`); what differs is registered with the id (``envs.ENV_IDS``):
``physics_step="ros2", jacobian_every=4`` instead of the scene's RK4 at 12.5 ms. These classes carry the id's own
page (docstring) and version history."""

from __future__ import annotations

from laddermill_gym.envs.task import WingTask
from laddermill_gym.envs.wing_env import WingEnv, WingVectorEnv

__all__ = ["LadderChainV1Env", "LadderChainV1VectorEnv"]


class LadderChainV1Env(WingEnv):
    """LadderChain-v0 on one ROS2 step per control period, its iteration matrix kept 4 periods: about 4x faster.

    ## Description

    LadderChain-v0's chain, task and disturbance (scene ``ladder_chain``: the paper's 101 wings on 70 m pieces
    between two ground points, Meijaard, Ockels & Schwab 1999; the 0.01 rad wind-direction step at t = 1 s), stepped
    by one linearly implicit ROS2 step (a Rosenbrock-W method, docs/numerics.md) per 50 ms control period whose
    iteration matrix (the Jacobian and its factorisation) is reused for 4 periods, where v0 takes four RK4 steps
    of 12.5 ms per period. This is the fastest fixed step that stays within 1e-3 of the extent of RK4 at a quarter
    of v0's step over a 10 s episode of seeded actions on both 101-wing envs (the chain: 4.3e-4; keeping the
    matrix 5 periods leaves the bound, docs/benchmarks.md, "The fastest step within 1e-3"). Closed loop, the
    centralised LQR (configs/agents/lqr_ladder_chain_central.yaml) holds it 300 s after the step with a mean power
    and largest lateral offset within 1e-6 of v0's (the same page; tests/test_fast_ids.py checks a short
    closed-loop run against v0's). At 8 copies on two threads it steps about 4x as many env steps per second as v0
    (``laddermill bench-envs``).
    Many copies: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    LadderChain-v0's: Box [-1, 1]^(3 n_groups) float32, per wing by default (``groups="per_wing"``): elevator,
    rudder, aileron over their physical ranges (:class:`~laddermill_gym.envs.wing_env.WingEnv`).

    ## Observation Space

    LadderChain-v0's: Box (15 n_wings,) float32, the 15 entries of each wing, wing 0 first.

    ## Rewards

    LadderChain-v0's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated],
    P the net pull of the two ends x v0 / 3; every term is in ``info``.

    ## Starting State

    The chain's static equilibrium with its controls (LadderChain-v0's); the wind disturbances are drawn from
    ``np_random`` at every reset.

    ## Episode End

    LadderChain-v0's: ``terminated`` on a physical failure (``info["failure"]``), ``truncated`` at
    ``episode_time`` (120 s).

    ## Arguments

    Those of :class:`laddermill_gym.envs.task.WingTask` and ``render_mode``; registered: scene ``ladder_chain``,
    control_dt 0.05 s, episode_time 120 s, groups ``"per_wing"``, physics_step ``"ros2"``, jacobian_every 4.
    ``physics_step=None, jacobian_every=1`` steps it as LadderChain-v0.

    ## Version History

    * v1: the physics step ``physics_step="ros2", jacobian_every=4`` (issue 32 point 3); scene, spaces and rewards
      as v0.
    * v0: initial version (``laddermill_gym/LadderChain-v0``, unchanged).
    """

    task_class = WingTask


class LadderChainV1VectorEnv(WingVectorEnv):
    """``num_envs`` copies of :class:`LadderChainV1Env` in one batch (LadderChain-v0's
    :class:`~laddermill_gym.envs.wing_env.WingVectorEnv` with LadderChain-v1's registered defaults)."""
