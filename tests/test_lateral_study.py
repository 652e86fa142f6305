"""Lateral study (laddermill_gym/studies/lateral/lateral_study.py): its eigenvalues against the nonlinear wing.

The study's claims (the default tethered wing is laterally unstable; a large enough dihedral effect makes it
stable) rest on the eigenvalues of the linearised lateral model. The oracle here is a separate computation:
the full nonlinear simulator (RK4 on the 13-state wing with quaternion attitude, no linearisation) is started
a micrometre sideways of the trim and the slow modes are identified from the sampled lateral position y(t)
alone. Once the fast modes have died out (their slowest decays at 1.7 1/s), y(t) is a sum of the three slow
modes, so its samples obey an exact third-order linear recurrence y[k] = a1 y[k-1] + a2 y[k-2] + a3 y[k-3];
the roots z of z^3 - a1 z^2 - a2 z - a3 give the continuous eigenvalues s = ln(z) / T. That is Prony's
method; it uses neither the Jacobian nor an eigenvalue solver of the study.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.studies.lateral.lateral_study import base_scene, lateral_eigenvalues, main, make_variant

SAMPLE = 0.5     # [s] sampling interval of y(t)
T_SETTLE = 10.0  # [s] fast modes (Re <= -1.7 1/s) decay by e^-17 before the fit window starts
T_END = 60.0     # [s]
Y0 = 1e-6        # [m] initial sideways offset: small enough that the response stays linear


def _prony_slow_modes(scene) -> tuple[np.ndarray, np.ndarray]:
    """(study's three slowest lateral eigenvalues, the same identified from the nonlinear response) [1/s]."""
    ev, x, u = lateral_eigenvalues(scene)
    sim = scene.simulator(x, u)
    x0 = x.copy()
    x0[1] += Y0  # wing CG y coordinate (global frame) in the full state
    sim.reset(x0, 0.0, u)
    n = int(round(SAMPLE / sim.settings.dt))
    t, y = [], []
    while sim.t <= T_END + 1e-9:
        t.append(sim.t)
        y.append(sim.state[1])
        sim.step(n_steps=n)
    t, y = np.array(t), np.array(y)
    y = y[t >= T_SETTLE] / Y0
    M = np.column_stack([y[2:-1], y[1:-2], y[:-3]])
    a, *_ = np.linalg.lstsq(M, y[3:], rcond=None)
    z = np.roots([1.0, -a[0], -a[1], -a[2]]).astype(complex)
    identified = np.log(z) / SAMPLE
    slow = ev[np.argsort(-ev.real)][:3]
    return np.sort_complex(slow), np.sort_complex(identified)


@pytest.mark.parametrize("clb_scale, unstable", [(1.0, True), (8.0, False)])
def test_eigenvalues_match_nonlinear_response(clb_scale, unstable):
    """Default wing (growing 0.111 +- 0.268j 1/s oscillation and 0.013 1/s drift) and the dihedral-effect
    variant Clb x 8 that the study reports as stable: the nonlinear response has the study's slow modes,
    including the sign of the largest real part."""
    base = base_scene()
    scene = base if clb_scale == 1.0 else make_variant(base, aero_scale={"Clb": clb_scale})
    slow, identified = _prony_slow_modes(scene)
    np.testing.assert_allclose(identified.real, slow.real, atol=1e-3)
    np.testing.assert_allclose(np.abs(identified.imag), np.abs(slow.imag), atol=1e-3)
    assert (identified.real.max() > 0) == unstable
    assert (slow.real.max() > 0) == unstable


def test_bad_input_raises_value_error():
    with pytest.raises(ValueError, match="--out"):
        main(["--out", "figure.txt"])
    with pytest.raises(ValueError, match="--sweeps"):
        main(["--out", "x.png", "--sweeps", "attach_x,nonsense"])
    base = base_scene()
    with pytest.raises(ValueError, match="attachment"):
        make_variant(base, attachment=[0.0, 1.0])
    with pytest.raises(ValueError, match="unknown aerodynamic column"):
        make_variant(base, aero_scale={"Cxx": 2.0})
    with pytest.raises(ValueError, match="v0"):
        make_variant(base, v0=-1.0)
