"""The crosswind pumping cycle on tethers of several element counts (issue 29 point 2): the shipped single
sag-corrected element (``configs/pumping/pumping_kite.yaml``) and the reeling multi-element tether
(``configs/pumping/pumping_kite_reeling.yaml``, ``kernels/reel.py``) at nominal element lengths l_n of 100, 60, 40
and 30 m (3, 5, 7.5 and 10 elements at the 300 m start; RK4 at ``model.reel.stable_dt``: 5, 2.5, 2.5 and 2 ms),
the same crosswind controller and scenario as
``pumping_cycle`` (steady wind after the envs' 0.01 rad direction step at 1 s). Per run: the elements in the air
(fewest, most), the second complete cycle's net electrical mean power, reel-out tension and speed, reel-in
tension, cycle time, and the tether's ground contacts (most nodes on the ground at once, the share of control steps
with one). docs/pumping.md, "The reeling tether".

Run: ``python -m laddermill_gym.studies.pumping.tether_convergence [--lengths 300 100 60 40 30] [--out DIR]``
(300 = the shipped single element).
"""

from __future__ import annotations

import argparse
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
from laddermill_gym.studies.commands import Command, check_number
from laddermill_gym.studies.pumping.pumping_cycle import cycle_stats, run_cycles

__all__ = ["tether_run", "add_parser", "main"]

#: The start tether [m] (configs/scenes/pumping_kite.yaml's piece_length): l_n at or above it is the single element.
START_LENGTH = 300.0


def _probe(task: PumpingTask) -> dict[str, float]:
    """Elements in the air and tether nodes on the ground in copy 0 now."""
    asm, x = task.batch.assembly, task.batch.states[0]
    if not is_reel(asm.station):
        return {"elements": float(asm.elements.count), "contacts": 0.0}
    return {"elements": float(nodes_in_air(asm, x) + 1), "contacts": float(ground_contacts(asm, x))}


def tether_run(element_length: float, cycles: int = 2, progress: bool = False) -> dict[str, float]:
    """Fly ``cycles`` + 1 crosswind cycles on a tether of nominal element length ``element_length`` [m] (the
    shipped single element at or above START_LENGTH); the figures of the last complete cycle and of the run."""
    if element_length >= START_LENGTH:
        task = PumpingTask(1, config="pumping_kite", episode_time=2000.0)
    else:
        cable = load_pumping("pumping_kite").scene.assembly.elements
        dt = stable_dt(element_length, float(cable.EA[0]), float(cable.mu[0]))
        task = PumpingTask(1, config="pumping_kite_reeling", episode_time=2000.0,
                           scene_options={"reeling": {"element_length": float(element_length), "dt": dt}})
    ctl = CrosswindController(task, lateral_lqr(task, DEFAULT_CONFIG), load_crosswind_config())
    rec = run_cycles(task, ctl, cycles + 1, progress=progress, probe=_probe)
    c = cycle_stats(rec, task.control_dt)[-1]
    return {"element_length_m": float(min(element_length, START_LENGTH)),
            "elements_at_start": START_LENGTH / min(element_length, START_LENGTH), "dt_s": task.scene.settings.dt,
            "elements_min": int(rec["elements"].min()), "elements_max": int(rec["elements"].max()),
            "power_W": c["power"], "tension_out_N": c["tension_out"], "speed_out_m_s": c["speed_out"],
            "tension_in_N": c["tension_in"], "cycle_s": c["t_cycle"], "alpha_deg": math.degrees(c["alpha"]),
            "contacts_max": int(rec["contacts"].max()), "contact_share": float((rec["contacts"] > 0).mean())}


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--lengths", type=float, nargs="+", default=[300.0, 100.0, 60.0, 40.0, 30.0],
                   help="[m] nominal element lengths (300: the shipped single element)")
    p.add_argument("--cycles", type=int, default=2, help="complete cycles after the first (the last is reported)")
    p.add_argument("--out", type=Path, default=None, help="folder for tether_convergence.json (default: none)")


def _run(args) -> int:
    for v in args.lengths:
        check_number("--lengths", v, low=5, high=1000, unit="m")
    check_number("--cycles", args.cycles, low=1, high=100, integer=True, strict=False)
    rows = []
    print(f"{'l_n m':>6} {'dt ms':>5} {'el. at 300 m':>12} {'el. min-max':>11} {'P W':>7} {'T_out N':>8} {'v_out':>6} "
          f"{'T_in N':>7} {'T_c s':>6} {'alpha':>6} {'on ground':>9} {'steps %':>7}")
    for ln in tqdm(args.lengths, unit="tether", leave=False):
        try:
            r = tether_run(ln, args.cycles)
        except RuntimeError as err:
            print(f"{ln:6.0f} failed: {err}")
            continue
        rows.append(r)
        tqdm.write(f"{r['element_length_m']:6.0f} {1e3 * r['dt_s']:5.1f} {r['elements_at_start']:12.1f} "
                   f"{r['elements_min']:5d}-{r['elements_max']:<5d} {r['power_W']:7.0f} {r['tension_out_N']:8.0f} "
                   f"{r['speed_out_m_s']:6.2f} {r['tension_in_N']:7.0f} {r['cycle_s']:6.1f} {r['alpha_deg']:6.2f} "
                   f"{r['contacts_max']:9d} {100 * r['contact_share']:7.1f}")
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "tether_convergence.json").write_text(json.dumps(rows, indent=1))
        print(args.out / "tether_convergence.json")
    return 0


#: ``laddermill tether-convergence``
COMMAND = Command("tether-convergence", "the crosswind cycle on tethers of 1 to 10 elements",
                  __doc__.split("\n\n")[0].replace("``", ""), _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
