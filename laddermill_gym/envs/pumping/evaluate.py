"""Rewards, terminations and failure texts of the pumping task (:class:`~laddermill_gym.envs.pumping.task.
PumpingTask`), computed from its composed observations and kernel read-outs after a control period."""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.winch_scene import unchecked_step, winch_limit_text
from laddermill_gym.envs.wing_failures import status_texts, wing_failure_text, wing_terms
from laddermill_gym.kernels.contract import LIMIT, SX_ENERGY
from laddermill_gym.kernels.rigid.observe import AUX_MAX_TENSION, AUX_MIN_ALTITUDE
from laddermill_gym.model.reel import ground_contacts, is_reel, nodes_in_air
from laddermill_gym.sim.batch import SUBSTEP_DIVISORS
from laddermill_gym.sim.reports import state_problems, trial_state
from laddermill_gym.sim.simulator import SimulationError

__all__ = ["evaluate_copies", "failure_codes", "failure_text", "limit_text"]

_LIMITS = "speed or rate limit, or the winch reeled in below 5 % of the tether's start length"
#: the failure code of the winch's reel-in end stop (``settings.PUMPING_FAILURES``)
REELED_IN = 5
_STATUS_TEXT = status_texts(_LIMITS)


def failure_codes(task) -> np.ndarray:
    """Failure code (B,) of each copy at its observed state (0: flying; codes of ``PUMPING_FAILURES``); where several
    apply, integration breakdown, then ground contact, cable overload, aerodynamic range; the winch's reel-in end
    stop is 5, not a breakdown."""
    return _with_reel_in(task, wing_terms(task, task.raw_obs[:, None, :])[2])


def _with_reel_in(task, failure: np.ndarray) -> np.ndarray:
    """``failure`` with code 5 where the integrator's LIMIT was the winch's reel-in end stop (a physical end)."""
    for i in np.flatnonzero((failure == 1) & (task.batch.status == LIMIT)):
        _, culprits, winch = _limit_step(task, int(i))
        if winch is not None and not culprits:
            failure[i] = REELED_IN
    return failure


def evaluate_copies(task, a: np.ndarray, n_clipped: np.ndarray):
    """(reward (B,), terminated (B,), truncated (B,), info) after a control period with the clipped normalised
    actions ``a`` (B, 4); the terms of :class:`~laddermill_gym.envs.pumping.settings.PumpingRewardConfig`.

    info (each (B,)): reward_power, reward_lateral, reward_rates, reward_failure (they sum to the reward);
    power_W, the net electrical power of the period [W] (its electrical energy / control_dt); mechanical_power_W
    [W] at the drum over the period; winch_speed_m_s; paid_out_m; drum_tension_N and max_tension_N [N];
    min_altitude_m [m]; t [s]; n_clipped; failure (code); on a reeling tether (``kernels/reel.py``) also
    tether_elements (in the air) and tether_ground_contacts (nodes on the ground).
    """
    b = task.batch
    o = task.raw_obs
    lat, rates, failure = wing_terms(task, o[:, None, :])
    failure = _with_reel_in(task, failure)  # the reel-in end stop: a physical end
    # per control period, as the reward is documented, also in a period a failure cut short (the energy of its
    # steps done; dividing by their time counted it up to n_substeps times over: fixed 2026-12-06)
    elapsed = task.control_dt
    power = np.where(np.isfinite(task.electrical_energy), task.electrical_energy / elapsed, 0.0)
    reward, terminated, truncated, info = task.shaped_reward(power, task.reward_config.reference_power, lat, rates,
                                                             None, failure)
    x = b.states
    w = WINCH_OBS_INDEX
    info.update(power_W=power, mechanical_power_W=(x[:, task.xoff + SX_ENERGY] - task.energy_start) / elapsed,
                winch_speed_m_s=o[:, w["winch_speed"]].copy(), paid_out_m=o[:, w["paid_out"]].copy(),
                drum_tension_N=o[:, w["drum_tension"]].copy(), max_tension_N=task.aux[:, AUX_MAX_TENSION].copy(),
                min_altitude_m=task.aux[:, AUX_MIN_ALTITUDE].copy(), t=b.t.copy(), n_clipped=n_clipped,
                failure=failure)
    asm = b.assembly
    if is_reel(asm.station):  # a reeling tether (model/reel.py): its elements in the air, its nodes on the ground
        info.update(tether_elements=np.array([nodes_in_air(asm, xi) + 1 for xi in x]),
                    tether_ground_contacts=np.array([ground_contacts(asm, xi) for xi in x]))
    return reward, terminated, truncated, info


def failure_text(task, b: int, code: int) -> str:
    """A sentence on why copy ``b`` terminated with failure ``code`` (time and quantity); "" for code 0. A limit
    of the integrator names the one that tripped, with its value (:func:`limit_text`); the reel-in end stop (code
    5) the rest length and the winch speed."""
    if code == REELED_IN:
        return f"t = {float(task.batch.t[b]):.2f} s: tether fully reeled in ({limit_text(task, b)})"
    if code == 1 and task.batch.status[b] == LIMIT:
        return f"t = {float(task.batch.t[b]):.2f} s: integration failed ({limit_text(task, b)})"
    return wing_failure_text(task, b, code, _STATUS_TEXT, task.raw_obs[b: b + 1], None, "wing")


def _limit_step(task, b: int):
    """(the state after copy ``b``'s failed step, taken again without the checks that stopped it, or None; the
    wings over the speed or rate limit there; the winch's reel-in sentence or None): see :func:`limit_text`."""
    sim = task.simulator(b)
    h = sim.settings.dt / SUBSTEP_DIVISORS[-1]  # a LIMIT stands after the batch's last, finest retry
    trial = trial_state(sim, h)  # None: the winch check (or a breakdown) failed it too
    try:
        x = trial[1] if trial is not None else unchecked_step(sim, h)
    except SimulationError:  # singular or non-finite on the way: no value to name
        return None, [], None
    return x, state_problems(sim, x), winch_limit_text(task.winch, sim.t + h, x, task.xoff)


def limit_text(task, b: int) -> str:
    """Which limit the failed physics step of copy ``b`` broke (the copy waits at its last good state; the step is
    the batch's finest retry, dt / 16, ``sim.batch.SUBSTEP_DIVISORS``), with its value: a wing's speed [m/s] or
    rate [rad/s] over the integrator's ``max_speed`` / ``max_rate`` (the step again without those checks,
    ``sim.reports.trial_state``), or the winch element's rest length [m] under ``MIN_FRACTION`` of its start length
    (``kernels/winch.py``; the step again without any check, classic RK4 on the right-hand side) with the winch
    speed [m/s]; the family's words for LIMIT if the step shows neither."""
    x, culprits, text = _limit_step(task, b)
    if x is None:
        return _LIMITS
    parts = [f"speed or rate limit: {', '.join(culprits[:4])}"] if culprits else []
    if text is not None:
        parts.append(text)
    return "; ".join(parts) if parts else _LIMITS


