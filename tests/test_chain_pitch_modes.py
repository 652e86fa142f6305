"""Why ROS2 converges slowly on LadderChain-v0 (issue 32 point 3; docs/numerics.md, "What an agent is given").

Over one control period from the chain's start (the first seeded action of ``tests/test_fast_ids.py``), the kernels'
ROS2 is compared with a second ROS2 written here from Verwer, Spee, Blom & Hundsdorfer (1999) in plain numpy, whose
matrix is the dense Jacobian of the full right-hand side by finite differences (every coupling in it). Both are judged
against RK4 at 50/256 ms. Measured 2026-12-05 (largest state error; the kernel's / the dense one's): 7.22e-2 / 7.25e-2
at 50 ms, 3.43e-2 / 2.44e-2 at 12.5 ms, 8.04e-3 / 8.00e-3 at 3.125 ms. So the slow convergence is not the kernel's W
matrix leaving something out: ROS2 with every coupling in its matrix does the same. The dense Jacobian's spectrum
gives the cause: its fastest modes (111-119 rad/s, damping ratios 0.037-0.043) are lightly damped pitch oscillations of
groups of neighbouring wings (their eigenvectors are largest in the wings' pitch rates q). A step of 12.5 ms does not
resolve them (h |lambda| = 1.5), 3.125 ms only partly (0.37): ROS2's error there is still pre-asymptotic, and its
order 2 appears below 1 ms (error ratio 10.5 from 3.125 to 0.78 ms, 16.0 from 0.78 to 0.195 ms)."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
import scipy.linalg as sla

import laddermill_gym.envs  # noqa: F401 (registers the ids)
from laddermill_gym.sim.simulator import IntegratorSettings, Simulator

CONTROL_DT = 0.05  # [s] LadderChain-v0's control period


def _chain_start():
    """(assembly, state after reset(seed=3), controls of the first seeded action) of LadderChain-v0."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        env = gym.make("laddermill_gym/LadderChain-v0").unwrapped
    env.reset(seed=3)
    task = env.task
    x0 = task.batch.states[0].copy()
    env.step((0.3 * np.random.default_rng(1).uniform(-1.0, 1.0, env.action_space.shape)).astype(np.float32))
    u = task.batch.controls[0].copy()
    env.close()
    return task.scene.assembly, x0, u


def _kernel_run(asm, x0, u, method: str, dt: float) -> np.ndarray:
    sim = Simulator(asm, x0, IntegratorSettings(method=method, dt=dt), u)
    sim.step(u, int(round(CONTROL_DT / dt)))
    return sim.state.copy()


def _dense_jacobian(f, x: np.ndarray, eps: float = 1e-7) -> np.ndarray:
    """Forward differences of f at x, column by column (step eps max(1, |x_i|))."""
    f0, jac = f(x), np.empty((x.size, x.size))
    for i in range(x.size):
        d = eps * max(1.0, abs(x[i]))
        xp = x.copy()
        xp[i] += d
        jac[:, i] = (f(xp) - f0) / d
    return jac


def _ros2_dense(f, jac: np.ndarray, x: np.ndarray, h: float, n: int) -> np.ndarray:
    """n steps of ROS2 as Verwer et al. (1999) write it: (I - gamma h J) k1 = f(y0), (I - gamma h J) k2 = f(y0 + h
    k1) - 2 k1, y1 = y0 + 3/2 h k1 + 1/2 h k2, gamma = 1 + 1/sqrt 2, with one matrix J for all steps (the method has
    order 2 for any J). The chain's right-hand side does not depend on time here (the wind is steady before 1 s)."""
    gamma = 1.0 + 1.0 / np.sqrt(2.0)
    lu = sla.lu_factor(np.eye(x.size) - gamma * h * jac)
    for _ in range(n):
        k1 = sla.lu_solve(lu, f(x))
        k2 = sla.lu_solve(lu, f(x + h * k1) - 2.0 * k1)
        x = x + 1.5 * h * k1 + 0.5 * h * k2
    return x


@pytest.mark.slow
def test_ros2s_slow_convergence_on_the_chain_is_its_own_and_the_wing_pitch_modes_cause_it():
    asm, x0, u = _chain_start()
    sim = Simulator(asm, x0, IntegratorSettings(), u)
    f = lambda x: sim.rhs(0.0, x, u)  # noqa: E731
    assert np.array_equal(sim.rhs(0.7, x0, u), f(x0))  # steady air over the period: the time column is zero
    ref = _kernel_run(asm, x0, u, "rk4", CONTROL_DT / 256)
    jac = _dense_jacobian(f, x0)
    err = lambda x: float(np.max(np.abs(x - ref)))  # noqa: E731
    rows = {k: (err(_kernel_run(asm, x0, u, "ros2", CONTROL_DT / k)), err(_ros2_dense(f, jac, x0, CONTROL_DT / k, k)))
            for k in (1, 4, 16)}
    fine = [err(_ros2_dense(f, jac, x0, CONTROL_DT / k, k)) for k in (16, 64, 256)]
    print("\nLadderChain-v0, one period, largest state error against RK4 at 50/256 ms, the kernel's ROS2 / ROS2 with "
          "the dense Jacobian: " + "; ".join(f"{50 / k:g} ms {a:.3e} / {b:.3e}" for k, (a, b) in rows.items())
          + f"; the dense one at 3.125, 0.78125, 0.1953125 ms: {fine[0]:.3e}, {fine[1]:.3e}, {fine[2]:.3e} "
          f"(ratios {fine[0] / fine[1]:.1f}, {fine[1] / fine[2]:.1f})")
    kern, dense = np.array(list(rows.values())).T
    # every coupling in the matrix does not make ROS2 converge faster: at 3.125 ms the two agree within 5 %
    assert abs(kern[-1] - dense[-1]) < 0.05 * dense[-1] and dense[0] / dense[-1] < 16.0
    # pre-asymptotic to 3.125 ms (order 2 over the two halvings from 12.5 ms would give 16), order 2 below 1 ms
    assert dense[1] / dense[2] < 6.0 and fine[1] / fine[2] > 12.0
    lam, vec = np.linalg.eig(jac)
    fast = np.argsort(-np.abs(lam))[:20]
    zeta = -lam.real[fast] / np.abs(lam[fast])
    print(f"fastest modes |lambda| {np.abs(lam[fast]).min():.1f}-{np.abs(lam[fast]).max():.1f} rad/s, damping ratios "
          f"{zeta.min():.3f}-{zeta.max():.3f}; h |lambda| at 12.5 ms {0.0125 * np.abs(lam).max():.2f}")
    assert 100.0 < np.abs(lam).max() < 130.0 and np.all(zeta < 0.05)
    names = [sim.state_name(int(np.argmax(np.abs(vec[:, i])))) for i in fast]
    assert all(n.endswith("q [rad/s]") for n in names), names  # each the pitching of wings
