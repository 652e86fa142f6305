"""Issue 30 points 1-3: the v1 wing (cable attachment below the wing's ac) and its in-plane mill, scene
``laddermill_v1``. Oracles: the paper's power relation P = (T_first - T_last) V_c in closed form from the period-mean
tensions, the paper's "of the order of 200 kW", the paper's statement that the in-plane mill returns to a new
stationary motion after a change of wind or cable speed, and the cable's breaking load over the safety factor
F_s = 2.5 of Lansdorp et al. (2008). The full runs are ``slow``."""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import yaml

from laddermill_gym import load_scene
from laddermill_gym.derivations.wing_checks import attachment_vector
from laddermill_gym.derivations.wing_parameters import ATT_ANGLE, ATT_ANGLE_V1
from laddermill_gym.ladder.periodic import run_to_periodic
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.studies.mill import power_curve

SCENE = "laddermill_v1"
LIMIT_N = 5.25e5 / 2.5  # [N] breaking_load of configs/cables/dyneema_25mm.yaml over F_s = 2.5 (Lansdorp et al. 2008)


def _wing(name):
    return yaml.safe_load((CONFIG_DIR / "wings" / f"{name}.yaml").read_text(encoding="utf-8"))


def test_v1_wing_is_v0_with_the_attachment_moved():
    """Same airframe, mass, inertia and table as the v0 wing; the attachment is the derivation's ATT_ANGLE_V1 at
    the paper's 1.5 m, directly below the wing's ac (x = 0.75 m, the paper's CG-ac distance)."""
    v0, v1 = _wing("meijaard_wing"), _wing("meijaard_wing_v1")
    assert {k: v for k, v in v0.items() if k not in ("name", "attachment")} == \
        {k: v for k, v in v1.items() if k not in ("name", "attachment")}
    np.testing.assert_allclose(v0["attachment"], attachment_vector(ATT_ANGLE), atol=1e-4)
    np.testing.assert_allclose(v1["attachment"], attachment_vector(ATT_ANGLE_V1), atol=1e-3)
    assert v1["attachment"][0] == pytest.approx(v1["aero_reference"][0], abs=1e-3)
    assert np.hypot(v1["attachment"][0], v1["attachment"][2]) == pytest.approx(1.5, abs=1e-3)


def test_v1_scene_is_the_laddermill_with_the_v1_wing():
    """laddermill_v1 differs from LadderMill-v0's scene only in the wing, the elevators and the insertion rule."""
    a0 = load_scene("laddermill", dimension=2).assembly
    s1 = load_scene(SCENE, dimension=2)
    a1 = s1.assembly
    assert a1.n_wings == a0.n_wings == 101
    assert a1.wind == a0.wind
    assert a1.station.insertion == "cable" and a0.station.insertion == "paper"
    np.testing.assert_allclose(a1.wing(0).attachment, attachment_vector(ATT_ANGLE_V1), atol=1e-3)
    assert np.degrees([s1.initial.elevator_up, s1.initial.elevator_down]) == pytest.approx([-8.0, -0.5])


def test_power_curve_quick(tmp_path):
    """``laddermill power-curve --scene laddermill_v1 --quick``: files written; every case's mean power equals the
    paper's relation (T_first - T_last) V_c from the period-mean tensions (closed form) to 1 %."""
    assert power_curve.main(["--scene", SCENE, "--quick", "--out", str(tmp_path)]) == 0
    for name in ("power_curve.csv", "power_curve.json", "power_curve.png"):
        assert (tmp_path / name).stat().st_size > 0
    meta = json.loads((tmp_path / "power_curve.json").read_text(encoding="utf-8"))
    assert meta["safety_factor"] == 2.5 and meta["scene"] == SCENE
    assert [r["v_c_m_s"] for r in meta["rows"]] == [2.0]
    assert meta["best_per_wind"][0]["v0_m_s"] == 8.0
    for r in meta["rows"]:
        assert r["power_kW"] == pytest.approx(r["hand_estimate_kW"], rel=1e-2)
        assert r["t_limit_kN"] == pytest.approx(LIMIT_N / 1e3)


def _periodic(v_c, max_time=3000.0, overrides=None):
    ov = {"station": {"speed_m_s": [0.0, v_c]}}
    ov.update(overrides or {})
    sim = load_scene(SCENE, dimension=2, overrides=ov).simulator()
    return sim, run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=False)


@functools.cache
def _periodic_result(v_c):
    return _periodic(v_c)[1]


@pytest.mark.slow
@pytest.mark.parametrize("v_c", [1.0, 2.0, pytest.param(5.0, marks=pytest.mark.xfail(strict=True, reason=(
    "issue 30 point 1 open at 5 m/s: the upper descending leg goes slack and the loop does not settle "
    "(docs/wing_data.md, 'Design study')")))])
def test_v1_mill_is_periodic_in_plane(v_c):
    """The paper: the in-plane motion is stable and periodic (Figs. 6-7 at 1 and 5 m/s, Fig. 8 at 2 m/s)."""
    res = _periodic_result(v_c)
    assert res.converged, res.summary()
    assert res.mean_power_W == pytest.approx(
        power_curve.hand_estimate_w(res.tension_mean_N[0], res.tension_mean_N[-1], v_c), rel=1e-2)


@pytest.mark.slow
def test_v1_mill_delivers_the_papers_power_at_2_m_s():
    """Issue 30 point 2, matched at V_c = 2 m/s (the paper's Fig. 8 speed; at 5 m/s the mill is not periodic): at
    least 150 kW, of the order of the paper's 200 kW, every tension of the period below breaking load / 2.5."""
    res = _periodic_result(2.0)
    assert res.converged, res.summary()
    assert 150e3 <= res.mean_electrical_power_W <= 300e3
    assert np.max(res.tension_max_N) < LIMIT_N


def _step_runs(first_vc, overrides_after, wind_factor=None, max_time=3000.0):
    """Run to the periodic motion, then change the cable-speed schedule or scale the wind (a 1 s ramp) and run to
    the periodic motion again; returns the two results."""
    from laddermill_gym.atmosphere.field import WindField

    sim, before = _periodic(first_vc, max_time=max_time)
    assert before.converged, before.summary()
    t1, x, u = sim.t, sim.state.copy(), sim.controls.copy()
    sim2 = load_scene(SCENE, dimension=2, overrides=overrides_after(t1)).simulator()
    sim2.reset(state=x, t=t1, controls=u)
    if wind_factor is not None:
        sim2.set_wind(WindField(t0=t1, dt=1.0, speed=np.array([1.0, wind_factor]), direction=np.zeros(2)))
    after = run_to_periodic(sim2, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=False)
    print(f"before the step: {before.summary()}\nafter the step: {after.summary()}; largest tension of its period "
          f"{np.max(after.tension_max_N) / 1e3:.1f} kN")
    return before, after


@pytest.mark.slow
def test_v1_mill_finds_a_new_periodic_motion_after_a_wind_step():
    """The paper: after a change of the wind the mill comes to a new stationary motion. Wind 8 -> 9 m/s at V_c =
    2 m/s (the whole profile scaled by 9/8 over 1 s)."""
    before, after = _step_runs(2.0, lambda t1: {"station": {"speed_m_s": [0.0, 2.0]}}, wind_factor=9.0 / 8.0)
    assert after.converged, after.summary()
    assert after.mean_power_W > before.mean_power_W  # more wind, more power
    assert np.max(after.tension_max_N) < LIMIT_N


@pytest.mark.slow
def test_v1_mill_finds_a_new_periodic_motion_after_a_cable_speed_step():
    """The paper: after a change of the cable speed the mill comes to a new stationary motion. V_c 2 -> 3 m/s over
    1 s, from the periodic motion at 2 m/s."""
    def after(t1):
        return {"station": {"speed_times_s": [0.0, 30.0, t1, t1 + 1.0], "speed_m_s": [0.0, 2.0, 2.0, 3.0]}}

    before, res = _step_runs(2.0, after)
    assert res.converged, res.summary()
    assert res.period_s == pytest.approx(70.0 / 3.0)
    assert res.mean_power_W == pytest.approx(
        power_curve.hand_estimate_w(res.tension_mean_N[0], res.tension_mean_N[-1], 3.0), rel=1e-2)
