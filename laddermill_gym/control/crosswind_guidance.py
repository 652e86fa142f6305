"""Path guidance of the crosswind controller: a lying figure eight (the lemniscate of Booth on the wind window, as
Rapp, Schmehl, Oland & Haas 2019, "Cascaded pumping cycle control for rigid wing airborne wind energy systems",
J. Guidance, Control, and Dynamics 42(11), eq. 20, fly their rigid wing) or a circle, sampled on the unit sphere,
followed by pure pursuit: the course command is the bearing from the kite to a point a look-ahead angle further
along the path (the carrot), measured in the kite's tangent plane, as the course of
``envs.pumping.wind_window`` (0 up, +pi/2 towards larger azimuth).

Figure eight (azimuth phi, elevation beta, path parameter s): phi(s) = phi_c + w sin(s) / (1 + (h/w cos s)^2),
beta(s) = beta_c + h sin(s) cos(s) / (1 + (h/w cos s)^2), w the half azimuth span, h about the height of a lobe.
It is flown with s decreasing for ``"up_at_sides"`` (down through the centre, the turns upwards at the ends: the
usual pumping figure, gravity helping the crossing) and increasing for ``"down_at_sides"``. A circle of angular
radius h about (phi_c, beta_c), flown with the azimuth growing ("positive") or falling ("negative") at its top.

The pursuit keeps each copy's last path index and searches only a window ahead of it, so the crossing of the
figure eight's two branches is never confused (``PathGuidance.course_command``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laddermill_gym.envs.pumping.wind_window import window_point

__all__ = ["PathSpec", "PathGuidance", "path_angles", "N_PATH_POINTS"]

#: samples of one lap of the path (0.5 deg of path parameter)
N_PATH_POINTS = 720
#: path points the closest-point search looks ahead of the last index (45 deg of path parameter)
_SEARCH = 90


@dataclass(frozen=True)
class PathSpec:
    """A path on the wind window: ``shape`` ("figure_eight" or "circle"), centre ``elevation`` and ``azimuth``
    [rad], ``width`` [rad] (the figure eight's half azimuth span; unused by a circle), ``height`` [rad] (the
    figure eight's lobe height parameter h, a circle's angular radius), ``direction`` ("up_at_sides" /
    "down_at_sides" for a figure eight; for a circle "positive" / "negative": the azimuth grows / falls at its
    top), ``lookahead`` [rad] the pursuit's carrot distance."""

    shape: str
    elevation: float
    azimuth: float
    width: float
    height: float
    direction: str
    lookahead: float

    def extent(self) -> tuple[float, float, float, float]:
        """(lowest, highest elevation, smallest, largest azimuth) [rad] the path reaches."""
        az, el = path_angles(self)
        return float(el.min()), float(el.max()), float(az.min()), float(az.max())


def path_angles(spec: PathSpec) -> tuple[np.ndarray, np.ndarray]:
    """(azimuth, elevation) [rad] of ``N_PATH_POINTS`` points of the path, in the order it is flown."""
    s = np.linspace(0.0, 2.0 * np.pi, N_PATH_POINTS, endpoint=False)
    if spec.shape == "figure_eight":
        if spec.direction == "up_at_sides":
            s = -s
        den = 1.0 + (spec.height / spec.width * np.cos(s)) ** 2
        return spec.azimuth + spec.width * np.sin(s) / den, spec.elevation + spec.height * np.sin(s) * np.cos(s) / den
    if spec.direction == "negative":  # azimuth falling at the circle's top
        s = -s
    # a small circle of angular radius h about the centre, built in the centre's tangent frame
    c = window_point(np.array([spec.azimuth]), np.array([spec.elevation]))[0]
    up = np.array([0.0, 0.0, -1.0])
    e_phi = np.cross(up, c)
    e_phi /= np.linalg.norm(e_phi)
    e_beta = np.cross(c, e_phi)
    pts = (np.cos(spec.height) * c[None, :] + np.sin(spec.height) * (np.cos(s)[:, None] * e_beta
                                                                      + np.sin(s)[:, None] * e_phi))
    down = np.array([-1.0, 0.0, 0.0])  # the window's frame as window_point's default (wind direction 0)
    side = np.cross(up, down)
    return np.arctan2(pts @ side, pts @ down), np.arcsin(np.clip(pts @ up, -1.0, 1.0))


class PathGuidance:
    """Pure pursuit of a :class:`PathSpec` for n kites (the unit-sphere path points ``points`` (N, 3))."""

    def __init__(self, spec: PathSpec):
        self.spec = spec
        az, el = path_angles(spec)
        self.azimuth, self.elevation = az, el
        self.points = window_point(az, el)
        step = np.arccos(np.clip(np.sum(self.points * np.roll(self.points, -1, axis=0), axis=1), -1.0, 1.0))
        #: path points per look-ahead (the carrot's offset in indices)
        self.ahead = max(1, int(round(spec.lookahead / max(float(np.mean(step)), 1e-9))))

    def closest(self, e_r: np.ndarray, last: np.ndarray) -> np.ndarray:
        """Index (n,) of the path point closest to each tether direction ``e_r`` (n, 3): globally where ``last`` is
        -1, else within the next ``_SEARCH`` points after ``last`` (the direction of flight)."""
        cos = e_r @ self.points.T  # (n, N)
        idx = np.argmax(cos, axis=1)
        local = last >= 0
        if local.any():
            win = (last[local, None] + np.arange(_SEARCH)[None, :]) % len(self.points)
            rows = np.flatnonzero(local)
            idx[local] = win[np.arange(len(rows)), np.argmax(cos[rows[:, None], win], axis=1)]
        return idx

    def course_command(self, e_r: np.ndarray, e_phi: np.ndarray, e_beta: np.ndarray,
                       last: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(course command [rad], new path index, angular distance to the path [rad]), each (n,), of kites with
        tangent frames (e_r, e_phi, e_beta) (n, 3) and last path indices ``last`` (n,) (-1: unknown)."""
        idx = self.closest(e_r, last)
        carrot = self.points[(idx + self.ahead) % len(self.points)]
        return (bearing(carrot, e_r, e_phi, e_beta), idx,
                np.arccos(np.clip(np.sum(self.points[idx] * e_r, axis=1), -1.0, 1.0)))


def bearing(target: np.ndarray, e_r: np.ndarray, e_phi: np.ndarray, e_beta: np.ndarray) -> np.ndarray:
    """Course [rad] (n,) from kites with tangent frames (e_r, e_phi, e_beta) towards unit-sphere points ``target``
    (n, 3) (the great circle's initial course)."""
    t = target - np.sum(target * e_r, axis=1)[:, None] * e_r
    return np.arctan2(np.sum(t * e_phi, axis=1), np.sum(t * e_beta, axis=1))
