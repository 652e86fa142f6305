"""``laddermill bench-envs --threads``: steps/s and the speed-up per thread count, then the serial share of a step
(CPU outside the compiled step kernel) and Amdahl's bound at 16 threads (issue 32 point 2); on two threads, the
copies on numba's threads and, beside them, on Python threads."""

from __future__ import annotations

import numba
import pytest

from laddermill_gym.studies.benchmarks.env_benchmark import thread_scaling


@pytest.mark.filterwarnings("ignore")
def test_thread_scaling_prints_rates_speedups_and_the_serial_share():
    lines: list[str] = []
    res = thread_scaling([1], envs=["TetheredWing-v0"], copies=4, quick=True, echo=lines.append)
    text = "\n".join(lines)
    assert "steps/s" in text and "speed-up  1.00x" in text and "serial share on one thread" in text
    share = res["tethered_wing_serial_share"]
    assert 0.0 < share < 1.0  # a share: some CPU outside the kernel (Python, numpy), some inside
    rows = res["tethered_wing"]
    assert rows[0]["threads"] == 1 and rows[0]["speedup"] == 1.0 and rows[0]["steps_per_s"] > 0
    bound = 1.0 / (share + (1.0 - share) / 16)
    assert f"{bound:.1f}x" in text


@pytest.mark.filterwarnings("ignore")
def test_on_two_threads_both_ways_of_running_the_copies_are_printed():
    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("needs two numba threads")
    lines: list[str] = []
    res = thread_scaling([1, 2], envs=["TetheredWing-v0"], copies=40, quick=True, echo=lines.append)
    one, two = res["tethered_wing"]
    assert "python_threads_steps_per_s" not in one  # one thread: one way only
    assert two["python_threads_steps_per_s"] > 0
    assert two["python_threads_speedup"] == pytest.approx(two["python_threads_steps_per_s"] / one["steps_per_s"])
    assert f"(Python threads {two['python_threads_steps_per_s']:12,.0f}" in "\n".join(lines)
