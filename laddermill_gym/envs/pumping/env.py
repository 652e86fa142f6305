"""The pumping kite as a Gymnasium environment (``laddermill_gym/PumpingKite-v0``): the single env, a
:class:`~laddermill_gym.envs.pumping.task.PumpingTask` with one copy (the vector env,
:class:`~laddermill_gym.envs.pumping.vector.PumpingKiteVectorEnv`, is the same task with many)."""

from __future__ import annotations

import inspect
from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs.actions import single_action
from laddermill_gym.envs.observation import OBS_FIELDS
from laddermill_gym.envs.pickling import TaskPickling
from laddermill_gym.envs.pumping.observation import WINCH_OBS_FIELDS
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.render import TaskRendering

__all__ = ["PumpingKiteEnv", "TASK_ARGUMENTS", "check_task_arguments"]

#: The PumpingTask arguments the envs take (all but the number of copies; ``parallel`` only in the vector env)
TASK_ARGUMENTS: tuple[str, ...] = tuple(p for p in inspect.signature(PumpingTask).parameters if p != "n_copies")


def check_task_arguments(kwargs: dict, allowed: tuple[str, ...] = TASK_ARGUMENTS) -> None:
    """ValueError naming the arguments (and values) that are not PumpingTask arguments."""
    unknown = sorted(set(kwargs) - set(allowed))
    if unknown:
        raise ValueError(f"{', '.join(f'{k} = {kwargs[k]!r}' for k in unknown)}: not arguments of PumpingKite "
                         f"(known: {', '.join(allowed)})")


def _table(fields, start: int) -> str:
    return "\n".join(f"    | {start + i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(fields))


class PumpingKiteEnv(TaskPickling, TaskRendering, gym.Env):
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
    policy gains by paying out for ever). a = 0 holds the reel-out trim with the winch stopped
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
    than any energy flown before a crash) (:class:`~laddermill_gym.envs.pumping.settings.PumpingRewardConfig`). The
    power terms of an episode sum to its net electrical energy over P_ref dt. Every term is in ``info``.

    ## Starting State

    The wing trimmed at alpha = 8 deg on the tether held at 300 m, winch at rest, nothing paid out; ``initial_noise``
    adds random lateral velocity and roll / yaw rates; the wind disturbances are drawn from ``np_random`` at every
    reset.

    ## Episode End

    ``terminated`` on a physical failure (``info["failure"]``, ``info["failure_name"]``, ``info["failure_reason"]``):
    integration breakdown (including the winch reeling in below 5 % of the tether's start length), the wing at the
    ground or below ``termination.min_altitude``, the tether over ``breaking_factor`` x its breaking load, or alpha /
    beta outside ``termination``. ``truncated`` at ``episode_time`` (default 400 s, about two cycles).

    ## Arguments

    config (a pumping config name or path), scene_options (``load_scene`` overrides), control_dt [s], episode_time
    [s], initial_noise, disturbances, wind_dt [s], reward, termination, render_mode ("rgb_array" or "human").

    ## Version History

    * v0: initial version.
    """

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 20}

    def __init__(self, render_mode: str | None = None, **task_kwargs):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode = {render_mode!r}: must be one of {self.metadata['render_modes']} or None")
        task_kwargs.pop("n_copies", None)
        task_kwargs.pop("max_episode_steps", None)
        check_task_arguments(task_kwargs, tuple(a for a in TASK_ARGUMENTS if a != "parallel"))
        self.task = PumpingTask(1, parallel=False, **task_kwargs)
        self._kwargs = dict(task_kwargs)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=int(round(1.0 / self.task.control_dt)))
        self.observation_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                                self.task.obs_high.astype(np.float32), dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self._renderer = None
        self._needs_reset = True

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        self.task.reset(np.ones(1, bool), [self.np_random])
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), {"t": 0.0}

    def step(self, action):
        a = single_action(action, self.task.n_actions, self._needs_reset)
        reward, terminated, truncated, info = self.task.step(a)
        code = int(info["failure"][0])
        out = {k: v[0].item() for k, v in info.items()}
        out["failure_name"] = self.task.failure_names[code]
        out["failure_reason"] = self.task.failure_text(0, code)
        if terminated[0] or truncated[0]:
            self._needs_reset = True
        if self.render_mode == "human":
            self.render()
        return self.task.obs[0].astype(np.float32), float(reward[0]), bool(terminated[0]), bool(truncated[0]), out


PumpingKiteEnv.__doc__ = (PumpingKiteEnv.__doc__.replace("WING_TABLE", _table(OBS_FIELDS, 0))
                          .replace("WINCH_TABLE", _table(WINCH_OBS_FIELDS, len(OBS_FIELDS))))
