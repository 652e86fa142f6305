"""Roberts' tethered twin-rotor craft as a Gymnasium environment (``laddermill_gym/Rotorcraft-v0``).

The physics is the core simulator with the craft's loads (:mod:`laddermill_gym.rotorcraft.craft`: one rigid body,
two Gessow & Myers rotors, fins, frame drag, three tethers of core cable elements). The environment is the
rotorcraft task (:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`) with one copy, stepped by the same
compiled kernel as the native vector env (:class:`~laddermill_gym.envs.rotorcraft.vector.RotorcraftVectorEnv`),
so a single env and copy i of a vector env seeded alike agree bit for bit. The observation layout lives in
``envs/rotorcraft/observation.py``, the trim and the trim action in ``envs/rotorcraft/trim.py``, the settings in
``envs/rotorcraft/settings.py``; this module re-exports their public names.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs.actions import single_action
from laddermill_gym.envs.pickling import TaskPickling
from laddermill_gym.envs.render import TaskRendering
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
from laddermill_gym.rotorcraft.config import DEFAULT_CRAFT
from laddermill_gym.rotorcraft.craft import CraftSimulator

__all__ = ["RotorcraftEnv", "RotorcraftRewardConfig", "RotorcraftTerminationConfig", "InitialNoise",
           "CRAFT_OBS_FIELDS", "CRAFT_OBS_INDEX", "CRAFT_FAILURES", "N_CRAFT_OBS", "OBS_Y", "OBS_PHI", "OBS_VY",
           "OBS_P", "OBS_PSI", "OBS_R", "craft_trim", "trim_action", "control_ranges",
           "CraftTask"]

#: Read-only attributes of the task that the env shows as its own (units and shapes: CraftTask).
_TASK_ATTRIBUTES: tuple[str, ...] = (
    "craft", "x_trim", "u_trim", "trim_action", "control_dt", "episode_time", "wind_dt", "n_substeps", "n_steps_max",
    "disturbances", "reward_config", "termination_config", "initial_noise", "nominal_position", "thrust_trim",
    "tension_trim", "p_ref", "lateral_scale", "min_altitude", "breaking_tension")


# ---------------------------------------------------------------------------------------------- the env
def _obs_table() -> str:
    return "\n".join(f"    | {i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(CRAFT_OBS_FIELDS))


class RotorcraftEnv(TaskPickling, TaskRendering, gym.Env):
    """Roberts' tethered twin-rotor craft held by differential collective pitch.

    ## Description

    Roberts' flying model (configs/rotorcraft/roberts_flying_model.yaml): two contra-rotating rotors side by
    side in a frame with vertical fins, on three tethers (two rear, one forward), generating electricity while
    its rotors carry it (Roberts, "Tethered rotorcraft as a means of electricity generation at high altitude",
    sec. 2, 3 and 7). Below a critical wind speed the craft has a coupled roll / lateral translation
    instability (Roberts sec. 7): at the default 10 m/s an oscillatory roll / lateral / yaw mode (period of
    some 15 s) grows until the craft crashes with its trim controls held; in stronger wind it is stable
    (growth rate and period: the unstable eigenvalue of the linearisation at the trim, which
    tests/test_rotorcraft_env.py checks against the open-loop rollout). Roberts stabilises it with the
    differential collective pitch. The task: produce power while holding the craft
    laterally still in changing wind. Simulated by the core kernels with the craft's loads (one compiled call per
    control period, :mod:`laddermill_gym.rotorcraft.craft_observe`; ``env.sim`` is a
    :class:`laddermill_gym.rotorcraft.craft.CraftSimulator` at the current state); the default disturbance is a
    0.01 rad step of the wind direction at t = 1 s. Many copies: ``gymnasium.make_vec(id, n,
    vectorization_mode="vector_entry_point")`` (:class:`~laddermill_gym.envs.rotorcraft.vector.RotorcraftVectorEnv`).

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

    r = P / P_ref - w_y S((dy / y_s)^2) - w_w S((p^2 + r^2) / w_s^2) - w_u S(mean (a - a_trim)^2)
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
    60 deg by default). ``truncated`` only when ``episode_time`` is reached.

    ## Arguments

    * ``craft``: craft name in configs/rotorcraft/ or a YAML path (default ``roberts_flying_model``);
    * ``wind_speed`` [m/s]: wind speed v0 at h0 (default: the config's, 10 m/s);
    * ``collective`` [rad]: trim collective (default: the config's, 4 deg);
    * ``control_dt`` [s]: control period, a whole multiple of the physics step (default 0.05);
    * ``physics_dt`` [s]: RK4 step (default: the config's, 2 ms);
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

    * v0: initial version.
    """

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 20}

    def __init__(self, craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
                 control_dt: float = 0.05, physics_dt: float | None = None, episode_time: float = 120.0,
                 disturbances=None, wind_dt: float = 0.1, initial_noise=None, reward=None, termination=None,
                 render_mode: str | None = None):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode = {render_mode!r}: must be one of {self.metadata['render_modes']} or None")
        self._kwargs = dict(craft=craft, wind_speed=wind_speed, collective=collective, control_dt=control_dt,
                            physics_dt=physics_dt, episode_time=episode_time, disturbances=disturbances,
                            wind_dt=wind_dt, initial_noise=initial_noise, reward=reward, termination=termination)
        self.task = CraftTask(1, parallel=False, **self._kwargs)
        for name in _TASK_ATTRIBUTES:
            setattr(self, name, getattr(self.task, name))
        self.observation_space = gym.spaces.Box(self.task.obs_low, self.task.obs_high, dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=int(round(1.0 / self.control_dt)))
        self._renderer = None
        self._needs_reset = True

    @property
    def steps(self) -> int:
        """Control periods since the last reset."""
        return int(self.task.steps[0])

    @property
    def sim(self) -> CraftSimulator:
        """A :class:`CraftSimulator` of the craft at the env's current state, time, controls and wind (a snapshot
        for read-outs and linearisation: stepping it does not step the env)."""
        return self.task.simulator(0)

    # ------------------------------------------------------------------ Gymnasium API
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        self.task.reset(np.ones(1, bool), [self.np_random])
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), {"t": 0.0, "reference_power_W": self.p_ref}

    def step(self, action):
        a = single_action(action, self.task.n_actions, self._needs_reset)
        reward, terminated, truncated, info = self.task.step(a)
        code = int(info["failure"][0])
        out = {k: (v[0].item() if v.ndim == 1 else v[0].copy()) for k, v in info.items()}
        out["failure_name"] = CRAFT_FAILURES[code]
        out["failure_reason"] = self.task.failure_text(0, code)
        if terminated[0] or truncated[0]:
            self._needs_reset = True
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), float(reward[0]), bool(terminated[0]), bool(truncated[0]), out


RotorcraftEnv.__doc__ = RotorcraftEnv.__doc__.replace("OBS_TABLE", _obs_table())
