"""The envs' per-step read-outs in compiled code (issue 32 point 2): reward arguments, failure codes, the shaped
reward's terms, ``terminated`` and ``truncated`` of every copy, in one pass over the copies each, so that the
Python work of a vector step does not grow with the number of copies.

The arithmetic is that of the numpy code these kernels replace, operation for operation, so the rewards are bit
for bit those of before (tests/test_task_rewards.py holds them to a numpy reference):

* no fastmath (a fused multiply-add or a reordered sum would change last bits);
* a mean over fewer than 8 wings or actions is their sum in order from -0.0 divided by the count, which is what
  numpy's pairwise sum does below 8 entries (``pairwise_sum`` of ``loops_utils.h``); from 8 on (the 101-wing
  chain) numpy's 8-way interleaved sums differ, so the caller takes those means with numpy and passes them in
  (``means_given``): the chain's physics costs a millisecond per copy, its means a microsecond. Keeping numpy's
  order here instead would compile five more functions into every cold start (issue 32 point 1);
* the exponentials ``expm1`` of the shaped reward stay in numpy (:func:`shaped_terms`' caller): numpy evaluates
  them with its own SIMD library where the CPU has AVX-512 (SVML), which differs from the C library's ``expm1``
  in the last bit for about 1 % of arguments (measured on this machine: 9,607 of 800,000).

Serial kernels: a copy costs tens of nanoseconds here against 10-50 microseconds of physics (docs/benchmarks.md),
so a thread pool's start would cost more than the pass (512 copies: a few microseconds).
"""

import math

import numpy as np
from numba import njit

from laddermill_gym.kernels.contract import (
    AUX_GROUND_END,
    AUX_GROUND_START,
    AUX_MAX_TENSION,
    AUX_MIN_ALTITUDE,
    CA_ALTITUDE,
    CA_INFLOW_OK,
    CA_MAX_TENSION,
    CA_POWER,
    CA_TIP_AOA,
    CO_EULER,
    CO_OFFSET,
    CO_RATES,
    CO_THRUST,
    GROUND,
    OBS_ALPHA,
    OBS_BETA,
    OBS_OFFSET,
    OBS_RATES,
    OBS_SIZE,
    OK,
)

#: rows of the (3, B) argument block of the shaped reward's saturating terms S(x) = 1 - exp(-x)
ARG_LATERAL, ARG_RATES, ARG_EFFORT, N_ARGS = 0, 1, 2, 3
#: rows of the (5, B) terms block (the info keys ``reward_power`` ... ``reward_failure``, in the order summed)
TERM_POWER, TERM_LATERAL, TERM_RATES, TERM_EFFORT, TERM_FAILURE, N_TERMS = 0, 1, 2, 3, 4, 5
#: the info keys of those rows
TERM_KEYS = ("reward_power", "reward_lateral", "reward_rates", "reward_effort", "reward_failure")
#: largest finite float64 (numpy's ``nan_to_num`` puts it for +inf)
_BIG = np.finfo(np.float64).max
#: degrees per radian, as numpy's ``degrees`` multiplies (180 / pi in double precision)
_DEG = 180.0 / math.pi


#: below this many entries numpy's pairwise sum adds in order (the kernels' means; from it on the caller's numpy)
SEQUENTIAL_SUM = 8


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def wing_readout(obs, aux, status, a, nominal_action, nw, v_reel, power_weight, p_ref, lateral_scale, rate_scale2,
                 limits, means_given, power, p_term, neg_args, failure):
    """Per copy b of the wing task: ``power`` [W] (ground tension difference x reel speed ``v_reel`` [m/s]),
    ``p_term`` = power_weight power / p_ref, the negated arguments of the saturating terms into ``neg_args``
    (3, B) (mean over the ``nw`` wings of (dy / lateral_scale)^2 and of (p^2 + r^2) / rate_scale2, mean over the
    actions of (a - nominal_action)^2; left as they are when ``means_given``, which the caller sets from
    :data:`SEQUENTIAL_SUM` wings or actions on) and the failure code (``envs.task.FAILURES``: 4 alpha / beta out
    of range, 3 tension, 2 altitude, 1 integration, 2 ground contact; a later one wins). ``limits`` = (alpha_lo,
    alpha_hi, beta_max [rad], breaking tension [N], min altitude [m])."""
    alpha_lo, alpha_hi, beta_max, breaking, min_alt = limits[0], limits[1], limits[2], limits[3], limits[4]
    na = a.shape[1]
    for b in range(obs.shape[0]):
        pw = (aux[b, AUX_GROUND_START] - aux[b, AUX_GROUND_END]) * v_reel
        power[b] = pw
        p_term[b] = power_weight * pw / p_ref
        out_of_range = False
        lat, rates, effort = -0.0, -0.0, -0.0
        for k in range(nw):
            o = OBS_SIZE * k
            q = obs[b, o + OBS_OFFSET + 1] / lateral_scale
            lat += q * q
            p, r = obs[b, o + OBS_RATES], obs[b, o + OBS_RATES + 2]
            rates += (p * p + r * r) / rate_scale2
            al, be = obs[b, o + OBS_ALPHA], obs[b, o + OBS_BETA]
            if al < alpha_lo or al > alpha_hi or abs(be) > beta_max:
                out_of_range = True
        for j in range(na):
            d = a[b, j] - nominal_action[j]
            effort += d * d
        if not means_given:
            neg_args[ARG_LATERAL, b] = -(lat / nw)
            neg_args[ARG_RATES, b] = -(rates / nw)
            neg_args[ARG_EFFORT, b] = -(effort / na)
        code = 4 if out_of_range else 0
        if aux[b, AUX_MAX_TENSION] > breaking:
            code = 3
        if aux[b, AUX_MIN_ALTITUDE] < min_alt:
            code = 2
        if status[b] != OK:
            code = 2 if status[b] == GROUND else 1
        failure[b] = code


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def craft_readout(raw, aux, status, a, trim_action, v_ref, limits, power, p_term, neg_args, failure, tip):
    """Per copy b of the rotorcraft task (``envs.rotorcraft.task``; its 2 actions, under
    :data:`SEQUENTIAL_SUM`): ``power`` [W] (0 where not finite), ``p_term`` = power_weight power / p_ref,
    ``neg_args`` (3, B) as :func:`wing_readout` (nan observations taken as 0, +-inf as the largest float, as
    ``np.nan_to_num``), the failure code of ``CRAFT_FAILURES`` (5 attitude, 4 tension, 3 altitude, 2 inflow,
    integration 1 or 2, 3 ground contact; a later one wins; 6, a blade tip past its incidence limit, the first) and
    ``tip`` the larger retreating-tip incidence [rad] (nan if either is). ``v_ref`` = (power_weight, p_ref [W],
    lateral_scale [m], rate_scale^2 [rad^2/s^2]); ``limits`` = (max |roll|, pitch low, pitch high, max |yaw| [deg],
    breaking tension [N], min altitude [m], blade-incidence limit [rad], inf for none)."""
    power_weight, p_ref, lateral_scale, rate_scale2 = v_ref[0], v_ref[1], v_ref[2], v_ref[3]
    na = a.shape[1]
    for b in range(raw.shape[0]):
        pw = aux[b, CA_POWER]
        pw = pw if math.isfinite(pw) else 0.0
        power[b] = pw
        p_term[b] = power_weight * pw / p_ref
        q = _finite(raw[b, CO_OFFSET + 1]) / lateral_scale
        neg_args[ARG_LATERAL, b] = -(q * q)
        p, r = _finite(raw[b, CO_RATES]), _finite(raw[b, CO_RATES + 2])
        neg_args[ARG_RATES, b] = -((p * p + r * r) / rate_scale2)
        effort = -0.0
        for j in range(na):
            d = a[b, j] - trim_action[j]
            effort += d * d
        neg_args[ARG_EFFORT, b] = -(effort / na)
        phi, theta, psi = raw[b, CO_EULER] * _DEG, raw[b, CO_EULER + 1] * _DEG, raw[b, CO_EULER + 2] * _DEG
        t0, t1 = aux[b, CA_TIP_AOA], aux[b, CA_TIP_AOA + 1]
        tip[b] = math.nan if (t0 != t0 or t1 != t1) else max(t0, t1)
        code = 6 if tip[b] > limits[6] else 0
        if abs(phi) > limits[0] or not (limits[1] <= theta and theta <= limits[2]) or abs(psi) > limits[3]:
            code = 5
        if aux[b, CA_MAX_TENSION] > limits[4]:
            code = 4
        if aux[b, CA_ALTITUDE] < limits[5]:
            code = 3
        if not (math.isfinite(raw[b, CO_THRUST]) and math.isfinite(raw[b, CO_THRUST + 1])):
            code = 2
        if status[b] != OK:
            code = 3 if status[b] == GROUND else (1 if aux[b, CA_INFLOW_OK] == 1.0 else 2)
        failure[b] = code


@njit(cache=True, inline="always")
def _finite(v):
    """``np.nan_to_num`` of one float: 0 for nan, the largest finite float for +-inf (with its sign)."""
    if v != v:
        return 0.0
    if v == math.inf:
        return _BIG
    if v == -math.inf:
        return -_BIG
    return v


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def clip_rows(raw, low, high, out):
    """``out`` = ``raw`` (B, n) clipped to [low, high] (n,), a non-finite entry replaced by the bound on its side
    (nan: the upper), as ``envs.task_base.clip_observations`` does with numpy."""
    for b in range(raw.shape[0]):
        for i in range(raw.shape[1]):
            v = raw[b, i]
            if not math.isfinite(v):
                v = low[i] if v < 0 else high[i]
            m = v if v > low[i] else low[i]  # numpy's _NPY_CLIP: min(max(v, low), high), ties to the bound
            out[b, i] = m if m < high[i] else high[i]


@njit(cache=True, _nrt=True, fastmath=False, error_model="python")
def shaped_terms(p_term, e_args, failure, steps, weights, n_steps_max, terms, reward, terminated, truncated):
    """The shaped reward of every copy from ``p_term`` (B,), ``e_args`` (3, B) = expm1 of the negated arguments
    (numpy's), the failure codes and step counters (B,): terms (5, B) = (p_term, -w_y S_lat, -w_w S_rates,
    -w_u S_effort, -failure_penalty [terminated]) with S = -e_args (1, the full penalty, where an argument is nan:
    a state gone non-finite, as ``TaskCore.shaped_reward`` counts it), ``reward`` their sum in that order,
    ``terminated`` (failure != 0), ``truncated`` (steps >= n_steps_max and not terminated). ``weights`` =
    (w_y, w_w, w_u, failure_penalty) as numpy multiplied them: (-w) (-e) for each saturating term."""
    wl, wr, we, pen = weights[0], weights[1], weights[2], weights[3]
    for b in range(p_term.shape[0]):
        term = failure[b] != 0
        t0 = p_term[b]
        e_lat, e_rates = e_args[ARG_LATERAL, b], e_args[ARG_RATES, b]
        t1 = -wl * -(e_lat if e_lat == e_lat else -1.0)
        t2 = -wr * -(e_rates if e_rates == e_rates else -1.0)
        t3 = -we * -e_args[ARG_EFFORT, b]
        t4 = -pen * (1.0 if term else 0.0)
        terms[TERM_POWER, b], terms[TERM_LATERAL, b], terms[TERM_RATES, b] = t0, t1, t2
        terms[TERM_EFFORT, b], terms[TERM_FAILURE, b] = t3, t4
        reward[b] = (((t0 + t1) + t2) + t3) + t4
        terminated[b] = term
        truncated[b] = steps[b] >= n_steps_max and not term
