"""Orientation helpers (3-2-1 Euler angles, quaternions) and state-vector construction/conversion."""

from __future__ import annotations

import math

import numpy as np


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
    return np.concatenate([np.asarray(position, float), quaternion_from_euler(*euler),
                           np.asarray(v_body, float), np.asarray(rates, float)])


def planar_to_3d(x2: np.ndarray, n_wings: int, n_nodes: int) -> np.ndarray:
    """Embed an in-plane state (6 per wing, 4 per node) into the 3D layout (13 per wing, 6 per node)."""
    x2 = np.asarray(x2, dtype=float)
    out = []
    for k in range(n_wings):
        x, z, th, u, w, q = x2[6 * k: 6 * k + 6]
        out.append(wing_state_3d([x, 0.0, z], [0.0, th, 0.0], [u, 0.0, w], [0.0, q, 0.0]))
    b = 6 * n_wings
    for j in range(n_nodes):
        x, z, vx, vz = x2[b + 4 * j: b + 4 * j + 4]
        out.append(np.array([x, 0.0, z, vx, 0.0, vz]))
    return np.concatenate(out) if out else np.zeros(0)


def planar_from_3d(x3: np.ndarray, n_wings: int, n_nodes: int) -> np.ndarray:
    """Inverse of :func:`planar_to_3d` (drops the lateral components; pitch from the quaternion)."""
    x3 = np.asarray(x3, dtype=float)
    out = []
    for k in range(n_wings):
        s = x3[13 * k: 13 * k + 13]
        _, th, _ = euler_from_quaternion(s[3:7])
        out.append(np.array([s[0], s[2], th, s[7], s[9], s[11]]))
    b = 13 * n_wings
    for j in range(n_nodes):
        s = x3[b + 6 * j: b + 6 * j + 6]
        out.append(np.array([s[0], s[2], s[3], s[5]]))
    return np.concatenate(out) if out else np.zeros(0)
