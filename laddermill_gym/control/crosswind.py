"""The crosswind pumping-cycle controller of the pumping kite (``make_controller("crosswind", env_id)``): figure
eights (or circles) on the wind window during reel-out, a depowered reel-in at high elevation, and the transitions,
as a state machine over the observation (the first 20 entries of ``PumpingKite-v0``'s layout, which v1 keeps).

What it follows:

* **Guidance**: pure pursuit of a lemniscate of Booth (or a circle) on the wind window
  (``control/crosswind_guidance.py``; the path of Rapp, Schmehl, Oland & Haas 2019, "Cascaded pumping cycle
  control for rigid wing airborne wind energy systems", JGCD 42(11)); during the retraction the course aims at a
  park point at high elevation (the "parking" of Fechner & Schmehl's state machine, KiteControllers.jl).
* **Course loop**: the turn-rate command chi_dot = k (chi_c - chi) of Fechner & Schmehl's flight path controller
  (Fechner, Schmehl 2016, "Flight path control of kite power systems in a turbulent wind environment", ACC; Erhard
  & Strauch 2013, "Control of towing kites for seagoing vessels", IEEE TCST 21(5): the turn rate is the steering
  input's direct effect), on the course measured on the wind window (``envs.pumping.wind_window``).
* **A rigid wing turns by banking** (Rapp et al. 2019, the bank-angle command of their course loop): the
  tangential force m (v chi_dot - g_n) needed for the turn, g_n the weight's share along the turn's normal, comes
  from the lift tilted by the bank mu against the tether: sin mu_c = lift_factor m (v chi_dot - g_n) / T (the
  tension T carries the lift; lift_factor > 1 stands for the tether's and the wing's side forces that oppose the
  tilt, tuned). The aileron holds mu_c (PI plus roll damping); the rudder makes the yaw rate the turn rate
  (r = chi_dot about the wing's z axis, which points down the tether in crosswind flight) and cancels the sideslip.
* **Winch**: reel-out at f times the wind along the tether (Loyd's optimum f = 1/3; Lansdorp et al. 2008
  section V), paying out faster above a tension set-point; reel-in at a set speed; elevator at the pitch balance
  of alpha_out / alpha_in (``control.pumping_cycle.reel_in_elevator``).

Its wind window is the scene's nominal wind's (along -x, as the env's observations): it does not follow a
direction disturbance (gusts-v3's EDC turns the wind by 44.5 deg and holds it: the eights are then flown 45 deg off
the new wind, and the entry's airspeed gate reads a wrong airspeed) nor a direction turning with height.

Phases (``PHASE_NAMES``), per copy, kept between calls (reset where ``episode_start`` is true; a loop over a vector
env that autoresets must pass ``episode_start`` = the previous step's terminated | truncated, as SB3's
``evaluate_policy`` does, or a copy's next episode starts in the phase the last one ended in): reel_out (figure
eights) -> retract (still powered, flying straight up out of the power zone to the park elevation, the winch
still paying out) -> reel_in (depowered at alpha_in, held in the wind plane by the wing's lateral LQR, as the
scripted cycle's reel-in, ``control/pumping_cycle.py``) -> entry (repowered, diving to the path, the winch keeping
the tether taut) -> reel_out. A reel-in whose wing falls out of its hang near the zenith (a lull or a gust) goes to
the entry at once (the recovery, counted in ``recoveries``) and the next reel-out starts from the tether then out.
``last_phase`` holds the phase each copy flew.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from laddermill_gym.control.base import batch_observations
from laddermill_gym.control.crosswind_config import (
    DEFAULT_CROSSWIND_CONFIG,
    CrosswindConfig,
    check_against_scene,
    load_crosswind_config,
)
from laddermill_gym.control.crosswind_guidance import PathGuidance, bearing
from laddermill_gym.control.pumping_cycle import reel_in_elevator
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.wind_window import rotations_from_euler, wind_window, window_point
from laddermill_gym.kernels.contract import CTRL_AILERON, CTRL_ELEVATOR, CTRL_RUDDER

__all__ = ["CrosswindController", "PHASE_NAMES", "REEL_OUT", "RETRACT", "REEL_IN", "ENTRY", "wrap"]

REEL_OUT, RETRACT, REEL_IN, ENTRY = 0, 1, 2, 3
PHASE_NAMES = ("reel_out", "retract", "reel_in", "entry")
_G = 9.80665  # [m/s^2] standard gravity
_PARK_MARGIN = math.radians(5.0)  # [rad] the retraction ends this close to the park elevation
_ZENITH_STOP, _ZENITH_SLOW = math.radians(88.0), math.radians(4.0)  # [rad] the reel-in's elevation limit (chosen)
# [N], [m/s per N] the entry's taut-tether law (tuned under NTM turbulence, docs/pumping.md "Turbulence": at 2 kN and
# 1e-3 the diving wing's tether went slack, 110-600 N, the wing flew at its free trim alpha near 0 deg and stalled
# when the tether snatched; at 4 kN and 2e-3 the entries' least drum tension is 1.2-4.4 kN)
_ENTRY_TENSION, _ENTRY_GAIN = 4000.0, 2.0e-3
# [rad] the reel-in's recovery: a wing that has hung above _HANG and falls below _FALL (out of the hang, in a lull or a
# gust) is re-powered and flown to the path (entry) instead of being reeled in while it falls (chosen: the hangs of
# an NTM hour stay above 78.8 deg while they hold, docs/pumping.md "Turbulence")
_HANG, _FALL = math.radians(80.0), math.radians(78.0)
# [m/s] the entry's taut-tether reel-in acts in full above 15 m/s airspeed and not below 10 m/s (a slow wing is
# not hauled in: 9.8 m/s, alpha 20.7 deg and a 6 kN snatch in an NTM entry, seed 1; chosen)
_ENTRY_AIRSPEED = (10.0, 15.0)
_MIN_TENSION = 5000.0  # [N] the bank law's smallest tension (slack-tether turns are not banked harder; tuned)


def wrap(a: np.ndarray) -> np.ndarray:
    """Angles wrapped to [-pi, pi)."""
    return (np.asarray(a) + np.pi) % (2.0 * np.pi) - np.pi


class CrosswindController:
    """The crosswind cycle as an SB3-style controller over pumping observations (n, >= 20) -> normalised actions
    (n, 4). Parameters: the pumping task (its scene, winch, action map, start position and control period are
    read; it is not stepped), the wing's lateral LQR for the reel-in (``control.pumping_cycle.lateral_lqr``), the
    config (path, name or :class:`CrosswindConfig`). The config is checked against
    the scene (``crosswind_config.check_against_scene``)."""

    def __init__(self, task, lqr, config: str | CrosswindConfig = DEFAULT_CROSSWIND_CONFIG,
                 action_dtype=np.float32):
        cfg = config if isinstance(config, CrosswindConfig) else load_crosswind_config(config)
        sc = task.scene
        check_against_scene(cfg, float(np.sum(sc.assembly.elements.l0)), sc.cable.breaking_load,
                            task.min_altitude, task.winch.speed_limits, getattr(task, "max_paid_out", None))
        self.config, self.dt, self.lqr = cfg, float(task.control_dt), lqr
        self.guidance = PathGuidance(cfg.path)
        self.park = window_point(np.array([cfg.path.azimuth]), np.array([cfg.phases.park_elevation]))
        #: the path's two ends (centre azimuth + and - the half span, centre elevation): the entry's targets
        self.path_ends = window_point(cfg.path.azimuth + np.array([1.0, -1.0]) * cfg.path.width,
                                      np.full(2, cfg.path.elevation))
        self.nominal = np.asarray(task.nominal, float).reshape(3)
        wing = sc.assembly.wing(0)
        self.mass = float(wing.mass)
        self.actions, self.obs_dim = task.actions, task.obs_dim
        self.u_trim = np.asarray(task.u_trim[:3], float)
        self.elevator = {REEL_OUT: reel_in_elevator(wing, cfg.phases.alpha_out),
                         RETRACT: reel_in_elevator(wing, cfg.phases.alpha_in)}
        self.speed_limits = tuple(float(v) for v in task.winch.speed_limits)
        self.action_dtype = action_dtype
        self.phase = np.zeros(0, np.int64)
        #: per copy: the reel-in has reached its hang (above 80 deg); recoveries from a fall out of it (counted)
        self.hung, self.recoveries = np.zeros(0, bool), np.zeros(0, np.int64)
        self.path_index = np.zeros(0, np.int64)
        self.integral = np.zeros(0)
        self.last_phase = np.zeros(0, np.int64)
        self.last_course_command = np.zeros(0)

    def reset(self, n: int, mask: np.ndarray | None = None) -> None:
        """Start copies ``mask`` (default all n) afresh: reel-out, path index unknown, no bank integral."""
        if len(self.phase) != n:
            self.phase, self.path_index, self.integral = np.zeros(n, np.int64), np.full(n, -1), np.zeros(n)
            self.hung, self.recoveries = np.zeros(n, bool), np.zeros(n, np.int64)
            return
        m = np.ones(n, bool) if mask is None else np.asarray(mask, bool)
        self.phase[m], self.path_index[m], self.integral[m] = REEL_OUT, -1, 0.0
        self.hung[m], self.recoveries[m] = False, 0

    def _advance_phase(self, ww, s, tension) -> np.ndarray:
        ph, f = self.phase, self.config.phases
        to_retract = (ph == REEL_OUT) & (s >= f.reel_length)
        to_in = (ph == RETRACT) & ((tension < f.depower_tension) | (ww.elevation > f.park_elevation - _PARK_MARGIN))
        self.hung &= ph == REEL_IN
        self.hung |= (ph == REEL_IN) & (ww.elevation > _HANG)
        fell = self.hung & (ww.elevation < _FALL)  # the recovery: out of the hang, re-powered towards the path
        self.recoveries += fell
        to_entry = ((ph == REEL_IN) & (s <= 0.0)) | fell
        ph[to_retract], ph[to_in], ph[to_entry] = RETRACT, REEL_IN, ENTRY
        self.hung &= ~to_entry
        self.path_index[to_entry | to_retract] = -1
        return ph

    def _course_command(self, ww, ph) -> np.ndarray:
        chi_c = bearing(np.broadcast_to(self.park, ww.e_r.shape), ww.e_r, ww.e_phi, ww.e_beta)
        fly = (ph == REEL_OUT) | (ph == ENTRY)
        if fly.any():
            last = np.where(ph[fly] == ENTRY, -1, self.path_index[fly])
            c, idx, dist = self.guidance.course_command(ww.e_r[fly], ww.e_phi[fly], ww.e_beta[fly], last)
            chi_c[fly] = c
            self.path_index[fly] = idx
            rows = np.flatnonzero(fly)
            ph[rows[(ph[fly] == ENTRY) & (dist < self.config.phases.entry_distance)]] = REEL_OUT
        entry = ph == ENTRY  # aim at the path's end on the wing's side: a descent across the wind keeps airspeed
        if entry.any():
            side = (ww.azimuth[entry] < self.config.path.azimuth).astype(int)
            chi_c[entry] = bearing(self.path_ends[side], ww.e_r[entry], ww.e_phi[entry], ww.e_beta[entry])
        return chi_c

    def _steering(self, o: np.ndarray, ww, rot, chi_c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(aileron, rudder) [rad] of the course and bank loops."""
        g = self.config.course
        xb = rot[:, :, 0]
        heading = np.arctan2(np.sum(xb * ww.e_phi, axis=1), np.sum(xb * ww.e_beta, axis=1))
        chi = np.where(ww.tangential_speed > g.heading_speed, ww.course, heading)
        chi_dot = np.clip(g.turn_gain * wrap(chi_c - chi), -g.max_turn_rate, g.max_turn_rate)
        normal = -np.sin(chi)[:, None] * ww.e_beta + np.cos(chi)[:, None] * ww.e_phi
        g_n = _G * normal[:, 2]  # gravity (global +z) along the turn's normal
        tension = np.maximum(o[:, OBS_INDEX["tension"]], _MIN_TENSION)
        sin_mu = g.lift_factor * self.mass * (np.maximum(ww.tangential_speed, g.min_speed) * chi_dot - g_n) / tension
        mu_c = np.arcsin(np.clip(sin_mu, -math.sin(g.max_bank), math.sin(g.max_bank)))
        mu_c = np.where(ww.tangential_speed > g.heading_speed, mu_c, 0.0)  # slow: wings level, the rudder steers
        half = self.actions.half[CTRL_AILERON]
        self.integral = np.clip(self.integral + self.dt * g.bank_integral * (mu_c - ww.bank), -half, half)
        aileron = g.bank_gain * (mu_c - ww.bank) + self.integral - g.roll_damping * o[:, OBS_INDEX["p"]]
        rudder = g.yaw_rate_gain * (o[:, OBS_INDEX["r"]] - chi_dot) - g.sideslip_gain * o[:, OBS_INDEX["beta"]]
        return aileron, rudder

    def _winch(self, o: np.ndarray, ph: np.ndarray, s: np.ndarray, elevation: np.ndarray) -> np.ndarray:
        """Winch speed command [m/s]. Reel-out: f times the along-tether wind, faster above ``max_tension``.
        Reel-in: -reel_in_speed, slowed from ``_ZENITH_SLOW`` below ``_ZENITH_STOP`` to a stop there (reeling in
        lifts the wing towards the zenith, over which it would fall upwind), and paying out again by
        ``overload_gain`` per N of drum tension above ``reel_in_tension`` (the wing still powered after the
        retraction is not hauled in against its full pull). Entry: reel in ``_ENTRY_GAIN`` per N below
        ``_ENTRY_TENSION`` (at most reel_in_speed), so the diving wing keeps its tether taut, in full above
        ``_ENTRY_AIRSPEED[1]`` and not below ``_ENTRY_AIRSPEED[0]`` (a slow wing hauled in stalls)."""
        w, f = self.config.winch, self.config.phases
        tension = o[:, WINCH_OBS_INDEX["drum_tension"]]
        v_out = w.reel_out_factor * np.maximum(o[:, WINCH_OBS_INDEX["radial_wind"]], 0.0)
        v_out = v_out + w.overload_gain * np.maximum(tension - w.max_tension, 0.0)
        slow = np.clip((_ZENITH_STOP - elevation) / _ZENITH_SLOW, 0.0, 1.0)
        v_in = -w.reel_in_speed * slow + w.overload_gain * np.maximum(tension - w.reel_in_tension, 0.0)
        vel = o[:, OBS_INDEX["vx"]:OBS_INDEX["vz"] + 1]  # [m/s] the wing's velocity
        airspeed = np.linalg.norm(vel + o[:, WINCH_OBS_INDEX["wind_speed"], None] * np.array([1.0, 0.0, 0.0]),
                                  axis=1)  # |w - v| with the wind along -x (the scenes' direction) at its speed
        fast = np.clip((airspeed - _ENTRY_AIRSPEED[0]) / (_ENTRY_AIRSPEED[1] - _ENTRY_AIRSPEED[0]), 0.0, 1.0)
        v_entry = -fast * np.minimum(_ENTRY_GAIN * np.maximum(_ENTRY_TENSION - tension, 0.0), w.reel_in_speed)
        cmd = np.select([ph == REEL_OUT, ph == RETRACT, ph == REEL_IN],
                        [v_out, np.where(s < f.reel_length + f.overrun, v_out, 0.0), np.minimum(v_in, v_out)],
                        v_entry)
        return np.clip(cmd, *self.speed_limits)

    def controls(self, obs: np.ndarray) -> np.ndarray:
        """Physical controls (n, 4): elevator, rudder, aileron [rad], winch speed command [m/s]."""
        n = len(obs)
        if len(self.phase) != n:
            self.reset(n)
        o = np.asarray(obs, float)
        i = WINCH_OBS_INDEX
        s, tension = o[:, i["paid_out"]], o[:, i["drum_tension"]]
        rot = rotations_from_euler(o[:, OBS_INDEX["phi"]], o[:, OBS_INDEX["theta"]], o[:, OBS_INDEX["psi"]])
        ww = wind_window(self.nominal + o[:, 0:3], o[:, 3:6], rot)
        ph = self._advance_phase(ww, s, tension)
        chi_c = self._course_command(ww, ph)
        aileron, rudder = self._steering(o, ww, rot, chi_c)
        held = ph == REEL_IN
        if held.any():  # the depowered wing hangs in the wind plane on the lateral LQR, as in the scripted cycle
            lat = self.lqr.controls(o[held, : len(OBS_INDEX)])[:, 0]
            aileron[held] = lat[:, CTRL_AILERON] - self.u_trim[CTRL_AILERON]
            rudder[held] = lat[:, CTRL_RUDDER] - self.u_trim[CTRL_RUDDER]
        u = np.empty((n, 4))
        powered = ph != REEL_IN
        u[:, CTRL_ELEVATOR] = np.where(powered, self.elevator[REEL_OUT], self.elevator[RETRACT])
        u[:, CTRL_AILERON] = self.u_trim[CTRL_AILERON] + aileron
        u[:, CTRL_RUDDER] = self.u_trim[CTRL_RUDDER] + rudder
        u[:, 3] = self._winch(o, ph, s, ww.elevation)
        self.last_phase, self.last_course_command = ph.copy(), chi_c
        return u

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """Normalised actions (clipped to [-1, 1]) for batched (n, obs_dim) or single (obs_dim,) observations;
        copies where ``episode_start`` is true start their cycle afresh."""
        obs, single = batch_observations(observation, self.obs_dim)
        if episode_start is not None:
            self.reset(len(obs), np.asarray(episode_start, bool).reshape(-1))
        u = self.controls(obs[:, : len(OBS_INDEX) + len(WINCH_OBS_INDEX)])
        a = np.concatenate([self.actions.tail_actions(u[:, :3]), self.actions.winch_action(u[:, 3:])], axis=1)
        a = np.clip(a, -1.0, 1.0).astype(self.action_dtype)
        return (a[0], state) if single else (a, state)
