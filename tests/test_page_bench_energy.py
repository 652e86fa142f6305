"""pumping.md's gusts-v3 energies of PumpingKite-v1 are a check of the bench's CSV rows (docsite/printed_ratios.py,
``bench_energy``), not a Printed snippet: under the loose rule the static cycle's "0.47 MJ" read a 0.4737 energy ratio
of another row, so a changed static-cycle energy went unnamed (audit of 2026-11-30).

Oracle: the rows ``laddermill gust-bench --suite gusts-v3 --env laddermill_gym/PumpingKite-v1 --controllers crosswind
lqr`` printed on 2026-11-30 (--long gusts_v3_pumping_v1), copied by hand (columns after energy_ratio cut), and their
energies in MJ by hand (465431.1 J = 0.4654 MJ, quoted 0.47).
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.page_figures import long_differences  # noqa: E402
from docsite.printed_numbers import missing  # noqa: E402
from docsite.printed_ratios import bench_energy  # noqa: E402

HEAD = ("env,controller,scenario,seed,survived,t_end_s,failure,cause,max_lateral_m,rms_lateral_m,energy_J,"
        "energy_ratio\n")
ROWS = (("crosswind", "direction_step", 0, 10545179.265726572, 1.046033764043732),
        ("crosswind", "EDC_IA", 0, 2832074.483340855, 0.2809288924551182),
        ("crosswind", "NTM_IB", 0, 14940568.86176141, 1.48203639),
        ("crosswind", "NTM_IB", 1, 11898389.06381578, 1.18026601),
        ("crosswind", "NTM_IB", 2, 14819946.184700685, 1.47007117),
        ("lqr", "direction_step", 0, 465431.10298422846, 1.0026092772231807),
        ("lqr", "one_cos_20s", 0, 472325.6519433048, 0.4737034498984955))  # the last ratio altered by hand


def _bench(static_j: float = 465431.10298422846) -> dict:
    rows = "".join(f"laddermill_gym/PumpingKite-v1,{c},{s},{k},True,300.0,,,1.0,1.0,"
                   f"{static_j if (c, s) == ('lqr', 'direction_step') else e},{r}\n" for c, s, k, e, r in ROWS)
    return {"gusts_v3_pumping_v1": {"printed": HEAD + rows, "exit": [0]}}


def test_the_bench_energies_are_read_per_controller_and_scenario():
    found = bench_energy(_bench()["gusts_v3_pumping_v1"]["printed"])["energy_MJ"]
    assert round(found["lqr"]["direction_step/0"], 4) == 0.4654
    assert round(found["crosswind"]["NTM_IB/1"], 3) == 11.898 and round(found["crosswind"]["EDC_IA/0"], 2) == 2.83
    assert bench_energy("no bench here") == {}


def test_a_changed_static_cycle_energy_is_named():
    """As printed the page agrees; the static cycle's 0.4654 MJ made 0.4854 (quoted 0.47, now 0.49) is named, which
    the loose rule missed: its "0.47" found the 0.4737 ratio a row away."""
    assert long_differences(_bench()) == []
    bad = long_differences(_bench(485431.1))
    assert len(bad) == 1 and "docs/pumping.md" in bad[0] and "0.4854311" in bad[0], bad
    changed = _bench(485431.1)["gusts_v3_pumping_v1"]["printed"]
    assert missing("10.5 MJ in 300 s, the static cycle 0.47 MJ;", changed) == []
