"""The batched kernel against single simulators (an independent code path through the same physics)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.sim.batch import BatchSimulator


@pytest.fixture(scope="module")
def wing():
    scene = load_scene("tethered_wing", elements_per_piece=1)
    x, u = scene.initial_state()
    return scene, x, u


def test_each_copy_equals_a_single_simulator_with_its_own_wind(wing):
    scene, x, u = wing
    a = scene.assembly
    n = 6
    batch = BatchSimulator(a, n, scene.settings, n_modulation=3)
    rng = np.random.default_rng(3)
    batch.states[:] = x
    batch.states[:, 8] += 0.1 * rng.normal(size=n)  # sideways body velocity [m/s]
    batch.controls[:] = u
    start = batch.states.copy()
    winds = [(np.array([1.0, 1.0 + 0.1 * b, 1.0]), np.array([0.0, 0.02 * b, -0.01 * b])) for b in range(n)]
    for b, (s, d) in enumerate(winds):
        batch.set_wind(b, 0.2, 0.3, s, d)
    batch.active[4] = 0  # an inactive copy does not move
    status = batch.step(120)
    assert np.all(status == 0)
    assert np.array_equal(batch.states[4], start[4]) and batch.t[4] == 0.0
    for b, (s, d) in enumerate(winds):
        if b == 4:
            continue
        wind = a.wind.with_modulation(0.2, 0.3, s, d)
        single = scene.replace(assembly=dataclasses.replace(a, wind=wind)).simulator(start[b], u)
        single.step(n_steps=120)
        assert np.array_equal(single.state, batch.states[b]), f"copy {b}"
        assert batch.t[b] == pytest.approx(single.t)


def test_a_failing_copy_is_reported_and_the_others_go_on(wing):
    scene, x, u = wing
    batch = BatchSimulator(scene.assembly, 3, scene.settings)
    batch.states[:] = x
    batch.controls[:] = u
    batch.states[1, 10] = np.nan  # roll rate
    status = batch.step(5)
    assert status[1] != 0 and status[0] == 0 and status[2] == 0
    assert np.array_equal(batch.failed(), [False, True, False])


def test_bad_wind_modulation_is_refused(wing):
    scene, _, _ = wing
    batch = BatchSimulator(scene.assembly, 2, scene.settings, n_modulation=2)
    with pytest.raises(ValueError, match="copy 1"):
        batch.set_wind(1, 0.0, 1.0, np.ones(3), np.zeros(3))
    with pytest.raises(ValueError, match="spacing"):
        batch.set_wind(0, 0.0, 0.0, np.ones(2), np.zeros(2))
    with pytest.raises(ValueError, match="n_copies"):
        BatchSimulator(scene.assembly, 0, scene.settings)
