"""The simulator as a complete python-control plant: minimal coordinates, named states, inputs (controls and wind
disturbances) and outputs, for every vehicle and station: the wing scenes, Roberts' rotorcraft, the moving-cable
mill and the pumping kite's winch.

``control.nlsys(sim.rhs, ...)`` on the full state works but is a trap for control design: a body's attitude is a
quaternion (4 numbers, 3 degrees of freedom), so the full-state linearisation has a pole at 0 (the quaternion's norm)
that no controller can move, and ``control.find_eqpt`` on the full state may return a quaternion of any norm.
:func:`plant_system` avoids both: its states are the minimal coordinates of :mod:`.linearize` (per body position,
3-2-1 Euler angles, global velocity and body rates; per free node position and velocity), then a station's block
(the mill's generator or the pumping winch: :data:`STATION_STATE_NAMES`), so ``control.linearize(plant, plant.z0,
plant.u0, copy_names=True)`` gives a minimal (A, B, C, D) whose signals keep their names (python-control names them
``x[i]``, ``u[i]``, ``y[i]`` without ``copy_names=True``) and ``find_eqpt`` works in Euler angles.

Systems (the first argument):

* a wing scene (``ladder.load_scene``), the moving-cable mill (``load_scene("laddermill")``) included;
* Roberts' craft (``rotorcraft.craft.load_craft``, a :class:`~laddermill_gym.rotorcraft.craft.Craft`, or its
  :class:`~laddermill_gym.rotorcraft.craft.CraftSimulator`);
* a pumping config (``envs.pumping.winch_scene.load_pumping``): the wing on the winch.

Inputs: the simulator's controls by name (``sim.control_labels``: per wing elevator, rudder, aileron [rad]; the craft's
collective and differential [rad]; a station's generator torque [N m] or commanded speed [m/s] last), then the wind
disturbances ``wind_speed_factor`` [-] (the deviation of the wind's speed factor from 1: 0.1 is a 10 % stronger wind
at every height) and ``wind_direction_offset`` [rad] (added to the wind direction at every height). They replace the
simulator's time modulation by these constants (a steady wind: the alpha-rate term sees no wind rate).

Outputs (``outputs="observation"``, the default): what the environments observe, offsets taken from the positions at
(x0, u0):

* wings: the wing environments' observation (``control.base.OBS_NAMES`` per wing, the same kernel);
* the craft: the rotorcraft environments' observation (``CRAFT_OBS_FIELDS``: offsets, global velocity, Euler angles,
  rates from the minimal coordinates; thrust and tension over their values at (x0, u0) and the blade pitch from the
  simulator's read-outs, ``rotor_outputs`` and ``tether_tensions``);
* the mill: the wing observation by slot, then :data:`MILL_OUTPUT_NAMES` (cable speed [m/s], phase s / l0 [-],
  T_first - T_last [N], the generator's electrical power [W], from ``sim.generator_power()``);
* the winch: the wing observation, then :data:`WINCH_OUTPUT_NAMES` (tether tension at the drum [N], winch speed
  [m/s], electrical power [W], from ``winch_power()``).

``outputs="states"``: the states. A station's dynamics hold between wing transfers (the mill moves a wing on by one
slot each time the cable has moved a piece, in the step's check, not in the right-hand side).

``params``: ``{"wind_speed_factor": k}`` scales the whole wind profile by k (the same as a disturbance input of k - 1
held on top of any input); other keys raise ValueError.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from laddermill_gym.control.base import OBS_NAMES, elements_below_wings, observe
from laddermill_gym.control.linearize import full_from_minimal, minimal_derivative, minimal_from_full, state_labels
from laddermill_gym.envs.pumping.winch_scene import PumpingScene, WinchSimulator
from laddermill_gym.envs.rotorcraft.observation import CRAFT_OBS_FIELDS
from laddermill_gym.kernels.contract import SX_MOVED, TM_DT, TM_SIZE, TM_T0
from laddermill_gym.rotorcraft.craft import Craft, CraftSimulator

__all__ = ["DISTURBANCE_NAMES", "PARAMETER_NAMES", "STATION_STATE_NAMES", "MILL_OUTPUT_NAMES", "WINCH_OUTPUT_NAMES",
           "CRAFT_OUTPUT_NAMES", "plant_system", "with_steady_wind"]

#: Disturbance inputs after the controls, in order: speed factor deviation [-], direction offset [rad]
DISTURBANCE_NAMES: tuple[str, ...] = ("wind_speed_factor", "wind_direction_offset")
#: Parameters the plant's update and output functions take (``params``)
PARAMETER_NAMES: tuple[str, ...] = ("wind_speed_factor",)
#: States after the bodies of a system with a station (the ``SX_*`` block of kernels/contract.py): cable moved since
#: the last transfer [m], transfers [-], cable speed [m/s], generator (winch) energy [J]
STATION_STATE_NAMES: tuple[str, ...] = ("station_moved", "station_transfers", "station_cable_speed",
                                        "station_energy")
#: Outputs of the mill after its slots: V_c [m/s], s / l0 [-], T_first - T_last [N], electrical power [W]
MILL_OUTPUT_NAMES: tuple[str, ...] = ("station_cable_speed", "station_cable_phase", "station_tension_difference",
                                      "station_electrical_power")
#: Outputs of the winch after the wing: tether tension at the drum [N], winch speed [m/s], electrical power [W]
WINCH_OUTPUT_NAMES: tuple[str, ...] = ("winch_tension", "winch_speed", "winch_electrical_power")
#: Outputs of the craft: the rotorcraft environments' observation entries, in order
CRAFT_OUTPUT_NAMES: tuple[str, ...] = tuple(f"craft_{f.name}" for f in CRAFT_OBS_FIELDS)


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


@dataclass
class _Plant:
    """A system's simulator and what its outputs need: ``kind`` ("wing", "mill", "winch" or "craft"), the wing
    observation's nominal positions and elements below the wings, the craft's reference thrusts and tensions."""

    sim: Any
    kind: str
    nominal: np.ndarray | None = None
    below: np.ndarray | None = None
    thrust_ref: np.ndarray | None = None
    tension_ref: np.ndarray | None = None

    def output_names(self) -> list[str]:
        if self.kind == "craft":
            return list(CRAFT_OUTPUT_NAMES)
        wings = [f"wing{k}_{n}" for k in range(self.sim.assembly.n_wings) for n in OBS_NAMES]
        return wings + list({"wing": (), "mill": MILL_OUTPUT_NAMES, "winch": WINCH_OUTPUT_NAMES}[self.kind])

    def outputs(self, z: np.ndarray) -> np.ndarray:
        """The outputs at the simulator's current state, time, controls and wind (``z``: its minimal coordinates)."""
        sim = self.sim
        if self.kind == "craft":
            ro = sim.rotor_outputs()
            offset = z[0:3] - self.nominal
            return np.concatenate([offset, z[6:9], z[3:6], z[9:12], ro["thrust_N"] / self.thrust_ref,
                                   sim.tether_tensions() / self.tension_ref, ro["pitch_rad"]])
        y = observe(sim, self.nominal, self.below)
        if self.kind == "mill":
            g = sim.generator_power()
            phase = sim.state[sim.assembly.body_state_size + SX_MOVED] / sim.assembly.station.piece_length
            y = np.concatenate([y, [g["cable_speed_m_s"], phase, g["tension_difference_N"], g["electrical_W"]]])
        elif self.kind == "winch":
            w = sim.winch_power()
            y = np.concatenate([y, [w["tension_N"], w["speed_m_s"], w["electrical_W"]]])
        return y


def _craft_plant(sim: CraftSimulator) -> _Plant:
    """The craft's plant with its references (thrust and tether tension) at the simulator's state and controls."""
    ro = sim.rotor_outputs()
    p = _Plant(sim, "craft", thrust_ref=ro["thrust_N"].copy(), tension_ref=sim.tether_tensions())
    p.nominal = minimal_from_full(sim.assembly, sim.state)[0:3].copy()
    if not (np.all(p.thrust_ref > 0) and np.all(p.tension_ref > 0)):
        raise ValueError(f"craft at x0, u0: the observation's ratios need positive thrusts ({p.thrust_ref} N) and "
                         f"tether tensions ({p.tension_ref} N); give a flying state (craft.trim())")
    return p


def _simulator_plant(system, x0, u0) -> _Plant:
    """The plant of ``system`` (see the module doc) at (x0, u0) (None: the system's own initial state and
    controls); TypeError for anything else."""
    if isinstance(system, Craft | CraftSimulator):
        cfg, asm, layout = system.config, system.assembly, system.layout
        if x0 is None:
            x0 = system.state if isinstance(system, CraftSimulator) else system.trim()
        if u0 is None:
            u0 = system.controls if isinstance(system, CraftSimulator) else np.array([cfg.initial_collective, 0.0])
        return _craft_plant(CraftSimulator(cfg, asm, layout, np.asarray(x0, float), np.asarray(u0, float)))
    if isinstance(system, PumpingScene):
        sim, layout = system.simulator(x0, u0), system.scene.layout
    elif hasattr(system, "simulator") and hasattr(system, "layout"):
        sim, layout = system.simulator(x0, u0), system.layout
    else:
        raise TypeError(f"plant_system: {type(system).__name__} is not a wing scene (load_scene), a craft "
                        "(load_craft or its CraftSimulator) or a pumping config (load_pumping)")
    asm = sim.assembly
    if asm.dim != 3:
        raise ValueError(f"scene {getattr(system, 'name', '?')}: the plant needs a 3D scene (dimension = {asm.dim})")
    kind = "wing" if asm.station is None else ("winch" if isinstance(sim, WinchSimulator) else "mill")
    return _Plant(sim, kind, nominal=sim.wing_positions(), below=elements_below_wings(layout, asm.n_wings))


def plant_system(system, x0: np.ndarray | None = None, u0: np.ndarray | None = None, outputs: str = "observation",
                 name: str | None = None):
    """``control.nlsys`` of ``system`` (a wing scene or the mill, a craft, a pumping config: module doc) about the
    operating point (x0 full state, u0 controls; None: the system's initial state, the craft's trim, and controls)
    in minimal coordinates, with named states, inputs (controls, then :data:`DISTURBANCE_NAMES`) and outputs (the
    observation, or the states with ``outputs="states"``).

    Returns the system; ``plant.z0`` (the states at x0) and ``plant.u0`` (controls then zero disturbances) are
    attached for ``control.linearize(plant, plant.z0, plant.u0, copy_names=True)``.
    """
    import control

    if outputs not in ("observation", "states"):
        raise ValueError(f"outputs = {outputs!r}: 'observation' or 'states'")
    p = _simulator_plant(system, x0, u0)
    sim = p.sim
    asm = sim.assembly
    x_op, u_op = sim.state.copy(), sim.controls.copy()
    nb, nc = asm.body_state_size, sim.n_controls
    base_model = sim.model

    def _set(z, u, params):
        k = _parameters(params)
        z, u = np.asarray(z, dtype=float).reshape(-1), np.asarray(u, dtype=float).reshape(-1)
        sim.model = with_steady_wind(base_model, k * (1.0 + u[nc]), u[nc + 1])
        n_min = z.size - (asm.state_size - nb)
        return full_from_minimal(asm, z[:n_min], z[n_min:]), u[:nc]

    def updfcn(t, z, u, params=None):
        x, uc = _set(z, u, params)
        try:
            dx = sim.rhs(t, x, uc)
            return np.concatenate([minimal_derivative(asm, x, dx), dx[nb:]])
        finally:
            sim.model = base_model

    def outfcn(t, z, u, params=None):
        if outputs == "states":
            return np.asarray(z, dtype=float).copy()
        x, uc = _set(z, u, params)
        saved = (sim.state, sim.t, sim.controls)
        sim.state, sim.t, sim.controls = x, float(t), uc
        try:
            return p.outputs(np.asarray(z, dtype=float).reshape(-1))
        finally:
            sim.model = base_model
            sim.state, sim.t, sim.controls = saved

    states = state_labels(asm) + list(STATION_STATE_NAMES[: asm.state_size - nb])
    out_names = states if outputs == "states" else p.output_names()
    default = {"craft": "rotorcraft", "mill": "laddermill", "winch": "pumping_kite"}.get(p.kind, "wing_scene")
    plant = control.nlsys(updfcn, outfcn, states=states, inputs=list(sim.control_labels) + list(DISTURBANCE_NAMES),
                          outputs=out_names, name=name or default, params={})
    plant.z0 = np.concatenate([minimal_from_full(asm, x_op), x_op[nb:]])
    plant.u0 = np.concatenate([u_op, np.zeros(len(DISTURBANCE_NAMES))])
    return plant
