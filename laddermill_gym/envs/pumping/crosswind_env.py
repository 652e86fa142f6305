"""``laddermill_gym/PumpingKite-v1``, crosswind pumping: the single env (a
:class:`~laddermill_gym.envs.pumping.crosswind_task.CrosswindTask` with one copy) and the native vector env (the
same task with many)."""

from __future__ import annotations

from laddermill_gym.envs.observation import OBS_FIELDS, observation_table
from laddermill_gym.envs.pumping.crosswind_observation import CROSSWIND_OBS_FIELDS
from laddermill_gym.envs.pumping.crosswind_task import CrosswindTask
from laddermill_gym.envs.pumping.observation import WINCH_OBS_FIELDS
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv

__all__ = ["CrosswindKiteEnv", "CrosswindKiteVectorEnv"]


class CrosswindKiteEnv(TaskEnv):
    """Crosswind pumping (issue 29): the pumping kite of ``PumpingKite-v0`` (one Meijaard wing on a 300 m tether on
    a winch) flown across the wind during reel-out, as pumping kites fly (Lansdorp et al. 2008 eqs. 7-15; Loyd
    1980), with the observation a kite's flight controller has.

    ## Description

    The physics, scene, winch, actions and failures are v0's (:class:`~laddermill_gym.envs.pumping.env.
    PumpingKiteEnv`; configs/pumping/pumping_kite.yaml: 10 m/s wind at 50 m, the 0.01 rad direction step at
    1 s by default). The task: net electrical energy over reel-out / reel-in cycles, with the wing flown crosswind
    (figure eights or circles) during reel-out; the baseline is the crosswind controller
    (``make_controller("crosswind", "laddermill_gym/PumpingKite-v1")``, ``control/crosswind.py``). Many copies:
    ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    Box [-1, 1]^4 float32, v0's: elevator, rudder, aileron (trim plus a times 15 / 25 / 20 deg) and the winch's
    commanded speed (10 a m/s for a > 0, 16.7 a m/s for a < 0); the drum holds 240 m.

    ## Observation Space

    Box (29,) float32: v0's 20 entries, then the wind-window entries:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
WING_TABLE
WINCH_TABLE
CROSSWIND_TABLE

    Angles as ``envs/pumping/wind_window.py`` defines them (the winch at the origin, the wind towards -x). Clipped
    to generous bounds (:func:`~laddermill_gym.envs.pumping.crosswind_observation.crosswind_bounds`).

    ## Rewards

    r = E_el / (P_ref dt) - w_w S(rates) - w_b S((beta / 0.35)^2) - w_T S(max(0, T_max - 0.4 F_b) / (0.1 F_b))
    - failure_penalty [terminated], S(x) = 1 - exp(-x): E_el the net electrical energy of the control period (eta
    x the drum's energy generating, over eta motoring; eta = 0.92), P_ref = 10 kW, w_w = w_b = 0.1, w_T = 1, T_max
    the largest tether tension, F_b its breaking load (525 kN), failure_penalty 2e5
    (:class:`~laddermill_gym.envs.pumping.crosswind_task.CrosswindRewardConfig`). No wind-plane penalty. Every term
    is in ``info``.

    ## Starting State

    v0's: the wing trimmed at alpha = 8 deg on the tether held at 300 m (elevation 80 deg), the winch at rest.

    ## Episode End

    v0's failures (integration breakdown, ground contact or below ``termination.min_altitude``, tether over its
    breaking load, alpha / beta out of range); ``truncated`` at ``episode_time`` (default 600 s, about two
    crosswind cycles).

    ## Arguments

    v0's: config, scene_options, control_dt [s], episode_time [s], initial_noise, disturbances, wind_dt [s],
    reward, termination, render_mode.

    ## Version History

    * v1: crosswind pumping (this env); v0 keeps the static-cycle env (its observation, 400 s episodes and reward).
    """

    task_class = CrosswindTask


class CrosswindKiteVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`CrosswindKiteEnv` in one batch (:class:`~laddermill_gym.envs.vector.
    TaskVectorEnv` over a :class:`~laddermill_gym.envs.pumping.crosswind_task.CrosswindTask`); observations
    (num_envs, 29) float32, ``info`` as v0's vector env plus ``reward_sideslip`` and ``reward_tension``."""

    task_class = CrosswindTask


CrosswindKiteEnv.__doc__ = (CrosswindKiteEnv.__doc__.replace("WING_TABLE", observation_table(OBS_FIELDS))
                            .replace("WINCH_TABLE", observation_table(WINCH_OBS_FIELDS, start=len(OBS_FIELDS)))
                            .replace("CROSSWIND_TABLE", observation_table(
                                CROSSWIND_OBS_FIELDS, start=len(OBS_FIELDS) + len(WINCH_OBS_FIELDS))))
