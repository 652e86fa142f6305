"""The partitioned block elimination of the implicit point-mass step (kernels/pointmass/partitioned.py) on P
chunks: against scipy's banded solver (an independent assembly of the same matrix) on random strings of several
sizes, the implicit step on P chunks against one chunk on a short podgaets_5km run, and the same bits for a
given P on any thread count and in separate processes."""

import hashlib
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.linalg import eigvals_banded, solve_banded

from laddermill_gym.kernels.contract import N3_SIZE, N3_VEL
from laddermill_gym.kernels.pointmass.implicit import implicit_advance_parts
from laddermill_gym.kernels.pointmass.partitioned import MIN_PART, chunk_range, partitioned_solve, solver_parts
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.pointmass import PointMassKite, PointMassString, make_work, pack

PARTS = (1, 2, 3, 4, 7)
KITE = PointMassKite(name="k", mass=20.0, area=10.0, alpha=np.linspace(-np.pi, np.pi, 5), cl=np.zeros(5),
                     cd=np.zeros(5))


def _random_string(rng, n, end_fixed, *, EA=1e3, DA=10.0, mu=1.0):
    """n free nodes on 1 m elements in random directions, stretched or slack by up to 20 %, a 20 kg kite on
    every seventh node."""
    cab = CableSpec(diameter=0.01, mass_per_length=mu, EA=EA, DA=DA, cn0=0.0, ct0=0.0)
    d = rng.standard_normal((n + 1, 3))
    d *= (1.0 + 0.2 * rng.uniform(-1, 1, (n + 1, 1))) / np.linalg.norm(d, axis=1, keepdims=True)
    pts = np.cumsum(d, axis=0)
    s = PointMassString(wind=WindParams(v0=0.0, rho0=0.0), gravity=0.0, cable=cab, element_length=1.0, n_nodes=n,
                        anchor=np.zeros(3), end=pts[n] if end_fixed else None, kite=KITE,
                        kite_nodes=np.arange(3, n, 7))
    return s, pts[:n]


def _banded(s, pos, tension, dt):
    """The step's matrix M + sum_e S_e (3 n x 3 n) in scipy's banded storage (5 sub- and 5 superdiagonals),
    assembled from its definition (kernels/pointmass/implicit.py's docstring) without the kernels."""
    n, l0, c = s.n_nodes, s.element_length, s.cable
    pts = np.vstack([s.anchor, pos] + ([s.end] if s.end is not None else []))
    ab = np.zeros((11, 3 * n))
    mass = np.full(n, c.mass_per_length * l0)
    if s.end is None:
        mass[-1] *= 0.5
    mass[s.kite_nodes] += s.kite.mass

    def add(i, j, block):
        for a in range(3):
            for b in range(3):
                ab[5 + 3 * i + a - 3 * j - b, 3 * j + b] += block[a, b]

    for e in range(s.n_elements):
        d = pts[e + 1] - pts[e]
        ln = np.linalg.norm(d)
        t = d / ln
        b = dt * dt * tension[e] / ln
        S = (dt * c.DA / l0 + dt * dt * c.EA / l0 - b) * np.outer(t, t) + b * np.eye(3)
        for i in (e - 1, e):
            for j in (e - 1, e):
                if 0 <= i < n and 0 <= j < n:
                    add(i, j, S if i == j else -S)
    for i in range(n):
        add(i, i, mass[i] * np.eye(3))
    return ab


def _backward_error(ab, v, rhs):
    """|A v - rhs|_inf / (|A|_inf |v|_inf + |rhs|_inf) for A in banded storage."""
    m = v.size
    av, row = np.zeros(m), np.zeros(m)
    for k in range(-5, 6):  # ab[5 + i - j, j] = A[i, j], j = i - k
        i = np.arange(max(0, k), min(m, m + k))
        av[i] += ab[5 + k, i - k] * v[i - k]
        row[i] += np.abs(ab[5 + k, i - k])
    return np.abs(av - rhs).max() / (row.max() * np.abs(v).max() + np.abs(rhs).max())


def _solve_parts(s, pos, tension, dt, rhs, P, segment):
    x = np.zeros(s.state_size)
    x.reshape(-1, N3_SIZE)[:, :3] = pos
    x.reshape(-1, N3_SIZE)[:, N3_VEL:N3_VEL + 3] = rhs.reshape(-1, 3)
    W = make_work(s, segment=segment, parts=8)
    W.tension[:] = tension
    partitioned_solve(x, W.tension, pack(s), dt, W, P)
    return x.reshape(-1, N3_SIZE)[:, N3_VEL:N3_VEL + 3].ravel()


@pytest.mark.parametrize("n, end_fixed, segment", [(13, True, 1), (64, False, 5), (1000, True, 1024),
                                                   (5003, False, 64)])
def test_partitioned_solve_matches_banded_solver(n, end_fixed, segment):
    """Every P (more chunks than nodes allow is clamped to (n + 1) // 2) against solve_banded: 1e-13 of the
    solution's largest component (measured: at most 3.4e-15)."""
    rng = np.random.default_rng(n)
    s, pos = _random_string(rng, n, end_fixed)
    tension = rng.uniform(0.0, 200.0, s.n_elements) * (rng.uniform(size=s.n_elements) > 0.3)
    rhs = rng.standard_normal(3 * n)
    ref = solve_banded((5, 5), _banded(s, pos, tension, 0.1), rhs)
    for P in PARTS:
        got = _solve_parts(s, pos, tension, 0.1, rhs, P, segment)
        err = np.abs(got - ref).max() / np.abs(ref).max()
        print(f"n = {n}, P = {P}: {err:.2g} of the largest component")
        assert err < 1e-13, (P, err)


def test_stiff_string_backward_error():
    """A Podgaets-like stiff string (2,000 1 cm elements of the 2.5 cm Dyneema zigzagging at random, 3 g nodes
    against S = 2.4e5 kg along and up to 2e3 kg across the elements at dt = 0.01 s; condition number 3.3e5):
    every P solves with the backward error of the one-chunk elimination (measured 3e-12 to 5.5e-12 for P = 1
    to 7: the block Thomas without pivoting loses digits in S - S D'^{-1} S at 3 g nodes; solve_banded, with
    partial pivoting, 7e-17), and the solutions agree with P = 1 and with solve_banded to 1.5e-7 of the
    largest component."""
    rng = np.random.default_rng(3)
    s, pos = _random_string(rng, 2000, False, EA=2.16e7, DA=2.16e4, mu=0.3)
    s = PointMassString(wind=s.wind, gravity=0.0, cable=s.cable, element_length=0.01, n_nodes=s.n_nodes,
                        anchor=s.anchor, kite=KITE, kite_nodes=s.kite_nodes)
    pos = pos * 0.01
    tension = rng.uniform(0.0, 2e5, s.n_elements)
    rhs = rng.standard_normal(3 * s.n_nodes)
    ab = _banded(s, pos, tension, 0.01)
    eig = eigvals_banded(ab[:6], lower=False)  # symmetric: its upper band is rows 0-5 of the full band storage
    print(f"condition number {eig.max() / eig.min():.2g} (eigenvalues {eig.min():.3g} to {eig.max():.3g} kg)")
    assert eig.min() > 0 and 1e5 < eig.max() / eig.min() < 1e6  # positive definite, the docstring's 3.3e5
    ref = solve_banded((5, 5), ab, rhs)
    print(f"solve_banded's backward error {_backward_error(ab, ref, rhs):.2g}")
    assert _backward_error(ab, ref, rhs) < 1e-15
    one = _solve_parts(s, pos, tension, 0.01, rhs, 1, 128)
    for P in PARTS:
        got = _solve_parts(s, pos, tension, 0.01, rhs, P, 128)
        print(f"P = {P}: backward error {_backward_error(ab, got, rhs):.3g}, against P = 1 "
              f"{np.abs(got - one).max() / np.abs(one).max():.2g}, against solve_banded "
              f"{np.abs(got - ref).max() / np.abs(ref).max():.2g}")
        assert _backward_error(ab, got, rhs) < 1e-10, P
        assert np.abs(got - one).max() / np.abs(one).max() < 1e-6
        assert np.abs(got - ref).max() / np.abs(ref).max() < 1e-6


def test_chunks_cover_the_string():
    """Chunks and separators tile 0..n-1, each chunk at least one node; P = 2 splits at n // 2 (the two-sided
    elimination's middle); end chunks 5/3 the middle ones."""
    for n in (3, 4, 13, 100, 4097):
        for P in range(2, (n + 1) // 2 + 1):
            nodes = []
            for c in range(P):
                lo, hi = chunk_range(n, P, c)
                assert hi > lo
                nodes += list(range(lo, hi)) + ([hi] if c < P - 1 else [])
            assert nodes == list(range(n))
        assert chunk_range(n, 2, 0) == (0, n // 2)
    sizes = [np.subtract(*chunk_range(100_003, 6, c)[::-1]) for c in range(6)]
    assert sizes[0] / sizes[1] == pytest.approx(5 / 3, rel=1e-3)
    assert sizes[-1] / sizes[2] == pytest.approx(5 / 3, rel=1e-3)
    assert [solver_parts(n, 16, 16) for n in (2, 100, 3 * MIN_PART, 500_000)] == [1, 2, 3, 16]
    assert solver_parts(500_000, 16, 8) == 8 and solver_parts(500_000, 1, 8) == 2


def _podgaets(element_length=5.0):
    from laddermill_gym.ladder.pointmass_scene import load_pointmass_scene

    sc = load_pointmass_scene("podgaets_5km", element_length=element_length)
    x0, u = sc.initial_state()
    return sc, x0, u


def _run_parts(sc, x0, u, P, steps, capacity=8):
    x = x0.copy()
    W = make_work(sc.string, parts=capacity)
    st, done = implicit_advance_parts(0.0, x, u, sc.dt, steps, pack(sc.string), W, P)
    assert (st, done) == (0, steps)
    return x


def test_implicit_steps_on_chunks_match_one_chunk():
    """podgaets_5km at 5 m elements (1000 nodes, 100 kites), 50 steps of 0.01 s from the quasi-static start:
    positions within 1e-12 of the largest position and velocities within 1e-10 of the largest velocity of
    the one-chunk run, for every P."""
    sc, x0, u = _podgaets()
    one = _run_parts(sc, x0, u, 1, 50).reshape(-1, N3_SIZE)
    for P in PARTS[1:]:
        got = _run_parts(sc, x0, u, P, 50).reshape(-1, N3_SIZE)
        dp = np.abs(got[:, :3] - one[:, :3]).max() / np.abs(one[:, :3]).max()
        dv = np.abs(got[:, 3:] - one[:, 3:]).max() / np.abs(one[:, 3:]).max()
        print(f"P = {P}: positions {dp:.2g} of the largest ({dp * np.abs(one[:, :3]).max():.2g} m), velocities "
              f"{dv:.2g} of the largest")
        assert dp < 1e-12 and dv < 1e-10, (P, dp, dv)
    # a workspace for more chunks than used changes nothing
    assert np.array_equal(_run_parts(sc, x0, u, 4, 5), _run_parts(sc, x0, u, 4, 5, capacity=16))


@pytest.mark.slow
def test_one_step_at_500000_nodes_between_chunk_counts():
    """podgaets_5km at its 1 cm (500,000 nodes), one step of 0.01 s from the quasi-static start on P = 2, 8 and 16
    chunks against one chunk: velocities within 1e-10 of the largest velocity and positions within 1e-11 m
    (measured 2.5e-11 of 0.087 m/s and 9.1e-13 m, the elimination order's roundoff)."""
    sc, x0, u = _podgaets(0.01)
    assert sc.string.n_nodes == 500_000
    one = _run_parts(sc, x0, u, 1, 1, capacity=16).reshape(-1, N3_SIZE)
    vmax = np.abs(one[:, 3:]).max()
    for P in (2, 8, 16):
        got = _run_parts(sc, x0, u, P, 1, capacity=16).reshape(-1, N3_SIZE)
        dv = np.abs(got[:, 3:] - one[:, 3:]).max() / vmax
        dp = np.abs(got[:, :3] - one[:, :3]).max()
        print(f"P = {P} against P = 1 at 500,000 nodes: velocities {dv:.2g} of the largest ({vmax:.2g} m/s), "
              f"positions {dp:.2g} m")
        assert 0 < dv < 1e-10 and dp < 1e-11, (P, dv, dp)


_PROBE = """
import hashlib, sys
import numba, numpy as np
from laddermill_gym.ladder.pointmass_scene import load_pointmass_scene
from laddermill_gym.sim.pointmass import PointMassSimulator
sc = load_pointmass_scene("podgaets_5km", element_length=0.25)
x0, u = sc.initial_state()
sim = PointMassSimulator(sc.string, x0, u, sc.dt, "implicit", threads=int(sys.argv[1]))
sim.step(3)
print(numba.config.NUMBA_NUM_THREADS, hashlib.sha256(sim.x.tobytes()).hexdigest())
"""


@pytest.mark.slow
def test_same_bits_across_processes_and_thread_counts():
    """The simulator on 4 threads (20,000 nodes: P = 4 chunks) in two fresh processes gives the same bits, and
    so does this process's P = 4 on its own thread count with a workspace for 8 chunks (the partition and the
    checkpoint spacing depend on n and P only)."""
    env = dict(os.environ, NUMBA_NUM_THREADS="4")
    out = [subprocess.run([sys.executable, "-c", _PROBE, "4"], env=env, check=True, capture_output=True,
                          text=True).stdout.split() for _ in range(2)]
    assert out[0] == out[1] and out[0][0] == "4"
    sc, x0, u = _podgaets(0.25)
    assert sc.string.n_nodes == 20_000 and solver_parts(20_000, 4, 8) == 4
    x = _run_parts(sc, x0, u, 4, 3)
    assert hashlib.sha256(x.tobytes()).hexdigest() == out[0][1]
