"""Plain-numpy reference implementation of the laddermill model's right-hand side (3D only).

The package ``laddermill_gym.reference`` is the *oracle* the numba kernels are tested against. It
is written directly from ``laddermill_gym/docs/model.md`` with readability as the only goal: this module assembles
the dense global mass matrix ``M`` (``n_dof x n_dof``) and the dense generalised force vector ``F`` of eq. (M25),
``M v' = f + h - D^T sigma``, and solves with :func:`numpy.linalg.solve`. Nothing here is fast. The pieces live
beside it: ``wind`` (wind and air), ``rotations``, ``wing`` (wing aerodynamics), ``state`` (state access and
element-end kinematics) and ``cable`` (cable elements and tensions).

Conventions (see docs/model.md):

* SI units and radians; global frame x north, y east, z down; altitude ``h = -z``.
* Generalised velocities: per wing ``(v, omega)`` in body axes (6 dof, wing ``k`` at dof ``6 k``),
  then per free node its global velocity (3 dof, node ``j`` at dof ``6 n_w + 3 j``).
* State: per wing ``[x(3), q(4), v(3), omega(3)]`` (``B3_SIZE`` floats each), then per node
  ``[position(3), velocity(3)]`` (``N3_SIZE`` floats each; slot names of ``kernels/contract.py``).

Choices made where the specification leaves room (the kernels must make the same ones):

* Wind modulation: the sample interval is ``k = floor((t - t0) / dt)``; for ``0 <= k <= n-2`` the value
  is the linear interpolation on ``[k, k+1]`` and the time slope is ``(s[k+1] - s[k]) / dt``; for ``k < 0``
  the value is ``s[0]`` and for ``k >= n-1`` it is ``s[n-1]``, with slope 0 in both cases. At an exact
  sample time ``t0 + k dt`` the slope is that of the interval starting there.
* Wind profile at exactly ``h = h0`` uses the upper branch (value ``V0``, slope ``V1``); for ``h <= 0`` the
  speed and its slope are 0. With ``direction_inf == 0`` the direction is identically 0 (no division by
  ``direction_height``).
* ISA density: the base ``1 - 2.2558e-5 h`` is clipped at 0 (density 0 above ~44.3 km).
* Air density for a cable load is evaluated at the height of that end's attachment point.
* ``g = (-w_a, 0, u_a) / (u_a^2 + w_a^2)`` is set to 0 when ``u_a^2 + w_a^2 == 0`` (pure sideslip).
* Gravity also acts on a node's lumped ``node_mass`` (``node_mass * (0, 0, gravity)``).
* Controls are used as given (no clipping to ``control_limits``).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL, N3_POS, N3_SIZE, N3_VEL
from laddermill_gym.model.params import N_CONTROLS, Assembly
from laddermill_gym.reference.cable import element_loads_per_length, element_state, tension
from laddermill_gym.reference.rotations import quaternion_product, rotation
from laddermill_gym.reference.state import (
    check_dim,
    end_kinematics,
    end_transformation,
    n_dof,
    node_dof,
    node_state,
    wing_dof,
    wing_state,
)
from laddermill_gym.reference.wing import inertia_matrix, wing_aero


def mass_matrix_and_forces(asm: Assembly, t: float, x: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Dense global mass matrix and generalised force vector of eq. (M25).

    Parameters
    ----------
    asm : Assembly
        Must have ``dim == 3``.
    t : float
        Time [s].
    x : ndarray, shape (state_size,)
        State.
    u : ndarray, shape (3 n_w,)
        Controls, (elevator, rudder, aileron) per wing [rad].

    Returns
    -------
    M : ndarray, shape (n_dof, n_dof)
        Mass matrix including the alpha-rate apparent mass ``-k g^T`` (not symmetric then).
    F : ndarray, shape (n_dof,)
        Everything on the right side: gravity, gyroscopic and quadratic velocity terms, aerodynamics
        (with ``k adot0``), cable loads and tensions.
    """
    check_dim(asm)
    x = np.asarray(x, dtype=float)
    u = np.asarray(u, dtype=float)
    if x.shape != (asm.state_size,):
        raise ValueError(f"state x must have shape ({asm.state_size},), got {x.shape}")
    if u.shape != (N_CONTROLS * asm.n_wings,):
        raise ValueError(f"controls u must have shape ({N_CONTROLS * asm.n_wings},), got {u.shape}")
    n = n_dof(asm)
    M = np.zeros((n, n))
    F = np.zeros(n)
    gravity_global = np.array([0.0, 0.0, asm.gravity])
    _add_wings(asm, t, x, u, gravity_global, M, F)
    _add_nodes(asm, gravity_global, M, F)
    _add_elements(asm, t, x, gravity_global, M, F)
    return M, F


def _add_wings(asm: Assembly, t: float, x: np.ndarray, u: np.ndarray, gravity_global: np.ndarray,
               M: np.ndarray, F: np.ndarray) -> None:
    """Wings (M4): rigid-body mass, gravity, gyroscopic terms, aerodynamics (with the alpha-rate apparent mass)."""
    for k in range(asm.n_wings):
        wt = asm.wing(k)
        pos, q, v, w = wing_state(asm, x, k)
        R = rotation(q)
        J = inertia_matrix(wt)
        d = wing_dof(k)
        M[d : d + 3, d : d + 3] += wt.mass * np.eye(3)
        M[d + 3 : d + 6, d + 3 : d + 6] += J
        F[d : d + 3] += R.T @ (wt.mass * gravity_global)
        F[d : d + 3] += -wt.mass * np.cross(w, v)
        F[d + 3 : d + 6] += -np.cross(w, J @ w)
        controls = u[N_CONTROLS * k : N_CONTROLS * (k + 1)]
        force, moment, kvec, gvec, adot0 = wing_aero(wt, pos, R, v, w, controls, asm.wind, t)
        F[d : d + 3] += force
        F[d + 3 : d + 6] += moment
        F[d : d + 6] += kvec * adot0
        M[d : d + 6, d : d + 3] -= np.outer(kvec, gvec)


def _add_nodes(asm: Assembly, gravity_global: np.ndarray, M: np.ndarray, F: np.ndarray) -> None:
    """Nodes: lumped mass and its weight."""
    for j in range(asm.n_nodes):
        d = node_dof(asm, j)
        m_node = float(asm.node_mass[j])
        M[d : d + 3, d : d + 3] += m_node * np.eye(3)
        F[d : d + 3] += m_node * gravity_global


def _add_elements(asm: Assembly, t: float, x: np.ndarray, gravity_global: np.ndarray, M: np.ndarray,
                  F: np.ndarray) -> None:
    """Cable elements (M7)-(M25): consistent mass, quadratic velocity terms, distributed loads, tension."""
    el = asm.elements
    for e in range(el.count):
        st = element_state(asm, e, x)
        T_r = end_transformation(asm, e, 0, x)
        T_s = end_transformation(asm, e, 1, x)
        T = np.vstack([T_r, T_s])  # 6 x n_dof
        m_e = float(el.mu[e]) * float(el.l0[e])
        M0e = m_e / 6.0 * np.block([[2 * np.eye(3), np.eye(3)], [np.eye(3), 2 * np.eye(3)]])
        M += T.T @ M0e @ T

        # Quadratic velocity terms (M15).
        _, _, c_r = end_kinematics(asm, e, 0, x)
        _, _, c_s = end_kinematics(asm, e, 1, x)
        F += -T.T @ M0e @ np.concatenate([c_r, c_s])

        # Distributed loads as nodal forces.
        _, f_r, f_s = element_loads_per_length(asm, e, x, t, st)
        weight_half = 0.5 * m_e * gravity_global
        F_r = weight_half + st.length * (2.0 * f_r + f_s) / 6.0
        F_s = weight_half + st.length * (f_r + 2.0 * f_s) / 6.0
        F += T_r.T @ F_r + T_s.T @ F_s

        # Tension: -D^T sigma.
        sigma = tension(asm, e, x, t)
        F += sigma * (T_r.T @ st.e) - sigma * (T_s.T @ st.e)


def reference_rhs(t: float, x: np.ndarray, u: np.ndarray, asm: Assembly) -> np.ndarray:
    """State derivative dx/dt of the 3D model.

    Parameters
    ----------
    t : float
        Time [s].
    x : ndarray, shape (state_size,)
        State: per wing [x(3), q(4), v(3), omega(3)], then per node [position(3), velocity(3)].
    u : ndarray, shape (3 n_w,)
        Controls (elevator, rudder, aileron) per wing [rad].
    asm : Assembly
        Must have ``dim == 3``.

    Returns
    -------
    ndarray, shape (state_size,)
        Same layout as ``x``: per wing [R v, 1/2 q (x) (0, omega), v', omega'], per node [velocity, acceleration].
        ``q`` is the stored (unnormalised) quaternion in the kinematic equation; ``R`` uses the normalised one.
    """
    check_dim(asm)
    x = np.asarray(x, dtype=float)
    M, F = mass_matrix_and_forces(asm, t, x, u)
    accel = np.linalg.solve(M, F)
    dx = np.zeros_like(x)
    for k in range(asm.n_wings):
        _, q, v, w = wing_state(asm, x, k)
        o = B3_SIZE * k
        d = wing_dof(k)
        dx[o + B3_POS: o + B3_POS + 3] = rotation(q) @ v
        dx[o + B3_QUAT: o + B3_QUAT + 4] = 0.5 * quaternion_product(q, np.concatenate([[0.0], w]))
        dx[o + B3_VEL: o + B3_VEL + 3] = accel[d: d + 3]
        dx[o + B3_RATE: o + B3_RATE + 3] = accel[d + 3: d + 6]
    for j in range(asm.n_nodes):
        _, vel = node_state(asm, x, j)
        o = B3_SIZE * asm.n_wings + N3_SIZE * j
        d = node_dof(asm, j)
        dx[o + N3_POS: o + N3_POS + 3] = vel
        dx[o + N3_VEL: o + N3_VEL + 3] = accel[d: d + 3]
    return dx
