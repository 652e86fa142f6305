"""``laddermill_gym/LadderMill-v3``: LadderMill-v2 stepped by the fastest fixed step within 1e-3 (issue 32 point 3).
The same scene, operating point, task, observations, actions and rewards as ``LadderMill-v2``
(:class:`~laddermill_gym.envs.laddermill.task.MillTask`); what differs is registered with the id
(``envs.ENV_IDS``): ``physics_step="ros2", jacobian_every=4`` instead of the scene's RK4 at 10 ms. These classes
carry the id's own page (docstring) and version history."""

from __future__ import annotations

from laddermill_gym.envs.laddermill.env import LadderMillVectorEnv
from laddermill_gym.envs.laddermill.env_v2 import LadderMillV2Env

__all__ = ["LadderMillV3Env", "LadderMillV3VectorEnv"]


class LadderMillV3Env(LadderMillV2Env):
    """LadderMill-v2 on one ROS2 step per control period, its iteration matrix kept 4 periods: about 4x faster.

    ## Description

    LadderMill-v2's mill, task and disturbance (scene ``laddermill_v2``: 101 v2 wings on the endless cable at
    V_c = 2 m/s, 102.2 kW; the paper's 0.01 rad wind-direction step at t = 1 s), stepped by one linearly implicit
    ROS2 step (a Rosenbrock-W method, docs/numerics.md) per 50 ms control period whose iteration matrix (the
    Jacobian and its factorisation) is reused for 4 periods, where v2 takes five RK4 steps of 10 ms per period and
    needs no matrix. This is the fastest fixed step that stays within 1e-3 of the extent of RK4 at a quarter of
    v2's step over a 10 s episode of seeded actions on both 101-wing envs (the mill: 1.93e-5; keeping the matrix 5
    periods leaves the bound on the chain, docs/benchmarks.md, "The fastest step within 1e-3"). Closed loop, the
    lateral LQR (``make_controller("lqr", id)``, LadderMill-v2's design) holds it 300 s after the step at a mean
    power within 1e-3 of v2's (the same page; tests/test_fast_ids.py checks a short closed-loop run against v2's).
    At 8 copies on two threads it steps about 4x as many env steps per second as v2 (``laddermill bench-envs``).
    The operating point is v2's (found with the scene's own integrator and cached alike).

    A limit of the held matrix: it is verified on this id's 101 wings. On smaller mills it can be unstable:
    with 11 wings (from their fallback start) the largest tension grows to 3.7 MN within 0.4 s even under zero
    actions, with 21 wings under random actions of half amplitude two of four seeds end on the breaking load within
    a second, where ``jacobian_every=1`` (or 2) and RK4 run the 5 s through; 41 wings run (checked 2026-11-30 with
    the small cases of tests/env_cases.py). Give a smaller mill ``jacobian_every=1``. What goes wrong is the
    station's first element, whose rest length moves with the cable (``kernels/rigid/cable_jacobian.py``): on the
    11-wing mill under zero actions its tension reads 17.4, 13.8, 7.4 kN over the steps that reuse the matrix where
    the matrix formed every step gives 21.4, 22.0, 21.7 kN, and the swing grows after each rebuild (0.5 kN at 0.3 s,
    then the breaking load); on 41 wings, with three to four times the tension, the same drift stays a few kN.
    LadderChain-v1's held matrix (no moving ends) ran 2, 5, 11 and 101 wings under random actions of full amplitude
    for 10 s.
    Many copies: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

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
    ``laddermill_v2``, control_dt 0.05 s, episode_time 120 s, authority 0.2, physics_step ``"ros2"``,
    jacobian_every 4. ``physics_step=None, jacobian_every=1`` steps it as LadderMill-v2.

    ## Version History

    * v3: the physics step ``physics_step="ros2", jacobian_every=4`` (issue 32 point 3); scene, spaces and rewards
      as v2.
    * v2: the v2 wing (scene ``laddermill_v2``; ``laddermill_gym/LadderMill-v2``, unchanged).
    * v1: the v1 wing (scene ``laddermill_v1``) and ``authority=0.2`` (``laddermill_gym/LadderMill-v1``, unchanged).
    * v0: initial version (``laddermill_gym/LadderMill-v0``, unchanged).
    """


class LadderMillV3VectorEnv(LadderMillVectorEnv):
    """``num_envs`` copies of :class:`LadderMillV3Env` in one batch (LadderMill-v0's
    :class:`~laddermill_gym.envs.laddermill.env.LadderMillVectorEnv` with LadderMill-v3's registered defaults)."""
