"""``laddermill_gym/LadderMill-v2``: the laddermill with the v2 wing, whose lift falls with its air speed (issue 30
point 1 at 1-5 m/s). The same task, observations, actions and rewards as ``LadderMill-v0`` and ``-v1``
(:class:`~laddermill_gym.envs.laddermill.task.MillTask`); what differs is registered with the id
(``envs.ENV_IDS``): the scene ``laddermill_v2`` and ``authority=0.2`` (v1's). These classes carry the id's own page
(docstring) and version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

from laddermill_gym.envs.laddermill.env import LadderMillEnv, LadderMillVectorEnv
from laddermill_gym.envs.laddermill.observation import SLOT_OBS_FIELDS, STATION_OBS_FIELDS
from laddermill_gym.envs.observation import observation_table

__all__ = ["LadderMillV2Env", "LadderMillV2VectorEnv"]


class LadderMillV2Env(LadderMillEnv):
    """The laddermill with the v2 wing (periodic in plane at 1-5 m/s, 102.2 kW at 2 m/s), tails at a fifth of v0's.

    ## Description

    Scene ``laddermill_v2`` (configs/scenes/laddermill_v2.yaml: LadderMill-v1's mill of 101 wings on 70 m pieces
    at V_c = 2 m/s in 3D with the v2 wing, configs/wings/meijaard_wing_v2.yaml: v1's airframe with the pod moved
    onto the booms, so the CG lies 0.64 m behind the neutral point (unstable in free flight, stable about the cable
    attachment 0.20 m ahead of the neutral point) and a wing's trim angle of attack falls about 0.75 deg per m/s of
    air speed; elevators +1.3 deg ascending and +2.5 deg descending; the cable speed ramped from rest at
    0.01 m/s^2; docs/wing_data.md, "A wing whose lift falls with its air speed (v2)"). In plane the v2 mill is
    periodic at every cable speed from 1 to 5 m/s (v1's only up to 3 m/s) with every tension below the 2.5 cm
    cable's 525 kN breaking load over a safety factor of 2.5 (210 kN); at this id's 2 m/s it delivers 102.2 kW
    (v1: 152.9 kW), at 5 m/s 323.9 kW (``scene_options={"overrides": ...}`` changes the cable speed; the
    operating point is then searched anew). The task: keep the generator's power up while the loop stays
    laterally stable; the default disturbance is the paper's 0.01 rad wind-direction step at t = 1 s, after which
    the open-loop mill leaves the aerodynamic data at 16.2 s (slot 59, at the loop's top, at beta = 60.4 deg); the
    lateral LQR (``make_controller("lqr", id)``, configs/agents/lqr_laddermill_v2.yaml, v1's weights and
    period-mean design on this mill's orbit) holds it for 300 s within 0.09 m of the in-plane orbit at a mean power
    of 102.8 kW, and the same config designed at 1 and 5 m/s holds those mills too (0.088 and 0.086 m;
    tests/test_laddermill_v2.py).
    Many copies: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    LadderMill-v0's layout: Box [-1, 1]^(n_groups x n_surfaces (+1)) float32 by *slot* (``groups``: "per_slot"
    by default, "all", "halves", "bands" or slot lists; one entry per surface in ``surfaces``: elevator, rudder,
    aileron; with ``generator_torque=True`` or ``cable_speed_command=True`` a last entry for the station). a = 0
    holds the operating point (elevator +1.3 / +2.5 deg, rudder and aileron 0); a surface is u_op + a x
    ``authority`` x half its range, clipped to the limits (:mod:`~laddermill_gym.envs.laddermill.actions`).
    ``authority=0.2`` as LadderMill-v1 (the v2 wing's limits are v1's: one unit of action moves the elevator
    3 deg, the rudder 5 deg and the aileron 4 deg). Measured with ``env.action_space.sample()`` at every step after
    the 0.01 rad step (10 seeds; tests/test_laddermill_v2.py): the median episode lasts 17.58 s (15.3-24.1 s),
    about as long as the open-loop mill's 16.2 s.

    ## Observation Space

    Box (15 n + 4,) float32, LadderMill-v0's: per slot (slot 0 first) the 15 entries of the wing now in that slot,
    then the station:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
SLOT_TABLE
STATION_TABLE

    ## Rewards

    LadderMill-v0's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated],
    S(x) = 1 - exp(-x), P the generator's electrical power at the end of the control period, P_ref the operating
    point's period mean (102.2 kW) (:class:`~laddermill_gym.envs.laddermill.settings.MillRewardConfig`). Every
    term is in ``info``.

    ## Starting State

    The v2 mill's periodic stationary motion (:mod:`~laddermill_gym.envs.laddermill.operating_point`): found in
    plane from the scene's equilibrium at rest through its 200 s cable-speed ramp with the default ``settle``
    (periodic at t = 975 s of simulated time; 140 s of wall time, numba's cache warm, on a 2-core machine shared
    with about eight other processes; memoised per process and on disk, as LadderMill-v0's), mapped to 3D just
    after a transfer; or the ``operating_point`` passed in (it pickles). ``initial_noise`` adds random lateral
    velocity and roll / yaw rates to every wing; the wind disturbances are drawn from ``np_random`` at every
    reset.

    ## Episode End

    LadderMill-v0's: ``terminated`` on a physical failure (``info["failure"]``, ``info["failure_name"]``,
    ``info["failure_reason"]``): integration breakdown, ground contact or a wing below
    ``termination.min_altitude``, an element over ``breaking_factor`` x the cable's breaking load, or alpha / beta
    of a wing outside ``termination`` (default -30..60 deg, |beta| 60 deg). ``truncated`` at ``episode_time``
    (120 s).

    ## Arguments

    LadderMill-v0's (:class:`~laddermill_gym.envs.laddermill.env.LadderMillEnv`); registered: scene
    ``laddermill_v2``, control_dt 0.05 s, episode_time 120 s, authority 0.2.

    ## Version History

    * v2: the v2 wing (scene ``laddermill_v2``: CG behind the neutral point, lift falling with air speed,
      elevators +1.3 / +2.5 deg, the cable-speed ramp from rest over 200 s; periodic in plane at 1-5 m/s, 102.2 kW
      at 2 m/s, 323.9 kW at 5 m/s). Spaces, observation layout, rewards and ``authority=0.2`` as v1.
    * v1: the v1 wing (scene ``laddermill_v1``, 152.9 kW at 2 m/s) and ``authority=0.2`` by default
      (``laddermill_gym/LadderMill-v1``, unchanged).
    * v0: initial version (``laddermill_gym/LadderMill-v0``, unchanged).
    """

    registered_id = "laddermill_gym/LadderMill-v2"


class LadderMillV2VectorEnv(LadderMillVectorEnv):
    """``num_envs`` copies of :class:`LadderMillV2Env` in one batch (LadderMill-v0's
    :class:`~laddermill_gym.envs.laddermill.env.LadderMillVectorEnv` with LadderMill-v2's registered defaults)."""

    registered_id = "laddermill_gym/LadderMill-v2"


LadderMillV2Env.__doc__ = (LadderMillV2Env.__doc__.replace("SLOT_TABLE", observation_table(SLOT_OBS_FIELDS, "15k + "))
                           .replace("STATION_TABLE", observation_table(STATION_OBS_FIELDS, "15n + ")))
