"""The docs pages' dated records and the long tier of the page figures (issue 33, point 6).

Oracles: hand-written Markdown pages whose paragraphs, tables and headings are counted by hand; hand-rounded
numbers (25.64 printed is 25.6 quoted, not 25.7; 236273.0 W printed is 236.273 kW quoted); the pages themselves
(every History snippet's paragraph must carry its date); the commands' own argument parsers (a long group names
a module that exists).
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.ledger_kinds import History, Printed  # noqa: E402
from docsite.long_figures import LONG, argv_env  # noqa: E402
from docsite.page_figures import GROUPS, long_differences  # noqa: E402
from docsite.page_history import paragraphs, record_problems, undated  # noqa: E402
from docsite.page_ledger import LEDGER  # noqa: E402
from docsite.printed_numbers import missing, printed_differences  # noqa: E402

DOCS = ROOT / "laddermill_gym" / "docs"


def test_every_history_number_carries_its_date():
    """Each History record has a date, a command, a run and snippets; each snippet's paragraph (or its caption, or its
    section's heading) on the page names the record's date."""
    problems = {}
    for name, entry in LEDGER.items():
        for record in getattr(entry, "history", ()):
            bad = record_problems(record) + undated(DOCS / name, record.date, record.snippets)
            if bad:
                problems.setdefault(name, []).extend(bad)
    assert problems == {}
    assert sum(len(r.snippets) for e in LEDGER.values() for r in getattr(e, "history", ())) > 50


def test_a_history_snippet_without_its_date_is_named(tmp_path):
    """A hand-made page: four paragraphs, a table and a heading (counted by hand)."""
    page = tmp_path / "p.md"
    page.write_text("# Title\n\nPPO made 9125 W (run of 2026-11-24).\n\nThe LQR made 1771 W.\n\n"
                    "Its log (run of 2026-11-29):\n\n| round | R^2 |\n|---|---|\n| 2 | 0.9941 |\n\n"
                    "## Tried (runs of 2026-11-28)\n\nA ridge of 1e-4 shrank the gains 20x.\n")
    assert len(paragraphs(page.read_text())) == 7
    assert undated(page, "2026-11-24", ("PPO made 9125 W",)) == []
    assert undated(page, "2026-11-29", ("| 2 | 0.9941 |",)) == []  # the table's caption carries it
    assert undated(page, "2026-11-28", ("shrank the gains 20x",)) == []  # its section's heading carries it
    assert undated(page, "2026-11-24", ("The LQR made 1771 W.",)) == []  # the paragraph before carries it
    bad = undated(page, "2026-11-24", ("shrank the gains 20x", "made 5 kW"))
    assert len(bad) == 2 and "2026-11-24" in bad[0] and "not on the page" in bad[1]
    assert record_problems(History("29.11.2026", "", "a run", ())) == [
        "date '29.11.2026' is not YYYY-MM-DD", "empty command", "empty snippets"]


def test_the_printed_comparison_names_a_changed_figure():
    """Quoted numbers against a command's output: the printed value rounded to the quoted digits, by magnitude where
    the page writes no sign, near one another (worked by hand; the rule's own cases: tests/test_printed_rule.py)."""
    out = "3.13 MW at 25.64 m/s: C_p 0.1145; ppo_chain 5990.46 300.0 0.8103 236273.0 -"
    assert missing("3.13 MW is reached at 25.6 m/s", out) == []
    assert missing("C_p 0.114", out) == [] and missing("C_p 0.115", out) == []
    far = "3.13 at 25.64 " + " ".join(str(k) for k in range(200, 270)) + " C_p 0.1145"
    assert missing("25.64 and 0.1145", far) == ["0.1145"]  # more than a window of printed numbers apart
    assert missing("1.8 MJ in 138 s, 404 m", "t = 137.95 s: 1813 kJ, |dy| 404.2 m") == []  # any order, kJ as MJ
    assert missing("falls by 0.25 deg per m/s", "-0.252 | -0.252") == []  # the page's magnitude of a slope
    assert missing("C_p 0.113", out) == ["0.113"]
    assert missing("25.7 m/s", out) == ["25.7"]
    assert missing("max |dy| 0.8103 m, 236.273 kW", out) == []  # the page's kW of a printed W
    assert missing("1,555 s and 8.7x", "1555.0 s, ratio 8.70") == []
    entries = (Printed("g", ("at 25.6 m/s",)), Printed("other", ("at 99 m/s",)))
    assert printed_differences("p.md", entries, {"g": {"printed": out}}) == []
    bad = printed_differences("p.md", entries, {"g": {"printed": "at 26.1 m/s"}})
    assert bad == ["docs/p.md: g printed none of ['25.6'] in 'at 25.6 m/s'"]


def test_every_printed_group_has_its_command():
    """A Printed entry names a long group (a command of python -m or laddermill whose module exists) or a page group
    whose figures carry its output; long groups stay out of the default and slow sets."""
    named = {p.group for e in LEDGER.values() for p in getattr(e, "printed", ())}
    assert named - set(LONG) - set(GROUPS) == set()
    assert set(LONG) & set(GROUPS) == set()
    assert set(LONG) & {g for e in LEDGER.values() for g in e.groups} == set()
    for name, group in LONG.items():
        for command in group.command.split(" && "):
            argv, _ = argv_env(command)
            assert importlib.util.find_spec(argv[0]) is not None and "&&" not in argv, (name, command)
        assert group.page and group.cost


def test_long_list_prints_every_group_and_its_command(capsys):
    from docsite.readme_figures import main

    assert main(["--long", "--list"]) == 0
    out = capsys.readouterr().out
    assert all(f"{name} (" in out and group.command in out for name, group in LONG.items())


def test_a_long_run_names_a_changed_figure():
    """learned_mill.md's 0.1 rad chain sentence against an evaluate-like output: the page's figures pass; a changed
    excursion is named."""
    good = "ppo_chain 6000.1 300.0 0.8103 236273.0 -\nlqr:central 6001.2 300.0 0.8052 237510.0 -"
    assert long_differences({"chain_step_01": {"printed": good}}) == []
    bad = long_differences({"chain_step_01": {"printed": good.replace("0.8103", "0.9103")}})
    assert len(bad) == 1 and "learned_mill.md" in bad[0] and "0.8103" in bad[0]
    assert long_differences({}) == []


def test_a_crashed_or_silent_long_run_is_named_not_compared(tmp_path):
    """A command that crashed (exit 2: an argument error; a numba TypingError exits 1 with no output) or did not
    write the file the group reads is named whatever the page says; a study's exit 1 with its output counts."""
    good = "ppo_chain 6000.1 300.0 0.8103 236273.0 -\nlqr:central 6001.2 300.0 0.8052 237510.0 -"
    assert long_differences({"chain_step_01": {"printed": good, "exit": [1], "stderr": [""]}}) == []
    crashed = long_differences({"chain_step_01": {"printed": good, "exit": [2], "stderr": ["usage: ..."]}})
    assert len(crashed) == 1 and "chain_step_01" in crashed[0] and "exit [2]" in crashed[0]
    unwritten = {"printed": "", "exit": [1], "stderr": ["", "results/long/x/gust_bench.csv: not written"]}
    assert any("not written" in line for line in long_differences({"gusts_v1_rotorcraft": unwritten}))
