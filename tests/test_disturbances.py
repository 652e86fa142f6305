"""Wind disturbances against their closed forms: the 1-cosine gust shape, the direction step, the schedule's
linear interpolation, and the Ornstein-Uhlenbeck perturbation's stationary variance and autocorrelation."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_dict
from laddermill_gym.atmosphere.disturbances import (
    DirectionStep,
    Disturbance,
    OneMinusCosineGust,
    RandomPerturbation,
    Schedule,
    sample_modulation,
)

RNG = np.random.default_rng


def test_one_minus_cosine_gust_shape():
    t = np.linspace(0.0, 30.0, 3001)
    s, d = OneMinusCosineGust(amplitude=0.4, duration=8.0, time=5.0, direction_amplitude=0.1).sample(t, RNG(0))
    # closed form: peak 1 + A at t0 + T/2, half of it at t0 + T/4, nothing outside [t0, t0 + T]
    assert s[np.searchsorted(t, 9.0)] == pytest.approx(1.4, abs=1e-12)
    assert s[np.searchsorted(t, 7.0)] == pytest.approx(1.2, abs=1e-12)
    assert d[np.searchsorted(t, 9.0)] == pytest.approx(0.1, abs=1e-12)
    outside = (t < 5.0) | (t > 13.0)
    np.testing.assert_array_equal(s[outside], 1.0)
    np.testing.assert_array_equal(d[outside], 0.0)


def test_direction_step_and_ranges():
    t = np.arange(0.0, 5.0, 0.1)
    s, d = DirectionStep(step=0.01, time=1.0).sample(t, RNG(0))
    np.testing.assert_array_equal(s, 1.0)
    np.testing.assert_array_equal(d, np.where(t >= 1.0, 0.01, 0.0))
    steps = [DirectionStep(step=(0.02, 0.04), random_sign=True).sample(t, r)[1][-1] for r in map(RNG, range(200))]
    steps = np.array(steps)
    assert np.all((np.abs(steps) >= 0.02) & (np.abs(steps) <= 0.04))
    assert 60 < np.sum(steps > 0) < 140  # both signs, about half each


def test_schedule_interpolates_linearly():
    sch = Schedule(times=(0.0, 10.0), speed=(1.0, 1.5), direction=(0.0, -0.2))
    s, d = sch.sample(np.array([-1.0, 2.5, 10.0, 20.0]), RNG(0))
    np.testing.assert_allclose(s, [1.0, 1.125, 1.5, 1.5])
    np.testing.assert_allclose(d, [0.0, -0.05, -0.2, -0.2])


def test_ornstein_uhlenbeck_statistics():
    """Stationary from the first sample: variance std^2 at every time, lag-k correlation exp(-k dt / tau)."""
    dist = RandomPerturbation(speed_std=0.05, direction_std=0.02, correlation_time=4.0)
    dt = 0.5
    t = dt * np.arange(12)
    draws = np.array([dist.sample(t, r) for r in map(RNG, range(4000))])  # (n, 2, len(t))
    speed, direction = draws[:, 0] - 1.0, draws[:, 1]
    for x, std in ((speed, 0.05), (direction, 0.02)):
        for j in (0, 11):
            assert np.std(x[:, j]) == pytest.approx(std, rel=0.05)  # 4000 samples: sampling error ~1.1 %
        for k in (1, 4):
            rho = np.corrcoef(x[:, 3], x[:, 3 + k])[0, 1]
            assert rho == pytest.approx(math.exp(-k * dt / 4.0), abs=0.04)


def test_composition_multiplies_speed_and_adds_direction():
    gust = OneMinusCosineGust(amplitude=0.2, duration=4.0, time=2.0, direction_amplitude=0.05)
    step = DirectionStep(step=0.01, time=1.0)
    speed, direction = sample_modulation([gust, step], 10.0, 0.1, RNG(0))
    assert speed.size == 101
    assert speed[40] == pytest.approx(1.2)
    assert direction[40] == pytest.approx(0.06)


@pytest.mark.parametrize("spec, text", [
    ({"type": "Hurricane"}, "type"),
    ({"type": "DirectionStep", "stepp": 0.1}, "stepp"),
    ({"type": "DirectionStep", "step": [0.1, 0.0]}, "low <= high"),
    ({"type": "OneMinusCosineGust", "duration": 0.0}, "duration"),
    ({"type": "RandomPerturbation", "correlation_time": -1.0}, "correlation_time"),
    ({"step": 0.1}, "type"),
])
def test_bad_specs_name_the_field(spec, text):
    with pytest.raises(ValueError, match=text):
        disturbance_from_dict(spec)


def test_negative_speed_is_refused():
    """A 1-cosine lull past -1 is refused when it is made; a composition that still goes negative when sampled (a
    user's own Disturbance) is refused by the sampler."""
    with pytest.raises(ValueError, match=r"amplitude = -3\.0: every value must be >= -1"):
        OneMinusCosineGust(amplitude=-3.0)

    class Reversal(Disturbance):
        def sample(self, t, rng):
            return np.full_like(t, -0.5), np.zeros_like(t)

    with pytest.raises(ValueError, match="negative wind speed"):
        sample_modulation([Reversal()], 20.0, 0.1, RNG(0))
