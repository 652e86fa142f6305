"""Breakpoints "all" on the golden direction-step runs (tests/test_golden_trajectories.py; docs/work_precision.md,
"Breakpoints"): their wind modulation's kinks lie on the step grid, so "inside" splits nothing there, while "all"
gives every step that ends or starts on a kink its own segment's line. Printed (``pytest -s``): how much "all"
changes each run, in the golden test's two measures. Oracle: a tight DP5(4) run that steps onto every kink
(``breakpoints="all"``, rtol 1e-10) over the same span; "all" must be nearer to it than "inside", so the change
is the kinks resolved, not noise (it is also far above the runs' one-ulp floor, 1e-10 or less)."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.studies.numerics.scenes import with_settings
from tests.test_golden_trajectories import CASES, componentwise, normwise


def snapshots(sim, steps, controls) -> np.ndarray:
    """The states at the start and after each span of ``steps`` (the golden test's snapshots)."""
    xs = [sim.state.copy()]
    for n in steps:
        sim.step(controls, n_steps=n)
        xs.append(sim.state.copy())
    return np.array(xs)


def reference(sim, steps) -> np.ndarray:
    """DP5(4) at rtol 1e-10 stepping onto every kink from ``sim``'s state and controls (held), sampled at the same
    times."""
    ref = with_settings(sim, sim.state, sim.controls, method="dp54", rtol=1e-10, atol=1e-10, breakpoints="all")
    xs, t = [ref.state.copy()], 0.0
    for n in steps:
        t += n * sim.settings.dt
        ref.advance_to(t)
        xs.append(ref.state.copy())
    return np.array(xs)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["tethered_wing", "ladder_chain"])
def test_all_changes_the_aligned_direction_step_runs_toward_the_reference(name):
    sim, steps, u = CASES[name]()
    u = sim.initial_controls.copy() if u is None else u
    x0 = sim.state.copy()
    runs = {bp: snapshots(with_settings(sim, x0, u, breakpoints=bp), steps, u) for bp in ("inside", "all")}
    ref = reference(with_settings(sim, x0, u), steps)
    change_n, change_c = normwise(runs["all"], runs["inside"]), componentwise(runs["all"], runs["inside"])
    err = {bp: normwise(xs, ref) for bp, xs in runs.items()}
    print(f"{name}: breakpoints 'all' against 'inside': normwise relative {change_n:.2g}, componentwise "
          f"{change_c:.2g}; normwise error against DP5(4) at 1e-10: inside {err['inside']:.2g}, all {err['all']:.2g}")
    assert change_n > 1e-9  # far above the one-ulp floor of these runs
    assert err["all"] < err["inside"]
