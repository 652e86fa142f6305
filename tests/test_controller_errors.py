"""The work-precision study's controller-relevant errors (``studies/numerics/controller_errors.py``, issue 32
point 4).

Oracles: a synthetic trajectory pair with known differences (each error is the planted one, divided by the
planted largest reference value where relative; an attitude across +-pi wraps); the quaternion of known 3-2-1
Euler angles written out in closed form (Stevens & Lewis, eq. 1.8-19) and a known CG y read back; the envs' own
choice of the ground elements (the scene layout's first and last piece, ``envs/task.py``) for the power; and on a
study run the invariant that a wing's lateral error is at most its CG's position error.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym.studies.numerics import controller_errors as ce


def _pair():
    rng = np.random.default_rng(1)
    n, ne, nw = 6, 5, 3
    ref = {"tension": 1e5 + 1e4 * rng.random((n, ne)), "power": 2e5 + 1e4 * rng.random(n),
           "lateral": rng.normal(size=(n, nw)), "attitude": 0.3 * rng.normal(size=(n, nw, 3))}
    ref["tension"][2, 3] = 2.5e5  # the largest tension of the run
    ref["power"][4] = -3e5  # the largest power in magnitude (negative: a motor)
    return ref, {k: v.copy() for k, v in ref.items()}


def test_planted_differences():
    ref, q = _pair()
    q["tension"][1, 0] += 2000.0  # 2000 / 2.5e5 = 0.008
    q["power"][0] -= 4500.0  # 4500 / 3e5 = 0.015
    q["lateral"][5, 2] += 0.07
    q["attitude"][3, 1, 2] -= 0.004
    e = ce.controller_errors(q, ref)
    assert e["err_tension_rel"] == pytest.approx(0.008, rel=1e-9)
    assert e["err_power_rel"] == pytest.approx(0.015, rel=1e-9)
    assert e["err_lateral_m"] == pytest.approx(0.07, rel=1e-9)
    assert e["err_attitude_rad"] == pytest.approx(0.004, rel=1e-9)
    assert not e["meets_controller"]  # power beyond 1 %
    q["power"][0] += 3000.0  # now 1500 / 3e5 = 0.005
    assert ce.controller_errors(q, ref)["meets_controller"]
    q["attitude"][0, 0, 0] += 0.011
    assert not ce.controller_errors(q, ref)["meets_controller"]


def test_identical_and_wrapped_attitude():
    ref, q = _pair()
    e = ce.controller_errors(q, ref)
    assert e["meets_controller"] and all(e[k] == 0.0 for k in ce.TOLERANCES)
    ref["attitude"][0, 0, 2] = math.pi - 0.002  # yaw just below +pi; the run just beyond it, reported as -pi + 0.001
    q["attitude"][0, 0, 2] = -math.pi + 0.001
    assert ce.controller_errors(q, ref)["err_attitude_rad"] == pytest.approx(0.003, abs=1e-12)


def _quaternion_321(phi, theta, psi):
    """Closed form of the 3-2-1 (yaw, pitch, roll) rotation's quaternion (Stevens & Lewis eq. 1.8-19)."""
    c = [math.cos(a / 2) for a in (phi, theta, psi)]
    s = [math.sin(a / 2) for a in (phi, theta, psi)]
    return np.array([c[0] * c[1] * c[2] + s[0] * s[1] * s[2], s[0] * c[1] * c[2] - c[0] * s[1] * s[2],
                     c[0] * s[1] * c[2] + s[0] * c[1] * s[2], c[0] * c[1] * s[2] - s[0] * s[1] * c[2]])


def test_quantities_of_a_known_state():
    from laddermill_gym.kernels.contract import B3_POS, B3_QUAT
    from laddermill_gym.ladder.scene import load_scene

    sc = load_scene("tethered_wing")
    sim = sc.simulator()
    x = sim.initial_state.copy()
    angles = (0.05, 0.2, -0.3)
    x[B3_QUAT: B3_QUAT + 4] = _quaternion_321(*angles)
    x[B3_POS + 1] = 1.25
    ten, power, lat, att = ce.quantities_at(sim, 0.5, x)
    np.testing.assert_allclose(att[0], angles, atol=1e-12)
    assert lat[0] == 1.25
    assert ce.ground_elements(sc.assembly) == (sc.layout.piece_elements[0][0], -1)  # one-ended: T_ground alone
    assert power == ten[sc.layout.piece_elements[0][0]]


@pytest.mark.parametrize("scene", ["ladder_chain", "laddermill"])
def test_ground_elements_are_the_envs(scene):
    from laddermill_gym.ladder.scene import load_scene

    sc = load_scene(scene)
    lay = sc.layout
    assert ce.ground_elements(sc.assembly) == (lay.piece_elements[0][0], lay.piece_elements[-1][-1])


def test_study_rows_carry_the_controller_errors():
    from laddermill_gym.studies.numerics import work_precision as wp
    from laddermill_gym.studies.numerics.work_precision_output import print_summary

    res = wp.run_scene("tethered_wing", forcings=("step",), duration=0.6, n_samples=3, repeats=1, n_dt=2,
                       progress=False)
    ref = res["references"]["step"]
    assert ref["err_tension_rel_reference_agreement"] < 1e-7 and ref["err_attitude_rad_reference_agreement"] < 1e-9
    rows = [r for r in res["rows"] if r["status"] == "ok"]
    assert {r["method"] for r in rows} >= {"rk4", "ros34pw2", "ros34pw2a"}
    for r in rows:  # the wing's y error is one component of its CG's position error
        assert r["err_lateral_m"] <= r["err_max_pos_m"] * (1 + 1e-12) + 1e-15
        if r["err_max_pos_m"] > 0:  # the printed extent is the scale of each run's relative position error
            assert r["err_max_pos_m"] / r["err_max_pos_rel"] == pytest.approx(ref["extent_m"], rel=1e-12)
    assert any(r["meets_controller"] for r in rows if r["method"] == "rk4")
    lines = []
    print_summary(res, echo=lines.append)
    assert any("meeting the controller tolerances" in s for s in lines)
    assert any("x rk4 at " in s for s in lines)
    assert any(s.endswith(f"; extent {ref['extent_m']:.1f} m") for s in lines)


def test_w_step_cost_parts_within_the_step():
    """The W step's parts (body and cable Jacobians, factorisation) each cost less than the whole step, and a
    right-hand side less than an RK4 step (four of them): the bound it prints is then between 0 and the W step.
    On the chain (101 wings): each part is timed through its own call from Python (about 10 us), which on the
    one-wing tethered wing is most of a part's time."""
    from laddermill_gym.studies.numerics import w_step_cost

    c = w_step_cost.step_costs("ladder_chain", 0.05, 0.01, n_steps=5)
    assert all(v > 0 for v in c.values()), c
    assert c["body_jacobian"] + c["cable_jacobian"] + c["factor"] < c["w_step"], c
    assert c["rhs"] < c["rk4_step"], c
    assert "RK4 steps" in w_step_cost.summary("ladder_chain", c)
    with pytest.raises(SystemExit):
        w_step_cost.main(["tethered_wing", "--dt-w", "0"])
