"""The point-mass env on the explicit step past its stable step: it steps at a finer whole fraction of the control
period, with an UnstableStepWarning, as the wing envs do for RK4 (``envs/physics_step.py``). Oracle: the closed-form
limit of symplectic Euler on the string's highest mode, computed here from the cable's data: the step's amplification
matrix on m x'' = -k x - c x' (omega = 2c/l0, damping rate g = 4 DA/(mu l0^2)) has the spectral radius 1 where
(omega dt)^2 + 2 g dt = 4, i.e. (dt / t_c)^2 + dt / t_d = 1 (t_c = l0 / c, t_d = mu l0^2 / (2 DA)). Before,
PointMassChain-v0 with ``{"method": "explicit", "dt": 0.025}`` stopped within its first control period ("the
simulator stopped: speed limit exceeded"); until 2026-12-07 the limit was min(t_c, t_d), which at 17.5 m elements
(t_c = 2.06 ms, t_d = 2.13 ms) is 1.6x the true limit, and the env's own refined step diverged."""

from __future__ import annotations

import math
import warnings

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.sim.stable_step import UnstableStepWarning

PM = "laddermill_gym/PointMassChain-v0"
EXPLICIT = {"element_length": 70.0, "method": "explicit"}


def _limit(string) -> float:
    """The largest stable step [s]: the positive root of (omega dt)^2 + 2 g dt - 4 by numpy's polynomial roots."""
    c = string.cable
    l0 = string.element_length
    omega, g = 2.0 * math.sqrt(c.EA / c.mass_per_length) / l0, 4.0 * c.DA / (c.mass_per_length * l0 ** 2)
    roots = np.roots([omega ** 2, 2.0 * g, -4.0])
    return float(roots[roots > 0][0].real)


def _amplification_radius(string, dt: float) -> float:
    """Spectral radius of one symplectic Euler step (v += dt (-omega^2 x - g v), x += dt v) on the highest mode."""
    c = string.cable
    l0 = string.element_length
    w2, g = (2.0 * math.sqrt(c.EA / c.mass_per_length) / l0) ** 2, 4.0 * c.DA / (c.mass_per_length * l0 ** 2)
    kick = np.array([[1.0, 0.0], [-dt * w2, 1.0 - dt * g]])  # (x, v) -> (x, v+)
    drift = np.array([[1.0, dt], [0.0, 1.0]])  # (x, v+) -> (x+, v+)
    return float(np.max(np.abs(np.linalg.eigvals(drift @ kick))))


def _run_to_the_end(env) -> str:
    env.reset(seed=0)
    zero = np.zeros(env.action_space.shape, dtype=np.float32)
    while True:
        _, _, term, trunc, info = env.step(zero)
        if term:
            return info.get("failure_reason", "terminated")
        if trunc:
            return ""


def test_an_explicit_step_past_its_limit_is_refined_with_a_warning_and_runs():
    with pytest.warns(UnstableStepWarning, match=r"dt = 0.025 s is above 0.9 x the explicit step's stable step"):
        env = gym.make(PM, scene_options={**EXPLICIT, "dt": 0.025}, settle_time=0.0, episode_time=5.0)
    task = env.unwrapped.task
    limit = _limit(task.string)
    assert 0.0073 < limit < 0.00732, limit  # 70 m of Dyneema: l0 / c = 8.25 ms, with its damping 7.31 ms
    n = task.n_substeps
    assert task.scene.dt == pytest.approx(task.control_dt / n, rel=1e-12)
    assert task.scene.dt <= 0.9 * limit < task.control_dt / (n - 1)  # the largest whole fraction below the margin
    assert _run_to_the_end(env) == ""
    env.close()


def test_a_step_within_the_limit_and_the_implicit_step_are_kept():
    with warnings.catch_warnings():
        warnings.simplefilter("error", UnstableStepWarning)
        env = gym.make(PM, scene_options={**EXPLICIT, "dt": 0.005}, settle_time=0.0, episode_time=1.0)
        assert (env.unwrapped.task.scene.dt, env.unwrapped.task.n_substeps) == (0.005, 10)
        env.close()
        env = gym.make(PM, settle_time=0.0, episode_time=1.0)  # the registered implicit step at 25 ms
        assert (env.unwrapped.task.scene.method, env.unwrapped.task.scene.dt) == ("implicit", 0.025)
        env.close()


def test_a_step_that_does_not_divide_the_period_is_refused_before_any_refinement():
    with pytest.raises(ValueError, match=r"must be a whole number of scene steps \(0.03 s\)"):
        gym.make(PM, scene_options={**EXPLICIT, "dt": 0.03}, settle_time=0.0)


@pytest.mark.parametrize("l0", [0.01, 0.5, 5.0, 17.5, 70.0, 1000.0])
def test_explicit_stable_dt_is_the_closed_form_root(l0):
    from laddermill_gym.sim.pointmass import explicit_stable_dt

    s = _string(l0)
    dt = explicit_stable_dt(s)
    assert dt == pytest.approx(_limit(s), rel=1e-7)
    assert _amplification_radius(s, 0.999 * dt) < 1.0 < _amplification_radius(s, 1.001 * dt)
    c = s.cable
    assert dt < min(l0 / math.sqrt(c.EA / c.mass_per_length), c.mass_per_length * l0 ** 2 / (2.0 * c.DA))


def _string(l0, n_el=10):
    from laddermill_gym.model.builders import CableSpec
    from laddermill_gym.model.params import WindParams
    from laddermill_gym.model.pointmass import PointMassString

    cab = CableSpec(diameter=0.025, mass_per_length=0.3, EA=2.16e7, DA=2.16e4, cn0=0.0, ct0=0.0)
    return PointMassString(wind=WindParams(v0=0.0, rho0=0.0), gravity=0.0, cable=cab, element_length=l0,
                           n_nodes=n_el - 1, anchor=np.zeros(3), end=np.array([n_el * l0 * 1.01, 0.0, 0.0]))


@pytest.mark.parametrize("l0", [0.5, 5.0, 17.5, 70.0])
def test_a_run_at_nine_tenths_of_the_limit_stays_bounded(l0):
    """A taut 10-element string with an alternating axial perturbation (the highest mode), 2000 explicit steps at 0.9x
    the limit: bounded (the perturbation decays). At 17.5 m 0.9 min(t_c, t_d) diverged ("speed limit exceeded")."""
    from laddermill_gym.sim.pointmass import PointMassSimulator, explicit_stable_dt

    s = _string(l0)
    x = np.zeros(s.state_size)
    xs = x.reshape(-1, 6)
    rest = np.arange(1, 10) * l0 * 1.01  # evenly spaced: the taut equilibrium
    xs[:, 0] = rest + 1e-3 * l0 * (-1.0) ** np.arange(9)
    sim = PointMassSimulator(s, x, np.zeros(3), 0.9 * explicit_stable_dt(s), "explicit")
    sim.step(2000)
    assert np.abs(sim.positions[:, 0] - rest).max() <= 1e-3 * l0  # the perturbation did not grow


def test_the_env_refines_a_step_the_old_limit_let_through():
    """PointMassChain-v0 at 17.5 m elements with an explicit 25 ms step: the env's own refined step (0.9 of the
    limit) now runs its 5 s; with min(t_c, t_d) it was 1.6x too long and stopped ("speed limit exceeded")."""
    with pytest.warns(UnstableStepWarning):
        env = gym.make(PM, scene_options={"element_length": 17.5, "method": "explicit", "dt": 0.025},
                       settle_time=0.0, episode_time=5.0)
    task = env.unwrapped.task
    assert task.scene.dt <= 0.9 * _limit(task.string)
    assert _run_to_the_end(env) == ""
    env.close()


def _chain_radius(string, lengths, dt: float) -> float:
    """Spectral radius of one symplectic Euler step of the string's whole axial chain (free nodes between two anchors,
    element lengths ``lengths``, lumped masses, Voigt damping), built densely: the oracle for the moving cable."""
    c = string.cable
    k = c.EA / np.asarray(lengths)
    d = c.DA / np.asarray(lengths)
    m = c.mass_per_length * 0.5 * (lengths[:-1] + lengths[1:])
    n = m.size

    def assembled(e):
        mat = np.diag(e[:-1] + e[1:])
        mat -= np.diag(e[1:-1], 1) + np.diag(e[1:-1], -1)
        return mat / m[:, None]

    kick = np.block([[np.eye(n), np.zeros((n, n))], [-dt * assembled(k), np.eye(n) - dt * assembled(d)]])
    drift = np.block([[np.eye(n), dt * np.eye(n)], [np.zeros((n, n)), np.eye(n)]])
    return float(np.max(np.abs(np.linalg.eigvals(drift @ kick))))


def test_the_moving_cable_s_short_end_elements_set_its_explicit_step():
    """On the moving cable the end elements run from a to a + l_e and from b down to b - l_e; next to a 0.1 l_e element
    the string's stable step is about a fifth of the uniform string's, where the env stepped at 0.9 of the latter
    and the first element's tension came out 0 (review of 2026-12-08). Oracles: the dense amplification matrix of the
    whole chain at both extreme configurations, and runs of the moving string from a quiet start (its first element's
    tension at 0.9 x the limit equals a run at a quarter of it; at 1.25 x it does not)."""
    from laddermill_gym.model.pointmass_mill import PointMassStation, station_state
    from laddermill_gym.sim.pointmass import PointMassError, explicit_stable_dt
    from laddermill_gym.sim.pointmass_mill import PointMassMillSimulator
    from tests.test_pointmass_pay_out import moving_string

    _, string, x = moving_string(v_c=2.0, s=0.0)
    st = PointMassStation(1.0, 0.1, 1.1, (0.0,), (2.0,))
    dt = explicit_stable_dt(string, st)
    assert dt < 0.21 * explicit_stable_dt(string)
    n = string.n_nodes
    configs = [np.r_[0.1, np.ones(n - 1), 1.1], np.r_[1.1, np.ones(n - 1), 0.1]]
    assert max(_chain_radius(string, lengths, 0.999 * dt) for lengths in configs) < 1.0
    assert max(_chain_radius(string, lengths, 1.001 * dt) for lengths in configs) > 1.0
    xs = x.reshape(-1, 6)
    xs[:, 3:6], xs[:, 4], xs[:, 0], xs[:, 2] = 0.0, 2.0, 0.0, -100.0  # quiet: every node at V_c along the cable

    def first_tension(step):
        sim = PointMassMillSimulator(string, st, x.copy(), np.zeros(6), step, "explicit",
                                     station_x=station_state(st, 0.0, 0.0))
        try:
            sim.advance(0.002)
        except PointMassError:
            return math.nan
        return float(sim.tensions()[0])

    reference = first_tension(0.25 * dt)
    assert reference > 1e4
    assert first_tension(0.9 * dt) == pytest.approx(reference, rel=1e-3)
    assert not first_tension(1.25 * dt) == pytest.approx(reference, rel=1e-3)
