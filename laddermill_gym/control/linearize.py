"""Linearisation of the simulator at a trim point in minimal coordinates.

The simulator's state stores each wing's attitude as a quaternion (4 numbers, 3 degrees of freedom) and its
velocity in body axes. A linear model for control wants one coordinate per degree of freedom and the variables
the observations carry, so this module wraps :meth:`Simulator.rhs` in a change of coordinates:

* per wing (12): CG position (x, y, z) [m], 3-2-1 Euler angles (phi, theta, psi) [rad], global CG velocity
  (vx, vy, vz) [m/s], body rates (p, q, r) [rad/s];
* per free cable node (6): position (x, y, z) [m], velocity (vx, vy, vz) [m/s] (already minimal).

Minimal state -> full state: q = quaternion(phi, theta, psi), v_body = R^T v_global. Full derivative ->
minimal derivative: position' = R v_body (the simulator's own), (phi, theta, psi)' = A(phi, theta) (p, q, r)
(Meijaard eq. 6), v_global' = R (v_body' + omega x v_body), rates' as computed. The wrapped function has
python-control's ``updfcn`` signature, so ``control.nlsys`` + ``control.linearize`` give (A, B).

Longitudinal / lateral split: per wing the longitudinal states are (x, z, theta, vx, vz, q) and the
lateral ones (y, vy, phi, psi, p, r) (per node (x, z, vx, vz) and (y, vy)); the elevator is longitudinal,
rudder and aileron lateral. At a trim that is mirror-symmetric about the x-z plane (wind along x, no
direction turn, symmetric wing and attachment, phi = psi = y = 0) the coupling blocks A[lat, lon],
A[lon, lat], B[lat, elevator], B[lon, (rudder, aileron)] vanish (mirror symmetry maps lateral
perturbations to their negatives and leaves longitudinal ones unchanged, so a first-order effect of one
on the other must be zero); :func:`coupling_norms` measures them.
"""

from __future__ import annotations

from dataclasses import dataclass

import control
import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL, N3_SIZE
from laddermill_gym.model.params import N_CONTROLS, Assembly
from laddermill_gym.sim.simulator import Simulator

__all__ = [
    "WING_MINIMAL_NAMES",
    "NODE_MINIMAL_NAMES",
    "WING_LATERAL",
    "WING_LONGITUDINAL",
    "NODE_LATERAL",
    "NODE_LONGITUDINAL",
    "LATERAL_INPUTS",
    "LONGITUDINAL_INPUTS",
    "Linearization",
    "minimal_size",
    "minimal_from_full",
    "full_from_minimal",
    "minimal_derivative",
    "minimal_rhs",
    "minimal_system",
    "linearize",
    "lateral_indices",
    "longitudinal_indices",
    "lateral_subsystem",
    "coupling_norms",
    "wing_lateral_blocks",
]

#: Minimal coordinates of one wing, in order (units: m, rad, m/s, rad/s).
WING_MINIMAL_NAMES: tuple[str, ...] = ("x", "y", "z", "phi", "theta", "psi", "vx", "vy", "vz", "p", "q", "r")
#: Minimal coordinates of one free cable node (units: m, m/s).
NODE_MINIMAL_NAMES: tuple[str, ...] = ("x", "y", "z", "vx", "vy", "vz")
#: Positions in a wing's 12 minimal coordinates of the lateral states (y, vy, phi, psi, p, r).
WING_LATERAL: tuple[int, ...] = (1, 7, 3, 5, 9, 11)
#: Positions of the longitudinal states (x, z, theta, vx, vz, q).
WING_LONGITUDINAL: tuple[int, ...] = (0, 2, 4, 6, 8, 10)
#: Positions in a node's 6 coordinates of its lateral (y, vy) and longitudinal (x, z, vx, vz) states.
NODE_LATERAL: tuple[int, ...] = (1, 4)
NODE_LONGITUDINAL: tuple[int, ...] = (0, 2, 3, 5)
#: Positions in a wing's 3 controls of the lateral (rudder, aileron) and longitudinal (elevator) inputs.
LATERAL_INPUTS: tuple[int, ...] = (1, 2)
LONGITUDINAL_INPUTS: tuple[int, ...] = (0,)

_WM, _NM = len(WING_MINIMAL_NAMES), len(NODE_MINIMAL_NAMES)


def _check_3d(asm: Assembly) -> None:
    if asm.dim != 3:
        raise ValueError(f"minimal coordinates need a 3D assembly, got dim = {asm.dim}")


def minimal_size(asm: Assembly) -> int:
    """Number of minimal coordinates: 12 per wing + 6 per free node."""
    _check_3d(asm)
    return _WM * asm.n_wings + _NM * asm.n_nodes


# ------------------------------------------------------------------------ batched rotation helpers
def _rotations(euler: np.ndarray) -> np.ndarray:
    """R = Rz(psi) Ry(theta) Rx(phi) for each row (phi, theta, psi) of ``euler`` (n, 3) -> (n, 3, 3)."""
    cf, sf = np.cos(euler[:, 0]), np.sin(euler[:, 0])
    ct, st = np.cos(euler[:, 1]), np.sin(euler[:, 1])
    cp, sp = np.cos(euler[:, 2]), np.sin(euler[:, 2])
    R = np.empty((len(euler), 3, 3))
    R[:, 0, 0] = ct * cp
    R[:, 0, 1] = sf * st * cp - cf * sp
    R[:, 0, 2] = cf * st * cp + sf * sp
    R[:, 1, 0] = ct * sp
    R[:, 1, 1] = sf * st * sp + cf * cp
    R[:, 1, 2] = cf * st * sp - sf * cp
    R[:, 2, 0] = -st
    R[:, 2, 1] = sf * ct
    R[:, 2, 2] = cf * ct
    return R


def _quaternions(euler: np.ndarray) -> np.ndarray:
    """Unit quaternions (scalar first) of the 3-2-1 Euler angles, (n, 3) -> (n, 4)."""
    c1, s1 = np.cos(euler[:, 0] / 2), np.sin(euler[:, 0] / 2)
    c2, s2 = np.cos(euler[:, 1] / 2), np.sin(euler[:, 1] / 2)
    c3, s3 = np.cos(euler[:, 2] / 2), np.sin(euler[:, 2] / 2)
    return np.stack([c3 * c2 * c1 + s3 * s2 * s1, c3 * c2 * s1 - s3 * s2 * c1,
                     c3 * s2 * c1 + s3 * c2 * s1, s3 * c2 * c1 - c3 * s2 * s1], axis=1)


def euler_from_quaternions(q: np.ndarray) -> np.ndarray:
    """3-2-1 Euler angles (phi, theta, psi) of the (normalised) quaternions (n, 4) -> (n, 3)."""
    a, b, c, d = (q / np.linalg.norm(q, axis=1, keepdims=True)).T
    r32 = 2 * (c * d + a * b)
    r33 = a * a - b * b - c * c + d * d
    r31 = 2 * (b * d - a * c)
    r21 = 2 * (b * c + a * d)
    r11 = a * a + b * b - c * c - d * d
    return np.stack([np.arctan2(r32, r33), -np.arcsin(np.clip(r31, -1.0, 1.0)), np.arctan2(r21, r11)], axis=1)


# ------------------------------------------------------------------------ coordinate maps
def minimal_from_full(asm: Assembly, x: np.ndarray) -> np.ndarray:
    """Minimal coordinates (see module docstring) of a full simulator state ``x`` (shape (n_state,))."""
    _check_3d(asm)
    x = np.asarray(x, dtype=float)
    nw, nn = asm.n_wings, asm.n_nodes
    w = x[: B3_SIZE * nw].reshape(nw, B3_SIZE)
    euler = euler_from_quaternions(w[:, B3_QUAT: B3_QUAT + 4])
    R = _rotations(euler)
    z = np.empty((nw, _WM))
    z[:, 0:3] = w[:, B3_POS: B3_POS + 3]
    z[:, 3:6] = euler
    z[:, 6:9] = np.einsum("nij,nj->ni", R, w[:, B3_VEL: B3_VEL + 3])
    z[:, 9:12] = w[:, B3_RATE: B3_RATE + 3]
    return np.concatenate([z.reshape(-1), x[B3_SIZE * nw: B3_SIZE * nw + N3_SIZE * nn]])


def full_from_minimal(asm: Assembly, z: np.ndarray, tail: np.ndarray | None = None) -> np.ndarray:
    """Full simulator state (unit quaternions, body velocities) of minimal coordinates ``z``.

    ``tail``: the state entries after the bodies (a moving cable's station block ``SX_*``, held as given; the
    minimal coordinates cover the bodies only). Required when the assembly has a station."""
    _check_3d(asm)
    tail = _station_tail(asm, tail)
    z = np.asarray(z, dtype=float)
    nw, nn = asm.n_wings, asm.n_nodes
    zw = z[: _WM * nw].reshape(nw, _WM)
    R = _rotations(zw[:, 3:6])
    w = np.empty((nw, B3_SIZE))
    w[:, B3_POS: B3_POS + 3] = zw[:, 0:3]
    w[:, B3_QUAT: B3_QUAT + 4] = _quaternions(zw[:, 3:6])
    w[:, B3_VEL: B3_VEL + 3] = np.einsum("nji,nj->ni", R, zw[:, 6:9])  # R^T v_global
    w[:, B3_RATE: B3_RATE + 3] = zw[:, 9:12]
    return np.concatenate([w.reshape(-1), z[_WM * nw: _WM * nw + _NM * nn], tail])


def _station_tail(asm: Assembly, tail: np.ndarray | None) -> np.ndarray:
    """The state block after the bodies (empty without a station); ValueError if a station's is missing."""
    n_tail = asm.state_size - asm.body_state_size
    if n_tail == 0:
        return np.zeros(0)
    if tail is None or np.shape(tail) != (n_tail,):
        raise ValueError(f"the assembly has a station: its {n_tail} state entries after the bodies must be given "
                         f"as tail (got {None if tail is None else np.shape(tail)})")
    return np.asarray(tail, dtype=float)


def minimal_derivative(asm: Assembly, x: np.ndarray, dx: np.ndarray) -> np.ndarray:
    """Time derivative of the minimal coordinates from a full state ``x`` and its derivative ``dx``.

    Notes
    -----
    Per wing: position' = dx[B3_POS: B3_POS + 3]; (phi, theta, psi)' = A(phi, theta) omega with
    A = [[1, sin(phi) tan(theta), cos(phi) tan(theta)], [0, cos(phi), -sin(phi)],
    [0, sin(phi)/cos(theta), cos(phi)/cos(theta)]]; v_global' = R (v' + omega x v);
    omega' = dx[B3_RATE: B3_RATE + 3].
    """
    _check_3d(asm)
    x, dx = np.asarray(x, dtype=float), np.asarray(dx, dtype=float)
    nw, nn = asm.n_wings, asm.n_nodes
    w = x[: B3_SIZE * nw].reshape(nw, B3_SIZE)
    dw = dx[: B3_SIZE * nw].reshape(nw, B3_SIZE)
    euler = euler_from_quaternions(w[:, B3_QUAT: B3_QUAT + 4])
    R = _rotations(euler)
    phi, theta = euler[:, 0], euler[:, 1]
    p, q, r = w[:, B3_RATE], w[:, B3_RATE + 1], w[:, B3_RATE + 2]
    sf, cf, tt, ct = np.sin(phi), np.cos(phi), np.tan(theta), np.cos(theta)
    dz = np.empty((nw, _WM))
    dz[:, 0:3] = dw[:, B3_POS: B3_POS + 3]
    dz[:, 3] = p + sf * tt * q + cf * tt * r
    dz[:, 4] = cf * q - sf * r
    dz[:, 5] = (sf * q + cf * r) / ct
    vb, om = w[:, B3_VEL: B3_VEL + 3], w[:, B3_RATE: B3_RATE + 3]
    dz[:, 6:9] = np.einsum("nij,nj->ni", R, dw[:, B3_VEL: B3_VEL + 3] + np.cross(om, vb))
    dz[:, 9:12] = dw[:, B3_RATE: B3_RATE + 3]
    return np.concatenate([dz.reshape(-1), dx[B3_SIZE * nw: B3_SIZE * nw + N3_SIZE * nn]])


def minimal_rhs(sim: Simulator, rhs=None, tail: np.ndarray | None = None):
    """The dynamics in minimal coordinates, ``f(t, z, u, params) -> dz/dt`` (python-control ``updfcn``).

    Parameters
    ----------
    sim : Simulator
        A 3D simulator (its compiled right-hand side is wrapped).
    rhs : callable, optional
        ``rhs(t, x, u) -> dx`` to wrap instead of ``sim.rhs`` (e.g. the numpy reference, for tests).
    tail : ndarray, optional
        A moving cable's station state (held fixed: the bodies' dynamics at a frozen cable phase and speed).
    """
    asm = sim.assembly
    _check_3d(asm)
    full_rhs = sim.rhs if rhs is None else rhs
    tail = _station_tail(asm, tail)

    def updfcn(t, z, u, params=None):
        x = full_from_minimal(asm, z, tail)
        return minimal_derivative(asm, x, full_rhs(t, x, np.asarray(u, dtype=float).reshape(-1)))

    return updfcn


def state_labels(asm: Assembly) -> list[str]:
    labels = [f"wing{k}_{n}" for k in range(asm.n_wings) for n in WING_MINIMAL_NAMES]
    return labels + [f"node{j}_{n}" for j in range(asm.n_nodes) for n in NODE_MINIMAL_NAMES]


def minimal_system(sim: Simulator, name: str = "laddermill", tail: np.ndarray | None = None
                   ) -> control.NonlinearIOSystem:
    """``control.nlsys`` of the minimal-coordinate dynamics with labelled states and inputs; the outputs
    are the states (``tail``: see :func:`minimal_rhs`)."""
    asm = sim.assembly
    return control.nlsys(minimal_rhs(sim, tail=tail), None, states=state_labels(asm), inputs=sim.control_labels,
                         outputs=state_labels(asm), name=name)


# ------------------------------------------------------------------------ linear models
@dataclass(frozen=True)
class Linearization:
    """A linear model dz' = A dz + B du about (z0, u0) in minimal coordinates.

    Attributes
    ----------
    A : ndarray (n, n)          [1/s, per unit of each state]
    B : ndarray (n, m)          [per rad of each control]
    z0 : ndarray (n,)           operating point, minimal coordinates
    u0 : ndarray (m,)           operating controls [rad]
    x0 : ndarray (n_state,)     operating point, full simulator state
    state_names, input_names : tuple of str
    n_wings, n_nodes : int
    residual : float            max |dz/dt| at the operating point (0 at an exact trim)
    """

    A: np.ndarray
    B: np.ndarray
    z0: np.ndarray
    u0: np.ndarray
    x0: np.ndarray
    state_names: tuple[str, ...]
    input_names: tuple[str, ...]
    n_wings: int
    n_nodes: int
    residual: float

    def statespace(self) -> control.StateSpace:
        """The continuous-time model as a labelled ``control.StateSpace`` (outputs = states)."""
        n = self.A.shape[0]
        return control.ss(self.A, self.B, np.eye(n), np.zeros((n, self.B.shape[1])),
                          states=list(self.state_names), inputs=list(self.input_names),
                          outputs=list(self.state_names))


def linearize(sim: Simulator, x0: np.ndarray, u0: np.ndarray, t: float = 0.0, eps: float = 1e-6) -> Linearization:
    """Linearise the simulator at the full state ``x0`` and controls ``u0`` [rad] in minimal coordinates.

    Uses ``control.nlsys`` + ``control.linearize`` (forward differences of step ``eps`` in every minimal
    coordinate and input). For the ladder chain use :func:`wing_lateral_blocks`, which needs only the
    columns of each wing's own lateral states.

    Returns
    -------
    Linearization
    """
    asm = sim.assembly
    x0 = np.asarray(x0, dtype=float)
    sys = minimal_system(sim, tail=x0[asm.body_state_size:])
    z0 = minimal_from_full(asm, x0)
    u0 = np.asarray(u0, dtype=float).reshape(-1)
    lin = control.linearize(sys, z0, u0, t=t, eps=eps, copy_names=True)  # names kept (python-control drops them)
    residual = float(np.max(np.abs(sys.updfcn(t, z0, u0, {})))) if z0.size else 0.0
    return Linearization(A=np.asarray(lin.A), B=np.asarray(lin.B), z0=z0, u0=u0,
                         x0=np.asarray(x0, dtype=float).copy(), state_names=tuple(state_labels(asm)),
                         input_names=tuple(sim.control_labels), n_wings=asm.n_wings, n_nodes=asm.n_nodes,
                         residual=residual)


def lateral_indices(n_wings: int, n_nodes: int) -> np.ndarray:
    """Minimal-coordinate indices of the lateral states: per wing (y, vy, phi, psi, p, r), per node (y, vy)."""
    idx = [_WM * k + i for k in range(n_wings) for i in WING_LATERAL]
    idx += [_WM * n_wings + _NM * j + i for j in range(n_nodes) for i in NODE_LATERAL]
    return np.array(idx, dtype=np.int64)


def longitudinal_indices(n_wings: int, n_nodes: int) -> np.ndarray:
    """Indices of the longitudinal states: per wing (x, z, theta, vx, vz, q), per node (x, z, vx, vz)."""
    idx = [_WM * k + i for k in range(n_wings) for i in WING_LONGITUDINAL]
    idx += [_WM * n_wings + _NM * j + i for j in range(n_nodes) for i in NODE_LONGITUDINAL]
    return np.array(idx, dtype=np.int64)


def _input_indices(n_wings: int, which: tuple[int, ...]) -> np.ndarray:
    return np.array([N_CONTROLS * k + i for k in range(n_wings) for i in which], dtype=np.int64)


def lateral_subsystem(lin: Linearization) -> tuple[np.ndarray, np.ndarray, tuple[str, ...], tuple[str, ...]]:
    """(A_lat, B_lat, state names, input names): the lateral rows and columns of ``lin`` (states per wing
    y, vy, phi, psi, p, r then per node y, vy; inputs per wing rudder, aileron)."""
    s = lateral_indices(lin.n_wings, lin.n_nodes)
    i = _input_indices(lin.n_wings, LATERAL_INPUTS)
    return (lin.A[np.ix_(s, s)], lin.B[np.ix_(s, i)], tuple(lin.state_names[j] for j in s),
            tuple(lin.input_names[j] for j in i))


def coupling_norms(lin: Linearization) -> dict[str, float]:
    """Size of the longitudinal-lateral coupling blocks relative to the matrix they sit in.

    Returns max |entry| of each coupling block divided by max |entry| of the whole A (or B):
    ``A_lat_lon`` (lateral rows, longitudinal columns), ``A_lon_lat``, ``B_lat_elevator``,
    ``B_lon_lateral_inputs``. At a mirror-symmetric trim all four are at the level of the
    finite-difference noise.
    """
    lat = lateral_indices(lin.n_wings, lin.n_nodes)
    lon = longitudinal_indices(lin.n_wings, lin.n_nodes)
    ilat = _input_indices(lin.n_wings, LATERAL_INPUTS)
    ilon = _input_indices(lin.n_wings, LONGITUDINAL_INPUTS)
    a_scale = float(np.max(np.abs(lin.A)))
    b_scale = float(np.max(np.abs(lin.B)))
    return {
        "A_lat_lon": float(np.max(np.abs(lin.A[np.ix_(lat, lon)]))) / a_scale,
        "A_lon_lat": float(np.max(np.abs(lin.A[np.ix_(lon, lat)]))) / a_scale,
        "B_lat_elevator": float(np.max(np.abs(lin.B[np.ix_(lat, ilon)]))) / b_scale,
        "B_lon_lateral_inputs": float(np.max(np.abs(lin.B[np.ix_(lon, ilat)]))) / b_scale,
    }


def wing_lateral_blocks(sim: Simulator, x0: np.ndarray, u0: np.ndarray, t: float = 0.0,
                        eps: float = 1e-6) -> tuple[np.ndarray, np.ndarray]:
    """Per-wing lateral models of a chain: the diagonal blocks of the full minimal-coordinate Jacobian.

    For wing k, A_k (6 x 6) = d(lateral state derivatives of wing k) / d(lateral states of wing k) and
    B_k (6 x 2) = d(...)/d(rudder_k, aileron_k), all other wings' and nodes' states and controls held at the
    operating point. Central differences over only those 8 columns per wing (16 right-hand sides per
    wing instead of two per coordinate of the whole chain).

    Returns
    -------
    A_blocks : ndarray (n_wings, 6, 6)
    B_blocks : ndarray (n_wings, 6, 2)
    """
    asm = sim.assembly
    x0 = np.asarray(x0, dtype=float)
    f = minimal_rhs(sim, tail=x0[asm.body_state_size:])
    z0 = minimal_from_full(asm, x0)
    u0 = np.asarray(u0, dtype=float).reshape(-1)
    nw = asm.n_wings
    lat = np.array(WING_LATERAL)
    A = np.zeros((nw, len(lat), len(lat)))
    B = np.zeros((nw, len(lat), len(LATERAL_INPUTS)))
    for k in range(nw):
        rows = _WM * k + lat
        for c, j in enumerate(rows):
            zp, zm = z0.copy(), z0.copy()
            zp[j] += eps
            zm[j] -= eps
            A[k, :, c] = (f(t, zp, u0)[rows] - f(t, zm, u0)[rows]) / (2 * eps)
        for c, i in enumerate(LATERAL_INPUTS):
            up, um = u0.copy(), u0.copy()
            up[N_CONTROLS * k + i] += eps
            um[N_CONTROLS * k + i] -= eps
            B[k, :, c] = (f(t, z0, up)[rows] - f(t, z0, um)[rows]) / (2 * eps)
    return A, B
