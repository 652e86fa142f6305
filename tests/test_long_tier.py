"""The docs' long tier in the slow set: every long group of :data:`docsite.long_figures.LONG` (a command whose output
re-runs figures a docs page quotes) run in a fresh process, and the page's Printed snippets, text blocks and gust
scorecards compared with what it printed and wrote (:func:`docsite.page_figures.long_differences`), one test per
group, so that a stale figure fails ``python -m pytest -m slow``.

The groups take seconds to about an hour each (their costs: ``python -m docsite.readme_figures --long --list``), so
they carry the ``long`` mark as well: ``-m "slow and not long"`` leaves them out, ``-m long -k NAME`` runs one.

Oracle: the commands themselves, run now (nothing of an earlier run is read: a file a group reads is removed before
its command runs), against the numbers the pages quote.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.long_figures import LONG, measure_long  # noqa: E402
from docsite.page_figures import long_differences  # noqa: E402


@pytest.mark.slow
@pytest.mark.long
@pytest.mark.parametrize("name", sorted(LONG))
def test_the_long_group_prints_what_its_page_quotes(name, tmp_path):
    if LONG[name].avx512:
        import llvmlite.binding as ll

        if not ll.get_host_cpu_features().get("avx512f"):
            pytest.skip(f"{name} prints what {LONG[name].page} shows only on a CPU with AVX-512")
    figures = measure_long([name])
    (tmp_path / f"{name}.json").write_text(json.dumps(figures, indent=1))
    bad = long_differences(figures["long"])
    assert not bad, f"{LONG[name].page}: " + "\n".join(bad)


#: long groups whose output no page number reads, with why they are in the tier: their test checks that the command
#: still runs (exit 0, or 1 for a study that reports a failed case) and writes what it should
RUN_ONLY = {
    "w_step_cost": "CPU per step: work_precision.md quotes its figures as dated timings (load-dependent)",
    "stress_tethered_wing": "the tethered wing's stress cases alone; the page's records of them are dated History",
}


def test_every_long_group_is_compared_with_a_page():
    """Each long group names docs pages that exist, and a ledger entry reads its output (a Printed snippet, a check
    or a text block of its command), except the run-only groups named above; otherwise its test could not fail on a
    stale figure."""
    from docsite.long_checks import long_groups
    from docsite.page_ledger import LEDGER
    from docsite.printed_blocks import shown_blocks

    docs = ROOT / "laddermill_gym" / "docs"
    printed = {p.group for entry in LEDGER.values() for p in getattr(entry, "printed", ())}
    checked = long_groups(tuple(s for entry in LEDGER.values() for _, t in getattr(entry, "checks", ())
                                for s in (t if isinstance(t, tuple) else (t,))))
    pages = {name: g.page.split(", ") for name, g in LONG.items()}
    missing = [f"{name}: {p}" for name, ps in pages.items() for p in ps if not (docs / p).is_file()]
    blocks = {name for name, g in LONG.items() if not missing and any(
        c in [" ".join(w.split()) for w in (g.shows or (g.command,))]
        for p in pages[name] for c, _ in shown_blocks((docs / p).read_text()))}
    unread = set(LONG) - printed - checked - blocks
    assert not missing and unread == set(RUN_ONLY), (missing, sorted(unread ^ set(RUN_ONLY)))
