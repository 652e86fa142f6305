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
                                         (["--ramp", "fast"], "fast"), (["--max-time", "-5"], "-5"),
                                         (["--tail-rule", "feather"], "feather")])
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


# The depower tail rule (--tail-rule depower). Oracle: the moment of aerodynamics and weight about the attachment
# written out in trim_slope.moment_about_attachment (a separate implementation from the simulator's
# pitch_trim_alpha, which the rule searches on), its zero found here by scanning alpha, and the lift coefficient
# read from the wing file's table with a spline built here.

def _table_cl(wing, alpha: float, elevator: float) -> float:
    """C_L + C_L,de d [-] at alpha [rad] from the wing's table (a periodic cubic spline over the table's alphas)."""
    from scipy.interpolate import CubicSpline

    from laddermill_gym.model.params import AERO_INDEX

    c = CubicSpline(wing.aero.alpha, wing.aero.values, bc_type="periodic", axis=0)(alpha)
    return float(c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * elevator)


def _trim_alpha(wing, elevator: float, speed: float) -> float:
    """The attached-flow trim [rad]: the first nose-down crossing of M_P from -10 deg up (0.05 deg scan, brentq)."""
    from scipy.optimize import brentq

    from laddermill_gym.studies.mill.trim_slope import moment_about_attachment

    m = lambda a: moment_about_attachment(wing, a, elevator, speed)  # noqa: E731
    grid = [math.radians(-10.0 + 0.05 * i) for i in range(601)]
    for a0, a1 in zip(grid, grid[1:], strict=False):
        if m(a0) > 0.0 >= m(a1):
            return brentq(m, a0, a1, xtol=1e-12)
    raise AssertionError("no attached-flow trim")


@pytest.mark.parametrize("v0", [10.0, 12.0, 14.0])
def test_depower_rule_trims_the_scaled_lift_coefficient(v0):
    """Above 8 m/s each leg's elevator trims the wing (at rest on the cable, in the wind V0, sea-level density) at
    C_L(8 m/s, scene elevator) (8 / V0)^n, n = 2 ascending, 1.75 descending, to 1e-6; an elevator above the scene's."""
    from laddermill_gym.studies.mill.tail_schedule import DEPOWER_EXPONENTS, tail_rule

    sc = load_scene("laddermill_v2", dimension=2)
    wing, ini = sc.assembly.wing(0), _yaml("scenes", "laddermill_v2")["initial"]
    got = tail_rule(sc.initial, wing, v0, "depower")
    assert DEPOWER_EXPONENTS == (2.0, 1.75)
    for d_deg, scene_deg, n in zip(got, (ini["elevator_up_deg"], ini["elevator_down_deg"]), (2, 1.75), strict=True):
        d, ds = math.radians(d_deg), math.radians(scene_deg)
        target = _table_cl(wing, _trim_alpha(wing, ds, 8.0), ds) * (8.0 / v0) ** n
        print(f"V0 {v0:g} m/s, n = {n:g}: trim C_L {_table_cl(wing, _trim_alpha(wing, d, v0), d):.4f} at elevator "
              f"{d_deg:.2f} deg, target {target:.4f} = C_L at 8 m/s "
              f"{_table_cl(wing, _trim_alpha(wing, ds, 8.0), ds):.4f} x (8 / V0)^{n:g}")
        assert _table_cl(wing, _trim_alpha(wing, d, v0), d) == pytest.approx(target, abs=1e-6)
        assert d_deg > scene_deg


@pytest.mark.parametrize("v0", [4.0, 8.0])
def test_depower_rule_is_the_scenes_up_to_the_papers_wind(v0):
    from laddermill_gym.studies.mill.tail_schedule import tail_rule

    sc = load_scene("laddermill_v2", dimension=2)
    ini = _yaml("scenes", "laddermill_v2")["initial"]
    for rule in ("scene", "depower"):
        assert tail_rule(sc.initial, sc.assembly.wing(0), v0, rule) == pytest.approx(
            (ini["elevator_up_deg"], ini["elevator_down_deg"]), rel=1e-12)
    # bit for bit: the same floats, so run_case loads the scene file unchanged under either rule (the default depower)
    assert tail_rule(sc.initial, sc.assembly.wing(0), v0, "depower") == tail_rule(
        sc.initial, sc.assembly.wing(0), v0, "scene")
    with pytest.raises(ValueError, match="'feather'"):
        tail_rule(sc.initial, sc.assembly.wing(0), v0, "feather")


def test_table_merges_runs_a_later_case_replacing_an_earlier_one():
    """``--table A.json B.json``: rows in order, B's (V0, V_c) replacing A's, B's settings with both runs' speeds;
    a row from before the tail rule was recorded gets its run's rule."""
    base = {"scene": "laddermill_v2", "power_kW": 1.0}
    a = {"config": {"speeds": [1.0, 2.0], "wind_speeds": [2.0], "tail": "scene"},
         "rows": [base | {"v0_m_s": 8.0, "v_c_m_s": 2.0}, base | {"v0_m_s": 10.0, "v_c_m_s": 2.0}]}
    b = {"config": {"speeds": [], "wind_speeds": [2.0, 3.0], "tail": "depower"},
         "rows": [base | {"v0_m_s": 10.0, "v_c_m_s": 2.0, "tail_rule": "depower", "power_kW": 5.0}]}
    cfg, rows = power_curve.merge_tables([a, b])
    assert (cfg.tail, cfg.speeds, cfg.wind_speeds) == ("depower", (1.0, 2.0), (2.0, 3.0))
    assert [(r["v0_m_s"], r["tail_rule"], r["power_kW"]) for r in rows] == [(8.0, "scene", 1.0), (10.0, "depower", 5.0)]


def test_table_of_adaptive_runs_keeps_the_adaptive_search_for_its_caption():
    """A default run searches V_c adaptively (``wind_speeds: null`` in its JSON); ``--table`` on it made the grid an
    empty tuple and the figure's caption crashed (``min() arg is an empty sequence``) after the CSV and JSON were
    written (review of 2026-12-08)."""
    from laddermill_gym.studies.mill.power_curve_plot import grid_text

    adaptive = {"config": {"speeds": [2.0], "wind_speeds": None, "tail": "scene"}, "rows": []}
    cfg, _ = power_curve.merge_tables([adaptive, adaptive])
    assert cfg.wind_speeds is None and grid_text(cfg) == "adaptive V_c search"
    fixed = {"config": {"speeds": [], "wind_speeds": [2.0, 4.0], "tail": "scene"}, "rows": []}
    cfg, _ = power_curve.merge_tables([adaptive, fixed])
    assert grid_text(cfg) == "V_c 2-4 m/s"


# The adaptive V_c search per wind (studies/mill/vc_search.py). Oracle: the rule as stated in docs/power_curve.md
# (grid 2, 3, 5; up through 6-10 while the fastest operates; 4 where 3 is best and 5 fails; 1, 0.5 where nothing
# operates or the best is the lowest tried), walked by hand on synthetic mills that operate on a given set of V_c.

def _synthetic(operates: set[float]):
    """An evaluator: a row per V_c, an operating point (power V_c kW) when V_c is in ``operates``; records the
    order of the calls."""
    calls = []

    def evaluate(v_c):
        calls.append(v_c)
        return {"v_c_m_s": v_c, "periodic": v_c in operates, "within_limit": True, "power_kW": v_c}

    return evaluate, calls


@pytest.mark.parametrize("operates, tried, best", [
    ({2.0, 3.0, 5.0, 6.0, 7.0, 8.0}, [2, 3, 5, 6, 7, 8, 9], 8),  # the 14 m/s mill: climbs, stops at 9
    ({2.0, 3.0, 5.0}, [2, 3, 5, 6], 5),  # 10 m/s: 6 fails, nothing else
    ({2.0, 3.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0}, [2, 3, 5, 6, 7, 8, 9, 10], 10),  # the climb's end
    ({2.0, 3.0}, [2, 3, 5, 4], 3),  # 6 m/s: 3 best, 5 fails -> 4
    ({2.0, 3.0, 4.0}, [2, 3, 5, 4], 4),
    (set(), [2, 3, 5, 1, 0.5], None),  # 4 m/s: nothing operates -> 1, 0.5
    ({2.0, 1.0, 0.5}, [2, 3, 5, 1, 0.5], 2),  # best at the lowest tried -> 1, 0.5
    ({3.0}, [2, 3, 5, 4], 3),
])
def test_adaptive_search_walks_the_stated_rule(operates, tried, best):
    from laddermill_gym.studies.mill import vc_search

    evaluate, calls = _synthetic(operates)
    rows = vc_search.search(evaluate)
    assert calls == tried and [r["v_c_m_s"] for r in rows] == tried
    b = vc_search.best(rows)
    assert (b and b["v_c_m_s"]) == best


def _replay_file(tmp_path, rows) -> str:
    """An earlier run's power_curve.json holding ``rows`` (V0, V_c, periodic, elevators [deg]), the default
    settings of the run."""
    cfg = {"speeds": [2.0], "winds": [6.0], "wind_speeds": None, "max_time": 1500.0, "n_wings": None,
           "scene": "laddermill_v2", "ramp": "rate", "tail": "depower"}
    full = [{"scene": "laddermill_v2", "tail_rule": "scene", "v0_m_s": v0, "v_c_m_s": v, "ramp_s": 100.0 * v,
             "elevator_up_deg": up, "elevator_down_deg": down, "t_limit_kN": 210.0, "t_rest_max_kN": 99.0,
             "periodic": ok, "t_s": 900.0, "power_kW": 10.0 * v, "hand_estimate_kW": 10.0 * v, "h_low_m": 1.0,
             "h_high_m": 3000.0, "betz_kW": 1e4, "t_first_kN": 100.0, "t_last_kN": 90.0, "t_max_kN": 100.0,
             "within_limit": True, "t_peak_search_kN": 101.0, "breakdown": "", "overload": ""}
            for v0, v, ok, up, down in rows]
    path = tmp_path / "earlier.json"
    path.write_text(json.dumps({"config": cfg, "rows": full}), encoding="utf-8")
    return str(path)


def test_replay_walks_earlier_rows_and_refuses_a_missing_case(tmp_path, capsys):
    """``--replay``: the default run's walk over earlier rows (the scene's elevators at 6 and 8 m/s, the depower
    rule's there bit for bit); 6 m/s operating at 2, 3 needs 2, 3, 5, 4 (stated rule): without V_c 4 it fails naming
    V0 6, V_c 4; with it, the table and best as a run would print them; a row at 10 m/s with the scene's elevators
    is not the depower rule's case and is refused."""
    sc = load_scene("laddermill_v2", dimension=2)
    up, down = (math.degrees(float(e)) for e in (sc.initial.elevator_up, sc.initial.elevator_down))
    rows = [(8.0, 2.0, True, up, down), (6.0, 2.0, True, up, down), (6.0, 3.0, True, up, down),
            (6.0, 5.0, False, up, down)]
    argv = ["--speeds", "2", "--winds", "6", "--out", str(tmp_path / "out"), "--replay"]
    assert power_curve.main(argv + [_replay_file(tmp_path, rows)]) == 1
    assert "V0 6 m/s, V_c 4 m/s: the search needs this case" in capsys.readouterr().err
    assert power_curve.main(argv + [_replay_file(tmp_path, rows + [(6.0, 4.0, False, up, down)])]) == 0
    out = capsys.readouterr().out
    assert "V0 = 6.0 m/s: best V_c 3.0 m/s, 30.0 kW" in out and "V0 = 8.0 m/s: best V_c 2.0 m/s, 20.0 kW" in out
    meta = json.loads((tmp_path / "out" / "power_curve.json").read_text(encoding="utf-8"))
    assert [(r["v0_m_s"], r["v_c_m_s"]) for r in meta["rows"]] == [(8.0, 2.0), (6.0, 2.0), (6.0, 3.0), (6.0, 5.0),
                                                                    (6.0, 4.0)]
    ten = [(10.0, v, True, up, down) for v in (2.0, 3.0, 5.0, 6.0)]
    argv[3] = "10"
    assert power_curve.main(argv + [_replay_file(tmp_path, rows + ten)]) == 1
    assert "V0 10 m/s, V_c 2 m/s" in capsys.readouterr().err
