"""Batched stepping and observation for the environments: one pass over a range of copies advances each by
n RK4 steps and then writes its wing observations and the quantities the rewards and terminations need;
:func:`observe_state` observes one state with the same code (the task's trim, and
``control.base.observe`` on a ``Simulator``). This is the only implementation of the wing observation. The step
kernels read a state's tensions and rotations through ``kernels.dispatch.model_tensions`` (no wing aerodynamics, no
solve; ``observe_state`` runs the whole right-hand side: the same bits, tests/test_observation_tensions.py).

Observation layout per wing (15 floats, ``laddermill_gym/envs/observation.py`` documents it with units):
CG offset from the nominal position (3), global CG velocity (3), 3-2-1 Euler angles (3), body rates (3),
angle of attack, sideslip, tension of the element below the wing. 3D scenes only.
"""

import math

from numba import njit, prange, types

from laddermill_gym.kernels.batch import advance_copy
from laddermill_gym.kernels.contract import (  # noqa: F401 (read as attributes of this module)
    AUX_GROUND_END,
    AUX_GROUND_START,
    AUX_MAX_TENSION,
    AUX_MIN_ALTITUDE,
    B3_POS,
    B3_RATE,
    B3_SIZE,
    B3_VEL,
    N_AUX,
    OBS_ALPHA,
    OBS_BETA,
    OBS_EULER,
    OBS_OFFSET,
    OBS_RATES,
    OBS_SIZE,
    OBS_TENSION,
    OBS_VELOCITY,
    OK,
    SINGULAR,
    TM_DT,
    TM_T0,
)
from laddermill_gym.kernels.dispatch import model_tensions
from laddermill_gym.kernels.far_call import far_call
from laddermill_gym.kernels.integrate import rhs
from laddermill_gym.kernels.wind import modulation, wind_point

_FM = {"contract", "nsz", "arcp"}


# inlined into observe_state and the step-and-observe kernels (same flags): one compiled layer less (issue 32)
@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _observe_one(t, x, u, dx, M, W, nominal, below, ground, obs, aux):
    """Observation row ``obs`` (n_wings * 15,) and ``aux`` (N_AUX,) of one state (evaluates the right-hand
    side once for the tensions). Returns OK or SINGULAR."""
    if rhs(t, x, u, dx, M, W) != 0:
        return SINGULAR
    _observe_rows(t, x, M, W, nominal, below, ground, obs, aux)
    return OK


# the step kernels' observation: the tensions and rotations without the whole right-hand side where the kind has
# them (kernels/rigid/kinds.py rigid3d_tensions: the same bits, a third of the time), else the right-hand side
@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _observe_stepped(t, x, u, dx, M, W, nominal, below, ground, obs, aux):
    if model_tensions(M.kind, t, x, u, dx, M, W) != 0:
        return SINGULAR
    _observe_rows(t, x, M, W, nominal, below, ground, obs, aux)
    return OK


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _observe_rows(t, x, M, W, nominal, below, ground, obs, aux):
    """``obs`` and ``aux`` of the state x from the tensions W.tension and rotations W.Rw left at it."""
    nw = M.wtype.size
    s, d, _, _ = modulation(t, M.tmod[TM_T0], M.tmod[TM_DT], M.ms, M.md)
    ten = W.tension
    zmin = math.inf
    for k in range(nw):
        o = B3_SIZE * k
        b = OBS_SIZE * k
        R = W.Rw[k]  # filled by rhs at this state
        ov = o + B3_VEL
        vx, vy, vz = x[ov], x[ov + 1], x[ov + 2]
        for i in range(3):
            obs[b + OBS_OFFSET + i] = x[o + B3_POS + i] - nominal[k, i]
            obs[b + OBS_VELOCITY + i] = R[i, 0] * vx + R[i, 1] * vy + R[i, 2] * vz
            obs[b + OBS_RATES + i] = x[o + B3_RATE + i]
        obs[b + OBS_EULER] = math.atan2(R[2, 1], R[2, 2])
        obs[b + OBS_EULER + 1] = -math.asin(min(1.0, max(-1.0, R[2, 0])))
        obs[b + OBS_EULER + 2] = math.atan2(R[1, 0], R[0, 0])
        z = x[o + B3_POS + 2]
        wx, wy, wz = wind_point(x[o + B3_POS], x[o + B3_POS + 1], z, t, M.wf, s, d, M.gp, M.gv)
        ua = vx - (R[0, 0] * wx + R[1, 0] * wy + R[2, 0] * wz)
        va = vy - (R[0, 1] * wx + R[1, 1] * wy + R[2, 1] * wz)
        wa = vz - (R[0, 2] * wx + R[1, 2] * wy + R[2, 2] * wz)
        sp = math.sqrt(ua * ua + va * va + wa * wa)
        obs[b + OBS_ALPHA] = math.atan2(wa, ua)
        obs[b + OBS_BETA] = math.asin(min(1.0, max(-1.0, va / sp))) if sp > 0.0 else 0.0
        obs[b + OBS_TENSION] = ten[below[k]]
        zmin = min(zmin, -z)
    tmax = 0.0
    for e in range(M.ek.shape[0]):
        tmax = max(tmax, ten[e])
    aux[AUX_MAX_TENSION] = tmax
    aux[AUX_GROUND_START] = ten[ground[0]] if ground[0] >= 0 else 0.0
    aux[AUX_GROUND_END] = ten[ground[1]] if ground[1] >= 0 else 0.0
    aux[AUX_MIN_ALTITUDE] = zmin


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def observe_state(t, x, u, M, W, nominal, below, ground, obs, aux):
    """Observation of one 3D state: the single-state entry point of the kernel the batched envs use.

    t [s]; x (n_state,) 3D state; u (3 n_wings,) controls [rad]; M the packed model with its markers (a
    ``Simulator``'s ``model``; its own wind modulation ``tmod``, ``ms``, ``md`` is the one observed); W its
    workspace (``W.k1``, the integrators' first stage, serves as the derivative scratch: free between
    integrator calls); nominal (n_wings, 3) [m] CG positions the offsets are taken from; below (n_wings,)
    int64 element below each wing; ground (2,) int64 ground elements (start, end; -1 if none).

    Writes obs (15 n_wings,) in the ``OBS_*`` layout of ``kernels/contract.py`` (names and units:
    ``envs.observation.OBS_FIELDS``) and aux (N_AUX,) (``AUX_*`` columns), and the element tensions
    ``W.tension`` [N] and body rotations ``W.Rw`` of the state. Returns OK, or SINGULAR if the mass matrix is
    singular (obs and aux then untouched). 3D models only: the caller checks the kind.
    """
    return _observe_one(t, x, u, W.k1, M, W, nominal, below, ground, obs, aux)


# inlined into the step kernel (the same flags)
@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def _step_observe_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, nominal, below,
                       ground, obs, aux, status, done):
    run, st, dn, Mb, Wb = advance_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks)
    if run:
        ost = _observe_stepped(t[b] + dn * dt, X[b], U[b], DX[b], Mb, Wb, nominal, below, ground, obs[b], aux[b])
        st = st if st != OK else ost
    status[b] = st
    done[b] = dn


# Without numba's runtime (_nrt=False): no reference counting of the per-copy array views (about 60 per copy and
# step; 7-8 % of TetheredWing-v0's vector step went to the atomic counts, issue 32). The copy's gust grid rows come
# through kernels/batch.copy_air_model, not a function that returns a view (numba forbids that without its runtime:
# c2dd978, 45dd361 had reverted this for it). nogil: the vector envs run it on several threads at once, each on its
# own range of copies (envs/copy_threads.py). A numba prange kernel around the same copy step took 165 s of CPU to
# compile on top of this one (its parallel lowering re-analyses and re-optimises the whole inlined step); the
# vector envs now run the kernel the single env compiled.
@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False, nogil=True)
def step_observe_serial(t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, nominal, below,
                        ground, obs, aux, status, done, first, last):
    """Advance copies b = first, ..., last - 1 by nsteps[b] steps of the fixed-step method (RK4 when ``tableau`` is
    None, else that Rosenbrock-W method; steps meet the kinks of the copy's wind as ``breaks`` says,
    ``kernels/fixed_steps.py``), then observe each (nsteps[b] = 0: observe only; < 0: skip the copy), on the
    calling thread (``envs/copy_threads.CopyThreads`` splits the copies over threads).

    t (B,) [s] is each copy's time before the steps (not advanced here); X (B, n_state), U (B, n_controls);
    per-copy air AB (a ``KAir`` of arrays with a leading copy axis: wind modulation and gust grid); WB a KWork
    with a leading batch axis; DX (B, n_state) scratch; nominal (n_wings, 3) [m]; below (n_wings,) element below
    each wing; ground (2,) ground elements (start, end; -1 if none). M comes without its markers, passed as
    ``kind`` and ``vehicle`` (``kernels.batch.detach_markers``). Writes rows first..last-1 of obs (B, 15 n_wings),
    aux (B, N_AUX), status (B,) and done (B,) (steps completed). A copy whose integration fails is left at its last
    good state and observed there.
    """
    for b in range(first, last):
        _step_observe_copy(b, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, nominal,
                           below, ground, obs, aux, status, done)


_STEP_FAR = far_call(step_observe_serial, types.none)


# The vector envs' launcher on several threads: numba's thread pool runs the ranges, each calling the kernel above
# through its address (kernels/far_call.py), so this compiles only the loop (about 3-7 s) and each copy's arithmetic
# is the kernel's own: the same bits on any thread count (envs/copy_threads.py says why not Python threads).
@njit(cache=True, parallel=True, nogil=True, _nrt=True, fastmath=False, error_model="python")
def launch_step_observe(bounds, t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, nominal,
                        below, ground, obs, aux, status, done):
    """:func:`step_observe_serial` on the copy ranges ``bounds`` (n_ranges, 2) int64 of (first, last) rows, the
    ranges in parallel on numba's threads; the other arguments are the kernel's, without its first and last."""
    for r in prange(bounds.shape[0]):
        _STEP_FAR(t, X, U, dt, nsteps, M, kind, vehicle, WB, AB, limits, tableau, breaks, DX, nominal, below, ground,
                  obs, aux, status, done, bounds[r, 0], bounds[r, 1])
