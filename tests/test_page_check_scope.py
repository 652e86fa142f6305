"""What a docs page's check compares is what the coverage counts as checked (a review of 2026-12-07): a check compares
every place its pattern matches, so each pattern must match exactly one place; and the output blocks, which the
coverage leaves to the long groups, must each be a long group's output. Every picture README or a page embeds (in
Markdown or HTML) has the command that draws it, and that command's module and subcommand exist.

Oracles: the page files themselves, the long groups' commands (docsite/long_figures.py), the import system and the
command line's own parser.
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


def test_every_picture_command_names_a_module_and_subcommand_that_exist():
    """docsite/pictures.py names the command that draws each picture; a command pointing at a module or a
    ``laddermill`` subcommand that does not exist passed every test (a review of 2026-12-07; the long groups had this
    check already: tests/test_page_history.py)."""
    import argparse
    import importlib.util

    from docsite.long_figures import argv_env
    from docsite.pictures import PICTURES
    from laddermill_gym.cli import build_parser

    subparsers = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    bad = []
    for pic in PICTURES:
        for command in pic.command.split(" && "):
            argv, _ = argv_env(command.replace("{out}", "out"))
            if importlib.util.find_spec(argv[0]) is None:
                bad.append((pic.name, f"no module {argv[0]}"))
            elif argv[0] == "laddermill_gym.cli" and argv[1] not in subparsers.choices:
                bad.append((pic.name, f"no subcommand laddermill {argv[1]}"))
    assert not bad, bad


def test_pictures_embedded_as_html_are_found():
    from docsite.pictures import IMAGE

    page = 'text ![a](figures/a.png) and <img src="figures/b.png" width="40%"> and <img alt="c" src=\'figures/c.png\'>'
    assert [md or html for md, html in IMAGE.findall(page)] == ["figures/a.png", "figures/b.png", "figures/c.png"]


def test_every_embedded_picture_has_its_command():
    """Each picture README or a docs page embeds is drawn by one command of docsite/pictures.py, and each picture
    there is embedded somewhere (a new picture without a command, or a command for a dropped picture, fails)."""
    from docsite.pictures import PICTURES, drawn, embedded

    shown, made = embedded(), drawn()
    assert set(shown) - set(made) == set(), {n: shown[n] for n in set(shown) - set(made)}
    assert set(made) - set(shown) == set(), sorted(set(made) - set(shown))
    assert len({p.name for p in PICTURES}) == len(PICTURES)
    assert all(p.kind in ("quick", "long", "training") and "{out}" in p.command for p in PICTURES)


def test_numbers_glued_to_a_unit_after_a_slash_or_without_a_leading_zero_are_quoted_numbers():
    """Counted by hand (a review of 2026-12-07 found these passed the coverage unseen): 427 and 12 of "427kW in 12ms",
    8.5 of "alpha=8.5deg", both of "11/12", ".95"; still not the units' and exponents' digits (1/s, R^2/6, 3D, v1)."""
    from docsite.page_numbers import NUMBER, prose

    def found(text):
        return [m.group(0) for m in NUMBER.finditer(prose(text))]

    assert found("427kW in 12ms, alpha=8.5deg, 11/12 held, .95 of it") == ["427", "12", "8.5", "11", "12", ".95"]
    assert found("1/s, m^2, R^2/6 and B^3/3, a 3D v1 wing at 20 m/s") == ["20"]


def test_the_api_pages_quote_no_figures():
    """docs/api/ holds the reference's intros (the reference itself is generated from the docstrings); the ledger covers
    the top-level pages only, so a figure written here would be checked by nothing (a review of 2026-12-07). They
    may cite a paper's year or an equation's number, listed here by hand."""
    from docsite.page_numbers import numbers, prose

    citations = {"quasisteady.md": ["2008"], "rotorcraft.md": ["6"]}  # Lansdorp et al. (2008); Roberts' eq. (6)
    for page in sorted((ROOT / "laddermill_gym" / "docs" / "api").glob("*.md")):
        flat = prose(page.read_text())
        assert [flat[a:b] for a, b in numbers(flat)] == citations.get(page.name, []), page.name
