"""The kinds of a docs page's ledger entry (:mod:`docsite.page_ledger`): a covered page and a page not yet
covered.
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


@dataclass(frozen=True)
class NotYet:
    """A page whose numbers are not all accounted for yet: why, and the checks it has already (compared as a
    covered page's are; the rest of its numbers unchecked)."""

    reason: str
    groups: tuple = ()
    checks: tuple = ()


def row_check(head: str, group: str, keys: tuple) -> tuple:
    """A check of one Markdown table row: ``head`` (a regular expression of its first cells, as the flattened page
    writes them) followed by one cell per key, each compared exactly with ``{group[key]}`` (``group`` may index
    deeper, ``pumping_crosswind[c0]``)."""
    return (head + "".join(r" \| (\S+)" for _ in keys) + r" \|", tuple(f"{{{group}[{k}]}}" for k in keys))
