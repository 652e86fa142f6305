"""Run a gust benchmark and read its scorecard: open loop against the LQR on TetheredWing-v0.

The versioned suite ``configs/benchmarks/gusts-v1.yaml`` fixes every scenario (direction and speed steps, ramps,
1-cosine gusts, IEC EOG / EDC / ECD / EWS, NTM and Dryden turbulence) and its seeds, so every controller meets the
same wind. ``run_suite`` runs them (serially here; ``workers=N`` or ``ray=...`` give the same rows), ``summarise``
gives one line per controller and scenario (share of seeds survived, medians of the metrics), and
``write_outputs`` writes the CSV, the JSON and the scorecard figure. ``laddermill gust-bench --suite gusts-v1
--env laddermill_gym/TetheredWing-v0 --controllers open_loop lqr`` is the same from the command line. Run it as
``python tutorials/gust_benchmark.py``.
"""

import math
from pathlib import Path

from laddermill_gym.studies.gusts.gust_bench import run_suite, summarise, write_outputs
from laddermill_gym.studies.gusts.gust_suite import load_suite

ENV = "laddermill_gym/TetheredWing-v0"
SCENARIOS = None  # None: all of the suite's scenarios for this env

suite = load_suite("gusts-v1")
rows = run_suite(suite, [ENV], ["open_loop", "lqr"], scenarios=SCENARIOS, progress=False)
print(f"{suite.name} (version {suite.version}): {len(rows)} episodes")
print(f"{'controller':<12}{'scenario':<22}{'survived':>9}{'max |dy| [m]':>14}{'energy ratio':>14}")
for s in summarise(rows):
    energy = "" if math.isnan(s["energy_ratio"]) else f"{s['energy_ratio']:.3f}"
    print(f"{s['controller']:<12}{s['scenario']:<22}{s['survived']:>9.2f}{s['max_lateral_m']:>14.2f}{energy:>14}")
for path in write_outputs(rows, suite, Path(".")):
    print("wrote", path)
