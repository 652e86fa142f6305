"""A long group's printed output against the ``text`` blocks of its page that show it, line for line.

A page may show a command's output as a fenced ``text`` block: a line ``$ COMMAND`` and the lines it printed, up to
the next ``$`` line or the end of the fence. Such blocks are commands' blocks to :mod:`docsite.page_numbers` (their
numbers are not the page's quoted numbers), so no :class:`docsite.ledger_kinds.Printed` snippet can check them; this
module does, for the long groups (:data:`docsite.long_figures.LONG`) that ran: every block of the group's page whose
``$`` line is one of the commands the group shows (:attr:`docsite.long_figures.Long.shows`, else its own command) must
be the group's printed output, each line right-stripped, leaving out the ``wrote FILE`` lines where the block has
none; a block line ``...`` stands for any run of printed lines (the page elides a table). A stale row, a row the run
no longer prints or a row it prints that the block lacks is named with the first line that differs.
"""

from __future__ import annotations

import re
from pathlib import Path

from docsite.long_figures import LONG

DOCS = Path(__file__).resolve().parent.parent / "laddermill_gym" / "docs"
TEXT_FENCE = re.compile(r"^```text[ \t]*\n(.*?)^```[ \t]*$", re.M | re.S)
ELIDED = "..."


def shown_blocks(page_text: str) -> list[tuple[str, list[str]]]:
    """The (command, printed lines) of every ``$ COMMAND`` line of the page's ``text`` fences, in page order; the
    lines right-stripped."""
    found: list[tuple[str, list[str]]] = []
    for fence in TEXT_FENCE.finditer(page_text):
        current = None
        for line in fence.group(1).splitlines():
            if line.startswith("$ "):
                current = (" ".join(line[2:].split()), [])
                found.append(current)
            elif current is not None:
                current[1].append(line.rstrip())
    return found


def block_difference(block: list[str], printed: str) -> str | None:
    """What differs between a page's block (its lines after ``$ COMMAND``) and the command's ``printed`` output:
    None when they are the same lines (``wrote`` lines left out of the output where the block has none; a block
    line ``...`` matching any run of lines, the fewest that let the rest agree); else the first line that differs,
    as "block line N 'TEXT' where it printed 'TEXT'"."""
    lines = [line.rstrip() for line in printed.splitlines()]
    if not any(line.startswith("wrote ") for line in block):
        lines = [line for line in lines if not line.startswith("wrote ")]
    while lines and not lines[-1]:
        lines.pop()
    block = list(block)
    while block and not block[-1]:
        block.pop()
    i = j = 0
    while i < len(block):
        if block[i] == ELIDED:
            rest = block[i + 1:]
            if not rest:
                return None
            j = next((k for k in range(j, len(lines)) if lines[k] == rest[0]), len(lines))
            i += 1
            continue
        if j >= len(lines) or lines[j] != block[i]:
            got = lines[j] if j < len(lines) else "(nothing more)"
            return f"block line {i + 1} {block[i]!r} where it printed {got!r}"
        i, j = i + 1, j + 1
    if j < len(lines):
        return f"the block ends where it printed {lines[j]!r} (and {len(lines) - j - 1} more lines)"
    return None


def block_differences(long: dict) -> list[str]:
    """Every ``text`` block of a long group's page that shows one of the group's commands (``Long.shows``, else the
    command) and is not what the group printed (``long``: {group: {"printed": output}}, as
    :func:`docsite.long_figures.measure_long` gives it); a group with ``shows`` whose page has no such block is
    named too (a renamed command would otherwise go unchecked); [] when all agree or none ran."""
    bad = []
    for name, figures in long.items():
        group = LONG.get(name)
        if group is None or not isinstance(figures, dict) or "printed" not in figures:
            continue
        wanted = [" ".join(c.split()) for c in (group.shows or (group.command,))]
        pages = [p for p in group.page.split(", ") if (DOCS / p).is_file()]  # "features.md, wind.md"
        blocks = [(p, c, lines) for p in pages for c, lines in shown_blocks((DOCS / p).read_text()) if c in wanted]
        if group.shows and not blocks:
            bad.append(f"docs/{group.page}: --long {name} shows {group.shows} but no text block has that $ line")
        for page, command, lines in blocks:
            wrong = block_difference(lines, figures["printed"])
            if wrong:
                bad.append(f"docs/{page}: the block of '$ {command}': --long {name}: {wrong}")
    return bad
