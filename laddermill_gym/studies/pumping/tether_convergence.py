"""The crosswind pumping cycle on tethers of several element counts (issue 29 point 2): the shipped single
sag-corrected element (``configs/pumping/pumping_kite.yaml``) and the reeling multi-element tether
(``configs/pumping/pumping_kite_reeling.yaml``, ``kernels/reel.py``) at nominal element lengths l_n of 100, 60, 40
and 30 m (3, 5, 7.5 and 10 elements at the 300 m start; RK4 at ``model.reel.stable_dt``: 5, 2.5, 2.5 and 2 ms),
the same crosswind controller and scenario as
``pumping_cycle`` (steady wind after the envs' 0.01 rad direction step at 1 s). Per run: the elements in the air
(fewest, most), the second complete cycle's net electrical mean power, reel-out tension and speed, reel-in
tension, cycle time, and the tether's ground contacts (most nodes on the ground at once, the share of control steps
with one). docs/reeling_tether.md.

Run: ``python -m laddermill_gym.studies.pumping.tether_convergence [--lengths 300 100 60 40 30] [--out DIR]``
(300 = the shipped single element); ``--start-length 200 --lengths 40``: from 200 m to 500 m and back (Delta L
300 m).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
from pathlib import Path

from tqdm import tqdm

from laddermill_gym.control.crosswind import CrosswindController
from laddermill_gym.control.crosswind_config import load_crosswind_config
from laddermill_gym.control.lqr import DEFAULT_CONFIG
from laddermill_gym.control.pumping_cycle import lateral_lqr
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.envs.pumping.winch_scene import load_pumping
from laddermill_gym.model.reel import ground_contacts, is_reel, nodes_in_air, stable_dt
from laddermill_gym.studies.commands import Command, check_number, writable_folder
from laddermill_gym.studies.pumping.pumping_cycle import cycle_stats, run_cycles

__all__ = ["tether_run", "add_parser", "main"]

#: The start tether [m] (configs/scenes/pumping_kite.yaml's piece_length) and the longest (its start plus the crosswind
#: config's Delta L = 200 m, configs/agents/crosswind_pumping.yaml).
START_LENGTH, END_LENGTH = 300.0, 500.0


def _probe(task: PumpingTask) -> dict[str, float]:
    """Elements in the air and tether nodes on the ground in copy 0 now."""
    asm, x = task.batch.assembly, task.batch.states[0]
    if not is_reel(asm.station):
        return {"elements": float(asm.elements.count), "contacts": 0.0}
    return {"elements": float(nodes_in_air(asm, x) + 1), "contacts": float(ground_contacts(asm, x))}


def _task(element_length: float, start: float) -> PumpingTask:
    """The pumping task on the single element (``element_length`` >= ``start`` [m]) or the reeling tether, its
    tether ``start`` long at t = 0 (the scene's piece_length) and reeled out to END_LENGTH."""
    options = {} if start == START_LENGTH else {"overrides": {"chain": {"piece_length": float(start)}}}
    if element_length >= start:
        task = PumpingTask(1, config="pumping_kite", episode_time=3000.0, scene_options=options)
    else:
        cable = load_pumping("pumping_kite").scene.assembly.elements
        dt = stable_dt(element_length, float(cable.EA[0]), float(cable.mu[0]))
        options["reeling"] = {"element_length": float(element_length), "dt": dt}
        task = PumpingTask(1, config="pumping_kite_reeling", episode_time=3000.0, scene_options=options)
    if start != START_LENGTH:  # Delta L to END_LENGTH; the drum holds one more overrun than that
        cyc = dataclasses.replace(task.pumping.cycle, reel_length=END_LENGTH - start)
        task.pumping = dataclasses.replace(task.pumping, cycle=cyc)
        task.max_paid_out = cyc.reel_length + 2.0 * cyc.depower_overrun
    return task


def tether_run(element_length: float, cycles: int = 2, start: float = START_LENGTH,
               progress: bool = False) -> dict[str, float]:
    """Fly ``cycles`` + 1 crosswind cycles on a tether of nominal element length ``element_length`` [m] (the
    single element at or above ``start``), from ``start`` [m] to END_LENGTH and back; the figures of the last
    complete cycle and of the run."""
    task = _task(element_length, start)
    cfg = load_crosswind_config()
    cfg = dataclasses.replace(cfg, phases=dataclasses.replace(cfg.phases, reel_length=END_LENGTH - start))
    ctl = CrosswindController(task, lateral_lqr(task, DEFAULT_CONFIG), cfg)
    rec = run_cycles(task, ctl, cycles + 1, progress=progress, probe=_probe)
    c = cycle_stats(rec, task.control_dt)[-1]
    return {"element_length_m": float(min(element_length, start)), "start_m": start,
            "tether_min_m": float(start + rec["s"].min()), "tether_max_m": float(start + rec["s"].max()),
            "elements_at_start": start / min(element_length, start), "dt_s": task.scene.settings.dt,
            "elements_min": int(rec["elements"].min()), "elements_max": int(rec["elements"].max()),
            "power_W": c["power"], "tension_out_N": c["tension_out"], "speed_out_m_s": c["speed_out"],
            "tension_in_N": c["tension_in"], "cycle_s": c["t_cycle"], "alpha_deg": math.degrees(c["alpha"]),
            "contacts_max": int(rec["contacts"].max()), "contact_share": float((rec["contacts"] > 0).mean())}


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--lengths", type=float, nargs="+", default=[300.0, 100.0, 60.0, 40.0, 30.0],
                   help="[m] nominal element lengths (300: the shipped single element)")
    p.add_argument("--start-length", type=float, default=START_LENGTH,
                   help="[m] the tether at t = 0 (the scene's 300 m by default), reeled out to 500 m")
    p.add_argument("--cycles", type=int, default=2, help="complete cycles after the first (the last is reported)")
    p.add_argument("--out", type=Path, default=None, help="folder for tether_convergence.json (default: none)")


def _run(args) -> int:
    for v in args.lengths:
        check_number("--lengths", v, low=5, high=1000, unit="m")
    check_number("--cycles", args.cycles, low=1, high=100, integer=True, strict=False)
    check_number("--start-length", args.start_length, low=100, high=450, strict=False, unit="m")
    if args.out is not None:
        writable_folder(args.out)  # a bad folder named now, not after the runs
    rows, failed = [], []
    print(f"{'l_n m':>6} {'dt ms':>5} {'el. at start':>12} {'tether m':>9} {'el. min-max':>11} {'P W':>7} "
          f"{'T_out N':>8} {'v_out':>6} {'T_in N':>7} {'T_c s':>6} {'alpha':>6} {'on ground':>9} {'steps %':>7}")
    for ln in tqdm(args.lengths, unit="tether", leave=False):
        try:
            r = tether_run(ln, args.cycles, args.start_length)
        except RuntimeError as err:
            tqdm.write(f"{ln:6.0f} failed: {err}")
            failed.append({"element_length_m": float(ln), "failure": str(err)})
            continue
        rows.append(r)
        tqdm.write(f"{r['element_length_m']:6.0f} {1e3 * r['dt_s']:5.1f} {r['elements_at_start']:12.1f} "
                   f"{r['tether_min_m']:4.0f}-{r['tether_max_m']:<4.0f} "
                   f"{r['elements_min']:5d}-{r['elements_max']:<5d} {r['power_W']:7.0f} {r['tension_out_N']:8.0f} "
                   f"{r['speed_out_m_s']:6.2f} {r['tension_in_N']:7.0f} {r['cycle_s']:6.1f} {r['alpha_deg']:6.2f} "
                   f"{r['contacts_max']:9d} {100 * r['contact_share']:7.1f}")
    if args.out is not None:
        (args.out / "tether_convergence.json").write_text(json.dumps(rows + failed, indent=1))
        print(args.out / "tether_convergence.json")
    if failed:  # exit status 1, as pumping-cycle's for a failed run
        print(f"{len(failed)} of {len(args.lengths)} tether runs failed: element lengths "
              f"{', '.join(format(r['element_length_m'], 'g') for r in failed)} m")
        return 1
    return 0


#: ``laddermill tether-convergence``
COMMAND = Command("tether-convergence", "the crosswind cycle on tethers of 1 to 10 elements",
                  __doc__.split("\n\n")[0].replace("``", ""), _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
