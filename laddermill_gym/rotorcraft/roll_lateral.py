"""Roberts' eq. (6) for the tethered twin-rotor craft: the roll / lateral-translation perturbation model

    M [y'', phi'']^T + D [y', phi']^T + K [y, phi]^T = [alpha, beta]^T dtheta,

derived from the craft's physics at a trim point, and the same four blocks measured on the full nonlinear
simulator by central differences (:func:`restricted_jacobian`), for the check.

Coordinates: y the CG's lateral (global y) displacement [m], phi the roll about the body x axis [rad], dtheta
the differential collective [rad] (right rotor +dtheta, left -dtheta). Everything else (x, z, pitch, yaw, cable
nodes) stays at the trim. The derivation, term by term, is in ``laddermill_gym/docs/rotorcraft.md``
("Eq. (6)"); in short, with the craft at rest at the trim (rotation R0, body x axis b = R0 e_x):

- M: craft mass and Jxx plus each tether element's consistent end mass m_e/3 at its attachment point.
- Tethers (straight, as in Roberts): the end force f = T n + (weight share) changes by -S dp with the string
  stiffness S = k n n^T + (T / l)(I - n n^T), k = EA / l0, at dp = dy e_y + phi b x a (a: attachment,
  global); the moment changes also because the attachment arm turns: (phi b x a) x f. Voigt damping DA / l0
  along n gives the tethers' part of D.
- Rotors (Gessow & Myers with Glauert inflow): the rotor force is fixed in the body, so rolling tilts it in the
  global frame (b x F); rolling also turns the relative wind in the body (a lateral air component phi w_z)
  and moves the hubs through the wind shear; roll rate changes each hub's normal air speed by -+ p s
  (differential thrust: the roll damping); lateral air speed turns the H-force. Thrust derivatives with respect
  to the normal air speed, the advance ratio and the collective are taken in closed form through the inflow
  equation f(lam) = lam - lam_inf + C_T / (2 sqrt(mu^2 + lam^2)) = 0.
- Fins and frame drag: lateral air speed at the fins and at the CG.
- Input: beta = -2 s dT/dtheta0 (s half the hub spacing), alpha = 0 (no lateral force at the trim attitude).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL, N3_POS, N3_SIZE, TM_DT, TM_T0
from laddermill_gym.kernels.wind import density, modulation, profile, wind_at
from laddermill_gym.model.states import rotation_from_euler
from laddermill_gym.rotorcraft import craft_kernels as _kc

_EY = np.array([0.0, 1.0, 0.0])
_EX = np.array([1.0, 0.0, 0.0])


@dataclass(frozen=True)
class RollLateralModel:
    """Eq. (6) at a trim point: M, D, K (2, 2) and the input column b = (alpha, beta) (2,).

    Units: rows (lateral force [N], rolling moment [N m]); columns (y [m], phi [rad]) for K, their rates for D,
    their accelerations for M; b per rad of differential collective.
    """

    M: np.ndarray
    D: np.ndarray
    K: np.ndarray
    b: np.ndarray

    def state_space(self) -> tuple[np.ndarray, np.ndarray]:
        """(A (4, 4), B (4, 1)) of x = (y, phi, y', phi'), u = dtheta."""
        Mi = np.linalg.inv(self.M)
        A = np.zeros((4, 4))
        A[0:2, 2:4] = np.eye(2)
        A[2:4, 0:2] = -Mi @ self.K
        A[2:4, 2:4] = -Mi @ self.D
        B = np.zeros((4, 1))
        B[2:4, 0] = Mi @ self.b
        return A, B


def _thrust_partials(rp, mu, lam, theta, rho, radius, omega):
    """Thrust T [N] derivatives: d/d(normal air speed) [N s/m], d/d(in-plane air speed) [N s/m], d/dtheta0 [N].

    Through the inflow equation f(lam) = lam - lam_inf + C_T / (2 r) = 0, C_T = c0(mu, theta0) + c1 lam,
    r = sqrt(mu^2 + lam^2) (rotorcraft/rotor_kernels.py solve_inflow)."""
    sigma, a, B = rp[0], rp[1], rp[3]
    c1 = 0.25 * sigma * a * B * B
    ct = 0.5 * sigma * a * (theta * (B ** 3 / 3.0 + 0.5 * B * mu * mu) + 0.5 * lam * B * B)
    r = math.hypot(mu, lam)
    f_lam = 1.0 + c1 / (2.0 * r) - ct * lam / (2.0 * r ** 3)
    dc0_dth = 0.5 * sigma * a * (B ** 3 / 3.0 + 0.5 * B * mu * mu)
    dc0_dmu = 0.5 * sigma * a * theta * B * mu
    dct_dlinf = c1 / f_lam
    dlam_dth = -dc0_dth / (2.0 * r) / f_lam
    dct_dth = dc0_dth + c1 * dlam_dth
    df_dmu = dc0_dmu / (2.0 * r) - ct * mu / (2.0 * r ** 3)
    dct_dmu = dc0_dmu - c1 * df_dmu / f_lam
    vt = omega * radius
    scale = rho * math.pi * radius ** 2 * vt ** 2
    return scale * dct_dlinf / vt, scale * dct_dmu / vt, scale * dct_dth


def derive_roll_lateral(sim, x: np.ndarray | None = None, u: np.ndarray | None = None) -> RollLateralModel:
    """Eq. (6) of the craft simulator ``sim`` (a :class:`~laddermill_gym.rotorcraft.craft.CraftSimulator`) at the trim
    (x, u) (default: its current state and controls), from the craft's physics (module docstring).

    The tethers are treated as straight elements from each attachment to the next node or anchor, with their
    tension at the trim (the sag correction's softening and the cable aerodynamics are not in the model).
    """
    x = sim.state if x is None else np.asarray(x, float)
    u = sim.controls if u is None else np.asarray(u, float)
    cfg, asm, model = sim.config, sim.assembly, sim.model
    sim.rhs(0.0, x, u)
    tension = sim.work.tension[: asm.elements.count].copy()
    out = sim.work.vout.copy()
    R0 = rotation_from_euler(*sim_euler(x))
    b = R0 @ _EX
    pos = x[B3_POS: B3_POS + 3]
    M = np.diag([cfg.mass, cfg.inertia[0]])
    K = np.zeros((2, 2))
    D = np.zeros((2, 2))
    _add_tethers(asm, x, tension, pos, R0, b, cfg.gravity, M, D, K)
    # rotors, fins and drag: body-frame loads; tilting their resultant with the body (global y force only)
    F_body = out[_kc.V_FORCE: _kc.V_FORCE + 3]
    K[0, 1] -= (np.cross(b, R0 @ F_body))[1]
    s_mod, d_mod, _, _ = modulation(0.0, model.tmod[TM_T0], model.tmod[TM_DT], model.ms, model.md)
    beta_in = _add_rotors(cfg, model.wf, s_mod, d_mod, out, pos, R0, b, D, K)
    _add_fins_and_drag(cfg, model.wf, s_mod, d_mod, pos, R0, D, K)
    return RollLateralModel(M=M, D=D, K=K, b=np.array([0.0, beta_in]))


def _add_tethers(asm, x, tension, pos, R0, b, g, M, D, K) -> None:
    """Add the tethers' terms to M, D and K (in place): each element end at the craft is a straight string of
    stiffness S = k n n^T + (T / l)(I - n n^T) with Voigt damping DA / l0 along n and the consistent end mass
    m_e / 3; the moment changes also because the attachment arm turns with the roll."""
    el = asm.elements
    nodes = x[B3_SIZE:].reshape(-1, N3_SIZE)[:, N3_POS: N3_POS + 3] if asm.n_nodes else np.zeros((0, 3))
    for e in range(el.count):
        for end in range(2):
            if el.end_kind[e, end] != 0:  # not the craft's end
                continue
            other = 1 - end
            kind, idx = int(el.end_kind[e, other]), int(el.end_index[e, other])
            far = asm.fixed_points[idx] if kind == 2 else nodes[idx]
            a = R0 @ el.attach[e, end]
            p = pos + a
            d = far - p
            ln = float(np.linalg.norm(d))
            n = d / ln
            T = float(tension[e])
            me = el.mu[e] * el.l0[e]
            f = T * n + np.array([0.0, 0.0, 0.5 * me * g])
            S = el.EA[e] / el.l0[e] * np.outer(n, n) + (T / ln) * (np.eye(3) - np.outer(n, n))
            Sd = el.DA[e] / el.l0[e] * np.outer(n, n)
            c = np.cross(b, a)                      # attachment displacement per unit roll
            cols = (_EY, c)
            for j, dp in enumerate(cols):
                dfs = -S @ dp
                K[0, j] -= dfs[1]
                dmom = np.cross(a, dfs) + (np.cross(c, f) if j == 1 else 0.0)
                K[1, j] -= b @ dmom
                dfd = -Sd @ dp
                D[0, j] -= dfd[1]
                D[1, j] -= b @ np.cross(a, dfd)
            M[0, 0] += me / 3.0
            M[0, 1] += me / 3.0 * c[1]
            M[1, 0] += me / 3.0 * c[1]
            M[1, 1] += me / 3.0 * (c @ c)


def _add_rotors(cfg, wf, s_mod, d_mod, out, pos, R0, b, D, K) -> float:
    """Add the rotors' terms to D and K (in place): roll turns the relative wind in the body and moves the hubs
    through the wind shear, lateral air speed turns the H-force, roll rate changes each hub's normal air speed.
    Returns beta [N m per rad], the rolling moment of the differential collective."""
    rp = np.array(cfg.rotor.packed(), float)
    Rr, Om = cfg.rotor_radius, cfg.rotor_speed
    s = 0.5 * cfg.hub_spacing
    # perturbations j: roll phi (K column 1), lateral speed y' (D column 0), roll rate p (D column 1)
    targets = ((K, 1), (D, 0), (D, 1))
    beta_in = 0.0
    for r, hy in ((0, s), (1, -s)):
        h = np.array([cfg.hub_x, hy, -cfg.hub_height])
        hg = pos + R0 @ h
        w_g = np.array(wind_at(hg[2], wf, s_mod, d_mod))
        w_b = R0.T @ w_g
        rho = density(-hg[2], wf)
        blk = out[_kc.V_ROTOR + _kc.N_RO * r: _kc.V_ROTOR + _kc.N_RO * (r + 1)]
        H, mu, lam, th = blk[_kc.R_HFORCE], blk[_kc.R_MU], blk[_kc.R_LAMBDA], blk[_kc.R_THETA]
        dT_dvn, dT_dvip, dT_dth = _thrust_partials(rp, mu, lam, th, rho, Rr, Om)
        vip = math.hypot(w_b[0], w_b[1])
        # lateral air speed at the hub: roll turns the wind in the body (phi w_z), motion (-y'), rate x arm (p h_z)
        day = (w_b[2], -1.0, h[2])
        # roll moves the hub through the wind shear: wind speed change per unit roll
        _, dvdh = profile(-hg[2], wf)
        dV = -dvdh * np.cross(b, R0 @ h)[2] * s_mod
        speed = float(np.linalg.norm(w_g))
        dwb = w_b * (dV / speed) if speed > 0 else np.zeros(3)
        dvn = (-dwb[2], 0.0, h[1])                 # normal (up-through-disk) air speed: shear; -; p h_y
        dvip = (dwb[0] * w_b[0] / vip if vip > 0 else 0.0, 0.0, 0.0)
        for j, (mat, col) in enumerate(targets):
            dT = dT_dvn * dvn[j] + dT_dvip * dvip[j]
            dFy = H * day[j] / vip if vip > 0 else 0.0    # the H-force turns with the in-plane air flow
            dFz = -dT
            mat[0, col] -= dFy
            mat[1, col] -= h[1] * dFz - h[2] * dFy
        beta_in += hy * (-dT_dth) * (1.0 if r == 0 else -1.0)   # right +dtheta, left -dtheta; L = h_y F_z
    return beta_in


def _add_fins_and_drag(cfg, wf, s_mod, d_mod, pos, R0, D, K) -> None:
    """Add the fins' and the frame drag's side forces, linear in the lateral air speed, to D and K (in place)."""
    targets = ((K, 1), (D, 0), (D, 1))
    for px, pz, at_cg in ((cfg.fin_x, cfg.fin_z, False), (0.0, 0.0, True)):
        pg = pos + R0 @ np.array([px, 0.0, pz])
        w_b = R0.T @ np.array(wind_at(pg[2], wf, s_mod, d_mod))
        rho = density(-pg[2], wf)
        kk = 0.5 * rho * (cfg.drag_area * np.linalg.norm(w_b) if at_cg
                          else cfg.fin_area * cfg.fin_lift_slope * abs(w_b[0]))
        day = (w_b[2], -1.0, pz)
        for j, (mat, col) in enumerate(targets):
            dFy = kk * day[j]
            mat[0, col] -= dFy
            mat[1, col] -= -pz * dFy


def sim_euler(x: np.ndarray) -> np.ndarray:
    """3-2-1 Euler angles (phi, theta, psi) [rad] of the craft (body 0) in state x."""
    from laddermill_gym.model.states import euler_from_quaternion

    return np.asarray(euler_from_quaternion(x[B3_QUAT: B3_QUAT + 4]))


def lateral_state(x: np.ndarray, x_trim: np.ndarray) -> np.ndarray:
    """Eq. (6)'s state (y [m], phi [rad], y' [m/s], p [rad/s]) of the craft (body 0) in state x: the lateral CG
    offset from the trim ``x_trim``, the 3-2-1 roll angle, the global lateral velocity and the body roll rate."""
    eu = sim_euler(x)
    vy = (rotation_from_euler(*eu) @ x[B3_VEL: B3_VEL + 3])[1]
    return np.array([x[B3_POS + 1] - x_trim[B3_POS + 1], eu[0], vy, x[B3_RATE]])


def perturbed_state(x: np.ndarray, dy: float, dphi: float, dvy: float, dp: float) -> np.ndarray:
    """State x with the craft moved by dy (global y) [m], rolled by dphi about its body x axis [rad], given a
    global lateral velocity dvy [m/s] and a roll rate dp [rad/s]."""
    z = x.copy()
    z[B3_POS + 1] += dy
    if dphi:
        q = x[B3_QUAT: B3_QUAT + 4]
        c, s_ = math.cos(0.5 * dphi), math.sin(0.5 * dphi)
        # q (x) (cos, sin, 0, 0): rotation about the body x axis
        z[B3_QUAT: B3_QUAT + 4] = (q[0] * c - q[1] * s_, q[1] * c + q[0] * s_, q[2] * c + q[3] * s_,
                                   q[3] * c - q[2] * s_)
    R = rotation_from_euler(*sim_euler(z))
    z[B3_VEL: B3_VEL + 3] += R.T @ (_EY * dvy)
    z[B3_RATE] += dp
    return z


def _lateral_accelerations(sim, x: np.ndarray, u: np.ndarray) -> np.ndarray:
    """(global lateral acceleration [m/s^2], roll acceleration p' [rad/s^2]) of the craft at rest-ish state x."""
    dx = sim.rhs(0.0, x, u)
    R = rotation_from_euler(*sim_euler(x))
    return np.array([(R @ dx[B3_VEL: B3_VEL + 3])[1], dx[B3_RATE]])


def restricted_jacobian(sim, x: np.ndarray | None = None, u: np.ndarray | None = None, h: float = 1e-5
                        ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The full simulator's Jacobian restricted to (y, phi): the (y'', phi'') rows against (y, phi), against
    (y', phi') and against the differential collective, by central differences of ``sim.rhs`` (all other
    states held at x). Compare with -M^-1 K, -M^-1 D and M^-1 b of eq. (6). Returns three (2, 2), (2, 2), (2,)
    arrays."""
    x = sim.state.copy() if x is None else np.asarray(x, float)
    u = sim.controls.copy() if u is None else np.asarray(u, float)
    cols = []
    for k in range(4):
        d = np.zeros(4)
        d[k] = h
        cols.append((_lateral_accelerations(sim, perturbed_state(x, *d), u)
                     - _lateral_accelerations(sim, perturbed_state(x, *(-d)), u)) / (2 * h))
    J = np.array(cols).T
    du = np.array([0.0, h])
    Bn = (_lateral_accelerations(sim, x, u + du) - _lateral_accelerations(sim, x, u - du)) / (2 * h)
    return J[:, 0:2], J[:, 2:4], Bn
