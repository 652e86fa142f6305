"""Batched stepping and observation of Roberts' craft for the rotorcraft environments: one pass over the copies
advances each by n RK4 steps of the core kernels and then writes its observation and the quantities the rewards
and terminations need (one compiled call per control period, like ``kernels/rigid/observe.py`` for the wings).

Observation row (``N_CRAFT_OBS`` float64, raw: non-finite entries kept, not clipped; the environment's
``CRAFT_OBS_FIELDS`` names them with units): CG offset from the nominal position (3, global) [m], CG velocity
(3, global) [m/s], 3-2-1 Euler angles (3) [rad], body rates (3) [rad/s], rotor thrust over its trim thrust (2,
right then left) [-], craft-end tether tension over its trim tension (3, rear right, rear left, front) [-],
blade collective pitch of each rotor (2) [rad].

Auxiliary row (``N_CRAFT_AUX`` float64, slots ``CA_*``): net electrical power [W], largest element tension [N]
and its element index, CG altitude [m], whether both rotors' inflow converged (1.0 / 0.0), rotor thrusts [N],
tether tensions [N] and retreating-tip incidences [rad]. The references of the ratios come in ``ref`` (slots
``REF_*``).
"""

import math

from numba import njit, prange, types

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.batch import advance_copy
from laddermill_gym.kernels.far_call import far_call
from laddermill_gym.kernels.integrate import rhs
from laddermill_gym.rotorcraft.rotor_kernels import STATUS_OK

#: The craft is rigid body 0 of its assembly.
CRAFT_BODY = 0
#: Rotors and tethers of the craft.
N_ROTORS, N_TETHERS = 2, 3



# Inlined into both step-and-observe kernels (the same flags, no fastmath): one compile of about 3.5 s of CPU less in
# a cold start (issue 32)
@njit(cache=True, error_model="numpy", inline="always")
def _observe_craft(t, x, u, dx, M, W, cp, ref, tether_end, obs, aux):
    """Observation ``obs`` (N_CRAFT_OBS,) and auxiliary row ``aux`` (N_CRAFT_AUX,) of the state x at time t [s]
    (evaluates the right-hand side once for the rotation, the tensions and the rotor outputs). cp: the craft
    parameters (``craft_kernels.C_*``); tether_end (3,): the element at the craft end of each tether.
    Returns OK or SINGULAR (the mass matrix; the loads and tensions are written before the solve)."""
    status = C.OK if rhs(t, x, u, dx, M, W) == 0 else C.SINGULAR
    o = C.B3_SIZE * CRAFT_BODY
    R = W.Rw[CRAFT_BODY]
    vx, vy, vz = x[o + C.B3_VEL], x[o + C.B3_VEL + 1], x[o + C.B3_VEL + 2]
    for i in range(3):
        obs[C.CO_OFFSET + i] = x[o + C.B3_POS + i] - ref[C.REF_POSITION + i]
        obs[C.CO_VELOCITY + i] = R[i, 0] * vx + R[i, 1] * vy + R[i, 2] * vz
        obs[C.CO_RATES + i] = x[o + C.B3_RATE + i]
    obs[C.CO_EULER] = math.atan2(R[2, 1], R[2, 2])
    obs[C.CO_EULER + 1] = -math.asin(min(1.0, max(-1.0, R[2, 0])))
    obs[C.CO_EULER + 2] = math.atan2(R[1, 0], R[0, 0])
    out = W.vout
    power = 0.0
    inflow_ok = 1.0
    for r in range(N_ROTORS):
        k = C.V_ROTOR + C.N_RO * r
        obs[C.CO_THRUST + r] = out[k + C.R_THRUST] / ref[C.REF_THRUST + r]
        obs[C.CO_PITCH + r] = out[k + C.R_THETA]
        aux[C.CA_THRUST + r] = out[k + C.R_THRUST]
        aux[C.CA_TIP_AOA + r] = out[k + C.R_TIP_AOA]
        power += out[k + C.R_POWER]
        if out[k + C.R_STATUS] != STATUS_OK:
            inflow_ok = 0.0
    ten = W.tension
    for i in range(N_TETHERS):
        obs[C.CO_TENSION + i] = ten[tether_end[i]] / ref[C.REF_TENSION + i]
        aux[C.CA_TENSION + i] = ten[tether_end[i]]
    tmax, emax = ten[0], 0
    for e in range(1, M.ek.shape[0]):
        if ten[e] > tmax:
            tmax, emax = ten[e], e
    eta = cp[C.C_ETA]
    aux[C.CA_POWER] = eta * power if power >= 0.0 else power / eta
    aux[C.CA_MAX_TENSION] = tmax
    aux[C.CA_MAX_ELEMENT] = emax
    aux[C.CA_ALTITUDE] = -x[o + C.B3_POS + 2]
    aux[C.CA_INFLOW_OK] = inflow_ok
    return status


# inlined into the step kernel (the same flags)
@njit(cache=True, error_model="numpy", inline="always")
def _craft_step_observe_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, ref,
                             tether_end, obs, aux, status, done):
    run, st, dn, Mb, Wb = advance_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks)
    if run:
        ost = _observe_craft(t[b] + dn * dt, X[b], U[b], DX[b], Mb, Wb, vehicle.cp, ref, tether_end, obs[b], aux[b])
        st = st if st != C.OK else ost
    status[b] = st
    done[b] = dn


# Without numba's runtime (_nrt=False): no reference counting of the per-copy array views (about 60 per copy and
# step; 7-8 % of TetheredWing-v0's vector step went to the atomic counts, issue 32). The copy's gust grid rows come
# through kernels/batch.copy_air_model, not a function that returns a view (numba forbids that without its runtime:
# c2dd978, 45dd361 had reverted this for it). nogil: the vector envs run it on several threads, each on its own range
# of copies (envs/copy_threads.py), instead of a numba prange kernel that compiled the step a second time.
@njit(cache=True, error_model="numpy", _nrt=False, nogil=True, fastmath=False)
def craft_step_observe_serial(t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, ref,
                              tether_end, obs, aux, status, done, first, last):
    """Advance copies b = first, ..., last - 1 by nsteps[b] fixed steps of dt [s] (``tableau`` and ``breaks`` as in
    ``kernels/rigid/observe.step_observe_serial``), then observe each (nsteps[b] = 0: observe only; < 0: skip the
    copy), on the calling thread (``envs/copy_threads.CopyThreads`` splits the copies over threads).

    t (B,) [s] is each copy's time before the steps (not advanced here); X (B, n_state), U (B, 2) [rad]
    (collective, differential); M the packed craft model without its markers, passed as ``kind`` and
    ``vehicle`` (``kernels.batch.detach_markers``); WB a KWork with a leading batch axis; AB the copies' air, a
    KAir with a leading copy axis (the batch's ``air``: wind modulation and gust grid); limits (LIM_SIZE,);
    DX (B, n_state) scratch; ref (REF_SIZE,) references; tether_end (3,) int64. Writes rows first..last-1 of obs
    (B, N_CRAFT_OBS), aux (B, N_CRAFT_AUX), status (B,) (integrate.py's codes) and done (B,) (steps completed). A
    copy whose integration fails is left at its last good state and observed there.
    """
    for b in range(first, last):
        _craft_step_observe_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, ref,
                                 tether_end, obs, aux, status, done)


_STEP_FAR = far_call(craft_step_observe_serial, types.none)


# The vector envs' launcher on several threads, as kernels/rigid/observe.launch_step_observe: numba's thread pool
# runs the ranges, each calling the kernel above through its address (the same bits on any thread count).
@njit(cache=True, parallel=True, nogil=True, _nrt=True, fastmath=False, error_model="python")
def launch_craft_step_observe(bounds, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, ref,
                              tether_end, obs, aux, status, done):
    """:func:`craft_step_observe_serial` on the copy ranges ``bounds`` (n_ranges, 2) int64 of (first, last) rows,
    the ranges in parallel on numba's threads; the other arguments are the kernel's, without its first and last."""
    for r in prange(bounds.shape[0]):
        _STEP_FAR(t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, ref, tether_end, obs,
                  aux, status, done, bounds[r, 0], bounds[r, 1])
