"""Point-mass fidelity (Podgaets & Ockels 2007) against independent oracles (../shared/design/oracles.md):
the block-tridiagonal solve against a dense numpy solve of the same system, the elastic catenary (Irvine) and
its second-order convergence, axial and transverse standing waves against the lumped chain's dispersion
relation (explicit) and the closed form of backward Euler on an oscillator (implicit)."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq, fsolve

from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.params import WindParams
from laddermill_gym.model.pointmass import PointMassString, make_work
from laddermill_gym.sim.pointmass import PointMassSimulator

STILL = WindParams(v0=0.0, rho0=0.0)  # no air


def _chain(n_el, length, span, *, EA, DA, mu, gravity, wind=STILL, cable_drag=(0.0, 0.0), diameter=0.01):
    cab = CableSpec(diameter=diameter, mass_per_length=mu, EA=EA, DA=DA, cn0=cable_drag[0], ct0=cable_drag[1])
    return PointMassString(wind=wind, gravity=gravity, cable=cab, element_length=length / n_el, n_nodes=n_el - 1,
                           anchor=np.zeros(3), end=np.array([span, 0.0, 0.0]))


# ----------------------------------------------------------------------------------------- the linear solve
def _dense_step(s, P, V, dt):
    """One linearly implicit Euler step by a dense numpy solve, written from the equations of
    kernels/pointmass/implicit.py (independent of its block elimination)."""
    c, l0, n = s.cable, s.element_length, s.n_nodes
    pts = np.vstack([s.anchor, P] + ([s.end] if s.end is not None else []))
    A, F, m = np.zeros((3 * n, 3 * n)), np.zeros(3 * n), np.zeros(n)
    for e in range(s.n_elements):
        d = pts[e + 1] - pts[e]
        ln = np.linalg.norm(d)
        t = d / ln
        T = max(c.EA * (ln - l0) / l0, 0.0)
        tt = np.outer(t, t)
        S = dt * (c.DA / l0) * tt + dt * dt * ((c.EA / l0) * tt + T / ln * (np.eye(3) - tt))
        for a, sign in ((e - 1, 1.0), (e, -1.0)):
            if 0 <= a < n:
                F[3 * a:3 * a + 3] += sign * T * t
                m[a] += 0.5 * c.mass_per_length * l0
        for a in (e - 1, e):
            for b in (e - 1, e):
                if 0 <= a < n and 0 <= b < n:
                    A[3 * a:3 * a + 3, 3 * b:3 * b + 3] += S if a == b else -S
    A += np.kron(np.diag(m), np.eye(3))
    return np.linalg.solve(A, np.repeat(m, 3) * V.ravel() + dt * F).reshape(-1, 3)


@pytest.mark.parametrize("end_fixed", [True, False])
@pytest.mark.parametrize("segment", [1, 3, 1024])
def test_block_elimination_matches_dense_solve(end_fixed, segment):
    rng = np.random.default_rng(7)
    n, dt = 7, 0.3
    cab = CableSpec(diameter=0.1, mass_per_length=2.0, EA=1e4, DA=50.0, cn0=0.0, ct0=0.0)
    s = PointMassString(wind=STILL, gravity=0.0, cable=cab, element_length=1.0, n_nodes=n, anchor=np.zeros(3),
                        end=np.array([8.5, 0.3, 0.1]) if end_fixed else None)
    P = np.cumsum(np.tile([1.06, 0.0, 0.0], (n, 1)) + 0.05 * rng.standard_normal((n, 3)), axis=0)
    V = rng.standard_normal((n, 3))
    sim = PointMassSimulator(s, np.hstack([P, V]).ravel(), np.zeros(3), dt=dt, method="implicit")
    sim.W = make_work(s, segment=segment)
    ref = _dense_step(s, P, V, dt)
    sim.step(1)
    np.testing.assert_allclose(sim.velocities, ref, rtol=0, atol=1e-12 * np.abs(ref).max())
    np.testing.assert_allclose(sim.positions, P + dt * ref, rtol=0, atol=1e-12)


# ----------------------------------------------------------------------------------------- Irvine catenary
def _irvine(L0, span, w, EA):
    def res(p):
        H, V = p
        x = H * L0 / EA + (H / w) * (math.asinh((w * L0 - V) / H) + math.asinh(V / H))
        z = (w * L0 ** 2 / 2 - V * L0) / EA + (H / w) * (math.sqrt(1 + ((w * L0 - V) / H) ** 2)
                                                          - math.sqrt(1 + (V / H) ** 2))
        return [x - span, z]
    return fsolve(res, [600.0, 500.0], xtol=1e-13)


def _relaxed_catenary(n_el, dt=0.2, steps=400):
    """Chain of n_el elements relaxed to rest by the implicit method from the inextensible catenary; returns
    (H [N], mid-span sag [m])."""
    g, w = 9.81, 10.0
    s = _chain(n_el, 110.0, 100.0, EA=1e6, DA=1e3, mu=w / g, gravity=g,
               wind=WindParams(v0=0.0, rho0=1.225), cable_drag=(1.1, 0.0), diameter=0.1)
    a = brentq(lambda a: 2 * a * math.sinh(50 / a) - 110, 10, 1000)
    sarc = np.linspace(0, 110, n_el + 1)[1:-1]
    xs = 50 + a * np.arcsinh((sarc - 55) / a)
    x0 = np.zeros(s.state_size)
    x0[0::6], x0[2::6] = xs, a * np.cosh(50 / a) - a * np.cosh((xs - 50) / a)
    sim = PointMassSimulator(s, x0, np.zeros(3), dt=dt, method="implicit")
    sim.step(steps)
    assert np.abs(sim.velocities).max() < 1e-6
    T, p = sim.tensions(), sim.positions
    H = T[0] * p[0, 0] / np.linalg.norm(p[0])
    mid = np.interp(50.0, np.concatenate([[0], p[:, 0], [100]]), np.concatenate([[0], p[:, 2], [0]]))
    return H, mid


def test_catenary_matches_irvine_at_second_order():
    H_ref, V_ref = _irvine(110.0, 100.0, 10.0, 1e6)
    assert H_ref == pytest.approx(651.998593, rel=1e-8) and V_ref == pytest.approx(550.0, rel=1e-8)
    errs = {}
    for n in (16, 64):
        H, sag = _relaxed_catenary(n)
        errs[n] = (H - H_ref) / H_ref
        assert sag == pytest.approx(20.114865, abs=0.05)  # z down: the sag is +z
    print(f"Irvine H = {H_ref:.6f} N; relative error of H at n = 16: {errs[16]:.2g}, at n = 64: {errs[64]:.2g}")
    # oracles.md: relative error of H about -0.37/n^2 (n=16: -1.4e-3, n=64: -8.9e-5)
    assert errs[16] == pytest.approx(-1.4e-3, rel=0.15)
    assert errs[64] == pytest.approx(-8.9e-5, rel=0.15)
    assert math.log(errs[16] / errs[64], 4) == pytest.approx(2.0, abs=0.1)


def test_catenary_at_one_centimetre():
    """The string's own resolution, 1 cm (11,000 elements): H within the -0.37/n^2 estimate's 3e-9."""
    H_ref, _ = _irvine(110.0, 100.0, 10.0, 1e6)
    H, sag = _relaxed_catenary(11000, steps=600)
    print(f"1 cm (11,000 elements): relative error of H {(H - H_ref) / H_ref:.2g}, sag {sag:.6f} m")
    assert abs(H - H_ref) / H_ref < 1e-6
    assert sag == pytest.approx(20.114865, abs=1e-3)


# ----------------------------------------------------------------------------------------- waves
def _mode_history(axis, mode, n_el, method, dt, periods, pre=0.01):
    """Fixed-fixed straight string along x prestretched by ``pre``, no gravity or air, Voigt damping off;
    node displacements start in the standing-wave shape sin(mode pi j / n_el) along ``axis`` (0 axial,
    1 transverse). Returns (modal amplitude history, times, string, stretched element length)."""
    EA, mu, L = 1e5, 0.5, 10.0
    s = _chain(n_el, L, L * (1 + pre), EA=EA, DA=0.0, mu=mu, gravity=0.0)
    j = np.arange(1, n_el)
    shape = np.sin(mode * np.pi * j / n_el)
    x0 = np.zeros(s.state_size)
    x0[0::6] = j * L * (1 + pre) / n_el
    x0[axis::6] += 1e-6 * L * shape
    sim = PointMassSimulator(s, x0, np.zeros(3), dt=dt, method=method)
    base = x0[axis::6] - 1e-6 * L * shape
    n_steps = int(periods)
    hist = np.empty(n_steps)
    for k in range(n_steps):
        sim.step(1)
        hist[k] = (sim.positions[:, axis] - base) @ shape / (shape @ shape)
    return hist, dt * np.arange(1, n_steps + 1), s, L * (1 + pre) / n_el


def _frequency(hist, times):
    """Angular frequency from the first and last upward zero crossings (linear interpolation)."""
    up = np.nonzero((hist[:-1] < 0) & (hist[1:] >= 0))[0]
    tc = times[up] - hist[up] * (times[up + 1] - times[up]) / (hist[up + 1] - hist[up])
    return 2 * np.pi * (len(tc) - 1) / (tc[-1] - tc[0])


@pytest.mark.parametrize("axis,mode", [(0, 1), (0, 17), (1, 1), (1, 17)])
def test_standing_waves_follow_the_chain_dispersion_relation(axis, mode):
    n_el = 20
    EA, mu, l0 = 1e5, 0.5, 0.5
    ln = l0 * 1.01
    k_el = EA / l0 if axis == 0 else EA * 0.01 / ln  # axial EA/l0; transverse T/l
    w_exact = 2 * math.sqrt(k_el / (mu * l0)) * math.sin(mode * math.pi / (2 * n_el))  # oracles.md
    dt = 0.01 / w_exact
    hist, times, _, _ = _mode_history(axis, mode, n_el, "explicit", dt, 20 * 2 * math.pi / (w_exact * dt))
    w_num = _frequency(hist, times)
    # symplectic Euler's own frequency (closed form for x'' = -w^2 x): cos(w~ dt) = 1 - (w dt)^2 / 2
    w_se = math.acos(1 - (w_exact * dt) ** 2 / 2) / dt
    assert w_num == pytest.approx(w_se, rel=2e-4)
    assert w_se == pytest.approx(w_exact, rel=1e-4)
    if mode == 1:  # the long-wave limit: phase speed in material length = sqrt(EA/mu) or sqrt(T/mu) scaled
        c = w_exact / (mode * math.pi / (n_el * l0))
        c_ref = math.sqrt(EA / mu) if axis == 0 else math.sqrt(EA * 0.01 * l0 / ln / mu)
        assert c == pytest.approx(c_ref, rel=2e-3)


def test_implicit_axial_mode_is_backward_euler():
    """Linear axial mode under the implicit method: per step the amplitude shrinks by 1/sqrt(1 + (w dt)^2)
    and the phase advances by atan(w dt) (backward Euler on x'' = -w^2 x, closed form)."""
    n_el, mode = 20, 3
    w = 2 * math.sqrt(1e5 / 0.5 / (0.5 * 0.5)) * math.sin(mode * math.pi / (2 * n_el))
    dt = 0.3 / w
    hist, times, _, _ = _mode_history(0, mode, n_el, "implicit", dt, 400)
    assert _frequency(hist, times) == pytest.approx(math.atan(w * dt) / dt, rel=2e-3)
    # amplitude envelope: |hist| peaks decay geometrically at the closed-form rate
    rate = 1 / math.sqrt(1 + (w * dt) ** 2)
    mag = np.abs(hist)
    peaks = [k for k in range(1, len(hist) - 1) if mag[k] >= mag[k - 1] and mag[k] >= mag[k + 1]]
    k0, k1 = peaks[1], peaks[-2]
    assert abs(hist[k1] / hist[k0]) ** (1 / (k1 - k0)) == pytest.approx(rate, rel=5e-3)
