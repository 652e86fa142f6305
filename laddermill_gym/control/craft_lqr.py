"""LQR for Roberts' tethered twin-rotor craft on his eq. (6): differential collective from (y, phi, y', phi').

The design (:func:`design_craft_lqr`) trims the craft in the config's wind, derives eq. (6) there
(:mod:`laddermill_gym.rotorcraft.roll_lateral`), weights it by Bryson's rule from ``configs/agents/lqr_rotorcraft.yaml``
and solves the discrete LQR at the control period (python-control ``c2d`` + ``dlqr``). :class:`CraftLQRController`
applies the gain to environment observations with SB3's ``predict`` signature; the collective stays at the trim.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from laddermill_gym.control.base import batch_observations
from laddermill_gym.control.lqr import DiscreteLQR, bryson_weights, discrete_lqr
from laddermill_gym.control.lqr_config import CONTROL_PERIOD_BOUND, MAX_INPUT_BOUND, MAX_STATE_BOUNDS
from laddermill_gym.kernels.contract import CU_COLLECTIVE, CU_DIFFERENTIAL, CU_SIZE
from laddermill_gym.ladder.bounds import BOUNDS
from laddermill_gym.model.configio import CONFIG_DIR, config_path, find_config, read_yaml, shipped_names
from laddermill_gym.rotorcraft.roll_lateral import RollLateralModel, derive_roll_lateral, lateral_state

DEFAULT_CRAFT_LQR = CONFIG_DIR / "agents" / "lqr_rotorcraft.yaml"

_MAX_STATE_KEYS = (("y", 1.0), ("phi_deg", math.pi / 180), ("vy", 1.0), ("p_deg_s", math.pi / 180))


@dataclass(frozen=True)
class CraftLQRConfig:
    """An eq. (6) LQR design: craft name, design wind v0 [m/s], control period [s], Bryson limits of
    (y [m], phi [rad], y' [m/s], p [rad/s]) and of the differential collective [rad]."""

    file: Path
    craft: str
    wind_speed: float
    control_period: float
    max_state: np.ndarray
    max_input: float


def load_craft_lqr_config(path: str | Path = DEFAULT_CRAFT_LQR) -> CraftLQRConfig:
    """Read a craft LQR YAML (``path``: a file or the bare name of a shipped one, ``lqr_rotorcraft``) strictly:
    unknown keys, a missing craft file, and non-positive or out-of-range values raise ConfigError naming the field
    (the bounds and reasons of :func:`~laddermill_gym.control.lqr_config.load_lqr_config`; the wind's of a scene)."""
    path = find_config("agents", path, "config")
    s = read_yaml(path)
    craft = s.text("craft")
    if not config_path("rotorcraft", craft).is_file():
        raise s.error("craft", craft, "no such craft file (a bare name is one of the shipped crafts: "
                                      f"{', '.join(shipped_names('rotorcraft'))})")
    v = s.number("wind_speed", positive=True, **BOUNDS["wind.v0"])
    period = s.number("control_period", positive=True, **CONTROL_PERIOD_BOUND)
    ms = s.section("max_state")
    max_state = np.array([ms.number(k, positive=True, high=MAX_STATE_BOUNDS[k][0], why=MAX_STATE_BOUNDS[k][1])
                          * scale for k, scale in _MAX_STATE_KEYS])
    ms.done()
    mi = s.section("max_input_deg")
    max_input = math.radians(mi.number("differential", positive=True, **MAX_INPUT_BOUND))
    mi.done()
    s.done()
    return CraftLQRConfig(Path(path), craft, v, period, max_state, max_input)


@dataclass(frozen=True)
class CraftLQRDesign:
    """The design: eq. (6) at the trim, the discrete LQR on it, the trim (x, u) and its simulator;
    ``full_closed_loop``: the discrete closed-loop eigenvalues of the gain on the whole craft's linear model (every
    state of the simulator, tether nodes included, :func:`full_craft_check`), ``trim_residual`` max |dz/dt| of
    that model's linearisation at the trim (0 at an exact trim)."""

    config: CraftLQRConfig
    model: RollLateralModel
    lqr: DiscreteLQR
    x_trim: np.ndarray
    u_trim: np.ndarray
    sim: Any
    full_closed_loop: np.ndarray
    trim_residual: float

    @property
    def gain(self) -> np.ndarray:
        """K (4,): dtheta = -K (y, phi, y', p) [rad per m, rad, m/s, rad/s]."""
        return self.lqr.K[0].copy()

    def state_controls(self, x: np.ndarray) -> np.ndarray:
        """Controls (collective at the trim, differential dtheta = -K z clipped to the craft's limits) [rad],
        shape (2,), from the full simulator state x, z = :func:`lateral_state` (x, trim)."""
        lo, hi = self.sim.config.differential_limits
        d = float(np.clip(-self.gain @ lateral_state(x, self.x_trim), lo, hi))
        u = np.empty(CU_SIZE)
        u[CU_COLLECTIVE], u[CU_DIFFERENTIAL] = self.u_trim[CU_COLLECTIVE], d
        return u


def design_craft_lqr(config: CraftLQRConfig | str | Path = DEFAULT_CRAFT_LQR, craft=None) -> CraftLQRDesign:
    """Trim the craft at the config's wind, derive eq. (6) and solve the discrete LQR.

    ``craft``: a :class:`~laddermill_gym.rotorcraft.craft.Craft` to use instead of loading ``config.craft``
    (its wind speed is replaced by the config's)."""
    from laddermill_gym.rotorcraft.craft import load_craft

    cfg = config if isinstance(config, CraftLQRConfig) else load_craft_lqr_config(config)
    base = load_craft(cfg.craft) if craft is None else craft
    c = load_craft(config=base.config.with_wind_speed(cfg.wind_speed))
    sim = c.simulator()
    model = derive_roll_lateral(sim)
    A, B = model.state_space()
    Q, R = bryson_weights(cfg.max_state, np.array([cfg.max_input]))
    lqr = discrete_lqr(A, B, Q, R, cfg.control_period)
    full, residual = full_craft_check(sim, lqr.K[0], cfg.control_period)
    return CraftLQRDesign(cfg, model, lqr, sim.state.copy(), sim.controls.copy(), sim, full, residual)


def full_craft_check(sim, gain: np.ndarray, dt: float, h: float = 1e-6) -> tuple[np.ndarray, float]:
    """(discrete closed-loop eigenvalues, trim residual [state units/s]) of eq. (6)'s ``gain`` (4,) on the whole
    craft's linear model at the simulator's state and controls (its trim): every minimal coordinate linearised
    (:func:`~laddermill_gym.control.linearize.linearize`), the gain applied to eq. (6)'s state as a linear map of them
    (central differences of :func:`lateral_state`, step ``h``), ZOH at ``dt`` [s]. Eq. (6) leaves out the tether's
    nodes and couplings, so its own closed loop does not show this one's stability (``make_controller`` warns
    where this one's max |z| is 1 or more: a tighter roll weight than the shipped config's can do that)."""
    import control

    from laddermill_gym.control.linearize import full_from_minimal, linearize, minimal_from_full

    x0, asm = sim.state.copy(), sim.assembly
    lin = linearize(sim, x0, sim.controls.copy())
    z0, tail = minimal_from_full(asm, x0), x0[asm.body_state_size:]
    n = lin.A.shape[0]
    L = np.zeros((4, n))  # d (y, phi, y', p) / d (minimal coordinates, then the rest of the state)
    for j in range(n):
        zp, zm, tp, tm = z0.copy(), z0.copy(), tail.copy(), tail.copy()
        if j < z0.size:
            zp[j], zm[j] = z0[j] + h, z0[j] - h
        else:
            tp[j - z0.size], tm[j - z0.size] = tail[j - z0.size] + h, tail[j - z0.size] - h
        L[:, j] = (lateral_state(full_from_minimal(asm, zp, tp), x0)
                   - lateral_state(full_from_minimal(asm, zm, tm), x0)) / (2.0 * h)
    K = np.zeros((lin.B.shape[1], n))
    K[CU_DIFFERENTIAL] = np.asarray(gain, float) @ L
    sysd = control.c2d(control.ss(lin.A, lin.B, np.eye(n), np.zeros(lin.B.shape)), dt, "zoh")
    return np.linalg.eigvals(np.asarray(sysd.A) - np.asarray(sysd.B) @ K), float(lin.residual)


class CraftLQRController:
    """Differential collective dtheta = -K (y, phi, y', p) from Rotorcraft-v0 observations; collective at trim.

    Parameters
    ----------
    gain : ndarray (4,)             LQR gain on (y [m], phi [rad], y' [m/s], p [rad/s])
    obs_index : sequence of 4 int   where the env's observation holds y, phi, y', p (in those units)
    obs_dim : int                   length of the env's observation
    collective : float              trim collective [rad]
    mid, half_range : ndarray (2,)  the env's action map: control = mid + action * half_range [rad]
    """

    def __init__(self, gain, obs_index, obs_dim: int, collective: float, mid, half_range, action_dtype=np.float32):
        self.gain = np.asarray(gain, float).reshape(4)
        self.obs_index = np.asarray(obs_index, dtype=np.int64).reshape(4)
        self.obs_dim = int(obs_dim)
        self.collective = float(collective)
        self.mid = np.asarray(mid, float).reshape(2)
        self.half = np.asarray(half_range, float).reshape(2)
        self.action_dtype = action_dtype

    def controls(self, observation: np.ndarray) -> np.ndarray:
        """Controls (collective, differential) [rad], shape (n, 2), for observations of shape (n, obs_dim)."""
        z = observation[:, self.obs_index]
        u = np.empty((observation.shape[0], CU_SIZE))
        u[:, CU_COLLECTIVE] = self.collective
        u[:, CU_DIFFERENTIAL] = -z @ self.gain
        return u

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """SB3's signature: actions in [-1, 1] (clipped: the differential saturates at its limits)."""
        obs, single = batch_observations(observation, self.obs_dim)
        a = np.clip((self.controls(obs.astype(float)) - self.mid) / self.half, -1.0, 1.0).astype(self.action_dtype)
        return (a[0] if single else a), state
