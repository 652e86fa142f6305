"""Figures a docs page works from a long group's printed columns (ratios, ranges, bounds, a unit changed), each a small
function of the group's printed output, so that a changed run fails the page's check (the review's #15, 2026-11-30:
until then these were ``derived`` entries, checked by nobody).

:data:`RATIOS` maps a long group (:data:`docsite.long_figures.LONG`) to its function; :func:`with_ratios` adds what
each returns to the group's figures before :func:`docsite.long_checks.long_check_differences` compares the checks
that name it (``{reeling_power_curve_printed[tension_model][lo]}``), with the strict rule of
:func:`docsite.printed_numbers.template_agrees` (a ``~`` template: the value rounded to the quoted digits). A
function returns {} when its table is not in the output, so the check names the missing field.

Ranges are the smallest and largest over every row the command prints ("lo", "hi"); a bound such as "within 1e-3"
is the next power of ten above the largest value, "below 6 m" the next whole metre above it: a run that moves the
figure across that step fails the check, though the page's bound may still hold.
"""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
CONTROL_PERIOD_S = 0.05  # [s] LadderChain-v0's and LadderMill-v2's control period (their registered dt_control)
WITHIN_30 = 0.7  # the pages' criterion: simulated power at least 70 % of Schmehl's matched model ("within 30 %")


def _numbers(line: str, n: int) -> list[float] | None:
    """The ``n`` numbers of a table row (parentheses dropped), or None when it is not such a row."""
    cells = line.replace("(", " ").replace(")", " ").replace("/", " ").split()
    try:
        values = [float(c) for c in cells]
    except ValueError:
        return None
    return values if len(values) == n and all(math.isfinite(v) for v in values) else None


def _span(values: list[float]) -> dict:
    return {"lo": min(values), "hi": max(values)}


def power_curve_ratios(printed: str) -> dict:
    """``power_curve``'s three tables (sim W, matched W, ratio, Schmehl W, Lansdorp W, T_out N, matched T_out N per
    wind; the loss split; the reel-out tensions: drum, wing, wing / drum, 1/2 rho S C_R <v_a^2>, model [N]) as the
    pages read them: ``within30`` the winds [m/s] where sim / matched >= 0.7 ("lo", "hi"; both "winds A, B" when
    they are not one run of the table's winds) and those ratios to 3 decimals (", "-joined); over every wind the
    ranges of T_out / matched T_out (``tension_model``), of |wing / drum - 1| [%] (``wing_drum_pct``, its largest),
    of the aerodynamic force over the wing's tension, less 1 [%] (``aero_above_pct``), and of the aerodynamic force
    over the model's tension (``aero_model``)."""
    head, _, rest = printed.partition("matched - simulated by phase")
    _, _, tensions = rest.partition("reel-out tension [N]:")
    curve = [row for row in (_numbers(line.split("  no trim")[0], 8) for line in head.splitlines()) if row]
    pulls = [row for row in (_numbers(line, 6) for line in tensions.splitlines()) if row]
    if not curve or not pulls:
        return {}
    winds = [r[0] for r in curve]
    within = [r for r in curve if r[1] / r[2] >= WITHIN_30]
    run = [w for w in winds if within and within[0][0] <= w <= within[-1][0]]
    lo, hi = ((f"{within[0][0]:g}", f"{within[-1][0]:g}") if run == [r[0] for r in within] and within
              else ("winds " + ", ".join(f"{r[0]:g}" for r in within),) * 2)
    return {"within30": {"lo": lo, "hi": hi, "ratios": ", ".join(f"{r[1] / r[2]:.3f}" for r in within)},
            "tension_model": _span([r[6] / r[7] for r in curve]),
            "wing_drum_pct": max(abs(r[2] / r[1] - 1.0) for r in pulls) * 100.0,
            "aero_above_pct": _span([(r[4] / r[2] - 1.0) * 100.0 for r in pulls]),
            "aero_model": _span([r[4] / r[5] for r in pulls])}


def cycle_ratio(printed: str) -> dict:
    """``pumping-cycle``'s table (cycle, T_c, sim W, matched W, ...): its last cycle's sim / matched
    (``last_ratio``)."""
    rows = [line.split() for line in printed.splitlines() if re.match(r"^ +\d+ +[\d.]+ +-?\d+ +-?\d+ ", line)]
    return {"last_ratio": float(rows[-1][2]) / float(rows[-1][3])} if rows else {}


STEP_HEAD = re.compile(r"^laddermill_gym/(\S+): [\d.]+ s, extent [\d.]+ m; reference RK4 at [\d.]+ s ran (\d+) periods",
                       re.M)
STEP_ROW = re.compile(r"^ +([\w:]+) *: largest position error ([\d.e+-]+) m = ([\d.e+-]+) of the extent over (\d+) "
                      r"periods", re.M)


def step_accuracy(printed: str) -> dict:
    """``physics_step_accuracy``'s blocks, per env ("LadderMill-v2"): for the reference and each step ("ros2") the
    episode's end, (periods + 1) x the 50 ms control period [s] (``end_s``), and for each step its largest position
    error in cm (``cm``); ``share_bound``: per step the next power of ten above its largest share of the extent over
    the envs ("1e-3")."""
    found, shares = {}, {}
    heads = list(STEP_HEAD.finditer(printed))
    for k, head in enumerate(heads):
        block = printed[head.end():heads[k + 1].start() if k + 1 < len(heads) else len(printed)]
        env = found.setdefault(head.group(1), {"reference": {"end_s": round((int(head.group(2)) + 1)
                                                                             * CONTROL_PERIOD_S, 9)}})
        for m in STEP_ROW.finditer(block):
            env[m.group(1)] = {"cm": float(m.group(2)) * 100.0, "end_s": round((int(m.group(4)) + 1)
                                                                                * CONTROL_PERIOD_S, 9)}
            shares.setdefault(m.group(1), []).append(float(m.group(3)))
    if found:
        found["share_bound"] = {s: f"1e{math.ceil(math.log10(max(v)))}" if max(v) > 0.0 else "0"
                                for s, v in shares.items()}
    return found


def breaking_load_n(cable: str = "dyneema_25mm") -> float:
    """The cable's breaking load [N] from ``configs/cables/<cable>.yaml`` (the v2 mill's cable)."""
    return float(yaml.safe_load((ROOT / "configs" / "cables" / f"{cable}.yaml").read_text())["breaking_load"])


def mill_step_peak(printed: str) -> dict:
    """``fast_mill step``'s wind step (``wind x 1.125``): its printed peak tension over the limit (the breaking load,
    breaking fraction 1) as printed (``peak_ratio``) and times the cable's breaking load [kN] (``peak_kN``)."""
    m = re.search(r"wind x 1\.125 at .*?peak tension ([\d.]+) x the limit", printed)
    return {"peak_ratio": m.group(1), "peak_kN": float(m.group(1)) * breaking_load_n() / 1e3} if m else {}


def fidelity_ratios(printed: str) -> dict:
    """``pointmass_fidelity``'s tension line (first piece rigid, point mass; last piece rigid / point mass [kN]): the
    point mass's first and last piece over the rigid one's, less 1 [%] (``first_pct``, ``last_pct``)."""
    m = re.search(r"^tension: first piece rigid ([\d.]+) kN, point mass ([\d.]+) kN; last piece ([\d.]+) / ([\d.]+) "
                  r"kN", printed, re.M)
    if m is None:
        return {}
    a, b, c, d = (float(x) for x in m.groups())
    return {"first_pct": (b / a - 1.0) * 100.0, "last_pct": (d / c - 1.0) * 100.0}


def kite_travel(printed: str) -> dict:
    """``pointmass_benchmark``'s accuracy run: how far the kites travel [cm] (``kites_cm``)."""
    m = re.search(r"kites travel up to ([\d.e+-]+) m", printed)
    return {"kites_cm": float(m.group(1)) * 100.0} if m else {}


def craft_ratios(found: dict) -> dict:
    """``craft_stability``'s parsed figures (:func:`docsite.page_figures.craft_stability`) with the pages' figures
    worked from them: the 10 m/s mode's period 2 pi / frequency [s] (``period_v10``), the largest relative error's
    next whole percent ("1" for 0.998 %; ``rel_error_bound``), and per run its failure after the 1 s direction step
    [s] (``after_step``, "" without a failure)."""
    runs = {k: {**v, "after_step": float(v["fail"]) - 1.0 if v.get("fail") else ""}
            for k, v in found.items() if k.startswith(("open_", "lqr_"))}
    v10 = found.get("scan", {}).get("v10")
    return {**found, **runs, "period_v10": 2 * math.pi / v10["frequency"] if v10 else "",
            "rel_error_bound": str(math.ceil(found["rel_error_pct"]))}


def stress_counts(printed: str) -> dict:
    """``laddermill stress``'s summary ("127 passed, 1 failed") and its FAIL lines' scene, case and end [s]:
    ``passed``, ``failed``, ``total``, ``fail_t`` ({"laddermill/bang-bang controls": 5.46}) and ``end_t`` (every case's
    end [s], passed or failed, by the same key)."""
    m = re.search(r"^(\d+) passed, (\d+) failed$", printed, re.M)
    if m is None:
        return {}
    ends = {f"{a}/{b.strip()}": float(t) for a, b, t in re.findall(
        r"^FAIL +(\S+) +(.+?) {2,}failed: .*\n +t_end_s=([\d.]+)", printed, re.M)}
    every = {f"{a}/{b.strip()}": float(t) for a, b, t in re.findall(
        r"^(?:PASS|FAIL) +(\S+) +(.+?) {2,}\S.*\n +t_end_s=([\d.]+)", printed, re.M)}
    return {"passed": m.group(1), "failed": m.group(2), "total": str(int(m.group(1)) + int(m.group(2))),
            "fail_t": ends, "end_t": every}


def evaluate_rows(printed: str, episodes: int, reference: str) -> dict:
    """``laddermill evaluate``'s summary rows (controller, return, length [s], max |dy| [m], power [W], failures): per
    controller its power [kW] (``power_kW``), the episodes held of the ``episodes`` run ("5 of 5" where it prints no
    failure, else its failures; ``held``) and its power over the ``reference`` row's [%] (``pct``)."""
    rows = {m.group(1): (float(m.group(2)), m.group(3).strip()) for m in re.finditer(
        r"^(\S+) +-?[\d.]+ +[\d.]+ +[\d.]+ +(-?[\d.]+) +(.+)$", printed, re.M)}
    if reference not in rows:
        return {}
    return {name: {"power_kW": watts / 1e3, "pct": 100.0 * watts / rows[reference][0],
                   "held": f"{episodes} of {episodes}" if failures == "-" else failures}
            for name, (watts, failures) in rows.items()}


def bench_energy(printed: str) -> dict:
    """``laddermill gust-bench``'s CSV as printed (its header ``env,controller,scenario,seed,...,energy_J,...``): per
    controller and "scenario/seed" ("direction_step/0") the episode's energy [MJ] (``energy_MJ``)."""
    lines = printed.splitlines()
    head = next((line.split(",") for line in lines if line.startswith("env,controller,scenario,seed,")), None)
    if head is None or "energy_J" not in head:
        return {}
    k, found = head.index("energy_J"), {}
    for cells in csv.reader(line for line in lines if line.startswith("laddermill_gym/")):
        if len(cells) == len(head):
            found.setdefault(cells[1], {})[f"{cells[2]}/{cells[3]}"] = float(cells[k]) / 1e6
    return {"energy_MJ": found} if found else {}


#: long group -> the function of its printed output whose figures its pages' checks name.
RATIOS = {"reeling_power_curve_printed": power_curve_ratios, "pumping_power_curve_printed": power_curve_ratios,
          "reeling_cycle_40": cycle_ratio, "step_accuracy_10": step_accuracy, "step_accuracy_40": step_accuracy,
          "fast_mill_v2_step": mill_step_peak, "pointmass_fidelity": fidelity_ratios,
          "pointmass_accuracy": kite_travel, "gusts_v3_pumping_v1": bench_energy,
          "stress_all": stress_counts, "mill_claim": lambda out: evaluate_rows(out, 5, "lqr"),  # --episodes 5
          "chain_claim": lambda out: evaluate_rows(out, 5, "lqr:lqr_ladder_chain_central")}


def with_ratios(long: dict) -> dict:
    """``long`` ({group: figures}) with each group's :data:`RATIOS` figures added (from its ``"printed"``)."""
    return {name: {**(RATIOS[name](figures.get("printed", "")) if name in RATIOS and isinstance(figures, dict)
                      else {}), **figures} if isinstance(figures, dict) else figures
            for name, figures in long.items()}
