"""The standard gusts (laddermill_gym/atmosphere/iec_gusts.py) against IEC 61400-1 ed. 3 and the check values of
../shared/design/oracles.md: class IA at V_hub = 10 m/s, D = 10 m, z_hub > 60 m: EOG V_gust = 6.76 m/s, peak
15.0 m/s at 5.25 s; EDC theta_e = 46.3 deg; the shapes' closed forms written here from the standard."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym.atmosphere.disturbances import sample_wind_field
from laddermill_gym.atmosphere.field import pack_wind_field
from laddermill_gym.atmosphere.iec_gusts import ECD, EDC, EOG, EWS, Ramp, SpeedStep
from laddermill_gym.kernels.wind import gust_at

RNG = np.random.default_rng
IA10 = dict(wind_class="IA", wind_speed=10.0, diameter=10.0, hub_height=100.0)
SIGMA1 = 0.16 * (0.75 * 10.0 + 5.6)  # NTM, class A, 10 m/s
LAMBDA1 = 42.0  # z_hub > 60 m


def test_eog_check_values_and_shape():
    t0 = 2.0
    t = t0 + np.linspace(0.0, 10.5, 21001)
    s, d = EOG(time=t0, **IA10).sample(t, RNG(0))
    v = 10.0 * s
    v_gust = 3.3 * SIGMA1 / (1.0 + 0.1 * 10.0 / LAMBDA1)  # < 1.35 (0.8 * 1.4 * 50 - 10)
    assert v_gust == pytest.approx(6.76, abs=0.005)
    assert v.max() == pytest.approx(15.0, abs=0.005)
    assert t[np.argmax(v)] - t0 == pytest.approx(5.25, abs=1e-3)
    tau = t - t0
    np.testing.assert_allclose(v, 10.0 - 0.37 * v_gust * np.sin(3 * math.pi * tau / 10.5)
                               * (1 - np.cos(2 * math.pi * tau / 10.5)), atol=1e-9)
    assert np.all(d == 0.0)
    before_after = EOG(time=t0, **IA10).sample(np.array([0.0, 1.99, 12.6, 100.0]), RNG(0))[0]
    np.testing.assert_allclose(before_after, 1.0, atol=1e-12)


def test_eog_is_limited_by_the_extreme_wind_near_v_e1():
    """Class III at 40 m/s: 1.35 (V_e1 - V_hub) = 1.35 (0.8 * 1.4 * 37.5 - 40) = 2.7 m/s binds."""
    kw = dict(IA10, wind_class="IIIA", wind_speed=40.0)
    v = 40.0 * EOG(time=0.0, **kw).sample(np.array([5.25]), RNG(0))[0]
    assert v[0] == pytest.approx(40.0 + 0.74 * 1.35 * (0.8 * 1.4 * 37.5 - 40.0), rel=1e-12)


def test_edc_change_is_limited_to_180_degrees():
    """IEC 61400-1 ed. 3 6.3.2.4 limits theta_e to +-180 deg; 4 atan(x) passes it where x > 1 (V_hub of 0.8 m/s in
    class IA: sigma_1 = 0.16 (0.6 + 5.6) = 0.992 m/s)."""
    kw = dict(IA10, wind_speed=0.8)
    x = 0.16 * (0.75 * 0.8 + 5.6) / (0.8 * (1.0 + 0.1 * 10.0 / LAMBDA1))
    assert 4.0 * math.atan(x) > math.pi  # the unlimited formula would turn the wind past 180 deg
    d = EDC(time=0.0, **kw).sample(np.array([3.0, 6.0, 20.0]), RNG(0))[1]
    np.testing.assert_allclose(d, [0.5 * math.pi, math.pi, math.pi], rtol=1e-12)


def test_edc_check_value_and_shape():
    theta_e = 4.0 * math.atan(SIGMA1 / (10.0 * (1.0 + 0.1 * 10.0 / LAMBDA1)))
    assert math.degrees(theta_e) == pytest.approx(46.3, abs=0.05)
    t = np.array([0.0, 1.0, 2.5, 4.0, 7.0, 50.0])
    s, d = EDC(time=1.0, sign=-1, **IA10).sample(t, RNG(0))
    tau = np.clip(t - 1.0, 0.0, 6.0)
    np.testing.assert_allclose(d, -0.5 * theta_e * (1 - np.cos(math.pi * tau / 6.0)), atol=1e-12)
    assert d[-1] == pytest.approx(-theta_e) and np.all(s == 1.0)


@pytest.mark.parametrize("v_hub, theta_cg_deg", [(10.0, 72.0), (3.0, 180.0)])
def test_ecd_speed_and_direction(v_hub, theta_cg_deg):
    t = np.array([0.0, 5.0, 10.0, 15.0, 30.0])
    s, d = ECD(time=5.0, **dict(IA10, wind_speed=v_hub)).sample(t, RNG(0))
    c = 0.5 * (1 - np.cos(math.pi * np.clip(t - 5.0, 0.0, 10.0) / 10.0))
    np.testing.assert_allclose(v_hub * s, v_hub + 15.0 * c, atol=1e-12)
    np.testing.assert_allclose(np.degrees(d), theta_cg_deg * c, atol=1e-9)
    assert v_hub * s[-1] == pytest.approx(v_hub + 15.0)


def test_ews_through_the_kernels():
    """At z_hub +- D/2 the gust is +-0.5 A (1 - cos(2 pi tau / T)), A = 2.5 + 0.2 beta sigma1 (D / Lambda1)^(1/4),
    beta = 6.4, T = 12 s; linear in between, held beyond; it reaches a point x_ref + d downwind d / U later."""
    kw = dict(IA10, time=3.0)
    ews = EWS(**kw)
    f = sample_wind_field([ews], 40.0, 0.1, RNG(0))
    _, _, _, gp, gv = pack_wind_field(f)
    A = 2.5 + 0.2 * 6.4 * SIGMA1 * (10.0 / LAMBDA1) ** 0.25
    for t, d, dz in ((3.0 + 6.0, 0.0, 5.0), (3.0 + 2.0, 0.0, -5.0), (3.0 + 4.0 + 50.0 / 10.0, 50.0, 2.5),
                     (3.0 + 9.0, 0.0, 40.0), (3.0 + 12.5, 0.0, 5.0), (2.5, 0.0, 5.0)):
        tau = t - 3.0 - d / 10.0
        shape = 1 - math.cos(2 * math.pi * tau / 12.0) if 0 <= tau <= 12 else 0.0
        expected = (min(max(dz, -5.0), 5.0) / 10.0) * A * shape
        # heading 0: downwind e = -x, so the point d m downwind sits at x = -d; u downwind is global -x
        gx, gy, gz = gust_at(-d, 0.0, -(100.0 + dz), t, gp, gv)
        assert -gx == pytest.approx(expected, abs=1e-2 * A) and gy == 0.0 and gz == 0.0


def test_step_and_ramp():
    t = np.array([0.0, 1.0, 3.0, 6.0, 20.0])
    s, d = SpeedStep(step=-0.3, time=1.0).sample(t, RNG(0))
    np.testing.assert_allclose(s, [1.0, 0.7, 0.7, 0.7, 0.7])
    s, d = Ramp(speed_change=0.4, direction_change=-0.1, time=2.0, duration=4.0).sample(t, RNG(0))
    np.testing.assert_allclose(s, [1.0, 1.0, 1.1, 1.4, 1.4])
    np.testing.assert_allclose(d, [0.0, 0.0, -0.025, -0.1, -0.1])


@pytest.mark.parametrize("cls, kw, text", [
    (EOG, dict(wind_class="IVA"), "EOG.wind_class"),
    (EOG, dict(wind_speed=0.5), "EOG.wind_speed"),  # the gust's dip would reverse the wind
    (EOG, dict(wind_class="IIIA", wind_speed=45.0), "EOG.wind_speed = 45.0: above V_e1 = 42 m/s"),
    (EDC, dict(sign=2), "EDC.sign"),
    (EWS, dict(diameter=-1.0), "EWS.diameter"),
    (SpeedStep, dict(step=-1.5), "SpeedStep.step"),
    (Ramp, dict(duration=0.0), "Ramp.duration"),
])
def test_bad_parameters_name_the_field(cls, kw, text):
    with pytest.raises(ValueError, match=text):
        cls(**kw)


def test_grids_that_cannot_be_shared_are_named():
    """One gust grid is advected and faded in as a whole: an EWS (no fade-in) beside turbulence faded in over 10 s,
    or a gust advected at another speed, is refused naming both disturbances."""
    from laddermill_gym.atmosphere.disturbances import grid_geometry
    from laddermill_gym.atmosphere.turbulence import Turbulence

    with pytest.raises(ValueError, match=r"disturbances\[0\] \(Turbulence: .*fade_in 10 s\) and disturbances\[2\] "
                                         r"\(EWS: .*no fade-in\)"):
        grid_geometry([Turbulence(fade_in=10.0), SpeedStep(), EWS(**IA10)], 30.0)
    with pytest.raises(ValueError, match=r"disturbances\[1\] \(EWS: advected at 12 m/s"):
        grid_geometry([EWS(**IA10), EWS(**dict(IA10, wind_speed=12.0))], 30.0)
    assert grid_geometry([Turbulence(wind_speed=10.0), EWS(**IA10)], 30.0) is not None
