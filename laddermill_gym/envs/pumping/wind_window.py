"""The kite's place and motion on the wind window (the quarter sphere downwind of the winch), batched numpy: what a
kite's flight controller measures (Fechner et al. 2015, "Dynamic model of a pumping kite power system", Renewable
Energy 83, section 2: the wind reference frame and the small-earth frame; Erhard & Strauch 2013, "Control of
towing kites for seagoing vessels", IEEE TCST 21(5), fig. 2).

Frames, all global (x north, y east, z down; the winch at the origin): the wind blows towards ``downwind``
(for the scenes' wind direction 0, -x). With the tether direction e_r = p / |p|:

* elevation beta = asin(-z / |p|), azimuth phi = atan2(p . e_east', p . downwind) with e_east' = up x downwind
  (positive towards +y for wind direction 0);
* the tangent plane's unit vectors e_phi (increasing azimuth) and e_beta = e_r x e_phi (increasing elevation);
* course chi = atan2(v . e_phi, v . e_beta): the direction of the kite's velocity on the wind window, 0 flying
  up (towards the zenith), +pi/2 flying towards larger azimuth;
* bank mu = asin(-z_b . n), n = -sin(chi) e_beta + cos(chi) e_phi the tangent-plane normal to the course that
  increases it, z_b the wing's body z axis (down; -z_b is the lift's direction): the lift tilted towards n turns
  the course towards larger chi (Fechner & Schmehl's steering, here by the wing's roll).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["WindWindow", "wind_window", "rotations_from_euler", "downwind_vector", "window_point"]


def downwind_vector(direction: float = 0.0) -> np.ndarray:
    """Unit vector the wind blows towards, for a wind direction [rad] of ``kernels.wind.wind_at`` (0: -x)."""
    return np.array([-np.cos(direction), -np.sin(direction), 0.0])


def rotations_from_euler(phi: np.ndarray, theta: np.ndarray, psi: np.ndarray) -> np.ndarray:
    """Body -> global rotation matrices (n, 3, 3), R = Rz(psi) Ry(theta) Rx(phi) of 3-2-1 Euler angles (n,) [rad]
    (``model.states.rotation_from_euler``, batched)."""
    cf, sf = np.cos(phi), np.sin(phi)
    ct, st = np.cos(theta), np.sin(theta)
    cp, sp = np.cos(psi), np.sin(psi)
    r = np.empty((len(np.atleast_1d(phi)), 3, 3))
    r[:, 0, 0], r[:, 0, 1], r[:, 0, 2] = ct * cp, sf * st * cp - cf * sp, cf * st * cp + sf * sp
    r[:, 1, 0], r[:, 1, 1], r[:, 1, 2] = ct * sp, sf * st * sp + cf * cp, cf * st * sp - sf * cp
    r[:, 2, 0], r[:, 2, 1], r[:, 2, 2] = -st, sf * ct, cf * ct
    return r


@dataclass
class WindWindow:
    """Wind-window read-outs of n kites, each (n,): elevation, azimuth, course, bank [rad], distance from the
    winch [m], radial speed (> 0 away from the winch) and tangential speed [m/s]; ``e_r``, ``e_phi``, ``e_beta``
    (n, 3) the unit vectors."""

    elevation: np.ndarray
    azimuth: np.ndarray
    course: np.ndarray
    bank: np.ndarray
    distance: np.ndarray
    radial_speed: np.ndarray
    tangential_speed: np.ndarray
    e_r: np.ndarray
    e_phi: np.ndarray
    e_beta: np.ndarray


def _tangent_basis(p: np.ndarray, downwind: np.ndarray):
    up = np.array([0.0, 0.0, -1.0])
    side = np.cross(up, downwind)  # towards larger azimuth
    dist = np.linalg.norm(p, axis=1)
    e_r = p / np.maximum(dist, 1e-9)[:, None]
    elevation = np.arcsin(np.clip(e_r @ up, -1.0, 1.0))
    azimuth = np.arctan2(e_r @ side, e_r @ downwind)
    e_phi = -np.sin(azimuth)[:, None] * downwind + np.cos(azimuth)[:, None] * side
    e_beta = np.cross(e_r, e_phi)
    return dist, e_r, elevation, azimuth, e_phi, e_beta


def wind_window(p: np.ndarray, v: np.ndarray, rot: np.ndarray, downwind: np.ndarray | None = None) -> WindWindow:
    """Wind-window read-outs of kites at positions ``p`` (n, 3) [m] from the winch, velocities ``v`` (n, 3) [m/s],
    body -> global rotations ``rot`` (n, 3, 3), the wind blowing towards ``downwind`` (3,) (default -x)."""
    p, v = np.atleast_2d(np.asarray(p, float)), np.atleast_2d(np.asarray(v, float))
    dw = downwind_vector() if downwind is None else np.asarray(downwind, float)
    dist, e_r, elevation, azimuth, e_phi, e_beta = _tangent_basis(p, dw)
    vb, vp = np.sum(v * e_beta, axis=1), np.sum(v * e_phi, axis=1)
    course = np.arctan2(vp, vb)
    n = -np.sin(course)[:, None] * e_beta + np.cos(course)[:, None] * e_phi
    lift_axis = -rot[:, :, 2]
    bank = np.arcsin(np.clip(np.sum(lift_axis * n, axis=1), -1.0, 1.0))
    return WindWindow(elevation=elevation, azimuth=azimuth, course=course, bank=bank, distance=dist,
                      radial_speed=np.sum(v * e_r, axis=1), tangential_speed=np.hypot(vb, vp), e_r=e_r, e_phi=e_phi,
                      e_beta=e_beta)


def window_point(azimuth: np.ndarray, elevation: np.ndarray, distance: np.ndarray | float = 1.0,
                 downwind: np.ndarray | None = None) -> np.ndarray:
    """Global positions (n, 3) [m] of points at ``azimuth``, ``elevation`` [rad] and ``distance`` [m] from the winch
    (the inverse of the angles of :func:`wind_window`)."""
    dw = downwind_vector() if downwind is None else np.asarray(downwind, float)
    up = np.array([0.0, 0.0, -1.0])
    side = np.cross(up, dw)
    a, e = np.atleast_1d(azimuth)[:, None], np.atleast_1d(elevation)[:, None]
    return np.asarray(distance).reshape(-1, 1) * (np.cos(e) * (np.cos(a) * dw + np.sin(a) * side) + np.sin(e) * up)
