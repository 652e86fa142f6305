"""The single-copy Gymnasium environment over a wing scene (``laddermill_gym/TetheredWing-v0``,
``laddermill_gym/LadderChain-v0``)."""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs.observation import OBS_FIELDS
from laddermill_gym.envs.render import TaskRendering
from laddermill_gym.envs.task import FAILURES, WingTask


def _obs_table() -> str:
    rows = [f"    | 15k + {i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(OBS_FIELDS)]
    return "\n".join(rows)


class WingEnv(TaskRendering, gym.Env):
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
    action_mode, groups, alpha_servo_tau, episode_time, disturbances, wind_dt, reward, termination) and
    ``render_mode`` ("rgb_array" or "human").

    ## Version History

    * v0: initial version.
    """

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 20}

    def __init__(self, render_mode: str | None = None, **task_kwargs):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode = {render_mode!r}: must be one of {self.metadata['render_modes']} or None")
        task_kwargs.pop("n_copies", None)
        self._kwargs = dict(task_kwargs)
        self.task = WingTask(1, parallel=False, **task_kwargs)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=int(round(1.0 / self.task.control_dt)))
        self.observation_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                                self.task.obs_high.astype(np.float32), dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self._renderer = None
        self._needs_reset = True

    # pickling: rebuild from the constructor arguments and restore the copy's state
    def __getstate__(self):
        b = self.task.batch
        return {"kwargs": self._kwargs, "render_mode": self.render_mode, "np_random": self._np_random,
                "arrays": (b.states.copy(), b.controls.copy(), b.t.copy(),
                           *[None if a is None else a.copy() for a in b.air],
                           self.task.steps.copy(), self.task.last_action.copy(),
                           None if self.task.actions.alpha_servo is None else self.task.actions.alpha_servo.copy()),
                "needs_reset": self._needs_reset}

    def __setstate__(self, state):
        self.__init__(render_mode=state["render_mode"], **state["kwargs"])
        self._np_random = state["np_random"]
        b = self.task.batch
        (b.states[:], b.controls[:], b.t[:], *air, self.task.steps[:], self.task.last_action[:],
         servo) = state["arrays"]
        for mine, saved in zip(b.air, air, strict=True):
            if mine is not None:
                mine[:] = saved
        if servo is not None:
            self.task.actions.alpha_servo = servo
        self._needs_reset = state["needs_reset"]
        if not self._needs_reset:
            self.task._nsteps[:] = 0
            self.task._run(self.task._nsteps)

    def _obs(self) -> np.ndarray:
        return self.task.obs[0].astype(np.float32)

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        self.task.reset(np.ones(1, bool), [self.np_random])
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return self._obs(), {"t": 0.0, "reference_power_W": self.task.p_ref}

    def step(self, action):
        if self._needs_reset:
            raise RuntimeError("step() called before reset() or after the episode ended; call reset()")
        reward, terminated, truncated, info = self.task.step(np.asarray(action, dtype=float)[None])
        out = {k: (v[0].item() if isinstance(v, np.ndarray) else v) for k, v in info.items()}
        out["failure_reason"] = self.task.failure_text(0, int(info["failure"][0]))
        out["failure_name"] = FAILURES[int(info["failure"][0])]
        if terminated[0] or truncated[0]:
            self._needs_reset = True
        if self.render_mode == "human":
            self.render()
        return self._obs(), float(reward[0]), bool(terminated[0]), bool(truncated[0]), out


WingEnv.__doc__ = WingEnv.__doc__.replace("OBS_TABLE", _obs_table())
