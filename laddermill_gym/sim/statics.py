"""Steady states: static equilibria in steady wind (trim) by Newton's method on the simulator's own
accelerations, and a quasi-static shooting layout that gives chains a good first guess."""

from __future__ import annotations

import math
from collections import OrderedDict

import numpy as np

from laddermill_gym.kernels import contract as C
from laddermill_gym.model.states import block_view, euler_from_quaternion, quaternion_from_euler
from laddermill_gym.sim.simulator import SimulationError


def pack_unknowns(sim, x):
    """Equilibrium unknowns from a state: per wing position + Euler angles (3D) or x, z, theta (2D);
    per node its position."""
    a, x = sim.assembly, np.asarray(x, dtype=float)
    wings, nodes = _unknown_views(a, x)
    if a.dim == 3:
        euler = [euler_from_quaternion(q) for q in block_view(x, 0, a.n_wings, C.B3_SIZE, C.B3_QUAT, 4)]
        wings = np.hstack([wings, np.reshape(euler, (-1, 3))])
    return np.concatenate([wings.ravel(), nodes.ravel()])


def _unknown_views(a, x):
    """(wing, node) views of the state x that hold the equilibrium unknowns (3D: each wing's position, each node's;
    in-plane: each wing's x, z, theta, each node's x, z)."""
    if a.dim == 3:
        return (block_view(x, 0, a.n_wings, C.B3_SIZE, C.B3_POS, 3),
                block_view(x, C.B3_SIZE * a.n_wings, a.n_nodes, C.N3_SIZE, C.N3_POS, 3))
    return (block_view(x, 0, a.n_wings, C.B2_SIZE, C.B2_X, 3),
            block_view(x, C.B2_SIZE * a.n_wings, a.n_nodes, C.N2_SIZE, C.N2_POS, 2))


def unpack_unknowns(sim, z):
    """State at rest (all velocities zero) from the equilibrium unknowns."""
    a = sim.assembly
    x = np.zeros(a.state_size)
    wings, nodes = _unknown_views(a, x)
    z = np.asarray(z, dtype=float)
    per = 6 if a.dim == 3 else 3  # a 3D wing's unknowns: position and Euler angles
    zw = z[: per * a.n_wings].reshape(a.n_wings, per)
    wings[:] = zw[:, :3]
    if a.dim == 3:
        quats = block_view(x, 0, a.n_wings, C.B3_SIZE, C.B3_QUAT, 4)
        for k in range(a.n_wings):
            quats[k] = quaternion_from_euler(*zw[k, 3:])
    nodes[:] = z[per * a.n_wings: per * a.n_wings + nodes.size].reshape(nodes.shape)
    return x


def accelerations(sim, dx):
    """The acceleration entries of a state derivative (the equilibrium residual)."""
    a = sim.assembly
    if a.dim == 3:
        wings = block_view(dx, 0, a.n_wings, C.B3_SIZE, C.B3_VEL, C.B3_RATE + 3 - C.B3_VEL)
        nodes = block_view(dx, C.B3_SIZE * a.n_wings, a.n_nodes, C.N3_SIZE, C.N3_VEL, 3)
    else:
        wings = block_view(dx, 0, a.n_wings, C.B2_SIZE, C.B2_U, C.B2_Q + 1 - C.B2_U)
        nodes = block_view(dx, C.B2_SIZE * a.n_wings, a.n_nodes, C.N2_SIZE, C.N2_VEL, 2)
    return np.concatenate([wings.ravel(), nodes.ravel()])


def _accelerations_or_nan(sim, t: float, x: np.ndarray, u: np.ndarray) -> np.ndarray:
    """:func:`accelerations` of ``sim.rhs``; NaN where a trial state of the solver is outside what the model can
    evaluate (``rhs`` raises SimulationError for a non-finite derivative), which the solvers treat as a failed
    trial."""
    try:
        return accelerations(sim, sim.rhs(t, x, u))
    except SimulationError:
        return np.full(len(accelerations(sim, np.zeros_like(x))), np.nan)


def _newton(resid, z0, tol, jac=None):
    """Root of resid from z0: MINPACK hybrd first; where the cable starts near slack (a soft, strongly
    nonlinear start) Levenberg-Marquardt gets into the basin and hybrd polishes. ``jac``: the Jacobian (callable;
    default MINPACK's forward differences). Returns (z, |residual|, msg)."""
    from scipy.optimize import root
    sol = root(resid, z0, method="hybr", jac=jac, options={"xtol": tol})
    r = float(np.linalg.norm(resid(sol.x)))
    if sol.success or r < 1e-9:
        return sol.x, r, sol.message
    lm = root(resid, z0, method="lm", jac=jac, options={"xtol": tol, "ftol": tol, "maxiter": 200 * (len(z0) + 1)})
    pol = root(resid, lm.x, method="hybr", jac=jac, options={"xtol": tol})
    r_pol = float(np.linalg.norm(resid(pol.x)))
    r_lm = float(np.linalg.norm(resid(lm.x)))
    return (pol.x, r_pol, pol.message) if r_pol <= r_lm else (lm.x, r_lm, lm.message)


#: Acceptance of an equilibrium: RMS acceleration [m/s^2] (plain, or mass-weighted with ``scaled``).
REST_ACCELERATION = 1e-6
#: Acceptance of trim_alpha's angle of attack with ``scaled`` [rad].
TRIM_ALPHA_TOL = 1e-9


def mass_scales(sim) -> np.ndarray:
    """Per entry of :func:`accelerations`, the mass that turns it into a force: a wing's mass [kg] for its linear
    and its principal moments of inertia Jxx, Jyy, Jzz [kg m^2] for its angular accelerations (Jyy in the
    plane), a free cable node's lumped mass [kg] (its own plus half of each attached element's mu l0, as
    ``ladder/rigid_scene._refuse_impossible_step`` lumps them), floored at 1e-9 of the largest."""
    a = sim.assembly
    e = a.elements
    node = np.array(a.node_mass, dtype=float)
    for end in (0, 1):
        sel = e.end_kind[:, end] == C.END_NODE
        np.add.at(node, e.end_index[sel, end], 0.5 * (e.mu * e.l0)[sel])
    parts = []
    for k in range(a.n_wings):
        wt = a.wing(k)
        rot = [wt.inertia[0], wt.inertia[1], wt.inertia[2]] if a.dim == 3 else [wt.inertia[1]]
        parts.append([wt.mass] * a.dim + rot)
    parts += [[m] * a.dim for m in node]
    s = np.concatenate(parts) if parts else np.zeros(0)
    return np.maximum(s, 1e-9 * (s.max() if s.size else 1.0))


def body_masses(sim) -> np.ndarray:
    """The mass [kg] of every body, wings then free nodes (:func:`mass_scales`' linear entries)."""
    a = sim.assembly
    s = mass_scales(sim)
    per = C.DOF_B3 if a.dim == 3 else C.DOF_B2
    return np.concatenate([s[per * k: per * k + 1] for k in range(a.n_wings)] + [s[per * a.n_wings::a.dim]])


def rest_acceleration(sim, acc: np.ndarray) -> float:
    """Mass-weighted RMS acceleration [m/s^2] of :func:`accelerations` ``acc``: sqrt(acc' S acc / sum m), S the
    diagonal of :func:`mass_scales` (J for the angular entries), sum m the bodies' total mass: the RMS force
    imbalance per unit mass, which a light, stiff cable node does not dominate as it does the plain RMS."""
    s = mass_scales(sim)
    return float(math.sqrt(np.sum(s * acc * acc) / np.sum(body_masses(sim))))


def _unbalanced(sim, acc, scaled: bool) -> float:
    """The acceptance measure [m/s^2] of ``acc``: mass-weighted (:func:`rest_acceleration`) or plain RMS."""
    if not np.all(np.isfinite(acc)):
        return math.inf
    return rest_acceleration(sim, acc) if scaled else float(np.linalg.norm(acc)) / math.sqrt(max(acc.size, 1))


def fd_jacobian(resid, z: np.ndarray, r: np.ndarray | None = None, h: float = 1e-7) -> np.ndarray:
    """Forward-difference Jacobian of ``resid`` at z with the absolute step h [m or rad]: a chain's coordinates
    reach km, where MINPACK's relative steps (1.5e-8 |z_i|, 0.05 mm at 3.5 km) are too coarse for its slack
    apex elements, whose sag-corrected tension bends within millimetres."""
    r = resid(z) if r is None else r
    J = np.empty((r.size, z.size))
    for i in range(z.size):
        zi = z.copy()
        zi[i] += h
        J[:, i] = (resid(zi) - r) / h
    return J


def _polish(resid, measure, z, iterations: int = 10):
    """Newton steps on ``resid`` from z with a forward-difference Jacobian (absolute steps 1e-7 m or rad), each
    halved up to 8 times until ``measure`` (the acceptance measure of z) falls. hybrd stops when its step is below
    xtol of |z|, which for a long chain of stiff elements (|z| ~ 1e4 m, dF/dz ~ 1e6 N/m) can leave forces of order
    1 N, and its difference steps (1.5e-8 |z_i|, 0.05 mm at 3.5 km) are too coarse for its slack apex elements, whose
    sag-corrected tension bends within millimetres: fresh Jacobians with small steps bring the forces to
    round-off. Returns (z, measure(z))."""
    r, m = resid(z), measure(z)
    for _ in range(iterations):
        if not np.all(np.isfinite(r)) or m <= 1e-3 * REST_ACCELERATION:
            break
        J = fd_jacobian(resid, z, r)
        try:
            step = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            step = np.linalg.lstsq(J, -r, rcond=None)[0]
        for _ in range(9):
            m_new = measure(z + step)
            if m_new < m:
                break
            step = 0.5 * step
        else:
            break
        z = z + step
        r, m = resid(z), m_new
    return z, m


def static_equilibrium(sim, x_guess: np.ndarray, controls: np.ndarray | None = None, t: float = 0.0,
                       tol: float = 1e-10, scaled: bool = False) -> np.ndarray:
    """The state at rest in which all accelerations vanish, found by Newton (MINPACK hybrd) from x_guess.

    Accepted when the RMS acceleration is below REST_ACCELERATION = 1e-6 m/s^2. ``scaled``: Newton on the forces
    (accelerations times :func:`mass_scales`: N and N m) and the RMS taken mass-weighted (:func:`rest_acceleration`).
    The plain accelerations weigh a light cable node (several elements per piece: omega^2 = EA / (l0 m) up to
    1e6 s^-2) against a wing (g / L ~ 0.1 s^-2) 1e7 to one, which stalls hybrd (docs/numerics.md, "Initial states
    with several elements per piece"). Raises RuntimeError when the solve does not converge (with the measure)."""
    u = sim.controls if controls is None else np.asarray(controls, float)
    z0 = pack_unknowns(sim, x_guess)
    s = mass_scales(sim) if scaled else 1.0

    def acc(z):
        return _accelerations_or_nan(sim, t, unpack_unknowns(sim, z), u)

    def resid(z):
        return s * acc(z)

    jac = (lambda z: fd_jacobian(resid, z)) if scaled else None
    z, _, msg = _newton(resid, z0, tol, jac)
    r = _unbalanced(sim, acc(z), scaled)
    if r > REST_ACCELERATION:  # ill-conditioned (a long closed loop): restart once from there
        z2, _, msg2 = _newton(resid, z, tol, jac)
        r2 = _unbalanced(sim, acc(z2), scaled)
        if r2 < r:
            z, r, msg = z2, r2, msg2
    if r > 1e-2 * REST_ACCELERATION and scaled:  # hybrd's step test stopped short of round-off: Newton polishes
        z, r = _polish(resid, lambda zz: _unbalanced(sim, acc(zz), scaled), z)
    if r > REST_ACCELERATION:
        what = "mass-weighted RMS acceleration" if scaled else "RMS acceleration"
        raise RuntimeError(f"static equilibrium: Newton did not converge ({what} {r:.3g} m/s^2 > "
                           f"{REST_ACCELERATION:g}): {msg}")
    return unpack_unknowns(sim, z)


def trim_alpha(sim, x_guess: np.ndarray, alpha: float, wing: int = 0, t: float = 0.0,
               scaled: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Static equilibrium in which wing ``wing`` flies at angle of attack ``alpha`` [rad]: the elevator of
    that wing is an extra unknown. Returns (state, controls). ``scaled``: as :func:`static_equilibrium`, the angle
    of attack's equation weighted by the wing's weight [N/rad] and accepted below TRIM_ALPHA_TOL."""
    u0 = sim.controls.copy()
    z0 = np.concatenate([pack_unknowns(sim, x_guess), [u0[C.N_CONTROLS * wing + C.CTRL_ELEVATOR]]])
    s = np.append(mass_scales(sim), sim.assembly.wing(wing).mass * sim.assembly.gravity) if scaled else 1.0

    def resid(z):
        u = u0.copy()
        u[C.N_CONTROLS * wing + C.CTRL_ELEVATOR] = z[-1]
        x = unpack_unknowns(sim, z[:-1])
        acc = _accelerations_or_nan(sim, t, x, u)
        sim.state[:] = x
        sim.t = t
        return s * np.concatenate([acc, [sim.wing_alpha_beta()[wing, 0] - alpha]])

    def measure(z):  # the acceptance measure in REST_ACCELERATION's units: the worse of the two
        f = resid(z) / s
        return max(_unbalanced(sim, f[:-1], True), abs(f[-1]) * REST_ACCELERATION / TRIM_ALPHA_TOL)

    keep = sim.state.copy(), sim.t
    try:
        z, r, msg = _newton(resid, z0, 1e-12)
        if scaled and measure(z) > REST_ACCELERATION:  # hybrd stopped short (a fine cable: 40 elements): polish
            z, _ = _polish(resid, measure, z)
        f = resid(z) / s
    finally:
        sim.state[:], sim.t = keep
    if scaled:
        ok = _unbalanced(sim, f[:-1], True) <= REST_ACCELERATION and abs(f[-1]) <= TRIM_ALPHA_TOL
        r = _unbalanced(sim, f[:-1], True)
    else:
        ok = r <= 1e-6 * math.sqrt(len(z))
    if not ok:
        raise RuntimeError(f"trim: Newton did not converge (|residual| = {r:.3g}, angle of attack off by "
                           f"{f[-1]:.3g} rad): {msg}")
    u = u0.copy()
    u[C.N_CONTROLS * wing + C.CTRL_ELEVATOR] = z[-1]
    return unpack_unknowns(sim, z[:-1]), u


#: the splines of the tables used last, per table object (each entry keeps its table, so an id is not reused while
#: it is here); at most SPLINES_KEPT, so that a sweep loading many scenes does not hold every table it met
_SPLINES: OrderedDict = OrderedDict()
SPLINES_KEPT = 16


def table_spline(table):
    """Periodic cubic spline of an aerodynamic table (cached per table object, the SPLINES_KEPT used last)."""
    from scipy.interpolate import CubicSpline

    key = id(table)
    hit = _SPLINES.get(key)
    if hit is None or hit[0] is not table:
        hit = (table, CubicSpline(table.alpha, table.values, bc_type="periodic", axis=0))
        _SPLINES[key] = hit
    _SPLINES.move_to_end(key)
    while len(_SPLINES) > SPLINES_KEPT:
        _SPLINES.popitem(last=False)
    return hit[1]


def pitch_trim_alpha(wing_type, elevator: float, dynamic_pressure: float | None = None,
                     gravity: float = 9.80665) -> float:
    """Angle of attack [rad] at which a wing at rest in horizontal wind (pitch angle = alpha) has no pitching
    moment about its cable attachment point, the point where the resultant cable force acts: aerodynamic
    force at the reference point, aerodynamic moment, and (if ``dynamic_pressure`` [Pa] is given) the weight
    at the CG. A first guess for layouts, searched on the attached-flow branch (-10..25 deg)."""
    from scipy.optimize import brentq

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
