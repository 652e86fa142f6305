"""Loads on Roberts' tethered twin-rotor craft: two rotors side by side, vertical fins and frame drag.

The craft is body 0 of an ordinary 3D assembly (its tethers are the core's cable elements). Its packed model
names the vehicle :class:`CraftVehicle` ``(cp, rp)``, registered here with ``kernels/dispatch.py``, so the
generic rigid-body right-hand side takes the craft's loads from :func:`craft_body_loads` without importing this
module. Model and sources: ``laddermill_gym/docs/rotorcraft.md``; rotor formulas: ``rotorcraft/rotor_kernels.py``.

:func:`craft_loads` takes a tuple of four float64 arrays ``(cp, rp, cout, scratch)``; the last two are the
workspace's ``vout`` and ``vscratch`` (one per batched copy):

- ``cp[N_CP]``: craft parameters, indices C_* below (SI units, body axes x forward, y right, z down).
- ``rp[rotor.N_PARAMS]``: blade parameters (sigma, a, delta, B, gamma) as in ``rotorcraft/rotor_kernels.py``.
- ``cout[N_COUT]``: written on every call: body-frame force [N] (slots V_FORCE..+2) and moment [N m]
  (V_MOMENT..+2) on the craft, then per rotor r (right r = 0, left r = 1) the block at V_ROTOR + N_RO r: R_*
  indices.
- ``scratch[rotor.N_OUT]``: the inflow solver's output.

Controls: u[0] collective pitch theta0 [rad], u[1] differential collective dtheta [rad]: the right rotor
runs at theta0 + dtheta, the left at theta0 - dtheta.
"""

import math
from collections import namedtuple

from numba import njit

from laddermill_gym.kernels.callee_jit import callee_njit
from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    B3_POS,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    C_DRAG_AREA,
    C_ETA,
    C_FIN_AREA,
    C_FIN_SLOPE,
    C_FIN_X,
    C_FIN_Z,
    C_HUB_X,
    C_HUB_Y,
    C_HUB_Z,
    C_MAX_ITER,
    C_OMEGA,
    C_RADIUS,
    C_TOL,
    CU_COLLECTIVE,
    CU_DIFFERENTIAL,
    N_COUT,
    N_CP,
    N_RO,
    R_CT,
    R_HFORCE,
    R_LAMBDA,
    R_MU,
    R_POWER,
    R_STATUS,
    R_THETA,
    R_THRUST,
    R_TIP_AOA,
    R_TORQUE,
    V_FORCE,
    V_MOMENT,
    V_ROTOR,
)
from laddermill_gym.kernels.dispatch import register_vehicle
from laddermill_gym.kernels.wind import density, wind_point
from laddermill_gym.rotorcraft.rotor_kernels import (
    O_CT,
    O_LAMBDA,
    O_STATUS,
    P_A,
    P_B,
    P_DELTA,
    P_GAMMA,
    P_SIGMA,
    STATUS_OK,
    coning_angle,
    h_force_coefficient,
    lateral_flapping,
    longitudinal_flapping,
    solve_inflow,
    tip_incidence,
    torque_coefficient,
)

#: spin sense of the rotors about body -z (right rotor +1, left rotor -1: contra-rotating)
SPIN = (1.0, -1.0)


@callee_njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _air_at(x, o, R, px, py, pz, t, M, s_mod, d_mod):
    """Air velocity relative to the body point (px, py, pz) [m] in body axes [m/s], and the density there."""
    vx, vy, vz = x[o + B3_VEL], x[o + B3_VEL + 1], x[o + B3_VEL + 2]
    p, q, r = x[o + B3_RATE], x[o + B3_RATE + 1], x[o + B3_RATE + 2]
    zg = x[o + B3_POS + 2] + R[2, 0] * px + R[2, 1] * py + R[2, 2] * pz
    xg = x[o + B3_POS] + R[0, 0] * px + R[0, 1] * py + R[0, 2] * pz
    yg = x[o + B3_POS + 1] + R[1, 0] * px + R[1, 1] * py + R[1, 2] * pz
    wgx, wgy, wgz = wind_point(xg, yg, zg, t, M.wf, s_mod, d_mod, M.gp, M.gv)
    ax = R[0, 0] * wgx + R[1, 0] * wgy + R[2, 0] * wgz - (vx + q * pz - r * py)
    ay = R[0, 1] * wgx + R[1, 1] * wgy + R[2, 1] * wgz - (vy + r * px - p * pz)
    az = R[0, 2] * wgx + R[1, 2] * wgy + R[2, 2] * wgz - (vz + p * py - q * px)
    return ax, ay, az, density(-zg, M.wf)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _rotor(cp, rp, scratch, ax, ay, az, rho, theta0, out, k):
    """One rotor in the relative air velocity (ax, ay, az) [m/s, body axes] at its hub.

    Writes the R_* block at out[k:]; returns the body force (thrust along -z, H-force along the in-plane air
    flow) [N] and the torque the rotor's generator puts on the frame about body z [N m] (before the spin sign).
    """
    rad, om = cp[C_RADIUS], cp[C_OMEGA]
    vt = om * rad
    vip = math.sqrt(ax * ax + ay * ay)
    mu = max(vip / vt, 1e-9)
    lam_inf = -az / vt
    solve_inflow(rp, mu, lam_inf, theta0, cp[C_TOL], int(cp[C_MAX_ITER]), scratch)
    out[k + R_STATUS] = scratch[O_STATUS]
    out[k + R_THETA] = theta0
    out[k + R_MU] = mu
    if scratch[O_STATUS] != STATUS_OK:
        for j in (R_THRUST, R_HFORCE, R_TORQUE, R_POWER, R_LAMBDA, R_CT, R_TIP_AOA):
            out[k + j] = math.nan
        return math.nan, math.nan, math.nan, math.nan
    lam, ct = scratch[O_LAMBDA], scratch[O_CT]
    sigma, a, delta, b, gamma = rp[P_SIGMA], rp[P_A], rp[P_DELTA], rp[P_B], rp[P_GAMMA]
    a0 = coning_angle(gamma, mu, lam, theta0)
    a1 = longitudinal_flapping(mu, lam, theta0)
    b1 = lateral_flapping(mu, a0)
    ch = h_force_coefficient(sigma, a, delta, b, mu, lam, theta0, a0, a1, b1)
    cq = torque_coefficient(sigma, delta, mu, lam, ct, ch)
    f = rho * math.pi * rad * rad * vt * vt
    thrust, hforce, torque = f * ct, f * ch, f * rad * cq
    out[k + R_THRUST] = thrust
    out[k + R_HFORCE] = hforce
    out[k + R_TORQUE] = torque
    out[k + R_POWER] = -torque * om
    out[k + R_LAMBDA] = lam
    out[k + R_CT] = ct
    out[k + R_TIP_AOA] = tip_incidence(theta0, mu, lam, a1)
    ux, uy = (ax / vip, ay / vip) if vip > 0.0 else (0.0, 0.0)
    return hforce * ux, hforce * uy, -thrust, torque


@callee_njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def craft_loads(x, o, R, u, t, M, s_mod, d_mod, craft):
    """Aerodynamic and generator loads on the craft (body o of state x, rotation R) into craft[2][0:6], in the
    wind of the packed model M at time t [s] (speed factor s_mod, direction offset d_mod, its gust grid).

    Rotors at body (hub_x, +-hub_y, hub_z); quasi-steady Gessow & Myers rotor with Glauert inflow at each
    hub's own relative air velocity (so roll rate gives differential inflow: the rotors' roll damping);
    generator holds the rotor speed, so its reaction torque on the frame equals the rotor's torque. Fins:
    side force 1/2 rho S a_f |u_x| u_y at (fin_x, 0, fin_z). Frame drag 1/2 rho C_D A |u| u at the CG.
    Returns False if an inflow did not converge (loads then nan).
    """
    cp, rp, out, scratch = craft[0], craft[1], craft[2], craft[3]
    fx = fy = fz = mx = my = mz = 0.0
    ok = True
    for r in range(2):
        spin = SPIN[r]
        hx, hy, hz = cp[C_HUB_X], cp[C_HUB_Y] if r == 0 else -cp[C_HUB_Y], cp[C_HUB_Z]
        ax, ay, az, rho = _air_at(x, o, R, hx, hy, hz, t, M, s_mod, d_mod)
        theta = u[CU_COLLECTIVE] + u[CU_DIFFERENTIAL] if r == 0 else u[CU_COLLECTIVE] - u[CU_DIFFERENTIAL]
        k = V_ROTOR + N_RO * r
        gx, gy, gz, torque = _rotor(cp, rp, scratch, ax, ay, az, rho, theta, out, k)
        if out[k + R_STATUS] != STATUS_OK:
            ok = False
        fx += gx
        fy += gy
        fz += gz
        mx += hy * gz - hz * gy
        my += hz * gx - hx * gz
        mz += hx * gy - hy * gx + spin * torque
    # fins
    px, pz = cp[C_FIN_X], cp[C_FIN_Z]
    ax, ay, az, rho = _air_at(x, o, R, px, 0.0, pz, t, M, s_mod, d_mod)
    side = 0.5 * rho * cp[C_FIN_AREA] * cp[C_FIN_SLOPE] * abs(ax) * ay
    fy += side
    mx -= pz * side
    mz += px * side
    # frame drag at the CG
    ax, ay, az, rho = _air_at(x, o, R, 0.0, 0.0, 0.0, t, M, s_mod, d_mod)
    k = 0.5 * rho * cp[C_DRAG_AREA] * math.sqrt(ax * ax + ay * ay + az * az)
    fx += k * ax
    fy += k * ay
    fz += k * az
    out[V_FORCE], out[V_FORCE + 1], out[V_FORCE + 2] = fx, fy, fz
    out[V_MOMENT], out[V_MOMENT + 1], out[V_MOMENT + 2] = mx, my, mz
    return ok


#: The rotorcraft vehicle of a packed model: craft parameters ``cp`` (N_CP) and blade parameters ``rp``.
CraftVehicle = namedtuple("CraftVehicle", ["cp", "rp"])


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always")
def craft_body_loads(vehicle, k, t, x, R, u, M, W, Dk, env):
    """The body-loads plug-in (``kernels/dispatch.py``): the craft's loads on body k, body axes [N, N m];
    rotor outputs left in ``W.vout`` (layout of ``cout`` above)."""
    craft_loads(x, B3_SIZE * k, R, u, t, M, env[0], env[1], (vehicle.cp, vehicle.rp, W.vout, W.vscratch))
    co = W.vout
    return (co[V_FORCE], co[V_FORCE + 1], co[V_FORCE + 2], co[V_MOMENT], co[V_MOMENT + 1],
            co[V_MOMENT + 2])


register_vehicle(CraftVehicle, craft_body_loads)
