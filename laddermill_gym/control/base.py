"""The controller protocol shared by model-based controllers and RL agents, the observation layout of the
wing environments, and the helpers that map physical controls to normalised actions and simulator views to
observations (so a controller can be run directly on a :class:`~laddermill_gym.sim.simulator.Simulator`)."""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

import numpy as np

from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_FIELDS, OBS_INDEX
from laddermill_gym.model.params import Assembly

__all__ = [
    "Controller",
    "OBS_PER_WING",
    "OBS_NAMES",
    "OBS_INDEX",
    "control_ranges",
    "actions_from_controls",
    "controls_from_actions",
    "batch_observations",
    "observe",
    "elements_below_wings",
]

#: Observation entries per wing, in the environments' order (the table with units:
#: :data:`laddermill_gym.envs.observation.OBS_FIELDS`).
OBS_NAMES: tuple[str, ...] = tuple(f.name for f in OBS_FIELDS)
OBS_PER_WING = N_OBS_PER_WING


@runtime_checkable
class Controller(Protocol):
    """Stable-Baselines3's policy protocol: batched observations in, batched actions out.

    ``observation`` has shape (n_envs, obs_dim) or (obs_dim,); the returned actions have shape
    (n_envs, act_dim) or (act_dim,) to match, normalised to [-1, 1]. ``state`` is a recurrent state
    (None for memoryless controllers) and is returned unchanged.
    """

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        ...


def control_ranges(asm: Assembly) -> tuple[np.ndarray, np.ndarray]:
    """(mid, half_range) of every control of every wing, shape (3 n_wings,) each [rad]; physical
    u = mid + a * half_range for a normalised action a in [-1, 1]."""
    lim = np.concatenate([asm.wing(k).control_limits for k in range(asm.n_wings)])  # (3 n_wings, 2)
    return 0.5 * (lim[:, 0] + lim[:, 1]), 0.5 * (lim[:, 1] - lim[:, 0])


def actions_from_controls(u: np.ndarray, mid: np.ndarray, half: np.ndarray) -> np.ndarray:
    """Normalised actions (u - mid) / half_range (not clipped)."""
    return (np.asarray(u, dtype=float) - mid) / half


def controls_from_actions(a: np.ndarray, mid: np.ndarray, half: np.ndarray) -> np.ndarray:
    """Physical controls [rad] of normalised actions, mid + clip(a, -1, 1) * half_range."""
    return mid + np.clip(np.asarray(a, dtype=float), -1.0, 1.0) * half


def batch_observations(observation: np.ndarray, obs_dim: int) -> tuple[np.ndarray, bool]:
    """(observations as a 2-D float array (n, obs_dim), whether the input was a single vector)."""
    obs = np.asarray(observation, dtype=float)
    single = obs.ndim == 1
    obs2 = obs.reshape(1, -1) if single else obs
    if obs2.ndim != 2 or obs2.shape[1] != obs_dim:
        raise ValueError(f"observation: expected shape (n_envs, {obs_dim}) or ({obs_dim},), got {obs.shape}")
    return obs2, single


def observe(sim, nominal_positions: np.ndarray, below_elements: np.ndarray) -> np.ndarray:
    """The environments' observation vector (``OBS_PER_WING`` entries per wing, layout ``OBS_NAMES``) built from
    a simulator's views at its current state.

    Parameters
    ----------
    sim : Simulator
    nominal_positions : ndarray (n_wings, 3)
        CG positions at the initial equilibrium [m].
    below_elements : int array (n_wings,)
        Index of the cable element below each wing (for the tether tension).
    """
    pos = sim.wing_positions()
    euler = sim.wing_euler()
    R = sim.wing_rotations()
    v_global = np.einsum("nij,nj->ni", R, sim.wing_velocities())
    ab = sim.wing_alpha_beta()
    ten = sim.tensions()[np.asarray(below_elements, dtype=np.int64)]
    obs = np.concatenate([pos - nominal_positions, v_global, euler, sim.wing_rates(), ab, ten[:, None]], axis=1)
    return obs.reshape(-1)


def elements_below_wings(layout, n_wings: int) -> np.ndarray:
    """Index of the element of piece k that ends at wing k, for each wing (chain layouts)."""
    return np.array([layout.piece_elements[k][-1] for k in range(n_wings)], dtype=np.int64)

