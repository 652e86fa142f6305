"""What the wing families' evaluations share, written once: the failure codes 1-4 (integration, ground, cable,
aerodynamic range; the wing scenes, the laddermill and the pumping kite) and the sentences that say why a copy
ended, and the lateral and rate penalties' arguments of their rewards. Each family names its status text for the
LIMIT code and how it calls a wing ("wing k", "slot k", or the one wing)."""

from __future__ import annotations

import math
import re

import numpy as np

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.kernels.contract import GROUND, LIMIT, NONFINITE, OK, SINGULAR
from laddermill_gym.kernels.rigid.observe import AUX_MAX_TENSION, AUX_MIN_ALTITUDE
from laddermill_gym.sim.reports import ground_stop_text

__all__ = ["status_texts", "shared_failure_text", "aero_range_text", "wing_failure_text", "wing_terms",
           "integration_diagnosis"]


def wing_terms(task, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lateral, rates, failure), each (B,), of the wing observation ``rows`` (B, n, >= 15) and the kernel's
    read-outs after a control period: the means over the wings of (dy / lateral_scale)^2 and of (p^2 + r^2) /
    rate_scale^2 (``reward_config``'s; nan or inf where a row is not finite), the arguments of the rewards'
    saturating penalties, and each copy's failure code (0: flying); where several apply, integration breakdown
    (1), then ground contact (2), cable overload (3), a wing's alpha or beta outside the termination range (4)."""
    rc = task.reward_config
    with np.errstate(invalid="ignore", over="ignore"):
        lat = np.mean((rows[:, :, OBS_INDEX["dy"]] / task.lateral_scale) ** 2, axis=1)
        rates = np.mean((rows[:, :, OBS_INDEX["p"]] ** 2 + rows[:, :, OBS_INDEX["r"]] ** 2) / rc.rate_scale ** 2,
                        axis=1)
    alpha, beta = rows[:, :, OBS_INDEX["alpha"]], rows[:, :, OBS_INDEX["beta"]]
    failure = np.zeros(task.n_copies, dtype=np.int64)
    failure[np.any((alpha < task.alpha_lo) | (alpha > task.alpha_hi) | (np.abs(beta) > task.beta_max), axis=1)] = 4
    failure[task.aux[:, AUX_MAX_TENSION] > task.breaking_tension] = 3
    failure[task.aux[:, AUX_MIN_ALTITUDE] < task.min_altitude] = 2
    failure[task.batch.status != OK] = 1
    failure[task.batch.status == GROUND] = 2
    return lat, rates, failure


def status_texts(limit_text: str) -> dict[int, str]:
    """Integrator status -> words, with the family's meaning of the LIMIT status."""
    return {SINGULAR: "singular mass matrix", NONFINITE: "non-finite state", LIMIT: limit_text}


def copy_simulator(task, b: int):
    """A simulator of copy ``b``'s state as it is (the family's own, else the task's snapshot, unchecked)."""
    from laddermill_gym.sim.simulator import Simulator

    return task.simulator(b) if hasattr(task, "simulator") else task._snapshot_simulator(Simulator, b, check=False)


def integration_diagnosis(task, b: int) -> str:
    """Where copy ``b``'s integration broke down: its first non-finite state entry by name (wing, node or station
    quantity; the simulator refuses such a state, so a finite stand-in names it), else the simulator's diagnosis of
    its state (``sim.reports.diagnose``: the fastest wing and node, the largest rate and tension)."""
    from laddermill_gym.sim.simulator import Simulator

    bt = task.batch
    x = bt.states[b]
    bad = np.flatnonzero(~np.isfinite(x))
    try:
        if bad.size:
            i = int(bad[0])
            names = Simulator(bt.assembly, np.nan_to_num(x), bt.settings, bt.controls[b])
            return f"{names.state_name(i)} = {x[i]} (state entry {i}; {bad.size} entries not finite)"
        return copy_simulator(task, b).diagnose()
    except (ValueError, RuntimeError, AttributeError, IndexError) as err:  # the read-out must not hide the failure
        return f"no diagnosis of the state ({type(err).__name__}: {err})"


def failed_step_culprits(sim, status: int) -> str:
    """What a copy's failed physics step broke, from its last good state in ``sim`` (the copy's simulator): for the
    LIMIT status the bodies over the speed or rate limit with their values, the step taken again at the batch's
    finest retry, dt / 16 (``sim.batch.SUBSTEP_DIVISORS``; dt where retries are off), without those checks
    (``sim.reports.trial_state``, ``state_problems``); for NONFINITE the alpha-rate term's cause where it is one; ""
    where nothing shows (the last good state alone is below every limit by construction). Ends with "; " when not
    empty."""
    from laddermill_gym.sim.batch import SUBSTEP_DIVISORS
    from laddermill_gym.sim.reports import state_problems, step_alpha_rate_cause, trial_state

    h = sim.settings.dt / (SUBSTEP_DIVISORS[-1] if SUBSTEP_DIVISORS else 1)  # the finest step taken (no retries: dt)
    try:
        if status == LIMIT:
            trial = trial_state(sim, h)
            bad = state_problems(sim, trial[1]) if trial is not None else []
            return f"in the step to t = {sim.t + h:.6g} s: {', '.join(bad[:4])}; " if bad else ""
        if status == NONFINITE:
            cause = step_alpha_rate_cause(sim, h)
            return f"{cause}; " if cause else ""
    except (ValueError, RuntimeError, ArithmeticError, AttributeError, TypeError) as err:  # must not hide the failure
        return f"(the failed step not retraced: {type(err).__name__}: {err}); "
    return ""


def _copy_culprits(task, b: int, status: int) -> str:
    """:func:`failed_step_culprits` of copy ``b``'s simulator; a simulator that cannot be built says so instead
    (the read-out must not hide the failure)."""
    try:
        sim = copy_simulator(task, b)
    except (ValueError, RuntimeError, AttributeError, IndexError) as err:
        return f"(the failed step not retraced: {type(err).__name__}: {err}); "
    return failed_step_culprits(sim, status)


def shared_failure_text(task, b: int, code: int, statuses: dict[int, str], unit: str = "wing") -> str | None:
    """The sentence for copy ``b``'s failure ``code`` where the wing families word it alike: "" for 0, the
    integrator's status for 1, a ground stop of the integrator for 2, the cable's tension [N] for 3; None where the
    family words it (2 by altitude, 4). ``unit``: what the family calls a wing's index (the mill: "slot", its state
    held in slot order), used for the simulator's "wing k"."""
    if code == 0:
        return ""
    bt = task.batch
    t = float(bt.t[b])
    if code == 1:
        status = int(bt.status[b])
        culprits = _copy_culprits(task, b, status) if np.all(np.isfinite(bt.states[b])) else ""
        return (f"t = {t:.2f} s: integration failed ({statuses.get(status, 'unknown')}); "
                f"{_in_units(culprits + integration_diagnosis(task, b), unit)}")
    if code == 2 and bt.status[b] == GROUND:
        stop = ground_stop_text(bt.assembly, bt.states[b], bt.settings.ground_height)
        return f"t = {t:.2f} s: {_in_units(stop, unit)}"
    if code == 3:
        return (f"t = {t:.2f} s: cable tension {task.aux[b, AUX_MAX_TENSION]:.4g} N over {task.breaking_tension:.4g} N"
                f"{_strongest_element(task, b)}")
    return None


def _in_units(text: str, unit: str) -> str:
    """``text`` with the simulator's "wing k" as "``unit`` k"."""
    return text if unit == "wing" else re.sub(r"\bwing (\d+)", rf"{unit} \1", text)


def _strongest_element(task, b: int) -> str:
    """" in element e" for the most loaded element of copy ``b``'s state (its tensions evaluated again by the
    simulator of that state: the same element loop as the observation's), or "" where they cannot be."""
    try:
        tensions = copy_simulator(task, b).tensions()
    except (ValueError, RuntimeError, AttributeError, IndexError):  # the read-out must not hide the failure
        return ""
    return f" in element {int(np.argmax(tensions))}" if tensions.size else ""


def wing_failure_text(task, b: int, code: int, statuses: dict[int, str], rows: np.ndarray, label: str | None,
                      lowest: str) -> str:
    """A sentence on why copy ``b`` of a wing family ended with failure ``code`` ("" for 0): the integrator's
    status (``statuses``), a ground stop of the integrator or the ``lowest`` wing's ("slot k", "wing") CG altitude
    [m] below ``min_altitude``, the cable's tension [N], or the worst wing of the observation ``rows`` (n, 15)
    outside the aerodynamic range (:func:`aero_range_text` with ``label``)."""
    text = shared_failure_text(task, b, code, statuses, label or "wing")
    if text is not None:
        return text
    if code == 2:
        return (f"t = {float(task.batch.t[b]):.2f} s: ground contact, {lowest} CG at {altitude(task, b):.2f} m "
                f"altitude (< {task.min_altitude:.3g} m)")
    return aero_range_text(task, b, rows, label)


def aero_range_text(task, b: int, rows: np.ndarray, label: str | None) -> str:
    """Failure 4 of copy ``b``: the wing (``label`` k, the worst of the observation ``rows`` (n, 15); None: the one
    wing, unnamed) whose alpha or beta [deg] is furthest outside the termination range."""
    t = float(task.batch.t[b])
    al, be = rows[:, OBS_INDEX["alpha"]], rows[:, OBS_INDEX["beta"]]
    k = int(np.argmax(np.maximum(np.maximum(task.alpha_lo - al, al - task.alpha_hi), np.abs(be) - task.beta_max)))
    who = "" if label is None else f"{label} {k} "
    return (f"t = {t:.2f} s: {who}alpha = {math.degrees(al[k]):.1f} deg, beta = {math.degrees(be[k]):.1f} deg "
            "outside the aerodynamic range")


def altitude(task, b: int) -> float:
    """Copy ``b``'s lowest wing CG altitude [m] of the last observation."""
    return float(task.aux[b, AUX_MIN_ALTITUDE])
