"""Regression against trajectories produced by the code *before* the architecture change (issue 11).

This is the one test that compares with the code's own earlier output, and it says so: the refactor promises
that nothing changes in behaviour, so RK4 trajectories of ``tethered_wing`` (with a direction step and a speed
change through the wind modulation, and controls), its plain and in-plane variants, ``ladder_chain`` (3D with
a direction step, and in-plane) and the rotorcraft flying model must equal the states written by commit 16b454f
(``tests/data/make_golden_16b454f.py``). The physics itself is checked against independent oracles elsewhere in
the suite.

Two measures, both at every stored snapshot x_k (reference r_k):

- **normwise relative**, ||x_k - r_k||_inf / ||r_k||_inf, the relative error of a vector (Higham, *Accuracy and
  Stability of Numerical Algorithms*, sec. 1.2): held to the issue's 1e-12 (measured: at most 5.1e-14 on
  2026-11-30, 4.6e-14 on 2026-11-24);
- **componentwise**, max_i |x_ki - r_ki| / max(|r_ki|, 1): held to the trajectory's own round-off floor. The
  kernels compile without reference counting (kernels/rigid/rhs3d.py) and without fastmath reassociation (the
  cache-reproducibility fix, docs/numerics.md "Compiler flags"), so LLVM orders some sums differently from
  16b454f. Such last-bit differences grow like any other: the stiff cable elements (EA / l0 ~ 1.7e6 N/m on a
  lumped node of a few kg) and the equilibrium solve that makes the chain's start turn them into componentwise
  differences of about 1e-10 in the chain's near-zero velocities within 0.5 s, 2e-12 in the single wing's and the
  rotorcraft's. 16b454f differs from *itself* by as much when its start is moved by one ulp per entry (measured
  with ``tests/data/ulp_floor_16b454f.py`` at that commit: single wing 1.5-2.3e-12, its in-plane variant
  1.2-2.0e-12, rotorcraft 1.6-1.9e-12, chains 0.9-1.2e-10), so the issue's 1e-12 componentwise is below what the
  reference code reproduces of itself. The test measures that floor with today's code (the same one-ulp start
  moves, two seeds) and holds the difference from 16b454f to FLOOR_FACTOR times it.
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from laddermill_gym import Simulator, load_scene

GOLDEN = np.load(Path(__file__).parent / "data" / "golden_rk4_16b454f.npz")
#: the issue's bound, normwise relative
NORMWISE_RTOL = 1e-12
#: componentwise: the difference from 16b454f may be this many times the largest difference a one-ulp move of the
#: start makes (measured ratios 0.6-1.4 at the time of writing)
FLOOR_FACTOR = 3.0
_FLOOR_SEEDS = (1, 2)


def _modulated(scene, t0, dt, speed, direction):
    wind = scene.assembly.wind.with_modulation(t0, dt, np.array(speed), np.array(direction))
    start = scene.simulator()
    return Simulator(dataclasses.replace(scene.assembly, wind=wind), start.initial_state, scene.settings,
                     start.initial_controls)


def _tethered_wing():
    sim = _modulated(load_scene("tethered_wing"), 0.0, 0.5, [1.0, 1.0, 1.0, 1.1, 1.1], [0, 0, 0.01, 0.01, 0.01])
    u = sim.controls.copy()
    u[1], u[2] = 0.01, -0.005
    return sim, [200, 200, 200], u


def _ladder_chain():
    return _modulated(load_scene("ladder_chain"), 0.0, 0.25, [1.0, 1.0, 1.05], [0.0, 0.01, 0.01]), [20, 20], None


def _rotorcraft():
    from laddermill_gym.rotorcraft.craft import load_craft
    from laddermill_gym.sim.simulator import IntegratorSettings

    craft = load_craft("roberts_flying_model")
    # the kernels' arithmetic is pinned with the integrator of 16b454f (RK4 at 2 ms), whatever the config's default
    rk4 = IntegratorSettings(method="rk4", dt=0.002, max_speed=100.0, max_rate=50.0)
    sim = load_craft(config=dataclasses.replace(craft.config, settings=rk4)).simulator()
    u = sim.controls.copy()
    u[1] = 0.002
    return sim, [250, 250], u


def _variant(scene, steps, **options):
    return lambda: (load_scene(scene, **options).simulator(), steps, None)


#: name in the golden file -> the run (simulator, steps per stored span, controls)
CASES = {
    "tethered_wing": _tethered_wing,
    "tethered_wing_plain": _variant("tethered_wing", [100, 100], sag=False, cable_aero=False, elements_per_piece=1),
    "tethered_wing_2d": _variant("tethered_wing", [200, 200], dimension=2),
    "ladder_chain": _ladder_chain,
    "ladder_chain_2d": _variant("ladder_chain", [40, 40], dimension=2),
    "rotorcraft": _rotorcraft,
}


@cache
def _run(name):
    return CASES[name]()


def _trajectory(name, seed=None) -> np.ndarray:
    """The stored snapshots of run ``name``; with a seed, from its start with each entry moved by one ulp (a random
    sign per entry, relative 2^-52)."""
    sim, steps, u = _run(name)
    x0 = sim.initial_state.copy()
    if seed is not None:
        x0 *= 1.0 + np.random.default_rng(seed).choice([-1.0, 1.0], x0.shape) * 2.0 ** -52
    sim.reset(state=x0)
    xs = [sim.state.copy()]
    for n in steps:
        sim.step(u, n_steps=n)
        xs.append(sim.state.copy())
    return np.array(xs)


def componentwise(xs, ref) -> float:
    """max_i |x_ki - r_ki| / max(|r_ki|, 1) over every snapshot k and entry i."""
    return float(np.max(np.abs(xs - ref) / np.maximum(np.abs(ref), 1.0)))


def normwise(xs, ref) -> float:
    """max_k ||x_k - r_k||_inf / ||r_k||_inf."""
    return float(np.max(np.max(np.abs(xs - ref), axis=1) / np.max(np.abs(ref), axis=1)))


def test_the_measures():
    ref = np.array([[1000.0, 0.5, -2.0]])
    xs = ref + np.array([[1e-9, 1e-12, -4e-12]])
    assert componentwise(xs, ref) == pytest.approx(2e-12)  # the -2.0 entry: 4e-12 / 2
    assert normwise(xs, ref) == pytest.approx(1e-12)  # 1e-9 / 1000


@pytest.mark.parametrize("name", list(CASES))
def test_equals_16b454f(name):
    ref = GOLDEN[name]
    xs = _trajectory(name)
    assert xs.shape == ref.shape
    print(f"{name}: normwise relative difference {normwise(xs, ref):.3g}")
    assert normwise(xs, ref) <= NORMWISE_RTOL, f"{name}: normwise relative difference {normwise(xs, ref):.3g}"
    floor = max(componentwise(_trajectory(name, seed), xs) for seed in _FLOOR_SEEDS)
    assert floor > 0.0  # the start moves by one ulp and the run follows it
    err = componentwise(xs, ref)
    print(f"{name}: componentwise difference {err:.3g}, one-ulp floor {floor:.3g}")
    assert err <= FLOOR_FACTOR * max(floor, NORMWISE_RTOL), (
        f"{name}: componentwise difference {err:.3g}, {err / floor:.2f} times the one-ulp floor {floor:.3g}")
