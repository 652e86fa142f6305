"""The v2 laddermill wing's design study (issue 30 point 1 at 5 m/s; docs/mill_fast.md, "A wing whose lift falls with
its air speed (v2)"). Oracles: the closed form d alpha / dV = -2 W m_w / (V k) of the implicit-function theorem
against finite differences of the simulator's own trim search (``sim.statics.pitch_trim_alpha``, a separate
implementation of the moment about the attachment); the v2 mass properties against the parallel-axis theorem from
v1's numbers; the sign of the pitch stiffness about the attachment."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym.studies.mill.trim_slope import (
    closed_form_slope,
    geometry,
    load,
    lost_bounds,
    main,
    moment_about_attachment,
    trim,
)


@pytest.mark.parametrize("variant", ["v0", "v1", "v2"])
@pytest.mark.parametrize("leg", [0, 1])
@pytest.mark.parametrize("speed", [8.0, 10.0, 15.0])
def test_closed_form_slope_matches_the_trims(variant, leg, speed):
    wing, els = load(variant)
    de = els[leg]
    fd = (trim(wing, de, speed + 0.01) - trim(wing, de, speed - 0.01)) / 0.02
    assert closed_form_slope(wing, de, speed) == pytest.approx(fd, rel=2e-3, abs=1e-6)


@pytest.mark.parametrize("variant", ["v0", "v1", "v2"])
def test_moment_vanishes_at_the_simulator_trim_and_is_stable(variant):
    """Our moment about P vanishes at the statics' trim (two implementations), and falls with alpha there."""
    wing, els = load(variant)
    for de in els:
        for v in (6.0, 10.0, 15.0):
            a = trim(wing, de, v)
            scale = 0.5 * 1.225 * v * v * wing.area * wing.chord
            assert abs(moment_about_attachment(wing, a, de, v)) < 1e-6 * scale
            m_hi, m_lo = (moment_about_attachment(wing, a + s, de, v) for s in (1e-4, -1e-4))
            k = -(m_hi - m_lo) / 2e-4
            assert k > 0.0


def test_v2_descending_trim_falls_more_than_twice_as_fast_as_v1s():
    """The design aim: at 10 m/s the v2 descending wing's trim falls with air speed well over twice as fast as v1's
    (v1 near the bound of an airframe stable in free flight, trim_slope's docstring)."""
    v1, (_, d1) = load("v1")
    v2, (_, d2) = load("v2")
    assert closed_form_slope(v2, d2, 10.0) < 2.5 * closed_form_slope(v1, d1, 10.0) < 0.0


def test_v2_mass_properties_are_v1_with_the_pod_moved():
    """Pod 7.4 kg from 2.80 m ahead of v1's CG to 3.50 m behind it (docs/wing_data.md, "Mass properties")."""
    v1, _ = load("v1")
    v2, _ = load("v2")
    m, x0, x1, z = 7.4, 2.80, -3.50, 0.09
    shift = m * (x0 - x1) / v1.mass
    dj = m * (x1**2 - x0**2) - v1.mass * shift**2
    assert v2.mass == v1.mass
    assert v2.inertia[0] == pytest.approx(v1.inertia[0])
    assert v2.inertia[1] == pytest.approx(v1.inertia[1] + dj, abs=0.01)
    assert v2.inertia[2] == pytest.approx(v1.inertia[2] + dj, abs=0.01)
    assert v2.inertia[3] == pytest.approx(v1.inertia[3] + m * z * (x1 - x0), abs=0.01)
    assert v2.r_ref[0] == pytest.approx(v1.r_ref[0] + shift, abs=1e-4)
    g = geometry(v2)
    assert g["np_behind_P"] == pytest.approx(0.20, abs=1e-3)
    assert math.hypot(v2.attachment[0], v2.attachment[2]) == pytest.approx(1.5, abs=1e-3)  # the paper's 1.5 m


def _stable_roots_deg(wing, elevator, speed, lo_deg, hi_deg):
    """Brute force, independent of pitch_trim_alpha's grid and brentq: the angles [deg] in (lo, hi) where the moment
    about the attachment crosses from nose-up to nose-down, on a 0.005 deg grid."""
    grid = np.arange(lo_deg, hi_deg, 0.005)
    m = np.array([moment_about_attachment(wing, math.radians(a), elevator, speed) for a in grid])
    return grid[:-1][(m[:-1] > 0) & (m[1:] <= 0)]


@pytest.mark.parametrize("speed", [6.0, 10.0, 18.0])
def test_where_the_v2_attached_trim_is_lost_brackets_the_moments_roots(speed):
    """``lost_bounds`` bisects pitch_trim_alpha's answers; a scan of the moment itself brackets each bound: a stable
    attached root in (-10, 15) deg just below ``attached_up_to`` and none just above; a stable post-stall root in
    (15, 25) deg just above ``post_stall_from`` and none just below (6 m/s: none up to 12 deg)."""
    wing, _ = load("v2")
    b = lost_bounds(wing, speed)
    e, a, cl = b["attached_up_to"]
    d = math.radians(0.02)
    assert len(_stable_roots_deg(wing, e - d, speed, -10.0, 15.0)) == 1
    assert len(_stable_roots_deg(wing, e + d, speed, -10.0, 15.0)) == 0
    assert math.degrees(a) == pytest.approx(-10.0, abs=0.02) and cl < 0.0  # it leaves through the search's lower end
    if speed == 6.0:
        assert b["post_stall_from"] is None
        assert len(_stable_roots_deg(wing, math.radians(12.0), speed, 15.0, 25.0)) == 0
    else:
        e, a, _ = b["post_stall_from"]
        assert len(_stable_roots_deg(wing, e + d, speed, 15.0, 25.0)) >= 1
        assert len(_stable_roots_deg(wing, e - d, speed, 15.0, 25.0)) == 0
        assert 15.0 < math.degrees(a) < 25.0


def test_lost_rejects_elevators(capsys):
    with pytest.raises(SystemExit):
        main(["--variants", "v2", "--lost", "--elevators", "1", "2"])
    assert "--lost searches the elevators itself" in capsys.readouterr().err
