"""``laddermill_gym/LadderChain-v1``: LadderChain-v0 stepped by three RK4 steps of 1/60 s per control period instead of
four of 12.5 ms (issue 32 point 3). The same scene, start, task, observations, actions and rewards as
``LadderChain-v0`` (:class:`~laddermill_gym.envs.task.WingTask`); what differs is registered with the id
(``envs.ENV_IDS``): ``physics_step="rk4", physics_dt=1/60``. These classes carry the id's own page (docstring) and
version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

from laddermill_gym.envs.wing_env import WingEnv, WingVectorEnv

__all__ = ["LadderChainV1Env", "LadderChainV1VectorEnv"]


class LadderChainV1Env(WingEnv):
    """LadderChain-v0 on three RK4 steps per control period: a third faster, its rewards as close to a 4x finer RK4.

    ## Description

    LadderChain-v0's chain and task (scene ``ladder_chain``: the paper's 101 wings on 70 m pieces between two ground
    points, Meijaard, Ockels & Schwab 1999; the 0.01 rad wind-direction step at t = 1 s), stepped by three RK4 steps
    of 1/60 s per 50 ms control period where v0 takes four of 12.5 ms. Why this step: it is the longest RK4 step that
    divides the control period within the env's stability margin (0.9 x RK4's estimated limit at the chain's
    equilibrium, 24.6 ms: ``envs/physics_step.py``; two steps of 25 ms are past it), and every linearly implicit
    step once per control period moves the chain's open-loop rewards by 4-5 % (docs/benchmarks.md), which this one
    does not. Judged against RK4 at 3.125 ms over 10 s of seeded actions of 0.3 amplitude (tests/test_chain_v1.py,
    slow; 2026-12-05): the largest reward error 0.0041 (v0's: 0.0016), the mean reward 0.5458 as the reference's,
    the positions within 1e-3 of the chain's extent. On 8 copies on two threads it stepped 3,343 / 3,375 / 3,049 env
    steps/s in three runs, v0 2,668 / 2,703 / 2,380 in the same runs (issue 32's 3,000; ``laddermill bench-envs --quick
    --envs LadderChain-v0 LadderChain-v1 --copies 8``, docs/benchmarks.md). Stronger wind shortens RK4's stable step:
    the env checks it in the strongest wind of its disturbances and steps finer where needed, as v0 does.

    ## Action Space

    LadderChain-v0's (Box [-1, 1]^(3 n_groups) float32, per wing by default: elevator, rudder, aileron;
    :class:`~laddermill_gym.envs.wing_env.WingEnv`).

    ## Observation Space

    LadderChain-v0's: Box (15 n_wings,) float32, the 15 entries of every wing, wing 0 first.

    ## Rewards

    LadderChain-v0's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated], P the
    net pull of the two ends x v0 / 3; every term is in ``info``.

    ## Starting State

    LadderChain-v0's static equilibrium of the chain with its controls; the wind disturbances are drawn from
    ``np_random`` at every reset.

    ## Episode End

    LadderChain-v0's: ``terminated`` on a physical failure (``info["failure"]``), ``truncated`` at ``episode_time``
    (120 s).

    ## Arguments

    LadderChain-v0's (:class:`~laddermill_gym.envs.wing_env.WingEnv`); registered: scene ``ladder_chain``,
    control_dt 0.05 s, episode_time 120 s, groups ``"per_wing"``, physics_step ``"rk4"``, physics_dt 1/60 s.
    ``physics_step=None, physics_dt=None`` steps it as LadderChain-v0.

    ## Version History

    * v1: the physics step, three RK4 steps of 1/60 s per control period (issue 32 point 3); scene, spaces and
      rewards as v0.
    * v0: initial version (``laddermill_gym/LadderChain-v0``, unchanged).
    """

    registered_id = "laddermill_gym/LadderChain-v1"


class LadderChainV1VectorEnv(WingVectorEnv):
    """``num_envs`` copies of :class:`LadderChainV1Env` in one batch (LadderChain-v0's
    :class:`~laddermill_gym.envs.wing_env.WingVectorEnv` with LadderChain-v1's registered defaults)."""

    registered_id = "laddermill_gym/LadderChain-v1"
