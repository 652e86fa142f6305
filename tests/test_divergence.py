"""The end criteria of the diverging mill after the direction step (``studies/mill/divergence.py``, issue 30
point 7).

Oracles: hand-made samples whose crossing times are closed form (beta = 5 t deg passes 21 deg at 4.2 s; a height
100 - 10 t m passes 5 m at 9.5 s; a tension 1e4 t N passes 65 kN at 6.5 s), with samples 0.1 s apart; and the
11-wing mill with criteria set so that each one holds from the first sample after the step (0.1 s), the
aerodynamic one after its hold time on top, a rate guard below the wings' rates for the breakdown, and no
criterion for the time limit.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from laddermill_gym import Simulator, load_scene
from laddermill_gym.studies.mill import divergence as dv

T = np.round(np.arange(0.0, 12.0 + 1e-9, 0.1), 10)
N_WINGS, N_EL = 4, 5


def _run(judge: dv.Judge, beta=None, height=None, tension=None) -> dv.End | None:
    """Feed the judge samples at T: per wing beta [deg] and height [m], per element tension [N], each a function
    of t (default: inside every range)."""
    for t in T:
        b = np.zeros(N_WINGS) if beta is None else beta(t)
        h = np.full(N_WINGS, 500.0) if height is None else height(t)
        ten = np.full(N_EL, 1e4) if tension is None else tension(t)
        end = judge.see(t, np.full(N_WINGS, 5.0), b, h, ten)
        if end is not None:
            return end
    return None


def _judge(**kw) -> dv.Judge:
    return dv.Judge(dv.EndCriteria(**kw), N_WINGS, 5.0, np.full(N_EL, 6.5e4), t_step=1.0)


def test_aerodynamic_range_held_for_the_stated_time():
    """Wing 2's beta = 5 t deg leaves 21 deg at 4.2 s: first sample out at 4.3 s, the 2 s hold ends the run at 6.3 s
    (5.3 s after the step at 1 s). Wing 1 out from 1.0 to 2.9 s (1.9 s < 2 s) ends nothing."""
    def beta(t):
        b = np.zeros(N_WINGS)
        b[2] = 5.0 * t
        b[1] = 30.0 if 1.0 <= t < 2.95 else 0.0
        return b

    end = _run(_judge(aero_hold_s=2.0), beta=beta)
    assert end.outcome == dv.AERO and end.physical and end.bodies == [2]
    assert end.t_after_step_s == pytest.approx(5.3) and "wing 2" in end.text and "since 3.30 s" in end.text
    assert _run(_judge(aero_hold_s=2.0, aero_wings=(0, 1, 3)), beta=beta) is None  # wing 2 not judged


def test_wing_below_height_and_overload_at_their_crossings():
    """Wing 3's height 100 - 10 t m passes 5 m at 9.5 s: ended at the sample 9.6 s; element 4's tension 1e4 t N
    passes 65 kN at 6.5 s: ended at 6.6 s, which comes first when both happen."""
    def height(t):
        h = np.full(N_WINGS, 500.0)
        h[3] = 100.0 - 10.0 * t
        return h

    def tension(t):
        x = np.full(N_EL, 1e4)
        x[4] = 1e4 * t
        return x

    end = _run(_judge(), height=height)
    assert end.outcome == dv.HEIGHT and end.bodies == [3] and end.t_after_step_s == pytest.approx(8.6)
    end = _run(_judge(), height=height, tension=tension)
    assert end.outcome == dv.OVERLOAD and end.bodies == [4] and end.t_after_step_s == pytest.approx(5.6)
    assert "element 4 tension 66 kN over 65 kN" in end.text
    with pytest.raises(ValueError, match="aero_hold_s = 0"):
        dv.EndCriteria(aero_hold_s=0)


@pytest.fixture(scope="module")
def small_mill():
    """The 11-wing 3D mill 2 s into its speed ramp (the wings moving): (simulator, state, time)."""
    sc = load_scene("laddermill", dimension=3, n_wings=11)
    sim = sc.simulator()
    sim.step(n_steps=200)
    return sim, sim.state.copy(), sim.t


def _follow(small_mill, criteria, after_step=1.0, **settings):
    sim0, x, t = small_mill
    sim = Simulator(sim0.assembly, x, dataclasses.replace(sim0.settings, **settings), sim0.controls)
    sim.reset(x, t=t, controls=sim0.controls, check=False)
    return dv.follow(sim, "test", 4, after_step, 0.1, criteria, progress=False)


def test_each_criterion_ends_the_small_mill(small_mill):
    """Every criterion set to hold at once ends the run at the first sample after the step (0.1 s after it); the
    aerodynamic one (a band no wing is in) 0.5 s of hold later; the wings or elements concerned are all named."""
    sim0, x, _ = small_mill
    over = dv.EndCriteria(breaking_fraction=0.5 * float(np.min(sim0.tensions())) / 5.25e5)
    run = _follow(small_mill, over)
    assert run["end"].outcome == dv.OVERLOAD and run["end"].t_after_step_s == pytest.approx(0.1)
    assert run["end"].bodies == list(range(sim0.assembly.elements.count))
    run = _follow(small_mill, dv.EndCriteria(min_height_m=1e5))
    assert run["end"].outcome == dv.HEIGHT and run["end"].bodies == list(range(11))
    assert run["end"].t_after_step_s == pytest.approx(0.1)
    run = _follow(small_mill, dv.EndCriteria(alpha_range_deg=(-90.0, -80.0), aero_hold_s=0.5))
    assert run["end"].outcome == dv.AERO and run["end"].t_after_step_s == pytest.approx(0.6)
    assert len(run["rows"]) == int(round((dv.STEP_LEAD_S + 0.6) / 0.1)) + 1


def test_breakdown_and_time_limit_are_not_physical(small_mill):
    """A rate guard below the wings' rates: a numerical breakdown, named as such; no criterion: the time limit."""
    sim0 = small_mill[0]
    run = _follow(small_mill, dv.DEFAULT_END, max_rate=0.5 * float(np.max(np.abs(sim0.wing_rates()))))
    assert run["end"].outcome == dv.BREAKDOWN and not run["end"].physical and "angular rate" in run["end"].text
    run = _follow(small_mill, None, after_step=0.3)
    assert run["end"].outcome == dv.TIME_LIMIT and run["t_reached_s"] == pytest.approx(0.3)
    assert "no physical end, time limit" in dv.describe(run)


def test_undisturbed_spell_is_the_time_out_of_the_band(small_mill):
    """A band no wing is in: every wing is out from the first sample (0.1 s) on, so after 1 s the longest spell is
    0.9 s, and the aerodynamic criterion (hold 0.5 s) holds; the simulator given is not advanced."""
    sim = small_mill[0]
    t = sim.t
    ref = dv.undisturbed_spell(sim, dv.EndCriteria(alpha_range_deg=(-90.0, -80.0), aero_hold_s=0.5), 1.0)
    assert ref["longest_out_s"] == pytest.approx(0.9) and ref["end"].outcome == dv.AERO and sim.t == t
    assert ref["end"].t_after_step_s == pytest.approx(0.6)
