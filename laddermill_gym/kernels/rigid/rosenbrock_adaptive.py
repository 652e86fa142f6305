"""The Rosenbrock-W methods with error control: the step is chosen by accuracy alone.

``kernels/rigid/rosenbrock.py`` gives each method an embedded solution y_hat = y0 + sum mhat_i U_i of one order
less (ROS34PW2: order 2, Rang & Angermann 2005; ROS2: the linearly implicit Euler step). Their difference is
the local error estimate of the lower order; the step is accepted when its RMS norm

    err = sqrt(mean_i (e_i / (atol + rtol max(|x0_i|, |x1_i|)))^2) <= 1

and the next step is h min(5, max(0.2, 0.9 err^(-1/(q+1)))) with q the embedded order (the controller of
``kernels/integrate.py`` ``dp54_advance``, Hairer, Norsett & Wanner I, sect. II.4). A step whose new state fails
the model kind's check for a non-finite entry or a speed or rate beyond the limits is rejected and retried at a
quarter of its size: with a Jacobian frozen over the step, a violent event (a slack cable pulled taut at the
chain's apex) can throw a large step out where a smaller one follows it. A ground contact is physical and ends
the run at once. The run gives up (STALLED) when the step falls below ``H_MIN_REL`` max(1 s, |t|).
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import BUDGET, GROUND, LIMIT, NONFINITE, OK, SINGULAR, STALLED
from laddermill_gym.kernels.dispatch import model_check
from laddermill_gym.kernels.integrate import H_MIN_REL, all_finite, grown_step, trial_step
from laddermill_gym.kernels.rigid.rosenbrock import w_step

_FM = {"contract", "nsz", "arcp"}


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _error_norm(x, xp, W, m, mhat, rtol, atol):
    """RMS of the embedded error estimate sum (m_i - mhat_i) U_i, scaled by atol + rtol max(|x0|, |x1|)."""
    stages = (W.k1, W.k2, W.k3, W.k4)
    s = m.size
    acc = 0.0
    for i in range(x.size):
        e = 0.0
        for j in range(s):
            e += (m[j] - mhat[j]) * stages[j][i]
        sc = atol + rtol * max(abs(xp[i]), abs(x[i]))
        acc += (e / sc) ** 2
    err = math.sqrt(acc / x.size)
    return err if math.isfinite(err) else 1e10


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def w_adaptive(t, t_end, x, u, h, rtol, atol, M, W, limits, max_steps, tableau, q):
    """Integrate x in place from t to t_end [s] with the Rosenbrock-W method ``tableau`` under error control
    (embedded order q). h is the first trial step [s]. Returns (status, accepted steps, rejected steps, step size
    [s]: the failed step's on a failure, else the proposal for the next step as in ``dp54_advance``, time [s] of
    x: t_end, or on a failure the time of the last accepted step, where x is left)."""
    m, mhat = tableau[4], tableau[5]
    ns = x.size
    xp = W.xp
    acc = 0
    rej = 0
    expo = -1.0 / (q + 1.0)
    if not all_finite(x):  # no smaller step mends a non-finite state: stop at once (as dp54_advance)
        return NONFINITE, acc, rej, h, t
    while t < t_end:
        if acc + rej >= max_steps:
            return BUDGET, acc, rej, h, t
        hp, h, last = trial_step(t, t_end, h)
        if w_step(t, x, u, h, M, W, tableau) != OK:
            return SINGULAR, acc, rej, h, t
        err = _error_norm(x, xp, W, m, mhat, rtol, atol)
        status = OK
        if err <= 1.0:
            status = model_check(M.kind, x, M, limits)
            if status == GROUND:
                for i in range(ns):
                    x[i] = xp[i]
                return GROUND, acc, rej, h, t
        if err <= 1.0 and status == OK:
            t = t_end if last else t + h
            acc += 1
            h = grown_step(h, hp, err, expo, last)
        else:
            for i in range(ns):
                x[i] = xp[i]
            rej += 1
            if status == LIMIT or status == NONFINITE:
                h *= 0.25
            else:
                h *= max(0.2, 0.9 * err ** expo)
            if h < H_MIN_REL * max(1.0, abs(t)):
                return STALLED if status == OK else status, acc, rej, h, t
    return OK, acc, rej, h, t
