"""Observation layout of ``laddermill_gym/LadderMill-v0`` (names, units, meanings) and its bounds.

The observation is by *slot* (the position along the loop, a stationary layout while the wings travel): slot k's
block is the 15 entries of the wing currently in slot k, written by the wings' observation kernel
(``kernels/rigid/observe.py``, which runs on the moving-cable kinds unchanged: the state is in slot order and the
station block follows the bodies), in the order of :data:`laddermill_gym.envs.observation.OBS_FIELDS`. Slots are
concatenated (slot 0 first), then the station entries :data:`STATION_OBS_FIELDS`.

The CG offset is taken from the reference orbit at the current cable phase: the in-plane operating point's slot
positions, recorded over one period against the cable moved since the last transfer s, interpolated at the copy's
own s (:func:`~laddermill_gym.envs.laddermill.operating_point.nominal_positions`). The layout is a public contract;
change it only together with the env id's version.
"""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_FIELDS, OBS_INDEX, ObsField, observation_bounds
from laddermill_gym.ladder.scene import Scene

__all__ = ["SLOT_OBS_FIELDS", "STATION_OBS_FIELDS", "STATION_OBS_INDEX", "N_STATION_OBS", "N_OBS_PER_SLOT",
           "OBS_INDEX", "mill_observation_bounds", "observation_names"]

_SLOT_MEANINGS = {
    "dx": "CG x (north, upwind) relative to the reference orbit at the current cable phase",
    "dy": "CG y (east, lateral) relative to the reference orbit (in plane: y = 0)",
    "dz": "CG z (down) relative to the reference orbit at the current cable phase",
    "tension": "tension of the cable element below the slot (towards the veered ground point; slot 0: the first, "
               "moving element)",
}

#: Per-slot entries (the wing envs' per-wing entries, offsets from the reference orbit).
SLOT_OBS_FIELDS: tuple[ObsField, ...] = tuple(
    ObsField(f.name, f.unit, _SLOT_MEANINGS.get(f.name, f.description)) for f in OBS_FIELDS)
N_OBS_PER_SLOT = N_OBS_PER_WING

#: Station entries after the slots, in order.
STATION_OBS_FIELDS: tuple[ObsField, ...] = (
    ObsField("cable_speed", "m/s", "cable speed V_c (> 0: up the ascending side)"),
    ObsField("cable_phase", "-", "cable moved since the last wing transfer over the piece length, s / l0 in [0, 1)"),
    ObsField("tension_difference", "N", "T_first - T_last, first (veered) minus last (hauled) element tension"),
    ObsField("power_ratio", "-", "generator electrical power over the operating point's mean, P / P_ref"),
)
N_STATION_OBS = len(STATION_OBS_FIELDS)
STATION_OBS_INDEX: dict[str, int] = {f.name: i for i, f in enumerate(STATION_OBS_FIELDS)}


def observation_names(n_slots: int) -> tuple[str, ...]:
    """Names of every entry, e.g. ``'slot 3 dy'``, then ``'station cable_speed'`` (length 15 n + 4)."""
    return (tuple(f"slot {k} {f.name}" for k in range(n_slots) for f in SLOT_OBS_FIELDS)
            + tuple(f"station {f.name}" for f in STATION_OBS_FIELDS))


def mill_observation_bounds(scene: Scene, max_speed: float, max_power_ratio: float = 1e3
                            ) -> tuple[np.ndarray, np.ndarray]:
    """(low, high), each (15 n + 4,) float64: the wing envs' per-slot bounds (:func:`observation_bounds`: offsets
    +-(2 L + 100 m), the integrator's speed and rate limits, natural angle ranges, tension 0 to 100 x breaking load),
    then cable speed +-``max_speed`` [m/s] (one piece per physics step, the kernel's limit), phase 0 to 1, tension
    difference +-100 x breaking load [N], power ratio +-``max_power_ratio``. Observations are clipped to them."""
    low, high = observation_bounds(scene)
    tmax = 100.0 * scene.cable.breaking_load if math.isfinite(scene.cable.breaking_load) else 1e9
    st_low = np.array([-max_speed, 0.0, -tmax, -max_power_ratio])
    st_high = np.array([max_speed, 1.0, tmax, max_power_ratio])
    return np.concatenate([low, st_low]), np.concatenate([high, st_high])
