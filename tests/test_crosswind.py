"""The crosswind pumping controller (control/crosswind.py, crosswind_guidance.py, crosswind_config.py) and the
wind-window read-outs it flies on (envs/pumping/wind_window.py): the geometry against closed forms, the paths'
extents against their equations, bad configs refused naming the field, and a flown reel-out: figure eights on both
sides of the wind, far more power than the static cycle, never more than Loyd's bound, and a winch command that is
Loyd's third of the along-tether wind written from the scene file."""

import dataclasses
import math

import numpy as np
import pytest
import yaml

from laddermill_gym.control.crosswind import PHASE_NAMES, REEL_OUT
from laddermill_gym.control.crosswind_config import check_against_scene, load_crosswind_config
from laddermill_gym.control.crosswind_guidance import PathSpec, path_angles
from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.pumping.wind_window import wind_window
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.statics import table_spline

ID = "laddermill_gym/PumpingKite-v0"


def _rodrigues(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


@pytest.mark.parametrize("az, el, chi, mu", [(0.3, 0.5, 1.2, 0.1), (-0.6, 0.9, -2.5, -0.3), (0.0, 0.2, 0.0, 0.0)])
def test_wind_window_against_closed_forms(az, el, chi, mu):
    """Position (x north, z down, wind towards -x): p = L (-cos el cos az, cos el sin az, -sin el); the tangent
    vectors are dp/daz and dp/del normalised; a velocity cos(chi) e_el + sin(chi) e_az has course chi; a wing with
    body x along it and body z down the tether, rolled by mu about body x, has bank mu."""
    L = 400.0
    p = L * np.array([-math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), -math.sin(el)])
    e_az = np.array([math.sin(az), math.cos(az), 0.0])
    e_el = np.array([math.sin(el) * math.cos(az), -math.sin(el) * math.sin(az), -math.cos(el)])
    c = math.cos(chi) * e_el + math.sin(chi) * e_az
    z = -p / L
    y = np.cross(z, c)
    rot = _rodrigues(c, mu) @ np.column_stack([c, y, z])
    ww = wind_window(p[None], 30.0 * c[None], rot[None])
    np.testing.assert_allclose([ww.azimuth[0], ww.elevation[0], ww.course[0], ww.bank[0]], [az, el, chi, mu],
                               atol=1e-12)
    np.testing.assert_allclose([ww.distance[0], ww.tangential_speed[0], ww.radial_speed[0]], [L, 30.0, 0.0],
                               atol=1e-9)


def test_paths_against_their_equations():
    """The lemniscate of Booth reaches azimuth +-w at s = pi/2, 3pi/2 (at the centre elevation) and crosses the
    centre twice; every circle point is h from the centre (great-circle distance)."""
    spec = PathSpec("figure_eight", math.radians(30), math.radians(5), math.radians(25), math.radians(8),
                    "up_at_sides", math.radians(7))
    az, el = path_angles(spec)
    i = np.argmax(az)
    assert az[i] == pytest.approx(spec.azimuth + spec.width, abs=1e-12)
    assert el[i] == pytest.approx(spec.elevation, abs=1e-12)
    assert np.min(az) == pytest.approx(spec.azimuth - spec.width, abs=1e-12)
    assert np.sum(np.hypot(az - spec.azimuth, el - spec.elevation) < 1e-12) == 2
    # up at the sides: just after the right end the path climbs (flown order)
    assert el[(i + 1) % len(el)] > el[i]
    circle = dataclasses.replace(spec, shape="circle", direction="positive")
    az, el = path_angles(circle)
    cos_d = (math.sin(spec.elevation) * np.sin(el)
             + math.cos(spec.elevation) * np.cos(el) * np.cos(az - spec.azimuth))
    np.testing.assert_allclose(np.arccos(np.clip(cos_d, -1, 1)), spec.height, atol=1e-9)


@pytest.mark.parametrize("change, field", [
    (dict(path=dict(elevation=math.radians(88.0))), "path.elevation_deg"),
    (dict(path=dict(width=math.radians(95.0))), "path.width_deg"),
    (dict(path=dict(elevation=math.radians(2.0), height=math.radians(0.5))), "path.elevation_deg"),
    (dict(winch=dict(max_tension=6.0e5)), "winch.max_tension"),
    (dict(winch=dict(reel_in_speed=20.0)), "winch.reel_in_speed"),
])
def test_bad_configs_are_refused_naming_the_field(change, field):
    """A path out of the wind window (elevation over 90 deg, azimuth over 90 deg), a path whose lowest point on the
    300 m tether is below the 10 m minimum altitude, a tension set-point over the 525 kN breaking load, a reel-in
    faster than the winch's 16.7 m/s."""
    cfg = load_crosswind_config()
    parts = {k: dataclasses.replace(getattr(cfg, k), **v) for k, v in change.items()}
    with pytest.raises(ConfigError, match=field):
        check_against_scene(dataclasses.replace(cfg, **parts), 300.0, 5.25e5, 10.0, (-16.7, 10.0))


def test_a_reel_length_the_drum_does_not_hold_is_refused(tmp_path):
    """PumpingKite-v1's drum holds Delta L + 2 overruns = 240 m (envs/pumping/task.py ``max_paid_out``); a 250 m
    reel-out built and then stayed in reel-out for good, the winch stopped at the full drum (review of 2026-12-07)."""
    text = load_crosswind_config().file.read_text()
    assert "reel_length: 200.0" in text
    long = tmp_path / "long.yaml"
    long.write_text(text.replace("reel_length: 200.0", "reel_length: 250.0", 1))
    task = PumpingTask(1, episode_time=10.0)
    assert task.max_paid_out == 240.0
    with pytest.raises(ConfigError, match=r"long.yaml: field 'phases.reel_length' = 250: the drum holds 240 m"):
        make_controller(f"crosswind:{long}", "laddermill_gym/PumpingKite-v1")


def test_bad_yaml_names_file_field_and_value(tmp_path):
    text = (load_crosswind_config().file.read_text()).replace("shape: figure_eight", "shape: spiral")
    bad = tmp_path / "bad.yaml"
    bad.write_text(text)
    with pytest.raises(ConfigError, match=r"bad.yaml.*path.shape.*spiral"):
        load_crosswind_config(bad)


def test_reel_out_flies_figure_eights_under_loyds_bound():
    """60 s of reel-out from the trim: the wing crosses the wind both ways (azimuth beyond +-15 deg), stays in the
    reel-out phase, and its mean mechanical power at the drum is over 10 times the static cycle's (1.9 kW,
    docs/pumping.md) but below Loyd's crosswind bound (4/27) 1/2 rho S C_L (C_L / C_D)^2 w^3 at the largest wind
    the wing met (Loyd 1980, the wing alone: no tether drag, no gravity, both of which only lower the power)."""
    task = PumpingTask(1, episode_time=100.0)
    ctl = make_controller("crosswind", ID)
    task.reset(np.ones(1, bool), [np.random.default_rng(0)])
    az, phases, mech, wind = [], [], [], []
    for _ in range(1200):
        a, _ = ctl.predict(task.obs.copy())
        _, term, _, info = task.step(a)
        assert not term[0], task.failure_text(0, int(info["failure"][0]))
        o = task.raw_obs[0]
        p = task.nominal[0] + o[:3]
        az.append(math.atan2(p[1], -p[0]))
        phases.append(int(ctl.last_phase[0]))
        mech.append(info["mechanical_power_W"][0])
        wind.append(o[-1])
    assert set(phases) == {REEL_OUT}, [PHASE_NAMES[k] for k in set(phases)]
    late = np.array(az[400:])
    assert late.min() < -math.radians(15) and late.max() > math.radians(15)
    coef = table_spline(task.scene.assembly.wing(0).aero)(math.radians(8.0))
    cl, cd = float(coef[AERO_INDEX["CL"]]), float(coef[AERO_INDEX["CD"]])
    wing = task.scene.assembly.wing(0)
    loyd = 4 / 27 * 0.5 * task.scene.assembly.wind.rho0 * wing.area * cl * (cl / cd) ** 2 * max(wind) ** 3
    mean = float(np.mean(mech[400:]))
    assert 10 * 1.9e3 < mean < loyd, (mean, loyd)


def test_cycle_figures_from_a_record(tmp_path):
    """The study's angles of recorded positions agree with the wind-window read-outs (two implementations), and
    the three figures are written."""
    from laddermill_gym.studies.pumping.cycle_figures import cycle_figures, window_angles

    rng = np.random.default_rng(1)
    p = rng.normal(size=(50, 3)) * [100, 100, 50] + [-300, 0, -200]
    rec = {"x": p[:, 0], "y": p[:, 1], "z": p[:, 2], "t": np.arange(50) * 0.05, "phase": np.repeat([0, 1, 2, 3, 0], 10),
           "tension": np.ones(50), "v": np.zeros(50), "e_el": np.zeros(50)}
    az, el = window_angles(rec)
    ww = wind_window(p, np.zeros_like(p), np.repeat(np.eye(3)[None], 50, axis=0))
    np.testing.assert_allclose(az, ww.azimuth, atol=1e-12)
    np.testing.assert_allclose(el, ww.elevation, atol=1e-12)
    paths = cycle_figures(rec, 0.05, PHASE_NAMES, 2, "test", tmp_path)
    assert [q.name for q in paths] == ["pumping_window.png", "pumping_path3d.png", "pumping_timeseries.png"]
    assert all(q.stat().st_size > 1000 for q in paths)


@pytest.mark.slow
@pytest.mark.parametrize("wind", [10.0, 12.0, 14.0])
def test_cycle_power_within_30_percent_of_schmehl_at_its_operating_point(wind):
    """Issue 29 point 3: the crosswind cycle on the reeling tether (40 m elements, configs/pumping/
    pumping_kite_reeling.yaml), its net electrical mean power (second cycle from the trim) against Schmehl / van der
    Vlugt's quasi-steady model (quasisteady/schmehl.py, an independent implementation) at the simulated cycle's own
    reel-out factor, reeled length, reel-in speed, azimuth, reel-in elevation and the wing's mass: within 30 %
    (docs/pumping.md, "Power curve"); below Lansdorp's nominal prediction; the phase shares of the difference
    (power_curve.loss_split) sum to it; the reel-out's mean mechanical power below Loyd's crosswind bound
    (4/27) 1/2 rho S C_L (C_L / C_D)^2 w^3 at the cycle's reel-out wind and alpha (Loyd 1980)."""
    from laddermill_gym.studies.pumping.power_curve import curve_point

    r = curve_point(wind, reel_element_length=40.0)
    assert not r["failed"], r["failed"]
    assert 0.7 <= r["power"] / r["schmehl_matched_W"] <= 1.3, r["power"] / r["schmehl_matched_W"]
    assert r["power"] < r["lansdorp_W"]
    shares = sum(v for k, v in r.items() if k.startswith("loss_"))
    assert shares == pytest.approx(r["schmehl_matched_W"] - r["power"], rel=1e-9)
    loyd = 4 / 27 * 0.5 * r["rho"] * r["wing_area_m2"] * r["cl"] * (r["cl"] / r["cd"]) ** 2 * r["wind"] ** 3
    assert r["e_out"] / r["t_out"] < loyd, (r["e_out"] / r["t_out"], loyd)


def test_power_curve_exit_status_tells_a_failure_from_a_wind_without_trim(tmp_path, monkeypatch):
    """A wind too weak for the static start is a physical limit, reported and drawn (exit 0: the docs' picture
    command runs the default winds 4-20 m/s, and 4 and 6 m/s have no trim); a cycle that fails exits 1."""
    import json

    from laddermill_gym.studies.pumping import power_curve

    assert power_curve.main(["--winds", "4", "--out", str(tmp_path)]) == 0
    (row,) = json.loads((tmp_path / "pumping_power_curve.json").read_text())
    assert row["failed"].startswith("no trim") and (tmp_path / "pumping_power_curve.png").is_file()
    keys = ("power", "schmehl_matched_W", "lansdorp_W", "schmehl_W", "tension_out", "schmehl_matched_tension_N")
    failed = {"v0": 9.0, "failed": "t = 12.00 s: ground contact", **{k: math.nan for k in keys}}
    monkeypatch.setattr(power_curve, "curve_point", lambda wind, length=None: failed)
    assert power_curve.main(["--winds", "9"]) == 1


def test_reel_out_winch_command_is_loyds_fraction_of_the_along_tether_wind():
    """The reel-out's winch law (Loyd 1980's optimum; Lansdorp et al. 2008 section V): the commanded speed is f = 1/3
    of the wind along the tether at the wing, that wind written here from the scene file's numbers (Meijaard et al.
    1999 eq. 1 above the boundary layer, v0 + v1 (h - h0), blowing along -x) and the wing's observed position, plus
    the overload term (overload_gain per N of drum tension above max_tension; zero below it), the gains read from the
    controller's YAML file. 20 s of reel-out from the trim: the wing crosses the wind, so the wind along the tether
    and the command change by more than a third."""
    task = PumpingTask(1, episode_time=100.0, disturbances=[])  # the steady wind (no direction step)
    ctl = make_controller("crosswind", ID)
    law = yaml.safe_load(ctl.config.file.read_text())["winch"]
    assert law["reel_out_factor"] == pytest.approx(1 / 3)
    wind, winch = task.scene.assembly.wind, task.scene.assembly.fixed_points[0]
    task.reset(np.ones(1, bool), [np.random.default_rng(0)])
    commanded, expected = [], []
    for _ in range(400):
        o = task.raw_obs[0]
        r = task.nominal[0] + o[:3] - winch
        h = -(task.nominal[0][2] + o[2])
        assert h > wind.h0
        along = (wind.v0 + wind.v1 * (h - wind.h0)) * -r[0] / np.linalg.norm(r)
        over = max(o[WINCH_OBS_INDEX["drum_tension"]] - law["max_tension"], 0.0)
        expected.append(law["reel_out_factor"] * max(along, 0.0) + law["overload_gain"] * over)
        a, _ = ctl.predict(task.obs.copy())
        assert ctl.last_phase[0] == REEL_OUT
        commanded.append(float(task.actions.controls(a)[0, 3]))
        _, term, _, info = task.step(a)
        assert not term[0], task.failure_text(0, int(info["failure"][0]))
    expected = np.array(expected)
    assert expected.max() - expected.min() > expected.mean() / 3  # the law is exercised over a range of winds
    np.testing.assert_allclose(commanded, expected, rtol=0, atol=2e-5)
