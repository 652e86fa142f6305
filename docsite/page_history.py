"""Dated records on a docs page: every :class:`docsite.ledger_kinds.History` snippet must sit in a paragraph that
carries its run's date (``2026-11-25``), or right after one that does (a table's or a printed block's caption is
the paragraph before it), or under a heading that does (a section of records, "## Earlier attempt (runs
of 2026-11-29)").

A paragraph is a block of the page between blank lines; the page's text is flattened as
:func:`docsite.page_numbers.prose` does (so a ledger snippet is found where the coverage test finds it).
"""

from __future__ import annotations

import re
from pathlib import Path

from docsite.page_numbers import prose

ISO_DATE = re.compile(r"^\d{4}-\d{2}-\d{2}$")
_BREAK = "\u00a7\u00a7para\u00a7\u00a7"  # a token no page writes, put between paragraphs before flattening


def paragraphs(text: str) -> list[tuple[int, int, str]]:
    """(start, end, text) of each paragraph of ``text`` in the coordinates of ``prose(text)``."""
    flat = prose(text)
    marked = prose(re.sub(r"\n[ \t]*\n", f"\n\n{_BREAK}\n\n", text))
    pieces = [p.strip() for p in marked.split(_BREAK)]
    spans, pos = [], 0
    for piece in pieces:
        if not piece:
            continue
        start = flat.find(piece, pos)
        if start < 0:  # a code span or fence across a blank line: the page as one paragraph
            return [(0, len(flat), flat)]
        spans.append((start, start + len(piece), piece))
        pos = start + len(piece)
    return spans


def undated(page: Path, date: str, snippets: tuple) -> list[str]:
    """The ``snippets`` of ``page`` (a History record's, dated ``date``) whose paragraph, the paragraph before it and
    its section's heading all lack ``date``; a snippet not on the page is named too."""
    flat = prose(page.read_text())
    paras = paragraphs(page.read_text())
    bad = []
    for snippet in snippets:
        text = " ".join(snippet.split())
        starts = [m.start() for m in re.finditer(re.escape(text), flat)]
        if not starts:
            bad.append(f"not on the page: {snippet!r}")
        for k, start in enumerate(starts):  # every place it appears: a copy elsewhere needs its date too
            end = start + len(text)
            hit = [i for i, (a, b, _) in enumerate(paras) if a < end and start < b]
            near = set(hit) | {i - 1 for i in hit if i > 0}  # the caption of a table or a printed block
            near |= {max((j for j in range(i + 1) if paras[j][2].startswith("#")), default=i) for i in hit}
            if not any(date in paras[i][2] for i in near):
                where = f" (occurrence {k + 1} of {len(starts)})" if len(starts) > 1 else ""
                bad.append(f"no {date} in its paragraph{where}: {snippet!r}")
    return bad


def record_problems(record) -> list[str]:
    """What a History record lacks: an ISO date, a command, a run, snippets."""
    bad = [] if ISO_DATE.match(record.date) else [f"date {record.date!r} is not YYYY-MM-DD"]
    bad += [f"empty {k}" for k in ("command", "run", "snippets") if not getattr(record, k)]
    return bad
