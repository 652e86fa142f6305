"""The envs' step kernels observe a 3D rigid state through ``kernels.dispatch.model_tensions`` (the element tensions
and body rotations without the bodies' loads and the solve: ``kernels/rigid/kinds.py`` ``rigid3d_tensions``, issue 32
point 2). Oracle: the full right-hand side (``kernels/rigid/rhs3d.py``, through ``kernels.integrate.rhs``), which
the observation used before: the tensions
and rotations must be the same to the last bit, on moving states of the tethered wing (one wing, its cable's
aerodynamics and sag correction on) and of the 101-wing chain (free nodes, two ground ends), and the env's
observation must be ``observe_state``'s (which still runs the full right-hand side) for every copy."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
from numba import njit

import laddermill_gym  # noqa: F401  (registers the env ids)
from laddermill_gym.kernels.dispatch import model_tensions
from laddermill_gym.kernels.integrate import rhs
from laddermill_gym.kernels.rigid.observe import N_AUX, observe_state
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.packing import make_workspace
from laddermill_gym.sim.simulator import Simulator


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def _tensions(t, x, u, dx, M, W):
    return model_tensions(M.kind, t, x, u, dx, M, W)


def _bits(a: np.ndarray) -> np.ndarray:
    return np.ascontiguousarray(a, dtype=np.float64).view(np.int64)


@pytest.mark.parametrize("scene", ["tethered_wing", "ladder_chain"])
def test_tensions_and_rotations_are_the_right_hand_sides_bits(scene):
    """Perturbed states (positions, attitudes, velocities and rates, at times across the wind's modulation): the
    tension of every element and the rotation of every body equal the full right-hand side's bit for bit."""
    sc = load_scene(scene)
    x0, u = sc.initial_state()
    sim = Simulator(sc.assembly, x0, sc.settings, u)
    M = sim.model
    W_full, W_fast = make_workspace(sc.assembly), make_workspace(sc.assembly)
    rng = np.random.default_rng(7)
    dx = np.zeros_like(x0)
    for trial in range(20):
        x = x0 + rng.normal(scale=1e-3 * (1 + trial), size=x0.size) * (np.abs(x0) + 1.0)
        t = float(rng.uniform(0.0, 5.0))
        assert rhs(t, x, u, dx, M, W_full) == 0
        assert _tensions(t, x, u, dx, M, W_fast) == 0
        assert np.array_equal(_bits(W_fast.tension), _bits(W_full.tension)), (scene, trial)
        assert np.array_equal(_bits(W_fast.Rw), _bits(W_full.Rw)), (scene, trial)
        assert np.all(np.isfinite(W_full.tension)) and W_full.tension.max() > 0.0


def test_the_env_observation_is_the_full_right_hand_sides():
    """16 copies of TetheredWing-v0 under random actions for 60 control periods (the 0.01 rad direction step at
    1 s moves them): every copy's observation and read-outs are those of ``observe_state`` at its state, time,
    controls and wind, bit for bit."""
    env = gym.make_vec("laddermill_gym/TetheredWing-v0", num_envs=16, vectorization_mode="vector_entry_point")
    task = env.task
    bt = task.batch
    env.reset(seed=3)
    rng = np.random.default_rng(3)
    W = make_workspace(task.scene.assembly)
    obs, aux = np.zeros(task.obs_dim), np.zeros(N_AUX)
    compared = 0
    for _ in range(60):
        env.step((0.3 * rng.uniform(-1.0, 1.0, size=(16, task.n_actions))).astype(np.float32))
        for b in np.flatnonzero(bt.status == 0):
            air = {f: a[b] for f, a in zip(bt.air._fields, bt.air, strict=True) if a is not None}
            M = bt.model._replace(**air)
            assert observe_state(float(bt.t[b]), bt.states[b].copy(), bt.controls[b].copy(), M, W, task.nominal,
                                 task.below, task.ground, obs, aux) == 0
            assert np.array_equal(_bits(obs), _bits(task.obs[b])) and np.array_equal(_bits(aux), _bits(task.aux[b]))
            compared += 1
    env.close()
    assert compared > 16 * 50
