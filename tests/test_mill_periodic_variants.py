"""The in-plane mill's run to periodic motion (ladder/periodic.py) at the scene's 10 ms step against half of it,
and on small mills (docs/moving_cable.md: "Halving the step changes nothing in the periodic motion", "Small mills
wander"). Oracle for the step: the run at 5 ms (RK4's own error falls about 16-fold per halving, so what is left
between the two runs is mostly the search's: both stop when shape and power repeat to 1e-3 per period, and the
bound of 1e-4 of the base tension, 16 N, is of that size); for the small mills, the search's own criteria (shape and
power repeating to 1e-3 per period for two periods)."""

import numpy as np
import pytest

from laddermill_gym import load_scene
from laddermill_gym.ladder.periodic import run_to_periodic

TOL = dict(shape_tol=1e-3, power_tol=1e-3, progress=False)  # the page's command's criteria


@pytest.mark.slow
def test_halving_the_step_changes_nothing_in_the_periodic_motion():
    """The 2D default mill run to periodic motion at dt = 10 ms and 5 ms: the mean power within 0.5 % and every
    element's period-mean tension within 1e-4 of the first element's. Prints both powers and times and the largest
    tension difference."""
    runs = {dt: run_to_periodic(load_scene("laddermill", dimension=2, dt=dt).simulator(), **TOL)
            for dt in (0.01, 0.005)}
    for dt, res in runs.items():
        print(f"\ndt = {dt * 1e3:g} ms: {res.summary()}; first element {res.tension_mean_N[0] / 1e3:.1f} kN, last "
              f"{res.tension_mean_N[-1] / 1e3:.1f} kN")
    a, b = runs[0.01], runs[0.005]
    diff = np.abs(a.tension_mean_N - b.tension_mean_N)
    print(f"period-mean tensions at 10 ms against 5 ms: within {diff.max():.1f} N (element {int(np.argmax(diff))}) "
          f"of the first element's {b.tension_mean_N[0] / 1e3:.1f} kN; mean power {a.mean_power_W / 1e3:.2f} against "
          f"{b.mean_power_W / 1e3:.2f} kW")
    assert a.converged and b.converged
    assert a.mean_power_W == pytest.approx(b.mean_power_W, rel=5e-3)
    assert diff.max() < 1e-4 * b.tension_mean_N[0]


@pytest.mark.slow
@pytest.mark.parametrize("n_wings", [11, 21])
def test_small_mills_find_no_periodic_motion(n_wings):
    """The default mill's settings on 11 and 21 wings (2D): no periodic motion within 1500 s of search; the search
    says so with its history. Prints the summary and the last periods' power range."""
    res = run_to_periodic(load_scene("laddermill", dimension=2, n_wings=n_wings).simulator(), max_time=1500.0, **TOL)
    last = [h["mean_power_W"] / 1e3 for h in res.history[-10:]]
    print(f"\n{n_wings} wings, max_time 1500 s: {res.summary()}; the last {len(last)} periods' mean power "
          f"{min(last):.1f} to {max(last):.1f} kW")
    assert not res.converged and len(res.history) > 1
