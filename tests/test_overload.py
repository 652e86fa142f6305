"""Cable strength (issue 30 point 5): tensions checked against the cable's breaking load (``sim/overload.py``) in
the recorder, the periodic search and (already) LadderMill-v0.

Oracles: a tension ramp whose crossing time is closed form (T = a t passes the limit L at t = L / a); the cable
file's ``breaking_load`` read with PyYAML (not the package's reader); the recorded and sampled tensions compared
with fraction x breaking load by hand.
"""

from __future__ import annotations

import numpy as np
import pytest
import yaml

from laddermill_gym import load_scene
from laddermill_gym.ladder.periodic import run_to_periodic
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.sim.overload import Overload, OverloadWatch, overload_events, tension_limits
from laddermill_gym.sim.recording import record


def _breaking_load() -> float:
    """The Dyneema cable's breaking load [N] as its file says (both scenes below use it)."""
    with open(CONFIG_DIR / "cables" / "dyneema_25mm.yaml") as f:
        return float(yaml.safe_load(f)["breaking_load"])


def test_events_of_a_ramp_are_at_the_closed_form_crossing():
    """Element 0: T = 1e4 t N to 7 s, 1e4 (14 - t) to 9 s, 1e4 (t - 4) after, against a 65 kN limit: over it from
    6.5 s to 7.5 s and again after 10.5 s, so with samples 0.1 s apart (the crossings themselves are not over) its
    events are at 6.6 s and 10.6 s. Element 1 is over its limit from the start: one event at t = 0."""
    t = np.round(np.arange(0.0, 12.0 + 1e-9, 0.1), 10)
    tent = np.where(t <= 7.0, 1e4 * t, np.where(t <= 9.0, 1e4 * (14.0 - t), 1e4 * (t - 4.0)))
    ten = np.stack([tent, np.full(t.size, 5e4)], axis=1)
    over, ev = overload_events(t, ten, np.array([6.5e4, 4e4]))
    assert [(e.t, e.element) for e in ev] == [(0.0, 1), (6.6, 0), (10.6, 0)]
    assert over[:, 1].all() and over[(t > 6.5) & (t < 7.5), 0].all() and not over[(t >= 7.5) & (t <= 10.5), 0].any()
    assert ev[1].tension == pytest.approx(6.6e4) and ev[1].limit == 6.5e4
    assert "element 0 tension 66 kN over 65 kN" in ev[1].text()


def test_watch_keeps_the_first_event_and_the_peak_ratio():
    w = OverloadWatch(np.array([1e5, np.inf]))
    assert not w.see(0.0, np.array([5e4, 1e9])) and w.peak_ratio == 0.5  # no limit known for element 1
    assert w.see(1.0, np.array([2e5, 0.0])) and w.see(2.0, np.array([3e5, 0.0]))
    assert w.first == Overload(1.0, 0, 2e5, 1e5) and w.peak_ratio == pytest.approx(3.0, rel=1e-15)
    assert "cable overload: t = 1 s: element 0" in w.text()
    with pytest.raises(ValueError, match="breaking_fraction = 0"):
        tension_limits(load_scene("tethered_wing").assembly, 0)


def test_limits_are_the_cable_files_breaking_load():
    asm = load_scene("laddermill", dimension=2, n_wings=11).assembly
    np.testing.assert_array_equal(tension_limits(asm), np.full(asm.elements.count, _breaking_load()))
    np.testing.assert_allclose(tension_limits(asm, 0.5), 0.5 * _breaking_load())


def test_record_flags_overloads():
    """The tethered wing holds its cable at a few kN: no overload at the breaking load; at a fraction just below
    the smallest recorded tension over its breaking load every sample is over, one event per element at the start."""
    sim = load_scene("tethered_wing").simulator()
    rec = record(sim, 0.5, 0.05, progress=False)
    ten = rec.views["element_tension_N"]
    assert rec.overloads == [] and not rec.views["element_overload"].any()
    assert ten.max() < _breaking_load()
    frac = 0.99 * ten.min() / _breaking_load()
    assert sim.overloads() == [] and len(sim.overloads(0.5 * frac)) == ten.shape[1]  # the state now, both ways
    sim = load_scene("tethered_wing").simulator()
    rec = record(sim, 0.5, 0.05, progress=False, breaking_fraction=frac)
    assert rec.views["element_overload"].all()
    assert [(e.t, e.element) for e in rec.overloads] == [(0.0, k) for k in range(ten.shape[1])]


def test_periodic_search_reports_an_overload():
    """The 11-wing mill at 2 m/s pulls far less than the cable holds: no overload, and the peak ratio is the largest
    sampled tension over the breaking load; at a tenth of its largest tension the first step of the search is an
    overload and the summary says so."""
    r = run_to_periodic(load_scene("laddermill", n_wings=11, dimension=2).simulator(), max_time=40.0, progress=False)
    assert r.overload is None and "no cable overload" in r.summary()
    assert r.peak_tension_ratio >= r.tension_max_N.max() / _breaking_load() * (1 - 1e-12)
    frac = 0.1 * r.tension_max_N.max() / _breaking_load()
    r2 = run_to_periodic(load_scene("laddermill", n_wings=11, dimension=2).simulator(), max_time=40.0,
                         progress=False, breaking_fraction=frac)
    assert r2.overload is not None and r2.overload.limit == pytest.approx(frac * _breaking_load())
    assert r2.overload.tension > r2.overload.limit and "CABLE OVERLOAD" in r2.summary()
    assert r2.overload.t < r2.history[0]["t_s"]  # in the first period of the search
