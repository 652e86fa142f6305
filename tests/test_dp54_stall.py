"""DP5(4) gives up with a named status instead of spinning when its step size collapses.

Oracle: an error tolerance below double-precision round-off (rtol 1e-17, atol 0) cannot be met by any step, so the
error control must shrink the step until the guard H_MIN_REL max(1 s, t) stops it, within a bounded number of
right-hand sides, and the report says so.
"""

from __future__ import annotations

import pytest

from laddermill_gym import load_scene
from laddermill_gym.kernels.contract import NONFINITE, STALLED
from laddermill_gym.kernels.integrate import H_MIN_REL, dp54_advance
from laddermill_gym.sim.simulator import SimulationError


def test_unattainable_tolerance_stalls_with_a_report():
    sim = load_scene("tethered_wing").simulator()
    x = sim.state.copy()
    status, acc, rej, h, t = dp54_advance(0.0, 1.0, x, sim.controls, 1e-3, 1e-17, 0.0, sim.model, sim.work,
                                          sim.limits, 10_000_000)
    assert status == STALLED
    assert h < H_MIN_REL and rej < 200  # about log(1e-3 / 1e-12) / log(5) rejections, not millions
    with pytest.raises(SimulationError, match="step size collapsed"):
        sim.advance_to(1.0, rtol=1e-17, atol=1e-300)


def test_a_nan_state_stops_dp54_at_once_with_its_cause():
    """A NaN in the accepted state makes every derivative NaN: no smaller step can help, so DP5(4) returns
    NONFINITE before any trial step (was: 13-17 rejections, then a collapsed step), and the simulator names the
    body and quantity."""
    sim = load_scene("tethered_wing", method="dp54").simulator()
    x = sim.state.copy()
    x[7] = float("nan")  # the wing's body velocity
    status, acc, rej, _, t = dp54_advance(0.0, 1.0, x.copy(), sim.controls, 1e-3, 1e-6, 1e-9, sim.model, sim.work,
                                          sim.limits, 10_000_000)
    assert (status, acc, rej, t) == (NONFINITE, 0, 0, 0.0)
    sim.state = x  # reset() refuses a non-finite state; set it behind its back, as a diverged step would
    with pytest.raises(SimulationError, match=r"wing 0.*nan|nan.*wing 0"):
        sim.step(None, n_steps=1)


def test_a_nan_state_stops_the_error_controlled_w_method_at_once():
    """The same for ROS34PW2 under error control (was: 14 rejections, then a collapsed step)."""
    sim = load_scene("tethered_wing", method="ros34pw2a").simulator()
    x = sim.state.copy()
    x[7] = float("nan")
    sim.state = x
    with pytest.raises(SimulationError, match=r"\(non-finite state\).*wing 0 u \[m/s\] is nan"):
        sim.step(None, n_steps=1)
    assert sim.adaptive_steps == [0, 0]
