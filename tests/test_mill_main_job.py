"""The main job's pieces (issue 12, section 5): the cable drawn in the shape plot, the generator plot, the loop
animation, ``laddermill simulate`` on the moving mill.

Oracles: the element end points recomputed here from the quaternion state with the numpy reference's element
kinematics (``reference``), the GIF's frame count read back with Pillow, and the generator
energy's mean against the recorded power samples.
"""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from laddermill_gym import load_scene
from laddermill_gym.cli import main as cli_main
from laddermill_gym.plotting import cable_segments
from laddermill_gym.reference.cable import end_kinematics
from laddermill_gym.sim.recording import record


@pytest.fixture(scope="module")
def mill_record():
    scene = load_scene("laddermill", n_wings=11, dt=0.0125)  # the step counts below are at 12.5 ms
    sim = scene.simulator()
    sim.step(n_steps=800)  # 10 s: the cable moving, wings pitched
    return scene, record(sim, 3.0, 0.5, progress=False)


def test_cable_segments_are_the_element_end_points(mill_record):
    scene, rec = mill_record
    sim = scene.simulator()
    a = scene.assembly
    seg = cable_segments(a, rec.views["wing_position_m"][-1], rec.views["wing_euler_rad"][-1],
                         rec.views["node_position_m"][-1])
    # the same sample again from the simulator's state (quaternions), ends by the reference kinematics
    sim.step(n_steps=800 + 3 * 80)
    x = sim.state[:a.body_state_size]
    for e in range(a.elements.count):
        for end in (0, 1):
            p, _, _ = end_kinematics(a, e, end, x)
            np.testing.assert_allclose(seg[e, end], p, rtol=0, atol=1e-6)
    # consecutive elements share their ends: one unbroken cable from ground point to ground point
    np.testing.assert_allclose(seg[1:, 0], seg[:-1, 1], rtol=0, atol=1e-9)


def test_mill_plots_and_animation(mill_record, tmp_path):
    from laddermill_gym.animation import animate_loop
    from laddermill_gym.plotting import plot_generator, plot_shape

    scene, rec = mill_record
    shape = plot_shape(rec, tmp_path / "shape.png", "mill", asm=scene.assembly)
    gen = plot_generator(rec, tmp_path / "gen.png", "mill")
    gif = animate_loop(rec, scene.assembly, tmp_path / "loop.gif", max_frames=5, progress=False)
    for p in (shape, gen, gif):
        assert p.is_file() and p.stat().st_size > 1000
    with Image.open(gif) as im:
        assert im.n_frames == 5


def test_recorded_power_matches_the_energy(mill_record):
    """The energy integral's mean over the record equals the trapezoidal mean of the sampled power to 2 %
    (0.5 s samples of a smooth power)."""
    _, rec = mill_record
    p = rec.views["generator_power_W"]
    e = rec.views["generator_energy_J"]
    span = rec.t[-1] - rec.t[0]
    trap = float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(rec.t)))
    assert (e[-1] - e[0]) == pytest.approx(trap, rel=2e-2)
    assert abs(trap) / span > 1e2  # the generator is doing something


def test_simulate_command_on_the_mill(tmp_path, capsys):
    assert cli_main(["simulate", "laddermill", "--n-wings", "11", "--time", "2", "--sample-dt", "0.5",
                     "--direction-step", "0.01", "--animate", "--quiet", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    for name in ("laddermill.npz", "laddermill_shape.png", "laddermill_histories.png", "laddermill_generator.png",
                 "laddermill_loop.gif"):
        assert (tmp_path / name).is_file(), out
    data = np.load(tmp_path / "laddermill.npz")
    assert data["generator_power_W"].shape == data["t_s"].shape
    assert cli_main(["simulate", "tethered_wing", "--start", "periodic", "--quiet", "--out", str(tmp_path)]) == 2
    assert "laddermill simulate: error: --start periodic needs a moving-cable scene" in capsys.readouterr().err
