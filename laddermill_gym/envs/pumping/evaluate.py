"""Rewards, terminations and failure texts of the pumping task (:class:`~laddermill_gym.envs.pumping.task.
PumpingTask`), computed from its composed observations and kernel read-outs after a control period."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.wing_failures import aero_range_text, altitude, shared_failure_text, status_texts
from laddermill_gym.kernels.contract import GROUND, OK, SX_ENERGY
from laddermill_gym.kernels.rigid.observe import AUX_MAX_TENSION, AUX_MIN_ALTITUDE

__all__ = ["evaluate_copies", "failure_codes", "failure_text"]

_STATUS_TEXT = status_texts("speed or rate limit, or the winch reeled in below 5 % of the tether's start length")


def failure_codes(task) -> np.ndarray:
    """Failure code (B,) of each copy at its observed state (0: flying; codes of ``PUMPING_FAILURES``); where several
    apply, integration breakdown, then ground contact, cable overload, aerodynamic range."""
    o = task.raw_obs
    alpha, beta = o[:, OBS_INDEX["alpha"]], o[:, OBS_INDEX["beta"]]
    failure = np.zeros(task.n_copies, dtype=np.int64)
    failure[(alpha < task.alpha_lo) | (alpha > task.alpha_hi) | (np.abs(beta) > task.beta_max)] = 4
    failure[task.aux[:, AUX_MAX_TENSION] > task.breaking_tension] = 3
    failure[task.aux[:, AUX_MIN_ALTITUDE] < task.min_altitude] = 2
    failure[task.batch.status != OK] = 1
    failure[task.batch.status == GROUND] = 2
    return failure


def evaluate_copies(task, a: np.ndarray, n_clipped: np.ndarray):
    """(reward (B,), terminated (B,), truncated (B,), info) after a control period with the clipped normalised
    actions ``a`` (B, 4); the terms of :class:`~laddermill_gym.envs.pumping.settings.PumpingRewardConfig`.

    info (each (B,)): reward_power, reward_lateral, reward_rates, reward_failure (they sum to the reward);
    power_W, the net electrical power of the period [W] (its electrical energy / control_dt); mechanical_power_W
    [W] at the drum over the period; winch_speed_m_s; paid_out_m; drum_tension_N and max_tension_N [N];
    min_altitude_m [m]; t [s]; n_clipped; failure (code).
    """
    rc, b = task.reward_config, task.batch
    o = task.raw_obs
    with np.errstate(invalid="ignore", over="ignore"):
        lat = (o[:, OBS_INDEX["dy"]] / task.lateral_scale) ** 2
        rates = (o[:, OBS_INDEX["p"]] ** 2 + o[:, OBS_INDEX["r"]] ** 2) / rc.rate_scale ** 2
    elapsed = np.maximum(b.done, 1) * b.settings.dt
    power = np.where(np.isfinite(task.electrical_energy), task.electrical_energy / elapsed, 0.0)
    failure = failure_codes(task)
    terminated = failure != 0
    terms = {
        "reward_power": rc.power_weight * power / rc.reference_power,
        "reward_lateral": -rc.lateral_weight * -np.expm1(-np.nan_to_num(lat, nan=np.inf)),
        "reward_rates": -rc.rate_weight * -np.expm1(-np.nan_to_num(rates, nan=np.inf)),
        "reward_failure": -rc.failure_penalty * terminated,
    }
    reward = terms["reward_power"] + terms["reward_lateral"] + terms["reward_rates"] + terms["reward_failure"]
    truncated = (task.steps >= task.n_steps_max) & ~terminated
    x = b.states
    w = WINCH_OBS_INDEX
    info = dict(terms)
    info.update(power_W=power, mechanical_power_W=(x[:, task.xoff + SX_ENERGY] - task.energy_start) / elapsed,
                winch_speed_m_s=o[:, w["winch_speed"]].copy(), paid_out_m=o[:, w["paid_out"]].copy(),
                drum_tension_N=o[:, w["drum_tension"]].copy(), max_tension_N=task.aux[:, AUX_MAX_TENSION].copy(),
                min_altitude_m=task.aux[:, AUX_MIN_ALTITUDE].copy(), t=b.t.copy(), n_clipped=n_clipped,
                failure=failure)
    return reward, terminated, truncated, info


def failure_text(task, b: int, code: int) -> str:
    """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0."""
    text = shared_failure_text(task, b, code, _STATUS_TEXT)
    if text is not None:
        return text
    if code == 2:
        return (f"t = {float(task.batch.t[b]):.2f} s: ground contact, wing CG at {altitude(task, b):.2f} m "
                f"(< {task.min_altitude:.3g} m)")
    return aero_range_text(task, b, task.raw_obs[b: b + 1], None)
