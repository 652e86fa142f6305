"""Ground contact: a wing or free cable node reaching the ground height stops the run with a report (``stop``),
is flagged in the recording (``flag``) or ignored (``off``).

Oracle: a body released at rest at height H in vacuum falls freely, h(t) = H - g t^2 / 2 (RK4 integrates this
quadratic exactly, up to rounding), so it reaches the ground height h_g at t_c = sqrt(2 (H - h_g) / g): the
first RK4 step at or after t_c is the contact, the state before it the last one kept. A free cable node between
slack massless elements (sag off: no tension below the unstretched length) falls the same way.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pytest

from laddermill_gym.cli import main as cli_main
from laddermill_gym.kernels.contract import (
    B2_SIZE,
    B2_Z,
    B3_POS,
    B3_QUAT,
    B3_SIZE,
    GROUND,
    N2_POS,
    N2_SIZE,
    N3_POS,
    N3_SIZE,
    N3_VEL,
    OK,
)
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.builders import build_cable
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.params import WindParams
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.recording import record
from laddermill_gym.sim.simulator import IntegratorSettings, SimulationError, Simulator
from tests.conftest import G0, cable_spec, free_body_assembly, make_wing_type

DT = 0.01  # [s]
STILL_VACUUM = WindParams(v0=0.0, v1=0.0, rho0=0.0)
REPORT = re.compile(r"ground contact at t = ([-\d.e+]+) s: (wing|node) (\d+) at height ([-\d.e+]+) m")


def falling_wings(dim: int, heights):
    """(Assembly, state): free wings (no cable) at rest at the given heights [m] in still vacuum under gravity."""
    asm = dataclasses.replace(free_body_assembly(make_wing_type(), gravity=G0, wind=STILL_VACUUM), dim=dim,
                              wing_type_index=np.zeros(len(heights), dtype=np.int64))
    x = np.zeros(asm.state_size)
    for k, h in enumerate(heights):
        if dim == 3:
            x[B3_SIZE * k + B3_POS + 2] = -h
            x[B3_SIZE * k + B3_QUAT] = 1.0
        else:
            x[B2_SIZE * k + B2_Z] = -h
    return asm, x


def falling_node(dim: int, height: float, settings: IntegratorSettings) -> Simulator:
    """A 1 kg free node between two massless 5 m elements whose ends are at the node's start: slack while it
    falls less than 5 m. (With massive elements the consistent mass matrix would make it fall at 1.5 g.)"""
    asm = build_cable([0.0, 0.0, -height], [0.0, 0.0, -height], 10.0, 2, cable_spec(0.0, 1e5), sag=False,
                      gravity=G0, dim=dim, node_mass=1.0)
    x = np.zeros(asm.state_size)
    x[N3_POS + 2 if dim == 3 else N2_POS + 1] = -height
    assert asm.n_wings == 0 and asm.n_nodes == 1 and asm.state_size == (N3_SIZE if dim == 3 else N2_SIZE)
    return Simulator(asm, x, settings)


def contact_step(height: float, ground: float) -> int:
    """Index of the first RK4 step at or after the closed-form contact time."""
    t_c = math.sqrt(2.0 * (height - ground) / G0)
    n = math.ceil(t_c / DT)
    assert (n - 1) * DT < t_c <= n * DT and abs(t_c / DT - round(t_c / DT)) > 0.01, "choose a time off the grid"
    return n


def free_fall_height(height: float, t: float) -> float:
    return height - 0.5 * G0 * t * t


@pytest.mark.parametrize("dim", [3, 2])
@pytest.mark.parametrize("body", ["wing", "node"])
def test_stop_at_the_closed_form_time_with_a_report(dim, body):
    H, hg = 10.0, 9.0 if body == "node" else 2.5
    settings = IntegratorSettings(dt=DT, ground_height=hg)
    sim = falling_node(dim, H, settings) if body == "node" else Simulator(*falling_wings(dim, [H]), settings)
    n = contact_step(H, hg)
    with pytest.raises(SimulationError) as err:
        sim.step(n_steps=10 * n)
    assert sim.t == pytest.approx((n - 1) * DT, abs=1e-9), "the state is kept at the last step before the contact"
    h_wing, h_node = sim.body_heights()
    h_kept = (h_node if body == "node" else h_wing)[0]
    assert h_kept > hg
    assert h_kept == pytest.approx(free_fall_height(H, sim.t), abs=1e-9)
    m = REPORT.search(str(err.value))
    assert m, str(err.value)
    assert float(m.group(1)) == pytest.approx(n * DT, abs=1e-9)
    assert (m.group(2), int(m.group(3))) == (body, 0)
    assert float(m.group(4)) == pytest.approx(free_fall_height(H, n * DT), rel=1e-3, abs=1e-4)
    assert float(m.group(4)) <= hg
    assert f"ground height {hg:g} m" in str(err.value)
    # the depth below a ground above 0, from the closed-form fall (the review of 2026-12-07: a height rounded to four
    # digits could read above the ground)
    depth = re.search(r"at height [-0-9.e+]+ m \(([-0-9.e+]+) m from the ground\)", str(err.value))
    assert depth, str(err.value)
    assert float(depth.group(1)) == pytest.approx(free_fall_height(H, n * DT) - hg, rel=1e-2, abs=1e-6)
    assert float(depth.group(1)) <= 0.0


def test_a_ground_at_zero_reports_the_height_alone():
    """At a ground height of 0 the height is the depth: the report gives it at four digits, without a separate
    depth (0bb72da; a review of 2026-12-07 found its test covered only a ground above 0)."""
    H = 10.0
    sim = Simulator(*falling_wings(3, [H]), IntegratorSettings(dt=DT, ground_height=0.0))
    n = contact_step(H, 0.0)
    with pytest.raises(SimulationError) as err:
        sim.step(n_steps=10 * n)
    text = str(err.value)
    m = REPORT.search(text)
    assert m and "from the ground" not in text and "ground height 0 m" in text, text
    assert float(m.group(4)) == pytest.approx(free_fall_height(H, n * DT), rel=1e-3, abs=1e-4)
    assert float(m.group(4)) <= 0.0


def test_an_env_s_ground_stop_text_does_not_round_a_body_below_the_ground():
    """The envs' stop text gave the lowest body at three digits: 4.9 mm above a ground at 49.34 m read "at 49.3 m",
    below it (review of 2026-12-08). Oracle: the state's own lowest height, moved by hand."""
    from laddermill_gym.sim.reports import ground_stop_text, lowest_body

    asm = load_scene("tethered_wing").assembly
    x = load_scene("tethered_wing").simulator().state.copy()
    _, h = lowest_body(asm, x)
    ws, ns = asm.wing_state_size, asm.node_state_size
    for k in range(asm.n_wings):  # every body moved down by the same amount (z down): the lowest at 49.3449 m
        x[k * ws + B3_POS + 2] += h - 49.3449
    for j in range(asm.n_nodes):
        x[asm.n_wings * ws + j * ns + N3_POS + 2] += h - 49.3449
    name, low = lowest_body(asm, x)
    assert low == pytest.approx(49.3449, abs=1e-9)
    text = ground_stop_text(asm, x, 49.34)
    assert text.endswith(f"lowest body {name} at 49.34 m (0.0049 m above the ground)"), text
    assert ground_stop_text(asm, x, 0.0).endswith(f"lowest body {name} at 49.34 m"), text


def test_error_controlled_run_stops_in_the_step_that_reaches_the_ground():
    """DP5(4) takes steps of its own size: the contact lies in the step after the state kept, and the report's
    time and height are those of that step's end on the closed-form fall."""
    H, hg = 10.0, 2.5
    settings = IntegratorSettings(method="dp54", dt=DT, ground_height=hg)
    sim = Simulator(*falling_wings(3, [H]), settings)
    with pytest.raises(SimulationError) as err:
        sim.advance_to(5.0)
    m = REPORT.search(str(err.value))
    assert m, str(err.value)
    t_report, t_c = float(m.group(1)), math.sqrt(2.0 * (H - hg) / G0)
    assert sim.t < t_c <= t_report + 1e-6
    assert float(m.group(4)) == pytest.approx(free_fall_height(H, t_report), rel=1e-3, abs=1e-3)
    assert -sim.state[B3_POS + 2] == pytest.approx(free_fall_height(H, sim.t), abs=1e-9)


@pytest.mark.parametrize("dim", [3, 2])
def test_flag_records_the_contact_and_off_ignores_it(dim):
    H, hg = 10.0, 2.5
    n = contact_step(H, hg)
    recs = {}
    for mode in ("stop", "flag", "off"):
        settings = IntegratorSettings(dt=DT, ground_height=hg, ground_contact=mode)
        recs[mode] = record(Simulator(*falling_wings(dim, [H, 4 * H]), settings), 2 * n * DT, DT,
                            progress=False)
    flag, off, stop = recs["flag"], recs["off"], recs["stop"]
    assert flag.error is None and off.error is None and "ground contact" in stop.error
    # wing 0 reaches the ground in sample n; wing 1 (fall 37.5 m) only at t = 2.77 s, after the record
    assert flag.ground_contacts[0].body == "wing 0"
    assert flag.ground_contacts[0].t == pytest.approx(n * DT, abs=1e-9)
    assert flag.ground_contacts[0].height == pytest.approx(free_fall_height(H, n * DT), abs=1e-9)
    assert len(flag.ground_contacts) == 1
    contact = flag.views["wing_ground_contact"]
    assert contact.shape == (2 * n + 1, 2) and flag.views["node_ground_contact"].shape == (2 * n + 1, 0)
    np.testing.assert_array_equal(contact[:, 0], np.arange(2 * n + 1) >= n)
    assert not contact[:, 1].any()
    assert "wing_ground_contact" not in off.views and off.ground_contacts == []
    # the ground changes nothing in the motion: the three runs agree bit for bit while they last
    np.testing.assert_array_equal(flag.views["wing_position_m"], off.views["wing_position_m"])
    assert len(stop.t) == n and stop.t[-1] == pytest.approx((n - 1) * DT)
    np.testing.assert_array_equal(stop.views["wing_position_m"], flag.views["wing_position_m"][:n])
    assert not stop.views["wing_ground_contact"].any()


def test_batch_copy_stops_while_the_others_go_on():
    hg = 2.5
    heights = [10.0, 5.0, 40.0]  # contact at 1.24 s, 0.71 s and (after the 2 s here) 2.67 s
    settings = IntegratorSettings(dt=DT, ground_height=hg)
    asm, _ = falling_wings(3, [1.0])
    batch = BatchSimulator(asm, len(heights), settings)
    for b, h in enumerate(heights):
        batch.states[b] = falling_wings(3, [h])[1]
    status = batch.step(200)
    np.testing.assert_array_equal(status, [GROUND, GROUND, OK])
    steps = [contact_step(h, hg) - 1 for h in heights[:2]]
    np.testing.assert_array_equal(batch.done, [*steps, 200])
    np.testing.assert_allclose(batch.t, [steps[0] * DT, steps[1] * DT, 2.0], atol=1e-9)
    for b, h in enumerate(heights):
        assert -batch.states[b, B3_POS + 2] == pytest.approx(free_fall_height(h, batch.t[b]), abs=1e-9)
        assert -batch.states[b, B3_POS + 2] > hg
    np.testing.assert_array_equal(batch.failed(), [True, True, False])


def test_settings_are_validated_naming_field_and_value():
    with pytest.raises(ValueError, match=r"ground_contact = 'bounce'"):
        IntegratorSettings(ground_contact="bounce")
    with pytest.raises(ValueError, match=r"ground_height = nan"):
        IntegratorSettings(ground_height=float("nan"))
    with pytest.raises(ValueError, match=r"ground_height = '0'"):
        IntegratorSettings(ground_height="0")


def _scene_with(tmp_path, extra: str):
    """tethered_wing.yaml with its ground lines replaced by ``extra`` (paths made absolute)."""
    src = load_scene("tethered_wing").file
    text = src.read_text().replace("../wings/", "package:wings/").replace("../cables/", "package:cables/")
    text = re.sub(r"\n  ground_(height|contact):[^\n]*", "", text)
    path = tmp_path / "scene.yaml"
    path.write_text(text.replace("integrator:\n", "integrator:\n" + extra))
    return path


def test_scene_yaml_sets_the_ground_and_refuses_bad_values(tmp_path):
    sc = load_scene(_scene_with(tmp_path, "  ground_height: 12.5\n  ground_contact: flag\n"))
    assert (sc.settings.ground_height, sc.settings.ground_contact) == (12.5, "flag")
    assert load_scene("tethered_wing").settings.ground_contact == "stop"
    assert load_scene(_scene_with(tmp_path, "  ground_contact: off\n")).settings.ground_contact == "off"  # YAML false
    with pytest.raises(ConfigError, match=r"'integrator.ground_contact' = 'bounce'"):
        load_scene(_scene_with(tmp_path, "  ground_contact: bounce\n"))
    with pytest.raises(ConfigError, match=r"'integrator.ground_height' = 'low'"):
        load_scene(_scene_with(tmp_path, "  ground_height: low\n"))
    with pytest.raises(ConfigError, match=r"unknown field 'integrator.ground_heigth'"):
        load_scene(_scene_with(tmp_path, "  ground_heigth: 1.0\n"))


def test_rotorcraft_config_reads_the_ground(tmp_path):
    from laddermill_gym.rotorcraft.config import craft_path, load_craft_config

    src = craft_path("roberts_flying_model")
    text = src.read_text().replace("../rotors/", "package:rotors/").replace("../cables/", "package:cables/")
    path = tmp_path / "craft.yaml"
    path.write_text(text.replace("integrator:\n", "integrator:\n  ground_height: -3.0\n  ground_contact: off\n"))
    cfg = load_craft_config(path)
    assert (cfg.settings.ground_height, cfg.settings.ground_contact) == (-3.0, "off")
    assert load_craft_config().settings.ground_contact == "stop"


def test_default_cli_run_stops_on_the_ground_and_writes_what_it_has(tmp_path, capsys):
    """README's first command: the open-loop wing dives after the direction step; the run now ends at the first
    contact instead of flying through z = 0, prints the report and still writes its files."""
    code = cli_main(["simulate", "tethered_wing", "--time", "120", "--direction-step", "0.01", "--out",
                     str(tmp_path), "--quiet", "--csv"])
    out = capsys.readouterr().out
    assert code == 0
    m = REPORT.search(out)
    assert m and "run stopped early" in out, out
    assert float(m.group(4)) <= 0.0 and 0.0 < float(m.group(1)) < 120.0
    data = np.load(tmp_path / "tethered_wing.npz")
    assert "ground contact" in str(data["error"])
    assert data["t_s"][-1] == pytest.approx(float(m.group(1)) - 0.005, abs=1e-9)  # the last state before it
    assert np.all(-data["wing_position_m"][..., 2] > 0.0) and np.all(-data["node_position_m"][..., 2] > 0.0)
    assert (tmp_path / "tethered_wing.csv").read_text().count("\n") == len(data["t_s"]) + 1
    assert cli_main(["simulate", "tethered_wing", "--time", "120", "--direction-step", "0.01", "--out",
                     str(tmp_path), "--quiet", "--strict"]) == 1


def _failing_second_copy(task, action: np.ndarray):
    """Reset two copies of a one-body task, send copy 1's first cable node down at 5 m/s and step both one control
    period with the given action."""
    task.reset(np.ones(2, bool), [np.random.default_rng(s) for s in (0, 1)])
    task.batch.states[1, B3_SIZE + N3_VEL + 2] = 5.0  # node 0's vertical velocity; z is down
    return task.step(np.tile(action, (2, 1)))


def test_wing_env_ends_a_copy_on_the_ground_as_ground_contact(tmp_path):
    from laddermill_gym.envs.task import WingTask

    # the tether's middle node trims at 49.30 m: a ground 2 cm below it
    task = WingTask(n_copies=2, scene=str(_scene_with(tmp_path, "  ground_height: 49.28\n")))
    _, terminated, _, info = _failing_second_copy(task, task.actions.nominal_action)
    np.testing.assert_array_equal(task.batch.status, [OK, GROUND])
    np.testing.assert_array_equal(info["failure"], [0, 2])
    np.testing.assert_array_equal(terminated, [False, True])
    assert -task.batch.states[1, B3_SIZE + N3_POS + 2] > 49.28  # kept at the last state above the ground
    text = task.failure_text(1, 2)
    assert "ground contact" in text and "node 0" in text and "49.28 m" in text


def test_rotorcraft_env_ends_a_copy_on_the_ground_as_ground_contact(tmp_path):
    from laddermill_gym.envs.rotorcraft.task import CraftTask
    from laddermill_gym.rotorcraft.config import craft_path

    src = craft_path("roberts_flying_model")
    text = src.read_text().replace("../rotors/", "package:rotors/").replace("../cables/", "package:cables/")
    path = tmp_path / "craft.yaml"
    # the rear tethers' middle nodes trim at 21.50 m: a ground 5 cm below them
    path.write_text(text.replace("integrator:\n", "integrator:\n  ground_height: 21.45\n"))
    task = CraftTask(n_copies=2, craft=str(path))
    _, terminated, _, info = _failing_second_copy(task, task.trim_action)
    np.testing.assert_array_equal(task.batch.status, [OK, GROUND])
    np.testing.assert_array_equal(info["failure"], [0, 3])
    np.testing.assert_array_equal(terminated, [False, True])
    words = task.failure_text(1, 3)
    assert "ground contact" in words and "node 0" in words and "21.45 m" in words


def test_cli_ground_options(tmp_path, capsys):
    """--ground-contact flag runs the whole span and lists the contacts; --ground-height moves the ground."""
    base = ["simulate", "tethered_wing", "--time", "120", "--direction-step", "0.01", "--out", str(tmp_path), "--quiet"]
    assert cli_main([*base, "--ground-contact", "flag"]) == 0
    out = capsys.readouterr().out
    assert "run stopped early" not in out and "ground contacts flagged (the run went on): t = " in out
    data = np.load(tmp_path / "tethered_wing.npz")
    assert data["t_s"][-1] == pytest.approx(120.0) and data["wing_ground_contact"].any()
    assert cli_main([*base, "--ground-height", "40"]) == 0
    m = REPORT.search(capsys.readouterr().out)
    # the tether's middle node trims at 49 m and sinks below 40 m only in the dive after 50 s
    assert m and m.group(2) == "node" and float(m.group(4)) <= 40.0 and float(m.group(1)) > 50.0
