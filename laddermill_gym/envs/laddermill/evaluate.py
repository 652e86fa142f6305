"""Rewards, terminations and failure texts of the laddermill task (:class:`~laddermill_gym.envs.laddermill.task.
MillTask`), computed from its composed observations and kernel read-outs after a control period."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.laddermill.observation import N_OBS_PER_SLOT, OBS_INDEX
from laddermill_gym.envs.wing_failures import status_texts, wing_failure_text, wing_terms
from laddermill_gym.kernels.contract import B3_POS, B3_SIZE, SX_ENERGY, SX_TRANSFERS
from laddermill_gym.kernels.rigid.observe import AUX_GROUND_END, AUX_GROUND_START, AUX_MAX_TENSION, AUX_MIN_ALTITUDE
from laddermill_gym.model.station import electrical_power
from laddermill_gym.sim.recording import ALPHA_RANGE_DEG, MAX_ABS_BETA_DEG

__all__ = ["evaluate_copies", "failure_codes", "failure_text"]

_STATUS_TEXT = status_texts("speed or rate limit (or the cable moved more than one piece in a step)")
_BAND_LO, _BAND_HI = np.radians(ALPHA_RANGE_DEG)
_BAND_BETA = math.radians(MAX_ABS_BETA_DEG)


def _slots(task) -> np.ndarray:
    """The unclipped per-slot observations (B, n, 15)."""
    return task.raw_obs[:, : N_OBS_PER_SLOT * task.n_wings].reshape(task.n_copies, task.n_wings, N_OBS_PER_SLOT)


def failure_codes(task) -> np.ndarray:
    """Failure code (B,) of each copy at its observed state (0: flying; codes of ``MILL_FAILURES``); where several
    apply, integration breakdown, then ground contact, cable overload, aerodynamic range."""
    return wing_terms(task, _slots(task))[2]


def evaluate_copies(task, a: np.ndarray, n_clipped: np.ndarray):
    """(reward (B,), terminated (B,), truncated (B,), info) after a control period with the clipped normalised
    actions ``a`` (B, n_actions); the terms of :class:`~laddermill_gym.envs.laddermill.settings.MillRewardConfig`.

    info (each (B,)): reward_power, reward_lateral, reward_rates, reward_effort, reward_failure (they sum to the
    reward); power_W (electrical, the reward's P) and mechanical_power_W [W] at the end of the period;
    mean_power_W [W], the electrical power averaged over the period (generator energy / time); cable_speed_m_s;
    tension_difference_N (T_first - T_last) and max_tension_N [N]; min_altitude_m [m]; transfers (this episode);
    t [s]; n_clipped; n_aero_out_of_band (slots outside the wing data's attached-flow band, -14..18 deg alpha,
    |beta| <= 21 deg: a flag, not a termination); failure (code).
    """
    b = task.batch
    o = _slots(task)
    lat, rates, failure = wing_terms(task, o)
    power = np.where(np.isfinite(task.power), task.power, 0.0)
    reward, terminated, truncated, info = task.shaped_reward(power, task.p_ref, lat, rates, np.mean(a ** 2, axis=1),
                                                             failure)
    st = b.assembly.station
    x = b.states
    elapsed = np.maximum(b.done, 1) * b.settings.dt
    alpha, beta = o[:, :, OBS_INDEX["alpha"]], o[:, :, OBS_INDEX["beta"]]
    out_of_band = (alpha < _BAND_LO) | (alpha > _BAND_HI) | (np.abs(beta) > _BAND_BETA)
    info.update(power_W=power, mechanical_power_W=task.mechanical_power.copy(),
                mean_power_W=electrical_power((x[:, task.xoff + SX_ENERGY] - task.energy_start) / elapsed,
                                              st.efficiency),
                cable_speed_m_s=task.cable_speed.copy(),
                tension_difference_N=task.aux[:, AUX_GROUND_START] - task.aux[:, AUX_GROUND_END],
                max_tension_N=task.aux[:, AUX_MAX_TENSION].copy(), min_altitude_m=task.aux[:, AUX_MIN_ALTITUDE].copy(),
                transfers=np.rint(x[:, task.xoff + SX_TRANSFERS]).astype(np.int64), t=b.t.copy(),
                n_clipped=n_clipped, n_aero_out_of_band=np.count_nonzero(out_of_band, axis=1), failure=failure)
    return reward, terminated, truncated, info


def failure_text(task, b: int, code: int) -> str:
    """A sentence on why copy ``b`` terminated with failure ``code`` (time, slot and quantity); "" for code 0."""
    bt, n = task.batch, task.n_wings
    k = int(np.argmax(bt.states[b, : B3_SIZE * n].reshape(n, B3_SIZE)[:, B3_POS + 2]))  # lowest: largest z
    return wing_failure_text(task, b, code, _STATUS_TEXT, _slots(task)[b], "slot", f"slot {k}")
