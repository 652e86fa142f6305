"""The main job's command (``laddermill demo``, laddermill_gym/studies/mill/control_demo.py) on an 11-wing mill.

Oracles: the time axis is arithmetic (control periods counted from the start, less the step time); the CSV holds
exactly the series the runs recorded; the GIF puts the runs' frames side by side (width = runs x frame width); a
run's end is the env's own termination (its failure name and reason), and the top view's wings are the state's.
"""

import csv
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from laddermill_gym.envs.task import FAILURES
from laddermill_gym.studies.mill import control_demo as demo

SMALL = dict(scene_options={"n_wings": 11}, settle={"max_time": 100.0})  # as tests/env_cases.py's mill


@pytest.fixture(scope="module")
def runs():
    return demo.run_demo(controllers=("open_loop", "lqr"), duration=2.0, env_kwargs=SMALL, progress=False)


def test_runs_start_at_the_operating_point_and_count_time_from_the_step(runs):
    dt = 0.05  # the mill ids' control period [s]
    for r in runs:
        k = np.arange(1, len(r.t_s) + 1)
        assert np.allclose(r.t_s, k * dt - demo.STEP_TIME, atol=1e-9)
        assert r.positions.shape == (11, 3) and np.all(np.isfinite(r.positions))
        assert r.outcome == "ran to the end" or any(r.outcome.startswith(f"{name}: t = ")
                                                    for name in FAILURES.values() if name)
        if r.outcome == "ran to the end":
            assert r.t_s[-1] == pytest.approx(2.0)
    # before the step every controller flies the same trim from the same state: the same power to rounding
    before = [r.power_W[r.t_s < 0.0] for r in runs]
    assert before[0].size == 19 and np.allclose(before[0], before[1], rtol=1e-6)


def test_outputs_hold_the_recorded_series(runs, tmp_path):
    png = demo.plot_demo(runs, tmp_path / "demo.png", "test")
    gif = demo.write_gif(runs, tmp_path / "demo.gif")
    path = demo.write_csv(runs, tmp_path / "demo.csv")
    assert png.stat().st_size > 10_000
    with Image.open(gif) as im:
        h, w = runs[0].frames[0].shape[:2]
        assert im.size == (2 * w, h + demo.LABEL_BAND_PX) and im.n_frames == max(len(r.frames) for r in runs)
        band = np.asarray(im.convert("RGB"))[:demo.LABEL_BAND_PX]
        for k in range(2):  # each panel's band holds its controller's name: dark text on white
            panel = band[:, k * w:(k + 1) * w]
            assert (panel < 100).any() and (panel > 200).mean() > 0.5
    rows = list(csv.DictReader(Path(path).read_text().splitlines()))
    for r in runs:
        mine = [x for x in rows if x["controller"] == r.label]
        assert len(mine) == len(r.t_s)
        assert np.allclose([float(x["power_W"]) for x in mine], r.power_W, rtol=1e-5)
        assert np.allclose([float(x["max_lateral_m"]) for x in mine], r.lateral_m, rtol=1e-5, atol=1e-9)


def test_the_default_set_flies_the_shipped_policy_of_the_env():
    assert demo.default_controllers("laddermill_gym/LadderMill-v1") == ["open_loop", "lqr", "ppo_mill"]
    assert demo.default_controllers("laddermill_gym/LadderMill-v0") == ["open_loop", "lqr"]


@pytest.mark.parametrize("argv, message", [
    (["--time", "12.34"], "--time = 12.34: the step at 1 s plus it must be a whole number of control periods (0.05 s)"),
    (["--env", "laddermill_gym/TetheredWing-v1"], "--env 'laddermill_gym/TetheredWing-v1': not a mill id"),
])
def test_bad_arguments_are_refused_before_any_run(argv, message, capsys):
    with pytest.raises(SystemExit):
        demo.main(argv)
    assert message in capsys.readouterr().err
