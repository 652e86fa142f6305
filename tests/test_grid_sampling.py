"""studies/gusts/grid_sampling.py: the kernel's reading of a gust grid as the study uses it (the grid's own node
values at the nodes, the bilinear mean of the four nodes at a cell's centre, in the wind's axes whatever the
heading), and what it measures on a small grid: the nodes at the model's variance, points between them below it."""

import math

import numpy as np
import pytest

from laddermill_gym.atmosphere.turbulence import Turbulence
from laddermill_gym.studies.gusts.grid_sampling import grid_sampling, read_grid

KW = dict(model="NTM", wind_class="IB", wind_speed=8.0, hub_height=100.0, heights=(0.0, 100.0), dh=10.0,
          along_wind=(-50.0, 50.0), dxi=5.0, fade_in=2.0)


@pytest.mark.parametrize("heading", [0.0, 0.7])
def test_the_reading_is_the_node_values_and_their_bilinear_mean(heading):
    turb = Turbulence(heading=heading, **KW)
    g = turb.gust_grid(20.0, np.random.default_rng(3))
    v = g.values
    i, j = np.array([3, 10, 17]), np.array([1, 4, 8])
    at = read_grid(g, g.xi0 + g.dxi * i, g.h0 + g.dh * j, 5.0)
    np.testing.assert_allclose(at, v[i, j], rtol=0, atol=1e-12)
    mid = read_grid(g, g.xi0 + g.dxi * (i + 0.5), g.h0 + g.dh * (j + 0.5), 5.0)
    four = 0.25 * (v[i, j] + v[i + 1, j] + v[i, j + 1] + v[i + 1, j + 1])
    np.testing.assert_allclose(mid, four, rtol=0, atol=1e-12)
    assert math.isclose(float(read_grid(g, g.xi0 + g.dxi * i[:1], g.h0 + g.dh * j[:1], 1.0)[0, 0]),
                        0.5 * (1 - math.cos(math.pi * 1.0 / 2.0)) * v[i[0], j[0], 0], abs_tol=1e-12)  # the fade-in


def test_the_nodes_hold_the_models_variance_and_points_between_them_less():
    """Over 60 fields the nodes' g^2 / sigma_k^2 is 1 within the printed 95 % half-width (the synthesis scales each
    row to sigma^2, IEC's sigma_1 = I_ref (0.75 V + 5.6) times 1, 0.8, 0.5); at random points w's is below it (rows
    10 m apart against w's integral scale of 0.66 x 42 m); the model's correlation at lag 0 is 1."""
    r = grid_sampling(Turbulence(**KW), 20.0, seeds=60, points=100, lags=(0.0, 5.0))
    mean, half = r["node"]
    assert np.all(np.abs(mean - 1.0) < 2.0 * half + 0.02), (mean, half)
    assert r["between"][0][2] < mean[2] - 2.0 * (half[2] + r["between"][1][2])
    assert r["model_corr"][0] == pytest.approx(1.0, abs=1e-9) and r["field_corr"][0] == pytest.approx(1.0)
    assert 0.0 < r["model_corr"][1] < 1.0


def test_a_longer_record_keeps_the_models_correlation_at_long_lags():
    """``record``: the field's first columns are those of ``synthesize`` over a record four times the grid's (the
    same generator's draws); with the offset synthesis, u's correlation at a fixed point 20 and 40 s apart over 800
    fields is the unbounded Kaimal model's (the integral of S(kappa) cos(2 pi kappa U lag) over that of S) within
    0.08 (about 2.5 standard errors), where the grid-long record (record 1) is not at 40 s."""
    import dataclasses

    from laddermill_gym.atmosphere.turbulence import low_band, synthesize, turbulence_spectra

    turb = Turbulence(low_frequencies="offset", record=4.0, **KW)
    g = turb.gust_grid(20.0, np.random.default_rng(5))
    geo = turb.grid_geometry(20.0)
    n_rec = turb.record_columns(geo.n_xi)
    assert n_rec >= 4 * geo.n_xi and n_rec % 2 == 0
    dk = 1.0 / (n_rec * geo.dxi)
    h = geo.h0 + geo.dh * np.arange(geo.n_h)
    args = (turb.wind_class, turb.wind_speed, turb.hub_height, turb.severity, turb.w20)
    comps = turbulence_spectra(turb.model, dk * np.arange(1, (n_rec + 1) // 2), h, *args)
    lows = low_band(turb.model, 0.5 * dk, h, *args)
    rng = np.random.default_rng(5)
    direct = np.stack([synthesize(s, sig, dec, geo.dh, dk, n_rec, rng, rescale=False, low=low)
                       for (s, sig, dec), low in zip(comps, lows, strict=True)], axis=-1)
    np.testing.assert_array_equal(g.values, direct[: geo.n_xi])
    long = dict(model="NTM", wind_class="IB", wind_speed=8.08, hub_height=100.5, heights=(0.0, 250.0), dh=5.0,
                along_wind=(-100.0, 100.0), dxi=5.0, fade_in=10.0, low_frequencies="offset")
    r4 = grid_sampling(Turbulence(record=4.0, **long), 60.0, seeds=800, points=1, lags=(20.0, 40.0))
    assert np.all(np.abs(r4["field_corr"] - r4["model_corr"]) < 0.08), (r4["field_corr"], r4["model_corr"])
    r1 = grid_sampling(dataclasses.replace(Turbulence(**long), record=1.0), 60.0, seeds=800, points=1, lags=(40.0,))
    assert r1["field_corr"][0] - r1["model_corr"][0] > 0.05, (r1["field_corr"], r1["model_corr"])
    with pytest.raises(ValueError, match=r"Turbulence\.record = 0\.5: must lie in 1 \.\. 1000"):
        Turbulence(record=0.5)
