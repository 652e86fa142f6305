"""Per-wing observation layout and its computation from a raw simulator state.

Every wing contributes the 15 entries of :data:`OBS_FIELDS`, in that order; wings are concatenated in
chain order (wing 0 first). The layout is a public contract (controllers index it by name through
:data:`OBS_INDEX`); change it only together with the env ids' version.

The quantities are computed here directly from the state vector (quaternion algebra vectorised over
wings), not through :class:`~laddermill_gym.sim.simulator.Simulator`'s per-wing views, so the tests can use
those views as an independent check.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.atmosphere.wind_kernels import modulation, wind_at
from laddermill_gym.kernels.contract import (
    B2_Q,
    B2_SIZE,
    B2_THETA,
    B2_U,
    B2_W,
    B2_X,
    B2_Z,
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    TM_DT,
    TM_T0,
)
from laddermill_gym.ladder.scene import Scene
from laddermill_gym.sim.simulator import Simulator


@dataclass(frozen=True)
class ObsField:
    """One per-wing observation entry: its name, SI unit and meaning."""

    name: str
    unit: str
    description: str


#: Per-wing observation entries, in order.
OBS_FIELDS: tuple[ObsField, ...] = (
    ObsField("dx", "m", "CG x (north, upwind) relative to the nominal (initial equilibrium) position"),
    ObsField("dy", "m", "CG y (east) relative to the nominal position"),
    ObsField("dz", "m", "CG z (down) relative to the nominal position"),
    ObsField("vx", "m/s", "CG velocity, global x"),
    ObsField("vy", "m/s", "CG velocity, global y"),
    ObsField("vz", "m/s", "CG velocity, global z (down)"),
    ObsField("phi", "rad", "roll angle (3-2-1 Euler)"),
    ObsField("theta", "rad", "pitch angle (3-2-1 Euler)"),
    ObsField("psi", "rad", "yaw angle (3-2-1 Euler)"),
    ObsField("p", "rad/s", "roll rate, body x"),
    ObsField("q", "rad/s", "pitch rate, body y"),
    ObsField("r", "rad/s", "yaw rate, body z"),
    ObsField("alpha", "rad", "angle of attack of the CG air velocity, atan2(w_a, u_a)"),
    ObsField("beta", "rad", "sideslip of the CG air velocity, asin(v_a / |V_a|)"),
    ObsField("tension", "N", "tension of the cable element below the wing (towards the start ground point)"),
)
#: Number of observation entries per wing.
N_OBS_PER_WING = len(OBS_FIELDS)
#: Field name -> index within a wing's block.
OBS_INDEX: dict[str, int] = {f.name: i for i, f in enumerate(OBS_FIELDS)}


def observation_names(n_wings: int) -> list[str]:
    """Flat observation labels, e.g. ``'wing 3 alpha [rad]'``, length ``n_wings * N_OBS_PER_WING``."""
    return [f"wing {k} {f.name} [{f.unit}]" for k in range(n_wings) for f in OBS_FIELDS]


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


@dataclass(frozen=True)
class WingKinematics:
    """Kinematics of all wings, arrays over wings (n = n_wings).

    position (n, 3) [m] global CG; rotation (n, 3, 3) body -> global; euler (n, 3) [rad] (phi, theta, psi);
    velocity_body (n, 3) [m/s]; velocity (n, 3) [m/s] global; rates (n, 3) [rad/s] body (p, q, r).
    """

    position: np.ndarray
    rotation: np.ndarray
    euler: np.ndarray
    velocity_body: np.ndarray
    velocity: np.ndarray
    rates: np.ndarray


def _rotation_from_quaternions(quat: np.ndarray) -> np.ndarray:
    """Body -> global rotation matrices (n, 3, 3) of scalar-first quaternions (n, 4) (normalised here)."""
    qn = quat / np.linalg.norm(quat, axis=1, keepdims=True)
    a, b, c, d = qn[:, 0], qn[:, 1], qn[:, 2], qn[:, 3]
    rot = np.empty((len(qn), 3, 3))
    rot[:, 0, 0] = a * a + b * b - c * c - d * d
    rot[:, 0, 1] = 2.0 * (b * c - a * d)
    rot[:, 0, 2] = 2.0 * (b * d + a * c)
    rot[:, 1, 0] = 2.0 * (b * c + a * d)
    rot[:, 1, 1] = a * a - b * b + c * c - d * d
    rot[:, 1, 2] = 2.0 * (c * d - a * b)
    rot[:, 2, 0] = 2.0 * (b * d - a * c)
    rot[:, 2, 1] = 2.0 * (c * d + a * b)
    rot[:, 2, 2] = a * a - b * b - c * c + d * d
    return rot


def _rotation_about_y(theta: np.ndarray) -> np.ndarray:
    ct, st = np.cos(theta), np.sin(theta)
    rot = np.zeros((len(theta), 3, 3))
    rot[:, 0, 0] = ct
    rot[:, 0, 2] = st
    rot[:, 1, 1] = 1.0
    rot[:, 2, 0] = -st
    rot[:, 2, 2] = ct
    return rot


def wing_kinematics(state: np.ndarray, dim: int, n_wings: int) -> WingKinematics:
    """Wing kinematics from a raw state vector (3D: 13 floats per wing; in-plane: 6, embedded in 3D)."""
    if dim == 3:
        w = state[: B3_SIZE * n_wings].reshape(n_wings, B3_SIZE)
        pos = w[:, B3_POS: B3_POS + 3].copy()
        rot = _rotation_from_quaternions(w[:, B3_QUAT: B3_QUAT + 4])
        vb = w[:, B3_VEL: B3_VEL + 3].copy()
        rates = w[:, B3_RATE: B3_RATE + 3].copy()
        euler = np.stack([np.arctan2(rot[:, 2, 1], rot[:, 2, 2]),
                          -np.arcsin(np.clip(rot[:, 2, 0], -1.0, 1.0)),
                          np.arctan2(rot[:, 1, 0], rot[:, 0, 0])], axis=1)
    else:
        w = state[: B2_SIZE * n_wings].reshape(n_wings, B2_SIZE)
        zeros = np.zeros(n_wings)
        pos = np.stack([w[:, B2_X], zeros, w[:, B2_Z]], axis=1)
        rot = _rotation_about_y(w[:, B2_THETA])
        vb = np.stack([w[:, B2_U], zeros, w[:, B2_W]], axis=1)
        rates = np.stack([zeros, w[:, B2_Q], zeros], axis=1)
        euler = np.stack([zeros, w[:, B2_THETA], zeros], axis=1)
    vel = np.einsum("nij,nj->ni", rot, vb)
    return WingKinematics(position=pos, rotation=rot, euler=euler, velocity_body=vb, velocity=vel, rates=rates)


def wind_at_points(sim: Simulator, t: float, positions: np.ndarray) -> np.ndarray:
    """Wind velocity (n, 3) [m/s], global, at the given points (n, 3) [m] and time t [s], from the wind
    model (profile, direction and time modulation) the simulator was built with."""
    m = sim.model
    s, d, _, _ = modulation(float(t), m.tmod[TM_T0], m.tmod[TM_DT], m.ms, m.md)
    out = np.empty((len(positions), 3))
    for k in range(len(positions)):
        out[k] = wind_at(float(positions[k, 2]), m.wf, s, d)
    return out


def wing_observations(sim: Simulator, kin: WingKinematics, nominal_position: np.ndarray,
                      tensions: np.ndarray, local_element: np.ndarray) -> np.ndarray:
    """Observation rows (n_wings, N_OBS_PER_WING), float64, in :data:`OBS_FIELDS` order.

    Parameters
    ----------
    sim : Simulator
        Supplies the wind model and the time ``sim.t`` [s].
    kin : WingKinematics
        Kinematics of the state being observed.
    nominal_position : ndarray, shape (n_wings, 3)
        CG positions the offsets are taken from [m].
    tensions : ndarray, shape (n_elements,)
        Element tensions [N] of the same state.
    local_element : int ndarray, shape (n_wings,)
        Index of the element below each wing.
    """
    wind = wind_at_points(sim, sim.t, kin.position)
    air = kin.velocity_body - np.einsum("nji,nj->ni", kin.rotation, wind)  # R^T w
    speed = np.maximum(np.linalg.norm(air, axis=1), 1e-300)
    alpha = np.arctan2(air[:, 2], air[:, 0])
    beta = np.arcsin(np.clip(air[:, 1] / speed, -1.0, 1.0))
    return np.column_stack([kin.position - nominal_position, kin.velocity, kin.euler, kin.rates,
                            alpha, beta, tensions[local_element]])
