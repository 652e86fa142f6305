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
