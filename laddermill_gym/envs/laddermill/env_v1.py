"""``laddermill_gym/LadderMill-v1``: the laddermill with the v1 wing (issue 30) and learnable defaults (issue 31
point 3). The same task, observations, actions and rewards as ``LadderMill-v0``
(:class:`~laddermill_gym.envs.laddermill.task.MillTask`); what differs is registered with the id
(``envs.ENV_IDS``): the scene ``laddermill_v1`` and ``authority=0.2``. These classes carry the id's own page
(docstring) and version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

from laddermill_gym.envs.laddermill.env import LadderMillEnv, LadderMillVectorEnv
from laddermill_gym.envs.laddermill.observation import SLOT_OBS_FIELDS, STATION_OBS_FIELDS
from laddermill_gym.envs.observation import observation_table

__all__ = ["LadderMillV1Env", "LadderMillV1VectorEnv"]


class LadderMillV1Env(LadderMillEnv):
    """The laddermill with the v1 wing (152.9 kW at 2 m/s, stable in plane), tails by slot at a fifth of v0's range.

    ## Description

    Scene ``laddermill_v1`` (configs/scenes/laddermill_v1.yaml: LadderMill-v0's mill of 101 wings on 70 m pieces
    at V_c = 2 m/s in 3D, with the v1 wing, whose cable attachment lies directly below the wing's aerodynamic centre,
    elevators -8 deg ascending and -0.5 deg descending, and the wing-insertion rule ``cable``: a new wing moves with
    the cable it joins; docs/wing_data.md, "Design study: a stable in-plane mill"). In plane the mill is periodic
    at 152.9 kW with every tension of the period below 150 kN (the 2.5 cm cable's 525 kN breaking load over a
    safety factor of 2.5 is 210 kN). The task: keep the generator's power up while the loop stays laterally
    stable; the default disturbance is the paper's 0.01 rad wind-direction step at t = 1 s, after which the
    open-loop mill leaves the aerodynamic data at about 7 s (a wing near the top of the loop at |beta| > 60 deg);
    the lateral LQR (``make_controller("lqr", id)``, configs/agents/lqr_laddermill_v1.yaml) holds it for 300 s
    within 0.1 m of the in-plane orbit (docs/controllers.md).
    Many copies: ``gymnasium.make_vec(id, n, vectorization_mode="vector_entry_point")``.

    ## Action Space

    LadderMill-v0's layout: Box [-1, 1]^(n_groups x n_surfaces (+1)) float32 by *slot* (``groups``: "per_slot"
    by default, "all", "halves", "bands" or slot lists; one entry per surface in ``surfaces``: elevator, rudder,
    aileron; with ``generator_torque=True`` or ``cable_speed_command=True`` a last entry for the station). a = 0
    holds the operating point (elevator -8 / -0.5 deg, rudder and aileron 0); a surface is u_op + a x
    ``authority`` x half its range, clipped to the limits (:mod:`~laddermill_gym.envs.laddermill.actions`).

    **The learnable default: ``authority=0.2``**, so one unit of action moves the elevator 3 deg, the rudder 5 deg
    and the aileron 4 deg from the operating point (a fifth of the half ranges 15 / 25 / 20 deg). Measured with
    ``env.action_space.sample()`` at every step after the 0.01 rad step (10 seeds; tests/test_laddermill_v1.py):
    at ``authority=1`` (v0's mapping) the median episode ends after 0.82 s (a wing anywhere along the loop
    tumbles out of the aerodynamic data), at 0.5 after 1.5 s, at 0.2 after 6.75 s, close to the open-loop mill's
    7.15 s: random exploration then lasts as long as the instability it has to learn to suppress allows.
    On this mill the just-inserted wing (slot 0) is not the first to fail (the ``cable`` insertion rule), so no
    slot is held at trim. The full authority is one argument away: ``gymnasium.make(id, authority=1.0)``.

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
    point's period mean (152.9 kW) (:class:`~laddermill_gym.envs.laddermill.settings.MillRewardConfig`). Every
    term is in ``info``.

    ## Starting State

    The v1 mill's periodic stationary motion (:mod:`~laddermill_gym.envs.laddermill.operating_point`): found in
    plane from the scene's equilibrium at rest through its 30 s cable-speed ramp (periodic at t = 1,380 s of
    simulated time with the default ``settle``; 82 s of wall time, numba's cache warm, on a 2-core machine shared
    with other runs; memoised per process and on disk, as LadderMill-v0's), mapped
    to 3D just after a transfer; or the ``operating_point`` passed in (it pickles). ``initial_noise`` adds random
    lateral velocity and roll / yaw rates to every wing; the wind disturbances are drawn from ``np_random`` at
    every reset.

    ## Episode End

    LadderMill-v0's: ``terminated`` on a physical failure (``info["failure"]``, ``info["failure_name"]``,
    ``info["failure_reason"]``): integration breakdown, ground contact or a wing below
    ``termination.min_altitude``, an element over ``breaking_factor`` x the cable's breaking load, or alpha / beta
    of a wing outside ``termination`` (default -30..60 deg, |beta| 60 deg). ``truncated`` at ``episode_time``
    (120 s).

    ## Arguments

    LadderMill-v0's (:class:`~laddermill_gym.envs.laddermill.env.LadderMillEnv`); registered: scene
    ``laddermill_v1``, control_dt 0.05 s, episode_time 120 s, authority 0.2.

    ## Version History

    * v2: a new id, ``laddermill_gym/LadderMill-v2`` (the v2 wing, scene ``laddermill_v2``); this id keeps its scene,
      dynamics, spaces and rewards.
    * v1: the v1 wing (scene ``laddermill_v1``: attachment below the wing's ac, elevators -8 / -0.5 deg, the
      ``cable`` insertion rule; 152.9 kW at 2 m/s against v0's 66 kW) and ``authority=0.2`` by default (random
      actions survive a median 6.75 s instead of 0.82 s). Spaces, observation layout and rewards as v0.
    * v0: initial version (``laddermill_gym/LadderMill-v0``, unchanged).
    """

    registered_id = "laddermill_gym/LadderMill-v1"


class LadderMillV1VectorEnv(LadderMillVectorEnv):
    """``num_envs`` copies of :class:`LadderMillV1Env` in one batch (LadderMill-v0's
    :class:`~laddermill_gym.envs.laddermill.env.LadderMillVectorEnv` with LadderMill-v1's registered defaults)."""

    registered_id = "laddermill_gym/LadderMill-v1"


LadderMillV1Env.__doc__ = (LadderMillV1Env.__doc__.replace("SLOT_TABLE", observation_table(SLOT_OBS_FIELDS, "15k + "))
                           .replace("STATION_TABLE", observation_table(STATION_OBS_FIELDS, "15n + ")))
