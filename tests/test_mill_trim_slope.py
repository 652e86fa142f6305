"""The v2 laddermill wing's design study (issue 30 point 1 at 5 m/s; docs/mill_fast.md, "A wing whose lift falls with
its air speed (v2)"). Oracles: the closed form d alpha / dV = -2 W m_w / (V k) of the implicit-function theorem
against finite differences of the simulator's own trim search (``sim.statics.pitch_trim_alpha``, a separate
implementation of the moment about the attachment); the v2 mass properties against the parallel-axis theorem from
v1's numbers; the sign of the pitch stiffness about the attachment."""

from __future__ import annotations

import math

import pytest

from laddermill_gym.studies.mill.trim_slope import (
    closed_form_slope,
    geometry,
    load,
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
