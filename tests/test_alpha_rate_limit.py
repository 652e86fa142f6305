"""A limit of the quasi-steady model, reported as such: the alpha-rate terms at large sideslip.

The mill under bang-bang controls on all 101 wings tumbles wing 46 to about -74 deg sideslip at t = 0.384 s. There
the alpha-rate terms (-k g^T in the mass matrix, g = d alpha / d v_a growing as 1 / in-plane airspeed) make the mass
matrix singular: the accelerations pass through a pole and both error-controlled methods (DP5(4), ROS34PW2)
collapse their steps at the same time. The oracle for the time is a separate reference integration, fixed-step RK4
at 0.1 ms (no error control, no step-size collapse), along which the named wing's pitch acceleration passes through
the pole (its largest magnitude and a sign change, at 0.3835-0.3836 s here); for the cause, the same state with the two
alpha-rate columns of the wing table (C_L_alphadot, C_m_alphadot) set to zero, evaluated here independently of the
report, and the sign change of the acceleration across the pole.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.simulator import SimulationError
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings
from laddermill_gym.studies.numerics.stress import control_limits


@pytest.fixture(scope="module")
def failed():
    base = build_simulator("laddermill")
    lo, hi = control_limits(base)
    out = {}
    for method in ("ros34pw2a",):
        sim = with_settings(base, method=method, rtol=1e-5)
        sim.controls[:] = np.where(np.arange(lo.size) % 2 == 0, lo, hi)  # the stress suite's first bang-bang pattern
        with pytest.raises(SimulationError) as err:
            sim.advance_to(1.0)
        out[method] = (sim, str(err.value))
    return out


def pitch_accelerations_rk4(wing: int, dt: float = 1e-4, start: float = 0.37, end: float = 0.395):
    """(times, pitch accelerations q' [rad/s^2] of ``wing``) after each fixed RK4 step of ``dt`` [s] between ``start``
    and ``end``, from the same start and bang-bang controls as the error-controlled run."""
    base = build_simulator("laddermill")
    lo, hi = control_limits(base)
    sim = with_settings(base, method="rk4", dt=dt)
    sim.controls[:] = np.where(np.arange(lo.size) % 2 == 0, lo, hi)
    q = [i for i in range(sim.n_state) if sim.state_name(i) == f"wing {wing} q [rad/s]"][0]
    sim.step(n_steps=int(round(start / dt)))
    times, acc = [], []
    while sim.t < end:
        sim.step(n_steps=1)
        times.append(sim.t)
        acc.append(sim.rhs(sim.t, sim.state)[q])
    return np.array(times), np.array(acc)


def test_the_error_controlled_method_stops_at_the_pole(failed):
    """The stop time against the pole on the RK4 reference trajectory (docs/work_precision.md: 0.3836 s, DP5(4)
    stops there too)."""
    sim, msg = failed["ros34pw2a"]
    k = int(msg.split("; wing ")[-1].split(" ")[0])
    times, acc = pitch_accelerations_rk4(k)
    peak = int(np.argmax(np.abs(acc)))
    assert abs(acc[peak]) > 20 * np.median(np.abs(acc)), (times[peak], acc[peak])  # a pole, not a bump
    assert np.any(np.sign(acc[peak - 1: peak + 2]) != np.sign(acc[peak])), acc[peak - 1: peak + 2]
    assert abs(sim.t - times[peak]) < 1e-3, (sim.t, times[peak])


def test_the_report_names_the_alpha_rate_terms(failed):
    sim, msg = failed["ros34pw2a"]
    assert "step size collapsed" in msg and "alpha-rate terms make the mass matrix nearly singular" in msg, msg
    k = int(msg.split("; wing ")[-1].split(" ")[0])
    al, be = np.degrees(sim.wing_alpha_beta()[k])
    print(f"stopped at t = {sim.t:.4f} s: wing {k} at alpha {al:.3f} deg, sideslip {be:.3f} deg")
    assert abs(be) > 60.0, (k, al, be)  # flow along the span: outside the model's small-sideslip range
    x, t = sim.state.copy(), sim.t
    dx = sim.rhs(t, x)
    q = [i for i in range(sim.n_state) if sim.state_name(i) == f"wing {k} q [rad/s]"][0]
    ac = sim.model.ac
    keep = ac.copy()
    try:
        ac[:, :, :, [AERO_INDEX["CLad"], AERO_INDEX["Cmad"]]] = 0.0
        dx0 = sim.rhs(t, x)
    finally:
        ac[:] = keep
    print(f"pitch acceleration {dx[q]:.3g} rad/s^2, without the alpha-rate columns {dx0[q]:.3g} rad/s^2")
    assert abs(dx[q]) > 1e4 * abs(dx0[q]), (dx[q], dx0[q])
    # across the pole: a few microseconds further along the trajectory the acceleration has the other sign
    later = sim.rhs(t + 1e-4, x + 1e-4 * dx)
    print(f"1e-4 s later: {later[q]:.3g} rad/s^2")
    assert np.sign(later[q]) != np.sign(dx[q]) or abs(later[q]) > 10 * abs(dx[q]), (dx[q], later[q])


def test_rk4_at_the_scene_step_runs_through():
    """RK4 at the scene's 10 ms step never evaluates the state at the pole and goes on (docs/work_precision.md):
    the limit is the model's, not the integrators'."""
    base = build_simulator("laddermill")
    lo, hi = control_limits(base)
    sim = with_settings(base)
    sim.controls[:] = np.where(np.arange(lo.size) % 2 == 0, lo, hi)
    sim.step(n_steps=int(round(0.5 / sim.settings.dt)))
    assert sim.t == pytest.approx(0.5) and np.all(np.isfinite(sim.state))


def test_a_fixed_step_that_lands_on_the_pole_is_named_so():
    """The stress suite's mill under bang-bang controls at the scene's 10 ms RK4 step: the wings tumble (sideslip
    60-90 deg within the first second) and at 5.46 s a step throws one wing to a rate no physics gives (185 rad/s,
    over the 100 rad/s limit). The report names the pole the trajectory meets inside that step, so the stress suite
    counts a limit of the quasi-steady model, not a numerical failure. The oracle: a separate error-controlled run
    of that step through the public API (DP5(4) at rtol 1e-9 from the last good state, a new simulator) stops at
    the reported time, where the named wing's acceleration is over a thousand times what it is without the two
    alpha-rate columns (zeroed here, independently of the report)."""
    from laddermill_gym.studies.numerics import stress_cases as sc

    base = build_simulator("laddermill")
    lo, hi = control_limits(base)
    bang = lambda t: np.where((np.arange(lo.size) + int(t / 0.5)) % 2 == 0, lo, hi)  # noqa: E731
    sim = with_settings(base)
    row = sc.run_for(sim, 20.0, bang, sample=0.5)
    assert row["passed"] and row["outcome"].startswith("terminated (limit of the quasi-steady model): wing "), row
    k = int(row["outcome"].split(": wing ")[1].split(" ")[0])
    assert abs(np.degrees(sim.wing_alpha_beta()[k, 1])) > 60.0  # flow along the span
    exact = with_settings(base, state=sim.state.copy(), controls=sim.controls.copy(), method="dp54", rtol=1e-9,
                          atol=1e-12)
    with pytest.raises(SimulationError, match="step size collapsed"):
        exact.advance_to(sim.settings.dt)
    assert 0.0 < exact.t < sim.settings.dt  # the trajectory meets the pole inside the failed step
    reported = float(row["outcome"].split("meets the pole at t = ")[1].split(" s")[0])
    assert abs(sim.t + exact.t - reported) < 1e-5, (sim.t, exact.t, reported)
    acc = [i for i in range(sim.n_state) if sim.state_name(i).split(" [")[0] in
           {f"wing {k} {v}" for v in ("u", "v", "w", "p", "q", "r")}]  # wing k's accelerations
    dx = exact.rhs(exact.t, exact.state)
    ac = exact.model.ac
    keep = ac.copy()
    try:
        ac[:, :, :, [AERO_INDEX["CLad"], AERO_INDEX["Cmad"]]] = 0.0
        dx0 = exact.rhs(exact.t, exact.state)
    finally:
        ac[:] = keep
    assert np.max(np.abs(dx[acc])) > 1e3 * np.max(np.abs(dx0[acc])), (dx[acc], dx0[acc])
    # a step beyond RK4's stability limit (20 ms > 12.2 ms) from the trim, where no wing is near a pole: a numerical
    # failure, not named a pole (the exact run passes that step)
    fast = with_settings(base, dt=0.02)
    row = sc.run_for(fast, 0.5, bang, sample=0.5)
    assert row["outcome"].startswith("failed: ") and "alpha-rate" not in row["outcome"], row
