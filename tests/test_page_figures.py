"""The docs pages' numbers and pictures under ``make readme-figures``: every page is in the ledger, every number of a
covered page is checked or listed (given, dated timing, derived, not re-run); in the slow set the covered pages' checks
are re-run against their commands (the pictures' commands: tests/test_page_check_scope.py).

Oracles: the page files themselves (what they embed and quote), hand-counted numerals of a literal Markdown excerpt,
and, in the slow set, the commands the pages name, run in fresh processes.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.page_figures import coverage, pages_differences  # noqa: E402
from docsite.page_ledger import LEDGER  # noqa: E402
from docsite.page_numbers import numbers, prose  # noqa: E402


def test_the_numbers_of_a_page_are_its_prose_numerals():
    """Counted by hand: 6.15, 169.5, 2, 0.01, 500,000, 1e-3, 8.7x and the output block's 42 are quoted; the code
    span, the bash block, the link target, 3D, v1 and the units' 1 of 1/s and 2 of m^2 are not (6-8's 6 and 8 are)."""
    text = ("open loop 6.15 s at 169.5 kW (`--time 60`), a 2-core machine, a 0.01 rad step, 500,000 elements,\n"
            "tolerance 1e-3, 8.7x real time, the 3D mill, LadderMill-v1, Figs. 6-8 [page](figures/fig_12.png)\n"
            "growth 59 1/s on 4.91e-4 m^2\n"
            "```bash\nladdermill simulate --time 99\n```\n```\nprinted 42\n```\n")
    flat = prose(text)
    assert [flat[a:b] for a, b in numbers(flat)] == ["6.15", "169.5", "2", "0.01", "500,000", "1e-3", "8.7x", "6", "8",
                                                     "59", "4.91e-4", "42"]


def test_every_docs_page_is_in_the_ledger():
    """A new page must be covered or say why not yet; the ledger names no page that is gone."""
    pages = {p.name for p in (ROOT / "laddermill_gym" / "docs").glob("*.md")}
    assert pages - set(LEDGER) == set(), f"docsite/page_ledger.py lacks {sorted(pages - set(LEDGER))}"
    assert set(LEDGER) - pages == set(), f"docsite/page_ledger.py names missing pages {sorted(set(LEDGER) - pages)}"


def test_every_number_of_a_covered_page_is_checked_or_listed():
    """Each number of a covered page is checked or listed in its ledger entry; a listed snippet no longer on the page is
    stale. The message names each page, number and sentence, one per line, and where to account for it."""
    report = coverage()
    lines = [f"docs/{name}: {kind} {item}" for name, r in report.items() for kind in ("loose", "stale")
             for item in (r.get(kind) or ())]
    assert not lines, ("numbers nothing accounts for (loose) or ledger snippets gone from their page (stale); add a "
                       "check or list the number in the page's entry (docsite/page_ledger.py names its ledger_*.py "
                       "module; kinds in docsite/ledger_kinds.py: given, timings, derived, printed, history):\n"
                       + "\n".join(lines))


def test_the_page_check_names_a_changed_figure():
    """Roberts' page against the rotor design study's printed figures (25.6 / 32.5 m/s, alpha_c 35.3 / 29.7 deg,
    ideal C_p 0.290 / 0.222): they pass; another wind is named."""
    good = {"checked_pages": ["paper_roberts.md"],
            "rotor_design": {"15kft": {"wind": "25.6", "alpha_c": 35.3, "ideal_cp": 0.29},
                             "30kft": {"wind": "32.5", "alpha_c": 29.7, "ideal_cp": 0.222}}}
    assert pages_differences(good) == []
    assert pages_differences({}) == []
    bad = pages_differences({**good, "rotor_design": {**good["rotor_design"],
                                                      "30kft": {"wind": "33.0", "alpha_c": 29.7, "ideal_cp": 0.222}}})
    assert len(bad) == 1 and "33.0" in bad[0] and "paper_roberts.md" in bad[0]


@pytest.mark.slow
def test_the_covered_pages_figures_are_what_their_commands_print(tmp_path, capsys):
    """``python -m docsite.readme_figures --skip-readme --pages``: every page's checks re-run (the groups of
    docsite/page_figures.py: 28 groups in 22 minutes on the 2-core machine with one thread at a load of 1-2.4,
    about 70 at a load of 13, 2026-11-29; six groups added later that night about 11 minutes more at a load of 4-6;
    each group's cost is in that module's docstring)."""
    from docsite.readme_figures import main

    status = main(["--skip-readme", "--pages", "--out", str(tmp_path / "pages.json")])  # under a quoted profile
    assert status == 0, capsys.readouterr().out[-6000:]


def test_the_training_tables_are_the_shipped_training_curves():
    """docs/learned_mill.md's two training tables against the shipped policies' training_curve.csv (no command to
    run: the files are what the training wrote), in the fast set."""
    from docsite.page_figures import training_curves

    bad = pages_differences({"checked_pages": ["learned_mill.md"], "training_curves": training_curves()})
    slow = ("'gain_locality'", "'chain_controllers'", "'mill_v1_controllers'")  # the other checks: slow groups
    assert [b for b in bad if not any(group in b for group in slow)] == []


def test_every_ledger_group_has_its_measurement():
    """Each group a page's checks read is measured by docsite.page_figures.GROUPS or by README's own groups."""
    from docsite import readme_figures
    from docsite.page_figures import GROUPS

    named = {g for entry in LEDGER.values() for g in entry.groups}
    assert {g for g in named if g not in GROUPS and not callable(getattr(readme_figures, g, None))} == set()


def test_a_picture_drawn_again_is_judged_by_its_pixels(tmp_path):
    """The same pixels under other metadata are the same picture; one changed pixel is named with its count."""
    import numpy as np
    from matplotlib.image import imsave

    from docsite.pictures import compare

    img = np.zeros((4, 5, 3))
    imsave(tmp_path / "a.png", img, metadata={"Software": "one"})
    imsave(tmp_path / "b.png", img, metadata={"Software": "another"})
    img[1, 2] = 1.0
    imsave(tmp_path / "c.png", img)
    assert (tmp_path / "a.png").read_bytes() != (tmp_path / "b.png").read_bytes()
    assert compare(tmp_path / "b.png", tmp_path / "a.png") == "same"
    assert compare(tmp_path / "c.png", tmp_path / "a.png") == "changed (1 of 20 pixels, max 1.00)"


def test_the_cable_page_is_its_config_file_and_its_arithmetic():
    """docs/cable_data.md against configs/cables/dyneema_25mm.yaml and its worked numbers reworked in closed form
    from the inputs it gives (fast set); a config with another EA is named on each line that quotes it."""
    import copy

    from docsite.config_figures import cable_dyneema

    measured = {"checked_pages": ["cable_data.md"], "cable_dyneema": cable_dyneema()}
    assert pages_differences(measured) == []
    other = copy.deepcopy(measured)
    other["cable_dyneema"]["config"].update(breaking_load=5.3e5, tau=3e-3)
    bad = pages_differences(other)
    assert len(bad) == 4 and all("cable_data.md" in b and ("5.25e5" in b or "1e-3" in b) for b in bad), bad


def test_the_rotorcraft_data_are_its_config_file_and_its_mass_build_up():
    """docs/rotorcraft.md's data against configs/rotorcraft/roberts_flying_model.yaml and the page's mass table summed
    in closed form (20.0 kg, CG x -0.0925 m, Jxx 48.36 kg m^2 worked by hand), in the fast set; another Jxx in the
    config is named."""
    import copy

    from docsite.config_figures import craft_data

    measured = {"checked_pages": ["rotorcraft.md"], "craft_data": craft_data()}
    assert (measured["craft_data"]["worked"]["mass"], measured["craft_data"]["worked"]["Jxx"]) == ("20.0", "48.4")
    bad = pages_differences(measured)
    assert bad and all("craft_stability" in b for b in bad), [b for b in bad if "craft_stability" not in b]
    other = copy.deepcopy(measured)
    other["craft_data"]["config"]["Jxx"] = "50.1"
    named = [b for b in pages_differences(other) if "craft_stability" not in b]
    assert len(named) == 1 and "50.1" in named[0] and "rotorcraft.md" in named[0], named


def test_the_35m_design_inputs_are_its_configs_and_closed_forms():
    """docs/rotorcraft_design.md's tether, atmosphere, scaling and wind arithmetic against the two craft configs, the
    cable file and closed forms worked from the page's inputs (ISA 0.7708 / 0.4583 kg/m^3 at 4572 / 9144 m, the ICAO
    table's values), in the fast set; another v1 in a config is named."""
    import copy

    from docsite.design_figures import design_data

    data = design_data()
    assert (data["worked"]["15kft"]["rho"], data["worked"]["30kft"]["rho"]) == ("0.7708", "0.4583")
    measured = {"checked_pages": ["rotorcraft_design.md"], "design_data": data}
    assert [b for b in pages_differences(measured) if "'rotor_design'" not in b] == []
    other = copy.deepcopy(measured)
    other["design_data"]["config"]["30kft"]["v1"] = "2.900e-3"
    named = [b for b in pages_differences(other) if "'rotor_design'" not in b]
    assert len(named) == 1 and "2.900e-3" in named[0], named


def test_the_wind_page_is_the_standards_constants_in_the_code_and_its_closed_forms(tmp_path, monkeypatch):
    """docs/wind.md against the constants the atmosphere modules hold and its check values reworked from the IEC
    formulas (class IA, 10 m/s, D 10 m: EOG V_gust 6.76 m/s, peak 15.0 m/s at 5.25 s, EDC theta_e 46.3 deg worked by
    hand; the coherence of u over 20 m, exp(-1.44 x 20 / 340.2) = 0.92), in the fast set; another EWS beta in the
    code is named, and so is the page's earlier coherence 0.93."""
    import copy

    from docsite import page_figures
    from docsite.wind_figures import wind_data

    data = wind_data()
    worked = data["worked"]
    assert (worked["v_gust"], worked["peak"], worked["t_peak"], worked["theta_e"]) == ("6.76", "15.0", "5.25", "46.3")
    assert worked["coherence_20m"] == "0.92"
    measured = {"checked_pages": ["wind.md"], "wind_data": data}
    assert _named(measured) == []
    other = copy.deepcopy(measured)
    other["wind_data"]["code"]["ews_beta"] = "6.5"
    named = _named(other)
    assert len(named) == 1 and "6.5" in named[0] and "wind.md" in named[0], named
    page = (ROOT / "laddermill_gym" / "docs" / "wind.md").read_text()
    (tmp_path / "wind.md").write_text(page.replace("/ 340 m) = 0.92)", "/ 340 m) = 0.93)"))
    monkeypatch.setattr(page_figures, "DOCS", tmp_path)
    stale = _named(measured)
    assert len(stale) == 1 and "0.93" in stale[0], stale


def test_the_wing_page_is_what_derive_wing_prints():
    """docs/wing_data.md's key numbers, mass build-up, cable trims and pitch check against a fresh
    ``derive_wing --check`` (about 4 s; the command, not a stored copy of its output), in the fast set; another
    Clp at 7 deg and another Jxx are each named on the lines that quote them."""
    import copy

    from docsite.wing_figures import derive_wing

    measured = {"checked_pages": ["wing_data.md"], "derive_wing": derive_wing()}
    assert pages_differences(measured) == []
    other = copy.deepcopy(measured)
    other["derive_wing"]["deriv"]["Clp"][1] = "-0.6100"
    other["derive_wing"]["J"] = ["1330.2", *other["derive_wing"]["J"][1:]]
    bad = pages_differences(other)
    assert len(bad) == 3 and any("-0.652" in b and "-0.6100" in b for b in bad), bad  # Clp quoted twice
    assert any("1325" in b and "1330.2" in b for b in bad), bad


def test_the_numerics_page_closed_forms():
    """docs/numerics.md's RK4 limits against |R(z)| = 1 solved here (2 sqrt 2 = 2.83 on the imaginary axis, 2.785 on
    the real axis, the textbook values), in the fast set; a real-axis limit of 2.51 (RK3's) is named."""
    from docsite.numerics_figures import numerics_data

    data = numerics_data()
    assert (data["rk4_imag"], data["rk4_real"]) == (f"{8 ** 0.5:.2f}", "2.785")
    assert pages_differences({"checked_pages": ["numerics.md"], "numerics_data": data}) == []
    bad = pages_differences({"checked_pages": ["numerics.md"], "numerics_data": {**data, "rk4_real": "2.513"}})
    assert len(bad) == 1 and "2.513" in bad[0] and "numerics.md" in bad[0], bad


def test_the_pointmass_page_closed_forms_are_its_cable_file_and_table():
    """docs/pointmass.md's explicit stable steps from configs/cables/dyneema_25mm.yaml (l0 sqrt(mu/EA) = 1.18e-6 s and
    mu l0^2/(2 DA) = 6.94e-10 s at 1 cm, worked by hand), the partition model (3P + 4)/5 and the 6 deg trim from the
    shipped table, in the fast set; a cable with another DA is named."""
    from docsite.pointmass_figures import pointmass_data

    data = pointmass_data()
    assert (data["wave_dt_1cm"], data["damp_dt_1cm"], data["speedup"]) == ("1.2e-06", "6.9e-10",
                                                                         ["2", "3.2", "5.6", "10.4"])
    assert pages_differences({"checked_pages": ["pointmass.md"], "pointmass_data": data}) == []
    bad = pages_differences({"checked_pages": ["pointmass.md"],
                             "pointmass_data": {**data, "DA": "4.32e+04", "damp_dt_1cm": "3.5e-10"}})
    assert len(bad) == 1 and "3.5e-10" in bad[0] and "pointmass.md" in bad[0], bad


def test_the_work_precision_page_stability_limits_are_the_tableaux():
    """docs/work_precision.md's RK4 and DP5(4) limits against |R(z)| = 1 of the stability polynomials built here from
    the published tableaux (RK4: 2.785 real, 2 sqrt 2 = 2.828 imaginary, the textbook values; DP5(4) 3.307 real,
    0.997 imaginary, Hairer & Wanner's Fig. IV.2.1), in the fast set; RK3's 2.513 on the real axis is named."""
    from docsite.precision_figures import precision_data

    data = precision_data()
    assert (data["rk4_real"], data["rk4_imag"]) == ("2.785", f"{8 ** 0.5:.3f}")
    stable = {"stable_steps": {}}  # the table's rows need the command: only the closed-form check here
    bad = pages_differences({"checked_pages": ["work_precision.md"], "precision_data": data, **stable})
    assert [b for b in bad if "its command printed no" not in b] == [], bad
    other = pages_differences({"checked_pages": ["work_precision.md"], "precision_data": {**data, "rk4_real": "2.513"},
                               **stable})
    named = [b for b in other if "its command printed no" not in b]
    assert len(named) == 1 and "2.513" in named[0] and "work_precision.md" in named[0], named


def test_the_benchmarks_page_point_mass_figures_are_named_when_changed():
    """docs/benchmarks.md's point-mass scene (500,000 elements, 28.69 MB held, the explicit step 6.9e-10 s, as
    pointmass_benchmark printed them on 2026-11-29) pass; another held size is named."""
    printed = {"elements": "500,000", "held_MB": "28.69", "explicit_dt": "6.9e-10"}
    assert _named({"checked_pages": ["benchmarks.md"], "pointmass_benchmark": printed}) == []
    other = {**printed, "held_MB": "30.12"}
    bad = _named({"checked_pages": ["benchmarks.md"], "pointmass_benchmark": other})
    assert len(bad) == 1 and "30.12" in bad[0] and "benchmarks.md" in bad[0], bad


def test_the_controllers_page_names_a_changed_figure():
    """docs/controllers.md's chain paragraph against what its commands printed on 2026-11-29 (laddermill evaluate on
    LadderChain-v0: open loop 12.2 s, decentralised LQR 9.0 s, centralised 0.0803 m over 120.0 s; laddermill lqr:
    606 states, +0.7752 1/s, max |z| 1.06903 and 0.99035) passes; a centralised loop at max |z| 1.00210 is named."""
    row = {"return": "0", "dy": "0", "power": "0", "failures": ""}
    chain = {"open_loop": {**row, "length": "12.2"}, "lqr": {**row, "length": "9.0"},
             "central": {**row, "length": "120.0", "dy": "0.0803"}, "states": "606", "real_part": "+0.7752",
             "decentral_z": "1.06903", "central_z": "0.99035"}
    measured = {"checked_pages": ["controllers.md"], "chain_controllers": chain}
    assert [b for b in pages_differences(measured) if "printed no" not in b] == []
    measured["chain_controllers"] = {**chain, "central_z": "1.00210"}
    bad = [b for b in pages_differences(measured) if "printed no" not in b]
    assert len(bad) == 1 and "1.00210" in bad[0] and "controllers.md" in bad[0], bad


def test_the_halved_step_figure_is_named_when_changed():
    """docs/moving_cable.md's "halving the step ... mean power 66.2 kW" against ``laddermill simulate laddermill
    --start periodic --dt 0.005`` as it printed on 2026-11-29 (66.2 kW) passes; the 10 ms run's 66.1 kW is named."""
    measured = {"checked_pages": ["moving_cable.md"], "simulate_laddermill_half": {"periodic_kW": "66.2"}}
    assert [b for b in pages_differences(measured) if "printed no" not in b] == []
    measured["simulate_laddermill_half"] = {"periodic_kW": "66.1"}
    bad = [b for b in pages_differences(measured) if "printed no" not in b]
    assert len(bad) == 1 and "66.1" in bad[0] and "moving_cable.md" in bad[0], bad


def test_the_power_curve_page_is_mill_fast_cases():
    """docs/power_curve.md's 1-5 m/s powers at 8 m/s are fast_mill case's (mill_fast.md's in-plane table: 45.9, 102.2,
    168.6, 244.0, 323.9 kW as printed on 2026-11-29) and pass; another 5 m/s power is named where it is quoted."""
    printed = {f"v{v}": {"P": p} for v, p in zip(range(1, 6), (45.9, 102.2, 168.6, 244.0, 323.9), strict=True)}
    assert pages_differences({"checked_pages": ["power_curve.md"], "fast_mill_v2": printed}) == []
    other = {**printed, "v5": {"P": 330.1}}
    bad = pages_differences({"checked_pages": ["power_curve.md"], "fast_mill_v2": other})
    assert len(bad) == 2 and all("330.1" in b and "power_curve.md" in b for b in bad), bad


def _named(measured: dict) -> list[str]:
    """The differences of ``measured``'s pages, less those of groups it leaves out ("printed no")."""
    return [b for b in pages_differences(measured) if "printed no" not in b]


def test_the_benchmarks_stable_steps_are_named_when_changed():
    """docs/benchmarks.md's stable-step row against ``laddermill bench`` (bisection: 0.0193 / 0.0249 s, as it printed
    on 2026-11-30) and ``laddermill stable-step`` (0.01901 / 0.02445 s) passes; a bisection of 0.0201 s is named."""
    bench = {"tethered_wing": "0.0193", "ladder_chain": "0.0249"}
    measured = {"checked_pages": ["benchmarks.md"], "bench_stable_dt": bench,
                "stable_steps": {"tethered_wing": {"rk4": "0.01901"}, "ladder_chain": {"rk4": "0.02445"}}}
    assert _named(measured) == []
    measured["bench_stable_dt"] = {"tethered_wing": "0.0201", "ladder_chain": "0.0249"}
    bad = _named(measured)
    assert len(bad) == 1 and "0.0201" in bad[0] and "benchmarks.md" in bad[0], bad


#: pumping_cycle's crosswind table as it printed on 2026-12-07 (cycles 0 and 1; then each cycle's phases).
CROSSWIND_COLUMNS = ("t_cycle", "sim", "matched", "matched_tension", "lansdorp", "schmehl", "static", "fed",
                     "tension_out", "speed_out", "tension_in", "alpha", "max_dy")
CROSSWIND_PRINTED = {
    "c0": dict(zip(CROSSWIND_COLUMNS, "270.4 31711 46518 62081 111807 104339 3383 32609 47128 2.78 5185 8.48 "
                   "129.89".split(), strict=True)),
    "c1": {**dict(zip(CROSSWIND_COLUMNS, "276.2 31440 46266 62867 112682 105198 3392 32259 47606 2.77 5282 8.52 "
                      "128.53".split(), strict=True)),
           "t_out_s": "85", "energy_out_MJ": "11.2", "t_in_s": "192", "speed_in": "1.2"}}


def test_the_crosswind_cycle_table_is_named_when_changed():
    """docs/pumping.md's crosswind-cycle table and its cycle-1 phases against what ``pumping_cycle --cycles 2``
    printed on 2026-12-07 pass; a cycle-1 reel-in of 201 s and a cycle-0 power of 31712 W are each named."""
    c0, c1 = CROSSWIND_PRINTED["c0"], CROSSWIND_PRINTED["c1"]
    assert _named({"checked_pages": ["pumping.md"], "pumping_crosswind": CROSSWIND_PRINTED}) == []
    bad = _named({"checked_pages": ["pumping.md"], "pumping_crosswind": {"c0": {**c0, "sim": "31712"},
                                                                         "c1": {**c1, "t_in_s": "201"}}})
    assert len(bad) == 2 and any("201" in b for b in bad) and any("31712" in b for b in bad), bad


def test_the_gusts_v2_pumping_table_is_named_when_changed():
    """docs/wind.md's PumpingKite-v0 gusts-v2 rows against ``gust_table`` of gust-bench rows made here (two seeds of
    the LQR in NTM_IB survive, the third ends at 61.30 s with beta -62.3 deg; medians worked by hand: lateral 10.2 m,
    energy ratio 1.141): that row passes; the same with 2 of 3 seeds lost is named."""
    from docsite.study_figures import gust_table

    def row(seed, survived, lateral, ratio, t_end=60.0, cause=""):
        return {"controller": "lqr", "scenario": "NTM_IB", "seed": seed, "survived": survived, "t_end_s": t_end,
                "cause": cause, "failure": "" if survived else "aerodynamic range exceeded",
                "max_lateral_m": lateral, "energy_ratio": ratio}

    lost = "t = 61.30 s: alpha = 14.2 deg, beta = -62.3 deg outside the aerodynamic range"  # as gust-bench writes it
    rows = [row(0, True, 7.6, 1.30), row(1, True, 10.2, 1.141), row(2, False, 12.0, 0.9, 61.3, lost)]
    table = gust_table(rows)["lqr/NTM_IB"]
    assert [table[k] for k in ("survived", "ends", "lateral", "ratio", "beta")] == ["2/3", "61.3", "10.2", "1.141",
                                                                                    "-62.3"]
    full = {f"{c}/{s}": {"survived": "", "ends": "", "lateral": "", "ratio": ""} for c in ("open_loop", "lqr")
            for s in ("direction_step", "speed_step_20pct", "one_cos_4s", "one_cos_20s", "EOG_IA", "EDC_IA")}
    measured = {"checked_pages": ["wind.md"], "gusts_v2_pumping": {**full, "lqr/NTM_IB": table}}
    assert [b for b in _named(measured) if "NTM_IB" in b or "61.3" in b] == []
    rows[1] = row(1, False, 10.2, 1.141, 58.0, lost)
    bad = [b for b in _named({**measured, "gusts_v2_pumping": {**full, "lqr/NTM_IB": gust_table(rows)["lqr/NTM_IB"]}})
           if "lqr | NTM_IB" in b]
    assert len(bad) == 1 and "1/3" in bad[0], bad


def test_the_power_curve_rows_are_named_when_changed():
    """docs/pumping.md's 10 m/s power-curve row and phase split, and its 4 m/s "no trim", and docs/reeling_tether.md's
    10 m/s rows, against what ``power_curve`` (and with ``--reel-element-length 40``) printed on 2026-12-07 pass; a
    Lansdorp power of 111808 W and a model reel-in tension of 425 N are each named, once."""
    cells = ("sim", "matched", "ratio", "nominal", "lansdorp", "T_out", "matched_T_out", "out", "in", "within",
             "transitions")
    v10 = dict(zip(cells, "31711 46518 0.68 104339 111807 47128 62081 11892 4014 897 -1997".split(), strict=True))
    curve = {"v10": v10, "v4": {"failure": "no trim: iterations.); the wind (wind.v0 = 4 m/s"}}
    measured = {"checked_pages": ["pumping.md"], "pumping_power_curve": curve}
    assert _named(measured) == []
    bad = _named({**measured, "pumping_power_curve": {**curve, "v10": {**v10, "lansdorp": "111808"}}})
    assert len(bad) == 1 and "111808" in bad[0] and "pumping.md" in bad[0], bad
    # the reeling tether's (--reel-element-length 40) 10 m/s rows, not the element-count table's "| 10 |" row
    reel = dict(zip((*cells, "T_in", "model_T_in"), "45749 56803 0.81 104165 111594 53884 61585 7522 6455 -59 -2864 "
                    "6017 424".split(), strict=True))
    assert _named(measured := {"checked_pages": ["reeling_tether.md"], "reeling_power_curve": {"v10": reel}}) == []
    bad = _named({**measured, "reeling_power_curve": {"v10": {**reel, "model_T_in": "425"}}})
    assert len(bad) == 1 and "425" in bad[0] and "reeling_tether.md" in bad[0], bad


def test_the_meijaard_fixed_step_ends_are_named_when_changed():
    """paper_meijaard1999.md's fixed-step ends as znver3 wrote them (2026-12-01, breakdown.csv: 10 ms 24.0 s, wings 6-9
    over the speed guard, none over the rate guard; 2.5 ms 67.9 s, wing 54 over the rate guard only) pass; 2026-11-29's
    25.8 s is named wherever it is quoted (the table is znver3's: tests/test_host_cpu_figures.py)."""
    ends = {"rk4_10ms": {"t": "24.0", "speed": "wings 6-9", "rate": "no wing"}, "tumble_deg": "4268",
            "rk4_2_5ms": {"t": "67.9", "speed": "no wing", "rate": "wing 54"}}
    page = {"checked_pages": ["paper_meijaard1999.md"], "cpu": "znver3"}
    assert _named({**page, "meijaard_v1": {"files": ends}}) == []
    bad = _named({**page, "meijaard_v1": {"files": {**ends, "rk4_10ms": {**ends["rk4_10ms"], "t": "25.8"}}}})
    assert len(bad) == 4 and all("25.8" in b and "paper_meijaard1999.md" in b for b in bad), bad
