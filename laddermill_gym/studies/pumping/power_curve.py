"""Power curve of the crosswind pumping cycle against the quasi-steady models (issue 29 point 3): for each wind
speed v0 (the scene's speed at its h0 = 50 m) the crosswind controller (``control/crosswind.py``) flies
``PumpingKite-v0``'s task (steady wind after the 0.01 rad direction step at 1 s) from the trim until two reel-ins
have ended; the second (complete) cycle's net electrical mean power is set beside Lansdorp's eqs. 1-14, Schmehl's
model at the config's nominal parameters and Schmehl's model at the cycle's own operating point
(``pumping_cycle.quasi_steady``). A run that fails, or a wind too weak for the static start (the trim), is
reported with its reason (power NaN).

Run: ``python -m laddermill_gym.studies.pumping.power_curve [--winds 4 6 ... 20] [--out results/pumping_power]``.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.control.crosswind import CrosswindController
from laddermill_gym.control.lqr import DEFAULT_CONFIG
from laddermill_gym.control.pumping_cycle import lateral_lqr
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.studies.pumping.pumping_cycle import cycle_stats, quasi_steady, run_cycles

__all__ = ["curve_point", "main"]

_KEYS = ("power", "schmehl_matched_W", "lansdorp_W", "schmehl_W", "tension_out", "schmehl_matched_tension_N")


def curve_point(wind: float) -> dict:
    """The complete cycle's figures at scene wind ``wind`` [m/s] (the second cycle from the trim)."""
    try:
        task = PumpingTask(1, episode_time=3000.0, scene_options={"overrides": {"wind": {"v0": float(wind)}}})
    except ConfigError as err:  # no static start: the wing cannot lift its tether at this wind
        return {"v0": wind, "failed": f"no trim: {str(err)[-160:]}", **{k: math.nan for k in _KEYS}}
    ctl = CrosswindController(task, lateral_lqr(task, DEFAULT_CONFIG))
    try:
        rec = run_cycles(task, ctl, 2, progress=False)
    except RuntimeError as err:
        return {"v0": wind, "failed": str(err), **{k: math.nan for k in _KEYS}}
    stats = cycle_stats(rec, task.control_dt)
    if not stats:
        return {"v0": wind, "failed": "no complete cycle in 3000 s", **{k: math.nan for k in _KEYS}}
    c = stats[-1]
    return {"v0": wind, "failed": "", **c, **quasi_steady(c, task)}


def _figure(rows: list[dict], out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    v = [r["v0"] for r in rows]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for key, label, style in (("power", "simulated (crosswind controller)", "ko-"),
                              ("schmehl_matched_W", "Schmehl at the simulated operating point", "bs--"),
                              ("schmehl_W", "Schmehl, nominal", "c^:"), ("lansdorp_W", "Lansdorp eqs. 1-14", "r.:")):
        ax.plot(v, [r[key] / 1e3 for r in rows], style, label=label)
    ax.set_xlabel("wind speed v0 at 50 m [m/s]")
    ax.set_ylabel("net electrical mean power of a cycle [kW]")
    ax.set_title("PumpingKite: crosswind cycle against the quasi-steady models")
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = out / "pumping_power_curve.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.pumping.power_curve", description=__doc__)
    p.add_argument("--winds", type=float, nargs="+", default=[4, 6, 8, 10, 12, 14, 16, 18, 20],
                   help="[m/s] scene wind speeds v0 at 50 m")
    p.add_argument("--out", type=Path, default=None, help="folder for pumping_power_curve.json and .png")
    args = p.parse_args(argv)
    if any(not (0 < w <= 60) for w in args.winds):
        p.error(f"--winds = {args.winds}: each must be in (0, 60] m/s")
    rows = [curve_point(w) for w in tqdm(args.winds, unit="wind")]
    print(f"{'v0 m/s':>6} {'sim W':>8} {'matched W':>9} {'sim/matched':>11} {'Schmehl W':>10} {'Lansdorp W':>11} "
          f"{'T_out N':>8} {'matched T_out N':>15}  failure")
    for r in rows:
        print(f"{r['v0']:6.1f} {r['power']:8.0f} {r['schmehl_matched_W']:9.0f} "
              f"{r['power'] / r['schmehl_matched_W']:11.2f} {r['schmehl_W']:10.0f} {r['lansdorp_W']:11.0f} "
              f"{r['tension_out']:8.0f} {r['schmehl_matched_tension_N']:15.0f}  {r['failed'][:90]}")
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "pumping_power_curve.json").write_text(json.dumps(rows, indent=1, default=float))
        print(args.out / "pumping_power_curve.json")
        print(_figure(rows, args.out))
    return 0 if all(np.isfinite(r["power"]) for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
