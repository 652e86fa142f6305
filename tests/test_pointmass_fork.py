"""Issue 34 item 11: PointMassChain-v0 in ``gymnasium.make_vec(id, 2, vectorization_mode="async")`` with the default
"fork" context. A string of at most ``CHUNK`` nodes runs the serial twins of the point-mass kernels
(``*_serial``: the same chunks in the same order, in functions with no parallel loop), so neither building nor
stepping the env starts numba's thread pool (GNU OpenMP's is not fork-safe), and a worker forked from a process
that did start it still runs them.

Oracles: the parallel kernels (separate compiled code) on one thread for the serial twins, bit for bit, on
random strings spanning several chunks and partitions; Gymnasium's SyncVectorEnv (its own code) for the async
rollout; numba's own ``threading_layer()`` (it raises until the pool is started) for "no pool started"."""

from __future__ import annotations

import subprocess
import sys
import warnings

import gymnasium as gym
import numba
import numpy as np
import pytest

from laddermill_gym.kernels import fork_state
from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, N3_VEL
from laddermill_gym.kernels.pointmass.explicit import CHUNK, explicit_advance, explicit_advance_serial
from laddermill_gym.kernels.pointmass.implicit import implicit_advance, implicit_advance_serial
from laddermill_gym.kernels.pointmass.partitioned import partitioned_solve, partitioned_solve_serial
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.pointmass import PointMassKite, PointMassString, make_work, pack
from laddermill_gym.sim import pointmass as sim_pointmass
from tests.env_cases import PMC, case_kwargs


def _random_string(rng, n, end_fixed):
    """n free nodes on 1 m elements in random directions, stretched or slack by up to 20 %, a 20 kg kite on every
    seventh node (EA 1 kN, DA 10 N s, 1 kg/m: a test string, no data source needed)."""
    kite = PointMassKite(name="k", mass=20.0, area=10.0, alpha=np.linspace(-np.pi, np.pi, 5), cl=np.zeros(5),
                         cd=np.zeros(5))
    cab = CableSpec(diameter=0.01, mass_per_length=1.0, EA=1e3, DA=10.0, cn0=0.0, ct0=0.0)
    d = rng.standard_normal((n + 1, 3))
    d *= (1.0 + 0.2 * rng.uniform(-1, 1, (n + 1, 1))) / np.linalg.norm(d, axis=1, keepdims=True)
    pts = np.cumsum(d, axis=0)
    s = PointMassString(wind=WindParams(v0=0.0, rho0=0.0), gravity=0.0, cable=cab, element_length=1.0, n_nodes=n,
                        anchor=np.zeros(3), end=pts[n] if end_fixed else None, kite=kite,
                        kite_nodes=np.arange(3, n, 7))
    return s, pts[:n]


def _on_one_thread(fn, *args):
    before = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        return fn(*args)
    finally:
        numba.set_num_threads(before)


@pytest.mark.parametrize("n", [7, CHUNK + 5, 2 * CHUNK + 300])
def test_serial_twins_give_the_parallel_kernels_bits(n):
    rng = np.random.default_rng(n)
    s, pos = _random_string(rng, n, end_fixed=n % 2 == 1)
    x0 = np.zeros(s.state_size)
    nodes = x0.reshape(n, N3_SIZE)
    nodes[:, N3_POS:N3_POS + 3] = pos
    nodes[:, N3_VEL:N3_VEL + 3] = 0.1 * rng.standard_normal((n, 3))
    u = np.zeros(3 * max(1, s.n_kites))
    for serial, parallel in ((explicit_advance_serial, explicit_advance), (implicit_advance_serial, implicit_advance)):
        xs, xp = x0.copy(), x0.copy()
        Ws, Wp = make_work(s), make_work(s)
        rs = serial(0.0, xs, u, 1e-3, 5, pack(s), Ws)
        rp = _on_one_thread(parallel, 0.0, xp, u, 1e-3, 5, pack(s), Wp)
        assert rs == rp
        np.testing.assert_array_equal(xs, xp)
        np.testing.assert_array_equal(Ws.tension, Wp.tension)
    for P in (1, 2, 3, 5):
        xs, xp = x0.copy(), x0.copy()
        tension = np.abs(rng.standard_normal(s.n_elements)) * 100.0
        Ws, Wp = make_work(s, parts=8), make_work(s, parts=8)
        partitioned_solve_serial(xs, tension, pack(s), 1e-3, Ws, P)
        partitioned_solve(xp, tension, pack(s), 1e-3, Wp, P)
        np.testing.assert_array_equal(xs, xp)


def test_building_and_stepping_the_chain_starts_no_thread_pool():
    """In a fresh process: make, reset and step PointMassChain-v0 (with its start computation), then ask numba."""
    code = ("import gymnasium, numba, numpy as np, laddermill_gym\n"
            f"env = gymnasium.make({PMC!r}, settle_time=0.5, episode_time=1.0)\n"
            "env.reset(seed=0); env.step(np.zeros(env.action_space.shape, np.float32))\n"
            "try:\n    print('layer', numba.threading_layer())\nexcept ValueError:\n    print('no pool')\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.strip().splitlines()[-1] == "no pool"


def _rollout(vec, n_steps=5):
    obs, _ = vec.reset(seed=3)
    out, rewards = [obs], []
    a = np.full(vec.action_space.shape, 0.1, np.float32)
    for _ in range(n_steps):
        obs, r, *_ = vec.step(a)
        out.append(obs)
        rewards.append(r)
    vec.close()
    return np.array(out), np.array(rewards)


def test_async_fork_after_the_parent_started_numbas_threads():
    """The parent starts numba's thread pool (GNU OpenMP where that is the layer), then the default "fork" context:
    the workers run the serial kernels and give SyncVectorEnv's rollout bit for bit."""
    numba.set_num_threads(numba.get_num_threads())  # starts the pool in this process
    kw = case_kwargs(PMC, episode_time=0.2)
    kw["settle_time"] = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        ref = _rollout(gym.make_vec(PMC, 2, vectorization_mode="sync", **kw))
        got = _rollout(gym.make_vec(PMC, 2, vectorization_mode="async", **kw))
    np.testing.assert_array_equal(got[0], ref[0])
    np.testing.assert_array_equal(got[1], ref[1])


def test_parallel_kernels_in_a_fork_after_gnu_openmp_say_what_to_do(monkeypatch):
    """A string long enough for two threads still needs the pool: in such a fork, a clear error, not numba's
    SIGTERM; the serial kernels run."""
    monkeypatch.setattr(fork_state, "FORKED_AFTER_GNU_OPENMP", True)
    assert sim_pointmass.run_on_threads(1, lambda v: v + 1, None, 1) == 2
    with pytest.raises(RuntimeError, match=r"forked.*GNU OpenMP.*forkserver"):
        sim_pointmass.run_on_threads(2, None, lambda v: v, 1)
    assert sim_pointmass.kernel_threads(CHUNK, 16) == 1 and sim_pointmass.kernel_threads(CHUNK + 1, 16) == 2
