"""One long group of page figures (:data:`docsite.long_figures.LONG`): a command whose printed output re-runs
numbers the docs quote, with what it cost and where its figures are."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Long:
    """A long group: the command (as typed; a leading ``NAME=VALUE`` sets the environment, ``laddermill`` is the
    package's CLI; several joined by `` && `` run in turn, their outputs concatenated), what it cost when last run,
    the page its figures are on, the files it writes whose figures the page quotes (a gust bench's CSV), and the
    ``$`` commands of the page's ``text`` blocks that show its output (:mod:`docsite.printed_blocks`; none: a block
    of the command itself, where the page has one)."""

    command: str
    cost: str
    page: str
    reads: tuple = ()  # files (from the repository root) the command writes whose text counts as printed
    shows: tuple = ()  # $ lines of the page's text blocks that are this command's printed output, line for line
    avx512: bool = False  # prints what the page shows only on a CPU with AVX-512 (its test is skipped elsewhere)
