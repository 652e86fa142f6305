"""envs/copy_threads.py: the vector envs' copies split over threads. The oracle for the split is a plain loop over
the copies; for the envs, the single env (the same kernel on one copy): every copy of a threaded native vector env
must equal a single env bit for bit, through numba's threads (the kernel's launcher) and through Python's (a process
forked after GNU OpenMP), and making that vector env after the single env compiles only the launcher's loop."""

import multiprocessing
import pickle

import gymnasium as gym
import numba
import numpy as np
import pytest
from numba import njit
from numba.core import event

import laddermill_gym  # noqa: F401 (registers the ids)
from laddermill_gym.envs.copy_threads import CopyThreads, copy_ranges
from laddermill_gym.kernels import fork_state


@njit(nogil=True, cache=False)
def _square_rows(x, out, first, last):
    for b in range(first, last):
        if x[b, 0] < 0.0:
            raise ValueError("negative")
        for j in range(x.shape[1]):
            out[b, j] = x[b, j] * x[b, j] + b


@njit(nogil=True, parallel=True, cache=False)
def _square_rows_launcher(bounds, x, out):
    for r in numba.prange(bounds.shape[0]):
        _square_rows(x, out, bounds[r, 0], bounds[r, 1])


@pytest.mark.parametrize("n, k", [(1, 4), (5, 2), (7, 3), (8, 8), (3, 16), (512, 2)])
def test_ranges_cover_every_copy_once_in_order(n, k):
    r = copy_ranges(n, k)
    assert len(r) == min(n, k)
    assert r[0][0] == 0 and r[-1][1] == n
    assert all(a[1] == b[0] for a, b in zip(r, r[1:], strict=False))  # contiguous, in order
    sizes = [b - a for a, b in r]
    assert min(sizes) >= 1 and max(sizes) - min(sizes) <= 1


@pytest.mark.parametrize("parallel", [False, True])
def test_the_runner_gives_the_plain_loop_on_every_thread_count(parallel):
    x = np.random.default_rng(0).uniform(0, 2, size=(37, 5))
    expected = x * x + np.arange(37)[:, None]  # the plain loop, by hand
    run = CopyThreads(_square_rows, 37, parallel)
    for threads in range(1, min(4, numba.config.NUMBA_NUM_THREADS) + 1):
        numba.set_num_threads(threads)
        try:
            out = np.full_like(x, np.nan)
            run(x, out)
            np.testing.assert_array_equal(out, expected)
        finally:
            numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    run.close()


def test_the_launcher_runs_the_ranges_unless_forked_after_gnu_openmp(monkeypatch):
    """With a launcher, the ranges go to it (numba's threads) as one (n_ranges, 2) array; in a process forked after
    GNU OpenMP started (kernels/fork_state.py), to Python's threads; the plain loop's rows either way."""
    threads = min(2, numba.config.NUMBA_NUM_THREADS)
    if threads < 2:
        pytest.skip("needs two numba threads")
    x = np.random.default_rng(4).uniform(0, 2, size=(11, 3))
    expected = x * x + np.arange(11)[:, None]
    seen = []

    def launcher(bounds, *args):
        seen.append(bounds.copy())
        _square_rows_launcher(bounds, *args)

    run = CopyThreads(_square_rows, 11, True, launcher)
    numba.set_num_threads(threads)
    try:
        for forked in (False, True):
            monkeypatch.setattr(fork_state, "FORKED_AFTER_GNU_OPENMP", forked)
            out = np.full_like(x, np.nan)
            run(x, out)
            np.testing.assert_array_equal(out, expected)
    finally:
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    assert len(seen) == 1  # the forked process's call went to the Python threads
    np.testing.assert_array_equal(seen[0], np.array(copy_ranges(11, threads)))
    run.close()


def test_ranges_keep_right_when_the_arguments_change_type():
    """The other ranges call the entry point the dispatcher chose on an earlier call only while the arguments have
    its types; arrays of another dtype, layout or writeability must go through the dispatcher (a wrong entry point
    would read them as float64 C arrays)."""
    run = CopyThreads(_square_rows, 9, True)
    x = np.random.default_rng(1).uniform(0, 2, size=(9, 3))
    cases = [x, x, np.arange(27, dtype=np.int64).reshape(9, 3), np.asfortranarray(x), x[:, ::-1], x.astype(np.float32)]
    ro = x.copy()
    ro.setflags(write=False)
    cases += [ro, x]
    for xi in cases:
        for _ in range(2):  # the second call of each may take the kept entry point
            out = np.zeros((9, 3), dtype=np.float64)
            run(xi, out)
            np.testing.assert_array_equal(out, (xi * xi).astype(np.float64) + np.arange(9)[:, None])
    run.close()


def test_an_error_in_any_range_is_raised_after_all_ranges_end():
    x = np.ones((6, 2))
    x[5, 0] = -1.0  # the last range: another thread when there are two
    run = CopyThreads(_square_rows, 6, True)
    out = np.zeros_like(x)
    with pytest.raises(ValueError, match="negative"):
        run(x, out)
    assert np.all(out[:3] == 1.0 + np.arange(3)[:, None])  # the first range ran to its end
    copy = pickle.loads(pickle.dumps(run))  # the pool's threads are not pickled; the copy starts its own
    x[5, 0] = 1.0
    copy(x, out)
    np.testing.assert_array_equal(out, 1.0 + np.arange(6)[:, None] * np.ones((1, 2)))
    run.close()
    copy.close()


def _run_in_child(run, x, queue):
    out = np.zeros_like(x)
    run(x, out)
    queue.put(out)


@pytest.mark.skipif("fork" not in multiprocessing.get_all_start_methods(), reason="needs the fork start method")
def test_a_forked_process_starts_its_own_threads():
    """A runner whose pool the parent started is copied by ``fork`` without the pool's threads; the child's call
    must start its own rather than wait for ever on the parent's (the oracle: the plain loop, by hand)."""
    x = np.random.default_rng(2).uniform(0, 1, size=(8, 2))
    run = CopyThreads(_square_rows, 8, True)
    run(x, np.zeros_like(x))  # the parent's pool started (on two or more threads)
    ctx = multiprocessing.get_context("fork")
    queue = ctx.Queue()
    child = ctx.Process(target=_run_in_child, args=(run, x, queue))
    child.start()
    try:
        out = queue.get(timeout=60)
    finally:
        child.join(timeout=10)
        if child.is_alive():
            child.kill()
    np.testing.assert_array_equal(out, x * x + np.arange(8)[:, None])
    run.close()


#: the launcher of each env's step kernel (numba's threads), the one thing its threaded vector env compiles
_LAUNCHERS = {"laddermill_gym/TetheredWing-v0": "launch_step_observe",
              "laddermill_gym/Rotorcraft-v0": "launch_craft_step_observe"}


@pytest.mark.parametrize("env_id", sorted(_LAUNCHERS))
def test_a_threaded_vector_env_is_the_single_envs_bit_for_bit_and_compiles_only_its_launcher(env_id, monkeypatch):
    n, steps = 5, 12
    rng = np.random.default_rng(3)
    acts = rng.uniform(-0.5, 0.5, size=(steps, n, gym.make(env_id).action_space.shape[0])).astype(np.float32)
    singles = []
    for i in range(n):
        e = gym.make(env_id)
        o, _ = e.reset(seed=20 + i)
        rows = [o]
        for a in acts[:, i]:
            rows.append(e.step(a)[0])
        singles.append(np.array(rows))
    compiled = []

    class Count(event.Listener):
        def on_start(self, ev):
            compiled.append(ev.data["dispatcher"].py_func.__qualname__)

        def on_end(self, ev):
            pass

    def rollout():
        vec = gym.make_vec(env_id, n, vectorization_mode="vector_entry_point", parallel=True)
        o, _ = vec.reset(seed=20)
        hist = [o]
        for a in acts:
            hist.append(vec.step(a)[0])
        vec.close()
        return np.array(hist)

    listener = Count()
    threads = min(2, numba.config.NUMBA_NUM_THREADS)
    event.register("numba:compile", listener)
    try:
        numba.set_num_threads(threads)
        via_numba = rollout()
    finally:
        event.unregister("numba:compile", listener)
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    # the single env's kernels serve the threaded vector env; on two threads, its launcher's loop is compiled once
    assert set(compiled) <= {_LAUNCHERS[env_id]}
    monkeypatch.setattr(fork_state, "FORKED_AFTER_GNU_OPENMP", True)  # as in a process forked after GNU OpenMP
    numba.set_num_threads(threads)
    try:
        via_python = rollout()
    finally:
        numba.set_num_threads(numba.config.NUMBA_NUM_THREADS)
    for hist in (via_numba, via_python):
        for i in range(n):
            np.testing.assert_array_equal(hist[:, i], singles[i])
