"""The error-controlled methods keep their pace when a run is continued in pieces (between output times).

Oracles: the same run in one call (the controller's own pace, which a split at output times must not spoil by more
than one step per split) and the rule of HNW's DOPRI5 code that a step within 1 % of the end is stretched onto it
rather than followed by a sliver step.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.contract import OK
from laddermill_gym.kernels.integrate import dp54_advance
from laddermill_gym.kernels.rigid.rosenbrock_adaptive import w_adaptive
from laddermill_gym.sim.breakpoints import W_ADAPTIVE
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings


@pytest.mark.parametrize("method, tol", [("dp54", 1e-6), ("ros34pw2a", 1e-3)])
def test_output_times_cost_at_most_one_step_each(method, tol):
    base = build_simulator("tethered_wing")
    one = with_settings(base, method=method)
    one.advance_to(2.0, rtol=tol, atol=tol)
    pieces = with_settings(base, method=method)
    outputs = np.linspace(0.0, 2.0, 21)[1:]
    for t in outputs:
        pieces.advance_to(t, rtol=tol, atol=tol)
    # before, each piece restarted from settings.dt (5 ms): 60 ROS34PW2 steps against 5 in one call
    assert pieces.adaptive_steps[0] <= one.adaptive_steps[0] + outputs.size
    assert np.allclose(pieces.state, one.state, rtol=100 * tol, atol=100 * tol)
    pieces.reset()
    assert pieces.adaptive_steps == [0, 0]


@pytest.mark.parametrize("method", ["dp54", "ros34pw2a"])
def test_no_sliver_step_before_the_end(method):
    sim = build_simulator("tethered_wing")
    x = sim.state.copy()
    h0 = 0.005
    t_end = 1.005 * h0  # within 1 % of the proposal: one stretched step
    if method == "dp54":
        status, acc, rej, h, t = dp54_advance(0.0, t_end, x, sim.controls, h0, 1e-6, 1e-6, sim.model, sim.work,
                                              sim.limits, 100)
    else:
        tableau, q = W_ADAPTIVE[method]
        status, acc, rej, h, t = w_adaptive(0.0, t_end, x, sim.controls, h0, 1e-3, 1e-3, sim.model, sim.work,
                                            sim.limits, 100, tableau, q)
    assert status == OK and t == t_end
    assert (acc, rej) == (1, 0)
    assert h >= h0  # the proposal for the next step, not a shortened one
