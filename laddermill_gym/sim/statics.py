"""Steady states: static equilibria in steady wind (trim) by Newton's method on the simulator's own
accelerations, and a quasi-static shooting layout that gives chains a good first guess."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root

from laddermill_gym.kernels.contract import (
    B2_Q,
    B2_SIZE,
    B2_U,
    B2_X,
    B3_POS,
    B3_QUAT,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    CTRL_ELEVATOR,
    N2_POS,
    N2_SIZE,
    N2_VEL,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    N_CONTROLS,
)
from laddermill_gym.model.states import euler_from_quaternion, quaternion_from_euler
from laddermill_gym.sim.simulator import SimulationError


def pack_unknowns(sim, x):
    """Equilibrium unknowns from a state: per wing position + Euler angles (3D) or x, z, theta (2D);
    per node its position."""
    a = sim.assembly
    out = []
    if a.dim == 3:
        for k in range(a.n_wings):
            s = x[B3_SIZE * k: B3_SIZE * (k + 1)]
            out.extend([*s[B3_POS: B3_POS + 3], *euler_from_quaternion(s[B3_QUAT: B3_QUAT + 4])])
        b = B3_SIZE * a.n_wings
        for j in range(a.n_nodes):
            o = b + N3_SIZE * j + N3_POS
            out.extend(x[o: o + 3])
    else:
        for k in range(a.n_wings):
            o = B2_SIZE * k + B2_X
            out.extend(x[o: o + 3])  # x, z, theta
        b = B2_SIZE * a.n_wings
        for j in range(a.n_nodes):
            o = b + N2_SIZE * j + N2_POS
            out.extend(x[o: o + 2])
    return np.array(out)


def unpack_unknowns(sim, z):
    """State at rest (all velocities zero) from the equilibrium unknowns."""
    a = sim.assembly
    x = np.zeros(a.state_size)
    i = 0
    if a.dim == 3:
        for k in range(a.n_wings):
            o = B3_SIZE * k
            x[o + B3_POS: o + B3_POS + 3] = z[i: i + 3]
            x[o + B3_QUAT: o + B3_QUAT + 4] = quaternion_from_euler(*z[i + 3: i + 6])
            i += 6
        b = B3_SIZE * a.n_wings
        for j in range(a.n_nodes):
            o = b + N3_SIZE * j + N3_POS
            x[o: o + 3] = z[i: i + 3]
            i += 3
    else:
        for k in range(a.n_wings):
            o = B2_SIZE * k + B2_X
            x[o: o + 3] = z[i: i + 3]  # x, z, theta
            i += 3
        b = B2_SIZE * a.n_wings
        for j in range(a.n_nodes):
            o = b + N2_SIZE * j + N2_POS
            x[o: o + 2] = z[i: i + 2]
            i += 2
    return x


def accelerations(sim, dx):
    """The acceleration entries of a state derivative (the equilibrium residual)."""
    a = sim.assembly
    parts = []
    if a.dim == 3:
        parts += [dx[B3_SIZE * k + B3_VEL: B3_SIZE * k + B3_RATE + 3] for k in range(a.n_wings)]
        b = B3_SIZE * a.n_wings
        parts += [dx[b + N3_SIZE * j + N3_VEL: b + N3_SIZE * j + N3_VEL + 3] for j in range(a.n_nodes)]
    else:
        parts += [dx[B2_SIZE * k + B2_U: B2_SIZE * k + B2_Q + 1] for k in range(a.n_wings)]
        b = B2_SIZE * a.n_wings
        parts += [dx[b + N2_SIZE * j + N2_VEL: b + N2_SIZE * j + N2_VEL + 2] for j in range(a.n_nodes)]
    return np.concatenate(parts) if parts else np.zeros(0)


def _accelerations_or_nan(sim, t: float, x: np.ndarray, u: np.ndarray) -> np.ndarray:
    """:func:`accelerations` of ``sim.rhs``; NaN where a trial state of the solver is outside what the model can
    evaluate (``rhs`` raises SimulationError for a non-finite derivative), which the solvers treat as a failed
    trial."""
    try:
        return accelerations(sim, sim.rhs(t, x, u))
    except SimulationError:
        return np.full(len(accelerations(sim, np.zeros_like(x))), np.nan)


def _newton(resid, z0, tol):
    """Root of resid from z0: MINPACK hybrd first; where the cable starts near slack (a soft, strongly
    nonlinear start) Levenberg-Marquardt gets into the basin and hybrd polishes. Returns (z, |residual|, msg)."""
    sol = root(resid, z0, method="hybr", options={"xtol": tol})
    r = float(np.linalg.norm(resid(sol.x)))
    if sol.success or r < 1e-9:
        return sol.x, r, sol.message
    lm = root(resid, z0, method="lm", options={"xtol": tol, "ftol": tol, "maxiter": 200 * (len(z0) + 1)})
    pol = root(resid, lm.x, method="hybr", options={"xtol": tol})
    r_pol = float(np.linalg.norm(resid(pol.x)))
    r_lm = float(np.linalg.norm(resid(lm.x)))
    return (pol.x, r_pol, pol.message) if r_pol <= r_lm else (lm.x, r_lm, lm.message)


def static_equilibrium(sim, x_guess: np.ndarray, controls: np.ndarray | None = None, t: float = 0.0,
                       tol: float = 1e-10) -> np.ndarray:
    """The state at rest in which all accelerations vanish, found by Newton (MINPACK hybrd) from x_guess.

    Raises RuntimeError when the solve does not converge (with the residual norm)."""
    u = sim.controls if controls is None else np.asarray(controls, float)
    z0 = pack_unknowns(sim, x_guess)

    def resid(z):
        return _accelerations_or_nan(sim, t, unpack_unknowns(sim, z), u)

    z, r, msg = _newton(resid, z0, tol)
    if r > 1e-6 * math.sqrt(len(z)):  # ill-conditioned (a long closed loop): restart once from there
        z2, r2, msg2 = _newton(resid, z, tol)
        if r2 < r:
            z, r, msg = z2, r2, msg2
    if r > 1e-6 * math.sqrt(len(z)):  # RMS acceleration above 1e-6 m/s^2
        raise RuntimeError(f"static equilibrium: Newton did not converge (|residual| = {r:.3g}): {msg}")
    return unpack_unknowns(sim, z)


def trim_alpha(sim, x_guess: np.ndarray, alpha: float, wing: int = 0, t: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Static equilibrium in which wing ``wing`` flies at angle of attack ``alpha`` [rad]: the elevator of
    that wing is an extra unknown. Returns (state, controls)."""
    u0 = sim.controls.copy()
    z0 = np.concatenate([pack_unknowns(sim, x_guess), [u0[N_CONTROLS * wing + CTRL_ELEVATOR]]])

    def resid(z):
        u = u0.copy()
        u[N_CONTROLS * wing + CTRL_ELEVATOR] = z[-1]
        x = unpack_unknowns(sim, z[:-1])
        acc = _accelerations_or_nan(sim, t, x, u)
        sim.state[:] = x
        sim.t = t
        return np.concatenate([acc, [sim.wing_alpha_beta()[wing, 0] - alpha]])

    keep = sim.state.copy(), sim.t
    try:
        z, r, msg = _newton(resid, z0, 1e-12)
    finally:
        sim.state[:], sim.t = keep
    if r > 1e-6 * math.sqrt(len(z)):
        raise RuntimeError(f"trim: Newton did not converge (|residual| = {r:.3g}): {msg}")
    u = u0.copy()
    u[N_CONTROLS * wing + CTRL_ELEVATOR] = z[-1]
    return unpack_unknowns(sim, z[:-1]), u


_SPLINES: dict = {}


def table_spline(table):
    """Periodic cubic spline of an aerodynamic table (cached per table object)."""
    from scipy.interpolate import CubicSpline

    key = id(table)
    hit = _SPLINES.get(key)
    if hit is None or hit[0] is not table:
        hit = (table, CubicSpline(table.alpha, table.values, bc_type="periodic", axis=0))
        _SPLINES[key] = hit
    return hit[1]


def pitch_trim_alpha(wing_type, elevator: float, dynamic_pressure: float | None = None,
                     gravity: float = 9.80665) -> float:
    """Angle of attack [rad] at which a wing at rest in horizontal wind (pitch angle = alpha) has no pitching
    moment about its cable attachment point, the point where the resultant cable force acts: aerodynamic
    force at the reference point, aerodynamic moment, and (if ``dynamic_pressure`` [Pa] is given) the weight
    at the CG. A first guess for layouts, searched on the attached-flow branch (-10..25 deg)."""
    from laddermill_gym.model.params import AERO_INDEX

    sp = table_spline(wing_type.aero)
    ax = wing_type.r_ref[0] - wing_type.attachment[0]
    az = wing_type.r_ref[2] - wing_type.attachment[2]
    gx, gz = -wing_type.attachment[0], -wing_type.attachment[2]  # CG from the attachment [m]
    iCL, iCD, iCm = AERO_INDEX["CL"], AERO_INDEX["CD"], AERO_INDEX["Cm"]
    iCLde, iCmde = AERO_INDEX["CLde"], AERO_INDEX["Cmde"]

    def cm_att(a):  # works on scalars and arrays of alpha
        c = sp(a)
        cl = c[..., iCL] + c[..., iCLde] * elevator
        cd = c[..., iCD]
        cm = c[..., iCm] + c[..., iCmde] * elevator
        X = cl * np.sin(a) - cd * np.cos(a)
        Z = -cl * np.cos(a) - cd * np.sin(a)
        m = cm + (az * X - ax * Z) / wing_type.chord
        if dynamic_pressure is not None and dynamic_pressure > 0.0:
            w = wing_type.mass * gravity / (dynamic_pressure * wing_type.area)
            m = m + (gz * (-w * np.sin(a)) - gx * (w * np.cos(a))) / wing_type.chord
        return m

    grid = np.radians(np.linspace(-10, 25, 141))
    vals = cm_att(grid)
    for i in range(len(grid) - 1):
        if vals[i] > 0 >= vals[i + 1]:
            return float(brentq(cm_att, grid[i], grid[i + 1]))
    return float(grid[np.argmin(np.abs(vals))])
