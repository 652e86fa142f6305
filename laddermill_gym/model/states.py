"""Orientation helpers (3-2-1 Euler angles, quaternions) and state-vector construction/conversion."""

from __future__ import annotations

import math

import numpy as np

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
    N2_POS,
    N2_SIZE,
    N2_VEL,
    N3_POS,
    N3_SIZE,
    N3_VEL,
)


def rotation_from_euler(phi: float, theta: float, psi: float) -> np.ndarray:
    """R = Rz(psi) Ry(theta) Rx(phi) (body -> global), 3x3."""
    cf, sf = math.cos(phi), math.sin(phi)
    ct, st = math.cos(theta), math.sin(theta)
    cp, sp = math.cos(psi), math.sin(psi)
    return np.array([
        [ct * cp, sf * st * cp - cf * sp, cf * st * cp + sf * sp],
        [ct * sp, sf * st * sp + cf * cp, cf * st * sp - sf * cp],
        [-st, sf * ct, cf * ct],
    ])


def rotations_from_quaternions(q: np.ndarray) -> np.ndarray:
    """Body -> global rotation matrices of many quaternions.

    q : array (n, 4), scalar first, not necessarily unit (each row is normalised here).
    Returns float64 (n, 3, 3); entry [k] is R(q_k) of docs/model.md, so global = R @ body.
    """
    q = np.asarray(q, dtype=float)
    if q.ndim != 2 or q.shape[1] != 4:
        raise ValueError(f"rotations_from_quaternions: expected shape (n, 4), got {q.shape}")
    qn = q / np.linalg.norm(q, axis=1, keepdims=True)
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


def quaternion_from_euler(phi: float, theta: float, psi: float) -> np.ndarray:
    """Unit quaternion (scalar first) of the 3-2-1 Euler angles (roll, pitch, yaw) [rad]."""
    c1, s1 = math.cos(phi / 2), math.sin(phi / 2)
    c2, s2 = math.cos(theta / 2), math.sin(theta / 2)
    c3, s3 = math.cos(psi / 2), math.sin(psi / 2)
    return np.array([
        c3 * c2 * c1 + s3 * s2 * s1,
        c3 * c2 * s1 - s3 * s2 * c1,
        c3 * s2 * c1 + s3 * c2 * s1,
        s3 * c2 * c1 - c3 * s2 * s1,
    ])


def euler_from_quaternion(q) -> tuple[float, float, float]:
    """3-2-1 Euler angles (roll phi, pitch theta, yaw psi) [rad] of a (not necessarily unit) quaternion."""
    a, b, c, d = np.asarray(q, dtype=float) / np.linalg.norm(q)
    r32 = 2 * (c * d + a * b)
    r33 = a * a - b * b - c * c + d * d
    r31 = 2 * (b * d - a * c)
    r21 = 2 * (b * c + a * d)
    r11 = a * a + b * b - c * c - d * d
    return (math.atan2(r32, r33), -math.asin(max(-1.0, min(1.0, r31))), math.atan2(r21, r11))


def euler_rate_matrix(phi: float, theta: float) -> np.ndarray:
    """A of Meijaard eq. (6): (phi', theta', psi') = A (p, q, r) for 3-2-1 Euler angles."""
    sf, cf = math.sin(phi), math.cos(phi)
    tt, ct = math.tan(theta), math.cos(theta)
    return np.array([[1.0, sf * tt, cf * tt], [0.0, cf, -sf], [0.0, sf / ct, cf / ct]])


def wing_state_3d(position, euler, v_body, rates) -> np.ndarray:
    """13-float wing state from position [m], Euler angles (phi, theta, psi) [rad], body velocity [m/s]
    and body rates [rad/s]."""
    s = np.empty(B3_SIZE)
    s[B3_POS: B3_POS + 3] = np.asarray(position, float)
    s[B3_QUAT: B3_QUAT + 4] = quaternion_from_euler(*euler)
    s[B3_VEL: B3_VEL + 3] = np.asarray(v_body, float)
    s[B3_RATE: B3_RATE + 3] = np.asarray(rates, float)
    return s


def block_view(v: np.ndarray, start: int, count: int, size: int, first: int, n: int) -> np.ndarray:
    """The entries ``first`` .. ``first + n - 1`` of ``count`` consecutive blocks of ``size`` entries (every wing's
    or every node's state block) that begin at ``start`` of the flat contiguous vector v, as a (count, n) view:
    writing to it writes v."""
    return v[start: start + size * count].reshape(count, size)[:, first: first + n]


#: A node's in-plane (x, z) pairs and where they sit in its 3D block (x, y, z): the position, then the velocity.
NODE_PLANE_SLOTS = ((N2_POS, N3_POS), (N2_VEL, N3_VEL))


def planar_to_3d(x2: np.ndarray, n_wings: int, n_nodes: int) -> np.ndarray:
    """Embed an in-plane state (6 per wing, 4 per node) into the 3D layout (13 per wing, 6 per node)."""
    x2 = np.asarray(x2, dtype=float)
    out = []
    for k in range(n_wings):
        s = x2[B2_SIZE * k: B2_SIZE * (k + 1)]
        out.append(wing_state_3d([s[B2_X], 0.0, s[B2_Z]], [0.0, s[B2_THETA], 0.0], [s[B2_U], 0.0, s[B2_W]],
                                 [0.0, s[B2_Q], 0.0]))
    nodes = np.zeros((n_nodes, N3_SIZE))
    for s2, s3 in NODE_PLANE_SLOTS:
        nodes[:, s3: s3 + 3: 2] = block_view(x2, B2_SIZE * n_wings, n_nodes, N2_SIZE, s2, 2)
    return np.concatenate([*out, nodes.ravel()])


def planar_from_3d(x3: np.ndarray, n_wings: int, n_nodes: int) -> np.ndarray:
    """Inverse of :func:`planar_to_3d` (drops the lateral components; pitch from the quaternion)."""
    x3 = np.asarray(x3, dtype=float)
    out = []
    for k in range(n_wings):
        s = x3[B3_SIZE * k: B3_SIZE * (k + 1)]
        _, th, _ = euler_from_quaternion(s[B3_QUAT: B3_QUAT + 4])
        w = np.zeros(B2_SIZE)
        w[B2_X], w[B2_Z], w[B2_THETA] = s[B3_POS], s[B3_POS + 2], th
        w[B2_U], w[B2_W], w[B2_Q] = s[B3_VEL], s[B3_VEL + 2], s[B3_RATE + 1]
        out.append(w)
    nodes = np.zeros((n_nodes, N2_SIZE))
    for s2, s3 in NODE_PLANE_SLOTS:
        nodes[:, s2: s2 + 2] = block_view(x3, B3_SIZE * n_wings, n_nodes, N3_SIZE, s3, 3)[:, ::2]
    return np.concatenate([*out, nodes.ravel()])
