"""The docs pages' figures: re-run the commands the pages quote, compare each checked number, and report coverage.

``python -m docsite.readme_figures --pages [PAGE ...]`` runs the measurement groups the chosen pages' checks need
(:data:`GROUPS`: each runs its command in a fresh process, as a user types it, and parses what it prints; one reads
shipped files), writes them into the JSON under ``"pages"`` and compares every check of
:data:`docsite.page_ledger.LEDGER` with them: the text a check's groups capture on the page must equal its template
filled from the measured figures (the printed digits, or the printed value rounded to the digits the page quotes).
``--pages`` alone re-runs every page with checks.

Each group's cost, measured on the shared 2-core machine at a load of 6-8 (numba's cache warm): ``main_job``
(README's demo, shared with README's figures) 382 s, ``fast_mill_v2`` (five periodic searches) 647 s,
``meijaard_v1`` (its periodic searches saved) 310 s, ``simulate_laddermill`` 127-223 s, ``pointmass_benchmark``
125 s, ``rotor_design`` 54 s, ``craft_stability`` 32 s, ``lateral_study`` 31 s, ``tethered_wing_lqr`` 24 s,
``simulate_tethered_wing`` 17 s, ``training_curves`` (reads the shipped CSVs), ``cable_dyneema`` and ``craft_data``
(read the configs) 0 s; at a load of 6-17: ``site_tables`` 34-85 s, ``pumping_evaluate`` 42 s, ``pumping_cycle_lqr``
34 s, ``tether_convergence`` 2-5 min (:mod:`docsite.pumping_figures`), ``insertion_study`` 8 s,
``mill_periodic_2d`` 104-277 s, ``mill_lqr_check`` 216-274 s, ``pointmass_mill`` 173 s at a load of 3 (over 25
minutes at 13; :mod:`docsite.mill_figures`), ``gain_locality`` 780 s at a load of 13, ``rotor_chart`` 23 s,
``design_data``, ``wind_data``, ``numerics_data``, ``pointmass_data`` 0 s, ``derive_wing`` 4 s; at a load of 5-7
(2026-11-29): ``precision_data`` 0 s, ``stable_steps`` 19-65 s, ``wing_controllers`` 13 s, ``chain_controllers``
133 s, ``mill_v1_controllers`` 223 s,
``simulate_laddermill_half`` 267 s: every page about 70 minutes at a load of 13 (about 40 on a quieter machine);
``site_sweeps`` (``laddermill site --sweeps``) 247 s wall at nice 15, load 4-6 (2026-11-30).
"""

from __future__ import annotations

import re
import tempfile
import time
from pathlib import Path

from tqdm import tqdm

from docsite.config_figures import cable_dyneema, craft_data
from docsite.controllers_figures import CONTROLLER_GROUPS
from docsite.design_figures import design_data
from docsite.host_cpu import host_cpu, keyed
from docsite.learned_figures import gain_locality
from docsite.long_checks import check_difference, long_check_differences, long_groups
from docsite.mill_figures import MILL_GROUPS
from docsite.numerics_figures import numerics_data
from docsite.page_ledger import LEDGER, Covered
from docsite.page_numbers import prose, unaccounted
from docsite.paper_figures import printed_match, run_command
from docsite.pointmass_figures import pointmass_data
from docsite.precision_figures import PRECISION_GROUPS
from docsite.printed_blocks import block_differences
from docsite.printed_numbers import printed_differences
from docsite.printed_ratios import craft_ratios
from docsite.pumping_figures import PUMPING_GROUPS
from docsite.rotor_chart_figures import rotor_chart
from docsite.rotor_figures import parse_rotor_design, scan_figures
from docsite.study_figures import STUDY_GROUPS, meijaard_files
from docsite.wind_figures import wind_data
from docsite.wing_figures import derive_wing

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "laddermill_gym" / "docs"
STUDY = "laddermill_gym.studies."


def _search(pattern: str, text: str, argv: list[str]) -> re.Match:
    return printed_match(pattern, text, f"python -m {' '.join(argv)}")


def rotor_design() -> dict:
    """Roberts' 35 m design at 15,000 and 30,000 ft: the wind of the 3.13 MW rating [m/s], its incidence alpha_c
    [deg] and the ideal C_p at that incidence; ``printed``: its whole output up to the files it wrote (whitespace
    flattened, as docs/rotorcraft_design.md quotes it); ``prose`` and ``scan``: the figures its prose quotes
    and works from its scan (:func:`docsite.rotor_figures.parse_rotor_design`,
    :func:`docsite.rotor_figures.scan_figures`)."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [STUDY + "rotorcraft.rotor_design", "--out", tmp]
        out = run_command(argv, 600)
    found = {}
    for alt in ("15,000", "30,000"):
        block = _search(rf"^{alt} ft: .*?\n(?:.*\n){{0,3}}", out, argv).group(0)
        m = _search(r"3\.13 MW at ([\d.]+) m/s: .*alpha_c ([\d.]+) deg", block, argv)
        ideal = _search(r"ideal C_p at that incidence ([\d.]+)", block, argv)
        found[alt.replace(",000", "kft")] = {"wind": m.group(1), "alpha_c": float(m.group(2)),
                                       "ideal_cp": float(ideal.group(1))}
    found["printed"] = " ".join(out.split("\nwrote ")[0].split())  # all it prints before the files it wrote
    found["prose"], found["scan"] = parse_rotor_design(out), scan_figures(out)
    return found


def simulate(scene_args: list[str]) -> dict:
    """``laddermill simulate SCENE_ARGS``: its RK4 step and estimated stable step [s], the simulated span [s] (and
    after a step at 1 s, ``after_1s``), and how the run stopped (the first and last wing over the speed guard, or
    the ground contact's time and height)."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.cli", "simulate", *scene_args, "--out", tmp]
        out = run_command(argv, 1800)
    step = _search(r"^RK4 step ([\d.]+) s; estimated stability limit at the start ([\d.e-]+) s", out, argv)
    found = {"dt": step.group(1), "stable_step": float(step.group(2)),
             "simulated": _search(r"^simulated ([\d.]+) s in", out, argv).group(1)}
    found["after_1s"] = float(found["simulated"]) - 1.0
    periodic = re.search(r"periodic motion converged at t = [\d.]+ s \(period [\d.]+ s\): mean generator power "
                         r"([\d.]+) kW", out)
    if periodic:
        found["periodic_kW"] = periodic.group(1)
    wings = re.findall(r"wing (\d+) speed [\d.e+]+ m/s > (\d+) m/s", out)
    if wings:
        found.update(first_wing=wings[0][0], last_wing=wings[-1][0], guard=wings[0][1])
    contact = re.search(r"ground contact at t = ([\d.]+) s: node (\d+) at height ([-\d.e]+) m", out)
    if contact:
        found.update(contact_t=contact.group(1), contact_node=contact.group(2), contact_height=contact.group(3))
    return found


def training_curves() -> dict:
    """The shipped shared policies' ``training_curve.csv`` rows (no command: the files the training run wrote, as
    shipped), each as docs/learned_mill.md's tables print them: held, length [s] (whole when held), mean power [kW,
    3 decimals], max |dy| [m, 3 significant digits], PPO's agent steps [millions, 2 decimals]."""
    import csv

    curves = {}
    for policy in ("ppo_mill", "ppo_chain"):
        with open(ROOT / "laddermill_gym" / "policies" / policy / "training_curve.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        curves[policy] = [{"held": r["held"], "length": f"{float(r['mean_length_s']):.{0 if r['held'] == '1' else 1}f}",
                           "power": f"{float(r['mean_power_kW']):.3f}", "dy": f"{float(r['max_lateral_m']):#.3g}",
                           "million": f"{int(r['step']) / 1e6:.2f}"} for r in rows]
    return curves


def lateral_study() -> dict:
    """``python -m laddermill_gym.studies.lateral.lateral_study``: the default wing's lateral eigenvalues [1/s] (real,
    imaginary parts), and per sweep its rows (value, largest real part [1/s], period [s], doubling time [s], trim
    elevator and tether elevation [deg]) and zero crossings."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [STUDY + "lateral.lateral_study", "--out", str(Path(tmp) / "lateral_study.png")]
        out = run_command(argv, 900)
    eig = _search(r"^default lateral eigenvalues \[1/s\]: (.*)$", out, argv).group(1)
    found = {"eigenvalues": [[float(a), float(b)] for a, b in re.findall(r"([-\d.]+)([-+][\d.]+)j", eig)]}
    for name, table in re.findall(r"^(\w+): [^\n]*\(default [^\n]*\n +value[^\n]*\n((?:[^\n]+\n)+)", out, re.M):
        rows = [line.split() for line in table.splitlines() if re.match(r" +[-\d.]+ ", line)]
        found[name] = {"rows": [{"value": float(r[0]), "re": float(r[-6]), "period": float(r[-5]), "t2x": float(r[-3]),
                                 "elevator": float(r[-2]), "elevation": float(r[-1])} for r in rows],
                       "max_re_zero": _zero(table, "max Re"), "osc_zero": _zero(table, "Re of the slow oscillation")}
    return found


def pointmass_benchmark() -> dict:
    """``python -m laddermill_gym.studies.pointmass.pointmass_benchmark --quick`` on two numba threads (the held
    arrays depend on the thread count): the 5 km scene's elements, its held arrays [MB, 2 decimals as printed] and
    the explicit method's stable step [s] at that size (the step it runs over its safety factor)."""
    import json

    from laddermill_gym.studies.pointmass.pointmass_benchmark import EXPLICIT_SAFETY

    with tempfile.TemporaryDirectory() as tmp:
        argv = [STUDY + "pointmass.pointmass_benchmark", "--quick", "--json", str(Path(tmp) / "pm.json")]
        run_command(argv, 1800, threads=2)
        data = json.loads((Path(tmp) / "pm.json").read_text())
    big = max(r["elements"] for r in data["costs"])
    dt = next(r["dt_s"] for r in data["costs"] if r["elements"] == big and r["method"] == "explicit")
    return {"elements": f"{big:,}", "held_MB": f"{data['held_bytes']['total'] / 1e6:.2f}",
            "explicit_dt": f"{dt / EXPLICIT_SAFETY:.2g}", "explicit_step": dt}


def craft_stability() -> dict:
    """``python -m laddermill_gym.studies.rotorcraft.craft_stability``: the critical wind speed [m/s], the eq. (6)
    LQR's gain and discrete closed-loop max |z|, and per direction step (0.01, 0.1 rad) open loop and LQR: the
    failure time [s] ("" when none), the largest |y| [m] and |dtheta| [deg]; eq. (6)'s M, D, K (eq6_M...: row by
    row) and beta at 10 m/s, the largest relative error against the Jacobian [%], and the wind scan (per "vN":
    collective [deg], growth [1/s], frequency [rad/s]); and the pages' figures worked from these
    (:func:`docsite.printed_ratios.craft_ratios`)."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = [STUDY + "rotorcraft.craft_stability", "--out", tmp]
        out = run_command(argv, 900)
    lqr = _search(r"LQR gain K = \[([^\]]+)\], discrete closed loop max \|z\| = ([\d.]+)", out, argv)
    found = {"critical": float(_search(r"critical wind speed: ([\d.]+) m/s", out, argv).group(1)),
             "K": [float(k) for k in lqr.group(1).split(",")], "z": float(lqr.group(2))}
    for name in ("M", "D", "K"):  # eq. (6)'s matrices, flattened row by row
        found[f"eq6_{name}"] = [float(x) for x in re.findall(r"[-\d.e]+",
                                                             _search(rf"^ +{name} = (.*)$", out, argv).group(1))]
    found["beta"] = float(_search(r"\(alpha, beta\) = \[[-\d.]+, ([-\d.]+)\]", out, argv).group(1))
    found["rel_error_pct"] = 100 * max(float(e) for e in re.findall(r"max rel error ([\d.e-]+)", out))
    found["scan"] = {f"v{float(v):.0f}": {"collective": float(c), "growth": float(g), "frequency": float(f)}
                     for v, c, g, f in re.findall(r"v0 = +([\d.]+) m/s +collective +([-\d.]+) deg +growth ([-+\d.]+) "
                                                  r"1/s +frequency ([\d.]+)", out)}
    row = (r"^ +(open loop|eq\. \(6\) LQR), ([\d.]+) rad +(?:failure at ([\d.]+) s|no failure) \| max \|y\| ([\d.]+) m"
           r".*max \|dtheta\| ([\d.]+) deg")
    for who, step, fail, y, dtheta in re.findall(row, out, re.M):
        found[f"{'lqr' if 'LQR' in who else 'open'}_{step.replace('.', '')}"] = {
            "fail": fail, "y": float(y), "dtheta": float(dtheta)}
    return craft_ratios(found)


def fast_mill_v2() -> dict:
    """docs/mill_fast.md's table of the in-plane v2 mill at 1-5 m/s: ``fast_mill case --scene laddermill_v2 --speed
    V --start-ramp 100V --max-time 3000`` each (35 s to a few minutes of CPU each): per speed, where the periodic
    search converged [s], the period [s], the mean power and (T_first - T_last) V_c [kW], the last period's smallest
    and largest tension [kN], the search's peak over the limit, the last periods' means [kW] and their count."""
    found = {}
    for v in ("1", "2", "3", "4", "5"):
        argv = [STUDY + "mill.fast_mill", "case", "--scene", "laddermill_v2", "--speed", v, "--start-ramp",
                str(100 * int(v)), "--max-time", "3000"]
        out = run_command(argv, 3600)
        head = re.search(r"periodic motion converged at t = ([\d.]+) s \(period ([\d.]+) s\): mean generator power "
                         r"([-\d.]+) kW.*peak tension ([\d.]+) x the limit", out)
        if head is None:  # not periodic: no row to compare (each check of this speed then names it)
            continue
        tension = _search(r"last period: largest tension ([\d.]+) kN, smallest ([\d.]+) kN; .*V_c ([-\d.]+) kW", out,
                          argv)
        means = _search(r"last (\d+) periods: mean power ([-\d.]+) \.\. ([-\d.]+) kW", out, argv)
        found[f"v{v}"] = {"t": float(head.group(1)), "period": float(head.group(2)), "P": float(head.group(3)),
                          "peak": float(head.group(4)), "T_max": float(tension.group(1)),
                          "T_min": float(tension.group(2)), "dT_P": float(tension.group(3)), "n": means.group(1),
                          "lo": float(means.group(2)), "hi": float(means.group(3))}
    return found


def tethered_wing_lqr() -> dict:
    """``laddermill evaluate --env laddermill_gym/TetheredWing-v0 --controllers lqr --episodes 2`` (20 s): the LQR's
    printed row (return, length [s], max |dy| [m], power [W]) on the registered scenario."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.cli", "evaluate", "--env", "laddermill_gym/TetheredWing-v0", "--controllers", "lqr",
                "--episodes", "2", "--out", tmp]
        out = run_command(argv, 900)
    row = _search(r"^lqr +(\S+) +(\S+) +(\S+) +(\S+) +(\S+)$", out, argv)
    return dict(zip(("return", "length", "dy", "power", "failures"), row.groups(), strict=True))


def meijaard_v1() -> dict:
    """``python -m laddermill_gym.studies.mill.meijaard --out results/meijaard_v1`` (92 s with its periodic searches
    saved there, about 11 minutes without): its ``power.csv`` per case ("2D V_c=1", "2D V_c=2", "2D V_c=5",
    "3D V_c=2"), every column as a number (or the text it holds); ``files``: its claims panel and the direction
    step's ends (:func:`docsite.study_figures.meijaard_files`)."""
    import csv

    from docsite.paper_figures import MEIJAARD_OUT

    run_command([STUDY + "mill.meijaard", "--out", str(MEIJAARD_OUT), "--no-progress"], 2400)
    with open(MEIJAARD_OUT / "power.csv", newline="") as f:
        rows = {r["case"].replace(" V_c=", "_"): r for r in csv.DictReader(f)}

    def number(text: str) -> float | str:
        try:
            return float(text)
        except ValueError:
            return text

    found = {case: {k: number(v) for k, v in row.items()} for case, row in rows.items()}
    for row in found.values():  # "t = 392.55 s: element 0 tension ..." -> 392.55
        m = re.match(r"t = ([\d.]+) s", str(row.get("overload", "")))
        row["overload_s"] = float(m.group(1)) if m else ""
    found["files"] = meijaard_files(MEIJAARD_OUT)  # its claims panel and the direction step's ends
    return found


def _zero(table: str, what: str) -> float:
    m = re.search(rf"^ +{what} = 0 at \w+ = ([-\d.]+)", table, re.M)
    return float(m.group(1)) if m else float("nan")


#: Page groups: name -> the function that measures it (each runs its command in a fresh process).
GROUPS = {"rotor_design": rotor_design, "training_curves": training_curves, "lateral_study": lateral_study,
          "pointmass_benchmark": pointmass_benchmark, "craft_stability": craft_stability,
          "fast_mill_v2": fast_mill_v2, "tethered_wing_lqr": tethered_wing_lqr,
          "meijaard_v1": meijaard_v1, "cable_dyneema": cable_dyneema, "craft_data": craft_data,
          "design_data": design_data, "wind_data": wind_data, "numerics_data": numerics_data,
          "pointmass_data": pointmass_data, "gain_locality": gain_locality, "rotor_chart": rotor_chart,
          "derive_wing": derive_wing,
          "simulate_laddermill": lambda: simulate(["laddermill", "--start", "periodic", "--direction-step", "0.01",
                                                   "--time", "60", "--allow-breakdown"]),
          "simulate_laddermill_half": lambda: simulate(["laddermill", "--start", "periodic", "--dt", "0.005", "--time",
                                                        "1", "--allow-breakdown"]),
          "simulate_tethered_wing": lambda: simulate(["tethered_wing", "--time", "120", "--direction-step", "0.01"]),
          **PUMPING_GROUPS, **MILL_GROUPS, **PRECISION_GROUPS,
          **CONTROLLER_GROUPS, **STUDY_GROUPS}


def measure_pages(pages: list[str] | None = None, have: dict | None = None, more: dict | None = None) -> dict:
    """{"pages": {group: figures}} for the groups the ``pages`` (default: every page with checks) need; groups already
    in ``have`` (README's figures measured in the same run, e.g. ``main_job``) are not run again; ``more``: further
    group functions (README's, from :mod:`docsite.readme_figures`: {name: function returning {name: figures}}); with
    "cpu", the numeric profile (:mod:`docsite.host_cpu`)."""
    chosen = _pages(pages)
    needed = sorted({g for name in chosen for g in LEDGER[name].groups})
    have, more, measured, seconds = dict(have or {}), dict(more or {}), {}, {}
    unknown = [g for g in needed if g not in have and g not in GROUPS and g not in more]
    if unknown:
        raise ValueError(f"docsite/page_ledger.py names groups no function measures: {unknown}")
    for group in tqdm(needed, desc="page figures", unit="group"):
        t0 = time.perf_counter()
        if group in have:
            measured[group] = have[group]
        elif group in GROUPS:
            measured[group] = GROUPS[group]()
        else:
            measured.update(more[group]())
        seconds[group] = round(time.perf_counter() - t0)
        tqdm.write(f"{group}: {seconds[group]} s")
    return {"pages": {**measured, "seconds": seconds, "checked_pages": chosen, "cpu": host_cpu()}}


def _pages(pages: list[str] | None) -> list[str]:
    checked = [n for n, e in LEDGER.items() if e.checks or isinstance(e, Covered)]
    if not pages:
        return checked
    names = [p if p.endswith(".md") else f"{p}.md" for p in pages]
    bad = [n for n in names if n not in checked]
    if bad:
        raise ValueError(f"--pages: {bad} have no checks in docsite/page_ledger.py; the pages with checks: {checked}")
    return names


def pages_differences(measured: dict) -> list[str]:
    """Every check of the pages in ``measured["checked_pages"]`` whose quoted text is not what was measured; []
    when all agree or nothing was measured."""
    bad = []
    for name in measured.get("checked_pages", []):
        flat = " ".join((DOCS / name).read_text().split())
        for pattern, templates in LEDGER[name].checks:
            if long_groups(templates):  # compared by --long (docsite/long_checks.py)
                continue
            wrong = check_difference(name, flat, pattern, templates, measured,
                                     ("its command printed no {} (see the group's docstring)", "its command prints"),
                                     measured.get("cpu"))
            if wrong:
                bad.append(wrong)
        bad += printed_differences(name, getattr(LEDGER[name], "printed", ()), measured)
    return bad


def long_differences(long: dict) -> list[str]:
    """Every Printed snippet of a long group in ``long`` (``figures["long"]``: {group: {"printed": output}}) that
    quotes a number its command did not print, every check naming a long group that ran whose quoted text is not
    what its files give (:func:`docsite.long_checks.long_check_differences`: the gust scorecards), every text block
    of its page that shows its output and differs from it (:func:`docsite.printed_blocks.block_differences`), and
    every group
    whose command crashed (an exit other than 0, or 1 for a study reporting a failed case) or did not write a file
    it reads; [] when all agree or nothing was run."""
    failed = [f"--long {name}: exit {g['exit']}, {[e for e in g.get('stderr', ()) if e]}"
              for name, g in long.items() if any(code not in (0, 1) for code in g.get("exit", ()))
              or any(str(e).endswith(": not written") for e in g.get("stderr", ()))]
    printed = [line for name, entry in LEDGER.items()
               for line in printed_differences(name, getattr(entry, "printed", ()), long)]
    return failed + long_check_differences(long) + block_differences(long) + printed


def coverage() -> dict[str, dict]:
    """Per page: {"status": covered | not yet, counts per kind, "loose": numbers no entry accounts for, "stale":
    entries that match nothing}."""
    report = {}
    for page in sorted(DOCS.glob("*.md")):
        entry = LEDGER.get(page.name)
        flat = " ".join(page.read_text().split())
        if not isinstance(entry, Covered):
            report[page.name] = {"status": "not yet" if entry else "missing from the ledger",
                                 "reason": getattr(entry, "reason", ""), "checks": len(getattr(entry, "checks", ())),
                                 "stale": [c for c, _ in getattr(entry, "checks", ()) if not re.search(c, flat)]}
            continue
        checks = [keyed(c, None) for c, _ in entry.checks if re.search(keyed(c, None), prose(page.read_text()))]
        stale = [c for c, _ in entry.checks if not re.search(keyed(c, None), flat)]
        printed = [s for p in entry.printed for s in p.snippets]
        history = [s for h in entry.history for s in (*h.snippets, h.date)]  # a record's date marks it on the page
        snippets = [*entry.given, *entry.timings, *entry.derived, *entry.not_rerun, *printed, *history]
        loose, missing = unaccounted(page, checks, snippets)
        report[page.name] = {"status": "covered", "loose": loose, "stale": stale + missing,
                             **{k: len(getattr(entry, k)) for k in ("checks", "given", "timings", "derived",
                                                                    "not_rerun")},
                             "printed": len(printed), "history": sum(len(h.snippets) for h in entry.history)}
    return report
