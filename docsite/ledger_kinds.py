"""The kinds of a docs page's ledger entry (:mod:`docsite.page_ledger`): a covered page and a page not yet
covered, and two kinds of a covered page's snippets: :class:`Printed` (every number a command prints: re-run by its
group) and :class:`History` (figures of a dated training run that is not kept: a record, marked so on the page).
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Covered:
    groups: tuple = ()
    checks: tuple = ()
    given: tuple = ()
    timings: tuple = ()
    derived: tuple = ()
    not_rerun: tuple = field(default=())
    printed: tuple = ()  # Printed entries
    history: tuple = ()  # History entries


@dataclass(frozen=True)
class Printed:
    """Snippets each of whose numbers ``group``'s command prints (:mod:`docsite.printed_numbers` compares them by
    value at the digits the page quotes). ``group`` is a page group (:data:`docsite.page_figures.GROUPS`, whose
    figures carry the command's output under ``"printed"``) or a long group (:data:`docsite.long_figures.LONG`, run
    only by ``python -m docsite.readme_figures --long NAME``). ``cpu``: the numeric profile whose run printed them
    (:mod:`docsite.host_cpu`: numpy's SIMD loops and OpenBLAS's kernels), for figures that move with it: compared
    only when the group ran on that profile; "" for figures every profile prints."""

    group: str
    snippets: tuple
    cpu: str = ""


@dataclass(frozen=True)
class History:
    """Figures of a run that is not kept (a training run, a run of earlier code): their numbers depend on the CPU,
    the run and the code of the day, so they are a dated record, not re-run. ``date`` (ISO, the run's day, from git
    log or the config's comment) must appear in the paragraph of every snippet on the page, or in the paragraph just
    before its table (tests/test_page_history.py); ``command``: what made the figures; ``run``: which run (its
    config, seed, length)."""

    date: str
    command: str
    run: str
    snippets: tuple


@dataclass(frozen=True)
class NotYet:
    """A page whose numbers are not all accounted for yet: why, and the checks it has already (compared as a
    covered page's are; the rest of its numbers unchecked)."""

    reason: str
    groups: tuple = ()
    checks: tuple = ()


#: A table row's end in a flattened page, roughly: no one-word cell after the last ``|`` (the next row begins ``| ``),
#: so that a check of a short row does not match the first cells of a longer row of numbers; a next cell of several
#: words or an empty one is not seen (tests/test_page_check_scope.py catches a check matching twice).
ROW_END = r"(?! [^|\s]+ \|)"


def row_check(head: str, group: str, keys: tuple) -> tuple:
    """A check of one whole Markdown table row: ``head`` (a regular expression of its first cells, as the flattened
    page writes them, at a row's start) followed by one cell per key and the row's end, each cell compared exactly
    with ``{group[key]}`` (``group`` may index deeper, ``pumping_crosswind[c0]``)."""
    return (r"(?<=\| )" + head + "".join(r" \| (\S+)" for _ in keys) + r" \|" + ROW_END,
            tuple(f"{{{group}[{k}]}}" for k in keys))
