"""The apex-whip spectrum study (studies/numerics/whip_spectrum.py): the error's parts in groups of modes.

Oracle: a system whose eigenvectors and modal error coordinates are chosen, so the part in each group is known in
closed form (V[:, group] c[group]); the methods' stability functions are checked in tests/test_rosenbrock.py."""

import numpy as np
import pytest

from laddermill_gym.studies.numerics import whip_spectrum as ws


def test_error_parts_of_a_known_modal_error():
    lam = np.array([-0.1 + 0j, -5 + 100j, -5 - 100j, 0.3 + 0j])  # slow, a lightly damped pair, slow unstable
    rng = np.random.default_rng(1)
    a, b = rng.normal(size=4), rng.normal(size=4)
    V = np.column_stack([rng.normal(size=4), a + 1j * b, a - 1j * b, rng.normal(size=4)]).astype(complex)
    c = np.array([0.2, 0.05 + 0.03j, 0.05 - 0.03j, -0.4])
    e = (V @ c).real
    lat = np.array([0, 2])
    pair = (V[:, 1:3] @ c[1:3]).real
    slow = (V[:, [0, 3]] @ c[[0, 3]]).real
    h = 1 / 15  # z = -0.33 +- 6.7i on the pair: ROS34PW2 damps it to about 0.4 per step against the exact 0.72
    p = ws.error_parts(lam, V, e, lat, "ros34pw2", h)
    assert p["n_damped"] == 2 and p["n_slow"] == 2
    np.testing.assert_allclose(p["damped"], np.abs(pair[lat]).max(), rtol=1e-10)
    np.testing.assert_allclose(p["slow"], np.abs(slow[lat]).max(), rtol=1e-10)
    np.testing.assert_allclose(p["lateral"], np.abs(e[lat]).max(), rtol=0)
    np.testing.assert_allclose(p["exact"], np.abs(np.exp(h * lam)), rtol=1e-14)
    # ros2t keeps the pair's amplitude (|R| = 0.92 against the exact 0.72); RK4 at 0.01 s resolves it (0.947 against
    # 0.951; at 1/60 s it would damp it to 0.899 of the exact factor)
    for method, step in (("ros2t", h), ("rk4", 0.01)):
        q = ws.error_parts(lam, V, e, lat, method, step)
        assert q["n_damped"] == 0 and q["damped"] == 0.0


def test_command_prints_the_spectrum_and_the_parts(capsys):
    assert ws.main(["tethered_wing", "--time", "2", "--at", "1", "--methods", "ros34pw2:0.05", "rk4:0.005",
                    "--dt-ref", "0.001", "--top", "2"]) == 0
    out = capsys.readouterr().out
    assert "tethered_wing t = 1.0 s: 19 eigenvalues" in out
    assert "ros34pw2 at 0.05 s: largest lateral error" in out and "rk4 at 0.005 s" in out


@pytest.mark.parametrize("spec", ["rk4", "rk4:-1", "rk4:x", ":0.1"])
def test_a_bad_methods_entry_is_named(spec, capsys):
    from laddermill_gym.studies.numerics.whip_spectrum import main

    with pytest.raises(SystemExit):
        main(["ladder_chain", "--methods", spec])
    assert f"--methods {spec!r}: expected METHOD:STEP" in capsys.readouterr().err
