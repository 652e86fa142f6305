"""Observation layout of the rotorcraft environments (names, units, meanings) and its bounds.

The 19 entries of :data:`CRAFT_OBS_FIELDS` are a public contract (controllers index them by name through
:data:`CRAFT_OBS_INDEX` or by the fixed lateral indices ``OBS_*``); change them only together with the env id's
version. They are assembled from the slots ``CO_*`` that the observation kernel writes
(:mod:`laddermill_gym.rotorcraft.craft_observe`), and an import-time check fails if the named groups do not
tile its ``N_CRAFT_OBS`` slots.
"""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.envs.observation import ObsField
from laddermill_gym.kernels.contract import (
    CO_EULER,
    CO_OFFSET,
    CO_PITCH,
    CO_RATES,
    CO_TENSION,
    CO_THRUST,
    CO_VELOCITY,
    N_CRAFT_OBS,
)
from laddermill_gym.rotorcraft.config import CraftConfig

__all__ = ["CRAFT_OBS_FIELDS", "CRAFT_OBS_INDEX", "N_CRAFT_OBS", "OBS_Y", "OBS_PHI", "OBS_VY", "OBS_P", "OBS_PSI",
           "OBS_R", "craft_observation_bounds"]

#: The named entries of each slot group of the observation kernel (start slot -> fields, in order).
_SLOT_GROUPS: dict[int, tuple[ObsField, ...]] = {
    CO_OFFSET: (ObsField("dx", "m", "CG x (north, upwind) relative to the trim position"),
                ObsField("dy", "m", "CG y (east, lateral) relative to the trim position"),
                ObsField("dz", "m", "CG z (down) relative to the trim position")),
    CO_VELOCITY: (ObsField("vx", "m/s", "CG velocity, global x"),
                  ObsField("vy", "m/s", "CG velocity, global y (lateral)"),
                  ObsField("vz", "m/s", "CG velocity, global z (down)")),
    CO_EULER: (ObsField("phi", "rad", "roll angle (3-2-1 Euler)"),
               ObsField("theta", "rad", "pitch angle (3-2-1 Euler; the trim's is about the craft incidence alpha_c)"),
               ObsField("psi", "rad", "yaw angle (3-2-1 Euler)")),
    CO_RATES: (ObsField("p", "rad/s", "roll rate, body x"),
               ObsField("q", "rad/s", "pitch rate, body y"),
               ObsField("r", "rad/s", "yaw rate, body z")),
    CO_THRUST: (ObsField("thrust_right", "-", "right rotor thrust over its trim thrust"),
                ObsField("thrust_left", "-", "left rotor thrust over its trim thrust")),
    CO_TENSION: (
        ObsField("tension_rear_right", "-", "craft-end tension of the rear right tether over its trim tension"),
        ObsField("tension_rear_left", "-", "craft-end tension of the rear left tether over its trim tension"),
        ObsField("tension_front", "-", "craft-end tension of the forward tether over its trim tension")),
    CO_PITCH: (ObsField("pitch_right", "rad", "blade collective pitch of the right rotor, theta0 + dtheta"),
               ObsField("pitch_left", "rad", "blade collective pitch of the left rotor, theta0 - dtheta")),
}


def _fields_from_slots() -> tuple[ObsField, ...]:
    fields: list[ObsField] = []
    for start in sorted(_SLOT_GROUPS):
        if start != len(fields):
            raise ImportError(f"craft observation slot group at {start} does not follow the previous groups, which "
                              f"end at {len(fields)} (rotorcraft/craft_observe.py CO_*)")
        fields.extend(_SLOT_GROUPS[start])
    if len(fields) != N_CRAFT_OBS:
        raise ImportError(f"craft observation fields cover {len(fields)} slots, N_CRAFT_OBS = {N_CRAFT_OBS}")
    return tuple(fields)


#: Observation entries, in order (a public contract: change it only with the env id's version).
CRAFT_OBS_FIELDS: tuple[ObsField, ...] = _fields_from_slots()
#: Field name -> observation index.
CRAFT_OBS_INDEX: dict[str, int] = {f.name: i for i, f in enumerate(CRAFT_OBS_FIELDS)}
#: Fixed indices of the lateral states (read by the lateral controllers).
OBS_Y, OBS_PHI, OBS_VY, OBS_P, OBS_PSI, OBS_R = (CRAFT_OBS_INDEX[k] for k in ("dy", "phi", "vy", "p", "psi", "r"))


def craft_observation_bounds(cfg: CraftConfig, tether_lengths: np.ndarray,
                             tension_trim: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(low, high), each (N_CRAFT_OBS,) float32: +-(2 x longest tether + 100 m) for offsets, the integrator's
    speed [m/s] and rate [rad/s] limits, natural ranges for angles [rad], +-100 for thrust ratios, 0 to 100 x
    breaking load / smallest trim tension for tension ratios, the reachable blade pitches [rad].
    ``tether_lengths`` (3,) [m], ``tension_trim`` (3,) [N]."""
    reach = 2.0 * float(np.max(tether_lengths)) + 100.0
    vmax, wmax = cfg.settings.max_speed, cfg.settings.max_rate
    tmax = 100.0 * cfg.tethers.cable.breaking_load / float(np.min(tension_trim))
    hp = 0.5 * math.pi
    d_lo, d_hi = cfg.differential_limits  # a rotor's pitch is the collective plus or minus the differential
    pmin = cfg.collective_limits[0] + min(d_lo, -d_hi)
    pmax = cfg.collective_limits[1] + max(d_hi, -d_lo)
    high = np.zeros(N_CRAFT_OBS)
    low = np.zeros(N_CRAFT_OBS)
    for start, value in ((CO_OFFSET, reach), (CO_VELOCITY, vmax), (CO_RATES, wmax)):
        high[start: start + 3] = value
        low[start: start + 3] = -value
    high[CO_EULER: CO_EULER + 3] = (math.pi, hp, math.pi)
    low[CO_EULER: CO_EULER + 3] = (-math.pi, -hp, -math.pi)
    high[CO_THRUST: CO_THRUST + 2], low[CO_THRUST: CO_THRUST + 2] = 100.0, -100.0
    high[CO_TENSION: CO_TENSION + 3], low[CO_TENSION: CO_TENSION + 3] = tmax, 0.0
    high[CO_PITCH: CO_PITCH + 2], low[CO_PITCH: CO_PITCH + 2] = pmax, pmin
    return low.astype(np.float32), high.astype(np.float32)
