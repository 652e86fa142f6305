"""The moving-cable laddermill as a Gymnasium environment (``laddermill_gym/LadderMill-v0``): the single env, a
:class:`~laddermill_gym.envs.laddermill.task.MillTask` with one copy, and the native vector env, the same task
with many."""

from __future__ import annotations

from laddermill_gym.envs.laddermill.observation import SLOT_OBS_FIELDS, STATION_OBS_FIELDS
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.envs.observation import observation_table
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv

__all__ = ["LadderMillEnv", "LadderMillVectorEnv"]


class LadderMillEnv(TaskEnv):
    """The laddermill of Meijaard, Ockels & Schwab (1999): wings on an endless cable that moves through the ground
    generator, controlled through their tail surfaces by slot.

    ## Description

    Scene ``laddermill`` (configs/scenes/laddermill.yaml: 101 wings on 70 m pieces, V_c = 2 m/s, 3D), simulated by
    the moving-cable kinds (``kernels/moving_cable.py``): the first and last elements change length at the cable
    speed and a wing is transferred from the hauled to the veered side every l0 / V_c = 35 s. The task: keep the
    generator's power up while the loop stays laterally stable in changing wind (default: the paper's 0.01 rad
    wind-direction step at t = 1 s). Many copies: ``gymnasium.make_vec(id, n,
    vectorization_mode="vector_entry_point")``.

    ## Action Space

    Box [-1, 1]^(n_groups x n_surfaces (+1)) float32, by *slot* (slot k = the position k along the loop; a slot's
    command stays with the position while wings travel through it): per group of slots (``groups``:
    "per_slot", "all", "halves" ascending / descending, "bands" of consecutive slots per half, or slot lists), one
    entry per surface in ``surfaces`` (elevator, rudder, aileron), and with ``generator_torque=True`` a last entry
    for the drum's generator torque. a = 0 is the operating point (the scene's fixed tail settings: elevator
    -4 deg ascending, -1 deg descending); a surface is u_op + a x ``authority`` x half its range (15 / 25 / 20 deg
    per unit at ``authority=1``, the default), clipped to the limits; the torque Q_op + a x
    ``drum.torque_half_range`` (:mod:`~laddermill_gym.envs.laddermill.actions`). Entries outside [-1, 1] are
    clipped and counted in ``info["n_clipped"]``.

    ## Observation Space

    Box (15 n + 4,) float32: per slot (slot 0 first) the 15 entries of the wing now in that slot, then the station:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
SLOT_TABLE
STATION_TABLE

    Clipped to generous bounds (:func:`~laddermill_gym.envs.laddermill.observation.mill_observation_bounds`).

    ## Rewards

    r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated], S(x) = 1 - exp(-x);
    P the generator's electrical power at the end of the control period, P_ref the operating point's period mean
    (:class:`~laddermill_gym.envs.laddermill.settings.MillRewardConfig`). Every term is in ``info``.

    ## Starting State

    The mill's periodic stationary motion (:mod:`~laddermill_gym.envs.laddermill.operating_point`): found in plane
    (30-100 s of CPU for the 101-wing mills, memoised per process and kept on disk for later processes in
    ``~/.cache/laddermill_gym``, or ``$LADDERMILL_CACHE_DIR``, ``off`` for none: the same bits as a recomputation,
    :mod:`~laddermill_gym.envs.laddermill.op_cache`), mapped to 3D, just after a transfer; or the
    ``operating_point`` passed in. A small mill that does not converge starts from the state after the settling
    time, with a warning and ``info["operating_point_converged"] = False``. ``initial_noise`` adds random lateral
    velocity and roll / yaw rates to every wing; the wind disturbances are drawn from ``np_random`` at every reset.

    ## Episode End

    ``terminated`` on a physical failure (``info["failure"]``, ``info["failure_name"]``, ``info["failure_reason"]``):
    integration breakdown, a wing or node at the ground (the scene's ground height; the GROUND status) or a wing CG
    below ``termination.min_altitude``, an element over ``breaking_factor`` x the cable's breaking load, or alpha /
    beta of a wing outside ``termination`` (default -30..60 deg, |beta| 60 deg; ``info["n_aero_out_of_band"]``
    counts the slots outside the wing data's attached-flow band without ending). ``truncated`` at ``episode_time``.

    ## Arguments

    scene, scene_options (``load_scene`` overrides, e.g. ``{"n_wings": 11}``), control_dt [s], episode_time [s],
    groups, n_bands, surfaces, authority (share (0, 1] of a surface's half range per unit action), generator_torque,
    drum (:class:`~laddermill_gym.envs.laddermill.settings.DrumConfig`),
    cable_speed_command (the last action commands the cable speed instead), speed
    (:class:`~laddermill_gym.envs.laddermill.settings.SpeedCommandConfig`),
    operating_point, settle (:class:`~laddermill_gym.envs.laddermill.operating_point.SettleConfig`), initial_noise,
    disturbances, wind_dt [s], reward, termination, render_mode ("rgb_array" or "human"), physics_step and
    physics_dt [s] (the physics' fixed-step method, "rk4", "ros2" or "ros34pw2", and its step instead of the
    scene's RK4 at 10 ms; a Rosenbrock-W method steps once per control period by default: ``physics_step=
    "ros34pw2"`` stays within 1e-3 of the mill's extent of the registered step and runs about twice as fast,
    ``envs/physics_step.py``; the operating point and the spaces are the id's either way) and jacobian_every
    (physics steps per iteration matrix of a W-method step; default 1, every step; k > 1 keeps it for k steps,
    fresh on each episode's first step: an opt-in speed option with other last bits).

    ## Version History

    * v3: a new id, ``laddermill_gym/LadderMill-v3`` (:class:`~laddermill_gym.envs.laddermill.env_v3.LadderMillV3Env`):
      v2 with ``physics_step="ros2"``.
    * v2: a new id, ``laddermill_gym/LadderMill-v2`` (:class:`~laddermill_gym.envs.laddermill.env_v2.LadderMillV2Env`):
      the v2 wing (scene ``laddermill_v2``, periodic in plane at 1-5 m/s, 102.2 kW at 2 m/s) and ``authority=0.2``.
    * v1: a new id, ``laddermill_gym/LadderMill-v1`` (:class:`~laddermill_gym.envs.laddermill.env_v1.LadderMillV1Env`):
      the v1 wing (scene ``laddermill_v1``, 152.9 kW at 2 m/s) and ``authority=0.2`` by default; this id keeps its
      scene, dynamics, spaces and rewards.
    * v0: initial version.
    """

    task_class = MillTask

    @property
    def operating_point(self):
        """The :class:`~laddermill_gym.envs.laddermill.operating_point.OperatingPoint` the episodes start from."""
        return self.task.op


class LadderMillVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`LadderMillEnv` in one batch (:class:`~laddermill_gym.envs.vector.TaskVectorEnv`
    over a :class:`~laddermill_gym.envs.laddermill.task.MillTask`; copy i runs the same kernel code as a single env
    seeded seed + i; NextStep, SameStep or Disabled autoreset).

    Observations (num_envs, 15 n + 4) float32; ``info`` holds (num_envs,) arrays of every reward term, the powers
    [W], cable speed [m/s], tensions [N], lowest altitude [m], transfers, t [s], n_clipped, n_aero_out_of_band and
    the failure code (:data:`~laddermill_gym.envs.laddermill.settings.MILL_FAILURES`), each with its ``_name`` mask.
    ``lateral_offsets(obs)``: dy [m] per slot (num_envs, n).

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: one frame per copy), ``autoreset_mode``,
    ``parallel`` (threads; default from 2 copies on: ``task_base.default_parallel``) and the arguments of
    the single env; others raise ValueError.
    """

    task_class = MillTask


LadderMillEnv.__doc__ = (LadderMillEnv.__doc__.replace("SLOT_TABLE", observation_table(SLOT_OBS_FIELDS, "15k + "))
                         .replace("STATION_TABLE", observation_table(STATION_OBS_FIELDS, "15n + ")))
