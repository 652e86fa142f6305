"""Roberts' tethered twin-rotor craft as a Gymnasium environment (``laddermill_gym/Rotorcraft-v0``).

The physics is the core simulator with the craft's loads (:mod:`laddermill_gym.rotorcraft.craft`: one rigid body,
two Gessow & Myers rotors, fins, frame drag, three tethers of core cable elements). The environment is the
rotorcraft task (:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`) with one copy, stepped by the same
compiled kernel as the native vector env (:class:`RotorcraftVectorEnv`, below),
so a single env and copy i of a vector env seeded alike agree bit for bit. The observation layout lives in
``envs/rotorcraft/observation.py``, the trim and the trim action in ``envs/rotorcraft/trim.py``, the settings in
``envs/rotorcraft/settings.py``; this module re-exports their public names.
"""

from __future__ import annotations

from laddermill_gym.envs.observation import observation_table
from laddermill_gym.envs.rotorcraft.observation import (
    CRAFT_OBS_FIELDS,
    CRAFT_OBS_INDEX,
    N_CRAFT_OBS,
    OBS_P,
    OBS_PHI,
    OBS_PSI,
    OBS_R,
    OBS_VY,
    OBS_Y,
)
from laddermill_gym.envs.rotorcraft.settings import InitialNoise, RotorcraftRewardConfig, RotorcraftTerminationConfig
from laddermill_gym.envs.rotorcraft.task import CRAFT_FAILURES, CraftTask
from laddermill_gym.envs.rotorcraft.trim import control_ranges, craft_trim, trim_action
from laddermill_gym.envs.task_env import TaskEnv
from laddermill_gym.envs.vector import TaskVectorEnv
from laddermill_gym.rotorcraft.craft import CraftSimulator

__all__ = ["RotorcraftEnv", "RotorcraftRewardConfig", "RotorcraftTerminationConfig", "InitialNoise",
           "CRAFT_OBS_FIELDS", "CRAFT_OBS_INDEX", "CRAFT_FAILURES", "N_CRAFT_OBS", "OBS_Y", "OBS_PHI", "OBS_VY",
           "OBS_P", "OBS_PSI", "OBS_R", "craft_trim", "trim_action", "control_ranges",
           "CraftTask", "RotorcraftVectorEnv"]

class RotorcraftEnv(TaskEnv):
    """Roberts' tethered twin-rotor craft held by differential collective pitch.

    ## Description

    Roberts' flying model (configs/rotorcraft/roberts_flying_model.yaml): two contra-rotating rotors side by
    side in a frame with vertical fins, on three tethers (two rear, one forward), generating electricity while
    its rotors carry it (Roberts, "Tethered rotorcraft as a means of electricity generation at high altitude",
    sec. 2, 3 and 7). Below a critical wind speed the craft has a coupled roll / lateral translation
    instability (Roberts sec. 7): at the default 10 m/s an oscillatory roll / lateral / yaw mode (period
    12.6 s) grows until the craft crashes with its trim controls held; in stronger wind it is stable
    (growth rate and period: the unstable eigenvalue of the linearisation at the trim, which
    tests/test_rotorcraft_env.py checks against the open-loop rollout). Roberts stabilises it with the
    differential collective pitch. The task: produce power while holding the craft
    laterally still in changing wind. Simulated by the core kernels with the craft's loads (one compiled call per
    control period, :mod:`laddermill_gym.rotorcraft.craft_observe`; ``env.sim`` is a
    :class:`laddermill_gym.rotorcraft.craft.CraftSimulator` at the current state); the default disturbance is a
    0.01 rad step of the wind direction at t = 1 s. Many copies: ``gymnasium.make_vec(id, n,
    vectorization_mode="vector_entry_point")`` (:class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftVectorEnv`).

    ## Action Space

    Box [-1, 1]^2 float32; entry ``a`` maps linearly onto ``mid + a * half_range`` of the config's limits.
    Entries outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

    | Num | Action | Min | Max | Unit |
    |---|---|---|---|---|
    | 0 | collective pitch theta0 (both rotors) | -5 | 15 | deg |
    | 1 | differential collective dtheta (right theta0 + dtheta, left theta0 - dtheta) | -5 | 5 | deg |

    (limits of the default craft; the environment reads them from the config. The trim action, collective
    4 deg and no differential, is ``env.trim_action`` or :func:`trim_action`.)

    ## Observation Space

    Box (19,) float32; indices of the lateral states are exported as ``OBS_Y``, ``OBS_PHI``, ``OBS_VY``,
    ``OBS_P``, ``OBS_PSI``, ``OBS_R``:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
OBS_TABLE

    Bounds: +-(2 x longest tether + 100 m) for offsets, the integrator's speed / rate limits for velocities and
    rates, natural ranges for angles, +-100 for thrust ratios, 0 to 100 x breaking load / trim tension for
    tension ratios, the reachable blade pitches. Values are clipped to the bounds (a failed step's
    non-finite entries become the bound).

    ## Rewards

    r = w_P P / P_ref - w_y S((dy / y_s)^2) - w_w S((p^2 + r^2) / w_s^2) - w_u S(mean (a - a_trim)^2)
    - failure_penalty [terminated], S(x) = 1 - exp(-x); P the net electrical power, P_ref its trim value
    (:class:`RotorcraftRewardConfig`). Every term is in ``info`` (``reward_power``, ``reward_lateral``,
    ``reward_rates``, ``reward_effort``, ``reward_failure``), and they sum to the reward.

    ## Starting State

    The static equilibrium (trim) of the craft in the steady wind at the trim collective and no differential,
    computed once per (craft, wind speed, collective, physics step) and cached. ``initial_noise`` adds random
    lateral velocity and roll / yaw rates; the wind disturbances are drawn from ``np_random`` at every reset.

    ## Episode End

    ``terminated`` on a physical failure (``info["failure"]`` code, ``info["failure_name"]``,
    ``info["failure_reason"]`` with the time and the quantity): integration breakdown (non-finite state, speed
    or rate limit), a rotor's inflow not converging, the CG below ``termination.min_altitude``, a tether element
    over ``breaking_factor`` x its breaking load, or the attitude outside the termination ranges (roll beyond
    60 deg by default); with ``termination.blade_stall`` (Rotorcraft-v1's default) also a retreating blade tip
    past the rotor's blade-incidence limit. ``truncated`` only when ``episode_time`` is reached.

    ## Arguments

    * ``craft``: craft name in configs/rotorcraft/ or a YAML path (default ``roberts_flying_model``);
    * ``wind_speed`` [m/s]: wind speed v0 at h0 (default: the config's, 10 m/s);
    * ``collective`` [rad]: trim collective (default: the config's, 4 deg);
    * ``control_dt`` [s]: control period, a whole multiple of the physics step (default 0.05);
    * ``physics_dt`` [s]: physics step (default: the config's, one ROS34PW2 step of 50 ms; with ``physics_step`` a
      W-method, the control period);
    * ``physics_step``: the integrator instead of the config's (``"ros1"``, ``"ros2"``, ``"ros2t"``, ``"ros34pw2"``, or
      ``"rk4"`` with a ``physics_dt`` below its stability limit, about 6.2 ms; a step past it is replaced by a finer
      one with an UnstableStepWarning; default None: the config's);
    * ``jacobian_every``: physics steps per iteration matrix of a W-method (default 1: every step);
    * ``episode_time`` [s]: episode length (default 120);
    * ``disturbances``: :class:`~laddermill_gym.atmosphere.disturbances.Disturbance` objects or their config dicts
      (``{"type": "DirectionStep", "step": [-0.05, 0.05]}``; ranges are drawn per episode; every type of
      :mod:`laddermill_gym.atmosphere.disturbance_spec`: IEC gusts, turbulence), or YAML text of them; default the
      0.01 rad direction step at 1 s;
    * ``wind_dt`` [s]: spacing of the sampled wind modulation (default 0.1);
    * ``initial_noise``: dict or :class:`InitialNoise` (random start velocities);
    * ``reward``, ``termination``: dicts or :class:`RotorcraftRewardConfig` / :class:`RotorcraftTerminationConfig`;
    * ``render_mode``: "rgb_array" or "human".

    ## Version History

    * v1: the blade-incidence limit ends an episode (``laddermill_gym/Rotorcraft-v1``,
      :class:`~laddermill_gym.envs.rotorcraft.env_v1.RotorcraftV1Env`).
    * v0: initial version.
    """

    task_class = CraftTask

    @property
    def steps(self) -> int:
        """Control periods since the last reset."""
        return int(self.task.steps[0])

    @property
    def sim(self) -> CraftSimulator:
        """A :class:`CraftSimulator` of the craft at the env's current state, time, controls and wind (a snapshot
        for read-outs and linearisation: stepping it does not step the env)."""
        return self.task.simulator(0)


class RotorcraftVectorEnv(TaskVectorEnv):
    """``num_envs`` copies of :class:`RotorcraftEnv` in one batch (:class:`~laddermill_gym.envs.vector.TaskVectorEnv`
    over a :class:`CraftTask`: copy i equals a single env seeded seed + i bit for bit; NextStep, SameStep or Disabled
    autoreset).

    Observations (num_envs, 19) float32 (clipped to the bounds, as the single env's); ``info`` holds
    (num_envs,) arrays of every reward term, t [s], power_W [W], altitude_m [m], max_tip_incidence_rad [rad],
    n_clipped and failure (code of :data:`~laddermill_gym.envs.rotorcraft.task.CRAFT_FAILURES`), and
    thrust_N (num_envs, 2) [N] and tether_tension_N (num_envs, 3) [N], each with its ``_name`` mask.
    ``lateral_offsets(obs)``: dy [m] (num_envs, 1).

    Parameters: ``num_envs``, ``render_mode`` (``"rgb_array"``: one frame per copy), ``autoreset_mode``, ``parallel``
    (numba thread pool; default from 32 copies on) and the arguments of :class:`RotorcraftEnv` (craft,
    wind_speed [m/s], control_dt [s], episode_time [s], disturbances, ...); others raise ValueError naming them.
    """

    task_class = CraftTask


RotorcraftEnv.__doc__ = RotorcraftEnv.__doc__.replace("OBS_TABLE", observation_table(CRAFT_OBS_FIELDS))
