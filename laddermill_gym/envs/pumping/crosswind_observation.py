"""Observation layout of ``laddermill_gym/PumpingKite-v1`` beyond v0's 20 entries: what a kite's flight controller
measures on the wind window (``envs.pumping.wind_window``), the apparent wind and the cycle's progress on the drum.
The layout is a public contract; change it only together with the env id's version."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.observation import ObsField
from laddermill_gym.envs.pumping.observation import N_OBS as N_V0_OBS

__all__ = ["CROSSWIND_OBS_FIELDS", "CROSSWIND_OBS_INDEX", "N_CROSSWIND_OBS", "crosswind_bounds"]

#: Entries after v0's, in order.
CROSSWIND_OBS_FIELDS: tuple[ObsField, ...] = (
    ObsField("elevation", "rad", "elevation of the wing CG seen from the winch, beta"),
    # the wind window's frame is the scene's nominal wind (along -x): it does not turn with a direction disturbance
    ObsField("azimuth", "rad", "azimuth of the wing CG from the nominal wind's direction -x (+: towards +y), phi"),
    ObsField("course_sin", "-", "sin of the course chi on the wind window (0 up, +pi/2 towards larger azimuth)"),
    ObsField("course_cos", "-", "cos of the course chi"),
    ObsField("bank", "rad", "bank of the lift against the tether, towards larger course, mu"),
    ObsField("tangential_speed", "m/s", "speed of the wing CG across the tether (on the wind window)"),
    ObsField("radial_speed", "m/s", "speed of the wing CG along the tether, away from the winch"),
    ObsField("apparent_wind", "m/s", "airspeed of the wing CG, |w - v|"),
    ObsField("cycle_fraction", "-", "tether paid out over the reel length Delta L, s / Delta L (the cycle's phase)"),
)
N_CROSSWIND_OBS = N_V0_OBS + len(CROSSWIND_OBS_FIELDS)
CROSSWIND_OBS_INDEX: dict[str, int] = {f.name: N_V0_OBS + i for i, f in enumerate(CROSSWIND_OBS_FIELDS)}


def crosswind_bounds(v0_low: np.ndarray, v0_high: np.ndarray, max_speed: float,
                     reach_fraction: float) -> tuple[np.ndarray, np.ndarray]:
    """(low, high) of every entry: v0's, then the angles' ranges, speeds +-``max_speed`` [m/s] (the integrator's
    limit), the cycle fraction +-``reach_fraction``."""
    low = [-math.pi / 2, -math.pi, -1.0, -1.0, -math.pi / 2, 0.0, -max_speed, 0.0, -reach_fraction]
    high = [math.pi / 2, math.pi, 1.0, 1.0, math.pi / 2, max_speed, max_speed, 2.0 * max_speed, reach_fraction]
    return np.concatenate([v0_low, low]), np.concatenate([v0_high, high])
