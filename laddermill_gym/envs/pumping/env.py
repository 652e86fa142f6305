"""The pumping kite as a Gymnasium environment (``laddermill_gym/PumpingKite-v0``): the single env, a
:class:`~laddermill_gym.envs.pumping.task.PumpingTask` with one copy, and the native vector env, the same task with
many."""

from __future__ import annotations

from laddermill_gym.envs.observation import OBS_FIELDS, observation_table
from laddermill_gym.envs.pumping.observation import WINCH_OBS_FIELDS
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv

__all__ = ["PumpingKiteEnv", "PumpingKiteVectorEnv"]


class PumpingKiteEnv(TaskEnv):
    """The pumping kite of Lansdorp et al. (2008): one wing on a tether wound on a winch, flown through its tail
    surfaces while the winch reels out under high lift and in at low lift.

    ## Description

    Pumping config ``pumping_kite`` (configs/pumping/pumping_kite.yaml over the scene configs/scenes/pumping_kite.yaml:
    one Meijaard wing on a 300 m Dyneema tether, 10 m/s wind at 50 m, 3D), simulated by the winch kinds
    (``kernels/winch.py``: the tether's element at the drum changes its rest length with the winch; a commanded-speed
    winch with a 0.5 s lag). The task: make net electrical energy over reel-out / reel-in cycles while the wing
    stays laterally stable (default disturbance: the wing envs' 0.01 rad wind-direction step at t = 1 s).
    Many copies: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    Box [-1, 1]^4 float32:

    | Num | Action | Min | Max | Unit |
    |---|---|---|---|---|
    | 0 | elevator: trim + a x 15 deg | -15 | 15 | deg |
    | 1 | rudder: trim + a x 25 deg | -25 | 25 | deg |
    | 2 | aileron: trim + a x 20 deg | -20 | 20 | deg |
    | 3 | winch command: commanded speed 10 a (a > 0) or 16.7 a (a < 0) | -16.7 | 10 | m/s |

    The drum holds Delta L + 2 depower overruns (240 m): beyond that a reel-out command is replaced by 0 (so no
    policy gains by paying out for ever; checked at each control period's start, and the winch follows with its
    0.5 s lag, so it stops at 240 m plus about V x 0.5 s: 245 m at 10 m/s; the replaced command is not counted in
    ``n_clipped``). The elevator's trim is -0.52 deg, so a = +1 gives 14.48 deg and a below -0.965 meets the -15 deg
    limit. a = 0 holds the reel-out trim with the winch stopped
    (:class:`~laddermill_gym.envs.pumping.actions.PumpingActionMap`; a drum winch takes a torque instead). Entries
    outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

    ## Observation Space

    Box (20,) float32:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
WING_TABLE
WINCH_TABLE

    The CG offsets are from the trim position at the start of reel-out. Clipped to generous bounds
    (:func:`~laddermill_gym.envs.pumping.observation.pumping_observation_bounds`).

    ## Rewards

    r = E_el / (P_ref dt) - w_y S(dy) - w_w S(rates) - failure_penalty [terminated], S(x) = 1 - exp(-x): E_el the
    net electrical energy of the control period (eta times the drum's mechanical energy while generating, over eta
    while reeling in; eta = 0.92, Lansdorp eq. 13), P_ref = 1 kW, w_y = w_w = 0.1, failure_penalty 1e5 (5 MJ, more
    than the uncontrolled wing's dive makes before its crash, less than controlled crosswind flight makes in 400 s)
    (:class:`~laddermill_gym.envs.pumping.settings.PumpingRewardConfig`). The power terms of an episode sum to its
    net electrical energy over P_ref dt. Every term is in ``info``.

    ## Starting State

    The wing trimmed at alpha = 8 deg on the tether held at 300 m, winch at rest, nothing paid out; ``initial_noise``
    adds random lateral velocity and roll / yaw rates; the wind disturbances are drawn from ``np_random`` at every
    reset.

    ## Episode End

    ``terminated`` on a physical failure (``info["failure"]``, ``info["failure_name"]``, ``info["failure_reason"]``):
    integration breakdown (1), the wing at the ground or below ``termination.min_altitude`` (2), the tether over
    ``breaking_factor`` x its breaking load (3), alpha / beta outside ``termination`` (4), or the tether fully
    reeled in, its first element under 5 % of its start length (5, the winch's end stop; reported as 1 before
    2026-12-07). ``truncated`` at ``episode_time`` (default 400 s, about two cycles).

    ## Arguments

    config (a pumping config name or path), scene_options (``load_scene`` overrides), control_dt [s], episode_time
    [s], initial_noise, disturbances, wind_dt [s], reward, termination, render_mode ("rgb_array" or "human").

    ## Version History

    * v0: initial version.
    """

    task_class = PumpingTask


class PumpingKiteVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`PumpingKiteEnv` in one batch (:class:`~laddermill_gym.envs.vector.TaskVectorEnv`
    over a :class:`~laddermill_gym.envs.pumping.task.PumpingTask`; copy i runs the same kernel code as a single env
    seeded seed + i; NextStep, SameStep or Disabled autoreset).

    Observations (num_envs, 20) float32; ``info`` holds (num_envs,) arrays of every reward term, the net electrical
    and mechanical power [W], winch speed [m/s], paid out [m], tensions [N], lowest altitude [m], t [s], n_clipped
    and the failure code (:data:`~laddermill_gym.envs.pumping.settings.PUMPING_FAILURES`), each with its ``_name``
    mask. ``lateral_offsets(obs)``: dy [m] (num_envs, 1).

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: one frame per copy), ``autoreset_mode``,
    ``parallel`` (numba thread pool; default from 32 copies on) and the arguments of the single env; others raise
    ValueError.
    """

    task_class = PumpingTask


PumpingKiteEnv.__doc__ = (PumpingKiteEnv.__doc__.replace("WING_TABLE", observation_table(OBS_FIELDS))
                          .replace("WINCH_TABLE", observation_table(WINCH_OBS_FIELDS, start=len(OBS_FIELDS))))
