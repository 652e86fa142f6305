"""Actions of ``laddermill_gym/PumpingKite-v0``: normalised a in [-1, 1]^4 -> the wing's tail commands (elevator,
rudder, aileron) [rad] and the winch command (commanded speed [m/s] or generator torque [N m])."""

from __future__ import annotations

import numpy as np

from laddermill_gym.model.params import N_CONTROLS
from laddermill_gym.model.station import StationParams

__all__ = ["PumpingActionMap", "N_ACTIONS"]

N_ACTIONS = N_CONTROLS + 1


class PumpingActionMap:
    """Tail surfaces: u = u_trim + a x half their range (15 / 25 / 20 deg per unit for the Meijaard wing), clipped
    to the limits (a = 0 holds the reel-out trim). Winch, limits (lo, hi) (``speed_limits`` [m/s] of a commanded
    winch, ``torque_limits`` [N m] of a drum): when lo < 0 < hi, a = 0 is 0 and a = +-1 the limit on its side
    (hi a for a > 0, -lo a for a < 0: full reel-in at -1, full reel-out at +1); otherwise the range's centre plus a
    times its half width.

    Parameters: wing ``limits`` (3, 2) [rad], ``u_trim`` (3,) [rad], the winch (station parameters).
    """

    def __init__(self, limits: np.ndarray, u_trim: np.ndarray, winch: StationParams):
        self.limits = np.asarray(limits, dtype=float).reshape(N_CONTROLS, 2)
        self.half = 0.5 * (self.limits[:, 1] - self.limits[:, 0])
        self.u_trim = np.asarray(u_trim, dtype=float).reshape(N_CONTROLS)
        if winch.mode == "prescribed":
            raise ValueError("PumpingKite needs a winch with a control (mode 'commanded' or 'drum'), not 'prescribed'")
        lo, hi = winch.speed_limits if winch.mode == "commanded" else winch.torque_limits
        self.winch_range = (float(lo), float(hi))
        self.n_actions = N_ACTIONS

    def winch_command(self, a: np.ndarray) -> np.ndarray:
        """Winch command of normalised winch actions (any shape), clipped to [-1, 1] first."""
        lo, hi = self.winch_range
        a = np.clip(np.asarray(a, dtype=float), -1.0, 1.0)
        if lo < 0.0 < hi:
            return np.where(a > 0, hi * a, -lo * a)
        return 0.5 * (lo + hi) + 0.5 * (hi - lo) * a

    def winch_action(self, command: np.ndarray) -> np.ndarray:
        """Normalised action of a winch command (the inverse of :meth:`winch_command`; not clipped)."""
        lo, hi = self.winch_range
        c = np.asarray(command, dtype=float)
        if lo < 0.0 < hi:
            return np.where(c > 0, c / hi, -c / lo)
        return (c - 0.5 * (lo + hi)) / (0.5 * (hi - lo))

    def controls(self, a: np.ndarray) -> np.ndarray:
        """Physical controls (B, 4) of normalised actions (B, 4): tails [rad], winch command."""
        a = np.clip(np.asarray(a, dtype=float), -1.0, 1.0)
        tails = np.clip(self.u_trim + a[:, :N_CONTROLS] * self.half, self.limits[:, 0], self.limits[:, 1])
        return np.concatenate([tails, self.winch_command(a[:, N_CONTROLS:])], axis=1)

    def tail_actions(self, u: np.ndarray) -> np.ndarray:
        """Normalised tail actions of physical tail controls (..., 3) [rad] (not clipped)."""
        return (np.asarray(u, dtype=float) - self.u_trim) / self.half
