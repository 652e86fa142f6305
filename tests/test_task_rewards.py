"""The compiled per-step read-outs (``kernels/task_rewards.py``, issue 32 point 2) against a numpy reference: the
numpy code the wing and rotorcraft tasks ran before (written out here, term by term), on random observations
with nan and inf entries, failures of every kind, 1 to 101 wings and 2 to 303 actions (from 8 on, numpy's means
passed in, as the wing task does). Bit for bit: the kernels
promise the rewards of before, not rewards within a tolerance."""

from __future__ import annotations

import numpy as np
import pytest

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
    N_AUX,
    N_CRAFT_AUX,
    N_CRAFT_OBS,
    OBS_ALPHA,
    OBS_BETA,
    OBS_OFFSET,
    OBS_RATES,
    OBS_SIZE,
    OK,
    SINGULAR,
)
from laddermill_gym.kernels.task_rewards import (
    N_ARGS,
    N_TERMS,
    SEQUENTIAL_SUM,
    TERM_KEYS,
    clip_rows,
    craft_readout,
    shaped_terms,
)
from laddermill_gym.kernels.task_rewards import wing_readout as wing_kernel

W = {"power": 1.3, "lateral": 0.7, "rates": 0.4, "effort": 0.05, "penalty": 10.0}


def _same(a, b) -> bool:
    """Equal bit for bit where both are numbers; nan where either is nan."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and bool(np.all((a == b) | (np.isnan(a) & np.isnan(b))))


def _shaped(power, p_ref, lat, rates, effort, failure, steps, n_max):
    """The numpy shaped reward (``TaskCore.shaped_reward``'s arithmetic: a nan argument, a state gone non-finite, counts
    as the full penalty; the wing kernels' reward was nan there until 2026-12-07)."""
    terminated = failure != 0
    lat, rates = np.nan_to_num(lat, nan=np.inf), np.nan_to_num(rates, nan=np.inf)
    terms = {"reward_power": W["power"] * power / p_ref, "reward_lateral": -W["lateral"] * -np.expm1(-lat),
             "reward_rates": -W["rates"] * -np.expm1(-rates), "reward_effort": -W["effort"] * -np.expm1(-effort),
             "reward_failure": -W["penalty"] * terminated}
    reward = (terms["reward_power"] + terms["reward_lateral"] + terms["reward_rates"] + terms["reward_effort"]
              + terms["reward_failure"])
    return reward, terminated, (steps >= n_max) & ~terminated, terms


def _compiled_terms(p_term, neg_args, failure, steps, n_max):
    B = p_term.size
    terms, reward = np.empty((N_TERMS, B)), np.empty(B)
    terminated, truncated = np.empty(B, bool), np.empty(B, bool)
    weights = np.array([W["lateral"], W["rates"], W["effort"], W["penalty"]])
    shaped_terms(p_term, np.expm1(neg_args), failure, steps, weights, n_max, terms, reward, terminated, truncated)
    return reward, terminated, truncated, dict(zip(TERM_KEYS, terms, strict=True))


def _check(ref, got):
    for r, g in zip(ref[:3], got[:3], strict=True):
        assert _same(r, g)
    for k in TERM_KEYS:
        assert _same(ref[3][k], got[3][k]), k


@pytest.mark.parametrize("B,nw,na", [(1, 1, 3), (64, 1, 3), (50, 7, 7), (37, 101, 303), (16, 2, 8), (9, 9, 6)])
def test_wing_readout_is_the_numpy_reward(B, nw, na):
    rng = np.random.default_rng(B * nw)
    obs = rng.normal(0, 0.3, (B, OBS_SIZE * nw)) * 10.0 ** rng.uniform(-2, 2, (B, OBS_SIZE * nw))
    obs[rng.random(obs.shape) < 0.01] = np.nan
    aux = rng.uniform(0, 5e4, (B, N_AUX))
    status = np.where(rng.random(B) < 0.1, rng.choice([SINGULAR, GROUND], B), OK).astype(np.int64)
    a = rng.uniform(-1, 1, (B, na))
    nominal = rng.uniform(-0.3, 0.3, na)
    steps = rng.integers(5990, 6010, B)
    alpha_lo, alpha_hi, beta_max, breaking, min_alt, lat_scale, rate_scale, v_reel, p_ref = (
        -0.1, 0.3, 0.3, 4e4, 2.0, 0.65, 0.37, 3.3, 1.2e5)
    aux[:, AUX_MIN_ALTITUDE] = rng.uniform(0, 50, B)
    # the numpy code of before
    o = obs.reshape(B, nw, OBS_SIZE)
    power = (aux[:, AUX_GROUND_START] - aux[:, AUX_GROUND_END]) * v_reel
    lat = np.mean((o[:, :, OBS_OFFSET + 1] / lat_scale) ** 2, axis=1)
    rates = np.mean((o[:, :, OBS_RATES] ** 2 + o[:, :, OBS_RATES + 2] ** 2) / rate_scale ** 2, axis=1)
    effort = np.mean((a - nominal) ** 2, axis=1)
    alpha, beta = o[:, :, OBS_ALPHA], o[:, :, OBS_BETA]
    failure = np.zeros(B, dtype=np.int64)
    failure[np.any((alpha < alpha_lo) | (alpha > alpha_hi) | (np.abs(beta) > beta_max), axis=1)] = 4
    failure[aux[:, AUX_MAX_TENSION] > breaking] = 3
    failure[aux[:, AUX_MIN_ALTITUDE] < min_alt] = 2
    failure[status != OK] = 1
    failure[status == GROUND] = 2
    ref = _shaped(power, p_ref, lat, rates, effort, failure, steps, 6000)
    # the kernels
    got_power, p_term, got_failure = np.empty(B), np.empty(B), np.empty(B, np.int64)
    neg_args = np.full((N_ARGS, B), np.nan)
    given = max(nw, na) >= SEQUENTIAL_SUM  # numpy's 8-way pairwise order: the task passes numpy's means in
    if given:
        neg_args[:] = -lat, -rates, -effort
    wing_kernel(obs, aux, status, a, nominal, nw, v_reel, W["power"], p_ref, lat_scale, rate_scale ** 2,
                np.array([alpha_lo, alpha_hi, beta_max, breaking, min_alt]), given, got_power, p_term, neg_args,
                got_failure)
    assert _same(got_power, power) and _same(got_failure, failure)
    assert B < 16 or len(set(failure.tolist())) >= 3  # several failure kinds met
    _check(ref, _compiled_terms(p_term, neg_args, got_failure, steps, 6000))


def test_craft_readout_is_the_numpy_reward():
    rng = np.random.default_rng(7)
    B = 200
    raw = rng.normal(0, 0.5, (B, N_CRAFT_OBS)) * 10.0 ** rng.uniform(-1, 2, (B, N_CRAFT_OBS))
    raw[rng.random(raw.shape) < 0.02] = np.nan
    raw[rng.random(raw.shape) < 0.01] = np.inf
    raw[rng.random(raw.shape) < 0.01] = -np.inf
    aux = rng.uniform(0, 2e4, (B, N_CRAFT_AUX))
    aux[rng.random(B) < 0.1, CA_POWER] = np.nan
    aux[:, CA_INFLOW_OK] = rng.random(B) < 0.5
    aux[rng.random(B) < 0.1, CA_TIP_AOA + rng.integers(0, 2)] = np.nan
    aux[:, CA_ALTITUDE] = rng.uniform(0, 40, B)
    status = np.where(rng.random(B) < 0.15, rng.choice([SINGULAR, GROUND], B), OK).astype(np.int64)
    a = rng.uniform(-1, 1, (B, 2))
    trim = np.array([0.1, -0.2], dtype=np.float32)
    steps = rng.integers(2390, 2410, B)
    max_roll, pitch, max_yaw, breaking, min_alt, lat_scale, rate_scale, p_ref = 60.0, (-80.0, 30.0), 90.0, 1.8e4, 5.0, \
        1.5, 0.5, 3e3
    tip_limit = 1.5e4  # [rad] a quarter of the drawn tip incidences pass it (Rotorcraft-v1's blade limit; v0: inf)
    # the numpy code of before (CraftTask._failures and _evaluate), with v1's blade limit the weakest cause
    phi, theta, psi = np.degrees(raw[:, CO_EULER: CO_EULER + 3]).T
    tip_ref = np.max(aux[:, CA_TIP_AOA: CA_TIP_AOA + 2], axis=1)
    failure = np.where(tip_ref > tip_limit, 6, 0).astype(np.int64)
    failure[(np.abs(phi) > max_roll) | ~((pitch[0] <= theta) & (theta <= pitch[1])) | (np.abs(psi) > max_yaw)] = 5
    failure[aux[:, CA_MAX_TENSION] > breaking] = 4
    failure[aux[:, CA_ALTITUDE] < min_alt] = 3
    failure[~np.all(np.isfinite(raw[:, CO_THRUST: CO_THRUST + 2]), axis=1)] = 2
    broke = status != OK
    failure[broke] = np.where(aux[broke, CA_INFLOW_OK] == 1.0, 1, 2)
    failure[status == GROUND] = 3
    o = np.nan_to_num(raw)
    lat = (o[:, CO_OFFSET + 1] / lat_scale) ** 2
    rates = (o[:, CO_RATES] ** 2 + o[:, CO_RATES + 2] ** 2) / rate_scale ** 2
    effort = np.mean((a - trim) ** 2, axis=1)
    power = np.where(np.isfinite(aux[:, CA_POWER]), aux[:, CA_POWER], 0.0)
    ref = _shaped(power, p_ref, np.nan_to_num(lat, nan=np.inf), np.nan_to_num(rates, nan=np.inf), effort, failure,
                  steps, 2400)
    # the kernels
    got_power, p_term, got_failure, tip = np.empty(B), np.empty(B), np.empty(B, np.int64), np.empty(B)
    neg_args = np.empty((N_ARGS, B))
    craft_readout(raw, aux, status, a, trim.astype(float), np.array([W["power"], p_ref, lat_scale, rate_scale ** 2]),
                  np.array([max_roll, *pitch, max_yaw, breaking, min_alt, tip_limit]), got_power, p_term, neg_args,
                  got_failure, tip)
    assert _same(got_power, power) and _same(got_failure, failure) and _same(tip, tip_ref)
    assert set(failure.tolist()) >= {0, 1, 2, 3, 4, 5, 6}
    _check(ref, _compiled_terms(p_term, neg_args, got_failure, steps, 2400))


def test_clip_rows_is_the_numpy_clip():
    from laddermill_gym.envs.task_base import clip_observations

    rng = np.random.default_rng(3)
    raw = rng.normal(0, 3, (300, 19))
    raw[rng.random(raw.shape) < 0.05] = np.nan
    raw[rng.random(raw.shape) < 0.05] = np.inf
    raw[rng.random(raw.shape) < 0.05] = -np.inf
    raw[rng.random(raw.shape) < 0.05] = -0.0
    low, high = -rng.uniform(0, 4, 19), rng.uniform(0, 4, 19)
    low[3] = 0.0
    ref, got = np.empty_like(raw), np.empty_like(raw)
    clip_observations(raw, low, high, ref)
    clip_rows(raw, low, high, got)
    assert _same(got, ref) and np.array_equal(np.signbit(got), np.signbit(ref))

