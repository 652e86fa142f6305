"""The page groups re-run this session for figures once listed as not re-run (issue 33, point 6): rotor_design's scan
and sensitivity figures, gain_locality's far share, ``laddermill site --sweeps``'s prose. Each fast test feeds a
hand-made output shaped as the command prints it (figures worked by hand) and checks that the page's checks pass on
the page's figures and name a changed one.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.page_figures import pages_differences  # noqa: E402
from docsite.page_ledger import LEDGER  # noqa: E402
from docsite.rotor_figures import scan_figures  # noqa: E402

SCAN = """15,000 ft (roberts_35m_15kft): altitude 4572 m, ISA density 0.7708 kg/m^3, speed of sound 322.3 m/s; \
R 17.5 m, Omega R 180.0 m/s; craft 12100 kg; 3 tethers 9144 m at 30 deg, 2103 kg each; allowed tension 96.3 kN
30,000 ft (roberts_35m_30kft): altitude 9144 m, ISA density 0.4583 kg/m^3, speed of sound 303.2 m/s; R 17.5 m, \
Omega R 230.0 m/s; craft 12900 kg; 3 tethers 18288 m at 30 deg, 4206 kg each; allowed tension 96.3 kN

  23 |  2.303  0.269 35.6  6.6  0.104    96.3 1.00 stress      |  0.066  0.013 29.3  9.6  0.087    86.5 0.90 lift
  24 |  2.628  0.270 35.5 -0.4  0.109    96.3 1.00 stress      |  0.414  0.072 30.4 11.5  0.090    92.3 0.96 blade
  25 |  2.939  0.267 35.4  8.4  0.113    96.3 1.00 stress      |  0.766  0.117 30.4  4.1  0.094    92.6 0.98 blade

15,000 ft: cut-in 17 m/s; peak over 5-45 m/s 7.64 MW at 45 m/s
    3.13 MW at 25.6 m/s: C_p 0.264, alpha_c 35.3 deg
30,000 ft: cut-in 23 m/s; peak over 5-45 m/s 5.90 MW at 45 m/s
    3.13 MW at 32.5 m/s: C_p 0.217, alpha_c 29.7 deg

Sensitivity at 15,000 ft: best power at 26 m/s, and the wind that gives 3.13 MW
    tip speed [m/s]: power [MW] (craft mass re-estimated; -: cannot hold the altitude): 160: 2.73, 170: 3.31, 180: 3.24
    no tether stress limit            3.76 MW     24.4 m/s

Sensitivity at 30,000 ft: best power at 33 m/s, and the wind that gives 3.13 MW
    tip speed [m/s]: power [MW] (craft mass re-estimated; -: cannot hold the altitude): 200: -, 210: 1.83, 230: 3.26
    no tether stress limit            3.26 MW     32.5 m/s
"""


def test_the_scan_figures_are_worked_from_the_printed_lines():
    """By hand: the best tips 170 and 180 (3.31, 3.24 MW: 2 % apart), 160 m/s 16 % below 180's 3.24; 210 m/s the
    lowest tip holding 30,000 ft; collectives -0.4..8.4 and 4.1..11.5 deg; utilisation 0.96-0.98 from 24 m/s: 2-4 %;
    25.6 - 24.4 = 1.2 m/s; 0.4583 / 0.7708 = 0.59; 3 x 4206 kg = 12.6 t; 32.5 - 25.6 = 7 m/s."""
    found = scan_figures(SCAN)
    assert found["15kft"]["best"] == "170 and 180" and found["15kft"]["apart_pct"] == "2"
    assert found["15kft"]["drop160_pct"] == "16" and found["30kft"]["lowest_tip"] == "210"
    assert (found["15kft"]["theta"], found["30kft"]["theta"]) == ("-0.4..8.4", "4.1..11.5")
    assert found["30kft"]["short_pct"] == "2-4" and found["15kft"]["earlier"] == "1.2"
    assert (found["rho_ratio"], found["tethers_t"], found["rated_gap"]) == ("0.59", "12.6", "7")


def test_the_design_page_checks_name_a_changed_scan_figure():
    found = {"scan": scan_figures(SCAN)}
    measured = {"checked_pages": ["rotorcraft_design.md"], "rotor_design": found}
    assert [b for b in pages_differences(measured) if "rotor_design[scan]" in b] == []
    scan = found["scan"]
    changed = {**scan, "rho_ratio": "0.60", "15kft": {**scan["15kft"], "earlier": "1.3"}}
    bad = pages_differences({**measured, "rotor_design": {"scan": changed}})
    named = [b for b in bad if "times as dense" in b or "earlier at 15,000 ft" in b]
    assert len(named) == 2 and "0.60" in " ".join(named) and "1.3" in " ".join(named)


def test_the_learned_page_checks_the_far_share():
    """gain_locality's shares at distances 6-10 as printed (0.016, 0.010, 0.006, 0.004, 0.002) sum to 0.038."""
    def bad(share: str) -> list[str]:
        found = {"checked_pages": ["learned_mill.md"], "gain_locality": {"far_share": share}}
        return [b for b in pages_differences(found) if "together" in b]

    assert bad(f"{0.016 + 0.010 + 0.006 + 0.004 + 0.002:.3f}") == []
    assert len(bad("0.039")) == 1


def test_the_site_sweeps_prose_is_compared_with_its_output():
    """docs/quasisteady.md's Printed snippets against an output that prints their numbers in order (the snippets'
    own text): they pass; one changed figure (46.7 % printed as 47.7 %) is named."""
    snippets = [s for p in LEDGER["quasisteady.md"].printed for s in p.snippets]
    assert len(snippets) >= 5 and all(p.group == "site_sweeps" for p in LEDGER["quasisteady.md"].printed)
    out = "\n".join(snippets)
    measured = {"checked_pages": ["quasisteady.md"], "site_sweeps": {"printed": out}}
    assert [b for b in pages_differences(measured) if "site_sweeps" in b] == []
    bad = [b for b in pages_differences({**measured, "site_sweeps": {"printed": out.replace("46.7", "47.7")}})
           if "site_sweeps" in b]
    assert len(bad) == 1 and "46.7" in bad[0]
