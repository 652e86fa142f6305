"""Time integrators over the compiled right-hand sides: fixed-step classic RK4 (the paper's) and an
error-controlled Dormand-Prince 5(4) for reference solutions.

Status codes returned by the integrators: 0 ok, 1 singular mass matrix, 2 non-finite state,
3 a speed or rate limit exceeded, 4 a wing CG or free cable node at or below the ground height
(``limits[LIM_GROUND]``). On a non-zero status the state is left at the last good step.
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    BUDGET,
    GROUND,
    LIMIT,
    NONFINITE,
    OK,
    SINGULAR,
    STALLED,
)
from laddermill_gym.kernels.dispatch import model_check, model_rhs, model_rhs_entry

#: DP5(4) gives up (STALLED) when its step falls below this fraction of max(1 s, |t|): the error control is then
#: chasing a discontinuity or a stiff blow-up and would spin for ever.
H_MIN_REL = 1e-12

# _nrt=False on these kernels (and on the model kinds' rhs/check, kernels/rigid/kinds.py): they allocate nothing,
# and numba's reference counting of the packed model's arrays passed through them cost about 1.3 us per
# right-hand side of the rotorcraft (atomic increments and decrements; measured with a perf map, results bit
# for bit the same). A kernel that allocates must not carry the flag.


# rhs and normalise_and_check are inlined into jitted callers (one compiled layer less on the cold start, issue 32);
# called from Python they compile on their own, with these flags.
@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False, inline="always")
def rhs(t, x, u, dx, M, W):
    """State derivative of the packed model M (its kind chooses the right-hand side at compile time).
    Returns 0, or 1 if the mass matrix is singular."""
    return model_rhs(M.kind, t, x, u, dx, M, W)


# What Python calls (``Simulator.rhs``, the static equilibria and trims, the reports): the same derivative as rhs,
# the kind's right-hand side reached through its compiled address where the kind registered that (the rigid kinds,
# kernels/rigid/kinds.py), so that this entry compiles without linking the whole right-hand side again (issue 32)
@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def rhs_entry(t, x, u, dx, M, W):
    """:func:`rhs` for calls from Python: the state derivative of the packed model M into dx; 0, or 1 if the mass
    matrix is singular."""
    return model_rhs_entry(M.kind, t, x, u, dx, M, W)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False, inline="always")
def normalise_and_check(x, M, limits):
    """Normalise the state after a step as the model kind needs (quaternions) and check it against
    ``limits`` (``LIM_SPEED`` [m/s], ``LIM_RATE`` [rad/s], ``LIM_GROUND`` [m]). Returns a status code."""
    return model_check(M.kind, x, M, limits)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def _stage(t, x, a, k, xt, u, kout, M, W):
    """One explicit stage: kout = f(t, xt) at xt = x + a k; returns the right-hand side's 0 or 1 (singular)."""
    for i in range(x.size):
        xt[i] = x[i] + a * k[i]
    return rhs(t, xt, u, kout, M, W)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def rk4_advance(t, x, u, dt, n, M, W, limits, tableau=None):
    """Advance x in place by n classic RK4 steps of size dt. Returns (status, steps done). ``tableau`` is not
    read: the argument list is that of ``rosenbrock.w_advance``, so ``fixed_steps.advance_fixed`` can take either
    function as its implementation."""
    k1, k2, k3, k4, xt, xp = W.k1, W.k2, W.k3, W.k4, W.xt, W.xp
    ns = x.size
    h2 = 0.5 * dt
    h6 = dt / 6.0
    for step in range(n):
        for i in range(ns):
            xp[i] = x[i]
        if rhs(t, x, u, k1, M, W) != 0:
            return SINGULAR, step
        if _stage(t + h2, x, h2, k1, xt, u, k2, M, W) != 0:
            return SINGULAR, step
        if _stage(t + h2, x, h2, k2, xt, u, k3, M, W) != 0:
            return SINGULAR, step
        if _stage(t + dt, x, dt, k3, xt, u, k4, M, W) != 0:
            return SINGULAR, step
        for i in range(ns):
            x[i] += h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i])
        status = normalise_and_check(x, M, limits)
        if status != OK:
            for i in range(ns):
                x[i] = xp[i]
            return status, step
        t += dt
    return OK, n


# Dormand & Prince (1980) RK5(4)7M coefficients
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0,
                          22.0 / 525.0, -1.0 / 40.0)
C2, C3, C4, C5 = 0.2, 0.3, 0.8, 8.0 / 9.0


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def all_finite(v):
    """True if every entry of v is finite."""
    for i in range(v.size):
        if not (abs(v[i]) < math.inf):
            return False
    return True


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def _derivative(t, x, u, k, M, W):
    """k = f(t, x) at an accepted state: SINGULAR (mass matrix), NONFINITE (a non-finite derivative) or OK."""
    if rhs(t, x, u, k, M, W) != 0:
        return SINGULAR
    if not all_finite(k):
        return NONFINITE
    return OK


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def trial_step(t, t_end, h):
    """(h, the step to try from t [s], whether it is the last): h, unless it would leave a sliver before t_end
    (t + 1.01 h >= t_end); then t_end - t, stretched or cut to land there (as HNW's DOPRI5). The error-controlled
    methods keep h as their proposal after a last step (:func:`grown_step`)."""
    if t + 1.01 * h >= t_end:
        return h, t_end - t, True
    return h, h, False


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, inline="always", _nrt=False)
def grown_step(h, hp, err, expo, last):
    """The step [s] to try after an accepted step h [s] with error norm err: h min(5, max(0.2, 0.9 err^expo))
    (5 h at err = 0); after the ``last`` step, cut short to land on t_end, at least the proposal hp [s] (such a
    step says little about the next one)."""
    fac = min(5.0, max(0.2, 0.9 * err ** expo)) if err > 0.0 else 5.0
    if not last:
        return h * fac
    return max(hp, h * fac)


# dp54_advance is longer than 80 lines on purpose: the seven stages, the error norm and the step control share
# one loop over the workspace's stage vectors, and every stage returns its own status from inside that loop;
# split into helpers, each would have to hand a status and the step's state back through tuples.
@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def dp54_advance(t, t_end, x, u, h, rtol, atol, M, W, limits, max_steps):
    """Integrate x in place from t to t_end with adaptive Dormand-Prince 5(4) (local extrapolation).

    h is the first trial step [s]. Returns (status, accepted steps, rejected steps, step size [s], time [s]
    of x: t_end, or on a failure the time of the last accepted step, where x is left). The step size is, on a
    failure, that of the failed step; on success the step to try next: the controller's proposal, not the last
    step cut short to land on t_end (so a run continued in pieces, e.g. between output times, keeps its pace).
    The error norm is the RMS of err_i / (atol + rtol max(|x_i|, |x_new_i|)); steps are accepted when
    it is <= 1 and the next step is h * min(5, max(0.2, 0.9 err^(-1/5))). A non-finite trial stage is rejected
    like a large error; a non-finite derivative at an accepted state, which no smaller step can mend, returns
    NONFINITE at once.
    """
    k1, k2, k3, k4, k5, k6, k7, xt, xp = W.k1, W.k2, W.k3, W.k4, W.k5, W.k6, W.k7, W.xt, W.xp
    ns = x.size
    acc = 0
    rej = 0
    status = _derivative(t, x, u, k1, M, W)  # NONFINITE: at the accepted state no smaller step can help (issue 13)
    if status != OK:
        return status, acc, rej, h, t
    while t < t_end:
        if acc + rej >= max_steps:
            return BUDGET, acc, rej, h, t
        hp, h, last = trial_step(t, t_end, h)
        for i in range(ns):
            xt[i] = x[i] + h * A21 * k1[i]
        if rhs(t + C2 * h, xt, u, k2, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        for i in range(ns):
            xt[i] = x[i] + h * (A31 * k1[i] + A32 * k2[i])
        if rhs(t + C3 * h, xt, u, k3, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        for i in range(ns):
            xt[i] = x[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
        if rhs(t + C4 * h, xt, u, k4, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        for i in range(ns):
            xt[i] = x[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
        if rhs(t + C5 * h, xt, u, k5, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        for i in range(ns):
            xt[i] = x[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
        if rhs(t + h, xt, u, k6, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        for i in range(ns):
            xp[i] = x[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
        if rhs(t + h, xp, u, k7, M, W) != 0:
            return SINGULAR, acc, rej, h, t
        err = 0.0
        for i in range(ns):
            ei = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
            sc = atol + rtol * max(abs(x[i]), abs(xp[i]))
            err += (ei / sc) ** 2
        err = math.sqrt(err / ns)
        if not math.isfinite(err):
            err = 1e10
        if err <= 1.0:
            status = normalise_and_check(xp, M, limits)
            if status != OK:
                return status, acc, rej, h, t
            for i in range(ns):
                x[i] = xp[i]
            t = t_end if last else t + h
            acc += 1
            # first-same-as-last; after renormalisation re-evaluate for exactness
            status = _derivative(t, x, u, k1, M, W)
            if status != OK:
                return status, acc, rej, h, t
            h = grown_step(h, hp, err, -0.2, last)
        else:
            rej += 1
            h *= max(0.2, 0.9 * err ** -0.2)
            if h < H_MIN_REL * max(1.0, abs(t)):
                return STALLED, acc, rej, h, t
    return OK, acc, rej, h, t
