"""What the figures and the render views show (a review of 2026-12-07).

Before: the loop animation sized its view from the wings alone (one wing: a view 0.1 m wide, no cable, no ground
point); a constant tension gave a colour bar 1e-9 kN wide that read only an offset; the env's 3D view stayed on the
start's box while a kite reeled out of it; ``render_mode="human"`` left pyplot's interactive mode on after
``close``; an empty recording or a wing that does not exist ended in numpy's IndexError. Oracles: the scene's own
ground point and cable geometry, the recorded values, matplotlib's own state.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.animation import drawn_points
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.plotting import cable_segments, plot_histories, plot_shape, tension_norm
from laddermill_gym.sim.recording import record


@pytest.fixture(scope="module")
def wing_run():
    scene = load_scene("tethered_wing", elements_per_piece=1)
    sim = scene.simulator()
    return scene, record(sim, 0.5, 0.1, progress=False)


def test_the_animation_view_holds_the_ground_point_and_the_whole_cable(wing_run):
    scene, rec = wing_run
    asm = scene.assembly
    frames = np.arange(len(rec.t))
    points = drawn_points(rec, asm, frames)
    ground = asm.fixed_points[0]
    assert np.any(np.all(np.isclose(points, ground), axis=1))  # the tether's ground end is drawn and in view
    last = cable_segments(asm, rec.views["wing_position_m"][-1], rec.views["wing_euler_rad"][-1],
                          rec.views["node_position_m"][-1]).reshape(-1, 3)
    assert points.min(axis=0).tolist() <= last.min(axis=0).tolist()
    span = np.ptp(points[:, 0])
    assert span > 10.0  # the wing flies about 15 m downwind of its ground point; the wings alone spanned 0.1 m


def test_a_constant_tension_gets_a_readable_colour_scale():
    norm = tension_norm(np.full((3, 1), 2.24197632))
    assert norm.vmin < 2.24197632 < norm.vmax
    assert norm.vmax - norm.vmin == pytest.approx(0.02 * 2.24197632)
    varied = tension_norm(np.array([[1.0, 3.5]]))
    assert (varied.vmin, varied.vmax) == (1.0, 3.5)  # a real range is kept as it is


def test_an_empty_recording_and_a_missing_wing_are_named(wing_run, tmp_path):
    scene, rec = wing_run
    import dataclasses

    empty = dataclasses.replace(rec, t=rec.t[:0], views={k: v[:0] for k, v in rec.views.items()})
    with pytest.raises(ValueError, match="plot_shape: the recording has no samples"):
        plot_shape(empty, tmp_path / "shape.png", asm=scene.assembly)
    with pytest.raises(ValueError, match=r"plot_histories: wings \[3\] do not exist \(the recording has 1 wings"):
        plot_histories(rec, tmp_path / "h.png", wings=[3])


def test_each_copy_of_a_vector_env_keeps_its_own_view():
    """The view box and the time of the last frame were one for all copies: drawing copy 1 at the time copy 0 was
    drawn read as a reset and dropped copy 0's widened box (review of 2026-12-08). Oracle: the boxes by hand."""
    import gymnasium as gym

    import laddermill_gym  # noqa: F401
    from laddermill_gym.envs.render import SceneRenderer

    env = gym.make_vec("laddermill_gym/TetheredWing-v0", 2, vectorization_mode="vector_entry_point")
    env.reset(seed=[0, 1])
    env.step(np.zeros((2, *env.single_action_space.shape), dtype=np.float32))
    task = env.task
    view = SceneRenderer(task)
    start = tuple(c.copy() for c in view.box)
    task.batch.states[0][:3] += np.array([-500.0, 0.0, 0.0])  # copy 0's wing 500 m downwind
    view.draw(0)
    wide = tuple(c.copy() for c in view.box)
    assert wide[0][0] <= task.batch.states[0][0] - view.pad + 1e-9
    view.draw(1)  # copy 1 at the same time: its own (start) box
    assert all(np.array_equal(a, b) for a, b in zip(view.box, start, strict=True))
    task.batch.t[0] += 0.05
    task.batch.states[0][:3] -= np.array([-500.0, 0.0, 0.0])  # back inside the start's box
    view.draw(0)  # copy 0's next frame keeps its widened box (a view never narrows within an episode)
    assert all(np.array_equal(a, b) for a, b in zip(view.box, wide, strict=True))
    view.close()
    env.close()


def test_the_env_view_follows_a_body_that_leaves_it_and_human_mode_restores_pyplot():
    """Through ``draw``: a wing moved 500 m downwind widens the box to hold it; a broken-down (NaN) state draws on the
    box it has; the next episode (after a reset) starts on the start's box again."""
    import gymnasium as gym
    import matplotlib.pyplot as plt

    import laddermill_gym  # noqa: F401
    from laddermill_gym.envs.render import SceneRenderer

    env = gym.make("laddermill_gym/TetheredWing-v0", render_mode="rgb_array")
    env.reset(seed=0)
    frame = env.render()
    task = env.unwrapped.task
    view = SceneRenderer(task)
    assert view.draw().shape == frame.shape
    start = tuple(c.copy() for c in view.box)
    env.step(env.action_space.sample() * 0.0)
    task.batch.states[0][:3] += np.array([-500.0, 0.0, 0.0])  # the wing's CG 500 m downwind (x < 0)
    assert view.draw().shape == frame.shape
    assert view.box[0][0] <= task.batch.states[0][0] - view.pad + 1e-9 and np.array_equal(view.box[1], start[1])
    task.batch.t[0] += 0.05
    task.batch.states[0][:3] = np.nan  # a breakdown's state: drawn, the box kept finite
    assert view.draw().shape == frame.shape and np.all(np.isfinite(np.array(view.box)))
    env.reset(seed=0)
    view.draw()
    assert all(np.array_equal(a, b) for a, b in zip(view.box, start, strict=True))
    view.close()
    env.close()
    plt.ioff()
    human = SceneRenderer(task, interactive=True)
    assert plt.isinteractive()
    human.close()
    assert not plt.isinteractive()  # as the renderer found it


@pytest.mark.parametrize("peak, scale", [(0.06, "linear"), (40.0, "symlog")])
def test_the_lateral_figure_uses_a_log_scale_only_across_decades(peak, scale, tmp_path, monkeypatch):
    """Offsets all under 0.1 m (a held wing) on symlog's linear band gave two odd ticks (2.89257e-3, -6.0744e-2)."""
    from types import SimpleNamespace

    import laddermill_gym.plotting as plotting
    from laddermill_gym.harness.evaluate import plot_results

    seen = {}
    monkeypatch.setattr(plotting, "save_figure", lambda fig, path: seen.update(fig=fig) or path)
    t = np.linspace(0.0, 10.0, 11)
    res = SimpleNamespace(t=t, lateral_m=(peak * np.sin(t))[None, :, None], max_lateral_m=np.array([[peak]]))
    plot_results(tmp_path, {"lqr": res}, "TetheredWing-v0")
    assert seen["fig"].axes[0].get_yscale() == scale
