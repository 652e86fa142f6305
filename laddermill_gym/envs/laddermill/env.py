"""The moving-cable laddermill as a Gymnasium environment (``laddermill_gym/LadderMill-v0``): the single env, a
:class:`~laddermill_gym.envs.laddermill.task.MillTask` with one copy (the vector env,
:class:`~laddermill_gym.envs.laddermill.vector.LadderMillVectorEnv`, is the same task with many)."""

from __future__ import annotations

import inspect
from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs.actions import single_action
from laddermill_gym.envs.laddermill.observation import SLOT_OBS_FIELDS, STATION_OBS_FIELDS
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.envs.pickling import TaskPickling
from laddermill_gym.envs.render import TaskRendering

__all__ = ["LadderMillEnv", "TASK_ARGUMENTS", "check_task_arguments"]

#: The MillTask arguments the envs take (all but the number of copies; ``parallel`` only in the vector env)
TASK_ARGUMENTS: tuple[str, ...] = tuple(p for p in inspect.signature(MillTask).parameters if p != "n_copies")


def check_task_arguments(kwargs: dict, allowed: tuple[str, ...] = TASK_ARGUMENTS) -> None:
    """ValueError naming the arguments (and values) that are not MillTask arguments."""
    unknown = sorted(set(kwargs) - set(allowed))
    if unknown:
        raise ValueError(f"{', '.join(f'{k} = {kwargs[k]!r}' for k in unknown)}: not arguments of LadderMill "
                         f"(known: {', '.join(allowed)})")


def _table(fields, first: str) -> str:
    return "\n".join(f"    | {first}{i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(fields))


class LadderMillEnv(TaskPickling, TaskRendering, gym.Env):
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
    -4 deg ascending, -1 deg descending); a surface is u_op + a x half its range (15 / 25 / 20 deg per unit),
    clipped to the limits; the torque Q_op + a x ``drum.torque_half_range`` (:mod:`~laddermill_gym.envs.laddermill.
    actions`). Entries outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

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
    (about 30 s for the default mill, memoised per process), mapped to 3D, just after a transfer; or the
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
    groups, n_bands, surfaces, generator_torque, drum (:class:`~laddermill_gym.envs.laddermill.settings.DrumConfig`),
    cable_speed_command (the last action commands the cable speed instead), speed
    (:class:`~laddermill_gym.envs.laddermill.settings.SpeedCommandConfig`),
    operating_point, settle (:class:`~laddermill_gym.envs.laddermill.operating_point.SettleConfig`), initial_noise,
    disturbances, wind_dt [s], reward, termination, render_mode ("rgb_array" or "human").

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
        self.task = MillTask(1, parallel=False, **task_kwargs)
        # pickles carry the operating point, so an unpickled env does not recompute it
        self._kwargs = dict(task_kwargs, operating_point=self.task.op)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=int(round(1.0 / self.task.control_dt)))
        self.observation_space = gym.spaces.Box(self.task.obs_low.astype(np.float32),
                                                self.task.obs_high.astype(np.float32), dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(self.task.n_actions,), dtype=np.float32)
        self._renderer = None
        self._needs_reset = True

    @property
    def operating_point(self):
        """The :class:`~laddermill_gym.envs.laddermill.operating_point.OperatingPoint` the episodes start from."""
        return self.task.op

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        self.task.reset(np.ones(1, bool), [self.np_random])
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        op = self.task.op
        info = {"t": 0.0, "reference_power_W": self.task.p_ref, "operating_point_converged": op.converged,
                "operating_point_note": op.note}
        return self.task.obs[0].astype(np.float32), info

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


LadderMillEnv.__doc__ = (LadderMillEnv.__doc__.replace("SLOT_TABLE", _table(SLOT_OBS_FIELDS, "15k + "))
                         .replace("STATION_TABLE", _table(STATION_OBS_FIELDS, "15n + ")))
