"""The package's figure writers leave a user's matplotlib alone: no backend switched, no pyplot figure left open.

Oracle: matplotlib's own state (``matplotlib.get_backend``, ``pyplot.get_fignums``) in a fresh process whose backend
the test sets, and the PNG signature of the files written.
"""

import json
import os
import subprocess
import sys

SCRIPT = r"""
import json, sys
from pathlib import Path
import matplotlib
import laddermill_gym.animation, laddermill_gym.plotting, laddermill_gym.quasisteady.site_outputs  # noqa: F401
from laddermill_gym.figure_files import subplots
from laddermill_gym.harness.train import plot_curve
from laddermill_gym.plotting import save_figure
from laddermill_gym.studies.gusts.gust_scorecard import plot_scorecard

out = Path(sys.argv[1])
fig, ax = subplots(1, 2, squeeze=False)
ax[0, 0].plot([0, 1], [1, 0])
written = [save_figure(fig, out / "a.png")]
written.append(plot_curve(out, [{"minutes": 0.0, "mean_return": 1.0}, {"minutes": 1.0, "mean_return": 2.0}],
                          {"LQR": 1.5}))
row = dict(survived=0.5, t_end_s=3.0, t_fail_s=3.0, energy_ratio=0.9, max_lateral_m=0.1, peak_tension_ratio=0.8)
written.append(plot_scorecard([dict(row, scenario="eog", controller="lqr")], "laddermill_gym/TetheredWing-v0",
                              "gusts-v6", out / "card.png"))
import matplotlib.pyplot as plt
fig = plt.figure()
save_figure(fig, out / "pyplot.png")
print(json.dumps({"backend": matplotlib.get_backend(), "open": plt.get_fignums(),
                  "png": [Path(p).read_bytes()[:8].hex() for p in written]}))
"""


def test_figure_writers_keep_the_users_backend_and_close_nothing_of_theirs(tmp_path):
    env = dict(os.environ, MPLBACKEND="svg", NUMBA_NUM_THREADS="1")
    run = subprocess.run([sys.executable, "-c", SCRIPT, str(tmp_path)], capture_output=True, text=True, env=env,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    got = json.loads(run.stdout.strip().splitlines()[-1])
    assert got["backend"] == "svg"  # importing or drawing switched it to Agg before
    assert got["open"] == []  # a pyplot figure handed to save_figure is closed in pyplot
    assert got["png"] == ["89504e470d0a1a0a"] * 3
