"""State access of the reference model: slices of the state vector, degree-of-freedom offsets, and the
kinematics and velocity transformation of a cable element's end (wing, free node or fixed point).

Generalised velocities: per wing ``(v, omega)`` in body axes (6 dof, wing ``k`` at dof ``6 k``), then per free
node its global velocity (3 dof, node ``j`` at dof ``6 n_w + 3 j``). State: per wing ``[x(3), q(4), v(3),
omega(3)]`` (``B3_SIZE`` = 13 floats at ``B3_SIZE k``), then per node ``[position(3), velocity(3)]`` (``N3_SIZE`` =
6 floats after the wings); the slot names of ``kernels/contract.py``, the physics written independently.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import (
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    DOF_B3,
    DOF_N3,
    N3_POS,
    N3_SIZE,
    N3_VEL,
)
from laddermill_gym.model.params import END_FIXED, END_NODE, END_WING, Assembly
from laddermill_gym.reference.rotations import rotation, skew


def check_dim(asm: Assembly) -> None:
    if asm.dim != 3:
        raise ValueError(f"reference implementation supports only Assembly.dim == 3, got dim={asm.dim}")


def wing_state(asm: Assembly, x: np.ndarray, k: int):
    """(position, q, v, omega) of wing ``k`` (views into the state)."""
    o = B3_SIZE * k
    return (x[o + B3_POS: o + B3_POS + 3], x[o + B3_QUAT: o + B3_QUAT + 4], x[o + B3_VEL: o + B3_VEL + 3],
            x[o + B3_RATE: o + B3_RATE + 3])


def node_state(asm: Assembly, x: np.ndarray, j: int):
    """(position, velocity) of free node ``j``."""
    o = B3_SIZE * asm.n_wings + N3_SIZE * j
    return x[o + N3_POS: o + N3_POS + 3], x[o + N3_VEL: o + N3_VEL + 3]


def n_dof(asm: Assembly) -> int:
    return DOF_B3 * asm.n_wings + DOF_N3 * asm.n_nodes


def wing_dof(k: int) -> int:
    return DOF_B3 * k


def node_dof(asm: Assembly, j: int) -> int:
    return DOF_B3 * asm.n_wings + DOF_N3 * j


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
