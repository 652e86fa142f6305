"""The sentences that say why a copy of a wing task ended (the wing scenes, the laddermill and the pumping kite
share failure codes 1-4: integration, ground, cable, aerodynamic range), written once; each family names its status
text for the LIMIT code and how it calls a wing ("wing k", "slot k", or the one wing)."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.kernels.contract import GROUND, LIMIT, NONFINITE, SINGULAR
from laddermill_gym.kernels.rigid.observe import AUX_MAX_TENSION, AUX_MIN_ALTITUDE
from laddermill_gym.sim.reports import ground_stop_text

__all__ = ["status_texts", "shared_failure_text", "aero_range_text"]


def status_texts(limit_text: str) -> dict[int, str]:
    """Integrator status -> words, with the family's meaning of the LIMIT status."""
    return {SINGULAR: "singular mass matrix", NONFINITE: "non-finite state", LIMIT: limit_text}


def shared_failure_text(task, b: int, code: int, statuses: dict[int, str]) -> str | None:
    """The sentence for copy ``b``'s failure ``code`` where the wing families word it alike: "" for 0, the
    integrator's status for 1, a ground stop of the integrator for 2, the cable's tension [N] for 3; None where the
    family words it (2 by altitude, 4)."""
    if code == 0:
        return ""
    bt = task.batch
    t = float(bt.t[b])
    if code == 1:
        return f"t = {t:.2f} s: integration failed ({statuses.get(int(bt.status[b]), 'unknown')})"
    if code == 2 and bt.status[b] == GROUND:
        return f"t = {t:.2f} s: {ground_stop_text(bt.assembly, bt.states[b], bt.settings.ground_height)}"
    if code == 3:
        return f"t = {t:.2f} s: cable tension {task.aux[b, AUX_MAX_TENSION]:.4g} N over {task.breaking_tension:.4g} N"
    return None


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
