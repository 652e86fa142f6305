"""Checks of the docs pages whose figures a long group gives (:data:`docsite.long_figures.LONG`): a check of
:data:`docsite.page_ledger.LEDGER` whose templates name a long group (``{gusts_v1_rotorcraft[scorecard][lqr]}``) is
compared only when that group ran (``python -m docsite.readme_figures --skip-readme --long NAME``), against the
figures parsed from the files the group reads (:func:`docsite.gust_scorecards.scorecards`) and the ratios, ranges
and bounds worked from its printed columns (:mod:`docsite.printed_ratios`); ``--pages`` leaves it out. Compared as a
page check is (:func:`docsite.printed_numbers.template_agrees`).
"""

from __future__ import annotations

import re
from pathlib import Path

from docsite.gust_scorecards import scenario_key
from docsite.host_cpu import check_cpu, host_cpu, is_keyed, keyed
from docsite.long_figures import LONG
from docsite.page_ledger import LEDGER
from docsite.printed_numbers import template_agrees
from docsite.printed_ratios import with_ratios

DOCS = Path(__file__).resolve().parent.parent / "laddermill_gym" / "docs"
FIELD = re.compile(r"\{([\w.]+)\[")  # a template's group name


def check_difference(name: str, flat: str, pattern: str, templates: tuple, figures: dict,
                     words: tuple[str, str], cpu: str | None = None) -> str | None:
    """What is wrong with one check of page ``name`` (its text ``flat``, whitespace flattened): no text matches
    ``pattern`` (a pattern quoting a figure per numeric profile, :mod:`docsite.host_cpu`, is compared at ``cpu``'s
    figure, default this process's profile); ``figures`` lack a field a template names (``words[0] + field``, e.g. "its
    command printed no {field} (...)"); or the quoted groups are not what the templates give (``words[1] + figures``);
    None when it agrees."""
    if check_cpu(pattern) not in (None, cpu or host_cpu()):
        return None  # another profile's figure (docsite/host_cpu.py): compared on that profile
    if is_keyed(pattern):
        cpu = cpu or host_cpu()
        found = list(re.finditer(keyed(pattern, cpu), flat))
        if not found:
            return f"docs/{name}: quotes no figure for this profile ({cpu}, docsite/host_cpu.py) in the check " \
                   f"{pattern!r}"
    else:
        found = list(re.finditer(pattern, flat))
    if not found:
        return f"docs/{name}: no text matches the check {pattern!r}"
    try:
        want = tuple(t.format(**figures) for t in templates)
    except (KeyError, IndexError) as e:
        return f"docs/{name}: '{found[0].group(0)}': {words[0].format(e)}"
    for m in found:  # every place the page quotes it (the coverage counts each as accounted for)
        if len(m.groups()) != len(want) or not all(_agrees(q, w) for q, w in zip(m.groups(), want, strict=True)):
            return f"docs/{name}: '{m.group(0)}' quotes {m.groups()}; {words[1]} {want}"
    return None


def _agrees(quoted: str | None, want: str) -> bool:
    """A quoted text against its filled template: a template marked ``@`` is a gust bench's set of scenario ids, which
    the quoted list of names must name (:func:`docsite.gust_scorecards.scenario_key`); else
    :func:`docsite.printed_numbers.template_agrees`."""
    if want.startswith("@"):
        return quoted is not None and scenario_key(quoted) == want[1:]
    return template_agrees(quoted, want)


def long_groups(templates: tuple) -> set[str]:
    """The long groups a check's templates name (empty for a check of page groups)."""
    return {g for t in templates for g in FIELD.findall(t)} & set(LONG)


def long_check_differences(long: dict) -> list[str]:
    """Every check that names a long group in ``long`` ({group: figures}, as ``measure_long`` returns them under
    "long") whose quoted text is not what the group's files give, or what :mod:`docsite.printed_ratios` works from its
    printed output; [] when all agree or none ran."""
    long, bad = with_ratios(long), []
    for name, entry in LEDGER.items():
        flat = None
        for pattern, templates in entry.checks:
            groups = long_groups(templates)
            if not groups or not groups <= set(long):
                continue
            flat = flat or " ".join((DOCS / name).read_text().split())
            cpus = {long[g].get("cpu") for g in groups} - {None}
            if len(cpus) > 1:
                bad.append(f"docs/{name}: the check {pattern!r} joins groups run on different profiles {sorted(cpus)}")
                continue
            wrong = check_difference(name, flat, pattern, templates, long,
                                     (f"--long {sorted(groups)} gave no {{}} (did it crash?)",
                                      f"--long {sorted(groups)} gives"), next(iter(cpus), None))
            if wrong:
                bad.append(wrong)
    return bad
