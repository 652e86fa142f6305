"""What a docs page's check compares is what the coverage counts as checked (a review of 2026-12-07): a check compares
every place its pattern matches, so each pattern must match exactly one place; and the output blocks, which the
coverage leaves to the long groups, must each be a long group's output.

Oracles: the page files themselves and the long groups' commands (docsite/long_figures.py).
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.page_ledger import LEDGER  # noqa: E402


def test_every_check_matches_one_place_on_its_page():
    """A check compares every place its pattern matches, and the coverage counts each as accounted for: a pattern
    that also matched another table's row (a longer row's first cells, a row whose second cell is the label) or another
    run's sentence counted those numbers as checked while comparing them with the wrong figures (a review of
    2026-12-07). Each pattern, per numeric profile where it quotes one, must match exactly once."""
    import re

    from docsite.host_cpu import PROFILES, check_cpu, is_keyed, keyed

    bad = {}
    for name, entry in LEDGER.items():
        page = ROOT / "laddermill_gym" / "docs" / name
        if not getattr(entry, "checks", ()) or not page.exists():
            continue
        flat = " ".join(page.read_text().split())
        for pattern, _ in entry.checks:
            cpus = [c for c in PROFILES if check_cpu(pattern) in (None, c)]
            for text in {keyed(pattern, c) for c in cpus} if is_keyed(pattern) else {pattern}:
                n = len(re.findall(text, flat))
                if n > 1 or (n == 0 and not is_keyed(pattern)):  # a profile's figure may be quoted for one only
                    bad[f"{name}: {pattern[:100]}"] = n
    assert not bad, f"checks matching no place or more than one (make the pattern name its own table or sentence): " \
                    f"{bad}"


def test_every_text_block_with_figures_is_a_long_groups_output():
    """The numbers coverage leaves ``text`` blocks out (docsite/page_numbers.COMMAND_FENCES): only printed_blocks
    compares them, and only a block whose ``$ COMMAND`` lines are all long groups' commands or shows. A block with
    figures but no ``$`` line (mill_fast.md's drift table until 2026-12-07) or with one no group runs
    (power_curve.md's merged table) was compared with nothing (a review of 2026-12-07)."""
    from docsite.long_figures import LONG
    from docsite.page_numbers import FENCE, NUMBER
    from docsite.printed_blocks import DOCS

    wanted = {" ".join(c.split()) for g in LONG.values() for c in (g.shows or (g.command,))}
    bad = []
    for page in sorted(DOCS.glob("*.md")):
        text = page.read_text()
        for m in FENCE.finditer(text):
            if m.group(1).lower() != "text" or not NUMBER.search(m.group(2)):
                continue
            lines = [x for x in m.group(2).splitlines() if x.strip()]
            line = text[:m.start()].count("\n") + 1
            if not lines or not lines[0].startswith("$ "):
                bad.append(f"{page.name}:{line}: figures before any $ line")
            bad += [f"{page.name}:{line}: no long group runs {x[2:]!r}" for x in lines
                    if x.startswith("$ ") and " ".join(x[2:].split()) not in wanted]
    assert not bad, bad
