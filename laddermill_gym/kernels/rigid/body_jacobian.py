"""The bodies' own load derivatives as diagonal blocks: the second implicit part of the linearly implicit integrator
(``kernels/rigid/rosenbrock.py``, docs/numerics.md "A linearly implicit integrator").

A light wing in a strong wind has fast aerodynamic modes of its own: the heave damping rho S V C_L_alpha / (2 m)
and the short-period pitch mode reach tens to a hundred 1/s, beyond what an explicit stage can take at the steps
the cable's implicit treatment allows. Their loads depend only on the body's own velocities and attitude (and, weakly
through the wind profile, on its height, left out), so their Jacobian adds to the body's diagonal block only and
the block tree is unchanged. It is taken by forward differences of the vehicle's loads (``kernels/dispatch.py``
``body_loads``: the wing's aerodynamics, or the rotorcraft's rotors), so any vehicle is covered without a hand
derivation; the gravity's change with attitude is added in closed form. The integrator is a W-method, so a
difference approximation changes its stability, not its order.

Unstable diagonal terms are left out: a stalled wing's negative heave damping (dZ/dw > 0) or a divergent attitude
stiffness (dM_i/dtheta_i > 0) gives the body's own dynamics a positive eigenvalue lambda, and the iteration matrix
I - h gamma J is singular where h gamma lambda = 1 (the chain's apex wings after a disturbance: ROS2 blew up within
one 12.5 ms step at t = 8 s although RK4 follows them at 11 ms). Met explicitly, such a mode only needs the step
that resolves it.
"""


from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.contract import B3_QUAT, B3_SIZE, B3_VEL, GL_GRAVITY, TF_MASS, TM_DT, TM_T0
from laddermill_gym.kernels.dispatch import body_loads
from laddermill_gym.kernels.wind import modulation

_FM = {"contract", "nsz", "arcp"}
#: Relative difference step of the load derivatives (forward differences: the square root of the float64 epsilon)
DIFF_REL = 1.5e-8


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _loads(k, t, x, R, u, M, W, mods):
    """The vehicle's loads on body k at state x with rotation R (6 values, body axes)."""
    o = B3_SIZE * k + B3_VEL
    zd = R[2, 0] * x[o] + R[2, 1] * x[o + 1] + R[2, 2] * x[o + 2]
    env = (mods[0], mods[1], mods[2], mods[3], zd)
    return body_loads(M.vehicle, k, t, x, R, u, M, W, W.Y[0], env)  # Y[0]: scratch for the apparent mass


@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def add_body_jacobian(t, x, u, M, W, gh, gh2):
    """Subtract gh dL/dv + gh2 dL/dtheta from each body's diagonal block W.D[k] (L its loads: the vehicle's and
    gravity, body axes; v its 6 velocities; theta a small rotation in body axes [rad]) and keep dL/dtheta in
    W.kb[k] (6 x 3) [N/rad, N m/rad] for :func:`add_body_force`. x must hold the state whose rotations are in
    W.Rn; it is perturbed and restored. W.Rw, W.Y[0] and W.aout are scratch (W.Y has one block per body or node:
    a scene of one body has only W.Y[0])."""
    s_mod, d_mod, sd_mod, dd_mod = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    mods = (s_mod, d_mod, sd_mod, dd_mod)
    g = M.glob[GL_GRAVITY]
    for k in range(M.wtype.size):
        Rn = W.Rn[k]
        R = W.Rw[k]
        for i in range(3):
            for j in range(3):
                R[i, j] = Rn[i, j]
        base = _loads(k, t, x, R, u, M, W, mods)
        Dk = W.D[k]
        o = B3_SIZE * k + B3_VEL
        for j in range(6):
            v = x[o + j]
            h = DIFF_REL * max(1.0, abs(v))
            x[o + j] = v + h
            pert = _loads(k, t, x, R, u, M, W, mods)
            x[o + j] = v
            for i in range(6):
                d = (pert[i] - base[i]) / h
                if i != j or d < 0.0:  # a negative damping (a stalled wing's heave) is left explicit
                    Dk[i, j] -= gh * d
        kb = W.kb[k]
        for j in range(3):
            # R' = R (I + h e_j~): the body turned by h about its axis j
            h = DIFF_REL
            for i in range(3):
                c1 = Rn[i, (j + 1) % 3]
                c2 = Rn[i, (j + 2) % 3]
                R[i, (j + 1) % 3] = c1 + h * c2
                R[i, (j + 2) % 3] = c2 - h * c1
            pert = _loads(k, t, x, R, u, M, W, mods)
            for i in range(3):
                R[i, (j + 1) % 3] = Rn[i, (j + 1) % 3]
                R[i, (j + 2) % 3] = Rn[i, (j + 2) % 3]
            for i in range(6):
                kb[i, j] = (pert[i] - base[i]) / h
        # gravity m g R^T e_z in body axes turns with the body: d/dtheta = m g [g_b]x with g_b = R^T e_z
        mg = M.tf[M.wtype[k], TF_MASS] * g
        gx, gy, gz = Rn[2, 0], Rn[2, 1], Rn[2, 2]
        kb[0, 1] -= mg * gz
        kb[0, 2] += mg * gy
        kb[1, 0] += mg * gz
        kb[1, 2] -= mg * gx
        kb[2, 0] -= mg * gy
        kb[2, 1] += mg * gx
        for j in range(3):
            if kb[3 + j, j] > 0.0:  # a divergent attitude stiffness is left explicit (see the module docstring)
                kb[3 + j, j] = 0.0
        for i in range(6):
            for j in range(3):
                Dk[i, 3 + j] -= gh2 * kb[i, j]


# inlined into the W step (numba IR; called 3-4 times per step): inlining three such parts cut TetheredWing-v0's
# step from 7.1 to 6.3 us (2026-12-05; a slimmer argument list for add_stiffness_force instead gained nothing)
@callee_njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, inline="always")
def add_body_force(xn, rx, M, W, fac):
    """W.bv[k] += fac dL/dtheta dtheta for every body, dtheta = 2 vec(conj(q) dq) [rad] the small rotation of the
    state increment rx at the state xn (quaternion increment dq = rx's quaternion entries)."""
    for k in range(M.wtype.size):
        oq = B3_SIZE * k + B3_QUAT
        q0, q1, q2, q3 = xn[oq], xn[oq + 1], xn[oq + 2], xn[oq + 3]
        d0, d1, d2, d3 = rx[oq], rx[oq + 1], rx[oq + 2], rx[oq + 3]
        tx = 2.0 * (q0 * d1 - d0 * q1 - (q2 * d3 - q3 * d2))
        ty = 2.0 * (q0 * d2 - d0 * q2 - (q3 * d1 - q1 * d3))
        tz = 2.0 * (q0 * d3 - d0 * q3 - (q1 * d2 - q2 * d1))
        kb = W.kb[k]
        for i in range(6):
            W.bv[k, i] += fac * (kb[i, 0] * tx + kb[i, 1] * ty + kb[i, 2] * tz)

