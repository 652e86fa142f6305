"""``laddermill_gym/TetheredWing-v1``: TetheredWing-v0 stepped by two RK4 steps of 25 ms per control period instead of
one ROS34PW2 step of 50 ms (issue 31 point 4). The same scene, trim, task, observations, actions and rewards as
``TetheredWing-v0`` (:class:`~laddermill_gym.envs.task.WingTask`); what differs is registered with the id
(``envs.ENV_IDS``): ``physics_step="rk4", physics_dt=0.025``. These classes carry the id's own page
(docstring) and version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

from laddermill_gym.envs.wing_env import WingEnv, WingVectorEnv

__all__ = ["TetheredWingV1Env", "TetheredWingV1VectorEnv"]


class TetheredWingV1Env(WingEnv):
    """TetheredWing-v0 on two RK4 steps per control period: its physics converged at v0's speed.

    ## Description

    TetheredWing-v0's wing and task (scene ``tethered_wing``: one wing on a 100 m tether of one element; Meijaard,
    Ockels & Schwab 1999; the 0.01 rad wind-direction step at t = 1 s), stepped by two RK4 steps of 25 ms per 50 ms
    control period where v0 takes one linearly implicit ROS34PW2 step of 50 ms. Why: v0's step damps and shifts the
    wing's fast pitch and heave response, and in turbulence that decides knife-edge episodes. Judged against RK4
    at 3.125 ms (docs/scorecard_physics_step.md; 2026-12-05): over 10 s of seeded actions of 0.3
    amplitude the largest reward error is 0.00027 (v0's 0.056) and the largest position error 0.06 mm (v0's 10 mm);
    on gusts-v4's TetheredWing scenarios the LQR and the shipped ``ppo_tethered_wing`` lose the same episodes as
    on the reference, within 0.15 s, where v0's step changes which the LQR loses. The cost per control period is
    v0's (a median of 279,017 env steps/s at 512 copies on two threads against v0's 261,537 in the same runs;
    ``laddermill bench-envs --quick --envs TetheredWing-v0 TetheredWing-v1 --copies 512``). Stronger wind shortens
    RK4's stable step: the env checks it in the strongest wind of its disturbances and steps finer where needed, with
    a warning (``envs/physics_step.py``).

    ## Action Space

    TetheredWing-v0's: Box [-1, 1]^3 float32, elevator, rudder and aileron over their half ranges
    (:class:`~laddermill_gym.envs.wing_env.WingEnv`).

    ## Observation Space

    TetheredWing-v0's: Box (15,) float32, the wing's 15 entries.

    ## Rewards

    TetheredWing-v0's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated], P
    the ground tension x the reel-out speed v0 / 3; every term is in ``info``.

    ## Starting State

    TetheredWing-v0's trim; the wind disturbances are drawn from ``np_random`` at every reset.

    ## Episode End

    TetheredWing-v0's: ``terminated`` on a physical failure (``info["failure"]``), ``truncated`` at
    ``episode_time`` (300 s).

    ## Arguments

    TetheredWing-v0's (:class:`~laddermill_gym.envs.wing_env.WingEnv`); registered: scene ``tethered_wing``,
    scene_options ``{"elements_per_piece": 1}``, physics_step ``"rk4"``, physics_dt 0.025 s, control_dt 0.05 s,
    episode_time 300 s. ``physics_step="ros34pw2", physics_dt=None`` steps it as TetheredWing-v0.

    ## Version History

    * v1: the physics step, two RK4 steps of 25 ms per control period (issue 31 point 4); scene, spaces and rewards
      as v0.
    * v0: initial version (``laddermill_gym/TetheredWing-v0``, unchanged).
    """

    registered_id = "laddermill_gym/TetheredWing-v1"


class TetheredWingV1VectorEnv(WingVectorEnv):
    """``num_envs`` copies of :class:`TetheredWingV1Env` in one batch (TetheredWing-v0's
    :class:`~laddermill_gym.envs.wing_env.WingVectorEnv` with TetheredWing-v1's registered defaults)."""

    registered_id = "laddermill_gym/TetheredWing-v1"
