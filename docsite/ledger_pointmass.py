"""The ledger entries (:mod:`docsite.page_ledger`) of docs/pointmass_mill.md (the rigid run and the point-mass mill's
periodic searches against ``pointmass_mill``, :func:`docsite.mill_figures.pointmass_mill`) and docs/pointmass.md (its
closed forms against :mod:`docsite.pointmass_figures`)."""

from __future__ import annotations

from docsite.ledger_kinds import Covered, NotYet

PM = "{pointmass_mill[%s]}"
RIGID = tuple(PM % f"rigid][{k}" for k in ("power_kW", "first_kN", "last_kN", "min_kN", "min_element", "t"))
PM_ROW = (r"\| point mass \(implicit, 10 ms\) \| {} \| ([\d.]+) kW \| ([\d.]+) kN \| ([\d.]+) kN \| ([\d.]+) kN "
          r"\(slot (\d+)\) \|")
PM_KEYS = ("power_kW", "first_kN", "last_kN", "min_kN", "min_slot")
POINTMASS_MILL = Covered(
    groups=("pointmass_mill",),
    checks=(
        (
            r"rigid: ([\d.]+) kW, first element ([\d.]+) kN, last ([\d.]+) kN, smallest mean tension ([\d.]+) kN "
            r"at slot (\d+), periodic at (\d+) s\)",
            RIGID,
        ),
        (
            r"\| rigid \(RK4, 10 ms\) \| 101 x 70 m \| ([\d.]+) kW \| ([\d.]+) kN \| ([\d.]+) kN \| ([\d.]+) kN \(slot "
            r"(\d+)\) \| (\d+) s \|",
            RIGID,
        ),
        (PM_ROW.format("101 x 70 m"), tuple(PM % f"l70][{k}" for k in PM_KEYS)),
        (PM_ROW.format(r"(\d+) x 1 m"), (PM % "l1][nodes",) + tuple(PM % f"l1][{k}" for k in PM_KEYS)),
        (r"\(slot 50\) \| (\d+) s \| 335", ("~" + PM % "l70][t",)),
        (r"\(slot 50\) \| (\d+) s \| 8\.7", ("~" + PM % "l1][t",)),
        (r"the rigid run the start came from \((\d+) s\)", (PM % "rigid][t",)),
    ),
    given=(
        "(Podgaets & Ockels 2007)",
        "(veered ground point to node 0)",
        "(node n-1 to the hauled ground point)",
        "0 <= s < l_e",
        "node n-1 leaves",
        "enters at index 0",
        "a transfer moves 6 n numbers",
        "(every 0.5 s at 1 m elements and 2 m/s)",
        "l_e and 0 for a fixed string",
        "s < 0 transfers the other way (node 0 leaves, one enters at n-1)",
        "re-enters at index 0",
        "the first 0.1 l0 + s, the last 0.1 l0 + l_e - s (7-8 m",
        "(n_k + 0.2) l0",
        "a kite leaves 7 m from the hauled ground point and enters 7 m",
        "(7 m and 77 m)",
        "the paper's 1/10 and 11/10",
        "(the end elements 0.1-1.1 l_e)",
        "at 1 m elements a kite then enters 1 m",
        "The price: the 7 m",
        "(1 m elements, 2 m/s), every 0.5 s at 1 m elements against every 35 s",
        "At V_c = 0 this",
        "steady state to 1e-7.",
        "Resolving the string at 1 m",
        "end elements of 0.1-1.1 m:",
        "on nodes 0 and n-1",
        "so nodes 0 and n-1",
        "the first element is 7 m and the 1.5 m from CG",
        "(2 m/s, 101 wings,",
        "| 101 x 70 m |",
        "(RK4, 10 ms)",
        "(implicit, 10 ms)",
        "(implicit, 10 ms) | 7070 x 1 m",
        "(slot 50) | 1590 s",
        "(slot 50) | 1555 s",
        "counts from t = 0",
        "(shape 1e-3 l0, power 1e-3, twice)",
        "tail takes 9.6 % of the ascending wings' lift (-4 deg) and its descending setting (-1 deg)",
        "V_c = 0 reproduces",
        "at 70 m elements with both",
        "the mill's own 7 m / 14 m ends",
        "moving at +-2 m/s",
        "V_c (1 + eps), the tension EA eps to 1e-7",
        "to 1e-12 through",
        "l0 (1 + eps) along the cable to 1e-9",
        "(n_k + 0.2) l0 with the kites at 0.1 l0 and 1.1 l0",
        "the slow test runs the 70 m",
    ),
    timings=(
        "about 30-45 s, done once per process",
        "| 48 (3D, docs/moving_cable.md) |",
        "| 335 (0.030 ms per step) |",
        "| 8.7 (1.15 ms per step) |",
        "this machine's 2 cores shared by three jobs, load average about 4; the "
        "times are the steps' wall time over 100 s simulated",
    ),
    # ratios of the table's figures, worked by hand; atan(2 / 10) = 11 deg; the 7 m element stretched by 1.5 m
    derived=(
        "stretch it by 20 %",
        "about 11 deg",
        "delivers 25 % (70 m) to 33 % (1 m) more power, with the first "
        "element's tension 10-11 % and the last one's 6 % higher",
        "(slot 50) and is 5 % higher",
        "adds 6 kW (7 %) and changes the end tensions by 1-2 kN",
    ),
    # the straight-string oracle's slack step (tests/test_pointmass_mill.py) and the runs of the rejected variants
    not_rerun=(
        "carries 39 kN over its 21.6 kN",
        "broke down (speed limit) 35 s after its start",
        "(measured -240 kW at t = 60 s, 30 s after the ramp, at 70 m elements)",
    ),
)


PMD = "{pointmass_data[%s]}"  # docs/pointmass.md's closed forms
POINTMASS = NotYet(
    "its closed forms are checked (docsite/pointmass_figures.py: the stable steps, memory, checkpoint spacing, the "
    "partition model, the kites' trim from the shipped files); the benchmark, scaling, fidelity and env tables "
    "(timings and study figures) not yet listed",
    groups=("pointmass_data",),
    checks=((r"For the 2\.5 cm Dyneema \(EA ([\d.e]+) N, DA ([\d.e]+) N s, mu ([\d.]+) kg/m\) at 1 cm the first is "
             r"([\d.e-]+) s and the second \*\*([\d.e-]+) s\*\*",
             tuple("~" + PMD % k for k in ("EA", "DA")) + (PMD % "mu",)
             + tuple("~" + PMD % k for k in ("wave_dt_1cm", "damp_dt_1cm"))),
            (r"48 bytes per node, (\d+) MB for 500,000 nodes", (PMD % "state_MB",)),
            (r"one float64 tension per element \((\d+) MB\) and one kite-flag byte per node \(([\d.]+) MB\)",
             (PMD % "tension_MB", PMD % "flag_MB")),
            (r"every min\(1024, sqrt\(n\)\) nodes \((\d+) at 500k\)", (PMD % "seg",)),
            (r"seg = min\(1024, sqrt\(n\)\) \((\d+) at 500,000 nodes\)", (PMD % "seg",)),
            (r"\(3P \+ 4\)/5 times faster than the one-sided one on one core: ([\d.]+) for P = 2 \(as the two-sided\), "
             r"([\d.]+) for 4, ([\d.]+) for 8, ([\d.]+) for 16", tuple(f"{{pointmass_data[speedup][{i}]}}"
                                                                     for i in range(4))),
            (r"the base tension is 195 kN \((\d+) % of the breaking load\)", (PMD % "base_share_pct",)),
            (r"Every kite is pitched to 6 deg \(C_L ([\d.]+), C_L/C_D ([\d.]+)\)", (PMD % "cl6", PMD % "ld6")),
            (r"the kite moves ([\d.]+) m sideways, the wind's turn of its 14\.3 m", (PMD % "sideways_m",)),
            (r"l0 / c = ([\d.]+) ms", (PMD % "wave_dt_70m_ms",))),
)
