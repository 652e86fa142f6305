"""The numbers a docs page quotes, and which of them the ledger (:mod:`docsite.page_ledger`) accounts for.

A page's *quoted numbers* are the numerals of its prose, tables, picture captions and unlabelled fenced blocks (a
command's printed output); left out are code spans and fenced or indented blocks of commands (``bash``, ``python``,
``yaml``...: a command's arguments are its inputs), link targets, and numerals inside words (``3D``, ``v1``,
``Fig6``) and units (the 1 of ``1/s``, the 2 of ``m^2``). The text is compared with whitespace flattened, so a
ledger entry may span a line break.

A number is *accounted for* when it lies inside a match of one of its page's entries: a check (a regular expression
whose groups the re-run compares with what a command prints) or a listed snippet (a given: an input, a paper's own
figure, a date or a count of things; a dated machine timing; a figure read off a picture or worked by hand, not
printed by any command). :func:`unaccounted` returns the rest.
"""

from __future__ import annotations

import re
from pathlib import Path

FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```[ \t]*$", re.M | re.S)
COMMENT = re.compile(r"<!--.*?-->", re.S)
SNIPPET = re.compile(r"^.*--8<--.*$", re.M)  # pymdownx.snippets' include line: a file name, not a figure
COMMAND_FENCES = {"bash", "sh", "shell", "console", "python", "py", "yaml", "yml", "json", "toml", "text", "ini"}
# a line that starts with one of these is a command (its numbers are inputs)
COMMANDS = r"(?:python3?\b|laddermill\b(?!_)|cp\b|NUMBA_|pip\b|make\b|git\b|mkdocs\b|ray\b|for\b|done\b|# )"
INDENTED = re.compile(rf"^(?: {{4}}|\t)+(?:\$ )?{COMMANDS}[^\n]*$", re.M)
COMMAND_LINE = re.compile(rf"^ *(?:\$ )?{COMMANDS}[^\n]*$", re.M)  # in an unlabelled block: a command, not output
CODE_SPAN = re.compile(r"(`+)(?!`).*?(?<!`)\1(?!`)", re.S)
LINK_TARGET = re.compile(r"\]\([^)\s]*\)")
UNIT = r"(?:kW|MW|GW|W|kN|N|ms|s|min|h|km|mm|cm|m|deg|rad|Hz|kg|MB|GB|kB|J|MJ|kJ|Wh|kWh)(?![\w.])"  # glued: 427kW
NUMBER = re.compile(r"(?:(?<![\w.^/])[-+])?(?:(?<![\w.^/])|(?<=[^^]\d/))(?:\d(?:[\d,]*\d)?(?:\.\d+)?|(?<![\w.])\.\d+)"
                    rf"(?:e[-+]?\d+)?x?(?=(?:{UNIT})|(?!\w|\.\d|/[a-zA-Z]))")


def prose(text: str) -> str:
    """``text`` with code (command blocks, code spans) and link targets blanked, whitespace flattened."""
    text = SNIPPET.sub(" ", COMMENT.sub(" ", text))
    text = FENCE.sub(lambda m: COMMAND_LINE.sub(" ", m.group(2)) if m.group(1).lower() not in COMMAND_FENCES else " ",
                     text)
    text = INDENTED.sub(" ", text)
    text = CODE_SPAN.sub(" ", text)
    text = LINK_TARGET.sub("]", text)
    return " ".join(text.replace("```", " ").split())


def numbers(flat: str) -> list[tuple[int, int]]:
    """The spans of the quoted numbers in ``flat`` (a :func:`prose` text)."""
    return [m.span() for m in NUMBER.finditer(flat)]


def spans_of(flat: str, pattern: str, literal: bool) -> list[tuple[int, int]]:
    """Where ``pattern`` (a snippet when ``literal``, else a regular expression) matches ``flat``."""
    regex = re.escape(" ".join(pattern.split())) if literal else pattern
    return [m.span() for m in re.finditer(regex, flat)]


def unaccounted(page: Path, checks: list[str], snippets: list[str]) -> tuple[list[str], list[str]]:
    """(the numbers of ``page`` outside every check and snippet, each with its context; the checks and snippets
    that match nowhere on the page)."""
    flat = prose(page.read_text())
    covered, missing = [], []
    for pattern, literal in [(c, False) for c in checks] + [(s, True) for s in snippets]:
        found = spans_of(flat, pattern, literal)
        covered += found
        if not found:
            missing.append(pattern)
    loose = [f"{flat[a:b]!r} in '...{flat[max(0, a - 50):b + 30]}...'" for a, b in numbers(flat)
             if not any(s <= a and b <= e for s, e in covered)]
    return loose, missing
