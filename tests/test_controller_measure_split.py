"""work_precision.md's controller-measure section and its ros2t / ros34pw2a table (the review's #10, issue 33 point 6):
the steps and errors are Printed snippets of ``--long wp_controller_measure`` and its CPU speed-ups are timings
(docsite/ledger_controller_measure.py). The oracle is the study's summary lines of 2026-11-30 copied by hand (the
chain over 10 s, step forcing): the page's figures are those numbers rounded; a changed error is named; no Printed
snippet quotes a speed-up (a CPU ratio differs from run to run: 1.45x on 2026-11-29, 1.54x on 2026-11-30).
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite import ledger_controller_measure as cm  # noqa: E402
from docsite.page_numbers import NUMBER, prose  # noqa: E402
from docsite.printed_numbers import missing  # noqa: E402

SUMMARY = """-- fastest run of each method meeting the controller tolerances (tension 0.01 and power 0.01 of \
their largest value, lateral offset 0.1 m, attitude 0.01 rad; speed-up against the fastest such rk4 run in CPU time):
   step    rk4         0.02222 -     76.4x real time  tension 1.4e-04 power 4.6e-06 lat 6.0e-05 m att 6.3e-05 rad  \
1.00x rk4 at 0.02222 s (wall 1.00x)
   step    ros2t       0.03333 -     95.2x real time  tension 2.2e-03 power 9.3e-05 lat 4.9e-02 m att 3.6e-03 rad  \
1.25x rk4 at 0.02222 s (wall 1.25x)
   step    ros34pw2    0.06667 -    117.4x real time  tension 1.6e-03 power 9.4e-05 lat 9.8e-02 m att 4.4e-03 rad  \
1.54x rk4 at 0.02222 s (wall 1.54x)
"""
ROS34PW2_ROW = 'ladder_chain: 0.0222 s | 0.0667 s (1.6e-3, 9.4e-5, 0.098 m, 4.4e-3 rad):'
ROS2T_ROW = '| 0.0333 s (2.2e-3, 9.3e-5, 0.049 m, 3.6e-3 rad):'


def test_the_ros2t_table_is_the_summary_lines():
    for snippet in (ROS34PW2_ROW, ROS2T_ROW, 'yes when they are within 1 %, 1 %, 0.1 m and 0.01 rad;'):
        assert snippet in cm.PRINTED.snippets
        assert missing(snippet, SUMMARY) == [], snippet


def test_a_changed_error_is_named():
    assert missing(ROS34PW2_ROW, SUMMARY.replace("lat 9.8e-02", "lat 1.1e-01")) == ["0.098"]
    assert missing(ROS2T_ROW, SUMMARY.replace("tension 2.2e-03", "tension 2.4e-03")) == ["2.2e-3"]


def test_no_printed_snippet_quotes_a_speed_up():
    """Every x-suffixed figure of the section (a speed-up or a real-time factor) is a timing, never Printed."""
    ratios = [n for s in cm.PRINTED.snippets for n in NUMBER.findall(prose(s)) if n.endswith("x")]
    assert ratios == []
    assert any(n.endswith("x") for s in cm.TIMINGS for n in NUMBER.findall(prose(s)))
