"""Scripted pumping-cycle controllers of ``laddermill_gym/PumpingKite-v0`` (Lansdorp et al. 2008): the cycle's
winch speed and angle-of-attack schedule, with the rudder and aileron held at trim (``scripted``) or given by the
single wing's lateral LQR (``lqr_cycle``: ``control.lqr.design_tethered_wing`` on the pumping scene's tether held
at its start length, at the reel-out trim).

The phase is read from the observation alone (no memory, so autoreset and batched copies need no bookkeeping):

* reel-out (elevator at the reel-out trim, winch at f w_r, w_r the wind along the tether at the wing, never below
  0): while the winch is not reeling in and less than Delta L is paid out, or when reel-in has brought the tether
  back to its start length (s <= 0);
* depower (elevator at the reel-in setting, winch still reeling out at f w_r): paid out s >= Delta L and the drum
  tension above ``depower_tension`` and s < Delta L + ``depower_overrun``;
* reel-in (elevator at the reel-in setting, winch at -v_in): after the depower, recognised while the winch is
  slowing down or running backwards (V < 0.8 f w_r, the command has turned) and s > 0.

The reel-in elevator is the one that balances the tethered wing's pitching moment about its cable attachment at
``alpha_in`` (``sim.statics.pitch_trim_alpha``, found with ``scipy.optimize.brentq``); the reel-out elevator is the
scene's trim at ``alpha_out``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.optimize import brentq

from laddermill_gym.control.base import batch_observations
from laddermill_gym.envs.observation import N_OBS_PER_WING
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.kernels.contract import CTRL_AILERON, CTRL_ELEVATOR, CTRL_RUDDER
from laddermill_gym.sim.statics import pitch_trim_alpha

__all__ = ["PumpingCycleController", "lateral_lqr", "reel_in_elevator", "PHASE_OUT", "PHASE_DEPOWER", "PHASE_IN"]

PHASE_OUT, PHASE_DEPOWER, PHASE_IN = 0, 1, 2


def reel_in_elevator(wing_type, alpha: float) -> float:
    """Elevator [rad] at which the tethered wing has no pitching moment about its attachment at ``alpha`` [rad]
    (``pitch_trim_alpha``; searched between -15 and 5 deg, the branch where alpha falls as the elevator rises)."""
    lo, hi = math.radians(-15.0), math.radians(5.0)
    f = lambda e: pitch_trim_alpha(wing_type, e) - alpha  # noqa: E731
    if f(lo) * f(hi) > 0:
        raise ValueError(f"alpha_in = {math.degrees(alpha):.2f} deg: no elevator in [-15, 5] deg balances the wing "
                         "there")
    return float(brentq(f, lo, hi, xtol=1e-10))


class PumpingCycleController:
    """The scripted cycle (and, with ``lqr``, its lateral LQR assistance) as an SB3-style controller over
    :class:`~laddermill_gym.envs.pumping.task.PumpingTask` observations (n, 20) -> normalised actions (n, 4).

    Parameters
    ----------
    task : PumpingTask (its cycle, winch, action map and trim are read; it is not stepped)
    lqr : LQRController or None (rudder and aileron at trim)
    """

    def __init__(self, task, lqr=None, action_dtype=np.float32):
        cyc = task.pumping.cycle
        self.cycle = cyc
        self.actions = task.actions
        self.u_out = np.array(task.u_trim[:3], dtype=float)
        self.u_in = self.u_out.copy()
        self.u_in[CTRL_ELEVATOR] = reel_in_elevator(task.scene.assembly.wing(0), cyc.alpha_in)
        self.lqr = lqr
        self.obs_dim = task.obs_dim
        self.action_dtype = action_dtype
        self.last_phase = np.zeros(0, dtype=np.int64)

    def phases(self, obs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(phase (n,) of ``PHASE_*``, reel-out speed f w_r (n,) [m/s]) of observations (n, 20)."""
        i, c = WINCH_OBS_INDEX, self.cycle
        v, s, ten = obs[:, i["winch_speed"]], obs[:, i["paid_out"]], obs[:, i["drum_tension"]]
        v_out = np.maximum(c.reel_out_factor * obs[:, i["radial_wind"]], 0.0)
        phase = np.full(len(obs), PHASE_OUT, dtype=np.int64)
        turning = v < 0.8 * v_out  # the winch has been told to reel in (or is already)
        after = s >= c.reel_length
        depower = after & ~turning & (ten > c.depower_tension) & (s < c.reel_length + c.depower_overrun)
        phase[after & ~depower] = PHASE_IN
        phase[depower] = PHASE_DEPOWER
        phase[(v < 0) & (s > 0)] = PHASE_IN
        phase[(v < 0) & (s <= 0)] = PHASE_OUT
        return phase, v_out

    def controls(self, obs: np.ndarray) -> np.ndarray:
        """Physical controls (n, 4): elevator, rudder, aileron [rad], winch command [m/s or N m]."""
        phase, v_out = self.phases(obs)
        n = len(obs)
        u = np.where((phase == PHASE_OUT)[:, None], self.u_out, self.u_in)
        if self.lqr is not None:
            lat = self.lqr.controls(obs[:, :N_OBS_PER_WING])[:, 0]
            u[:, CTRL_RUDDER], u[:, CTRL_AILERON] = lat[:, CTRL_RUDDER], lat[:, CTRL_AILERON]
        cmd = np.where(phase == PHASE_IN, -self.cycle.reel_in_speed, v_out)
        self.last_phase = phase
        return np.concatenate([u, cmd.reshape(n, 1)], axis=1)

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """Normalised actions (clipped to [-1, 1]) for batched (n, 20) or single (20,) observations."""
        obs, single = batch_observations(observation, self.obs_dim)
        u = self.controls(obs)
        a = np.concatenate([self.actions.tail_actions(u[:, :3]), self.actions.winch_action(u[:, 3:])], axis=1)
        a = np.clip(a, -1.0, 1.0).astype(self.action_dtype)
        return (a[0], state) if single else (a, state)


def lateral_lqr(task, config):
    """The lateral LQR (:class:`~laddermill_gym.control.lqr.LQRController`) of the pumping task's wing: designed on
    the plain scene (tether held at its start length) at the reel-out trim with ``config`` (an LQRConfig or path;
    its control period must be the task's)."""
    from laddermill_gym.control.lqr import LQRConfig, design_tethered_wing, load_lqr_config

    cfg = config if isinstance(config, LQRConfig) else load_lqr_config(config)
    if abs(cfg.control_period - task.control_dt) > 1e-12:
        raise ValueError(f"LQR control_period = {cfg.control_period} s differs from the task's control_dt = "
                         f"{task.control_dt} s")
    ps = task.pumping
    if ps.base is not None:  # a reeling tether: designed on the single-element scene's trim
        x, u = ps.trim(ps.cycle.alpha_out)
        design = design_tethered_wing(cfg, ps.base, (x, u[:3]))
        return design.controller()
    nb = task.xoff
    design = design_tethered_wing(cfg, task.scene, (np.array(task.x_trim[:nb]), np.array(task.u_trim[:3])))
    return design.controller()
