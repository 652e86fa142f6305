"""Blade-tip guard for Roberts' tethered twin-rotor craft: the eq. (6) LQR's differential collective, and a collective
lowered whenever the retreating blade tips would pass the rotor model's incidence limit.

Rotorcraft-v1 ends an episode when a retreating tip passes Roberts' 13 deg blade-incidence limit; a gust raises the
tip's incidence at a fixed collective (+1.1 deg for 10 % more wind at the default trim), and the LQR
(:mod:`~laddermill_gym.control.craft_lqr`) moves only the differential. No observation gives the tip's incidence or
the wind. This guard estimates each rotor's tip incidence from what the env observes: the rotor's thrust over its
trim thrust T, its blade pitch, and the craft's offsets, velocities, attitude and rates s. On the linearised rotor
(:func:`linearise_tips`: central differences of the craft simulator's rotor outputs at the trim),

    T - 1 = G_w w + G_th dth + G_s ds,       alpha = alpha_0 + A_w w + A_th dth + A_s ds,

with w the relative change of the wind speed along the mean wind (the one unknown), dth the blade pitch's change
and ds the observed state's. The thrust gives w, w gives the tip's incidence alpha, and the blade pitch that puts
alpha at ``limit - margin`` in the present air is pitch + (limit - margin - alpha) / A_th. The collective is the
least of the trim collective and, for each rotor, that pitch less the rotor's share of the differential
(right: theta0 + dtheta, left: theta0 - dtheta), clipped to the craft's collective range. It acts a control period
late, and the wind's direction and vertical part are not observed: the margin (``configs/agents/
lqr_guard_rotorcraft.yaml``) covers both. Where the trim's tips lie below ``limit - margin`` (the default craft:
10.1 deg against 13 - 2.5 deg), the guard leaves the trim collective alone near the trim, so an undisturbed episode
is the LQR's.

``mode: hold`` (configs/agents/lqr_tip_hold_rotorcraft.yaml) holds the rotors' mean tip incidence at the trim's
instead, in gusts and lulls alike: the collective is the rotors' mean of pitch + (alpha_trim - alpha) / A_th, in which
the differential cancels (so with a differential one tip lies above the trim's incidence, the other below). That law
is affine in the observation (up to the actions' clip), so a PPO actor without hidden layers can start exactly at it
(``init_from`` in a training config, control/warm_start.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from laddermill_gym.control.base import batch_observations
from laddermill_gym.control.craft_lqr import CraftLQRController, CraftLQRDesign
from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL, CU_COLLECTIVE, CU_DIFFERENTIAL
from laddermill_gym.model.configio import CONFIG_DIR, find_config, read_yaml
from laddermill_gym.model.states import euler_from_quaternion, quaternion_from_euler, rotation_from_euler

DEFAULT_TIP_GUARD = CONFIG_DIR / "agents" / "lqr_guard_rotorcraft.yaml"

#: The observed rigid-body entries the estimate uses, in this order (Rotorcraft-v0's observation names).
STATE_NAMES = ("dx", "dy", "dz", "vx", "vy", "vz", "phi", "theta", "psi", "p", "q", "r")
#: Central-difference half steps: wind factor [-], blade pitch [rad], then per STATE_NAMES entry [m, m/s, rad, rad/s].
_H_WIND, _H_PITCH = 1e-3, 1e-4
_H_STATE = (1e-2,) * 3 + (1e-3,) * 3 + (1e-4,) * 3 + (1e-4,) * 3
#: Right and left rotor: observation names of thrust ratio and blade pitch, and the sign of the differential.
ROTORS = (("thrust_right", "pitch_right", 1.0), ("thrust_left", "pitch_left", -1.0))


@dataclass(frozen=True)
class TipGuardConfig:
    """A guard: its file, the LQR config it flies the differential with, its mode ("limit": lower the collective
    only past ``limit - margin``; "hold": hold the tips at the trim's incidence) and the margin [rad] below the limit
    (0 in hold mode)."""

    file: Path
    lqr: Path
    margin: float
    mode: str = "limit"


def load_tip_guard_config(path: str | Path = DEFAULT_TIP_GUARD) -> TipGuardConfig:
    """Read a guard YAML (``path``: a file or a shipped config's bare name) strictly: unknown keys, a missing LQR
    config, a mode other than limit or hold, or a margin outside [0, 5] deg (none in hold mode) raise ConfigError
    naming the file and the field."""
    path = find_config("agents", path, "config")
    s = read_yaml(path)
    lqr = find_config("agents", s.text("lqr"), "lqr")
    mode = s.text("mode", "limit", choices=("limit", "hold"))
    if mode == "hold":
        if s.has("margin_deg"):
            raise s.error("margin_deg", s.raw("margin_deg"), "has no meaning with mode: hold (the tips are held at the "
                          "trim's incidence)")
        margin = 0.0
    else:
        margin = s.number("margin_deg", low=0.0, high=5.0, why="past 5 deg the guard holds the trim collective down "
                          "in calm air")
    s.done()
    return TipGuardConfig(Path(path), Path(lqr), math.radians(margin), mode)


@dataclass(frozen=True)
class TipModel:
    """The linearised tips of the two rotors (right, left) at the trim; rows per rotor.

    alpha0 (2,) [rad]; thrust-ratio partials g_wind (2,) [per unit wind factor], g_pitch (2,) [1/rad],
    g_state (2, 12) [per STATE_NAMES unit]; tip partials a_wind, a_pitch, a_state likewise [rad per unit];
    s_trim (12,): the trim's observed state; pitch_trim [rad]: the trim's blade pitch (the collective);
    limit [rad]: the craft's blade-incidence limit."""

    alpha0: np.ndarray
    g_wind: np.ndarray
    g_pitch: np.ndarray
    g_state: np.ndarray
    a_wind: np.ndarray
    a_pitch: np.ndarray
    a_state: np.ndarray
    s_trim: np.ndarray
    pitch_trim: float
    limit: float

    def tips(self, thrust_ratio: np.ndarray, pitch: np.ndarray, state: np.ndarray) -> np.ndarray:
        """Estimated retreating-tip incidence [rad], shape (n, 2), from thrust ratios and blade pitches [rad]
        (n, 2) and observed states (n, 12) in STATE_NAMES order."""
        ds = np.asarray(state, float) - self.s_trim
        dth = np.asarray(pitch, float) - self.pitch_trim
        w = (np.asarray(thrust_ratio, float) - 1.0 - self.g_pitch * dth - ds @ self.g_state.T) / self.g_wind
        return self.alpha0 + self.a_wind * w + self.a_pitch * dth + ds @ self.a_state.T


def observed_state(x: np.ndarray, o: int) -> np.ndarray:
    """The 12 STATE_NAMES values, shape (12,), of the rigid body at offset o of the state x (n_state,): offsets 0
    (relative to its own position), global velocity [m/s], 3-2-1 Euler angles [rad], body rates [rad/s]."""
    e = np.array(euler_from_quaternion(x[o + B3_QUAT:o + B3_QUAT + 4]))
    s = np.zeros(12)
    s[3:6] = rotation_from_euler(*e) @ x[o + B3_VEL:o + B3_VEL + 3]
    s[6:9] = e
    s[9:12] = x[o + B3_RATE:o + B3_RATE + 3]
    return s


def with_observed_state(x: np.ndarray, o: int, s: np.ndarray, s_trim: np.ndarray) -> np.ndarray:
    """A copy of x (n_state,) with the body at offset o moved to the observed state s (12,), STATE_NAMES order
    (its offsets s[0:3] - s_trim[0:3] [m] added to the body's position in x)."""
    y = np.array(x, dtype=float)
    y[o + B3_POS:o + B3_POS + 3] += s[0:3] - s_trim[0:3]
    y[o + B3_QUAT:o + B3_QUAT + 4] = quaternion_from_euler(*s[6:9])
    y[o + B3_VEL:o + B3_VEL + 3] = rotation_from_euler(*s[6:9]).T @ s[3:6]
    y[o + B3_RATE:o + B3_RATE + 3] = s[9:12]
    return y


def linearise_tips(design: CraftLQRDesign) -> TipModel:
    """The tips' linearisation at the LQR design's trim: central differences of the simulator's rotor outputs
    (thrust [N] and retreating-tip incidence [rad] per rotor) in the wind speed, the collective and each observed
    state entry (about 50 evaluations of the craft's right-hand side and three craft builds)."""
    from laddermill_gym.rotorcraft.craft import load_craft
    from laddermill_gym.rotorcraft.craft_observe import CRAFT_BODY

    sim0 = design.sim
    o = B3_SIZE * CRAFT_BODY
    x0, u0 = np.array(design.x_trim, float), np.array(design.u_trim, float)
    s0 = observed_state(x0, o)
    v0 = sim0.config.wind.v0
    sims = {1.0: sim0}

    def outputs(s: np.ndarray, dpitch: float = 0.0, factor: float = 1.0) -> np.ndarray:
        if factor not in sims:
            sims[factor] = load_craft(config=sim0.config.with_wind_speed(v0 * factor)).simulator(state=x0)
        sim = sims[factor]
        sim.state[:] = with_observed_state(x0, o, s, s0)
        sim.controls[:] = u0 + np.array([dpitch, 0.0])
        r = sim.rotor_outputs()
        return np.concatenate([r["thrust_N"], r["tip_incidence_rad"]])

    def central(f, h: float) -> np.ndarray:
        return (f(h) - f(-h)) / (2.0 * h)

    base = outputs(s0)
    d_wind = central(lambda h: outputs(s0, factor=1.0 + h), _H_WIND)
    d_pitch = central(lambda h: outputs(s0, dpitch=h), _H_PITCH)
    d_state = np.empty((4, 12))
    for j in range(12):
        step = np.zeros(12)
        step[j] = 1.0
        d_state[:, j] = central(lambda h, e=step: outputs(s0 + h * e), _H_STATE[j])
    sim0.state[:], sim0.controls[:] = x0, u0
    t0 = base[:2]
    where = f"{sim0.config.name} at {v0:g} m/s, collective {u0[CU_COLLECTIVE]:.6g} rad"
    for name, values in (("thrust per unit wind factor", d_wind[:2]), ("tip incidence per rad of pitch", d_pitch[2:]),
                         ("thrust per rad of pitch", d_pitch[:2])):
        if not np.all(np.isfinite(values) & (values > 0.0)):
            raise ValueError(f"linearise_tips: {where}: the rotors' {name} is {values.tolist()}, not positive: the "
                             f"guard's estimate (thrust -> wind -> tip) and its collective law need it positive")
    return TipModel(alpha0=base[2:], g_wind=d_wind[:2] / t0, g_pitch=d_pitch[:2] / t0,
                    g_state=d_state[:2] / t0[:, None], a_wind=d_wind[2:], a_pitch=d_pitch[2:], a_state=d_state[2:],
                    s_trim=s0, pitch_trim=float(u0[CU_COLLECTIVE]), limit=float(sim0.config.blade_incidence_limit))


def guard_controller(guard: TipGuardConfig, lqr: CraftLQRController, design: CraftLQRDesign, collective_limits,
                     obs_index: dict) -> TipGuardController:
    """The guard of config ``guard`` around ``lqr`` (the LQR of ``design``), linearised at the design's trim."""
    return TipGuardController(lqr, linearise_tips(design), guard.margin, collective_limits, obs_index, guard.mode)


class TipGuardController:
    """The eq. (6) LQR's differential, the collective from the blade-tip guard (module docstring).

    Parameters
    ----------
    lqr : CraftLQRController      the differential's controller (and the env's action map)
    model : TipModel              the linearised tips
    margin : float                target below the blade-incidence limit [rad]
    collective_limits : (2,)      the craft's collective range [rad]
    obs_index : dict              observation name -> index (the env's ``CRAFT_OBS_INDEX``)
    mode : str                    "limit" or "hold" (module docstring)
    """

    def __init__(self, lqr: CraftLQRController, model: TipModel, margin: float, collective_limits, obs_index: dict,
                 mode: str = "limit"):
        if mode not in ("limit", "hold"):
            raise ValueError(f"TipGuardController: mode {mode!r} must be 'limit' or 'hold'")
        self.lqr = lqr
        self.model = model
        self.mode = mode
        self.action_dtype = lqr.action_dtype  # float64 when warm_start.affine_map probes the (hold) law
        self.margin = float(margin)
        self.collective_limits = tuple(float(v) for v in collective_limits)
        self.obs_dim = lqr.obs_dim
        self.state_index = np.array([obs_index[n] for n in STATE_NAMES])
        self.thrust_index = np.array([obs_index[t] for t, _, _ in ROTORS])
        self.pitch_index = np.array([obs_index[p] for _, p, _ in ROTORS])
        self.signs = np.array([s for _, _, s in ROTORS])

    def estimated_tips(self, observation: np.ndarray) -> np.ndarray:
        """Estimated retreating-tip incidence [rad] (n, 2) of observations (n, obs_dim)."""
        obs = np.asarray(observation, float)
        return self.model.tips(obs[:, self.thrust_index], obs[:, self.pitch_index], obs[:, self.state_index])

    def controls(self, observation: np.ndarray) -> np.ndarray:
        """Controls (collective, differential) [rad], shape (n, 2), for observations (n, obs_dim), each within the
        range the env applies."""
        obs = np.asarray(observation, float)
        u = self.lqr.controls(obs)
        lo, hi = self.lqr.mid[CU_DIFFERENTIAL] + np.array([-1.0, 1.0]) * self.lqr.half[CU_DIFFERENTIAL]
        diff = np.clip(u[:, CU_DIFFERENTIAL], lo, hi)  # the differential the env applies
        u[:, CU_DIFFERENTIAL] = diff
        pitch = obs[:, self.pitch_index]
        if self.mode == "hold":  # the differential cancels in the mean: affine in the observation
            room = (self.model.alpha0 - self.estimated_tips(obs)) / self.model.a_pitch
            u[:, CU_COLLECTIVE] = np.clip(np.mean(pitch + room, axis=1), *self.collective_limits)
            return u
        room = (self.model.limit - self.margin - self.estimated_tips(obs)) / self.model.a_pitch
        allowed = np.min(pitch + room - self.signs * diff[:, None], axis=1)
        u[:, CU_COLLECTIVE] = np.clip(np.minimum(self.lqr.collective, allowed), *self.collective_limits)
        return u

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """SB3's signature: actions in [-1, 1] (clipped: each control saturates at its limits)."""
        obs, single = batch_observations(observation, self.obs_dim)
        a = np.clip((self.controls(obs) - self.lqr.mid) / self.lqr.half, -1.0, 1.0).astype(self.action_dtype)
        return (a[0] if single else a), state
