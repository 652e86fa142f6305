"""The open-loop baseline: every wing holds its trim controls."""

from __future__ import annotations

from typing import Any

import numpy as np

from laddermill_gym.control.base import OBS_PER_WING, actions_from_controls, batch_observations, control_ranges
from laddermill_gym.ladder.scene import Scene

__all__ = ["OpenLoopController"]


class OpenLoopController:
    """Returns the trim controls as normalised actions whatever the observation (SB3 ``predict`` protocol).

    Parameters
    ----------
    u_trim : ndarray (3 n_wings,)       trim controls [rad]
    mid, half_range : ndarray (3 n_wings,)  control range centre and half width [rad]
    action_dtype : dtype of the returned actions
    """

    def __init__(self, u_trim: np.ndarray, mid: np.ndarray, half_range: np.ndarray, action_dtype=np.float32):
        self.actions = np.clip(actions_from_controls(u_trim, mid, half_range), -1.0, 1.0).astype(action_dtype)
        self.obs_dim = OBS_PER_WING * (self.actions.size // 3)

    @classmethod
    def from_scene(cls, scene: Scene, u_trim: np.ndarray | None = None,
                   action_dtype=np.float32) -> OpenLoopController:
        """Open loop at ``u_trim`` (default: the scene's initial controls)."""
        if u_trim is None:
            _, u_trim = scene.initial_state()
        mid, half = control_ranges(scene.assembly)
        return cls(u_trim, mid, half, action_dtype)

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        obs, single = batch_observations(observation, self.obs_dim)
        if single:
            return self.actions.copy(), state
        return np.tile(self.actions, (len(obs), 1)), state


def craft_open_loop_controller(env_kwargs: dict | None = None):
    """An :class:`OpenLoopController` holding the trim controls of the
    environment with arguments ``env_kwargs`` (only ``craft`` and ``collective`` matter: the open-loop action
    does not depend on the wind or the timing)."""
    from laddermill_gym.envs.rotorcraft.observation import N_CRAFT_OBS
    from laddermill_gym.envs.rotorcraft.trim import DEFAULT_CRAFT, control_ranges, craft_config, trim_controls

    kw = dict(env_kwargs or {})
    cfg = craft_config(str(kw.get("craft", DEFAULT_CRAFT)))
    mid, half = control_ranges(cfg)
    ctrl = OpenLoopController(trim_controls(cfg, kw.get("collective")), mid, half)
    ctrl.obs_dim = N_CRAFT_OBS  # its default assumes the wing layout (15 entries per 3 actions)
    return ctrl
