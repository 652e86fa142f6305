"""A scene at the point-mass fidelity as a Gymnasium environment whose actions command the kites' attitude."""

from __future__ import annotations

import math
from typing import Any

import gymnasium as gym
import numpy as np

from laddermill_gym.envs.task import RewardConfig
from laddermill_gym.kernels.pointmass.layout import PU_PITCH, PU_ROLL, PU_SIZE
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.sim.pointmass import PointMassError

#: Observation entries per kite: position offset from the start (3) [m], velocity (3) [m/s], tension of the
#: element below the kite [N].
OBS_PER_KITE = 7


class PointMassEnv(gym.Env):
    """Point-mass kites of a scene (``fidelity: pointmass``) controlled through their commanded attitude.

    ## Description

    Any scene read at the point-mass fidelity (``ladder.scene.load_scene(scene, fidelity="pointmass")``,
    Podgaets & Ockels 2007): kites are point masses whose attitude is set directly by the actions, on an elastic
    string (laddermill_gym/docs/pointmass.md). The task: pull on the ground point(s) while holding the kites
    near the plane of the wind. The kites have no rotational dynamics: an action is the attitude, at once.

    ## Action Space

    Box [-1, 1]^(2 n_groups) float32; per group of kites (``groups``: "all" one group, "per_kite" one each),
    entry 2g the pitch and 2g + 1 the roll offset from the scene's start attitude, ``a * range``;
    entries outside [-1, 1] are clipped and counted in ``info["n_clipped"]``.

    | Num | Action | Min | Max | Unit |
    |---|---|---|---|---|
    | 2g | pitch offset (alpha offset at rest in a level wind) | -pitch_range_deg | pitch_range_deg | deg |
    | 2g + 1 | roll offset | -roll_range_deg | roll_range_deg | deg |

    ## Observation Space

    Box (7 n_kites,) float32, per kite (kite 0 lowest): offset of its position from the start (x, y, z) [m],
    velocity (x, y, z) [m/s], tension of the cable element below it [N]. Bounds +-(2 x cable length) for
    offsets, +-max_speed for velocities, 0 to 100 x breaking load for tension.

    ## Rewards

    r = w_P P / P_ref - w_y S(x_y) - w_u S(x_u) - failure_penalty [terminated], S(x) = 1 - exp(-x), with the
    fields of :class:`~laddermill_gym.envs.task.RewardConfig`: P = T_ground v_reel (single tether) or
    (T_start - T_end) v_reel (chain between two ground points), v_reel = reel_speed_fraction x v0, P_ref the
    power at the start; x_y = mean over kites of (dy / lateral_scale)^2 (default 5 % of the piece length);
    x_u = mean of a^2. The rate term of the rigid envs is absent (a point mass has no body rates).

    ## Starting State

    The scene's point-mass start (quasi-static for a free upper end, the rigid static equilibrium for a chain
    between two ground points), computed once per env; every reset returns to it.

    ## Episode End

    terminated: the simulator stops (non-finite state, a node faster than ``integrator.max_speed``, a node at the
    ground), a kite below ``min_altitude`` [m], or an element above ``breaking_factor`` x the breaking load.
    truncated: ``episode_time`` [s] reached.

    ## Arguments

    scene, scene_options (keyword overrides of ``load_scene``, e.g. ``element_length`` [m]), control_dt [s]
    (a whole number of the scene's steps), episode_time [s], groups, pitch_range_deg, roll_range_deg,
    reward (RewardConfig), min_altitude [m], breaking_factor [-].

    ## Version History

    Not registered yet (no id); its vector entry point and registration are future work.
    """

    metadata = {"render_modes": []}

    def __init__(self, scene: str = "tethered_wing", scene_options: dict | None = None, control_dt: float = 0.05,
                 episode_time: float = 60.0, groups: str = "all", pitch_range_deg: float = 5.0,
                 roll_range_deg: float = 15.0, reward: RewardConfig | None = None, min_altitude: float = 10.0,
                 breaking_factor: float = 1.0):
        opts = {"element_length": 1.0, **(scene_options or {})}
        self.scene = load_scene(scene, fidelity="pointmass", **opts)
        s = self.scene.string
        n_sub = control_dt / self.scene.dt
        if abs(n_sub - round(n_sub)) > 1e-9 or round(n_sub) < 1:
            raise ValueError(f"control_dt = {control_dt!r}: must be a whole number of scene steps ({self.scene.dt} s)")
        if groups not in ("all", "per_kite"):
            raise ValueError(f"groups = {groups!r}: must be 'all' or 'per_kite'")
        self.n_sub, self.control_dt, self.episode_time = int(round(n_sub)), control_dt, episode_time
        self.groups = groups
        self.ranges = np.radians([pitch_range_deg, roll_range_deg])
        self.rc = reward or RewardConfig()
        self.min_altitude, self.breaking_factor = min_altitude, breaking_factor
        self.x0, self.u0 = self.scene.initial_state()
        self.sim = self.scene.simulator(self.x0, self.u0)
        ng = 1 if groups == "all" else s.n_kites
        self.action_space = gym.spaces.Box(-1.0, 1.0, (2 * ng,), np.float32)
        span = 2.0 * s.element_length * s.n_elements
        hi = np.tile([span] * 3 + [s.max_speed] * 3 + [100.0 * s.cable.breaking_load], s.n_kites)
        lo = np.tile([-span] * 3 + [-s.max_speed] * 3 + [0.0], s.n_kites)
        self.observation_space = gym.spaces.Box(lo.astype(np.float32), hi.astype(np.float32), dtype=np.float32)
        self.v_reel = self.rc.reel_speed_fraction * s.wind.v0
        self.lateral_scale = self.rc.lateral_scale or 0.05 * self.scene.piece_length
        self.p_ref = self._power(self.sim.tensions())
        if not self.p_ref > 0:
            raise ValueError(f"scene {self.scene.name}: the start gives no positive reference power")

    def _power(self, tension: np.ndarray) -> float:
        ends = tension[0] - (tension[-1] if self.scene.string.end is not None else 0.0)
        return float(ends * self.v_reel)

    def commanded_attitude(self, action: np.ndarray) -> np.ndarray:
        """Controls (n_k * 3,) [rad] of a normalised action: the start attitude plus pitch and roll offsets."""
        a = np.clip(np.asarray(action, dtype=np.float64), -1.0, 1.0).reshape(-1, 2) * self.ranges
        u = self.u0.reshape(-1, PU_SIZE).copy()
        u[:, PU_PITCH] += a[:, 0]
        u[:, PU_ROLL] += a[:, 1]
        return u.ravel()

    def _observe(self, tension: np.ndarray) -> np.ndarray:
        s = self.scene.string
        kn = s.kite_nodes
        pos = self.sim.positions[kn] - self.x0.reshape(-1, 6)[kn, :3]
        obs = np.concatenate([pos, self.sim.velocities[kn], tension[kn, None]], axis=1)
        return np.clip(obs.ravel(), self.observation_space.low, self.observation_space.high).astype(np.float32)

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        super().reset(seed=seed)
        self.sim.x[:] = self.x0
        self.sim.u[:] = self.u0
        self.sim.t = 0.0
        return self._observe(self.sim.tensions()), {"time": 0.0}

    def step(self, action):
        act = np.asarray(action, dtype=np.float64)
        n_clipped = int(np.sum(np.abs(act) > 1.0))
        self.sim.u[:] = self.commanded_attitude(act)
        failure = None
        try:
            self.sim.step(self.n_sub)
        except PointMassError as err:
            failure = str(err)
        tension = self.sim.tensions()
        s = self.scene.string
        if failure is None and np.min(-self.sim.positions[s.kite_nodes, 2]) < self.min_altitude:
            failure = "a kite below min_altitude"
        if failure is None and tension.max() > self.breaking_factor * s.cable.breaking_load:
            failure = "cable overload"
        rc = self.rc
        dy = self.sim.positions[s.kite_nodes, 1] - self.x0.reshape(-1, 6)[s.kite_nodes, 1]
        terms = {"reward_power": rc.power_weight * self._power(tension) / self.p_ref,
                 "reward_lateral": -rc.lateral_weight * (1 - math.exp(-np.mean((dy / self.lateral_scale) ** 2))),
                 "reward_effort": -rc.effort_weight * (1 - math.exp(-np.mean(np.clip(act, -1, 1) ** 2)))}
        terminated = failure is not None
        reward = sum(terms.values()) - (rc.failure_penalty if terminated else 0.0)
        truncated = not terminated and self.sim.t >= self.episode_time - 1e-9
        info: dict[str, Any] = {"time": self.sim.t, "n_clipped": n_clipped, "failure": failure, **terms}
        return self._observe(tension), float(reward), terminated, truncated, info
