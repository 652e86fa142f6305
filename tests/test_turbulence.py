"""Turbulence fields (laddermill_gym/atmosphere/turbulence.py) against the models' closed forms.

Oracles, written here from the standards' formulas (not from the code's helpers): IEC 61400-1 ed. 3 NTM / ETM
standard deviations (6.3.1.3, 6.3.2.3) and Kaimal ratios (Table B.1); the Kaimal spectrum; the IEC coherence
exp(-12 sqrt((f r / V)^2 + (0.12 r / L_c)^2)), L_c = 8.1 Lambda_1; the exact discrete Dryden update's
autocorrelation a^k, a = exp(-dx / L) (../shared/design/oracles.md), the Dryden lateral autocorrelation
(1 - r / (2 L)) exp(-r / L) and the von Karman longitudinal autocorrelation 2^(2/3) / Gamma(1/3) (r / a)^(1/3)
K_(1/3)(r / a), a = 1.339 L; their integral scales; MIL-F-8785C intensities at altitude.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import gamma, kv

from laddermill_gym.atmosphere.disturbances import sample_wind_field
from laddermill_gym.atmosphere.field import pack_wind_field
from laddermill_gym.atmosphere.turbulence import Turbulence
from laddermill_gym.kernels.wind import gust_at

FT = 0.3048
L_HIGH = 1750 * FT  # MIL-F-8785C 3.7.2.1: Dryden scale above 2000 ft [m]
L_HIGH_VK = 2500 * FT  # MIL-F-8785C 3.7.2.1: von Karman scale above 2000 ft [m]


def fields(turb: Turbulence, t_end: float, n: int, seed0: int = 0):
    """n fields' values (n, n_xi, n_h, 3) drawn with seeds seed0, seed0 + 1, ..."""
    return np.array([turb.gust_grid(t_end, np.random.default_rng(seed0 + i)).values for i in range(n)])


def circular_autocorrelation(x: np.ndarray, lags: np.ndarray) -> np.ndarray:
    """Mean over records (axis 0) of the circular autocovariance along axis 1, at the given lags."""
    f = np.fft.rfft(x, axis=1)
    acov = np.fft.irfft(np.abs(f) ** 2, n=x.shape[1], axis=1) / x.shape[1]
    return acov.mean(axis=0)[lags]


@pytest.mark.parametrize("model, sigma1", [
    ("NTM", 0.16 * (0.75 * 10.0 + 5.6)),  # class A, V_hub 10 m/s
    ("ETM", 2.0 * 0.16 * (0.072 * (0.2 * 50.0 / 2.0 + 3.0) * (10.0 / 2.0 - 4.0) + 10.0)),  # class IA
])
def test_iec_variances_per_component_and_height(model, sigma1):
    turb = Turbulence(model=model, wind_class="IA", wind_speed=10.0, hub_height=100.0, heights=(50.0, 150.0),
                      dh=50.0, along_wind=(0.0, 1.0), dxi=8.0)
    v = fields(turb, 6000.0, 100)  # 100 records of 60 km (about 90 integral scales of u each)
    var = v.var(axis=1).mean(axis=0)  # (n_h, 3)
    for k, ratio in enumerate((1.0, 0.8, 0.5)):
        np.testing.assert_allclose(var[:, k], (ratio * sigma1) ** 2, rtol=0.05)


def test_kaimal_spectrum_of_the_longitudinal_component():
    """Averaged periodogram against (Kaimal S scaled to the record's sigma^2), in octave bands."""
    U, lam = 10.0, 42.0
    sigma = 0.16 * (0.75 * U + 5.6)
    turb = Turbulence(model="NTM", wind_class="IA", wind_speed=U, heights=(100.0, 101.0), dh=1.0,
                      along_wind=(0.0, 1.0), dxi=4.0)
    v = fields(turb, 1200.0, 80)[:, :, 0, 0]  # (80, n_xi)
    n, dx = v.shape[1], turb.dxi
    kappa = np.arange(1, n // 2) / (n * dx)
    period = (2.0 * np.abs(np.fft.rfft(v, axis=1)[:, 1: n // 2]) ** 2 / n ** 2).mean(axis=0) / (kappa[0])
    L1 = 8.1 * lam
    S = 4.0 * sigma ** 2 * L1 / (1.0 + 6.0 * kappa * L1) ** (5.0 / 3.0)
    S *= sigma ** 2 / (S.sum() * kappa[0])  # the record's variance is sigma^2
    edges = kappa[0] * 2.0 ** np.arange(1, int(np.log2(kappa.size)))
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        band = (kappa >= lo) & (kappa < hi)
        assert period[band].mean() == pytest.approx(S[band].mean(), rel=0.15 if band.sum() > 8 else 0.35)


@pytest.mark.parametrize("r", [10.0, 40.0])
def test_iec_coherence_between_two_heights(r):
    U, Lc = 10.0, 8.1 * 42.0
    turb = Turbulence(model="NTM", wind_speed=U, heights=(100.0, 100.0 + r), dh=r, along_wind=(0.0, 1.0), dxi=4.0)
    u = fields(turb, 600.0, 150)[..., 0]  # (150, n_xi, 2)
    n = u.shape[1]
    F = np.fft.rfft(u, axis=1)
    for k, half in ((1, 0), (3, 0), (8, 2), (20, 3), (50, 5)):  # neighbouring modes pooled at higher k
        ks = np.arange(k - half, k + half + 1)
        a, b = F[:, ks, 0], F[:, ks, 1]
        coh = abs(np.sum(a * np.conj(b))) / math.sqrt(np.sum(abs(a) ** 2) * np.sum(abs(b) ** 2))
        f = ks / (n * turb.dxi) * U  # temporal frequencies of the modes [Hz]
        expected = np.mean(np.exp(-12.0 * np.sqrt((f * r / U) ** 2 + (0.12 * r / Lc) ** 2)))
        assert coh == pytest.approx(expected, abs=0.06)


def test_dryden_autocorrelations_and_integral_scale_at_altitude():
    """Above 2000 ft: isotropic, L = 1750 ft; u follows the exact discrete Dryden update (lag-k correlation
    a^k), v and w have (1 - r / 2L) exp(-r / L)."""
    turb = Turbulence(model="Dryden", severity="moderate", wind_speed=10.0, heights=(1000.0, 1001.0), dh=1.0,
                      along_wind=(0.0, 1.0), dxi=10.0)
    v = fields(turb, 16000.0, 60)[:, :, 0, :]  # records of 300 L: the missing mean biases R by about 2 L / 300 L
    sigma2 = v.var(axis=1).mean(axis=0)
    sigma_table = np.interp(1000.0 / FT, [500, 1750, 3750, 7500], [8.6, 9.6, 10.6, 10.1]) * FT  # 1e-3 exceedance
    np.testing.assert_allclose(np.sqrt(sigma2), sigma_table, rtol=0.03)
    lags = np.array([1, 5, 20, 50, 100])
    r = lags * turb.dxi
    a = math.exp(-turb.dxi / L_HIGH)
    np.testing.assert_allclose(circular_autocorrelation(v[..., 0], lags) / sigma2[0], a ** lags, atol=0.05)
    lateral = (1.0 - r / (2.0 * L_HIGH)) * np.exp(-r / L_HIGH)
    for k in (1, 2):
        np.testing.assert_allclose(circular_autocorrelation(v[..., k], lags) / sigma2[k], lateral, atol=0.05)
    # integral scale of u: int_0^5L R / sigma^2 dr = L (1 - exp(-5))
    m = int(5 * L_HIGH / turb.dxi)
    rho = circular_autocorrelation(v[..., 0], np.arange(m + 1)) / sigma2[0]
    integral = turb.dxi * (rho.sum() - 0.5 * (rho[0] + rho[-1]))
    assert integral == pytest.approx(L_HIGH * (1.0 - math.exp(-5.0)), rel=0.1)


def test_von_karman_longitudinal_autocorrelation_and_integral_scale():
    turb = Turbulence(model="VonKarman", severity="light", wind_speed=10.0, heights=(1000.0, 1001.0), dh=1.0,
                      along_wind=(0.0, 1.0), dxi=10.0)
    u = fields(turb, 3000.0, 80, seed0=100)[:, :, 0, 0]
    s2 = u.var(axis=1).mean()
    a = 1.339 * L_HIGH_VK

    def rho(r):
        return 2.0 ** (2.0 / 3.0) / gamma(1.0 / 3.0) * (r / a) ** (1.0 / 3.0) * kv(1.0 / 3.0, r / a)

    lags = np.array([2, 10, 40, 100])
    np.testing.assert_allclose(circular_autocorrelation(u, lags) / s2, rho(lags * turb.dxi), atol=0.05)
    m = int(3 * L_HIGH_VK / turb.dxi)
    est = circular_autocorrelation(u, np.arange(m + 1)) / s2
    integral = turb.dxi * (est.sum() - 0.5 * (est[0] + est[-1]))
    assert integral == pytest.approx(quad(rho, 1e-12, m * turb.dxi)[0], rel=0.1)


def test_mil_high_altitude_scales_per_form():
    """MIL-F-8785C 3.7.2.1 above 2000 ft: L_u = L_v = L_w = 1750 ft for the Dryden form, 2500 ft for von Karman's;
    below 1000 ft both forms share the low-altitude scales."""
    from laddermill_gym.atmosphere.turbulence_models import mil_intensity_scale

    h = np.array([100.0, 2500.0 * FT])
    (_, dryden) = mil_intensity_scale(h, "light")
    (_, vk) = mil_intensity_scale(h, "light", model="VonKarman")
    for k in range(3):
        assert dryden[k][1] == pytest.approx(L_HIGH, rel=1e-12) and vk[k][1] == pytest.approx(L_HIGH_VK, rel=1e-12)
        assert dryden[k][0] == vk[k][0]
    with pytest.raises(ValueError, match="model = 'NTM'"):
        mil_intensity_scale(h, "light", model="NTM")


def test_mil_low_altitude_intensities():
    """Below 1000 ft: sigma_w = 0.1 W20, sigma_u = sigma_v = sigma_w / (0.177 + 0.000823 h)^0.4 (h in ft)."""
    h = 60.0
    hf = h / FT
    sw = 0.1 * 30.0 * 1852.0 / 3600.0  # moderate: W20 = 30 kt
    su = sw / (0.177 + 0.000823 * hf) ** 0.4
    turb = Turbulence(model="Dryden", severity="moderate", wind_speed=10.0, heights=(h, h + 1.0), dh=1.0,
                      along_wind=(0.0, 1.0), dxi=2.0)
    v = fields(turb, 1200.0, 40, seed0=7)[:, :, 0, :]
    np.testing.assert_allclose(np.sqrt(v.var(axis=1).mean(axis=0)), [su, su, sw], rtol=0.05)


def test_replayable_from_the_seed_and_sampled_by_the_kernels():
    turb = Turbulence(model="NTM", heights=(0.0, 200.0), dh=20.0, along_wind=(-100.0, 100.0))
    f1 = sample_wind_field([turb], 30.0, 0.1, np.random.default_rng(5))
    f2 = sample_wind_field([turb], 30.0, 0.1, np.random.default_rng(5))
    f3 = sample_wind_field([turb], 30.0, 0.1, np.random.default_rng(6))
    np.testing.assert_array_equal(f1.grid.values, f2.grid.values)
    assert not np.array_equal(f1.grid.values, f3.grid.values)
    # the kernel reads the grid node at xi = p . e - U t (heading 0: e = -x), h = -z
    g = f1.grid
    _, _, _, gp, gv = pack_wind_field(f1)
    i, j, t = 37, 4, 2.0
    xi, h = g.xi0 + i * g.dxi, g.h0 + j * g.dh
    x = -(xi + g.advection * t)
    u, v, w = g.values[i, j]
    np.testing.assert_allclose(gust_at(x, 3.0, -h, t, gp, gv), (-u, -v, -w), rtol=1e-12, atol=1e-12)


def test_memory_of_a_field_for_the_3500_m_chain_over_600_s():
    """24 bytes per node: n_xi = (span + U T + 2 dxi) / dxi (+1, even), n_h = (h_top - h_bottom) / dh + 1."""
    turb = Turbulence(model="NTM", wind_speed=13.5, heights=(0.0, 3600.0), dh=25.0, along_wind=(-4000.0, 500.0),
                      dxi=10.0)
    g = turb.grid_geometry(600.0)
    n_xi = math.ceil((4500.0 + 13.5 * 600.0 + 2 * 10.0) / 10.0) + 1
    n_xi += n_xi % 2
    assert (g.n_xi, g.n_h) == (n_xi, 145)
    assert g.bytes == 24 * n_xi * 145 < 5e6
    assert turb.gust_grid(600.0, np.random.default_rng(0)).values.nbytes == g.bytes


@pytest.mark.parametrize("kw, text", [
    ({"model": "Kolmogorov"}, "Turbulence.model"),
    ({"heights": (100.0, 10.0)}, "Turbulence.heights"),
    ({"dxi": 0.0}, "Turbulence.dxi"),
    ({"wind_class": "IVA"}, "Turbulence.wind_class"),
    ({"model": "Dryden", "severity": "extreme"}, "Turbulence.severity"),
    # fields the model does not read were accepted and ignored, even when invalid (review of 2026-12-07)
    ({"model": "NTM", "severity": "extreme"}, "Turbulence.severity = 'extreme': must be one of"),
    ({"model": "NTM", "severity": "severe"}, "Turbulence.severity = 'severe': model NTM does not use it"),
    ({"model": "ETM", "w20": 10.0}, "Turbulence.w20 = 10.0: model ETM does not use it"),
    ({"model": "Dryden", "wind_class": "ZZ"}, "Turbulence.wind_class"),
    ({"model": "VonKarman", "wind_class": "IIB"}, "Turbulence.wind_class = 'IIB': model VonKarman does not use it"),
    ({"model": "Dryden", "hub_height": 50.0}, "Turbulence.hub_height = 50.0: model Dryden does not use it"),
])
def test_bad_parameters_name_the_field(kw, text):
    with pytest.raises(ValueError, match=text):
        Turbulence(**kw)


def test_fade_in_scales_the_field_and_its_rate():
    """r(t) = 0.5 (1 - cos(pi t / T_f)) on [0, T_f), 0 before, 1 after: the kernel's gust is r times the unfaded
    grid's, its rate along a moving point is the central difference of the sampled gust, and the plain-numpy
    reference (scipy interpolation) agrees."""
    from laddermill_gym.atmosphere.field import GustGrid, WindField
    from laddermill_gym.kernels.wind import gust_rate
    from laddermill_gym.model.params import WindParams
    from laddermill_gym.reference.wind import gust_rate as ref_rate
    from laddermill_gym.reference.wind import gust_velocity

    tf = 10.0
    turb = Turbulence(model="NTM", heights=(0.0, 200.0), dh=20.0, along_wind=(-100.0, 100.0), fade_in=tf)
    f = sample_wind_field([turb], 30.0, 0.1, np.random.default_rng(5))
    g = f.grid
    assert g.fade_in == tf
    plain = GustGrid(g.values, g.xi0, g.dxi, g.h0, g.dh, g.advection, g.heading)
    _, _, _, gp, gv = pack_wind_field(f)
    _, _, _, gp0, gv0 = pack_wind_field(WindField(grid=plain))
    wind = WindParams().with_field(f)
    p0, vel = np.array([-12.0, 4.0, -63.0]), np.array([1.5, -0.7, 0.4])
    for t in (-1.0, 0.0, 2.5, 5.0, 9.9, 10.0, 20.0):
        r = 0.0 if t <= 0 else (1.0 if t >= tf else 0.5 * (1 - math.cos(math.pi * t / tf)))
        p = p0 + vel * t
        np.testing.assert_allclose(gust_at(*p, t, gp, gv), r * np.array(gust_at(*p, t, gp0, gv0)), atol=1e-12)
        np.testing.assert_allclose(gust_at(*p, t, gp, gv), gust_velocity(wind, p, t), atol=1e-9)
    for t in (3.3, 7.1):  # inside a grid cell: the sampled gust is smooth there
        h = 1e-5
        fd = (np.array(gust_at(*(p0 + vel * (t + h)), t + h, gp, gv))
              - np.array(gust_at(*(p0 + vel * (t - h)), t - h, gp, gv))) / (2 * h)
        rate = np.array(gust_rate(*(p0 + vel * t), *vel, t, gp, gv))
        np.testing.assert_allclose(rate, fd, rtol=1e-5, atol=1e-6)
        np.testing.assert_allclose(rate, ref_rate(wind, p0 + vel * t, vel, t), atol=1e-9)


def test_low_band_is_the_kaimal_spectrums_closed_form_integral():
    """The variance below kappa_max of S = 4 sigma^2 L / (1 + 6 kappa L)^(5/3) is sigma^2 (1 - (1 + 6 kappa_max
    L)^(-2/3)) in closed form; the coherence decay at zero wavenumber is IEC's 12 x 0.12 / L_c."""
    from laddermill_gym.atmosphere.turbulence import low_band

    U, lam, K = 8.0, 42.0, 1.0 / 1400.0
    sigma = 0.14 * (0.75 * U + 5.6)  # class B
    h = np.array([90.0, 100.0, 110.0])
    lows = low_band("NTM", K, h, "IB", U, 100.0, "moderate", None)
    for (var, _), (ratio, scale) in zip(lows, ((1.0, 8.1), (0.8, 2.7), (0.5, 0.66)), strict=True):
        L = scale * lam
        np.testing.assert_allclose(var, (ratio * sigma) ** 2 * (1.0 - (1.0 + 6.0 * K * L) ** (-2.0 / 3.0)), rtol=1e-6)
    np.testing.assert_allclose(lows[0][1], 12.0 * 0.12 / (8.1 * lam), rtol=1e-12)  # L_c = 8.1 Lambda_1 (eq. B.4)


def test_offset_mode_keeps_the_spectrums_level_and_adds_the_low_band_as_row_offsets():
    """On a 700 m grid (a gusts-v1 NTM scenario's) the default rescales the kept modes to sigma^2; "offset" keeps
    them at S(kappa) dkappa (their closed-form sum) and adds the variance below the first mode as each row's mean
    over the grid (the Fourier series has no mean mode), the rows' offsets correlated exp(-12 x 0.12 dh / L_c)."""
    from laddermill_gym.atmosphere import turbulence_models as tm

    kw = dict(model="NTM", wind_class="IB", wind_speed=8.0, hub_height=100.0, heights=(100.0, 140.0), dh=40.0,
              along_wind=(-100.0, 100.0), dxi=10.0)
    t_end = 60.0
    offset = Turbulence(**kw, low_frequencies="offset")
    g = offset.grid_geometry(t_end)
    dk = 1.0 / (g.n_xi * g.dxi)
    kappa = dk * np.arange(1, (g.n_xi + 1) // 2)
    sigma, L = 0.14 * (0.75 * 8.0 + 5.6), 8.1 * 42.0
    kept = float(np.sum(tm.kaimal_spectrum(kappa, sigma, L)) * dk)
    low = sigma ** 2 * (1.0 - (1.0 + 6.0 * 0.5 * dk * L) ** (-2.0 / 3.0))
    assert kept < 0.7 * sigma ** 2  # a short grid: the rescaling raised the kept modes by more than 1.4
    u = fields(offset, t_end, 600)[..., 0]  # (600, n_xi, 2)
    means = u.mean(axis=1)
    assert means.var(axis=0) == pytest.approx(np.full(2, low), rel=0.15)
    rho = np.corrcoef(means[:, 0], means[:, 1])[0, 1]
    assert rho == pytest.approx(math.exp(-12.0 * 0.12 * 40.0 / L), abs=0.05)
    assert (u - means[:, None, :]).var(axis=1).mean(axis=0) == pytest.approx(np.full(2, kept), rel=0.1)
    rescaled = fields(Turbulence(**kw), t_end, 200)[..., 0]
    assert rescaled.var(axis=1).mean(axis=0) == pytest.approx(np.full(2, sigma ** 2), rel=0.1)
    assert np.abs(rescaled.mean(axis=1)).max() < 1e-9  # no offset in the default


@pytest.mark.parametrize("env_id, top", [("laddermill_gym/LadderChain-v0", 400.0),
                                         ("laddermill_gym/Rotorcraft-v0", 20.0),
                                         ("laddermill_gym/PumpingKite-v0", 250.0),
                                         ("laddermill_gym/PointMassChain-v0", 400.0)])
def test_a_grid_below_the_start_warns_naming_the_field(env_id, top):
    """Turbulence's default grid (0-400 m) under the chain's wings (up to about 3.5 km) held the top row's gust for
    every wing above it without a word (review of 2026-12-07); as for LadderMill's loop, a grid that does not cover
    the start's bodies, nodes and anchors now warns, naming the field and the heights needed."""
    import warnings

    import gymnasium as gym

    turb = {"type": "Turbulence", "model": "NTM", "wind_class": "IB", "wind_speed": 10.0, "hub_height": 100.0,
            "heights": [0.0, top], "dh": 10.0, "along_wind": [-5000.0, 5000.0], "dxi": 20.0}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # Gymnasium: v0 ids out of date
        with pytest.warns(RuntimeWarning, match=rf"disturbances\[0\]\.heights = \[0, {top:g}\] m does not cover the "
                                                r"start's bodies and cable nodes \(-?[\d.]+ to [\d.]+ m\)"):
            gym.make(env_id, disturbances=[turb], episode_time=10.0).close()
