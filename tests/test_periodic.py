"""The periodic stationary motion of the moving mill (``ladder/periodic.py``).

Oracles: the generator's energy integral against the sampled tensions (P = (T_first - T_last) V_c averaged over
the period), the convergence criteria recomputed from the reported history, and the period l0 / V_c.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym import load_scene
from laddermill_gym.ladder.periodic import run_to_periodic


def test_not_converged_is_reported():
    """A small mill (11 wings) that keeps wandering: the result says so, with its history, and never raises."""
    sim = load_scene("laddermill", n_wings=11, dimension=2).simulator()
    r = run_to_periodic(sim, max_time=150.0, progress=False)
    assert r.period_s == pytest.approx(70.0 / 2.0)
    assert not r.converged
    assert "NOT converged" in r.summary()
    assert len(r.history) >= 3
    assert all(h["t_s"] > 30.0 for h in r.history)  # the search starts after the schedule's ramp


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="needs a moving cable"):
        run_to_periodic(load_scene("tethered_wing").simulator(), progress=False)


@pytest.mark.slow
def test_default_mill_reaches_its_periodic_motion():
    """The default mill in plane (101 wings, V_c = 2 m/s) repeats itself to 1e-3 l0 and 1e-3 in power (measured:
    after about 1100 s, mean power 66 kW); the mean power from the energy integral equals the period-mean of the
    sampled tension difference times V_c (1 % for the step-end sampling of a fast-varying tension)."""
    sim = load_scene("laddermill", dimension=2).simulator()
    r = run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=3000.0, progress=False)
    assert r.converged, r.summary()
    last = r.history[-1]
    assert last["shape_change"] < 1e-3 and last["power_change"] < 1e-3
    sampled = (r.tension_mean_N[0] - r.tension_mean_N[-1]) * 2.0
    assert r.mean_power_W == pytest.approx(sampled, rel=1e-2)
    # the smallest tension is near the top of the loop (Meijaard et al. 1999, Fig. 7)
    top = int(np.argmax(-r.shape_m[:, 2]))
    assert abs(int(np.argmin(r.tension_mean_N)) - top) <= 3


def test_a_breakdown_during_the_search_is_reported_not_raised():
    """A mill that diverges while it is searched (here: the step that fails is simulated after 300 good steps of
    the search) returns a result that says so, with the report and the last period's power, instead of raising."""
    from laddermill_gym import SimulationError

    sim = load_scene("laddermill", dimension=2, n_wings=11).simulator()
    real_step, calls = sim.step, {"n": 0}

    def step(*a, **kw):
        if sim.t > 100.0:  # after the speed ramp and the first transfer: inside the search
            calls["n"] += 1
            if calls["n"] > 300:
                raise SimulationError(f"integration failed at t = {sim.t:.6g} s (injected)")
        return real_step(*a, **kw)

    sim.step = step
    res = run_to_periodic(sim, max_time=2000.0, progress=False)
    assert not res.converged and res.breakdown.endswith("(injected)")
    assert "broke down" in res.summary()
    assert np.isfinite(res.mean_power_W) and res.tension_mean_N.shape == (sim.assembly.elements.count,)
