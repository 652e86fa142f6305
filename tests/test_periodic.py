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


@pytest.mark.parametrize("inject_after", [None, 300])
def test_tensions_of_the_last_period_only_are_the_same_bits(inject_after):
    """``watch_every_period=False`` (the operating point's search) evaluates the tensions of the last period only,
    after the search, from the recorded states: the oracle is the default search, which evaluates them at every
    step as it goes; tension statistics, history and shape agree bit for bit, also when the integration breaks
    down inside a period (after 300 good steps of the search)."""
    from laddermill_gym import SimulationError

    results = []
    for every in (True, False):
        sim = load_scene("laddermill", dimension=2, n_wings=11).simulator()
        real_step, calls = sim.step, {"n": 0}

        def step(*a, _sim=sim, _real=real_step, _calls=calls, **kw):
            if inject_after is not None and _sim.t > 100.0:
                _calls["n"] += 1
                if _calls["n"] > inject_after:
                    raise SimulationError(f"integration failed at t = {_sim.t:.6g} s (injected)")
            return _real(*a, **kw)

        sim.step = step
        results.append(run_to_periodic(sim, max_time=80.0, progress=False, watch_every_period=every))
    a, b = results
    assert (a.breakdown is None) == (inject_after is None)
    assert a.breakdown == b.breakdown and a.t_s == b.t_s and len(a.history) == len(b.history) >= 1

    def rows(r):
        return np.array([[h[k] for k in sorted(h)] for h in r.history])

    assert rows(a).tobytes() == rows(b).tobytes()  # (nan where a change has no previous period)
    for name in ("tension_mean_N", "tension_min_N", "tension_max_N", "shape_m"):
        assert getattr(a, name).tobytes() == getattr(b, name).tobytes(), name
    assert 0.0 < b.peak_tension_ratio <= a.peak_tension_ratio  # the last period's peak against the whole search's
