"""``laddermill site``: optimise a pumping laddermill for a site's wind (Lansdorp et al. 2008, eqs. 16-20) and
write Tables 1-2 beside the paper's, Figs. 10-20 and the turbine comparison (also ``python -m
laddermill_gym.quasisteady.cli``)."""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import sys
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.atmosphere.site_wind import SiteWindError
from laddermill_gym.quasisteady import site_outputs as so
from laddermill_gym.quasisteady.site_data import SHIPPED, load_wind
from laddermill_gym.quasisteady.site_optimise import (
    TABLE1,
    TABLE2,
    altitude_angle_grid,
    covered_heights,
    operate,
    optimise,
    sweep,
)

SWEEPS = {  # Figs. 15-18: parameter, values, unit
    "kite_glide": (np.array([5.0, 7.0, 10.0, 13.0, 16.0]), "-"),
    "reel_in_speed": (np.array([4.0, 8.0, 12.0, 16.7, 25.0]), "m/s"),
    "reel_length": (np.array([100.0, 200.0, 300.0, 450.0, 600.0]), "m"),
    "reel_in_tension_ratio": (np.array([0.01, 0.02, 0.05, 0.1, 0.2]), "-"),
}


def _eval_spec(spec: str) -> str:
    """The states a design is run through (Figs. 19-20, capacity factor): the hourly data behind daily means."""
    if spec == "weather2010-daily":
        return "weather2010"
    return spec[len("daily:"):] if spec.startswith("daily:") else spec


def _tag(spec: str) -> str:
    """A file-name part for a data set: the shipped name, or the file's stem."""
    daily = spec.startswith("daily:")
    name = spec[len("daily:"):] if daily else spec
    name = name if name in SHIPPED else Path(name).name.split(".")[0]
    return ("daily_" if daily else "") + name


def _note(wind, r) -> str:
    if wind.is_extrapolated(r.design.h):
        return (f"wind at {r.design.h:.0f} m is an extrapolation ({wind.extrapolation}); measured up to "
                f"{wind.measured_top:g} m")
    return "; ".join(wind.notes)


def _run_case(case, spec, wind, out, quiet, fmt="auto"):
    r = optimise(case, wind)
    stem = f"{case.name}_{_tag(spec)}"
    files = [so.plot_design(r, wind.weight, wind.labels, out / f"{stem}_figs10-13.png",
                            f"{case.name} on {spec}: h {r.design.h:.0f} m, S {r.design.S:.0f} m^2")]
    ev = _evaluation_wind(spec, fmt)
    w_ev = ev.at(r.design.h)
    ok = np.isfinite(w_ev)
    runs = {f"f <= {lab}": operate(case, r.design, w_ev[ok], fm)[:2] for lab, fm in (("1/3", 1 / 3), ("1/2", 0.5))}
    files.append(so.plot_operation(runs, ev.weight[ok], out / f"{stem}_figs19-20.png",
                                   f"{case.name} design run through {_eval_spec(spec)}"))
    if not quiet:
        print(f"  {case.name} on {spec}: {r.states} states, {r.evaluations} inner solves, {r.wall_time:.2f} s, "
              f"feasible {r.feasible}" + "".join(f"; on a bound: {note}" for note in r.at_bounds))
        # the time mean (eq. 16's P-bar): time outside the data, and states without data at h, count as no power
        means = ", ".join(f"{lab} mean {np.sum(ev.weight[ok] * P) / 1e6:.3f} MW" for lab, (P, _) in runs.items())
        print(f"  {case.name} design run through {_eval_spec(spec)} (figs. 19-20): {means}"
              + "".join(f"; {note}" for note in ev.notes))
    return r, ev, w_ev[ok], ev.weight[ok], files


def _turbine(case, r, spec, w_ev, p_ev, ev, hub, turbine, out):
    from laddermill_gym.quasisteady import turbine as tb

    P, *_ = operate(case, r.design, w_ev, 0.5)
    name = turbine if turbine != "auto" else tb.nearest_turbine(float(np.max(P)))
    ty = tb.turbine_yield(ev, name, hub)
    lm = tb.laddermill_yield(f"laddermill {case.name} (f <= 1/2)", P, p_ev, ty.rated_power, r.design.h,
                             ev.is_extrapolated(r.design.h))
    path = so.plot_yields([lm, ty], out / f"turbine_{_tag(spec)}.png",
                          f"same rated power {ty.rated_power / 1e6:.2f} MW on {_eval_spec(spec)} (* extrapolated)")
    return [lm, ty], path, float(np.max(P))


def _evaluation_wind(spec: str, fmt: str):
    """The states a design is run through (:func:`_eval_spec`), read in the ``--format`` the user gave; exit 2
    naming the data when they cannot be read."""
    try:
        return load_wind(_eval_spec(spec), fmt)
    except (SiteWindError, ValueError) as err:
        _fail(f"--wind {spec!r}: {err}")


def _check_turbine_type(name: str) -> None:
    """Exit 2 naming ``--turbine`` unless windpowerlib's library has a power curve for the type ``name``."""
    from laddermill_gym.quasisteady.turbine import turbine_library

    try:
        lib = turbine_library()
    except ImportError as err:
        _fail(f"--turbine {name!r}: {err} (or --no-turbine)")
    known = set(lib[lib["has_power_curve"]]["turbine_type"])
    if name not in known:
        near = sorted(t for t in known if name.split("/")[0].lower() in t.lower())[:5]
        _fail(f"--turbine {name!r}: not a windpowerlib turbine type with a power curve"
              + (f" (of that maker: {', '.join(near)})" if near else " ('auto' picks the nearest rated power)"))


def _fail(message: str):
    print(f"laddermill site: error: {message}", file=sys.stderr)
    raise SystemExit(2)


def _check_heights(spec: str, wind, cases, args) -> None:
    """Exit 2 naming the option unless every case's altitude bounds meet the data's heights and the turbine's hub
    lies within the evaluation data's (checked before any optimisation runs)."""
    try:
        bottom, top = covered_heights(wind)
    except ValueError as err:
        _fail(f"--wind {spec!r}: {err}")
    for cname in args.case:
        lo, hi = cases[cname].h_bounds
        if max(lo, bottom) > min(hi, top):
            _fail(f"--wind {spec!r}: every state has data at {bottom:g}-{top:g} m only (data heights "
                  f"{wind.heights[0]:g}-{wind.heights[-1]:g} m, {wind.source}), outside {cname}'s altitude bounds "
                  f"{lo:g}-{hi:g} m")
    if (bottom, top) != (wind.heights[0], wind.heights[-1]):
        print(f"note: --wind {spec!r}: not every state has data at {wind.heights[0]:g}-{wind.heights[-1]:g} m; the "
              f"design altitude is kept within {bottom:g}-{top:g} m, where all have (elsewhere a state without data "
              "would count as calm)", file=sys.stderr)
    if not args.no_turbine:
        ev = _evaluation_wind(spec, args.format)
        if not ev.heights[0] <= args.hub_height <= ev.heights[-1]:
            _fail(f"--hub-height = {args.hub_height:g} m: outside the heights {ev.heights[0]:g}-{ev.heights[-1]:g} m "
                  f"of {_eval_spec(spec)} ({ev.source}), where the turbine is evaluated")


def run(args) -> int:
    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        _fail(f"--out {args.out!r}: cannot make the folder ({err})")
    base = {"table1": dataclasses.replace(TABLE1, k1=args.k1, power_target=args.power_mw * 1e6),
            "table2": dataclasses.replace(TABLE2, power_target=args.power_mw * 1e6)}
    tables, record, files, yields = {c: {} for c in args.case}, {}, [], []
    if not args.no_turbine and args.turbine != "auto":
        _check_turbine_type(args.turbine)
    winds = {}
    for spec in args.wind:  # every data set read and checked before the first optimisation
        try:
            winds[spec] = load_wind(spec, args.format)
        except (SiteWindError, ValueError) as err:
            _fail(f"--wind {spec!r}: {err}")
        _check_heights(spec, winds[spec], base, args)
    for spec, wind in winds.items():
        print(f"{spec}: {wind.n} wind states, {wind.heights[0]:g}-{wind.heights[-1]:g} m ({wind.source})"
              + "".join(f"; {note}" for note in wind.notes))
        for cname in args.case:
            case = base[cname]
            r, ev, w_ev, p_ev, f = _run_case(case, spec, wind, out, args.quiet, args.format)
            files += f
            tables[cname][spec] = (r, wind.weight, _note(wind, r))
            record[f"{cname}/{spec}"] = {"design": dataclasses.asdict(r.design), "feasible": r.feasible,
                                         "mean_power_W": r.solution.mean_power,
                                         "mean_tension_N": r.solution.mean_tension, "F_max_N": r.solution.f_max,
                                         "values": so.design_values(r, wind.weight), "wall_time_s": r.wall_time,
                                         "inner_solves": r.evaluations, "states": r.states,
                                         "at_bounds": list(r.at_bounds)}
            if cname == args.case[-1]:
                speeds = np.linspace(3.0, 25.0, 45)
                curves = so.model_power_curves(case, r.design, speeds)
                files.append(so.plot_models(curves, speeds, out / f"models_{_tag(spec)}.png",
                                            f"{cname} design on {spec}: Lansdorp vs Schmehl quasi-steady model"))
                if not args.quiet:
                    print(f"  {cname} design on {spec}, models_{_tag(spec)}.png: {so.model_ratio_text(curves, speeds)}")
                if not args.no_turbine:
                    ys, path, peak = _turbine(case, r, spec, w_ev, p_ev, ev, args.hub_height, args.turbine, out)
                    yields.append((spec, ys, peak))
                    files.append(path)
        if args.sweeps:
            files += _sweeps(base[args.case[0]], spec, wind, out, args.sweep_states, args.quiet)
    text = []
    for cname, res in tables.items():
        text += [f"## {cname} ({'eq. 16' if base[cname].cost == 'eq16' else 'eq. 20'})", "", so.table_markdown(cname,
                                                                                                                res)]
    if yields:
        text += ["## Capacity factor beside a wind turbine of the same rated power", "",
                 "| machine | rated [MW] | height [m] | mean power [MW] | capacity factor [%] | energy [GWh/yr] |",
                 "|---|---|---|---|---|---|"]
        for spec, ys, peak in yields:
            text += [y.row() for y in ys] + [f"| (data: {_eval_spec(spec)}; laddermill peak {peak / 1e6:.2f} MW; "
                                             f"time outside the data counts as no power) | | | | | |"]
    (out / "tables.md").write_text("\n".join(text) + "\n")
    record["yields"] = {spec: [dataclasses.asdict(y) for y in ys] for spec, ys, _ in yields}
    (out / "results.json").write_text(json.dumps(record, indent=1, default=float))
    print("\n".join(text))
    print("wrote", out / "tables.md", out / "results.json", *files, sep="\n  ")
    missed = [f"{cname} on {spec}" for cname, res in tables.items() for spec, (r, _, _) in res.items()
              if not r.feasible]
    if missed:  # the tables show the last design tried, marked: not a design that meets the target
        print(f"laddermill site: no design within the bounds delivers the {args.power_mw:g} MW mean power for "
              f"{', '.join(missed)} (tables marked infeasible; exit status 1)", file=sys.stderr)
        return 1
    return 0


#: Fig. 14's altitudes in the paper [m] (Lansdorp et al. 2008: 200-600 m)
PAPER_FIG14_HEIGHTS = np.linspace(200.0, 600.0, 9)


def fig14_heights(wind) -> np.ndarray:
    """Fig. 14's altitudes [m]: the paper's 200-600 m in 50 m steps within the heights every state has data for
    (:func:`covered_heights`; a fixed altitude outside them is refused), or, where fewer than two of those lie
    within them, nine across what the data cover (one where they cover a single height)."""
    bottom, top = covered_heights(wind)
    hs = PAPER_FIG14_HEIGHTS[(PAPER_FIG14_HEIGHTS >= bottom) & (PAPER_FIG14_HEIGHTS <= top)]
    if hs.size >= 2:
        return hs
    return np.linspace(bottom, top, 9) if top > bottom else np.array([bottom])


def _sweeps(case, spec, wind, out, n_states, quiet):
    sub = wind.subset(slice(None, None, max(1, wind.n // n_states)))
    sub = dataclasses.replace(sub, weight=sub.weight / sub.weight.sum() * wind.weight.sum())
    hs, thetas = fig14_heights(wind), np.radians(np.linspace(45.0, 80.0, 8))
    if not np.isin(hs, PAPER_FIG14_HEIGHTS).all():
        print(f"laddermill site: Fig. 14 of {spec} at {hs[0]:g}-{hs[-1]:g} m, the heights its data cover (the paper's "
              "200-600 m lie outside them)", file=sys.stderr)
    total = hs.size * thetas.size + sum(v.size for v, _ in SWEEPS.values())
    with tqdm(total=total, desc=f"sensitivity on {sub.n} states", disable=quiet) as bar:
        grid = altitude_angle_grid(case, sub, hs, thetas, bar)
        runs = {k: (v, sweep(case, sub, k, v, bar), u) for k, (v, u) in SWEEPS.items()}
    tag = _tag(spec)
    return [so.plot_altitude_angle(hs, thetas, grid, out / f"fig14_{tag}.png",
                                   f"Fig. 14 on {sub.n} states of {spec} ({case.name})"),
            so.plot_sweeps(runs, out / f"figs15-18_{tag}.png", f"Figs. 15-18 on {sub.n} states of {spec}")]


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("site", help="optimise a pumping laddermill for a site's wind (Lansdorp et al. 2008)",
                       description=__doc__.replace("``", ""))
    p.add_argument("--wind", nargs="+", default=["weather2010-daily", "cabauw"],
                   help=f"shipped data {sorted(SHIPPED)} or wind files ('daily:FILE' for daily means)")
    p.add_argument("--format", default="auto", choices=("auto", "csv", "wyoming", "two-heights"))
    p.add_argument("--case", nargs="+", default=["table1", "table2"], choices=("table1", "table2"))
    p.add_argument("--power-mw", type=float, default=1.0, help="design mean power P_d [MW] (eq. 19)")
    p.add_argument("--k1", type=float, default=TABLE1.k1, help="kite-area weight of eq. 16 [N/m^2]")
    p.add_argument("--sweeps", action="store_true", help="also the sensitivity studies (Figs. 14-18)")
    p.add_argument("--sweep-states", type=int, default=120, help="states used by the sweeps (a subset, as the paper)")
    p.add_argument("--no-turbine", action="store_true", help="skip the windpowerlib turbine comparison")
    p.add_argument("--turbine", default="auto", help="windpowerlib turbine type, or 'auto' (nearest rated power)")
    p.add_argument("--hub-height", type=float, default=80.0, help="turbine hub height [m]")
    p.add_argument("--out", default="runs/site", help="output folder")
    p.add_argument("--quiet", action="store_true")
    p.set_defaults(func=run)
    return p


class _OneLineParser(argparse.ArgumentParser):
    """argparse with its errors on one line and exit status 2, as every ``laddermill`` command (the commands' own
    ``studies.commands.Parser`` is a layer above this package, which may not import it)."""

    def error(self, message: str):
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


#: numeric options and their lower bounds (strict: > low): the design power, the kite-area weight (>= 0), the
#: sweeps' number of states and the turbine's hub height
_BOUNDS = (("power_mw", 0.0, True), ("k1", 0.0, False), ("sweep_states", 0.0, True), ("hub_height", 0.0, True))


def main(argv=None) -> int:
    parser = _OneLineParser(prog="laddermill")
    add_parser(parser.add_subparsers(dest="command", required=True, parser_class=_OneLineParser))
    args = parser.parse_args(["site", *(argv if argv is not None else sys.argv[1:])])
    for name, low, strict in _BOUNDS:
        v = getattr(args, name)
        if not (math.isfinite(v) and (v > low if strict else v >= low)):
            parser.exit(2, f"laddermill site: error: --{name.replace('_', '-')} = {v!r}: must be a finite number "
                           f"{'>' if strict else '>='} {low:g} (see laddermill site --help)\n")
    return args.func(args)


if __name__ == "__main__":
    raise SystemExit(main())
