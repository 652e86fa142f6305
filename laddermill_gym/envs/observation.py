"""Per-wing observation layout (names, units, meanings) and its bounds.

Every wing contributes the 15 entries of :data:`OBS_FIELDS`, in that order; wings are concatenated in
chain order (wing 0 first). The layout is a public contract (controllers index it by name through
:data:`OBS_INDEX`); change it only together with the env ids' version.

The layout is defined once: :data:`OBS_FIELDS` is assembled from the slots ``OBS_*`` of
``kernels/contract.py`` that the observation kernel writes (``kernels/rigid/observe.py``, the only
implementation of the observation: the environments and ``control.base.observe`` both call it), and an
import-time check fails if the named groups do not tile the ``OBS_SIZE`` slots.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels.contract import (
    OBS_ALPHA,
    OBS_BETA,
    OBS_EULER,
    OBS_OFFSET,
    OBS_RATES,
    OBS_SIZE,
    OBS_TENSION,
    OBS_VELOCITY,
)
from laddermill_gym.ladder.scene import Scene


@dataclass(frozen=True)
class ObsField:
    """One per-wing observation entry: its name, SI unit and meaning."""

    name: str
    unit: str
    description: str


#: The named entries of each slot group of ``kernels/contract.py`` (start slot -> fields, in order).
_SLOT_GROUPS: dict[int, tuple[ObsField, ...]] = {
    OBS_OFFSET: (
        ObsField("dx", "m", "CG x (north, upwind) relative to the nominal (initial equilibrium) position"),
        ObsField("dy", "m", "CG y (east) relative to the nominal position"),
        ObsField("dz", "m", "CG z (down) relative to the nominal position"),
    ),
    OBS_VELOCITY: (
        ObsField("vx", "m/s", "CG velocity, global x"),
        ObsField("vy", "m/s", "CG velocity, global y"),
        ObsField("vz", "m/s", "CG velocity, global z (down)"),
    ),
    OBS_EULER: (
        ObsField("phi", "rad", "roll angle (3-2-1 Euler)"),
        ObsField("theta", "rad", "pitch angle (3-2-1 Euler)"),
        ObsField("psi", "rad", "yaw angle (3-2-1 Euler)"),
    ),
    OBS_RATES: (
        ObsField("p", "rad/s", "roll rate, body x"),
        ObsField("q", "rad/s", "pitch rate, body y"),
        ObsField("r", "rad/s", "yaw rate, body z"),
    ),
    OBS_ALPHA: (ObsField("alpha", "rad", "angle of attack of the CG air velocity, atan2(w_a, u_a)"),),
    OBS_BETA: (ObsField("beta", "rad", "sideslip of the CG air velocity, asin(v_a / |V_a|)"),),
    OBS_TENSION: (
        ObsField("tension", "N", "tension of the cable element below the wing (towards the start ground point)"),
    ),
}


def _fields_from_slots(groups: dict[int, tuple[ObsField, ...]], size: int) -> tuple[ObsField, ...]:
    """The per-wing fields in slot order; ValueError unless the groups tile slots 0 .. size - 1 exactly."""
    fields: list[ObsField] = []
    for start in sorted(groups):
        if start != len(fields):
            raise ValueError(f"observation layout: a group starts at slot {start}, expected {len(fields)} "
                             "(kernels/contract.py OBS_* and envs/observation.py disagree)")
        fields.extend(groups[start])
    if len(fields) != size:
        raise ValueError(f"observation layout: {len(fields)} named entries, OBS_SIZE = {size}")
    return tuple(fields)


#: Per-wing observation entries, in order (slot i of a wing's block is OBS_FIELDS[i]).
OBS_FIELDS: tuple[ObsField, ...] = _fields_from_slots(_SLOT_GROUPS, OBS_SIZE)
#: Number of observation entries per wing (= ``kernels.contract.OBS_SIZE``).
N_OBS_PER_WING = len(OBS_FIELDS)
#: Field name -> index within a wing's block.
OBS_INDEX: dict[str, int] = {f.name: i for i, f in enumerate(OBS_FIELDS)}


def observation_bounds(scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    """Generous physical bounds (low, high), each shape (n_wings * N_OBS_PER_WING,), float64.

    Position offsets: +-(2 L + 100 m) with L the chain's total unstretched cable length (no wing can be
    further than that from its nominal position while tethered). Velocities and body rates: the
    integrator's ``max_speed`` and ``max_rate`` (a state beyond them stops the simulation). Angles: their
    natural ranges. Tension: 0 to 100 times the cable's breaking load (the episode ends above 1 times).
    """
    a = scene.assembly
    reach = 2.0 * float(np.sum(a.elements.l0)) + 100.0
    vmax, wmax = scene.settings.max_speed, scene.settings.max_rate
    tmax = 100.0 * scene.cable.breaking_load if math.isfinite(scene.cable.breaking_load) else 1e9
    half_pi = 0.5 * math.pi
    per_wing = {
        "dx": reach, "dy": reach, "dz": reach, "vx": vmax, "vy": vmax, "vz": vmax,
        "phi": math.pi, "theta": half_pi, "psi": math.pi, "p": wmax, "q": wmax, "r": wmax,
        "alpha": math.pi, "beta": half_pi,
    }
    high = np.array([per_wing.get(f.name, tmax) for f in OBS_FIELDS])
    low = -high
    low[OBS_INDEX["tension"]] = 0.0
    return np.tile(low, a.n_wings), np.tile(high, a.n_wings)


def wing_lateral_offsets(obs: np.ndarray, n_wings: int) -> np.ndarray:
    """Lateral CG offsets dy [m] (B, n_wings) float64 of observations (B, >= 15 n_wings) that begin with the
    per-wing rows of :data:`OBS_FIELDS` (wing and mill envs, the pumping kite)."""
    o = np.asarray(obs, dtype=float)
    return o[:, : N_OBS_PER_WING * n_wings].reshape(o.shape[0], n_wings, N_OBS_PER_WING)[:, :, OBS_INDEX["dy"]]


def observation_table(fields, prefix: str = "", start: int = 0) -> str:
    """Markdown rows ``| prefix + index | name | unit | meaning |`` of observation ``fields`` (the envs' docs)."""
    rows = (f"    | {prefix}{start + i} | {f.name} | {f.unit} | {f.description} |" for i, f in enumerate(fields))
    return "\n".join(rows)
