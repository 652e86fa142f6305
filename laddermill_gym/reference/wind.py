"""Wind and air of the reference model: the speed and direction profiles (M1)-(M2), the time modulation, the
frozen gust grid (scipy's linear grid interpolation, independent of the kernels' bilinear formula), the wind
velocity and its rate along a moving point, and the air density (M3 or ISA).

Choices where the specification leaves room (the kernels make the same ones): the modulation interval is
``k = floor((t - t0) / dt)`` with the end values held (slope 0) outside ``0 <= k <= n-2``; at exactly ``h = h0``
the profile uses the upper branch; for ``h <= 0`` the speed and its slope are 0; with ``direction_inf == 0`` the
direction is identically 0; the ISA base ``1 - 2.2558e-5 h`` is clipped at 0.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.model.params import WindParams


def wind_speed_profile(wind: WindParams, h: float) -> tuple[float, float]:
    """Wind speed V_w(h) of eq. (M1) and its height derivative.

    Parameters
    ----------
    wind : WindParams
    h : float
        Altitude [m] (``h = -z``).

    Returns
    -------
    V : float
        Speed [m/s]: 0 for ``h <= 0``, ``V0 (h/h0)^n`` for ``0 < h < h0``, ``V0 + V1 (h - h0)`` for ``h >= h0``.
    dV_dh : float
        dV_w/dh [1/s] (0 for ``h <= 0``).
    """
    if h <= 0.0:
        return 0.0, 0.0
    if h < wind.h0:
        V = wind.v0 * (h / wind.h0) ** wind.exponent
        dV = wind.exponent * wind.v0 / wind.h0 * (h / wind.h0) ** (wind.exponent - 1.0)
        return V, dV
    return wind.v0 + wind.v1 * (h - wind.h0), wind.v1


def wind_direction_profile(wind: WindParams, h: float) -> tuple[float, float]:
    """Wind direction phi_s(h) = phi_inf (1 - exp(-h/h_s)) of eq. (M2) and its height derivative.

    Returns
    -------
    phi : float
        Direction [rad].
    dphi_dh : float
        d phi_s / dh [rad/m].
    """
    if wind.direction_inf == 0.0:
        return 0.0, 0.0
    decay = np.exp(-h / wind.direction_height)
    return wind.direction_inf * (1.0 - decay), wind.direction_inf / wind.direction_height * decay


def _interp_with_slope(samples: np.ndarray, t0: float, dt: float, t: float) -> tuple[float, float]:
    """Linear interpolation of uniform samples, held constant outside; returns (value, d value/dt).

    The interval is ``k = floor((t - t0)/dt)`` (so an exact sample time belongs to the interval that
    starts there); outside ``0 <= k <= n - 2`` the end value is held and the slope is 0.
    """
    n = samples.size
    tau = (t - t0) / dt
    k = int(np.floor(tau))
    if k < 0:
        return float(samples[0]), 0.0
    if k >= n - 1:
        return float(samples[n - 1]), 0.0
    frac = tau - k
    value = samples[k] + (samples[k + 1] - samples[k]) * frac
    slope = (samples[k + 1] - samples[k]) / dt
    return float(value), float(slope)


def wind_modulation(wind: WindParams, t: float) -> tuple[float, float, float, float]:
    """Time modulation of the wind.

    Returns
    -------
    s, ds_dt : float
        Speed factor [-] and its time derivative [1/s].
    delta, ddelta_dt : float
        Direction offset [rad] and its time derivative [rad/s].
    """
    s, ds = _interp_with_slope(np.asarray(wind.mod_speed, dtype=float), wind.mod_t0, wind.mod_dt, t)
    d, dd = _interp_with_slope(np.asarray(wind.mod_direction, dtype=float), wind.mod_t0, wind.mod_dt, t)
    return s, ds, d, dd


def wind_velocity(wind: WindParams, position: np.ndarray, t: float) -> np.ndarray:
    """Wind velocity w(p, t) = -s(t) V_w(h) (cos(phi_s(h) + delta(t)), sin(phi_s(h) + delta(t)), 0).

    Parameters
    ----------
    wind : WindParams
    position : ndarray, shape (3,)
        Global position [m] (z down).
    t : float
        Time [s].

    Returns
    -------
    ndarray, shape (3,)
        Wind velocity in global components [m/s].
    """
    h = -float(position[2])
    V, _ = wind_speed_profile(wind, h)
    phi, _ = wind_direction_profile(wind, h)
    s, _, delta, _ = wind_modulation(wind, t)
    angle = phi + delta
    return -s * V * np.array([np.cos(angle), np.sin(angle), 0.0]) + gust_velocity(wind, position, t)


def _gust_axes(grid) -> np.ndarray:
    """Rows: the global directions of the grid's u (downwind), v (right of downwind) and w (up) components."""
    e = -np.array([np.cos(grid.heading), np.sin(grid.heading), 0.0])
    return np.array([e, np.cross([0.0, 0.0, 1.0], e), [0.0, 0.0, -1.0]])


def _grid_coordinates(grid, position: np.ndarray, t: float) -> tuple[float, float]:
    """(xi, h) of a point at time t: the along-wind coordinate in the frozen, advected field and the height."""
    e = _gust_axes(grid)[0]
    return float(e @ position - grid.advection * t), -float(position[2])


def _grid_interpolator(grid):
    from scipy.interpolate import RegularGridInterpolator

    n_xi, n_h, _ = grid.values.shape
    xi = grid.xi0 + grid.dxi * np.arange(max(n_xi, 2))
    h = grid.h0 + grid.dh * np.arange(max(n_h, 2))
    vals = grid.values
    if n_xi == 1:  # one column: constant along xi
        vals = np.concatenate([vals, vals], axis=0)
    if n_h == 1:
        vals = np.concatenate([vals, vals], axis=1)
    return RegularGridInterpolator((xi, h), vals, method="linear"), xi, h


def gust_velocity(wind: WindParams, position: np.ndarray, t: float) -> np.ndarray:
    """The frozen gust grid's velocity (global, m/s) at a point and time: scipy's linear interpolation on the
    grid at (xi, h), with the query held inside the grid (edge values outside); zero without a grid."""
    grid = wind.gust
    if grid is None:
        return np.zeros(3)
    interp, xs, hs = _grid_interpolator(grid)
    xi, h = _grid_coordinates(grid, position, t)
    q = np.array([np.clip(xi, xs[0], xs[-1]), np.clip(h, hs[0], hs[-1])])
    uvw = interp(q[None])[0]
    return _fade_in(grid, t)[0] * (uvw @ _gust_axes(grid))


def _fade_in(grid, t: float) -> tuple[float, float]:
    """The grid's fade-in factor 0.5 (1 - cos(pi t / T_f)) on [0, T_f) (0 before, 1 after or for T_f = 0) and
    its time derivative [1/s]."""
    tf = getattr(grid, "fade_in", 0.0)
    if tf <= 0.0 or t >= tf:
        return 1.0, 0.0
    if t <= 0.0:
        return 0.0, 0.0
    return 0.5 * (1.0 - np.cos(np.pi * t / tf)), 0.5 * np.pi / tf * np.sin(np.pi * t / tf)


def gust_rate(wind: WindParams, position: np.ndarray, velocity: np.ndarray, t: float) -> np.ndarray:
    """d/dt of :func:`gust_velocity` along a point moving with global ``velocity``: the chain rule through
    xi' = velocity . e - U and h' = -velocity[2], with the gradient of the linear interpolant in the grid cell
    (a one-sided difference of the interpolant across the cell; 0 along an axis where the point is outside)."""
    grid = wind.gust
    if grid is None:
        return np.zeros(3)
    interp, xs, hs = _grid_interpolator(grid)
    axes = _gust_axes(grid)
    xi, h = _grid_coordinates(grid, position, t)
    q = np.array([np.clip(xi, xs[0], xs[-1]), np.clip(h, hs[0], hs[-1])])
    grad = np.zeros((2, 3))
    for axis, (coord, nodes, step) in enumerate(((xi, xs, grid.dxi), (h, hs, grid.dh))):
        if not nodes[0] < coord < nodes[-1]:
            continue
        k = min(int(np.floor((coord - nodes[0]) / step)), nodes.size - 2)
        lo, hi = q.copy(), q.copy()
        lo[axis], hi[axis] = nodes[k], nodes[k + 1]
        grad[axis] = (interp(hi[None])[0] - interp(lo[None])[0]) / step
    rates = np.array([float(velocity @ axes[0]) - grid.advection, -float(velocity[2])])
    r, r_dot = _fade_in(grid, t)
    return r * ((rates @ grad) @ axes) + r_dot * (interp(q[None])[0] @ axes)


def wind_rate(wind: WindParams, position: np.ndarray, velocity: np.ndarray, t: float) -> np.ndarray:
    """Rate of change of the wind seen by a point moving with global velocity ``velocity``.

    ``dw/dt = (partial w / partial h) h' + partial w / partial t`` with ``h' = -velocity[2]``; the time
    part uses the slopes of the modulation (see :func:`wind_modulation`).

    Parameters
    ----------
    wind : WindParams
    position : ndarray, shape (3,)
        Global position [m].
    velocity : ndarray, shape (3,)
        Global velocity of the point [m/s].
    t : float
        Time [s].

    Returns
    -------
    ndarray, shape (3,)
        dw/dt in global components [m/s^2].
    """
    h = -float(position[2])
    h_dot = -float(velocity[2])
    V, dV_dh = wind_speed_profile(wind, h)
    phi, dphi_dh = wind_direction_profile(wind, h)
    s, ds_dt, delta, ddelta_dt = wind_modulation(wind, t)
    angle = phi + delta
    along = np.array([np.cos(angle), np.sin(angle), 0.0])  # unit vector of the direction
    turn = np.array([-np.sin(angle), np.cos(angle), 0.0])  # its derivative with respect to the angle
    # w = -s V along(angle)
    dw_dh = -s * (dV_dh * along + V * dphi_dh * turn)
    dw_dt = -(ds_dt * V * along + s * V * ddelta_dt * turn)
    return dw_dh * h_dot + dw_dt + gust_rate(wind, position, velocity, t)


def air_density(wind: WindParams, h: float) -> float:
    """Air density [kg/m^3] at altitude ``h`` [m] (eq. M3 "barometric", or ISA troposphere "isa")."""
    if wind.density_model == "barometric":
        return float(wind.rho0 * np.exp(-h / wind.scale_height))
    if wind.density_model == "isa":
        base = max(1.0 - 2.2558e-5 * h, 0.0)
        return float(wind.rho0 * base**4.2559)
    raise ValueError(f"wind.density_model must be 'barometric' or 'isa', got {wind.density_model!r}")
