"""The task of ``laddermill_gym/PumpingKite-v1``, crosswind pumping: v0's pumping kite (``envs/pumping/task.py``,
the same scene, winch, actions, physics and failures) with a flight controller's observation (the wind-window
entries of ``crosswind_observation.py`` after v0's 20) and a reward for crosswind flight: net electrical power
over 10 kW, the rates' and the sideslip's stability penalties and a tether-force penalty instead of v0's
wind-plane (lateral) penalty."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.crosswind_observation import (
    CROSSWIND_OBS_INDEX,
    N_CROSSWIND_OBS,
    crosswind_bounds,
)
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.settings import PumpingRewardConfig
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.pumping.wind_window import rotations_from_euler, wind_window
from laddermill_gym.envs.task_base import clip_observations
from laddermill_gym.kernels.contract import B3_POS, TM_DT, TM_T0
from laddermill_gym.kernels.wind import modulation, wind_point

__all__ = ["CrosswindRewardConfig", "CrosswindTask"]


@dataclass(frozen=True)
class CrosswindRewardConfig(PumpingRewardConfig):
    """v1's reward per control period: r = E_el / (P_ref dt) - w_w S(rates) - w_b S((beta / beta_s)^2)
    - w_T S(max(0, T_max - a F_b) / (c F_b)) - failure_penalty [terminated], S(x) = 1 - exp(-x): E_el and the
    rates' term as v0 (:class:`~laddermill_gym.envs.pumping.settings.PumpingRewardConfig`), beta the sideslip
    [rad], T_max the largest tether tension [N], F_b the tether's breaking load [N].

    Defaults: ``reference_power`` P_ref = 10 kW (the crosswind cycle's order, docs/pumping.md), ``lateral_weight``
    0 (crosswind flight leaves the wind plane by design), ``sideslip_weight`` w_b = 0.1, ``sideslip_scale``
    beta_s = 0.35 rad (20 deg), ``tension_weight`` w_T = 1, ``tension_allowed`` a = 0.4 (the controller's 200 kN
    set-point is 0.38 F_b), ``tension_scale`` c = 0.1, ``failure_penalty`` 2e5 (1e8 J at P_ref dt = 500 J: more
    than the 60 MJ a 600 s episode at 100 kW makes)."""

    lateral_weight: float = 0.0
    reference_power: float = 10000.0
    failure_penalty: float = 2.0e5
    sideslip_weight: float = 0.1
    sideslip_scale: float = 0.35
    tension_weight: float = 1.0
    tension_allowed: float = 0.4
    tension_scale: float = 0.1

    def __post_init__(self):
        super().__post_init__()
        for name in ("sideslip_scale", "tension_allowed", "tension_scale"):
            if not getattr(self, name) > 0:
                raise ValueError(f"reward.{name} = {getattr(self, name)!r}: must be > 0")


class CrosswindTask(PumpingTask):
    """B copies of the crosswind pumping kite (arguments: :class:`~laddermill_gym.envs.pumping.crosswind_env.
    CrosswindKiteEnv`); v0's :class:`~laddermill_gym.envs.pumping.task.PumpingTask` with the observation of
    :data:`~laddermill_gym.envs.pumping.crosswind_observation.CROSSWIND_OBS_FIELDS` appended and v1's reward."""

    reward_class = CrosswindRewardConfig

    def __init__(self, n_copies: int = 1, config: str = "pumping_kite", scene_options: dict | None = None,
                 control_dt: float = 0.05, episode_time: float = 600.0, initial_noise=None, disturbances=None,
                 wind_dt: float = 0.1, reward=None, termination=None, parallel: bool | None = None):
        super().__init__(n_copies, config, scene_options, control_dt, episode_time, initial_noise, disturbances,
                         wind_dt, reward, termination, parallel)
        allowed, breaking = self.reward_config.tension_allowed, self.termination_config.breaking_factor
        if allowed >= breaking:  # a tension that high has ended the episode already: the penalty would never act
            raise ValueError(f"reward.tension_allowed = {allowed:g}: at or above termination.breaking_factor = "
                             f"{breaking:g}, so the tension penalty could never act")
        B = self.n_copies
        self.obs_dim = N_CROSSWIND_OBS
        self.raw_obs = np.zeros((B, N_CROSSWIND_OBS))
        self.obs = np.zeros((B, N_CROSSWIND_OBS))
        cyc = self.pumping.cycle
        reach = (float(self.scene.assembly.elements.l0[0]) + 2.0 * cyc.reel_length) / cyc.reel_length
        self.obs_low, self.obs_high = crosswind_bounds(self.obs_low, self.obs_high, self.scene.settings.max_speed,
                                                       reach)

    def _wind_vector(self, i: int) -> np.ndarray:
        """Wind velocity [m/s] (3,) at copy i's wing CG now (its own air), as v0's ``radial_wind``."""
        b, m = self.batch, self.batch.model
        x, t, a = b.states[i], float(b.t[i]), b.air
        s, d, _, _ = modulation(t, a.tmod[i, TM_T0], a.tmod[i, TM_DT], a.ms[i], a.md[i])
        p = x[B3_POS: B3_POS + 3]
        return np.array(wind_point(p[0], p[1], p[2], t, m.wf, s, d, None if a.gp is None else a.gp[i],
                                   None if a.gv is None else a.gv[i]))

    def _compose(self) -> None:
        """v0's entries, then the wind-window entries from the same (unclipped) wing observation."""
        super()._compose()
        ro, j = self.raw_obs, CROSSWIND_OBS_INDEX
        p = self.nominal + ro[:, 0:3] - self.batch.assembly.fixed_points[0]
        v = ro[:, 3:6]
        rot = rotations_from_euler(ro[:, OBS_INDEX["phi"]], ro[:, OBS_INDEX["theta"]], ro[:, OBS_INDEX["psi"]])
        ww = wind_window(p, v, rot)
        wind = np.array([self._wind_vector(c) for c in range(self.n_copies)])
        ro[:, j["elevation"]], ro[:, j["azimuth"]], ro[:, j["bank"]] = ww.elevation, ww.azimuth, ww.bank
        ro[:, j["course_sin"]], ro[:, j["course_cos"]] = np.sin(ww.course), np.cos(ww.course)
        ro[:, j["tangential_speed"]], ro[:, j["radial_speed"]] = ww.tangential_speed, ww.radial_speed
        ro[:, j["apparent_wind"]] = np.linalg.norm(wind - v, axis=1)
        ro[:, j["cycle_fraction"]] = ro[:, WINCH_OBS_INDEX["paid_out"]] / self.pumping.cycle.reel_length
        clip_observations(ro, self.obs_low, self.obs_high, self.obs)

    def step(self, action: np.ndarray, mask: np.ndarray | None = None):
        """v0's step with v1's reward terms (``reward_sideslip``, ``reward_tension`` in ``info``; the reward terms
        sum to the reward)."""
        reward, terminated, truncated, info = super().step(action, mask)
        rc = self.reward_config
        brk = self.scene.cable.breaking_load
        over = np.maximum(info["max_tension_N"] - rc.tension_allowed * brk, 0.0) / (rc.tension_scale * brk)
        beta = np.nan_to_num(self.raw_obs[:, OBS_INDEX["beta"]], nan=np.inf)
        info["reward_sideslip"] = rc.sideslip_weight * np.expm1(-(beta / rc.sideslip_scale) ** 2)
        info["reward_tension"] = rc.tension_weight * np.expm1(-np.nan_to_num(over, nan=np.inf))
        return reward + info["reward_sideslip"] + info["reward_tension"], terminated, truncated, info
