"""Observation layout of ``laddermill_gym/PumpingKite-v0`` (names, units, meanings) and its bounds: the wing's 15
entries (:data:`laddermill_gym.envs.observation.OBS_FIELDS`, written by ``kernels/rigid/observe.py``; the CG offset
from the trim position at the start of reel-out), then the winch entries :data:`WINCH_OBS_FIELDS`. The layout is a
public contract; change it only together with the env id's version."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_FIELDS, ObsField, observation_bounds
from laddermill_gym.ladder.scene import Scene

__all__ = ["WINCH_OBS_FIELDS", "WINCH_OBS_INDEX", "N_WINCH_OBS", "N_OBS", "observation_names",
           "pumping_observation_bounds"]

#: Winch entries after the wing's, in order.
WINCH_OBS_FIELDS: tuple[ObsField, ...] = (
    ObsField("winch_speed", "m/s", "winch speed V (> 0: reeling out)"),
    ObsField("paid_out", "m", "tether paid out since the start of the episode, s (the start of reel-out: 0)"),
    ObsField("drum_tension", "N", "tension of the tether element at the drum, T_0"),
    ObsField("radial_wind", "m/s", "wind at the wing CG along the tether direction (winch -> wing), w . e_r"),
    ObsField("wind_speed", "m/s", "wind speed at the wing CG, |w|"),
)
N_WINCH_OBS = len(WINCH_OBS_FIELDS)
WINCH_OBS_INDEX: dict[str, int] = {f.name: N_OBS_PER_WING + i for i, f in enumerate(WINCH_OBS_FIELDS)}
N_OBS = N_OBS_PER_WING + N_WINCH_OBS


def observation_names() -> tuple[str, ...]:
    """Names of every entry: the wing's (``'dy'``, ...), then ``'winch_speed'``, ... (length 20)."""
    return tuple(f.name for f in OBS_FIELDS) + tuple(f.name for f in WINCH_OBS_FIELDS)


def pumping_observation_bounds(scene: Scene, reel_length: float) -> tuple[np.ndarray, np.ndarray]:
    """(low, high), each (20,) float64: the wing envs' bounds (:func:`observation_bounds`) with the offsets widened
    by twice the reel length [m], then winch speed +-(max_speed) [m/s] (the integrator's speed limit), paid out
    +-(start length + 2 reel lengths) [m], drum tension 0 to 100 x breaking load [N], winds +-max_speed [m/s].
    Observations are clipped to them."""
    low, high = observation_bounds(scene)
    for k in range(3):  # the CG offsets dx, dy, dz
        low[k] -= 2.0 * reel_length
        high[k] += 2.0 * reel_length
    vmax = scene.settings.max_speed
    reach = float(scene.assembly.elements.l0[0]) + 2.0 * reel_length
    tmax = 100.0 * scene.cable.breaking_load if math.isfinite(scene.cable.breaking_load) else 1e9
    w_low = np.array([-vmax, -reach, 0.0, -vmax, 0.0])
    w_high = np.array([vmax, reach, tmax, vmax, vmax])
    return np.concatenate([low, w_low]), np.concatenate([high, w_high])
