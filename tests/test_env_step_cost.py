"""The single-craft step-cost study (``studies/benchmarks/env_step_cost.py``, issue 32 point 2): its compiled
W-step loop runs the env's own step, its table's rows are the measured parts' sums and differences, and bad
arguments are refused."""

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401 (registers the envs)
from laddermill_gym.studies.benchmarks import env_step_cost as esc


@pytest.mark.parametrize("env_id", ["laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"])
def test_the_timed_w_step_is_the_envs_step(env_id):
    """One pass of the study's W-step loop from a copy's state and controls lands where the env's step kernel took
    that copy (to the quaternion normalisation and check the env adds after the step), with the flags of the env's
    kernel (the wing's fastmath, the rotorcraft's none)."""
    env = gym.make_vec(env_id, num_envs=2, vectorization_mode="vector_entry_point")
    env.reset(seed=3)
    task = env.unwrapped.task
    b = task.batch
    assert b.tableau is not None and task.n_substeps == 1
    action = np.zeros((2, task.n_actions))
    env.step(action)
    x0, t0 = b.states[0].copy(), float(b.t[0])
    env.step(action)
    x1 = b.states[0].copy()
    assert float(b.t[0]) == pytest.approx(t0 + b.settings.dt)
    assert not np.allclose(x1, x0, rtol=0, atol=1e-6)  # the copy moved
    loop = esc.loops_for(task._kernel)[0]
    loop(1, t0, x0, b.states, b.controls, b.settings.dt, *b.detached, b.work, b.air, b.limits, b.tableau)
    np.testing.assert_allclose(b.states[0], x1, rtol=1e-12, atol=1e-12)
    env.close()


def test_the_table_is_the_parts_arithmetic():
    us = 1e-6
    c = {"step": 12.0 * us, "kernel": 11.0 * us, "w_step": 9.0 * us, "assembly": 1.0 * us, "rhs": 1.5 * us,
         "body_jacobian": 2.0 * us, "cable_jacobian": 0.5 * us, "factorisation": 0.25 * us, "elimination": 0.125 * us,
         "observe": 1.5 * us, "stages": 4.0}
    text = esc.table("laddermill_gym/TetheredWing-v0", c, 512, 400_000.0)
    # 9 - (1 + 3 x 1.5 + 2 + 0.5 + 0.25 + 4 x 0.125) = 0.25; 11 - 9 - 1.5 = 0.5; 12 - 11 = 1
    assert "3 right-hand sides" in text and "4 eliminations" in text
    for name, value in (("rest of the W step", "0.25"), ("rest of the kernel", "0.50"), ("Python and numpy", "1.00"),
                        ("3 right-hand sides", "4.50"), ("4 eliminations", "0.50")):
        line = next(ln for ln in text.splitlines() if name in ln)
        assert f" {value} us" in line, line
    assert "one thread: 83,333 env steps/s; two threads sharing perfectly: 166,667" in text
    # Amdahl with the serial share 1 / 12: 1 / (1/12 + (11/12) / 16) = 7.11; 12x at 16 threads: s <= 1/45 = 2.2 %
    assert "Python and numpy's 8.3% of the step (not parallel) bound the speed-up on 16 threads to 7.1x" in text
    assert "needs at most 5.00 us per copy-step (0.42 of today's; the W step alone is 1.80x that)" in text


def test_bad_arguments_are_refused(capsys):
    with pytest.raises(SystemExit):
        esc.main(["laddermill_gym/TetheredWing-v0", "--copies", "0"])
    assert "--copies 0" in capsys.readouterr().err
