"""The controller protocol shared by model-based controllers and RL agents, the observation layout of the
wing environments, and the helpers that map physical controls to normalised actions and a simulator's state to
the environments' observation (with the environments' kernel, so a controller can be run directly on a
:class:`~laddermill_gym.sim.simulator.Simulator`)."""

from __future__ import annotations

from typing import Any, Protocol, runtime_checkable

import numpy as np

from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_FIELDS, OBS_INDEX
from laddermill_gym.kernels.contract import OK
from laddermill_gym.kernels.rigid.observe import N_AUX, observe_state
from laddermill_gym.model.params import Assembly
from laddermill_gym.sim.simulator import SimulationError

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
    "UnstableDesignWarning",
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
    """The environments' observation vector of a simulator's current state (time ``sim.t``, controls
    ``sim.controls``, the simulator's own wind modulation): shape (n_wings * ``OBS_PER_WING``,) float64, layout
    ``OBS_NAMES``, computed by the environments' kernel
    (:func:`laddermill_gym.kernels.rigid.observe.observe_state` on ``sim.model`` and ``sim.work``).

    Parameters
    ----------
    sim : Simulator
        A simulator of a 3D scene (ValueError for an in-plane one).
    nominal_positions : ndarray (n_wings, 3)
        CG positions at the initial equilibrium [m].
    below_elements : int array (n_wings,)
        Index of the cable element below each wing (for the tether tension).

    Raises
    ------
    ValueError
        In-plane scene, or arguments of the wrong shape or an element index out of range.
    SimulationError
        The mass matrix is singular at the current state.
    """
    asm = sim.assembly
    if asm.dim != 3:
        raise ValueError(f"observe: the wing observation needs a 3D scene, this simulator is in-plane "
                         f"(dimension = {asm.dim})")
    nw = asm.n_wings
    nominal = np.ascontiguousarray(nominal_positions, dtype=np.float64)
    below = np.ascontiguousarray(below_elements, dtype=np.int64)
    if nominal.shape != (nw, 3) or below.shape != (nw,):
        raise ValueError(f"observe: nominal_positions must have shape ({nw}, 3) and below_elements ({nw},), "
                         f"got {nominal.shape} and {below.shape}")
    ne = asm.elements.count
    if np.any((below < -ne) | (below >= ne)):
        raise ValueError(f"observe: below_elements {below.tolist()} outside -{ne}..{ne - 1}")
    below = np.where(below < 0, below + ne, below)  # numpy's meaning of a negative index
    obs, aux = np.zeros(nw * N_OBS_PER_WING), np.zeros(N_AUX)
    if observe_state(float(sim.t), sim.state, sim.controls, sim.model, sim.work, nominal, below,
                     np.array([-1, -1], dtype=np.int64), obs, aux) != OK:
        raise SimulationError(f"t = {sim.t:.6g} s: the mass matrix is singular")
    return obs


def elements_below_wings(layout, n_wings: int) -> np.ndarray:
    """Index of the element of piece k that ends at wing k, for each wing (chain layouts)."""
    return np.array([layout.piece_elements[k][-1] for k in range(n_wings)], dtype=np.int64)


class UnstableDesignWarning(UserWarning):
    """An LQR whose closed loop grows: a mill's over the orbit's period (Floquet: the transition matrix's spectral
    radius is 1 or more), a decentralised chain design's on the full coupled lateral model, a craft's eq. (6) gain on
    the whole craft's linear model (max |z| of the discrete closed loop 1 or more); flown as asked (a small test
    mill, a study of a design that fails), said once per build (``control.factory.make_controller``)."""
