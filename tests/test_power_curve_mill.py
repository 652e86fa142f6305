"""``laddermill power-curve`` (issue 30 point 3) on the v2 mill, scene ``laddermill_v2`` (the default). Oracles: the
scene files' own numbers (the ramp rule's times and the tail settings, read from the YAML), the paper's relation
P = (T_first - T_last) V_c from the period-mean tensions (closed form), Betz's limit 16/27 of the wind power through
the loop's frontal strip (the paper's wind profile and density, eqs. 1 and 3, integrated here by scipy's adaptive
quadrature, independently of the command's trapezoid) and the cable's breaking load over F_s = 2.5 (Lansdorp et al.
2008). The full sweep is ``laddermill power-curve --workers 1`` (docs/power_curve.md)."""

from __future__ import annotations

import json
import math

import pytest
import yaml
from scipy.integrate import quad

from laddermill_gym import load_scene
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.studies.mill import power_curve


def _yaml(kind: str, name: str) -> dict:
    return yaml.safe_load((CONFIG_DIR / kind / f"{name}.yaml").read_text(encoding="utf-8"))


def _betz_w(scene: dict, span: float, h_low: float, h_high: float) -> float:
    """16/27 of the integral of rho V^3 / 2 over a strip ``span`` [m] wide from h_low to h_high [m], the wind of
    the scene file: V = v0 (h / h0)^a below h0, v0 + v1 (h - h0) above (eq. 1); rho = rho0 exp(-h / H) (eq. 3)."""
    w = scene["wind"]

    def power_density(h):
        v = w["v0"] * (h / w["h0"]) ** w["exponent"] if h < w["h0"] else w["v0"] + w["v1"] * (h - w["h0"])
        return 0.5 * w["rho0"] * math.exp(-h / w["scale_height"]) * v ** 3 * span

    pts = [w["h0"]] if h_low < w["h0"] < h_high else None
    return 16.0 / 27.0 * quad(power_density, h_low, h_high, points=pts, limit=200, epsrel=1e-10)[0]


@pytest.mark.parametrize("argv, value", [(["--scene", "laddermill_v9"], "laddermill_v9"),
                                         (["--ramp", "fast"], "fast"), (["--max-time", "-5"], "-5")])
def test_bad_option_is_refused_naming_the_value(argv, value, capsys):
    with pytest.raises(SystemExit) as exc:
        power_curve.main(argv)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert value in err and argv[0] in err


def test_default_scene_is_the_v2_mill():
    """The default is the mill periodic over the paper's range (v2); v1 stays selectable."""
    assert power_curve.SCENE == "laddermill_v2" == power_curve.Config().scene
    assert set(power_curve.SCENES) == {"laddermill_v1", "laddermill_v2"}


@pytest.mark.parametrize("scene", ["laddermill_v2", "laddermill_v1"])
@pytest.mark.parametrize("v_c", [0.5, 2.0, 5.0])
def test_ramp_rules_from_the_scene_file(scene, v_c):
    """'rate': V_c at the scene's own acceleration (its last speed over its last time); 'scene': its ramp time."""
    st = _yaml("scenes", scene)["station"]
    station = load_scene(scene, dimension=2).assembly.station
    rate = st["speed_m_s"][-1] / st["speed_times_s"][-1]  # [m/s^2] v2: 0.01 (2 m/s over 200 s)
    assert power_curve.ramp_time(station, v_c, "rate") == pytest.approx(v_c / rate, rel=1e-12)
    assert power_curve.ramp_time(station, v_c, "scene") == pytest.approx(st["speed_times_s"][-1], rel=1e-12)
    with pytest.raises(ValueError, match="'fast'"):
        power_curve.ramp_time(station, v_c, "fast")


@pytest.mark.parametrize("h_low, h_high", [(0.0, 3000.0), (20.0, 40.0), (60.0, 3500.0)])
def test_betz_bound_against_quadrature(h_low, h_high):
    sc = load_scene("laddermill_v2", dimension=2)
    got = power_curve.betz_bound_w(sc.assembly.wind, sc.assembly.wing(0).span, h_low, h_high)
    span = _yaml("wings", "meijaard_wing_v2")["span"]
    assert got == pytest.approx(_betz_w(_yaml("scenes", "laddermill_v2"), span, h_low, h_high), rel=1e-5)


def test_quick_v2_case_against_the_papers_relation_and_betz(tmp_path):
    """``laddermill power-curve --quick`` (scene laddermill_v2, V_c 2 m/s at V0 8 m/s, its 200 s ramp then 70 s of
    search): files written; the scene's tail settings; the power is the paper's relation (T_first - T_last) V_c to
    1 %, positive and below Betz's limit through the loop's strip; within_limit is the last period's largest tension
    against breaking_load / 2.5."""
    assert power_curve.main(["--quick", "--out", str(tmp_path)]) == 0
    for name in ("power_curve.csv", "power_curve.json", "power_curve.png"):
        assert (tmp_path / name).stat().st_size > 0
    meta = json.loads((tmp_path / "power_curve.json").read_text(encoding="utf-8"))
    scene = _yaml("scenes", "laddermill_v2")
    assert meta["scene"] == "laddermill_v2" and meta["config"]["ramp"] == "rate"
    (r,) = meta["rows"]
    assert (r["v0_m_s"], r["v_c_m_s"]) == (8.0, 2.0)
    assert r["ramp_s"] == pytest.approx(2.0 * scene["station"]["speed_times_s"][-1] / scene["station"]["speed_m_s"][-1])
    assert (r["elevator_up_deg"], r["elevator_down_deg"]) == pytest.approx(
        (scene["initial"]["elevator_up_deg"], scene["initial"]["elevator_down_deg"]))
    assert r["breakdown"] == "" and r["power_kW"] > 0.0
    assert r["power_kW"] == pytest.approx((r["t_first_kN"] - r["t_last_kN"]) * r["v_c_m_s"], rel=1e-2)
    betz_kw = _betz_w(scene, _yaml("wings", "meijaard_wing_v2")["span"], r["h_low_m"], r["h_high_m"]) / 1e3
    assert r["betz_kW"] == pytest.approx(betz_kw, rel=1e-4)
    assert r["power_kW"] < betz_kw
    limit_kn = _yaml("cables", "dyneema_25mm")["breaking_load"] / 2.5 / 1e3
    assert r["t_limit_kN"] == pytest.approx(limit_kn)
    assert r["within_limit"] == (r["t_max_kN"] <= limit_kn)
    # --table: the same files again from the JSON, without a run
    assert power_curve.main(["--table", str(tmp_path / "power_curve.json"), "--out", str(tmp_path / "again")]) == 0
    assert (tmp_path / "again" / "power_curve.csv").read_text() == (tmp_path / "power_curve.csv").read_text()
