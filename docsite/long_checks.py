"""Checks of the docs pages whose figures a long group gives (:data:`docsite.long_figures.LONG`): a check of
:data:`docsite.page_ledger.LEDGER` whose templates name a long group (``{gusts_v1_rotorcraft[scorecard][lqr]}``) is
compared only when that group ran (``python -m docsite.readme_figures --skip-readme --long NAME``), against the
figures parsed from the files the group reads (:func:`docsite.gust_scorecards.scorecards`); ``--pages`` leaves it
out. Compared as a page check is (:func:`docsite.printed_numbers.template_agrees`).
"""

from __future__ import annotations

import re
from pathlib import Path

from docsite.long_figures import LONG
from docsite.page_ledger import LEDGER
from docsite.printed_numbers import template_agrees

DOCS = Path(__file__).resolve().parent.parent / "laddermill_gym" / "docs"
FIELD = re.compile(r"\{([\w.]+)\[")  # a template's group name


def long_groups(templates: tuple) -> set[str]:
    """The long groups a check's templates name (empty for a check of page groups)."""
    return {g for t in templates for g in FIELD.findall(t)} & set(LONG)


def long_check_differences(long: dict) -> list[str]:
    """Every check that names a long group in ``long`` ({group: figures}, as ``measure_long`` returns them under
    "long") whose quoted text is not what the group's files give; [] when all agree or none ran."""
    bad = []
    for name, entry in LEDGER.items():
        flat = None
        for pattern, templates in entry.checks:
            groups = long_groups(templates)
            if not groups or not groups <= set(long):
                continue
            flat = flat or " ".join((DOCS / name).read_text().split())
            m = re.search(pattern, flat)
            if m is None:
                bad.append(f"docs/{name}: no text matches the check {pattern!r}")
                continue
            try:
                want = tuple(t.format(**long) for t in templates)
            except (KeyError, IndexError) as e:
                bad.append(f"docs/{name}: '{m.group(0)}': --long {sorted(groups)} gave no {e} (did it crash?)")
                continue
            if len(m.groups()) != len(want) or not all(template_agrees(q, w) for q, w in
                                                       zip(m.groups(), want, strict=True)):
                bad.append(f"docs/{name}: '{m.group(0)}' quotes {m.groups()}; --long {sorted(groups)} gives {want}")
    return bad
