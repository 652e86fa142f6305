"""The automatic stable-step estimate (``studies/numerics/stable_step.py``).

Oracles: RK4's stability boundary in closed form (2 sqrt 2 on the imaginary axis, the real root 2.7853 of
|1 + x + x^2/2 + x^3/6 + x^4/24| = 1) and DP5(4)'s stability polynomial (1 + z + ... + z^5/120 + z^6/600,
Hairer, Norsett & Wanner, Solving ODEs I, sec. II.5); the fastest cable mode measured from outside (issue 13:
-13 +- 154i 1/s on ``tethered_wing``); and direct simulation: RK4 just below the estimated step follows a DP5(4)
reference, just above it the fastest mode grows until the run breaks down.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from laddermill_gym.sim.simulator import SimulationError
from laddermill_gym.studies.numerics import stable_step as ss
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings


def test_stability_boundaries_closed_form():
    assert ss.ray_limit("rk4", math.pi / 2) == pytest.approx(2 * math.sqrt(2), rel=1e-9)
    real_root = brentq(lambda x: 1 - x + x**2 / 2 - x**3 / 6 + x**4 / 24 - 1, 2.0, 3.0)
    assert ss.ray_limit("rk4", math.pi) == pytest.approx(real_root, rel=1e-9)
    z = np.array([-0.7 + 0.4j, 1.3j, -2.0])
    taylor = sum(z**k / math.factorial(k) for k in range(6)) + z**6 / 600
    assert np.allclose(ss.stability_function("dp54", z), taylor, rtol=1e-13)
    assert np.allclose(ss.stability_function("rk4", z), sum(z**k / math.factorial(k) for k in range(5)), rtol=1e-13)


@pytest.fixture(scope="module")
def wing():
    return build_simulator("tethered_wing")


def test_fastest_mode_and_arpack(wing, monkeypatch):
    est = ss.estimate_stable_step(wing, "rk4")
    lam = est.eigenvalue
    assert abs(lam.real + 13) < 1.5 and abs(abs(lam.imag) - 154) < 3  # the issue's -13 +- 154i 1/s
    assert est.dt_max == pytest.approx(ss.ray_limit("rk4", math.atan2(lam.imag, lam.real)) / abs(lam))
    dense = ss.jacobian_eigenvalues(wing)
    monkeypatch.setattr(ss, "DENSE_MAX", 5)  # ARPACK on Jacobian-vector products instead
    sparse = ss.jacobian_eigenvalues(wing, k=6)
    for a, b in ((sparse[0], dense[0]), (sparse[2], dense[2])):  # conjugate pairs: compare real and |imag|
        assert abs(a.real - b.real) < 1e-3 * abs(b) and abs(abs(a.imag) - abs(b.imag)) < 1e-4 * abs(b)


def test_estimate_separates_stable_from_unstable_runs(wing):
    est = ss.estimate_stable_step(wing, "rk4")
    horizon = 3.0
    ref = with_settings(wing, method="dp54")
    ref.advance_to(horizon, rtol=1e-10, atol=1e-10)
    below = with_settings(wing, dt=horizon / math.ceil(horizon / (0.97 * est.dt_max)))
    below.step(n_steps=int(round(horizon / below.settings.dt)))
    assert np.max(np.abs(below.state - ref.state)) < 1e-6
    above = with_settings(wing, dt=horizon / math.floor(horizon / (1.05 * est.dt_max)))
    with pytest.raises(SimulationError):
        above.step(n_steps=int(round(horizon / above.settings.dt)))


def test_check_step_warns_naming_dt(wing):
    est = ss.check_step(wing)  # the scene's 5 ms: no warning
    over = with_settings(wing, dt=1.1 * est.dt_max)
    with pytest.warns(ss.UnstableStepWarning, match=r"dt = 0\.02\d* s .* estimated stability limit"):
        ss.check_step(over)
    with pytest.raises(ValueError, match="stability limit"):
        ss.check_step(over, action="error")


def test_a_scene_past_its_stable_step_warns_when_its_simulator_is_made(monkeypatch):
    """The issue's case: ``ladder_chain`` at 0.025 s (the README's old "largest stable" step) oscillates, bounded,
    without any error. Made through its scene, the simulator warns with the estimate (0.02445 s against the
    bisection's 0.02458 s, docs/work_precision.md); the scene's own 12.5 ms does not warn."""
    import warnings

    from laddermill_gym import load_scene
    from laddermill_gym.ladder import rigid_scene as scene_module

    monkeypatch.setattr(scene_module, "CHECKED_STEPS", set())  # checked once per process: forget earlier tests'
    with warnings.catch_warnings():
        warnings.simplefilter("error", ss.UnstableStepWarning)
        load_scene("ladder_chain").simulator()
    with pytest.warns(ss.UnstableStepWarning, match=r"dt = 0\.025 s .* 0\.024\d* s") as record:
        load_scene("ladder_chain", dt=0.025).simulator()
    print(record[0].message)


@pytest.mark.slow
def test_after_the_first_transfer_the_short_first_element_sets_a_smaller_step(capsys):
    """``laddermill stable-step laddermill --after-transfer``: the scene is stepped at its own RK4 step to the first
    wing transfer (the station's count changes in the last step taken), where the station's first element is at its
    shortest (l_p / 10, docs/numerics.md) and so at its stiffest (EA / l0): the limiting mode is faster and the stable
    step smaller than at the start (docs/benchmarks.md: 0.0122 s against 0.0154 s, -30 +- 240i 1/s)."""
    sim = build_simulator("laddermill")
    start = ss.estimate_stable_step(sim, "rk4")
    t = ss.step_to_first_transfer(sim)
    assert sim.transfers() == 1 and t == pytest.approx(sim.t)
    assert round(t / sim.settings.dt) == pytest.approx(t / sim.settings.dt, abs=1e-6)  # whole steps of the scene's dt
    after = ss.estimate_stable_step(sim, "rk4")
    print(f"\nladdermill at the start: {start}\nafter the first transfer (t = {t:.2f} s): {after}")
    assert after.dt_max < 0.9 * start.dt_max and abs(after.eigenvalue) > abs(start.eigenvalue)
    with pytest.raises(ValueError, match="--after-transfer: .*no moving cable"):
        ss.step_to_first_transfer(build_simulator("tethered_wing"))
    assert ss.main(["laddermill", "--after-transfer"]) == 0
    assert f"after the first wing transfer, at t = {t:.2f} s" in capsys.readouterr().out
