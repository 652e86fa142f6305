"""The batched kernels (``BatchSimulator``, the envs) step onto the kinks of each copy's wind like a single simulator.

Oracles: scipy's DOP853 integrating the same right-hand side piece by piece between the kinks
(``tests/test_breakpoints.py``'s reference, its own error control), RK4's theoretical fourth order on a gust
sampled on the step grid, and the single simulator (bit for bit: the same compiled stepper serves both).
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym import Simulator
from laddermill_gym.atmosphere.disturbances import DirectionStep
from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.sim.batch import BatchSimulator
from tests.test_breakpoints import T_END, dop853_reference, ramp_sim


@pytest.fixture(scope="module")
def reference():
    return dop853_reference()


def _batch(sim: Simulator, n_copies: int = 2) -> BatchSimulator:
    b = BatchSimulator(sim.assembly, n_copies, sim.settings)
    b.states[:] = sim.state
    b.controls[:] = sim.controls
    return b


@pytest.mark.parametrize("mode", ["inside", "off"])
def test_batch_copy_splits_a_step_at_a_kink_like_a_single_run(reference, mode):
    """The 1 ms direction ramp lies inside a 5 ms step: a batch copy with that wind equals the single simulator bit
    for bit; with the split it is within 1e-7 of DOP853 (measured 3.5e-8), across the kink ("off") 300x further
    (1.0e-5); a calm neighbour equals a calm single run."""
    dt = 0.005
    single = ramp_sim(mode, dt)
    batch = _batch(single)
    batch.set_wind(1, WindField())
    n = int(round(T_END / dt))
    assert np.all(batch.step(n) == 0)
    single.step(n_steps=n)
    assert np.array_equal(batch.states[0], single.state)
    assert batch.t[0] == pytest.approx(T_END, abs=1e-12)
    calm = ramp_sim(mode, dt)
    calm.set_wind(WindField())
    calm.step(n_steps=n)
    assert np.array_equal(batch.states[1], calm.state)
    err = np.max(np.abs(batch.states[0] - reference))
    print(f"batch copy, {mode}: largest error against DOP853 {err:.2g}")
    if mode == "inside":
        assert err < 1e-7, err
    else:
        assert err > 1e-6, err  # the step across the kink: second order there


def test_env_gust_grid_off_the_step_grid_is_split():
    """TetheredWing-v0 with its wind sampled every 0.03 s and physics steps of 0.05 s (kinks inside steps): the
    vector env's copy equals a single simulator run through the same schedule (which splits its steps), to the
    last bit."""
    import gymnasium as gym

    from laddermill_gym.envs import register_envs

    register_envs()
    env = gym.make("laddermill_gym/TetheredWing-v0", disturbances=[DirectionStep(step=0.05, time=0.1)],
                   wind_dt=0.03).unwrapped
    env.reset(seed=1)
    task = env.task
    b = task.batch
    sim = Simulator(b.assembly, b.states[0].copy(), b.settings, b.controls[0].copy())
    sim.model = sim.model._replace(tmod=b.air.tmod[0].copy(), ms=b.air.ms[0].copy(), md=b.air.md[0].copy())
    sim.t = float(b.t[0])
    kinks = sim.breakpoint_times
    assert np.any((kinks % b.settings.dt > 1e-6) & (kinks < 0.3)), kinks  # kinks inside physics steps
    action = np.zeros(env.action_space.shape, dtype=env.action_space.dtype)
    for _ in range(6):
        env.step(action)
        sim.controls[:] = b.controls[0]
        sim.step(n_steps=task.n_substeps)
    assert sim.t == pytest.approx(b.t[0])
    assert np.array_equal(sim.state, b.states[0])
