"""The laddermill's power curve (issue 30 point 3): mean electrical power against the cable speed V_c at the paper's
wind, and the best V_c and its power against the wind speed V0.

Run ``laddermill power-curve [--scene laddermill_v2] [--ramp rate] [--out results/power_curve] [--quick]
[--workers N]`` (or ``python -m laddermill_gym.studies.mill.power_curve``). Scene (``--scene``): ``laddermill_v2``
(the default: the v2 wing, docs/mill_fast.md "A wing whose lift falls with its air speed (v2)", the design whose
in-plane mill is periodic over the paper's range, 1-5 m/s) or ``laddermill_v1`` (the v1 wing, docs/wing_data.md
"Design study", periodic at 0.5-2 m/s only), in plane (``dimension: 2``). Each case starts at rest; the cable speed is
ramped from 0 to V_c by the ramp rule (:func:`ramp_time`, ``--ramp``): ``rate`` (the default) reaches V_c at the
scene's own acceleration (v2: 2 m/s over 200 s, 0.01 m/s^2, so 100 V_c s: the ramp the v2 mill needs from rest;
v1: 2 m/s over 30 s, 15 V_c s), ``scene`` takes the scene's ramp time for every V_c (the v1 table of
docs/wing_data.md). Then the case is run to its periodic motion (:func:`laddermill_gym.ladder.periodic.run_to_periodic`,
shape and power repeating to 1e-3 for two periods, at most ``max_time`` s of search after the ramp); a case that is
not periodic is reported as such with its last period, a breakdown (during the ramp or the search) with its time and
message, never dropped. Per case: the mean electrical power over the last period, the hand estimate (T_first -
T_last) V_c from the period-mean tensions (the paper's relation, closed form), the Betz bound of the wind power
through the loop's frontal strip (:func:`betz_bound_w`), whether the motion is periodic, and the largest tension of
the last period against the cable's breaking load divided by the safety factor :data:`SAFETY_FACTOR`
(``within_limit``); ``t_rest_max_kN`` is the largest tension of the rest state the case starts from and
``t_peak_search_kN`` the largest of the search (every step after the ramp). The ramp is stepped in one call, as
run_to_periodic and ``fast_mill case`` step it (so a case is bit for bit that command's case); its tensions are not
sampled.

Tail settings, the stated rule (``--tail-rule``, :func:`laddermill_gym.studies.mill.tail_schedule.tail_rule`):
``depower`` (the default), the scene's elevators up to the paper's V0 = 8 m/s (the same floats, so those cases are
``scene``'s bit for bit) and above it each leg's trim C_L the scene's at 8 m/s times (8 / V0)^n, n = 2 ascending and
1.75 descending; ``scene``, the scene's elevators for every case. The V_c per wind: every one of ``speeds`` at the
paper's wind; at the other winds the adaptive search of :mod:`vc_search` (its cases in sequence, winds in parallel),
or a fixed grid (``--wind-speeds``). ``--replay`` walks the run over earlier runs' rows and runs nothing.

Writes ``power_curve.csv`` (one row per case), ``power_curve.json`` (settings, rows, best V_c per V0) and
``power_curve.png`` (power against V_c at the paper's wind; best power and V_c against V0).
"""

from __future__ import annotations

import csv
import dataclasses
import json
import sys
from pathlib import Path

import numpy as np

from laddermill_gym.studies import parallel
from laddermill_gym.studies.commands import Parser, UsageError, check_number, writable_folder
from laddermill_gym.studies.mill import vc_search
from laddermill_gym.studies.mill.power_curve_plot import plot_power_curve
from laddermill_gym.studies.mill.tail_schedule import RULES, tail_rule

SCENES = ("laddermill_v2", "laddermill_v1")  # the first: the default (periodic over the paper's 1-5 m/s)
SCENE = SCENES[0]
RAMPS = ("rate", "scene")  # ramp rules (ramp_time); the first: the default
PAPER_V0 = 8.0  # [m/s] Meijaard et al. 1999, the example's wind at h0 = 50 m
PAPER_POWER_W = 200e3  # [W] Meijaard et al. 1999: "of the order of 200 kW"
#: [-] tension limit = breaking_load / SAFETY_FACTOR: F_s = 2.5 of Lansdorp, Ruiterkamp, Williams & Ockels,
#: "Long-Term Laddermill Modeling for Site Selection" (AIAA 2008), its nominal case (../shared/papers/003_*.txt)
SAFETY_FACTOR = 2.5
BETZ = 16.0 / 27.0  # [-] Betz's limit on the power an actuator disc takes from the wind through it

@dataclasses.dataclass(frozen=True)
class Config:
    """speeds [m/s]: V_c at the paper's wind (every one run); winds [m/s]: V0 of the second sweep; wind_speeds
    [m/s]: None (the default) for the adaptive search per wind (:mod:`vc_search`: 2, 3, 5 m/s, up through 6-10 while
    the fastest operates, 4 between, 1 and 0.5 below), or a fixed grid of V_c tried per wind; max_time [s]: periodic
    search per case after the ramp; n_wings: None for the scene's 101; scene: one of SCENES; ramp: one of RAMPS;
    tail: one of RULES (default ``depower``: the scene's elevators up to 8 m/s, bit for bit)."""

    speeds: tuple[float, ...] = (0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    winds: tuple[float, ...] = (4.0, 6.0, 8.0, 10.0, 12.0, 14.0)
    wind_speeds: tuple[float, ...] | None = None
    max_time: float = 1500.0
    n_wings: int | None = None
    scene: str = SCENE
    ramp: str = RAMPS[0]
    tail: str = "depower"


QUICK = Config(speeds=(2.0,), winds=(8.0,), wind_speeds=(2.0,), max_time=70.0)


def ramp_time(station, v_c: float, rule: str) -> float:
    """The time [s] the cable speed takes from rest to ``v_c`` [m/s]: ``rate``, at the scene's own acceleration
    (its schedule's last speed over its last time); ``scene``, the scene's ramp time whatever V_c."""
    t, v = np.asarray(station.speed_times, float), np.asarray(station.speed_values, float)
    if t.size != 2 or v[0] != 0.0 or not v[1] > 0.0:
        raise ValueError(f"station.speed_m_s = {list(v)} at speed_times_s = {list(t)}: the ramp rule needs one ramp "
                         "from rest (0 m/s) to a positive speed")
    if rule == "scene":
        return float(t[1] - t[0])
    if rule == "rate":
        return float(v_c * (t[1] - t[0]) / v[1])
    raise ValueError(f"ramp rule {rule!r}: use one of {RAMPS}")


def betz_bound_w(wind, span: float, h_low: float, h_high: float, n: int = 4001) -> float:
    """Betz's limit [W] on the wind power through the loop's frontal strip: BETZ times the integral of
    rho(h) V(h)^3 / 2 over the span [m] wide strip from h_low to h_high [m] (the wings' lowest and highest height;
    in plane both legs fly in the same strip). ``wind``: the scene's WindParams (the paper's eqs. 1 and 3: power law
    below h0, linear above; barometric density); trapezoidal rule on ``n`` points."""
    if wind.density_model != "barometric":
        raise ValueError(f"wind.density_model = {wind.density_model!r}: the bound is written for 'barometric'")
    h = np.linspace(max(h_low, 0.0), max(h_high, 0.0), n)
    v = np.where(h < wind.h0, wind.v0 * (np.maximum(h, 0.0) / wind.h0) ** wind.exponent,
                 wind.v0 + wind.v1 * (h - wind.h0))
    rho = wind.rho0 * np.exp(-h / wind.scale_height)
    f = 0.5 * rho * v ** 3 * span
    return float(BETZ * np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(h)))


def hand_estimate_w(t_first_n: float, t_last_n: float, v_c: float) -> float:
    """The paper's power relation, closed form: (T_first - T_last) V_c [W] from the tensions [N] and V_c [m/s]."""
    return (t_first_n - t_last_n) * v_c


def run_case(v0: float, v_c: float, max_time: float, n_wings: int | None = None, scene: str = SCENE,
             ramp: str = RAMPS[0], tail: str = "depower") -> dict:
    """One case in plane: the scene at wind V0 [m/s], from rest, its cable speed ramped to V_c [m/s] by the ramp
    rule and held, its elevators by the tail rule, run to its periodic motion (or a breakdown, or ``max_time`` [s]
    of search)."""
    from laddermill_gym import load_scene
    from laddermill_gym.ladder.periodic import run_to_periodic
    from laddermill_gym.sim.simulator import SimulationError

    base = load_scene(scene, dimension=2)
    t_ramp = ramp_time(base.assembly.station, v_c, ramp)
    up, down = tail_rule(base.initial, base.assembly.wing(0), v0, tail)
    overrides = {"wind": {"v0": float(v0)},
                 "station": {"speed_times_s": [0.0, t_ramp], "speed_m_s": [0.0, float(v_c)]}}
    if (up, down) != tail_rule(base.initial, base.assembly.wing(0), v0, "scene"):  # else the file's own (bit for bit)
        overrides["initial"] = {"elevator_up_deg": up, "elevator_down_deg": down}
    sc = load_scene(scene, dimension=2, n_wings=n_wings, overrides=overrides)
    breaking = float(np.min(sc.assembly.elements.breaking_load))
    limit = breaking / SAFETY_FACTOR
    row = {"scene": scene, "tail_rule": tail, "v0_m_s": float(v0), "v_c_m_s": float(v_c), "ramp_s": t_ramp,
           "elevator_up_deg": up, "elevator_down_deg": down, "t_limit_kN": limit / 1e3}
    sim = sc.simulator()
    row["t_rest_max_kN"] = float(np.max(sim.tensions())) / 1e3
    try:
        res = run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=False)
    except SimulationError as err:  # the search catches its own; this is the ramp (stepped in one call)
        nan = float("nan")
        return row | {"periodic": False, "t_s": float(sim.t), "power_kW": nan, "hand_estimate_kW": nan,
                      "h_low_m": nan, "h_high_m": nan, "betz_kW": nan,
                      "t_first_kN": nan, "t_last_kN": nan, "t_max_kN": nan, "within_limit": False,
                      "t_peak_search_kN": nan, "breakdown": f"during the ramp: {err}", "overload": ""}
    t_max, peak = float(np.max(res.tension_max_N)), float(res.peak_tension_ratio) * breaking
    h_low, h_high = float(np.min(-res.shape_m[:, 2])), float(np.max(-res.shape_m[:, 2]))  # [m] the wings' heights
    betz = betz_bound_w(sc.assembly.wind, sc.assembly.wing(0).span, h_low, h_high)
    return row | {"periodic": bool(res.converged), "t_s": float(res.t_s), "power_kW": res.mean_electrical_power_W / 1e3,
                  "hand_estimate_kW": hand_estimate_w(res.tension_mean_N[0], res.tension_mean_N[-1], v_c) / 1e3,
                  "h_low_m": h_low, "h_high_m": h_high, "betz_kW": betz / 1e3,
                  "t_first_kN": float(res.tension_mean_N[0]) / 1e3, "t_last_kN": float(res.tension_mean_N[-1]) / 1e3,
                  "t_max_kN": t_max / 1e3,
                  "within_limit": bool(t_max <= limit), "t_peak_search_kN": peak / 1e3,
                  "breakdown": res.breakdown or "", "overload": res.overload.text() if res.overload else ""}


def best_per_wind(rows: list[dict]) -> list[dict]:
    """Per V0: the periodic case within the tension limit with the largest power, if positive (a mill that takes
    power is no operating point: :func:`vc_search.best`); None fields when there is none."""
    out = []
    for v0 in sorted({r["v0_m_s"] for r in rows}):
        best = vc_search.best([r for r in rows if r["v0_m_s"] == v0])
        out.append({"v0_m_s": v0, "best_v_c_m_s": best and best["v_c_m_s"], "power_kW": best and best["power_kW"]})
    return out


def tasks(cfg: Config, case=run_case) -> list[tuple]:
    """The sweep as tasks (fn, kwargs): one case per V_c at the paper's wind; per other wind the adaptive search
    (one task, its cases in sequence: :func:`vc_search.search_case`) or, with a fixed ``wind_speeds``, one case per
    V_c. ``case``: run_case, or a :class:`vc_search.Lookup` (``--replay``)."""
    settings = dict(max_time=cfg.max_time, n_wings=cfg.n_wings, scene=cfg.scene, ramp=cfg.ramp, tail=cfg.tail)
    cases = [(PAPER_V0, v) for v in cfg.speeds]
    out = [(case, dict(v0=w, v_c=v, **settings)) for w, v in cases]
    if cfg.wind_speeds is None:
        return out + [(vc_search.search_case, dict(v0=w, case=case, **settings)) for w in cfg.winds if w != PAPER_V0]
    return out + [(case, dict(v0=w, v_c=v, **settings)) for w in cfg.winds for v in cfg.wind_speeds
                  if (w, v) not in cases]


def _flat(results: list) -> list[dict]:
    """The tasks' results as rows: a search's list of rows in its order."""
    return [r for res in results for r in (res if isinstance(res, list) else [res])]


def run(cfg: Config, workers: int = 0, progress: bool = True, ray: str | None = None) -> tuple[list[dict], list[dict]]:
    """Both sweeps, winds in parallel (``workers`` local processes, or on Ray at ``ray``), the cases of one wind's
    search in sequence; returns (rows, best per wind over every row: the paper's wind included)."""
    rows = _flat(parallel.run_tasks(tasks(cfg), workers=workers, ray=ray, desc="power curve", unit="task",
                                    progress=progress))
    return rows, best_per_wind(rows)


def replay(cfg: Config, metas: list[dict], names: list[str]) -> tuple[list[dict], list[dict]]:
    """The run ``cfg`` walked over earlier runs' rows (:func:`write`'s JSON, ``names`` their files), no case run: a
    row stands for a case when its file's scene, ramp, max_time and n_wings and its elevators are the run's (a later
    file's replacing an earlier one's); raises :class:`vc_search.MissingCase` naming a case the walk needs that none
    holds. Returns (rows, best per wind) as :func:`run` would."""
    from laddermill_gym import load_scene

    base = load_scene(cfg.scene, dimension=2)
    elevators = {}
    held: dict = {}
    for meta in metas:
        c = meta["config"]
        if (c["scene"], c["ramp"], c["max_time"], c["n_wings"]) != (cfg.scene, cfg.ramp, cfg.max_time, cfg.n_wings):
            continue
        for r in meta["rows"]:
            v0 = r["v0_m_s"]
            if v0 not in elevators:
                elevators[v0] = tail_rule(base.initial, base.assembly.wing(0), v0, cfg.tail)
            if (r["elevator_up_deg"], r["elevator_down_deg"]) == elevators[v0]:
                held[(v0, r["v_c_m_s"])] = r
    lookup = vc_search.Lookup(held, " ".join(names))
    rows = _flat([fn(**kw) for fn, kw in tasks(cfg, lookup)])
    return rows, best_per_wind(rows)


def write(out: Path, cfg: Config, rows: list[dict], best: list[dict]) -> list[Path]:
    """CSV, JSON and PNG under ``out``; returns the paths."""
    out.mkdir(parents=True, exist_ok=True)
    paths = [out / "power_curve.csv", out / "power_curve.json", out / "power_curve.png"]
    with open(paths[0], "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    meta = {"scene": cfg.scene, "safety_factor": SAFETY_FACTOR, "config": dataclasses.asdict(cfg),
            "ramp_rule": {"rate": "V_c reached at the scene's own acceleration (ramp_time)",
                          "scene": "the scene's ramp time for every V_c (ramp_time)"}[cfg.ramp],
            "tail_rule": {"scene": "the scene's elevators for every case (tail_rule)",
                          "depower": "above V0 8 m/s the elevators whose trim C_L is the scene's at 8 m/s times "
                                     "(8 / V0)^2 ascending, (8 / V0)^1.75 descending (tail_rule)"}[cfg.tail],
            "rows": rows, "best_per_wind": best}
    paths[1].write_text(json.dumps(meta, indent=1), encoding="utf-8")
    plot_power_curve(paths[2], cfg, rows, best, PAPER_V0, PAPER_POWER_W)
    return paths


def _limit_cell(row: dict) -> str:
    """'ok' / 'OVER' for the last period's largest tension against the limit; 'n/a' when the ramp broke down."""
    return "n/a" if row["t_max_kN"] != row["t_max_kN"] else ("ok" if row["within_limit"] else "OVER")


def print_table(cfg: Config, rows: list[dict], best: list[dict]) -> None:
    """The rows, the breakdowns and overloads, and the best V_c per wind, as the docs quote them."""
    print(f"{cfg.scene}, in plane, ramp rule '{cfg.ramp}', tail rule '{cfg.tail}', search {cfg.max_time:g} s; "
          f"tension limit breaking load / {SAFETY_FACTOR} = {rows[0]['t_limit_kN']:.0f} kN")
    print("   V0   V_c  ramp [s]  elev up/down  periodic   t [s]     P [kW]  (T1-Tn)V_c [kW]  Betz [kW]  "
          "T_rest  T_max  limit  search peak [kN]")
    for r in rows:
        print(f"{r['v0_m_s']:5.1f} {r['v_c_m_s']:5.2f} {r['ramp_s']:8.0f}  {r['elevator_up_deg']:5.2f}/"
              f"{r['elevator_down_deg']:5.2f}  {str(r['periodic']):8s} {r['t_s']:7.1f} {r['power_kW']:9.1f} "
              f"{r['hand_estimate_kW']:15.1f} {r['betz_kW']:10.0f}  {r['t_rest_max_kN']:6.1f} {r['t_max_kN']:6.1f}  "
              f"{_limit_cell(r):5s}  {r['t_peak_search_kN']:8.1f}")
    for r in rows:
        for what in ("breakdown", "overload"):
            if r[what]:
                print(f"V0 {r['v0_m_s']:g} m/s, V_c {r['v_c_m_s']:g} m/s: {what} {r[what]}")
    for b in best:
        txt = "no periodic case within the limit" if b["power_kW"] is None else \
            f"best V_c {b['best_v_c_m_s']:.1f} m/s, {b['power_kW']:.1f} kW"
        print(f"V0 = {b['v0_m_s']:.1f} m/s: {txt}")


def _config(args) -> Config:
    """The sweep's settings: ``--quick`` or the full one, with the options given replacing its fields."""
    cfg = dataclasses.replace(QUICK if args.quick else Config(), scene=args.scene, ramp=args.ramp,
                              tail=args.tail_rule)
    for opt, name in (("--speeds", "speeds"), ("--winds", "winds"), ("--wind-speeds", "wind_speeds")):
        values = getattr(args, name)
        if values is not None:
            for v in values:
                check_number(opt, v, low=0.0, high=30.0, unit="m/s")
            cfg = dataclasses.replace(cfg, **{name: tuple(values)})
    if args.max_time is not None:
        check_number("--max-time", args.max_time, low=0.0, unit="s")
        cfg = dataclasses.replace(cfg, max_time=args.max_time)
    return cfg


def merge_tables(metas: list[dict]) -> tuple[Config, list[dict]]:
    """The settings and rows of earlier runs' JSON (:func:`write`): rows in order, a later run's (V0, V_c) replacing
    an earlier one's; the last run's settings with the cable speeds of all (``wind_speeds`` None when every run
    searched adaptively); a row from before the tail rule was recorded gets its run's (``scene``)."""
    cases: dict = {}
    cfgs = []
    for meta in metas:
        cfg = Config(**({"tail": "scene"} | {k: tuple(v) if isinstance(v, list) else v
                                             for k, v in meta["config"].items()}))
        cfgs.append(cfg)
        for r in meta["rows"]:
            cases[(r["v0_m_s"], r["v_c_m_s"])] = {"scene": r["scene"], "tail_rule": cfg.tail} | r
    join = lambda name: tuple(sorted({v for c in cfgs for v in getattr(c, name) or ()}))  # noqa: E731
    # the fixed wind-speed grids' union; None (the adaptive search) where no run had one: an empty grid crashed the
    # figure's caption after the table was written
    return (dataclasses.replace(cfgs[-1], speeds=join("speeds"), wind_speeds=join("wind_speeds") or None),
            list(cases.values()))


def main(argv=None) -> int:
    p = Parser(prog="laddermill power-curve", description=__doc__.split("\n\n")[0])
    p.add_argument("--out", default="results/power_curve", help="output folder (CSV, JSON, PNG)")
    p.add_argument("--scene", choices=SCENES, default=SCENE,
                   help=f"the mill (default {SCENE}: periodic over the paper's 1-5 m/s; laddermill_v1: 0.5-2 m/s)")
    p.add_argument("--ramp", choices=RAMPS, default=RAMPS[0],
                   help="cable speed from rest: 'rate' at the scene's own acceleration (default; v2: 100 V_c s), "
                        "'scene' in the scene's ramp time whatever V_c")
    p.add_argument("--tail-rule", choices=RULES, default=Config.tail,
                   help="elevators per case: 'depower' (default) the scene's up to V0 8 m/s, above it the trim C_L "
                        "of 8 m/s times (8 / V0)^2 ascending, (8 / V0)^1.75 descending; 'scene' the scene's always")
    p.add_argument("--quick", action="store_true", help="one case, V_c = 2 m/s at the paper's wind, 70 s search")
    p.add_argument("--speeds", type=float, nargs="*", default=None, metavar="V_C",
                   help="cable speeds [m/s] at the paper's wind (default: the full sweep's; none: only the winds')")
    p.add_argument("--winds", type=float, nargs="*", default=None, metavar="V0",
                   help="winds V0 [m/s] of the sweep (none: the paper's wind only)")
    p.add_argument("--wind-speeds", type=float, nargs="+", default=None, metavar="V_C",
                   help="cable speeds [m/s] tried per wind, a fixed grid (default: the adaptive search of "
                        "studies/mill/vc_search.py: 2, 3, 5; up through 6-10 while the fastest operates; 4; 1, 0.5)")
    p.add_argument("--max-time", type=float, default=None, help="periodic search per case after the ramp [s]")
    p.add_argument("--table", metavar="JSON", nargs="+", default=None,
                   help="print the table and write the files again from earlier runs' power_curve.json (no run); "
                        "several: their rows merged, a later file's case replacing an earlier one's, the settings "
                        "of the last file, its cable speeds joined with the others'")
    p.add_argument("--replay", metavar="JSON", nargs="+", default=None,
                   help="walk this command's run over earlier runs' power_curve.json rows (no case run): fails "
                        "naming a case the run needs that they do not hold; prints and writes as the run would")
    parallel.add_arguments(p)
    args = p.parse_args(argv)
    parallel.check_arguments(args, p.prog)
    try:
        if args.table is not None and args.replay is not None:
            raise UsageError("--table and --replay: give one (--table redraws earlier runs, --replay walks a run "
                             "over them)")
        cfg = _config(args)
        writable_folder(args.out)  # a bad folder named before the cases, not after them
        earlier = _earlier_runs("--table" if args.table is not None else "--replay", args.table or args.replay or [])
    except UsageError as err:
        p.error(str(err))
    if args.table is not None:  # the rows of an earlier run, printed and drawn again
        cfg, rows = merge_tables(earlier)
        best = best_per_wind(rows)
    elif args.replay is not None:  # this run, its cases looked up in earlier runs
        try:
            rows, best = replay(cfg, earlier, args.replay)
        except vc_search.MissingCase as err:
            print(f"{p.prog} --replay: {err}", file=sys.stderr)
            return 1
    else:
        rows, best = run(cfg, workers=args.workers, ray=args.ray)
    print_table(cfg, rows, best)
    for path in write(Path(args.out), cfg, rows, best):
        print(f"wrote {path}")
    return 0


def _earlier_runs(option: str, files: list[str]) -> list[dict]:
    """The earlier runs' ``power_curve.json`` contents; UsageError naming ``option`` and the file that is missing,
    not JSON, or without the run's ``config`` and ``rows``."""
    runs = []
    for f in files:
        try:
            meta = json.loads(Path(f).read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, json.JSONDecodeError) as err:
            raise UsageError(f"{option} {f!r}: not a readable power_curve.json ({type(err).__name__}: {err})") from None
        missing = [k for k in ("config", "rows") if not isinstance(meta, dict) or k not in meta]
        if missing:
            raise UsageError(f"{option} {f!r}: not a power_curve.json of this command (no {' or '.join(missing)})")
        runs.append(meta)
    return runs


if __name__ == "__main__":
    raise SystemExit(main())
