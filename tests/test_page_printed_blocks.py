"""The text blocks a page shows as a long group's output, compared line for line with what the group prints (issue 33,
point 6: a stale figure must fail the checks; docsite/printed_blocks.py). Hand-made outputs, shaped as
``laddermill power-curve`` prints them, with one row changed by hand, are the oracle: the unchanged output agrees, the
changed row is named, a row the page lacks or the run no longer prints is named.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.long_figures import LONG  # noqa: E402
from docsite.page_figures import long_differences  # noqa: E402
from docsite.printed_blocks import DOCS, block_difference, block_differences, shown_blocks  # noqa: E402

HEADER = "   V0   V_c  ramp [s]  periodic   P [kW]"
ROW_9 = " 14.0  9.00      900  False      812.3"
ROW_10 = " 14.0 10.00     1000  False     1174.2"
PAGE = f"""Some prose, 3 numbers.

```text
$ laddermill power-curve --winds 14   --out results/x
{HEADER}
{ROW_9}
{ROW_10}
V0 = 14.0 m/s: no periodic case within the limit
$ laddermill power-curve --table a.json b.json
...
V0 = 14.0 m/s: best V_c 8.0 m/s, 763.6 kW
```

```bash
$ laddermill power-curve --winds 14 --out results/x
```
"""
OUTPUT = (f"{HEADER}\n{ROW_9}   \n{ROW_10}\nV0 = 14.0 m/s: no periodic case within the limit\n"
          "wrote results/x/power_curve.csv\n")


def test_blocks_are_split_at_their_dollar_lines_in_text_fences_only():
    blocks = shown_blocks(PAGE)
    assert [c for c, _ in blocks] == ["laddermill power-curve --winds 14 --out results/x",
                                      "laddermill power-curve --table a.json b.json"]
    assert blocks[0][1] == [HEADER, ROW_9, ROW_10, "V0 = 14.0 m/s: no periodic case within the limit"]


def test_the_same_output_agrees_and_its_wrote_lines_are_left_out():
    assert block_difference(shown_blocks(PAGE)[0][1], OUTPUT) is None


def test_a_changed_row_is_named():
    stale = OUTPUT.replace("812.3", "812.4")
    wrong = block_difference(shown_blocks(PAGE)[0][1], stale)
    assert wrong is not None and "812.3" in wrong and "812.4" in wrong


def test_a_row_the_block_lacks_and_a_row_no_longer_printed_are_named():
    more = OUTPUT.replace(ROW_10, ROW_10 + "\n 14.0 11.00     1100  False     1300.0")
    assert "11.00" in block_difference(shown_blocks(PAGE)[0][1], more)
    fewer = OUTPUT.replace(ROW_10 + "\n", "")
    assert "10.00" in block_difference(shown_blocks(PAGE)[0][1], fewer)


def test_an_elided_block_matches_its_last_lines():
    lines = shown_blocks(PAGE)[1][1]
    printed = "header\n 8.0 5.00 323.9\nV0 = 14.0 m/s: best V_c 8.0 m/s, 763.6 kW\n"
    assert block_difference(lines, printed) is None
    assert block_difference(lines, printed.replace("763.6", "763.5")) is not None


def test_each_power_curve_group_finds_its_block_on_the_page():
    """The six runs and the replay each show one block of docs/power_curve.md (by their command, or the ``--table``
    command of their JSON that ``shows`` names): a renamed command or block would leave it unchecked."""
    blocks = shown_blocks((DOCS / "power_curve.md").read_text())
    names = [n for n in LONG if n.startswith("power_curve_v2") or n == "power_curve_replay"]
    assert len(names) == 7
    for name in names:
        wanted = [" ".join(c.split()) for c in (LONG[name].shows or (LONG[name].command,))]
        found = [lines for c, lines in blocks if c in wanted]
        assert len(found) == 1, name
        # the block itself, printed back, agrees; with its last line changed it does not
        printed = "\n".join(found[0])
        assert block_differences({name: {"printed": printed}}) == []
        assert block_differences({name: {"printed": printed + " (changed)"}}), name


def test_long_differences_name_a_stale_block():
    lines = next(lines for c, lines in shown_blocks((DOCS / "power_curve.md").read_text())
                 if c == " ".join(LONG["power_curve_v2_depower10"].command.split()))
    printed = "\n".join(lines).replace("812.3", "900.0")
    bad = long_differences({"power_curve_v2_depower10": {"printed": printed, "exit": [1], "stderr": [""]}})
    assert any("812.3" in b and "900.0" in b for b in bad), bad

