"""Steady states: static equilibria in steady wind (trim) by Newton's method on the simulator's own
accelerations, and a quasi-static shooting layout that gives chains a good first guess."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root

from .states import euler_from_quaternion, quaternion_from_euler


def _pack_unknowns(sim, x):
    """Equilibrium unknowns from a state: per wing position + Euler angles (3D) or x, z, theta (2D);
    per node its position."""
    a = sim.assembly
    out = []
    if a.dim == 3:
        for k in range(a.n_wings):
            s = x[13 * k: 13 * k + 13]
            out.extend([*s[0:3], *euler_from_quaternion(s[3:7])])
        b = 13 * a.n_wings
        for j in range(a.n_nodes):
            out.extend(x[b + 6 * j: b + 6 * j + 3])
    else:
        for k in range(a.n_wings):
            out.extend(x[6 * k: 6 * k + 3])
        b = 6 * a.n_wings
        for j in range(a.n_nodes):
            out.extend(x[b + 4 * j: b + 4 * j + 2])
    return np.array(out)


def _unpack_unknowns(sim, z):
    """State at rest (all velocities zero) from the equilibrium unknowns."""
    a = sim.assembly
    x = np.zeros(a.state_size)
    i = 0
    if a.dim == 3:
        for k in range(a.n_wings):
            x[13 * k: 13 * k + 3] = z[i: i + 3]
            x[13 * k + 3: 13 * k + 7] = quaternion_from_euler(*z[i + 3: i + 6])
            i += 6
        b = 13 * a.n_wings
        for j in range(a.n_nodes):
            x[b + 6 * j: b + 6 * j + 3] = z[i: i + 3]
            i += 3
    else:
        for k in range(a.n_wings):
            x[6 * k: 6 * k + 3] = z[i: i + 3]
            i += 3
        b = 6 * a.n_wings
        for j in range(a.n_nodes):
            x[b + 4 * j: b + 4 * j + 2] = z[i: i + 2]
            i += 2
    return x


def _accelerations(sim, dx):
    """The acceleration entries of a state derivative (the equilibrium residual)."""
    a = sim.assembly
    parts = []
    if a.dim == 3:
        parts += [dx[13 * k + 7: 13 * k + 13] for k in range(a.n_wings)]
        b = 13 * a.n_wings
        parts += [dx[b + 6 * j + 3: b + 6 * j + 6] for j in range(a.n_nodes)]
    else:
        parts += [dx[6 * k + 3: 6 * k + 6] for k in range(a.n_wings)]
        b = 6 * a.n_wings
        parts += [dx[b + 4 * j + 2: b + 4 * j + 4] for j in range(a.n_nodes)]
    return np.concatenate(parts) if parts else np.zeros(0)


def static_equilibrium(sim, x_guess: np.ndarray, controls: np.ndarray | None = None, t: float = 0.0,
                       tol: float = 1e-10) -> np.ndarray:
    """The state at rest in which all accelerations vanish, found by Newton (MINPACK hybrd) from x_guess.

    Raises RuntimeError when the solve does not converge (with the residual norm)."""
    u = sim.controls if controls is None else np.asarray(controls, float)
    z0 = _pack_unknowns(sim, x_guess)

    def resid(z):
        return _accelerations(sim, sim.rhs(t, _unpack_unknowns(sim, z), u))

    sol = root(resid, z0, method="hybr", options={"xtol": tol})
    r = np.linalg.norm(resid(sol.x))
    if not sol.success and r > 1e-6:
        raise RuntimeError(f"static equilibrium: Newton did not converge (|residual| = {r:.3g}): {sol.message}")
    return _unpack_unknowns(sim, sol.x)


def trim_alpha(sim, x_guess: np.ndarray, alpha: float, wing: int = 0, t: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Static equilibrium in which wing ``wing`` flies at angle of attack ``alpha`` [rad]: the elevator of
    that wing is an extra unknown. Returns (state, controls)."""
    u0 = sim.controls.copy()
    z0 = np.concatenate([_pack_unknowns(sim, x_guess), [u0[3 * wing]]])

    def resid(z):
        u = u0.copy()
        u[3 * wing] = z[-1]
        x = _unpack_unknowns(sim, z[:-1])
        acc = _accelerations(sim, sim.rhs(t, x, u))
        sim.state[:] = x
        sim.t = t
        return np.concatenate([acc, [sim.wing_alpha_beta()[wing, 0] - alpha]])

    keep = sim.state.copy(), sim.t
    try:
        sol = root(resid, z0, method="hybr", options={"xtol": 1e-12})
        r = np.linalg.norm(resid(sol.x))
    finally:
        sim.state[:], sim.t = keep
    if not sol.success and r > 1e-6:
        raise RuntimeError(f"trim: Newton did not converge (|residual| = {r:.3g}): {sol.message}")
    u = u0.copy()
    u[3 * wing] = sol.x[-1]
    return _unpack_unknowns(sim, sol.x[:-1]), u


def pitch_trim_alpha(wing_type, elevator: float) -> float:
    """Angle of attack [rad] where the wing alone has no pitching moment about its CG at this elevator
    (ignoring the cable): a first guess for layouts. Searched on the attached-flow branch (-10..25 deg)."""
    from scipy.interpolate import CubicSpline

    from .params import AERO_INDEX

    tab = wing_type.aero
    sp = CubicSpline(tab.alpha, tab.values, bc_type="periodic", axis=0)
    rx, rz = wing_type.r_ref[0], wing_type.r_ref[2]

    def cm_cg(a):
        c = sp(a)
        cl = c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * elevator
        cd = c[AERO_INDEX["CD"]]
        cm = c[AERO_INDEX["Cm"]] + c[AERO_INDEX["Cmde"]] * elevator
        X = cl * math.sin(a) - cd * math.cos(a)
        Z = -cl * math.cos(a) - cd * math.sin(a)
        return cm + (rz * X - rx * Z) / wing_type.chord

    grid = np.radians(np.linspace(-10, 25, 141))
    vals = np.array([cm_cg(a) for a in grid])
    for i in range(len(grid) - 1):
        if vals[i] > 0 >= vals[i + 1]:
            return float(brentq(cm_cg, grid[i], grid[i + 1]))
    return float(grid[np.argmin(np.abs(vals))])
