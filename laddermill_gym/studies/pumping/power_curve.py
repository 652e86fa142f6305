"""Power curve of the crosswind pumping cycle against the quasi-steady models (issue 29 point 3): for each wind
speed v0 (the scene's speed at its h0 = 50 m) the crosswind controller (``control/crosswind.py``) flies
``PumpingKite-v0``'s task (steady wind after the 0.01 rad direction step at 1 s) from the trim until two reel-ins
have ended; the second (complete) cycle's net electrical mean power is set beside Lansdorp's eqs. 1-14, Schmehl's
model at the config's nominal parameters and Schmehl's model at the cycle's own operating point
(``pumping_cycle.quasi_steady``). A run that fails, or a wind too weak for the static start (the trim), is
reported with its reason (power NaN). Exit status 1 when a wind's cycle fails; a wind without a trim is a physical
limit, not a failure (exit 0).

Run: ``python -m laddermill_gym.studies.pumping.power_curve [--winds 4 6 ... 20] [--reel-element-length 40]
[--out results/pumping_power]`` (``--reel-element-length``: on the reeling multi-element tether). The difference
from Schmehl's model at the simulated operating point is split by phase (:func:`loss_split`).
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
from laddermill_gym.control.pumping_cycle import PHASE_IN, lateral_lqr
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.observation import WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.quasisteady import lansdorp
from laddermill_gym.quasisteady.lansdorp import PumpingParams
from laddermill_gym.reference.wind import air_density
from laddermill_gym.sim.statics import table_spline
from laddermill_gym.studies.commands import writable_folder
from laddermill_gym.studies.pumping.pumping_cycle import cycle_stats, quasi_steady, run_cycles

__all__ = ["curve_point", "loss_split", "main"]

_KEYS = ("power", "schmehl_matched_W", "lansdorp_W", "schmehl_W", "tension_out", "schmehl_matched_tension_N",
         "loss_reel_out_tension_W", "loss_reel_in_tension_W", "loss_within_phases_W", "loss_model_timing_W")


def curve_point(wind: float, reel_element_length: float | None = None) -> dict:
    """The complete cycle's figures at scene wind ``wind`` [m/s] (the second cycle from the trim); on the reeling
    tether (``configs/pumping/pumping_kite_reeling.yaml``, elements of ``reel_element_length`` [m]) when given, else
    on the single element of ``configs/pumping/pumping_kite.yaml``."""
    options: dict = {"overrides": {"wind": {"v0": float(wind)}}}
    config = "pumping_kite"
    if reel_element_length is not None:
        options["reeling"], config = {"element_length": float(reel_element_length)}, "pumping_kite_reeling"
    try:
        task = PumpingTask(1, config=config, episode_time=3000.0, scene_options=options)
    except ConfigError as err:  # no static start: the wing cannot lift its tether at this wind
        return {"v0": wind, "failed": f"no trim: {str(err)[-160:]}", **{k: math.nan for k in _KEYS}}
    ctl = CrosswindController(task, lateral_lqr(task, DEFAULT_CONFIG))
    try:
        rec = run_cycles(task, ctl, 2, progress=False, probe=_wing_probe)
    except RuntimeError as err:
        return {"v0": wind, "failed": str(err), **{k: math.nan for k in _KEYS}}
    stats = cycle_stats(rec, task.control_dt)
    if not stats:
        return {"v0": wind, "failed": "no complete cycle in 3000 s", **{k: math.nan for k in _KEYS}}
    c = stats[-1]
    q = quasi_steady(c, task)
    return {"v0": wind, "failed": "", **c, **q, **loss_split(c, q, task.pumping.winch.efficiency),
            **_reel_out_means(rec, task)}


def _wing_probe(task) -> dict[str, float]:
    """The tether tension at the wing [N] and the squared airspeed [m^2/s^2] (steady wind along -x at the wing's
    wind speed, the scene's profile) of copy 0 now."""
    ro = task.raw_obs[0]
    wind = np.array([-ro[WINCH_OBS_INDEX["wind_speed"]], 0.0, 0.0])
    return {"wing_tension": float(ro[OBS_INDEX["tension"]]), "airspeed2": float(np.sum((wind - ro[3:6]) ** 2))}


def _reel_out_means(rec: dict, task) -> dict[str, float]:
    """Over the last complete cycle's reel-out (winch speed > 0): mean tension at the wing [N], its ratio to the
    drum's, and the aerodynamic force 1/2 rho S C_R v_a^2 [N] at the flown airspeed (mean of v_a^2) and the mean
    C_R of the flown alpha; the model's reel-out tension is this force of its own apparent wind."""
    ph = rec["phase"]
    starts = np.flatnonzero((ph[1:] != PHASE_IN) & (ph[:-1] == PHASE_IN)) + 1
    sl = slice(starts[-2], starts[-1])
    o = rec["v"][sl] > 0
    wing = task.scene.assembly.wing(0)
    coef = table_spline(wing.aero)(float(np.mean(rec["alpha"][sl][o])))
    c_r = math.hypot(float(coef[AERO_INDEX["CL"]]), float(coef[AERO_INDEX["CD"]]))
    rho = air_density(task.scene.assembly.wind, float(np.mean(-rec["z"][sl][o])))  # at the mean reel-out altitude
    t_wing = float(np.mean(rec["wing_tension"][sl][o]))
    return {"wing_tension_out_N": t_wing, "wing_over_drum": t_wing / float(np.mean(rec["tension"][sl][o])),
            "aero_force_out_N": 0.5 * rho * wing.area * c_r * float(np.mean(rec["airspeed2"][sl][o])),
            "wing_area_m2": float(wing.area), "rho": float(rho)}


def loss_split(c: dict, q: dict, eta: float) -> dict[str, float]:
    """Where the simulated cycle ``c`` loses against Schmehl's model at its operating point ``q`` [W], by phase:
    Lansdorp's eqs. 10-14 (``lansdorp.cycle``, the cycle's energy and time from its phase means) at the simulated
    reel-out speed, reeled length and reel-in speed, fed first the model's reel-out and reel-in tensions, then the
    simulated reel-out tension, then both simulated tensions. The shares: ``reel_out_tension`` (the simulated
    reel-out tension below the model's), ``reel_in_tension`` (the simulated reel-in tension above the model's),
    ``within_phases`` (eqs. 10-14 on the simulated means less the simulated power: the mean of T V over the
    reel-out against the product of the means, the transitions and the speed lag), ``model_timing`` (the model's
    power less eqs. 10-14 on its own tensions: its cycle time's transitions); they sum to matched - simulated."""
    params = PumpingParams(eta=eta, reel_length=c["reeled"], reel_in_speed=c["speed_in"])
    t_out, t_in = q["schmehl_matched_tension_N"], q["schmehl_matched_in_N"]
    model = float(lansdorp.cycle(np.array([t_out]), c["speed_out"], params, tension_in=np.array([t_in]))[4][0])
    out = float(lansdorp.cycle(np.array([c["tension_out"]]), c["speed_out"], params,
                               tension_in=np.array([t_in]))[4][0])
    fed = q["eqs10_14_fed_W"]
    return {"loss_reel_out_tension_W": model - out, "loss_reel_in_tension_W": out - fed,
            "loss_within_phases_W": fed - c["power"], "loss_model_timing_W": q["schmehl_matched_W"] - model}


def _figure(rows: list[dict], out: Path) -> Path:
    from laddermill_gym.figure_files import subplots

    v = [r["v0"] for r in rows]
    fig, ax = subplots(figsize=(7, 4.5))
    for key, label, style in (("power", "simulated (crosswind controller)", "ko-"),
                              ("schmehl_matched_W", "Schmehl at the simulated operating point", "bs--"),
                              ("schmehl_W", "Schmehl, nominal", "c^:"), ("lansdorp_W", "Lansdorp eqs. 1-14", "r.:")):
        ax.plot(v, [r[key] / 1e3 for r in rows], style, label=label)
    no_trim = [r["v0"] for r in rows if r["failed"].startswith("no trim")]
    if no_trim:  # a physical limit, shown rather than left out: the wing cannot lift its tether at these winds
        ax.plot(no_trim, [0.0] * len(no_trim), "kx", ms=9, label="no trim: the wing cannot lift its tether")
    ax.set_xlabel("wind speed v0 at 50 m [m/s]")
    ax.set_ylabel("net electrical mean power of a cycle [kW]")
    ax.set_title("PumpingKite: crosswind cycle against the quasi-steady models")
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = out / "pumping_power_curve.png"
    fig.savefig(path, dpi=100)
    return path


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.pumping.power_curve", description=__doc__)
    p.add_argument("--winds", type=float, nargs="+", default=[4, 6, 8, 10, 12, 14, 16, 18, 20],
                   help="[m/s] scene wind speeds v0 at 50 m")
    p.add_argument("--out", type=Path, default=None, help="folder for pumping_power_curve.json and .png")
    p.add_argument("--reel-element-length", type=float, default=None,
                   help="[m] fly the reeling multi-element tether (configs/pumping/pumping_kite_reeling.yaml, "
                   "docs/reeling_tether.md) with elements of this length (default: the single element)")
    args = p.parse_args(argv)
    if any(not (0 < w <= 60) for w in args.winds):
        p.error(f"--winds = {args.winds}: each must be in (0, 60] m/s")
    if args.reel_element_length is not None and not 1.0 <= args.reel_element_length <= 1000.0:
        p.error(f"--reel-element-length = {args.reel_element_length}: must be in [1, 1000] m")
    if args.out is not None:
        writable_folder(args.out, "--out")  # before the minutes of flight, not after them
    rows = [curve_point(w, args.reel_element_length) for w in tqdm(args.winds, unit="wind")]
    print(f"{'v0 m/s':>6} {'sim W':>8} {'matched W':>9} {'sim/matched':>11} {'Schmehl W':>10} {'Lansdorp W':>11} "
          f"{'T_out N':>8} {'matched T_out N':>15}  failure")
    for r in rows:
        print(f"{r['v0']:6.1f} {r['power']:8.0f} {r['schmehl_matched_W']:9.0f} "
              f"{r['power'] / r['schmehl_matched_W']:11.2f} {r['schmehl_W']:10.0f} {r['lansdorp_W']:11.0f} "
              f"{r['tension_out']:8.0f} {r['schmehl_matched_tension_N']:15.0f}  {r['failed'][:90]}")
    print("matched - simulated by phase [W] (loss_split): reel-out tension, reel-in tension, within the phases, "
          "the model's transitions; T_in simulated / model [N]")
    for r in rows:
        if np.isfinite(r["power"]):
            print(f"{r['v0']:6.1f} {r['loss_reel_out_tension_W']:9.0f} {r['loss_reel_in_tension_W']:9.0f} "
                  f"{r['loss_within_phases_W']:9.0f} {r['loss_model_timing_W']:9.0f}   "
                  f"{r['tension_in']:7.0f} / {r['schmehl_matched_in_N']:6.0f}")
    print("reel-out tension [N]: drum, at the wing (wing / drum), 1/2 rho S C_R <v_a^2> at the flown airspeed, model")
    for r in rows:
        if np.isfinite(r["power"]):
            print(f"{r['v0']:6.1f} {r['tension_out']:8.0f} {r['wing_tension_out_N']:8.0f} ({r['wing_over_drum']:.3f}) "
                  f"{r['aero_force_out_N']:8.0f} {r['schmehl_matched_tension_N']:8.0f}")
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "pumping_power_curve.json").write_text(json.dumps(rows, indent=1, default=float))
        print(args.out / "pumping_power_curve.json")
        print(_figure(rows, args.out))
    # a wind without a trim is a physical limit, shown in the table and the figure; any other failure exits 1
    return 0 if all(np.isfinite(r["power"]) or r["failed"].startswith("no trim") for r in rows) else 1


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("pumping power_curve", main))
