"""The wing scenes' environments (``laddermill_gym/TetheredWing-v0``, ``laddermill_gym/LadderChain-v0``): the
single env and the native vector env over :class:`~laddermill_gym.envs.task.WingTask`."""

from __future__ import annotations

from laddermill_gym.envs.observation import OBS_FIELDS, observation_table
from laddermill_gym.envs.task import WingTask
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv


class WingEnv(TaskEnv):
    """Wings of a laddermill scene on their cables, controlled through their tail surfaces.

    ## Description

    One wing on its tether (``laddermill_gym/TetheredWing-v0``) or the paper's 101-wing chain between two
    ground points (``laddermill_gym/LadderChain-v0``), simulated by the numba kernels of
    :mod:`laddermill_gym.kernels` (Meijaard, Ockels & Schwab 1999). The task: hold power-producing flight that
    is laterally stable in changing wind. A wing on a cable is laterally unstable on its own
    (laddermill_gym/docs/lateral_stability.md); the wind disturbances (default: the paper's 0.01 rad direction
    step at t = 1 s) excite that mode.

    ## Action Space

    Box [-1, 1]^(3 n_groups) float32; per group of wings (``groups``), entry ``a`` maps linearly onto
    ``mid + a * half_range`` of the physical range. Entries outside [-1, 1] are clipped and counted in
    ``info["n_clipped"]``.

    | Num | Action (``action_mode="tail"`` / ``"alpha"``) | Min | Max | Unit |
    |---|---|---|---|---|
    | 3g | elevator / commanded angle of attack (servo lag ``alpha_servo_tau``) | -15 / map low | 15 / map high | deg |
    | 3g + 1 | rudder | -25 | 25 | deg |
    | 3g + 2 | aileron | -20 | 20 | deg |

    (limits of the default wing, configs/wings/meijaard_wing.yaml; the environment reads them from the scene.)

    ## Observation Space

    Box (15 n_wings,) float32, per wing in this order (wing 0 first):

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
OBS_TABLE

    Bounds: +-(2 x cable length + 100 m) for offsets, the integrator's speed / rate limits for velocities and
    rates, natural ranges for angles, 0 to 100 x breaking load for tension.

    ## Rewards

    r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated], S(x) = 1 - exp(-x);
    P = ground tension x reel-out speed (v0 / 3) for one tether, the net pull of the two ends for a chain,
    P_ref its value at the trim (:class:`laddermill_gym.envs.task.RewardConfig`). Every term is in ``info``
    (``reward_power``, ``reward_lateral``, ``reward_rates``, ``reward_effort``, ``reward_failure``).

    ## Starting State

    The scene's equilibrium (trim of the single wing, static equilibrium of the chain) with its controls; the
    wind disturbances are drawn from ``np_random`` at every reset.

    ## Episode End

    ``terminated`` on a physical failure: integration breakdown (non-finite state, speed or rate limit), a wing
    CG below ``termination.min_altitude``, cable tension over ``breaking_factor`` x the breaking load, or
    alpha / beta far outside the aerodynamic model (``info["failure"]``, ``info["failure_reason"]`` say which
    and when). ``truncated`` only when ``episode_time`` is reached.

    ## Arguments

    Those of :class:`laddermill_gym.envs.task.WingTask` (scene, scene_options, control_dt, physics_dt,
    physics_step, jacobian_every, action_mode, groups, alpha_servo_tau, episode_time, disturbances, wind_dt, reward,
    termination)
    and ``render_mode`` ("rgb_array" or "human").

    ## Version History

    * v0: initial version.
    """

    task_class = WingTask


class WingVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`WingEnv` in one batch (:class:`~laddermill_gym.envs.vector.TaskVectorEnv` over
    a :class:`~laddermill_gym.envs.task.WingTask`).

    ``info`` holds (num_envs,) arrays of every reward term, power [W], largest tension [N], lowest wing
    altitude [m], time [s], clipped action entries and the failure code (0 flying; see
    :data:`laddermill_gym.envs.task.FAILURES`), each with its ``_name`` mask.

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: one frame per copy), ``autoreset_mode`` ("NextStep",
    "SameStep" or "Disabled"), ``parallel`` (threads; default from 32 copies on, from 2 for the 101-wing
    chain) and the :class:`~laddermill_gym.envs.task.WingTask` arguments.
    """

    task_class = WingTask


WingEnv.__doc__ = WingEnv.__doc__.replace("OBS_TABLE", observation_table(OBS_FIELDS, "15k + "))
