"""Honest failure flags: a wing outside the range where its aerodynamic data are accurate is flagged per wing and
sample in the recording, and a blow-up stops the run with a report naming the time, the body and the quantity,
with the data so far saved.

Oracles: in still vacuum without gravity a free wing keeps its body velocity (u, v, w) = V (cos a cos b, sin b,
sin a cos b), so its angle of attack is a and its sideslip b; spinning at a steady pitch rate q about its largest
principal axis, its angle of attack grows as a + q t. A body released at rest under gravity reaches the speed
v_max at t = v_max / g.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from laddermill_gym.cli import main as cli_main
from laddermill_gym.kernels.contract import B2_SIZE, B2_U, B2_W, B2_Z, B3_POS, B3_QUAT, B3_RATE, B3_SIZE, B3_VEL
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.params import WindParams
from laddermill_gym.sim.recording import ALPHA_RANGE_DEG, MAX_ABS_BETA_DEG, record
from laddermill_gym.sim.simulator import IntegratorSettings, SimulationError, Simulator
from tests.conftest import G0, free_body_assembly, make_wing_type

STILL_VACUUM = WindParams(v0=0.0, v1=0.0, rho0=0.0)
SPEED = 20.0  # [m/s]


def flying_wings(angles_deg, dim: int = 3, gravity: float = 0.0, rate: float = 0.0, settings=None,
                 speed: float = SPEED) -> Simulator:
    """Free wings 100 m up in still vacuum with body velocities of ``speed`` [m/s] at the given (alpha, beta) [deg]
    and pitch rate [rad/s]; inertia (1, 3, 2): the pitch axis is the largest, a steady spin about it is stable."""
    wt = make_wing_type(inertia=(1.0, 3.0, 2.0, 0.0))
    asm = dataclasses.replace(free_body_assembly(wt, gravity=gravity, wind=STILL_VACUUM), dim=dim,
                              wing_type_index=np.zeros(len(angles_deg), dtype=np.int64))
    x = np.zeros(asm.state_size)
    for k, (a, b) in enumerate(np.radians(angles_deg)):
        u, v, w = speed * math.cos(a) * math.cos(b), speed * math.sin(b), speed * math.sin(a) * math.cos(b)
        if dim == 3:
            o = B3_SIZE * k
            x[o + B3_POS + 2], x[o + B3_QUAT] = -100.0, 1.0
            x[o + B3_VEL: o + B3_VEL + 3] = u, v, w
            x[o + B3_RATE + 1] = rate
        else:
            o = B2_SIZE * k
            x[o + B2_Z], x[o + B2_U], x[o + B2_W] = -100.0, u, w
    return Simulator(asm, x, settings or IntegratorSettings(dt=0.01))


@pytest.mark.parametrize("alpha, beta, out", [
    (17.5, 0.0, False), (18.5, 0.0, True), (-13.5, 0.0, False), (-14.5, 0.0, True),
    (5.0, 20.5, False), (5.0, -21.5, True), (170.0, 0.0, True), (0.0, 0.0, False),
])
def test_flag_of_a_constructed_state_against_the_documented_band(alpha, beta, out):
    rec = record(flying_wings([(alpha, beta)]), 0.5, 0.1, progress=False)
    np.testing.assert_allclose(np.degrees(rec.views["wing_alpha_rad"][:, 0]), alpha, atol=1e-9)
    np.testing.assert_allclose(np.degrees(rec.views["wing_beta_rad"][:, 0]), beta, atol=1e-9)
    flags = rec.views["aero_out_of_range"]
    assert flags.shape == (len(rec.t), 1) and flags.dtype == bool
    assert np.all(flags == out)


def test_documented_band_is_the_wing_data_stall_band():
    """wing_data.md: wing stall -16 / +18 deg, tail plane from about -14 deg, fins at +-21 deg."""
    assert ALPHA_RANGE_DEG == (-14.0, 18.0) and MAX_ABS_BETA_DEG == 21.0


def test_flags_per_wing_and_the_band_as_arguments():
    sim = flying_wings([(5.0, 0.0), (25.0, 0.0), (10.0, 0.0)])
    rec = record(sim, 0.3, 0.1, progress=False)
    np.testing.assert_array_equal(rec.views["aero_out_of_range"], np.tile([False, True, False], (len(rec.t), 1)))
    sim.reset()
    narrow = record(sim, 0.3, 0.1, progress=False, alpha_range_deg=(-5.0, 8.0), max_abs_beta_deg=1.0)
    np.testing.assert_array_equal(narrow.views["aero_out_of_range"], np.tile([False, True, True], (len(rec.t), 1)))
    with pytest.raises(ValueError, match="alpha_range_deg"):
        record(sim, 0.3, 0.1, progress=False, alpha_range_deg=(10.0, -10.0))


def test_flag_in_plane():
    rec = record(flying_wings([(12.0, 0.0), (-20.0, 0.0)], dim=2), 0.2, 0.1, progress=False)
    np.testing.assert_array_equal(rec.views["aero_out_of_range"], np.tile([False, True], (len(rec.t), 1)))


def test_flag_switches_on_when_the_pitching_wing_leaves_the_band():
    """alpha = 10 deg + q t with q = 0.2 rad/s crosses 18 deg at t = 0.698 s."""
    q, a0 = 0.2, 10.0
    rec = record(flying_wings([(a0, 0.0)], rate=q), 1.5, 0.05, progress=False)
    alpha = a0 + np.degrees(q * rec.t)
    np.testing.assert_allclose(np.degrees(rec.views["wing_alpha_rad"][:, 0]), alpha, atol=1e-6)
    assert np.min(np.abs(alpha - 18.0)) > 1e-3
    np.testing.assert_array_equal(rec.views["aero_out_of_range"][:, 0], alpha > 18.0)
    assert 0 < np.count_nonzero(alpha > 18.0) < len(rec.t)


def test_a_body_without_aerodynamic_tables_is_never_flagged():
    from laddermill_gym.rotorcraft.craft import load_craft

    sim = load_craft().simulator()
    rec = record(sim, 0.1, 0.05, progress=False)
    assert rec.error is None
    assert abs(np.degrees(rec.views["wing_alpha_rad"][0, 0])) > 18.0  # the craft flies at a rotor incidence
    assert not rec.views["aero_out_of_range"].any()


LIMIT_REPORT = re.compile(r"integration failed at t = ([\d.e+-]+) s \(speed or rate limit exceeded\); in the step "
                          r"to t = ([\d.e+-]+) s: (wing|node) (\d+) speed ([\d.e+-]+) m/s > 5 m/s")


def test_speed_limit_report_names_time_body_and_quantity():
    """Released at rest under gravity, the wing passes 5 m/s at t = 5/g = 0.5099 s: in the step to 0.51 s."""
    dt = 0.01
    settings = IntegratorSettings(dt=dt, max_speed=5.0, ground_contact="off")
    sim = flying_wings([(0.0, 0.0)], gravity=G0, settings=settings, speed=0.0)
    with pytest.raises(SimulationError) as err:
        sim.step(n_steps=100)
    n = math.ceil(5.0 / G0 / dt)
    m = LIMIT_REPORT.search(str(err.value))
    assert m, str(err.value)
    assert float(m.group(1)) == pytest.approx((n - 1) * dt) and float(m.group(2)) == pytest.approx(n * dt)
    assert (m.group(3), m.group(4)) == ("wing", "0")
    assert float(m.group(5)) == pytest.approx(G0 * n * dt, rel=1e-3)
    assert sim.t == pytest.approx((n - 1) * dt)
    assert np.linalg.norm(sim.wing_velocities()[0]) == pytest.approx(G0 * sim.t, rel=1e-9) and G0 * sim.t < 5.0


def test_blow_up_is_recorded_and_saved_with_its_report(tmp_path):
    """A 25 ms step on the stiff tether (stable up to 19 ms) makes RK4 explode (test_bad_input): the record ends at the
    last good state with the report, and both files hold the data so far."""
    sim = load_scene("tethered_wing", dt=0.025).simulator()
    rec = record(sim, 20.0, 0.025, progress=False)
    assert rec.error and rec.t[-1] < 20.0 and rec.t[-1] == pytest.approx(sim.t)
    m = re.search(r"integration failed at t = ([\d.e+-]+) s \((.+?)\); in the step to t = ([\d.e+-]+) s: "
                  r"(wing|node) (\d+) (speed|angular rate) ([\d.e+-]+)", rec.error)
    assert m, rec.error
    assert float(m.group(1)) == pytest.approx(rec.t[-1]) and float(m.group(3)) == pytest.approx(rec.t[-1] + 0.025)
    assert float(m.group(7)) > 100.0
    for views in rec.views.values():
        assert len(views) == len(rec.t) and np.all(np.isfinite(views))
    data = np.load(rec.save_npz(tmp_path / "run.npz"))
    assert str(data["error"]) == rec.error
    np.testing.assert_array_equal(data["t_s"], rec.t)
    np.testing.assert_array_equal(data["aero_out_of_range"], rec.views["aero_out_of_range"])
    rows = (rec.save_csv(tmp_path / "run.csv")).read_text().splitlines()
    assert len(rows) == len(rec.t) + 1 and "aero_out_of_range[0]" in rows[0]


def test_cli_writes_what_it_has_and_prints_the_report(tmp_path, capsys):
    args = ["simulate", "tethered_wing", "--dt", "0.025", "--time", "20", "--out", str(tmp_path), "--quiet", "--csv"]
    assert cli_main(args) == 3  # a breakdown exits non-zero, outputs written
    out = capsys.readouterr().out
    assert re.search(r"run stopped early: integration failed at t = [\d.]+ s .*(wing|node) \d+ (speed|angular rate)",
                     out), out
    for name in ("tethered_wing.npz", "tethered_wing.csv", "tethered_wing_shape.png", "tethered_wing_histories.png"):
        assert (tmp_path / name).is_file()
    assert cli_main([*args, "--strict"]) == 3
    assert cli_main([*args, "--allow-breakdown"]) == 0


def test_cli_gives_a_breakdown_time_from_the_runs_own_start(tmp_path, capsys, monkeypatch):
    """A run started on another clock (``--start periodic`` starts where the operating-point search ended) says when
    it broke down from its own start: the same breakdown as from t = 0, shifted by the start time."""
    import laddermill_gym.cli as cli

    args = ["simulate", "tethered_wing", "--dt", "0.025", "--time", "20", "--out", str(tmp_path), "--quiet"]
    assert cli_main([*args, "--allow-breakdown"]) == 0
    t_fail = float(re.search(r"simulated ([\d.]+) s in", capsys.readouterr().out).group(1))
    start = cli.start_state

    def later(scene, a):
        x, u, _ = start(scene, a)
        return x, u, 100.0

    monkeypatch.setattr(cli, "start_state", later)
    assert cli_main([*args, "--allow-breakdown"]) == 0
    out = capsys.readouterr().out
    m = re.search(r"run stopped early: integration failed at t = ([\d.]+) s .*\(([\d.]+) s after the run's start at "
                  r"t = 100 s\)", out)
    assert m, out
    assert float(m.group(2)) == pytest.approx(t_fail, abs=0.01)
    assert float(m.group(1)) == pytest.approx(100.0 + t_fail, abs=0.1)


def test_diagnose_names_a_fast_node_and_an_overflowing_quaternion():
    """diagnose() on states the right-hand side refuses or that hold a fast node: the report names the node and
    its speed (set by hand: the oracle), and an overflowing quaternion by wing and norm, instead of raising."""
    from laddermill_gym.kernels.contract import N3_VEL
    from laddermill_gym.sim.reports import diagnose

    sim = load_scene("tethered_wing").simulator()
    a = sim.assembly
    assert a.n_nodes == 1  # the cable's free node between the two elements
    x = sim.state.copy()
    o = a.n_wings * a.wing_state_size + N3_VEL
    x[o: o + 3] = (0.0, 120.0, 50.0)  # node 0 at 130 m/s
    sim.state = x
    assert "fastest node 0: speed 130 m/s" in diagnose(sim)
    x = sim.initial_state.copy()
    x[3:7] *= 1e160
    sim.state = x
    assert "wing 0 quaternion norm 1e+160" in diagnose(sim)
