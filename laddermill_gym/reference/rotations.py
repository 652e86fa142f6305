"""Rotations of the reference model: the skew matrix, quaternion rotation matrix and product, 3-2-1 Euler angles."""

from __future__ import annotations

import numpy as np


def skew(a: np.ndarray) -> np.ndarray:
    """The 3x3 antisymmetric matrix ``a~`` with ``a~ b = a x b``."""
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


def rotation(q: np.ndarray) -> np.ndarray:
    """Rotation matrix (body -> global components) of a quaternion, normalised first.

    Parameters
    ----------
    q : ndarray, shape (4,)
        Quaternion (q0, q1, q2, q3), scalar first; need not be unit.

    Returns
    -------
    ndarray, shape (3, 3)
    """
    q = np.asarray(q, dtype=float)
    q0, q1, q2, q3 = q / np.linalg.norm(q)
    return np.array(
        [
            [1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q1 * q3 + q0 * q2)],
            [2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1)],
            [2 * (q1 * q3 - q0 * q2), 2 * (q2 * q3 + q0 * q1), 1 - 2 * (q1 * q1 + q2 * q2)],
        ]
    )


def quaternion_product(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product ``a (x) b`` of two quaternions (scalar first), shape (4,)."""
    a0, av = a[0], np.asarray(a[1:], dtype=float)
    b0, bv = b[0], np.asarray(b[1:], dtype=float)
    return np.concatenate([[a0 * b0 - av @ bv], a0 * bv + b0 * av + np.cross(av, bv)])


def euler_321(R: np.ndarray) -> tuple[float, float, float]:
    """3-2-1 Euler angles of ``R = Rz(psi) Ry(theta) Rx(phi)``.

    Returns
    -------
    (phi, theta, psi) : tuple of float
        Roll, pitch, yaw [rad]: ``phi = atan2(R32, R33)``, ``theta = -asin(R31)``, ``psi = atan2(R21, R11)``.
    """
    phi = float(np.arctan2(R[2, 1], R[2, 2]))
    theta = float(-np.arcsin(np.clip(R[2, 0], -1.0, 1.0)))
    psi = float(np.arctan2(R[1, 0], R[0, 0]))
    return phi, theta, psi
