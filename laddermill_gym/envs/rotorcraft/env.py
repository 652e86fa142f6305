"""Roberts' tethered twin-rotor craft as a Gymnasium environment (``laddermill_gym/Rotorcraft-v0``).

The physics is :class:`laddermill_gym.rotorcraft.craft.CraftSimulator` (one rigid body, two Gessow & Myers rotors, fins,
frame drag, three tethers of core cable elements); this module only maps actions to the two controls, reads
observations and rewards from the simulator's views, applies the wind disturbances through the packed
model's wind modulation arrays and decides when an episode ends.
"""

from __future__ import annotations

import dataclasses
import math
from functools import lru_cache
from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.atmosphere.disturbances import DirectionStep, Disturbance, disturbance_from_dict, sample_modulation
from laddermill_gym.envs.observation import ObsField
from laddermill_gym.envs.rotorcraft.render import craft_renderer
from laddermill_gym.envs.rotorcraft.settings import InitialNoise, RotorcraftRewardConfig, RotorcraftTerminationConfig
from laddermill_gym.envs.task import _config
from laddermill_gym.rotorcraft import craft_kernels as _kc
from laddermill_gym.rotorcraft.config import DEFAULT_CRAFT, CraftConfig, load_craft_config
from laddermill_gym.rotorcraft.craft import TETHER_NAMES, Craft, CraftSimulator, load_craft
from laddermill_gym.rotorcraft.rotor_kernels import STATUS_OK
from laddermill_gym.sim.simulator import SimulationError

__all__ = ["RotorcraftEnv", "RotorcraftRewardConfig", "RotorcraftTerminationConfig", "InitialNoise",
           "CRAFT_OBS_FIELDS", "CRAFT_OBS_INDEX", "CRAFT_FAILURES", "OBS_Y", "OBS_PHI", "OBS_VY", "OBS_P",
           "OBS_PSI", "OBS_R", "craft_trim", "trim_action", "open_loop_controller"]

#: Observation entries, in order (a public contract: change it only with the env id's version).
CRAFT_OBS_FIELDS: tuple[ObsField, ...] = (
    ObsField("dx", "m", "CG x (north, upwind) relative to the trim position"),
    ObsField("dy", "m", "CG y (east, lateral) relative to the trim position"),
    ObsField("dz", "m", "CG z (down) relative to the trim position"),
    ObsField("vx", "m/s", "CG velocity, global x"),
    ObsField("vy", "m/s", "CG velocity, global y (lateral)"),
    ObsField("vz", "m/s", "CG velocity, global z (down)"),
    ObsField("phi", "rad", "roll angle (3-2-1 Euler)"),
    ObsField("theta", "rad", "pitch angle (3-2-1 Euler; the trim's is about the craft incidence alpha_c)"),
    ObsField("psi", "rad", "yaw angle (3-2-1 Euler)"),
    ObsField("p", "rad/s", "roll rate, body x"),
    ObsField("q", "rad/s", "pitch rate, body y"),
    ObsField("r", "rad/s", "yaw rate, body z"),
    ObsField("thrust_right", "-", "right rotor thrust over its trim thrust"),
    ObsField("thrust_left", "-", "left rotor thrust over its trim thrust"),
    ObsField("tension_rear_right", "-", "craft-end tension of the rear right tether over its trim tension"),
    ObsField("tension_rear_left", "-", "craft-end tension of the rear left tether over its trim tension"),
    ObsField("tension_front", "-", "craft-end tension of the forward tether over its trim tension"),
    ObsField("pitch_right", "rad", "blade collective pitch of the right rotor, theta0 + dtheta"),
    ObsField("pitch_left", "rad", "blade collective pitch of the left rotor, theta0 - dtheta"),
)
#: Field name -> observation index.
CRAFT_OBS_INDEX: dict[str, int] = {f.name: i for i, f in enumerate(CRAFT_OBS_FIELDS)}
#: Fixed indices of the lateral states (read by the lateral controllers).
OBS_Y, OBS_PHI, OBS_VY, OBS_P, OBS_PSI, OBS_R = (CRAFT_OBS_INDEX[k] for k in ("dy", "phi", "vy", "p", "psi", "r"))
N_CRAFT_OBS = len(CRAFT_OBS_FIELDS)

#: Termination causes (code -> name); 0: still flying.
CRAFT_FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state, speed or rate limit)",
                                  2: "rotor inflow failed", 3: "ground contact", 4: "tether over its breaking load",
                                  5: "attitude out of range"}


# ---------------------------------------------------------------------------------------------- trim
@lru_cache(maxsize=8)
def _craft_config(craft: str) -> CraftConfig:
    try:
        return load_craft_config(craft)
    except ValueError as err:
        raise ValueError(f"craft = {craft!r}: {err}") from None


def _control_ranges(cfg: CraftConfig) -> tuple[np.ndarray, np.ndarray]:
    lim = np.array([cfg.collective_limits, cfg.differential_limits])
    return 0.5 * (lim[:, 0] + lim[:, 1]), 0.5 * (lim[:, 1] - lim[:, 0])


def _trim_controls(cfg: CraftConfig, collective: float | None) -> np.ndarray:
    th = cfg.initial_collective if collective is None else collective
    lo, hi = cfg.collective_limits
    if not (isinstance(th, (int, float)) and math.isfinite(th) and lo <= th <= hi):
        raise ValueError(f"collective = {th!r} rad: must lie in the craft's collective_limits [{lo:.4g}, {hi:.4g}] rad")
    return np.array([float(th), 0.0])


@lru_cache(maxsize=16)
def craft_trim(craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
               physics_dt: float | None = None) -> tuple[Craft, np.ndarray, np.ndarray]:
    """(craft, x_trim (n_state,), u_trim (2,) [rad]) for a craft name or path, wind speed v0 [m/s] (None: the
    config's), trim collective [rad] (None: the config's) and physics step [s] (None: the config's).

    Cached on the arguments (a trim takes about 0.5 s); the returned arrays are read-only."""
    cfg = _craft_config(craft)
    u = _trim_controls(cfg, collective)
    if wind_speed is not None:
        cfg = cfg.with_wind_speed(wind_speed)
    if physics_dt is not None:
        cfg = cfg.replace(settings=dataclasses.replace(cfg.settings, dt=float(physics_dt)))
    c = load_craft(config=cfg)
    try:
        x = c.trim(u[0])
    except RuntimeError as err:
        raise ValueError(f"wind_speed = {wind_speed!r} m/s, collective = {collective!r} rad: {err}") from None
    x.setflags(write=False)
    u.setflags(write=False)
    return c, x, u


def trim_action(craft: str = DEFAULT_CRAFT, collective: float | None = None) -> np.ndarray:
    """The normalised action (2,) float32 that holds the trim controls (collective, zero differential).

    Needs only the config (no trim): the trim controls do not depend on the wind."""
    cfg = _craft_config(str(craft))
    mid, half = _control_ranges(cfg)
    return ((_trim_controls(cfg, collective) - mid) / half).astype(np.float32)


def open_loop_controller(env_kwargs: dict | None = None):
    """An :class:`~laddermill_gym.control.open_loop.OpenLoopController` holding the trim controls of the
    environment with arguments ``env_kwargs`` (only ``craft`` and ``collective`` matter: the open-loop action
    does not depend on the wind or the timing)."""
    from laddermill_gym.control.open_loop import OpenLoopController

    kw = dict(env_kwargs or {})
    cfg = _craft_config(str(kw.get("craft", DEFAULT_CRAFT)))
    mid, half = _control_ranges(cfg)
    ctrl = OpenLoopController(_trim_controls(cfg, kw.get("collective")), mid, half)
    ctrl.obs_dim = N_CRAFT_OBS  # its default assumes the wing layout (15 entries per 3 actions)
    return ctrl


def _positive(name: str, v, unit: str) -> float:
    if not (isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {v!r}: must be a finite number > 0 {unit}")
    return float(v)


def _inflow_failed(sim: CraftSimulator) -> bool:
    """Whether the last right-hand side evaluation met a rotor whose Glauert inflow did not converge."""
    out = sim.work.vout
    return any(out[6 + _kc.N_RO * r + _kc.R_STATUS] != STATUS_OK for r in range(2))


# ---------------------------------------------------------------------------------------------- the env
def _obs_table() -> str:
    return "\n".join(f"    | {i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(CRAFT_OBS_FIELDS))


class RotorcraftEnv(gym.Env):
    """Roberts' tethered twin-rotor craft held by differential collective pitch.

    ## Description

    Roberts' flying model (configs/rotorcraft/roberts_flying_model.yaml): two contra-rotating rotors side by
    side in a frame with vertical fins, on three tethers (two rear, one forward), generating electricity while
    its rotors carry it (Roberts, "Tethered rotorcraft as a means of electricity generation at high altitude",
    sec. 2, 3 and 7). Below a critical wind speed the craft has a coupled roll / lateral translation
    instability (Roberts sec. 7): at the default 10 m/s an oscillatory roll / lateral / yaw mode (period of
    some 15 s) grows until the craft crashes with its trim controls held; in stronger wind it is stable
    (growth rate and period: the unstable eigenvalue of the linearisation at the trim, which
    tests/test_rotorcraft_env.py checks against the open-loop rollout). Roberts stabilises it with the
    differential collective pitch. The task: produce power while holding the craft
    laterally still in changing wind. Simulated by :class:`laddermill_gym.rotorcraft.craft.CraftSimulator` (numba
    kernels); the default disturbance is a 0.01 rad step of the wind direction at t = 1 s.

    ## Action Space

    Box [-1, 1]^2 float32; entry ``a`` maps linearly onto ``mid + a * half_range`` of the config's limits.
    Entries outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

    | Num | Action | Min | Max | Unit |
    |---|---|---|---|---|
    | 0 | collective pitch theta0 (both rotors) | -5 | 15 | deg |
    | 1 | differential collective dtheta (right theta0 + dtheta, left theta0 - dtheta) | -5 | 5 | deg |

    (limits of the default craft; the environment reads them from the config. The trim action, collective
    4 deg and no differential, is ``env.trim_action`` or :func:`trim_action`.)

    ## Observation Space

    Box (19,) float32; indices of the lateral states are exported as ``OBS_Y``, ``OBS_PHI``, ``OBS_VY``,
    ``OBS_P``, ``OBS_PSI``, ``OBS_R``:

    | Num | Observation | Unit | Meaning |
    |---|---|---|---|
OBS_TABLE

    Bounds: +-(2 x longest tether + 100 m) for offsets, the integrator's speed / rate limits for velocities and
    rates, natural ranges for angles, +-100 for thrust ratios, 0 to 100 x breaking load / trim tension for
    tension ratios, the reachable blade pitches. Values are clipped to the bounds (a failed step's
    non-finite entries become the bound).

    ## Rewards

    r = P / P_ref - w_y S((dy / y_s)^2) - w_w S((p^2 + r^2) / w_s^2) - w_u S(mean (a - a_trim)^2)
    - failure_penalty [terminated], S(x) = 1 - exp(-x); P the net electrical power, P_ref its trim value
    (:class:`RotorcraftRewardConfig`). Every term is in ``info`` (``reward_power``, ``reward_lateral``,
    ``reward_rates``, ``reward_effort``, ``reward_failure``), and they sum to the reward.

    ## Starting State

    The static equilibrium (trim) of the craft in the steady wind at the trim collective and no differential,
    computed once per (craft, wind speed, collective, physics step) and cached. ``initial_noise`` adds random
    lateral velocity and roll / yaw rates; the wind disturbances are drawn from ``np_random`` at every reset.

    ## Episode End

    ``terminated`` on a physical failure (``info["failure"]`` code, ``info["failure_name"]``,
    ``info["failure_reason"]`` with the time and the quantity): integration breakdown (non-finite state, speed
    or rate limit), a rotor's inflow not converging, the CG below ``termination.min_altitude``, a tether element
    over ``breaking_factor`` x its breaking load, or the attitude outside the termination ranges (roll beyond
    60 deg by default). ``truncated`` only when ``episode_time`` is reached.

    ## Arguments

    * ``craft``: craft name in configs/rotorcraft/ or a YAML path (default ``roberts_flying_model``);
    * ``wind_speed`` [m/s]: wind speed v0 at h0 (default: the config's, 10 m/s);
    * ``collective`` [rad]: trim collective (default: the config's, 4 deg);
    * ``control_dt`` [s]: control period, a whole multiple of the physics step (default 0.05);
    * ``physics_dt`` [s]: RK4 step (default: the config's, 2 ms);
    * ``episode_time`` [s]: episode length (default 120);
    * ``disturbances``: :class:`~laddermill_gym.atmosphere.disturbances.Disturbance` objects or their config dicts
      (``{"type": "DirectionStep", "step": [-0.05, 0.05]}``; ranges are drawn per episode); default the 0.01 rad
      direction step at 1 s;
    * ``wind_dt`` [s]: spacing of the sampled wind modulation (default 0.1);
    * ``initial_noise``: dict or :class:`InitialNoise` (random start velocities);
    * ``reward``, ``termination``: dicts or :class:`RotorcraftRewardConfig` / :class:`RotorcraftTerminationConfig`;
    * ``render_mode``: "rgb_array" or "human".

    ## Version History

    * v0: initial version.
    """

    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 20}

    def __init__(self, craft: str = DEFAULT_CRAFT, wind_speed: float | None = None, collective: float | None = None,
                 control_dt: float = 0.05, physics_dt: float | None = None, episode_time: float = 120.0,
                 disturbances=None, wind_dt: float = 0.1, initial_noise=None, reward=None, termination=None,
                 render_mode: str | None = None):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode = {render_mode!r}: must be one of {self.metadata['render_modes']} or None")
        self._kwargs = dict(craft=craft, wind_speed=wind_speed, collective=collective, control_dt=control_dt,
                            physics_dt=physics_dt, episode_time=episode_time, disturbances=disturbances,
                            wind_dt=wind_dt, initial_noise=initial_noise, reward=reward, termination=termination)
        self.control_dt = _positive("control_dt", control_dt, "s")
        self.episode_time = _positive("episode_time", episode_time, "s")
        self.wind_dt = _positive("wind_dt", wind_dt, "s")
        if wind_speed is not None:
            wind_speed = _positive("wind_speed", wind_speed, "m/s")
        if physics_dt is not None:
            physics_dt = _positive("physics_dt", physics_dt, "s")
        self.disturbances = self._disturbances(disturbances)
        self.reward_config = _config(reward, RotorcraftRewardConfig, "reward")
        self.termination_config = _config(termination, RotorcraftTerminationConfig, "termination")
        self.initial_noise = _config(initial_noise, InitialNoise, "initial_noise")
        self.craft, self.x_trim, self.u_trim = craft_trim(str(craft), wind_speed, collective, physics_dt)
        cfg = self.craft.config
        dt = cfg.settings.dt
        self.n_substeps = int(round(self.control_dt / dt))
        if self.n_substeps < 1 or abs(self.n_substeps * dt - self.control_dt) > 1e-9 * self.control_dt:
            raise ValueError(f"control_dt = {control_dt!r} s is not a whole multiple of the physics step {dt!r} s")
        self.n_steps_max = int(round(self.episode_time / self.control_dt))
        self.sim = CraftSimulator(cfg, self.craft.assembly, self.craft.layout, self.x_trim, self.u_trim)
        self._n_mod = int(math.ceil(self.episode_time / self.wind_dt - 1e-9)) + 1
        self._mid, self._half = _control_ranges(cfg)
        self.trim_action = ((self.u_trim - self._mid) / self._half).astype(np.float32)
        # trim read-outs: the references of the observation ratios and the power term
        ro = self.sim.rotor_outputs()
        self.nominal_position = self.sim.wing_positions()[0]
        self._rotation_trim = self.sim.wing_rotations()[0]
        self.thrust_trim = ro["thrust_N"]
        self.tension_trim = self.sim.tether_tensions()
        self.p_ref = self.sim.electrical_power()
        if not (self.p_ref > 0 and np.all(self.thrust_trim > 0) and np.all(self.tension_trim > 0)):
            raise ValueError(f"craft {cfg.name} at wind_speed = {cfg.wind.v0!r} m/s: the trim gives no positive power "
                             f"({self.p_ref:.4g} W), thrust {self.thrust_trim} N or tensions {self.tension_trim} N")
        rc, tc = self.reward_config, self.termination_config
        self.lateral_scale = rc.lateral_scale if rc.lateral_scale is not None else 0.05 * cfg.tethers.length
        span = cfg.hub_spacing + 2.0 * cfg.rotor_radius
        self.min_altitude = tc.min_altitude if tc.min_altitude is not None else 0.5 * span
        self.breaking_tension = tc.breaking_factor * cfg.tethers.cable.breaking_load
        self.observation_space = gym.spaces.Box(*self._bounds(), dtype=np.float32)
        self.action_space = gym.spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        self.render_mode = render_mode
        self.metadata = dict(self.metadata, render_fps=int(round(1.0 / self.control_dt)))
        self.steps = 0
        self._obs = np.zeros(N_CRAFT_OBS)
        self._renderer = None
        self._needs_reset = True

    # ------------------------------------------------------------------ construction helpers
    @staticmethod
    def _disturbances(disturbances) -> tuple[Disturbance, ...]:
        if disturbances is None:
            return (DirectionStep(),)
        out = []
        for i, d in enumerate(disturbances):
            if isinstance(d, dict):
                d = disturbance_from_dict(d, f"disturbances[{i}]")
            if not isinstance(d, Disturbance):
                raise ValueError(f"disturbances[{i}] = {d!r}: not a Disturbance or its config dict")
            out.append(d)
        return tuple(out)

    def _bounds(self) -> tuple[np.ndarray, np.ndarray]:
        cfg = self.craft.config
        reach = 2.0 * float(np.max(self.craft.layout.lengths)) + 100.0
        vmax, wmax = cfg.settings.max_speed, cfg.settings.max_rate
        tmax = 100.0 * cfg.tethers.cable.breaking_load / float(np.min(self.tension_trim))
        hp = 0.5 * math.pi
        pmin = cfg.collective_limits[0] - cfg.differential_limits[1]
        pmax = cfg.collective_limits[1] + cfg.differential_limits[1]
        high = [reach] * 3 + [vmax] * 3 + [math.pi, hp, math.pi] + [wmax] * 3 + [100.0] * 2 + [tmax] * 3 + [pmax] * 2
        low = [-h for h in high[:14]] + [0.0] * 3 + [pmin] * 2
        return np.array(low, dtype=np.float32), np.array(high, dtype=np.float32)

    # ------------------------------------------------------------------ pickling
    def __getstate__(self):
        m = self.sim.model
        return {"kwargs": self._kwargs, "render_mode": self.render_mode, "np_random": self._np_random,
                "sim": (self.sim.state.copy(), self.sim.t, self.sim.controls.copy()),
                "wind": (m.tmod.copy(), m.ms.copy(), m.md.copy()), "steps": self.steps, "obs": self._obs.copy(),
                "needs_reset": self._needs_reset}

    def __setstate__(self, state):
        self.__init__(render_mode=state["render_mode"], **state["kwargs"])
        self._np_random = state["np_random"]
        x, t, u = state["sim"]
        tmod, ms, md = state["wind"]
        self.sim.model = self.sim.model._replace(tmod=tmod, ms=ms, md=md)
        self.sim.reset(state=x, t=t, controls=u)
        self.steps, self._obs, self._needs_reset = state["steps"], state["obs"], state["needs_reset"]

    # ------------------------------------------------------------------ observation and evaluation
    def _observe(self) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        """The observation (N_CRAFT_OBS,) float64 at the simulator's state (non-finite entries kept) and the
        rotor read-outs."""
        sim = self.sim
        ro = sim.rotor_outputs()
        pos = sim.wing_positions()[0]
        R = sim.wing_rotations()[0]
        obs = np.concatenate([pos - self.nominal_position, R @ sim.wing_velocities()[0], sim.wing_euler()[0],
                              sim.wing_rates()[0], ro["thrust_N"] / self.thrust_trim,
                              sim.tether_tensions() / self.tension_trim, ro["pitch_rad"]])
        return obs, ro

    def _clipped_obs(self) -> np.ndarray:
        lo, hi = self.observation_space.low, self.observation_space.high
        obs = np.where(np.isfinite(self._obs), self._obs, np.where(self._obs < 0, lo, hi))
        return np.clip(obs, lo, hi).astype(np.float32)

    def _failure(self, integration_error: str | None, inflow_failed: bool) -> tuple[int, str]:
        """(failure code, sentence) at the current state; code 0 while flying."""
        t = self.sim.t
        if integration_error is not None:
            if inflow_failed:
                return 2, f"t = {t:.2f} s: a rotor's Glauert inflow did not converge ({integration_error})"
            return 1, f"t = {t:.2f} s: {integration_error}"
        o = self._obs
        if not np.all(np.isfinite(o[CRAFT_OBS_INDEX["thrust_right"]:CRAFT_OBS_INDEX["thrust_left"] + 1])):
            return 2, f"t = {t:.2f} s: a rotor's Glauert inflow did not converge"
        altitude = -self.sim.wing_positions()[0, 2]
        if altitude < self.min_altitude:
            return 3, f"t = {t:.2f} s: ground contact, CG at {altitude:.2f} m altitude (< {self.min_altitude:.3g} m)"
        ten = self.sim.tensions()
        if ten.max() > self.breaking_tension:
            e = int(np.argmax(ten))
            which = next(TETHER_NAMES[i] for i, els in enumerate(self.craft.layout.tether_elements) if e in els)
            return 4, f"t = {t:.2f} s: {which} tether tension {ten[e]:.4g} N over {self.breaking_tension:.4g} N"
        tc = self.termination_config
        phi, theta, psi = np.degrees(o[CRAFT_OBS_INDEX["phi"]:CRAFT_OBS_INDEX["psi"] + 1])
        if (abs(phi) > tc.max_abs_roll_deg or not tc.pitch_range_deg[0] <= theta <= tc.pitch_range_deg[1]
                or abs(psi) > tc.max_abs_yaw_deg):
            return 5, (f"t = {t:.2f} s: attitude roll {phi:.1f}, pitch {theta:.1f}, yaw {psi:.1f} deg outside "
                       f"|roll| <= {tc.max_abs_roll_deg:g}, pitch in {list(tc.pitch_range_deg)}, "
                       f"|yaw| <= {tc.max_abs_yaw_deg:g} deg")
        return 0, ""

    def _reward_terms(self, a: np.ndarray, power: float, terminated: bool) -> dict[str, float]:
        rc = self.reward_config
        o = np.nan_to_num(self._obs)
        lat = (o[OBS_Y] / self.lateral_scale) ** 2
        rates = (o[OBS_P] ** 2 + o[OBS_R] ** 2) / rc.rate_scale ** 2
        effort = float(np.mean((a - self.trim_action) ** 2))
        return {"reward_power": rc.power_weight * power / self.p_ref,
                "reward_lateral": -rc.lateral_weight * -math.expm1(-lat),
                "reward_rates": -rc.rate_weight * -math.expm1(-rates),
                "reward_effort": -rc.effort_weight * -math.expm1(-effort),
                "reward_failure": -rc.failure_penalty * float(terminated)}

    # ------------------------------------------------------------------ Gymnasium API
    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        super().reset(seed=seed)
        rng = self.np_random
        speed, direction = sample_modulation(self.disturbances, self.episode_time, self.wind_dt, rng)
        self.sim.model = self.sim.model._replace(tmod=np.array([0.0, self.wind_dt]), ms=speed, md=direction)
        x = np.array(self.x_trim)
        n = self.initial_noise
        if n.lateral_velocity > 0 or n.roll_rate > 0 or n.yaw_rate > 0:
            dvy, dp, dr = rng.normal(size=3) * np.array([n.lateral_velocity, n.roll_rate, n.yaw_rate])
            x[7:10] += self._rotation_trim.T @ np.array([0.0, dvy, 0.0])  # body velocity of a global vy
            x[10] += dp
            x[12] += dr
        self.sim.reset(state=x, t=0.0, controls=self.u_trim)
        self.steps = 0
        self._obs = self._observe()[0]
        self._needs_reset = False
        if self.render_mode == "human":
            self.render()
        return self._clipped_obs(), {"t": 0.0, "reference_power_W": self.p_ref}

    def step(self, action):
        if self._needs_reset:
            raise RuntimeError("step() called before reset() or after the episode ended; call reset()")
        a = np.asarray(action, dtype=float).reshape(-1)
        if a.shape != (2,):
            raise ValueError(f"action: expected shape (2,), got {np.shape(action)}")
        if not np.all(np.isfinite(a)):
            raise ValueError(f"action = {a.tolist()}: entries must be finite")
        n_clipped = int(np.count_nonzero(np.abs(a) > 1.0))
        a = np.clip(a, -1.0, 1.0)
        error, inflow_failed = None, False
        try:
            self.sim.step(self._mid + a * self._half, n_steps=self.n_substeps)
        except SimulationError as err:
            inflow_failed = _inflow_failed(self.sim)  # read before any other evaluation overwrites it
            error = str(err)
        self.steps += 1
        self._obs, ro = self._observe()
        code, reason = self._failure(error, inflow_failed)
        terminated = code != 0
        truncated = self.steps >= self.n_steps_max and not terminated
        power = self.sim.electrical_power()
        power = power if math.isfinite(power) else 0.0
        terms = self._reward_terms(a, power, terminated)
        reward = float(sum(terms.values()))
        info = dict(terms, t=self.sim.t, power_W=power, thrust_N=ro["thrust_N"],
                    tether_tension_N=self.sim.tether_tensions(), altitude_m=float(-self.sim.wing_positions()[0, 2]),
                    max_tip_incidence_rad=float(np.max(ro["tip_incidence_rad"])), n_clipped=n_clipped,
                    failure=code, failure_name=CRAFT_FAILURES[code], failure_reason=reason)
        if terminated or truncated:
            self._needs_reset = True
        if self.render_mode == "human":
            self.render()
        return self._clipped_obs(), reward, terminated, truncated, info

    def render(self):
        if self.render_mode is None:
            gym.logger.warn("render() called without a render_mode; pass render_mode='rgb_array' or 'human'")
            return None
        if self._renderer is None:
            self._renderer = craft_renderer(self, interactive=self.render_mode == "human")
        frame = self._renderer.draw(0)
        return frame if self.render_mode == "rgb_array" else None

    def close(self):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None


RotorcraftEnv.__doc__ = RotorcraftEnv.__doc__.replace("OBS_TABLE", _obs_table())
