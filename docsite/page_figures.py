"""The docs pages' figures: re-run the commands the pages quote, compare each checked number, and report coverage.

``python -m docsite.readme_figures --pages [PAGE ...]`` runs the measurement groups the chosen pages' checks need
(:data:`GROUPS`, each one command in a fresh process, as a user types it; what it prints is parsed), writes them into
the JSON under ``"pages"`` and compares every check of :data:`docsite.page_ledger.LEDGER` with them: the text a
check's groups capture on the page must equal its template filled from the measured figures (the printed digits,
or the printed value rounded to the digits the page quotes). ``--pages`` alone re-runs every covered page.

Each group's cost on the shared 2-core machine (load 1-2, numba's cache warm): ``rotor_design`` 42 s,
``simulate_laddermill`` about 4 minutes (the periodic search, then 60 s of the 3D mill), ``simulate_tethered_wing``
about 30 s, ``main_job`` (README's demo, shared with README's figures) about 2 minutes.
"""

from __future__ import annotations

import re
import tempfile
import time
from pathlib import Path

from tqdm import tqdm

from docsite.page_ledger import LEDGER, Covered
from docsite.page_numbers import prose, unaccounted
from docsite.paper_figures import run_command

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "laddermill_gym" / "docs"
STUDY = "laddermill_gym.studies."


def _search(pattern: str, text: str, argv: list[str]) -> re.Match:
    m = re.search(pattern, text, re.M)
    if m is None:
        raise RuntimeError(f"python -m {' '.join(argv)} printed nothing matching {pattern!r}:\n{text[-2000:]}")
    return m


def rotor_design() -> dict:
    """Roberts' 35 m design at 15,000 and 30,000 ft: the wind of the 3.13 MW rating [m/s], its incidence alpha_c
    [deg] and the ideal C_p at that incidence."""
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
    return found


def simulate(scene_args: list[str]) -> dict:
    """``laddermill simulate SCENE_ARGS``: its RK4 step and estimated stable step [s], the simulated span [s], and
    how the run stopped (the first and last wing over the speed guard, or the ground contact's time and height)."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.cli", "simulate", *scene_args, "--out", tmp]
        out = run_command(argv, 1800)
    step = _search(r"^RK4 step ([\d.]+) s; estimated stability limit at the start ([\d.e-]+) s", out, argv)
    found = {"dt": step.group(1), "stable_step": float(step.group(2)),
             "simulated": _search(r"^simulated ([\d.]+) s in", out, argv).group(1)}
    wings = re.findall(r"wing (\d+) speed [\d.e+]+ m/s > (\d+) m/s", out)
    if wings:
        found.update(first_wing=wings[0][0], last_wing=wings[-1][0], guard=wings[0][1])
    contact = re.search(r"ground contact at t = ([\d.]+) s: node (\d+) at height ([-\d.e]+) m", out)
    if contact:
        found.update(contact_t=contact.group(1), contact_node=contact.group(2), contact_height=contact.group(3))
    return found


#: Page groups: name -> the function that measures it (each runs its command in a fresh process).
GROUPS = {"rotor_design": rotor_design,
          "simulate_laddermill": lambda: simulate(["laddermill", "--start", "periodic", "--direction-step", "0.01",
                                                   "--time", "60", "--allow-breakdown"]),
          "simulate_tethered_wing": lambda: simulate(["tethered_wing", "--time", "120", "--direction-step", "0.01"])}


def measure_pages(pages: list[str] | None = None, have: dict | None = None) -> dict:
    """{"pages": {group: figures}} for the groups the ``pages`` (default: every covered page) check; groups already
    in ``have`` (README's figures measured in the same run, e.g. ``main_job``) are not run again."""
    from docsite import readme_figures

    chosen = _pages(pages)
    needed = sorted({g for name in chosen for g in LEDGER[name].groups})
    have, measured, seconds = dict(have or {}), {}, {}
    for group in tqdm(needed, desc="page figures", unit="group"):
        t0 = time.perf_counter()
        if group in have:
            measured[group] = have[group]
        elif group in GROUPS:
            measured[group] = GROUPS[group]()
        else:  # a README group (readme_figures.main_job ...): {group: ...}
            measured.update(getattr(readme_figures, group)())
        seconds[group] = round(time.perf_counter() - t0)
        tqdm.write(f"{group}: {seconds[group]} s")
    return {"pages": {**measured, "seconds": seconds, "checked_pages": chosen}}


def _pages(pages: list[str] | None) -> list[str]:
    covered = [n for n, e in LEDGER.items() if isinstance(e, Covered)]
    if not pages:
        return covered
    names = [p if p.endswith(".md") else f"{p}.md" for p in pages]
    bad = [n for n in names if n not in covered]
    if bad:
        raise ValueError(f"--pages: {bad} are not covered pages of docsite/page_ledger.py; the covered: {covered}")
    return names


def pages_differences(measured: dict) -> list[str]:
    """Every check of the pages in ``measured["checked_pages"]`` whose quoted text is not what was measured; []
    when all agree or nothing was measured."""
    bad = []
    for name in measured.get("checked_pages", []):
        flat = " ".join((DOCS / name).read_text().split())
        for pattern, templates in LEDGER[name].checks:
            m = re.search(pattern, flat)
            if m is None:
                bad.append(f"docs/{name}: no text matches the check {pattern!r}")
                continue
            want = tuple(t.format(**measured) for t in templates)
            if m.groups() != want:
                bad.append(f"docs/{name}: '{m.group(0)}' quotes {m.groups()}; its command prints {want}")
    return bad


def coverage() -> dict[str, dict]:
    """Per page: {"status": covered | not yet, counts per kind, "loose": numbers no entry accounts for, "stale":
    entries that match nothing}."""
    report = {}
    for page in sorted(DOCS.glob("*.md")):
        entry = LEDGER.get(page.name)
        if not isinstance(entry, Covered):
            report[page.name] = {"status": "not yet" if entry else "missing from the ledger",
                                 "reason": getattr(entry, "reason", "")}
            continue
        flat = " ".join(page.read_text().split())
        checks = [c for c, _ in entry.checks if re.search(c, prose(page.read_text()))]
        stale = [c for c, _ in entry.checks if not re.search(c, flat)]
        snippets = [*entry.given, *entry.timings, *entry.derived, *entry.not_rerun]
        loose, missing = unaccounted(page, checks, snippets)
        report[page.name] = {"status": "covered", "loose": loose, "stale": stale + missing,
                             **{k: len(getattr(entry, k)) for k in ("checks", "given", "timings", "derived",
                                                                    "not_rerun")}}
    return report
