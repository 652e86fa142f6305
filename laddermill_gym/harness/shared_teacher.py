"""The LQR teacher of a shared per-wing policy as one linear law, for the mill and the fixed chain alike.

A shared policy's actor (:mod:`laddermill_gym.control.shared_policy`) is linear in each wing's lateral deviations,
so what it learns from (DAgger, ``harness.shared_train``) and what it is checked against (``harness.shared_fit``)
is the LQR's law *before* its clip to [-1, 1]: per wing, a = offset - (K dz) / half on the lateral surfaces
(rudder, aileron) and a = offset on the others, with dz the (dy, vy, phi - phi_trim, wrap(psi - psi_trim), p, r)
of every wing, K (2n, 6n) the gain [rad per unit state] and half (n, 2) the surfaces' half ranges [rad per unit
action]. The two LQR controllers hold it in different forms:

* the mill's :class:`~laddermill_gym.control.mill_lqr.MillLQRController` (``K``, ``half``, ``column``): its
  actions are increments around the operating point's settings, so the offset is 0;
* the chain's :class:`~laddermill_gym.control.lqr.LQRController` (``gains``, ``u_trim``, ``mid``,
  ``half_range``): its actions are (u - mid) / half_range with u = u_trim - K dz, so the offset is the trim
  settings' normalised action (u_trim - mid) / half_range (the elevator's trim is not the middle of its range).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["LinearTeacher", "linear_teacher", "make_teacher"]


@dataclass(frozen=True)
class LinearTeacher:
    """The linear law of an LQR controller (see the module doc). ``controller`` is the controller itself (its
    ``predict`` clips what :meth:`labels` gives); ``column`` (2,) the rudder's and aileron's entries within a
    wing's ``n_surfaces`` action entries; ``offset`` (n, n_surfaces) the action at zero deviation; ``act_dim``
    the controller's action entries (the wings' first; any after them, a station's, get 0)."""

    controller: object
    K: np.ndarray
    half: np.ndarray
    column: np.ndarray
    n_surfaces: int
    offset: np.ndarray
    act_dim: int

    @property
    def n_wings(self) -> int:
        return int(self.offset.shape[0])

    @property
    def trim_attitude(self) -> np.ndarray:
        """(n, 2) the (phi, psi) every wing's deviation is measured from [rad]."""
        return np.asarray(self.controller.trim_attitude, dtype=float)

    def labels(self, obs: np.ndarray) -> np.ndarray:
        """The law's actions (B, act_dim) at single-agent observations ``obs`` (B, D), not clipped."""
        obs = np.asarray(obs, dtype=float)
        B, n, m = len(obs), self.n_wings, self.n_surfaces
        dz = np.asarray(self.controller.lateral_deviation(obs), dtype=float).reshape(B, n * 6)
        a = np.zeros((B, self.act_dim))
        wings = a[:, : n * m].reshape(B, n, m)  # a view
        wings[:] = self.offset
        wings[:, :, self.column] -= (dz @ self.K.T).reshape(B, n, 2) / self.half
        return a


def linear_teacher(controller) -> LinearTeacher | None:
    """The :class:`LinearTeacher` of a mill or chain LQR controller; None for any other controller."""
    from laddermill_gym.control.linearize import LATERAL_INPUTS

    if all(hasattr(controller, a) for a in ("lateral_deviation", "K", "half", "column", "n_surfaces")):
        n = int(controller.n_wings)
        return LinearTeacher(controller, np.asarray(controller.K, dtype=float), np.asarray(controller.half, float),
                             np.asarray(controller.column), int(controller.n_surfaces),
                             np.zeros((n, int(controller.n_surfaces))), int(controller.act_dim))
    if all(hasattr(controller, a) for a in ("lateral_deviation", "gains", "u_trim", "mid", "half_range")):
        from laddermill_gym.control.lqr import full_gain

        half_range = np.asarray(controller.half_range, dtype=float)
        offset = (np.asarray(controller.u_trim, dtype=float) - controller.mid) / half_range
        cols = np.array(LATERAL_INPUTS)
        return LinearTeacher(controller, full_gain(controller.gains), half_range[:, cols], cols,
                             half_range.shape[1], offset, int(controller.act_dim))
    return None


def make_teacher(env_id: str, lqr_config: Path | None, env_kwargs: dict | None = None):
    """The LQR controller of ``env_id`` designed with ``lqr_config`` (None: the env's default design,
    ``control.factory.DEFAULT_LQR_CONFIGS``), on the env with ``env_kwargs``."""
    from laddermill_gym.control.factory import make_controller

    return make_controller("lqr" if lqr_config is None else f"lqr:{lqr_config}", env_id, env_kwargs)
