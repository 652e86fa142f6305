"""Page groups for figures the ledger once listed as not re-run (issue 33, point 6): commands of a few seconds to a
few minutes whose printed tables the pages quote, each run in a fresh process as the page names it and parsed from
what it prints or writes.

* ``bench_stable_dt``: ``laddermill bench --scenes tethered_wing ladder_chain --no-mill --no-pointmass --json F``,
  its largest stable RK4 step per scene [s] (a bisection against a DP5(4) reference from a seeded disturbance:
  deterministic), docs/benchmarks.md;
* ``pumping_crosswind``: ``python -m laddermill_gym.studies.pumping.pumping_cycle --cycles 2 --out DIR`` (about
  40 s), its printed cycle table, docs/pumping.md;
* ``pumping_power_curve`` and ``reeling_power_curve``: ``python -m laddermill_gym.studies.pumping.power_curve
  [--reel-element-length 40]`` (3.5 and 6 minutes at a load of 7), their printed tables, docs/pumping.md and
  docs/reeling_tether.md;
* ``rotorcraft_evaluate``: ``laddermill evaluate --env laddermill_gym/Rotorcraft-v0 --controllers open_loop lqr
  --episodes 1`` (8 s), its rows, docs/controllers.md's trimmed craft (1.6 kW) and its PPO paragraph's LQR and open
  loop;
* ``gusts_v2_pumping``: ``laddermill gust-bench --suite gusts-v2 --env laddermill_gym/PumpingKite-v0 --controllers
  open_loop lqr`` (16 s) and the LadderMill-v0 grid scenarios (2 min 50 s), their summaries per controller and
  scenario, docs/wind.md.
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from docsite.paper_figures import printed_match, run_command

ROOT = Path(__file__).resolve().parent.parent
CLI = "laddermill_gym.cli"


def bench_stable_dt() -> dict:
    """{scene: largest stable RK4 dt [s] as the bench's table prints it (4 decimals)} of the tethered wing and the
    ladder chain."""
    with tempfile.TemporaryDirectory() as tmp:
        run_command([CLI, "bench", "--scenes", "tethered_wing", "ladder_chain", "--no-mill", "--no-pointmass",
                     "--json", str(Path(tmp) / "bench.json")], 1800)
        data = json.loads((Path(tmp) / "bench.json").read_text())
    return {scene: f"{data['scenes'][scene]['stability']['dt_stable_s']:.4f}" for scene in ("tethered_wing",
                                                                                          "ladder_chain")}


#: pumping_cycle's printed columns, in order (docs/pumping.md's table of the crosswind cycle).
CROSSWIND_COLUMNS = ("t_cycle", "sim", "matched", "matched_tension", "lansdorp", "schmehl", "static", "fed",
                     "tension_out", "speed_out", "tension_in", "alpha", "max_dy")


def pumping_crosswind() -> dict:
    """``python -m laddermill_gym.studies.pumping.pumping_cycle --cycles 2`` (the crosswind controller, three cycles
    from the trim): {"c0", "c1", "c2": {column: the printed cell}} and, per cycle from its JSON, the reel-out time
    [s] and energy at the drum [MJ], the reel-in time [s] and mean reel-in speed [m/s], as the page rounds them."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [STUDY_PUMPING + "pumping_cycle", "--cycles", "2", "--out", tmp]
        out = run_command(argv, 1800)
        cycles = json.loads((Path(tmp) / "pumping_cycle.json").read_text())
    printed_match(r"^cycle +T_c s +sim W +matched W", out.lstrip(), f"python -m {' '.join(argv)}")
    found = {}
    for line in out.splitlines():
        cells = line.split()
        if len(cells) == len(CROSSWIND_COLUMNS) + 1 and cells[0].isdigit():
            found[f"c{cells[0]}"] = dict(zip(CROSSWIND_COLUMNS, cells[1:], strict=True))
    for k, c in enumerate(cycles):
        found.setdefault(f"c{k}", {}).update(phases(c))
    return found


STUDY_PUMPING = "laddermill_gym.studies.pumping."


def phases(cycle: dict) -> dict:
    """A cycle's reel-out time [s, whole], reel-out energy at the drum [MJ, 1 decimal], reel-in time [s, whole] and
    mean reel-in speed [m/s, 1 decimal] from pumping_cycle's JSON row (missing keys: nothing)."""
    keys = ("t_out", "e_out", "t_in", "speed_in")
    if not all(k in cycle for k in keys):
        return {}
    return {"t_out_s": f"{cycle['t_out']:.0f}", "energy_out_MJ": f"{cycle['e_out'] / 1e6:.1f}",
            "t_in_s": f"{cycle['t_in']:.0f}", "speed_in": f"{cycle['speed_in']:.1f}"}


def power_curve(reel_element_length: str | None = None) -> dict:
    """``python -m laddermill_gym.studies.pumping.power_curve [--reel-element-length L]`` at its default winds (4-20
    m/s; it exits 1 when a wind has no trim, which the page reports): per wind ("v8", ...) the first table's cells
    (simulated, matched, ratio, Schmehl nominal, Lansdorp [W], T_out, matched T_out [N]) or {"failure": its text}, and
    the loss split's cells (reel-out, reel-in, within, transitions [W], T_in simulated / model [N]) as printed."""
    argv = [STUDY_PUMPING + "power_curve", *(["--reel-element-length", reel_element_length]
                                            if reel_element_length else [])]
    env = dict(os.environ)
    proc = subprocess.run([sys.executable, "-m", *argv], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=2400)
    where = f"python -m {' '.join(argv)}"
    if proc.returncode not in (0, 1):
        raise RuntimeError(f"{where} exited {proc.returncode}:\n{proc.stdout[-2000:]}{proc.stderr[-3000:]}")
    out = proc.stdout
    head, _, rest = out.partition("matched - simulated by phase")
    printed_match(r"^v0 m/s +sim W +matched W", head.lstrip(), where)
    found = {}
    names = ("sim", "matched", "ratio", "nominal", "lansdorp", "T_out", "matched_T_out")
    for line in head.splitlines():
        cells = line.split()
        if not cells or not _is_number(cells[0]):
            continue
        key = f"v{float(cells[0]):.0f}"
        if cells[1] == "nan" or not _is_number(cells[1]):
            found[key] = {"failure": " ".join(cells[len(names) + 1:])}
        else:
            found[key] = dict(zip(names, cells[1:len(names) + 1], strict=True))
    split, _, _ = rest.partition("reel-out tension [N]")
    for line in split.splitlines()[1:]:
        cells = line.replace("/", " ").split()
        if len(cells) == 7 and _is_number(cells[0]):
            found[f"v{float(cells[0]):.0f}"].update(zip(("out", "in", "within", "transitions", "T_in", "model_T_in"),
                                                        cells[1:], strict=True))
    return found


def _is_number(text: str) -> bool:
    try:
        return math.isfinite(float(text)) or True
    except ValueError:
        return False


def gusts_v2_pumping() -> dict:
    """``laddermill gust-bench --suite gusts-v2 --env laddermill_gym/PumpingKite-v0 --controllers open_loop lqr``:
    per "controller/scenario" the survived seeds ("k/n"), the failed seeds' end times [s, 1 decimal, ", "-joined],
    the median largest lateral excursion [m, 1 decimal] and the median energy ratio (3 decimals, "-" when undefined),
    as docs/wind.md's table writes them."""
    with tempfile.TemporaryDirectory() as tmp:
        run_command([CLI, "gust-bench", "--suite", "gusts-v2", "--env", "laddermill_gym/PumpingKite-v0",
                     "--controllers", "open_loop", "lqr", "--out", tmp], 1800)
        data = json.loads((Path(tmp) / "gust_bench.json").read_text())
    return gust_table(data["rows"])


def gusts_v2_mill() -> dict:
    """``laddermill gust-bench --suite gusts-v2 --env laddermill_gym/LadderMill-v0 --scenarios EWS_IA NTM_IB
    dryden_light dryden_moderate --controllers open_loop lqr`` (2 min 50 s): :func:`gust_table` of its rows, and
    ``end_bound`` (:func:`end_bound`: features.md's "no controller keeps the mill ... beyond 15 s")."""
    with tempfile.TemporaryDirectory() as tmp:
        run_command([CLI, "gust-bench", "--suite", "gusts-v2", "--env", "laddermill_gym/LadderMill-v0", "--scenarios",
                     "EWS_IA", "NTM_IB", "dryden_light", "dryden_moderate", "--controllers", "open_loop", "lqr",
                     "--out", tmp], 2400)
        data = json.loads((Path(tmp) / "gust_bench.json").read_text())
    return {**gust_table(data["rows"]), "end_bound": end_bound(data["rows"])}


def end_bound(rows: list[dict]) -> str:
    """The next whole second above the latest end [s] of gust-bench ``rows`` when every one failed, else "a seed
    survived"."""
    if any(r["survived"] for r in rows):
        return "a seed survived"
    return str(math.floor(max(r["t_end_s"] for r in rows)) + 1)


def gust_table(rows: list[dict]) -> dict:
    """The wind page's table cells of gust-bench ``rows`` (one per controller, scenario and seed: seeds survived
    "k/n", and k and n alone as ``kept`` and ``seeds``), and the sideslip [deg] each failed seed's cause names
    (``beta``: ", "-joined, "" when none)."""
    import numpy as np

    groups: dict[str, list[dict]] = {}
    for r in rows:
        groups.setdefault(f"{r['controller']}/{r['scenario']}", []).append(r)
    found = {}
    for key, rs in groups.items():
        ratio = np.array([np.nan if r["energy_ratio"] is None else r["energy_ratio"] for r in rs], dtype=float)
        lateral = float(np.median([r["max_lateral_m"] for r in rs]))
        failed = [r for r in rs if not r["survived"]]
        found[key] = {"survived": f"{len(rs) - len(failed)}/{len(rs)}", "kept": str(len(rs) - len(failed)),
                      "seeds": str(len(rs)),
                      "ends": ", ".join(f"{r['t_end_s']:.1f}" for r in failed) or "-",
                      "causes": [r["cause"] for r in failed], "failures": [r["failure"] for r in failed],
                      "beta": ", ".join(m.group(1) for r in failed if (m := re.search(r"beta = ([-\d.]+) deg",
                                                                                       r["cause"]))),
                      "lateral": f"{lateral:.1f}", **{f"f{i}": failed_wing(r["cause"]) for i, r in enumerate(failed)},
                      "ratio": f"{np.nanmedian(ratio):.3f}" if np.isfinite(ratio).any() else "-"}
    return found


def failed_wing(cause: str) -> dict:
    """A gust-bench failure's time [s], and where it names a slot out of the aerodynamic range, the slot and its
    alpha and beta [deg], as printed ({} keys missing where the cause does not name them)."""
    m = re.match(r"t = ([\d.]+) s: (?:slot (\d+) alpha = ([-\d.]+) deg, beta = ([-\d.]+) deg)?", cause)
    if m is None:
        return {}
    return {k: v for k, v in zip(("t", "slot", "alpha", "beta"), m.groups(), strict=True) if v is not None}


#: The Meijaard study's claims (claims.csv's "paper" column, its start) and what each "ours" text gives, in order.
CLAIMS = (("legs almost parallel", r"loop (\d+) m wide on average for a top (\d+) m above the station \(width / height "
           r"([\d.]+)\)", ("width", "top", "ratio")),
          ("the loop widens", r"loop width (\d+)-(\d+) m at 1 m/s; (\d+)-(\d+) m at 5 m/s",
           ("w1_lo", "w1_hi", "w5_lo", "w5_hi")),
          ("tension smallest near the top (V_c = 1", r"tension ([\d.]+) kN in element (\d+), at ([\d.]+) of",
           ("T1", "element1", "height1")),
          ("tension smallest near the top (V_c = 5", r"tension ([\d.]+) kN in element (\d+), at ([\d.]+) of",
           ("T5", "element5", "height5")),
          ("power of the order of 200 kW (2D V_c=5)",
           r"the last (\d+) period means (-?\d+) to (-?\d+) kW, mean ([\d.]+) kW", ("periods5", "mean_lo5", "mean_hi5",
                                                                                "mean5")),
          ("node 40 yaws", r"up to (\d+) deg before the end at ([\d.]+) s .*?; (\d+) deg over ([\d.]+) s",
           ("yaw", "yaw_end", "tumble_deg", "tumble_s")),
          ("alpha and sideslip", r"in alpha at ([\d.]+) s, in beta at ([\d.]+) s; slot 40 at \S+ / ([\d.]+) s",
           ("alpha_any", "beta_any", "beta_slot")))


def meijaard_files(folder: Path) -> dict:
    """What the Meijaard study wrote into ``folder`` beside power.csv: the claims panel's figures (:data:`CLAIMS`, as
    printed) and the direction step's ends (breakdown.csv): the physical end [s, 2 decimals], the wings outside the
    data ("8-15"), the first one's sideslip [deg] and since when [s]; the fixed-step runs without the aerodynamic
    criterion ("rk4_10ms", "rk4_2_5ms"): where they broke down [s, 1 decimal] and the wings over the guards."""
    import csv

    with open(folder / "claims.csv", newline="") as f:
        claims = [r for r in csv.DictReader(f) if r["scene"] == "laddermill_v1"]
    found = {}
    for start, pattern, keys in CLAIMS:
        row = next(r for r in claims if r["paper"].startswith(start))
        found.update(zip(keys, printed_match(pattern, row["ours"], "meijaard's claims.csv").groups(), strict=True))
    with open(folder / "breakdown.csv", newline="") as f:
        runs = {r["label"]: r for r in csv.DictReader(f)}
    first = runs["RK4 dt = 10 ms"]
    bodies = [int(b) for b in first["end_bodies"].split()]
    wing = printed_match(r"wing (\d+) outside .*beta ([\d.]+) deg.* since ([\d.]+) s", first["message"],
                         "breakdown.csv")
    found.update(end=f"{float(first['t_reached_s']):.2f}", end_wings=f"{min(bodies)}-{max(bodies)}",
                 end_wing=wing.group(1), end_beta=wing.group(2), end_since=wing.group(3))
    for key, label in (("rk4_10ms", "RK4 dt = 10 ms, no end criterion"),
                       ("rk4_2_5ms", "RK4 dt/4 = 2.5 ms, aerodynamic range not judged")):
        step = runs[label]["message"].split("; last good state")[0]
        found[key] = {"t": f"{float(runs[label]['t_reached_s']):.1f}",
                      "speed": _wings(re.findall(r"wing (\d+) speed", step)),
                      "rate": _wings(re.findall(r"wing (\d+) angular rate", step))}
    return found


def _wings(numbers: list[str]) -> str:
    """Wing numbers as the page names them: "wing 10", "wings 17-19" (a run), "wings 3, 7", "no wing"."""
    w = sorted({int(n) for n in numbers})
    if not w:  # the run's message names no wing for this limit (a run that ends by speed alone)
        return "no wing"
    if len(w) == 1:
        return f"wing {w[0]}"
    return f"wings {w[0]}-{w[-1]}" if w == list(range(w[0], w[-1] + 1)) else "wings " + ", ".join(map(str, w))


def rotorcraft_evaluate() -> dict:
    """``laddermill evaluate --env laddermill_gym/Rotorcraft-v0 --controllers open_loop lqr --episodes 1`` (8 s): per
    controller its printed row (return, length [s], max |dy| [m], power [W], failures) and the power in kW as the
    page rounds it (1 decimal); the LQR holds the trim collective, so its power is the trimmed craft's
    (docs/controllers.md, "Rotorcraft-v0")."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [CLI, "evaluate", "--env", "laddermill_gym/Rotorcraft-v0", "--controllers", "open_loop", "lqr",
                "--episodes", "1", "--out", tmp]
        out = run_command(argv, 900)
    rows = {}
    for label in ("open_loop", "lqr"):
        m = printed_match(rf"^{label} +(\S+) +(\S+) +(\S+) +(\S+) +(.*)$", out, f"python -m {' '.join(argv)}")
        rows[label] = dict(zip(("return", "length", "dy", "power", "failures"), m.groups(), strict=True))
        rows[label]["power_kW"] = f"{float(m.group(4)) / 1e3:.1f}"
    return rows


#: This module's page groups (merged into docsite.page_figures.GROUPS).
STUDY_GROUPS = {"bench_stable_dt": bench_stable_dt, "pumping_crosswind": pumping_crosswind,
                "pumping_power_curve": power_curve,
                "reeling_power_curve": lambda: power_curve("40"),
                "gusts_v2_pumping": gusts_v2_pumping, "gusts_v2_mill": gusts_v2_mill,
                "rotorcraft_evaluate": rotorcraft_evaluate}
