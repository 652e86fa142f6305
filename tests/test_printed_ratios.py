"""The pages' ratios, ranges and bounds worked from a long group's printed columns (docsite/printed_ratios.py; the
review's #15, 2026-11-30: until then ``derived`` entries that no run re-checked) are checks: a changed run fails them.

Oracles: the commands' printed lines as they ran on 2026-11-30 (docs/reeling_tether.md's and docs/pumping.md's power
curve tables are the same numbers; the reeling tether's as printed on 2026-12-07), the ratios worked by hand from them
(33145 / 36709 = 0.903, 33557 / 33145 = 1.0124,
(322 + 1) x 50 ms = 16.15 s, 0.412 x 525 kN = 216.3 kN), and one printed cell changed by hand, which must be named on
the page that quotes the figure.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from docsite.long_checks import long_check_differences  # noqa: E402
from docsite.mill_figures import vs_rigid  # noqa: E402
from docsite.page_figures import pages_differences  # noqa: E402
from docsite.printed_ratios import power_curve_ratios, step_accuracy  # noqa: E402

HEAD = "v0 m/s    sim W matched W sim/matched  Schmehl W  Lansdorp W  T_out N matched T_out N  failure\n"
NO_TRIM = "   4.0      nan       nan         nan        nan         nan      nan             nan  no trim: (...)\n"
SPLIT = ("matched - simulated by phase [W] (loss_split): ...; T_in simulated / model [N]\n"
         "   8.0  8058  4452  568  -1928  4355 /  0\n")
PULLS = "reel-out tension [N]: drum, at the wing (wing / drum), 1/2 rho S C_R <v_a^2> at the flown airspeed, model\n"
# python -m laddermill_gym.studies.pumping.power_curve --reel-element-length 40 (2026-12-07): v, sim, matched, ratio,
# Schmehl, Lansdorp, T_out, matched T_out; then v, drum, wing, (wing / drum), aerodynamic force, model
REELING_CURVE = ((8, 23660, 30097, 0.79, 55203, 63046, 33145, 36709),
                 (10, 45749, 56803, 0.81, 104165, 111594, 53884, 61585),
                 (12, 78427, 93455, 0.84, 169856, 177968, 79659, 90573),
                 (14, 122104, 140271, 0.87, 250614, 259776, 108554, 122627),
                 (16, 171357, 193248, 0.89, 346243, 356839, 137860, 156027),
                 (18, 228524, 257831, 0.89, 472832, 485383, 168311, 193799),
                 (20, 272706, 315758, 0.86, 608918, 623235, 190551, 223307))
REELING_PULLS = ((8, 33145, 33557, 1.012, 34944, 36709), (10, 53884, 54207, 1.006, 56256, 61585),
                 (12, 79659, 79877, 1.003, 82946, 90573), (14, 108554, 108655, 1.001, 112691, 122627),
                 (16, 137860, 137848, 1.000, 142953, 156027), (18, 168311, 168169, 0.999, 173926, 193799),
                 (20, 190551, 190339, 0.999, 197430, 223307))


def _printed(curve: tuple, pulls: tuple) -> str:
    rows = "".join(f"{r[0]:6.1f} " + " ".join(f"{x:10}" for x in r[1:]) + "\n" for r in curve)
    tensions = "".join(f"{p[0]:6.1f} {p[1]:8} {p[2]:8} ({p[3]:.3f}) {p[4]:8} {p[5]:8}\n" for p in pulls)
    return HEAD + NO_TRIM + rows + SPLIT + PULLS + tensions


def test_the_power_curve_ratios_are_worked_from_its_printed_columns():
    found = power_curve_ratios(_printed(REELING_CURVE, REELING_PULLS))
    # 23660 / 30097 ... 272706 / 315758: every wind within 30 %
    assert found["within30"] == {"lo": "8", "hi": "20", "ratios": "0.786, 0.805, 0.839, 0.870, 0.887, 0.886, 0.864"}
    # 190551 / 223307 and 33145 / 36709
    assert round(found["tension_model"]["lo"], 4) == 0.8533 and round(found["tension_model"]["hi"], 4) == 0.9029
    assert round(found["wing_drum_pct"], 2) == 1.24  # 33557 / 33145
    # 173926 / 168169 and 34944 / 33557
    assert round(found["aero_above_pct"]["lo"], 2) == 3.42 and round(found["aero_above_pct"]["hi"], 2) == 4.13
    # 197430 / 223307 and 34944 / 36709
    assert round(found["aero_model"]["lo"], 4) == 0.8841 and round(found["aero_model"]["hi"], 4) == 0.9519
    assert power_curve_ratios("no table here") == {}


def test_a_changed_power_curve_is_named_on_the_pages_that_work_from_it():
    """As printed, reeling_tether.md's and pumping.md's ratios of the reeling curve agree; a drum tension at 8 m/s
    of 29145 N (wing / drum 1.151, T_out / model 0.794) is named for "within 1.2 %" and "0.85-0.90"; 12 m/s below
    0.7 of the model (sim 60000 W) breaks "Within 30 % at 8 to 20 m/s"."""
    group = "reeling_power_curve_printed"
    assert long_check_differences({group: {"printed": _printed(REELING_CURVE, REELING_PULLS)}}) == []
    curve = ((8, 23660, 30097, 0.79, 55203, 63046, 29145, 36709), *REELING_CURVE[1:])
    pulls = ((8, 29145, 33557, 1.151, 34944, 36709), *REELING_PULLS[1:])
    bad = long_check_differences({group: {"printed": _printed(curve, pulls)}})
    assert len(bad) == 2 and all(b.startswith("docs/reeling_tether.md") for b in bad), bad
    assert any("within 1.2 %" in b for b in bad) and any("0.85-0.90" in b for b in bad)
    gap = (*REELING_CURVE[:2], (12, 60000, 93455, 0.64, 169856, 177968, 79659, 90573), *REELING_CURVE[3:])
    bad = long_check_differences({group: {"printed": _printed(gap, REELING_PULLS)}})
    assert [b.split(" quotes ")[1] for b in bad] == ["('8', '20'); --long ['reeling_power_curve_printed'] gives "
                                                    "('winds 8, 10, 14, 16, 18, 20', 'winds 8, 10, 14, 16, 18, 20')"]


STEPS_10 = """laddermill_gym/LadderMill-v2: 10 s, extent 3477.4 m; reference RK4 at 0.0025 s ran 200 periods
  registered: largest position error 3.179e-05 m = 9.14e-09 of the extent over 200 periods; CPU 0.35 s
  ros34pw2  : largest position error 0.002439 m = 7.01e-07 of the extent over 200 periods; CPU 0.18 s
  ros2      : largest position error 0.06437 m = 1.85e-05 of the extent over 200 periods; CPU 0.14 s
laddermill_gym/LadderChain-v0: 10 s, extent 3612.8 m; reference RK4 at 0.003125 s ran 200 periods
  ros34pw2  : largest position error 1.158 m = 0.00032 of the extent over 200 periods; CPU 0.15 s
  ros2      : largest position error 1.628 m = 0.00045 of the extent over 200 periods; CPU 0.10 s
"""
STEPS_40 = """laddermill_gym/LadderMill-v2: 40 s, extent 3477.4 m; reference RK4 at 0.0025 s ran 321 periods
  ros34pw2  : largest position error 0.02623 m = 7.54e-06 of the extent over 322 periods; CPU 0.31 s
  ros2      : largest position error 0.2567 m = 7.38e-05 of the extent over 317 periods; CPU 0.24 s
"""


def test_the_step_accuracy_figures_are_worked_from_its_printed_lines():
    """benchmarks.md: the mill's ROS2 error 6.4 cm; the ends (periods + 1) x 50 ms, 16.15, 16.10 and 15.9 s; 2.6 cm;
    both steps within 1e-3 of the extent over 10 s. A ROS34PW2 that ends one period earlier, or a chain error of
    0.0012 of the extent, is named."""
    found = step_accuracy(STEPS_40)
    assert found["LadderMill-v2"]["ros34pw2"]["end_s"] == 16.15 and found["LadderMill-v2"]["reference"]["end_s"] == 16.1
    assert step_accuracy(STEPS_10)["share_bound"] == {"registered": "1e-8", "ros34pw2": "1e-3", "ros2": "1e-3"}
    long = {"step_accuracy_10": {"printed": STEPS_10}, "step_accuracy_40": {"printed": STEPS_40}}
    assert long_check_differences(long) == []
    early = {**long, "step_accuracy_40": {"printed": STEPS_40.replace("over 322 periods", "over 321 periods")}}
    assert ["16.15" in b for b in long_check_differences(early)] == [True]
    loose = {**long, "step_accuracy_10": {"printed": STEPS_10.replace("0.00032 of", "0.0012 of")}}
    assert ["ROS34PW2 is the step of choice" in b and "'1e-2'" in b for b in long_check_differences(loose)] == [True]


def test_the_fidelity_travel_and_peak_figures_are_named_when_changed():
    """pointmass.md's +11 % / -6 % (178.9 / 161.0, 67.3 / 71.8) and 3 cm (0.0302 m); mill_fast.md's 216 kN (0.412 x
    525 kN)."""
    fidelity = ("tension: first piece rigid 161.0 kN, point mass 178.9 kN; last piece 71.8 / 67.3 kN; smallest 0.2 / "
                "0.1 kN")
    long = {"pointmass_fidelity": {"printed": fidelity},
            "pointmass_accuracy": {"printed": "(10000 elements, kites travel up to 0.0302 m):"},
            "fast_mill_v2_step": {"printed": "after V_c 2 -> 2 m/s, wind x 1.125 at t = 940.0 s: ...; no cable overload"
                                             " (peak tension 0.412 x the limit); largest tension 197.6 kN"}}
    assert long_check_differences(long) == []
    changed = {"pointmass_fidelity": {"printed": fidelity.replace("178.9", "180.9")},
               "pointmass_accuracy": {"printed": "(10000 elements, kites travel up to 0.0352 m):"},
               "fast_mill_v2_step": {"printed": long["fast_mill_v2_step"]["printed"].replace("0.412", "0.420")}}
    bad = long_check_differences(changed)
    assert sorted(b.split(":")[0] for b in bad) == ["docs/mill_fast.md", "docs/pointmass.md", "docs/pointmass.md"], bad


def test_the_point_mass_mills_ratios_are_worked_from_its_table():
    """pointmass_mill.md's 36 % more power at both resolutions, 12 % and 5 % (first, last), 5 % (smallest), the
    resolution's -0.1 kW (-0.1 %) and 0.1 kN, from the table's printed figures; a 1 m string at 92.2 kW (+39 %,
    +2.1 kW) is named."""
    rigid = {"power_kW": "66.1", "first_kN": "160.0", "last_kN": "126.9", "min_kN": "10.5", "min_element": "50",
             "t": "1135"}
    l70 = {"nodes": "102", "state": "converged", "t": "1590", "power_kW": "90.1", "first_kN": "178.5",
           "last_kN": "133.5", "min_kN": "11.0", "min_slot": "50"}
    l1 = {**l70, "nodes": "7071", "t": "1555", "power_kW": "90.0", "first_kN": "178.4", "last_kN": "133.4"}

    def differences(power_1m: str) -> list[str]:
        found = {"rigid": rigid, "l70": l70, "l1": {**l1, "power_kW": power_1m}}
        measured = {"checked_pages": ["pointmass_mill.md"], "pointmass_mill": {**found, "vs_rigid": vs_rigid(found)}}
        return [b for b in pages_differences(measured) if "more power" in b or "changes the mean power" in b]

    assert differences("90.0") == []
    assert len(differences("92.2")) == 2


def test_the_lqr_cycles_offset_bound_is_named_when_crossed():
    """pumping.md's "stays below 6 m through three cycles": the next whole metre above the largest printed max |dy|
    (5.27 m on 2026-11-30); a run whose largest is 6.2 m gives 7 and is named."""
    from docsite.pumping_figures import CYCLE_COLUMNS, dy_bound

    def bound(dys: tuple) -> list[str]:
        rows = [dict(zip(CYCLE_COLUMNS, ("0",) * 13 + (dy,), strict=True)) for dy in dys]
        measured = {"checked_pages": ["pumping.md"], "pumping_cycle_lqr": {"rows": rows, "dy_bound": dy_bound(rows)}}
        return [b for b in pages_differences(measured) if "stays below" in b]

    assert bound(("3.90", "5.27", "4.8")) == []
    assert len(bound(("3.90", "6.2", "4.8"))) == 1


def test_the_mills_gust_bound_is_the_latest_failure():
    """features.md's "no controller keeps the mill through turbulence or EWS beyond 15 s": every seed of the gusts-v2
    mill bench lost, the last at 14.8 s (2026-11-30); a last loss at 15.3 s, or a seed that survives, is named."""
    from docsite.study_figures import end_bound

    def named(rows: list[dict]) -> list[str]:
        measured = {"checked_pages": ["features.md"], "gusts_v2_mill": {"end_bound": end_bound(rows)}}
        return [b for b in pages_differences(measured) if "beyond" in b]

    lost = [{"survived": False, "t_end_s": t} for t in (3.2, 14.8, 9.95)]
    assert end_bound(lost) == "15" and named(lost) == []
    assert len(named([*lost, {"survived": False, "t_end_s": 15.3}])) == 1
    assert named([*lost, {"survived": True, "t_end_s": 60.0}])[0].endswith("('a seed survived',)")


def test_the_crafts_period_error_bound_and_failure_are_worked_from_its_figures():
    """controllers.md's and rotorcraft.md's "a period of 12.6 s" (2 pi / 0.497 rad/s), "to 1 %" (0.998 % on
    2026-11-30) and "(32 s after the step)" (33.0 s less the 1 s of the step); a frequency of 0.52 rad/s (12.1 s), an
    error of 1.2 % and a failure at 34.0 s are named."""
    from docsite.printed_ratios import craft_ratios

    def named(frequency: float, error: float, fail: str) -> list[str]:
        found = craft_ratios({"scan": {"v10": {"growth": 0.1267, "frequency": frequency}}, "rel_error_pct": error,
                              "open_01": {"fail": fail, "y": 47.4, "dtheta": 0.0}})
        measured = {"checked_pages": ["controllers.md", "rotorcraft.md"], "craft_stability": found}
        return [b for b in pages_differences(measured) if any(w in b for w in ("a period of", "Jacobian to",
                                                                                "after the step"))]

    assert craft_ratios({"rel_error_pct": 0.998, "open_01": {"fail": "33.0"}})["open_01"]["after_step"] == 32.0
    assert named(0.497, 0.998, "33.0") == []
    assert len(named(0.52, 0.998, "33.0")) == 2 and len(named(0.497, 1.2, "34.0")) == 2


def test_the_mills_run_after_the_step_is_named_when_changed():
    """getting_started.md's "stops about 20 s after the step (21.45 s simulated, the step at 1 s)" and its picture's
    caption: simulate's span less the step's 1 s (20.45 s); a span of 22.65 s (21.65 s after) is named twice."""
    def named(span: str) -> list[str]:
        measured = {"checked_pages": ["getting_started.md"],
                    "simulate_laddermill": {"simulated": span, "after_1s": float(span) - 1.0}}
        return [b for b in pages_differences(measured) if "s after" in b and "printed no" not in b]

    assert named("21.45") == [] and len(named("22.65")) == 2


CLAIM = """controller                       return  length [s]  max |dy| [m]  power [W]  failures
ppo_mill                        6039.23       300.0        0.0940   154025.9  -
lqr                             6039.22       300.0        0.0948   154025.9  -
"""


def test_the_claims_rows_are_worked_from_evaluates_table():
    """learned_mill.md's "5 of 5 | 300.0 | 0.0940 | 154.026 (100.0 % of the LQR's)" (laddermill evaluate --episodes 5,
    2026-11-30): 154025.9 W is 154.026 kW, 100.0 % of the LQR's; a failure, or 153925.9 W (99.94 %), is named."""
    from docsite.printed_ratios import evaluate_rows

    rows = evaluate_rows(CLAIM, 5, "lqr")
    assert rows["ppo_mill"]["held"] == "5 of 5" and round(rows["ppo_mill"]["power_kW"], 4) == 154.0259
    assert evaluate_rows(CLAIM, 5, "lqr:lqr_ladder_chain_central") == {}
    assert long_check_differences({"mill_claim": {"printed": CLAIM}}) == []
    worse = CLAIM.replace("154025.9  -\nlqr", "153925.9  1 x aerodynamic range exceeded\nlqr")
    bad = long_check_differences({"mill_claim": {"printed": worse}})
    assert len(bad) == 1 and "'1 x aerodynamic range exceeded'" in bad[0] and "~99.93" in bad[0], bad


STRESS = """PASS  laddermill             random controls              ok
      t_end_s=20, min_wing_height_m=58.34, max_tension_N=1.634e+05, max_kinetic_energy_J=5.742e+05
PASS  laddermill             bang-bang controls           terminated (limit of the quasi-steady model): wing 12 (angle
      t_end_s=5.46, min_wing_height_m=54.94, max_tension_N=1.808e+05, max_kinetic_energy_J=4.25e+06

128 passed, 0 failed
"""


def test_the_stress_runs_counts_are_its_summary():
    """work_precision.md's and features.md's counts as laddermill stress printed them on 2026-11-30 after c576da4
    (128 passed, 0 failed: the mill under bang-bang controls ends at 5.46 s at a limit of the quasi-steady model);
    the day's first run (127 passed, 1 failed: that case a failure) fails both pages' checks."""
    from docsite.printed_ratios import stress_counts

    assert stress_counts(STRESS) == {"passed": "128", "failed": "0", "total": "128", "fail_t": {},
                                     "end_t": {"laddermill/random controls": 20.0,
                                               "laddermill/bang-bang controls": 5.46}}
    assert long_check_differences({"stress_all": {"printed": STRESS}}) == []
    old = STRESS.replace("PASS  laddermill             bang-bang controls           terminated (limit of the "
                         "quasi-steady model): wing 12 (angle", "FAIL  laddermill             bang-bang controls    "
                         "       failed: integration failed at t = 5.46 s (speed or rate limit)")
    old = old.replace("128 passed, 0 failed", "127 passed, 1 failed")
    assert stress_counts(old)["fail_t"] == {"laddermill/bang-bang controls": 5.46}
    bad = long_check_differences({"stress_all": {"printed": old}})
    assert sorted(b.split(":")[0] for b in bad) == ["docs/features.md", "docs/work_precision.md"], bad
