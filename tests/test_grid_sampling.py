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
