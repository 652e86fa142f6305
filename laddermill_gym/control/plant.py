"""The simulator as a complete python-control plant: minimal coordinates, the environments' observation as its
output, and the wind as a disturbance input.

``control.nlsys(sim.rhs, ...)`` on the full state works but is a trap for control design: a wing's attitude is a
quaternion (4 numbers, 3 degrees of freedom), so the full-state linearisation has a pole at 0 (the quaternion's norm)
that no controller can move, and ``control.find_eqpt`` on the full state may return a quaternion of any norm.
:func:`plant_system` avoids both: its states are the minimal coordinates of :mod:`.linearize` (per wing position,
3-2-1 Euler angles, global velocity and body rates; per free node position and velocity), so
``control.linearize(plant, z0, u0)`` gives a minimal (A, B, C, D) and ``find_eqpt`` works in Euler angles.

Inputs: the controls (elevator, rudder, aileron per wing [rad]; a station's control last), then the wind
disturbances ``wind_speed_factor`` [-] (the deviation of the wind's speed factor from 1: 0.1 is a 10 % stronger
wind at every height) and ``wind_direction_offset`` [rad] (added to the wind direction at every height). They replace
the simulator's time modulation by these constants (a steady wind: the alpha-rate term sees no wind rate).

Outputs: the environments' observation (``control.base.OBS_NAMES`` per wing, the same kernel), offsets from the
positions at (z0, u0); or, with ``outputs="states"``, the states.

``params``: ``{"wind_speed_factor": k}`` scales the whole wind profile by k (the same as a disturbance input of k - 1
held on top of any input); other keys raise ValueError.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.control.base import OBS_NAMES, elements_below_wings, observe
from laddermill_gym.control.linearize import full_from_minimal, minimal_derivative, minimal_from_full, state_labels
from laddermill_gym.kernels.contract import TM_DT, TM_SIZE, TM_T0

__all__ = ["DISTURBANCE_NAMES", "PARAMETER_NAMES", "plant_system", "with_steady_wind"]

#: Disturbance inputs after the controls, in order: speed factor deviation [-], direction offset [rad]
DISTURBANCE_NAMES: tuple[str, ...] = ("wind_speed_factor", "wind_direction_offset")
#: Parameters the plant's update and output functions take (``params``)
PARAMETER_NAMES: tuple[str, ...] = ("wind_speed_factor",)


def _parameters(params) -> float:
    """The wind speed factor of ``params`` (1 without); ValueError naming unknown keys or a bad value."""
    params = dict(params or {})
    unknown = sorted(set(params) - set(PARAMETER_NAMES))
    if unknown:
        raise ValueError(f"params: unknown {unknown}; the plant takes {list(PARAMETER_NAMES)}")
    k = params.get("wind_speed_factor", 1.0)
    if isinstance(k, bool) or not np.isfinite(k) or k < 0:
        raise ValueError(f"params['wind_speed_factor'] = {k!r}: must be a finite number >= 0")
    return float(k)


def with_steady_wind(model, speed_factor: float, direction_offset: float):
    """A copy of the packed ``model`` whose wind modulation is the constant speed factor [-] and direction offset
    [rad] (the profile, density and any gust grid unchanged)."""
    tmod = np.zeros(TM_SIZE)
    tmod[TM_T0], tmod[TM_DT] = 0.0, 1.0
    return model._replace(tmod=tmod, ms=np.array([float(speed_factor)]), md=np.array([float(direction_offset)]))


def plant_system(scene, x0: np.ndarray, u0: np.ndarray, outputs: str = "observation", name: str = "laddermill"):
    """``control.nlsys`` of ``scene`` about the operating point (x0 full state, u0 controls) in minimal
    coordinates, with the wind disturbance inputs and the observation (or state) outputs (see the module doc).

    Returns the system; ``plant.z0`` (minimal coordinates of x0) and ``plant.u0`` (controls then zero
    disturbances) are attached for ``control.linearize(plant, plant.z0, plant.u0)``.
    """
    import control

    if outputs not in ("observation", "states"):
        raise ValueError(f"outputs = {outputs!r}: 'observation' or 'states'")
    x0 = np.asarray(x0, dtype=float)
    sim = scene.simulator(x0, u0)
    asm = sim.assembly
    if asm.dim != 3:
        raise ValueError(f"scene {scene.name}: the plant needs a 3D scene (dimension = {asm.dim})")
    tail = x0[asm.body_state_size:]
    nc = sim.n_controls
    base_model = sim.model
    nominal = sim.wing_positions()
    below = elements_below_wings(scene.layout, asm.n_wings)

    def _set(z, u, params):
        k = _parameters(params)
        u = np.asarray(u, dtype=float).reshape(-1)
        sim.model = with_steady_wind(base_model, k * (1.0 + u[nc]), u[nc + 1])
        return full_from_minimal(asm, z, tail), u[:nc]

    def updfcn(t, z, u, params=None):
        x, uc = _set(z, u, params)
        try:
            return minimal_derivative(asm, x, sim.rhs(t, x, uc))
        finally:
            sim.model = base_model

    def outfcn(t, z, u, params=None):
        if outputs == "states":
            return np.asarray(z, dtype=float).copy()
        x, uc = _set(z, u, params)
        saved = (sim.state, sim.t, sim.controls)
        sim.state, sim.t, sim.controls = x, float(t), uc
        try:
            return observe(sim, nominal, below)
        finally:
            sim.model = base_model
            sim.state, sim.t, sim.controls = saved

    states = state_labels(asm)
    out_names = states if outputs == "states" else [f"wing{k}_{n}" for k in range(asm.n_wings) for n in OBS_NAMES]
    plant = control.nlsys(updfcn, outfcn, states=states, inputs=list(sim.control_labels) + list(DISTURBANCE_NAMES),
                          outputs=out_names, name=name, params={})
    plant.z0 = minimal_from_full(asm, x0)
    plant.u0 = np.concatenate([np.asarray(u0, dtype=float).reshape(-1), np.zeros(len(DISTURBANCE_NAMES))])
    return plant
