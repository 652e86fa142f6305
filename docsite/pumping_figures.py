"""Page groups of the pumping kite's pages (docs/paper_lansdorp2008.md): ``laddermill site`` (the quasi-steady site
optimisation, eqs. 1-20) and ``laddermill pumping-cycle`` (the dynamic cycle), each run in a fresh process and
parsed from what it prints."""

from __future__ import annotations

import math
import re
import tempfile

from docsite.paper_figures import printed_match, run_command

#: pumping_cycle's printed columns, in order: cycle, its time [s], simulated power, Schmehl matched [W], its tension
#: [N], Lansdorp eqs. 1-14, Schmehl, eq. 9's static kite, eqs. 10-14 fed the simulation [W], reel-out tension [N], speed
#: [m/s], reel-in tension [N], alpha [deg], max |dy| [m]
CYCLE_COLUMNS = ("cycle", "t_cycle", "sim", "matched", "matched_tension", "lansdorp", "schmehl", "static", "fed",
                 "tension_out", "speed_out", "tension_in", "alpha", "max_dy")
TABLE2_ROWS = {"Kite altitude": "altitude", "Cable angle": "angle", "Cable diameter": "diameter",
               "Kite area": "area", "Average kite C_L": "cl"}


def _need(pattern: str, text: str, argv: list[str]) -> re.Match:
    return printed_match(pattern, text, f"python -m {' '.join(argv)}")


def site_tables() -> dict:
    """``laddermill site`` (about 35 s): Table 2's design (eq. 20) per wind source ("weather2010" daily means,
    "cabauw" clusters: altitude [m], cable angle [deg], cable diameter [mm], kite area [m^2], mean C_L, as printed;
    altitude_m: the altitude to the metre),
    the same of Table 1 (eq. 16; keys ending "_1"), the share of the time the Cabauw clusters cover [%], and per
    source the capacity table's rows of the laddermill and of the windpowerlib turbine of the same rating
    (``kite_row``, ``turbine_row``: rated [MW], height [m], mean [MW], capacity factor [%], energy [GWh/yr]; the
    capacity factors alone and the turbine's name) and the laddermill's peak [MW]."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.cli", "site", "--out", tmp]
        out = run_command(argv, 900)
    found = {"weather2010": {}, "cabauw": {}}
    for table, suffix in (("table1 \\(eq\\. 16\\)", "_1"), ("table2 \\(eq\\. 20\\)", "")):
        block = _need(rf"^## {table}\n((?:.*\n)+?)\n## ", out, argv).group(1)
        for label, key in TABLE2_ROWS.items():
            cells = [c.strip() for c in _need(rf"^\| {re.escape(label)} \|.*$", block, argv).group(0).split("|")[1:-1]]
            found["weather2010"][key + suffix], found["cabauw"][key + suffix] = cells[3], cells[4]
    for source in found.values():
        source["altitude_m"] = f"{float(source['altitude']):.0f}"
    found["cabauw"]["covered_pct"] = _need(r"cabauw: wind-speed bins cover ([\d.]+) % of the time", out, argv).group(1)
    for source in ("weather2010", "cabauw"):
        block = _need(rf"^((?:\|.*\n){{2}})\| \(data: {source}", out, argv).group(1)
        kite, turbine = ([c.strip() for c in line.split("|")[1:-1]] for line in block.splitlines())
        found[source].update(kite_row=kite[1:], turbine_row=turbine[1:], kite_cf=kite[4], turbine_cf=turbine[4],
                             turbine=turbine[0].split(" ")[0])
        found[source]["peak_MW"] = _need(rf"\(data: {source}; laddermill peak ([\d.]+) MW", out, argv).group(1)
    # the models' line of Table 2's design on Cabauw: Schmehl / Lansdorp at 4, 6, 8, 12, 16, 20, 25 m/s, and the
    # lowest wind of Schmehl's flown loop; models_lo / models_hi: the least and largest ratio at 8-25 m/s
    m = _need(r"table2 design on cabauw, models_cabauw\.png: .* m/s: ([\d. ]+); Schmehl's loop flown from ([\d.]+) m/s",
              out, argv)
    ratios = m.group(1).split()
    strong = sorted(ratios[2:], key=float)
    found["cabauw"].update(models_4=ratios[0], models_6=ratios[1], models_lo=strong[0], models_hi=strong[-1],
                           models_from=m.group(2))
    return found


def pumping_cycle_lqr() -> dict:
    """``laddermill pumping-cycle --cycles 3 --controller lqr`` (the static scripted cycle with the lateral LQR; about
    25 s): per cycle the simulated mean power, Lansdorp's eqs. 1-14 and Schmehl's model at the cycle's
    parameters, the static-kite form of eq. 9 and eqs. 10-14 fed the simulated tension and speed [W] (``rows``); and
    each one's range over the cycles after the first in kW as the page rounds it ("lo-hi", or one figure when both
    round alike; ``static_all``, ``fed_all``: over every cycle); ``dy_bound``: the next whole metre above the largest
    max |dy| of every cycle (the page's "stays below 6 m")."""
    argv = ["laddermill_gym.cli", "pumping-cycle", "--cycles", "3", "--controller", "lqr"]
    out = run_command(argv, 1800)
    _need(r"^ *cycle +T_c s +sim W +matched W +m\. T_out N +Lansdorp W +Schmehl W +static W +eq10-14 fed W ", out, argv)
    rows = [dict(zip(CYCLE_COLUMNS, line.split(), strict=True)) for line in out.splitlines()
            if re.match(r"^ +\d+ +[\d.]+ +\d+ ", line)]
    if len(rows) < 2:
        raise RuntimeError(f"python -m {' '.join(argv)} printed fewer than two cycle rows:\n{out[-2000:]}")

    def kw(column: str, digits: int, first: int = 1) -> str:
        values = [float(r[column]) / 1e3 for r in rows[first:]]  # by default the cycles after the first (from the trim)
        lo, hi = f"{min(values):.{digits}f}", f"{max(values):.{digits}f}"
        return lo if lo == hi else f"{lo}-{hi}"

    return {"rows": rows, "sim": kw("sim", 1), "lansdorp": kw("lansdorp", 0), "schmehl": kw("schmehl", 0),
            "static": kw("static", 1), "fed": kw("fed", 2), "static_all": kw("static", 1, 0),
            "fed_all": kw("fed", 2, 0), "dy_bound": dy_bound(rows)}


def dy_bound(rows: list[dict]) -> str:
    """The next whole metre above the largest ``max_dy`` [m] of the cycle ``rows`` (the page's "below 6 m")."""
    return str(math.floor(max(float(r["max_dy"]) for r in rows)) + 1)


def pumping_evaluate() -> dict:
    """``laddermill evaluate --env laddermill_gym/PumpingKite-v0 --controllers open_loop scripted lqr --episodes 4``
    (400 s episodes, the registered 0.01 rad direction step; about 35 s): per controller its printed return, length
    [s], max |dy| [m], power [W] and failure ("-": none), and the power as the page writes it ("0 W" or "13.1 kW")."""
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["laddermill_gym.cli", "evaluate", "--env", "laddermill_gym/PumpingKite-v0", "--controllers",
                "open_loop", "scripted", "lqr", "--episodes", "4", "--out", tmp]
        out = run_command(argv, 1800)
    found = {}
    for name in ("open_loop", "scripted", "lqr"):
        row = _need(rf"^{name} +(\S+) +(\S+) +(\S+) +(\S+) +(.+)$", out, argv)
        found[name] = dict(zip(("return", "length", "dy", "power", "failure"), row.groups(), strict=True))
        watts = float(row.group(4))
        found[name]["power_text"] = "0 W" if watts == 0 else f"{watts / 1e3:.1f} kW"
    return found


def tether_convergence() -> dict:
    """``python -m laddermill_gym.studies.pumping.tether_convergence`` (the crosswind cycle on the single element and on
    reeling tethers of 100, 60, 40 and 30 m; 2-5 minutes): per element length ("l300", "l100", ...) the RK4 step [ms],
    the elements at the start and over the run ("3-5"; "1" for the single element), the power [W], the reel-out
    tension [N] and speed [m/s], the reel-in tension [N], the cycle [s], alpha [deg] and the nodes on the ground
    ("-" for the single element), from its JSON, as its table prints them."""
    import json
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        run_command(["laddermill_gym.studies.pumping.tether_convergence", "--out", tmp], 2400)
        rows = json.loads((Path(tmp) / "tether_convergence.json").read_text())
    found = {}
    for r in rows:
        single = r["elements_min"] == r["elements_max"] == 1
        found[f"l{r['element_length_m']:.0f}"] = {
            "dt_ms": f"{1e3 * r['dt_s']:.1f}", "start": f"{r['elements_at_start']:g}",
            "elements": "1" if single else f"{r['elements_min']}-{r['elements_max']}", "power": f"{r['power_W']:.0f}",
            "T_out": f"{r['tension_out_N']:.0f}", "v_out": f"{r['speed_out_m_s']:.2f}",
            "T_in": f"{r['tension_in_N']:.0f}",
            "cycle": f"{r['cycle_s']:.1f}", "alpha": f"{r['alpha_deg']:.2f}", "ground": "-" if single else
            str(r["contacts_max"])}
    return found


#: This module's page groups (merged into docsite.page_figures.GROUPS).
def site_sweeps() -> dict:
    """``laddermill site --sweeps`` (the tables and Figs. 14-18's sweeps; 4 min 7 s wall, 92 s CPU at nice 15 and a load
    of 4-6, 2026-11-30): {"printed": its whole output}, for docs/quasisteady.md's Printed snippets."""
    with tempfile.TemporaryDirectory() as tmp:
        return {"printed": run_command(["laddermill_gym.cli", "site", "--sweeps", "--out", tmp], 1800)}


PUMPING_GROUPS = {"site_tables": site_tables, "site_sweeps": site_sweeps, "pumping_cycle_lqr": pumping_cycle_lqr,
                  "pumping_evaluate": pumping_evaluate, "tether_convergence": tether_convergence}
