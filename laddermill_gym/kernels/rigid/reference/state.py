"""State access of the reference model: slices of the state vector, degree-of-freedom offsets, and the
kinematics and velocity transformation of a cable element's end (wing, free node or fixed point).

Generalised velocities: per wing ``(v, omega)`` in body axes (6 dof, wing ``k`` at dof ``6 k``), then per free
node its global velocity (3 dof, node ``j`` at dof ``6 n_w + 3 j``). State: per wing ``[x(3), q(4), v(3),
omega(3)]`` (13 floats at ``13 k``), then per node ``[position(3), velocity(3)]`` (6 floats at ``13 n_w + 6 j``).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.rigid.reference.rotations import rotation, skew
from laddermill_gym.model.params import END_FIXED, END_NODE, END_WING, Assembly


def check_dim(asm: Assembly) -> None:
    if asm.dim != 3:
        raise ValueError(f"reference implementation supports only Assembly.dim == 3, got dim={asm.dim}")


def wing_state(asm: Assembly, x: np.ndarray, k: int):
    """(position, q, v, omega) of wing ``k`` (views into the state)."""
    o = 13 * k
    return x[o : o + 3], x[o + 3 : o + 7], x[o + 7 : o + 10], x[o + 10 : o + 13]


def node_state(asm: Assembly, x: np.ndarray, j: int):
    """(position, velocity) of free node ``j``."""
    o = 13 * asm.n_wings + 6 * j
    return x[o : o + 3], x[o + 3 : o + 6]


def n_dof(asm: Assembly) -> int:
    return 6 * asm.n_wings + 3 * asm.n_nodes


def wing_dof(k: int) -> int:
    return 6 * k


def node_dof(asm: Assembly, j: int) -> int:
    return 6 * asm.n_wings + 3 * j


def end_kinematics(asm: Assembly, e: int, end: int, x: np.ndarray):
    """Position, velocity and the quadratic acceleration term of one element end (global).

    Returns
    -------
    position, velocity, accel_quadratic : ndarray, shape (3,)
        ``accel_quadratic`` is ``R [w x (v + w x a)]`` for a wing end and 0 otherwise.
    """
    el = asm.elements
    kind = int(el.end_kind[e, end])
    idx = int(el.end_index[e, end])
    if kind == END_WING:
        pos, q, v, w = wing_state(asm, x, idx)
        R = rotation(q)
        a = np.asarray(el.attach[e, end], dtype=float)
        position = pos + R @ a
        velocity = R @ (v + np.cross(w, a))
        accel_quadratic = R @ np.cross(w, v + np.cross(w, a))
        return position, velocity, accel_quadratic
    if kind == END_NODE:
        pos, vel = node_state(asm, x, idx)
        return pos.copy(), vel.copy(), np.zeros(3)
    if kind == END_FIXED:
        return np.asarray(asm.fixed_points[idx], dtype=float).copy(), np.zeros(3), np.zeros(3)
    raise ValueError(f"elements.end_kind[{e}, {end}] = {kind} is not END_WING, END_NODE or END_FIXED")


def end_transformation(asm: Assembly, e: int, end: int, x: np.ndarray) -> np.ndarray:
    """Matrix ``T_end`` (3 x n_dof) mapping generalised velocities to the end's global velocity.

    A wing end has ``(R, -R a~)`` in the wing's (v, omega) columns, a node end the identity in the
    node's columns, a fixed end is all zeros.
    """
    el = asm.elements
    kind = int(el.end_kind[e, end])
    idx = int(el.end_index[e, end])
    T = np.zeros((3, n_dof(asm)))
    if kind == END_WING:
        _, q, _, _ = wing_state(asm, x, idx)
        R = rotation(q)
        a = np.asarray(el.attach[e, end], dtype=float)
        d = wing_dof(idx)
        T[:, d : d + 3] = R
        T[:, d + 3 : d + 6] = -R @ skew(a)
    elif kind == END_NODE:
        d = node_dof(asm, idx)
        T[:, d : d + 3] = np.eye(3)
    elif kind != END_FIXED:
        raise ValueError(f"elements.end_kind[{e}, {end}] = {kind} is not END_WING, END_NODE or END_FIXED")
    return T
