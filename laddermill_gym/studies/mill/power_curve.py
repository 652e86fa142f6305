"""The laddermill's power curve (issue 30 point 3): mean electrical power against the cable speed V_c at the paper's
wind, and the best V_c and its power against the wind speed V0.

Run ``laddermill power-curve [--out results/power_curve] [--quick] [--workers N]`` (or ``python -m
laddermill_gym.studies.mill.power_curve``). Scene ``laddermill_v1`` (the v1 wing, docs/wing_data.md "Design study")
in plane (``dimension: 2``), the cable speed ramped from rest in the scene's 30 s and held; each case is run to
its periodic motion (:func:`laddermill_gym.ladder.periodic.run_to_periodic`, shape and power repeating to 1e-3
for two periods, at most ``max_time`` s). Per case: the mean electrical power over the last period, the hand
estimate (T_first - T_last) V_c from the period-mean tensions (the paper's relation, closed form), whether the
motion is periodic, and the largest tension of the last period against the cable's breaking load divided by the
safety factor :data:`SAFETY_FACTOR` (``within_limit``); ``t_peak_search_kN`` is the largest tension of the whole
search, which includes the transient from the start at rest (the mill jerked to V_c in 30 s).

Tail settings, the stated rule (:func:`tail_rule`): every case flies the scene's own elevators (ascending -8 deg,
descending -0.5 deg), for which the v1 design was chosen; a wing's trim alpha depends on its elevator and cable
attachment, not on the wind or the cable speed (derivations/pitch_stability.py), so one setting holds each leg's
C_L across the curve.

Writes ``power_curve.csv`` (one row per case), ``power_curve.json`` (settings, rows, best V_c per V0) and
``power_curve.png`` (power against V_c at the paper's wind; best power and V_c against V0).
"""

from __future__ import annotations

import csv
import dataclasses
import json
from pathlib import Path

import numpy as np

from laddermill_gym.studies import parallel
from laddermill_gym.studies.commands import Parser, UsageError, check_number

SCENE = "laddermill_v1"
PAPER_V0 = 8.0  # [m/s] Meijaard et al. 1999, the example's wind at h0 = 50 m
PAPER_POWER_W = 200e3  # [W] Meijaard et al. 1999: "of the order of 200 kW"
#: [-] tension limit = breaking_load / SAFETY_FACTOR: F_s = 2.5 of Lansdorp, Ruiterkamp, Williams & Ockels,
#: "Long-Term Laddermill Modeling for Site Selection" (AIAA 2008), its nominal case (../shared/papers/003_*.txt)
SAFETY_FACTOR = 2.5


@dataclasses.dataclass(frozen=True)
class Config:
    """speeds [m/s]: V_c at the paper's wind; winds [m/s]: V0 of the second sweep; wind_speeds [m/s]: the V_c
    tried per wind; max_time [s]: periodic search per case; n_wings: None for the scene's 101."""

    speeds: tuple[float, ...] = (0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    winds: tuple[float, ...] = (4.0, 6.0, 8.0, 10.0, 12.0, 14.0)
    wind_speeds: tuple[float, ...] = (1.0, 2.0, 3.0)
    max_time: float = 1500.0
    n_wings: int | None = None


QUICK = Config(speeds=(2.0,), winds=(8.0,), wind_speeds=(2.0,), max_time=70.0)


def tail_rule(scene_initial) -> tuple[float, float]:
    """(ascending, descending) elevator [deg] of a case: the scene's own settings for every V0 and V_c."""
    return float(np.degrees(scene_initial.elevator_up)), float(np.degrees(scene_initial.elevator_down))


def hand_estimate_w(t_first_n: float, t_last_n: float, v_c: float) -> float:
    """The paper's power relation, closed form: (T_first - T_last) V_c [W] from the tensions [N] and V_c [m/s]."""
    return (t_first_n - t_last_n) * v_c


def run_case(v0: float, v_c: float, max_time: float, n_wings: int | None = None, scene: str = SCENE) -> dict:
    """One case in plane: the scene at wind V0 [m/s] and cable speed V_c [m/s] run to its periodic motion."""
    from laddermill_gym import load_scene
    from laddermill_gym.ladder.periodic import run_to_periodic

    sc = load_scene(scene, dimension=2, n_wings=n_wings,
                    overrides={"wind": {"v0": float(v0)}, "station": {"speed_m_s": [0.0, float(v_c)]}})
    up, down = tail_rule(sc.initial)
    sim = sc.simulator()
    res = run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=False)
    breaking = float(np.min(sc.assembly.elements.breaking_load))
    limit = breaking / SAFETY_FACTOR
    t_max = float(np.max(res.tension_max_N))
    return {"v0_m_s": float(v0), "v_c_m_s": float(v_c), "elevator_up_deg": up, "elevator_down_deg": down,
            "periodic": bool(res.converged), "t_s": float(res.t_s), "power_kW": res.mean_electrical_power_W / 1e3,
            "hand_estimate_kW": hand_estimate_w(res.tension_mean_N[0], res.tension_mean_N[-1], v_c) / 1e3,
            "t_first_kN": float(res.tension_mean_N[0]) / 1e3, "t_last_kN": float(res.tension_mean_N[-1]) / 1e3,
            "t_max_kN": t_max / 1e3, "t_limit_kN": limit / 1e3, "within_limit": bool(t_max <= limit),
            "t_peak_search_kN": float(res.peak_tension_ratio) * breaking / 1e3,
            "breakdown": res.breakdown or ""}


def best_per_wind(rows: list[dict]) -> list[dict]:
    """Per V0: the periodic case within the tension limit with the largest power (None fields when none is)."""
    out = []
    for v0 in sorted({r["v0_m_s"] for r in rows}):
        ok = [r for r in rows if r["v0_m_s"] == v0 and r["periodic"] and r["within_limit"]]
        best = max(ok, key=lambda r: r["power_kW"]) if ok else None
        out.append({"v0_m_s": v0, "best_v_c_m_s": best and best["v_c_m_s"], "power_kW": best and best["power_kW"]})
    return out


def run(cfg: Config, workers: int = 0, progress: bool = True) -> tuple[list[dict], list[dict]]:
    """Both sweeps; returns (rows, best per wind over every row: the paper's wind included). The paper's wind's V_c
    are shared by the two sweeps."""
    cases = [(PAPER_V0, v) for v in cfg.speeds]
    cases += [(w, v) for w in cfg.winds for v in cfg.wind_speeds if (w, v) not in cases]
    tasks = [(run_case, dict(v0=w, v_c=v, max_time=cfg.max_time, n_wings=cfg.n_wings)) for w, v in cases]
    rows = parallel.run_tasks(tasks, workers=workers, desc="power curve", unit="case", progress=progress)
    return rows, best_per_wind(rows)


def write(out: Path, cfg: Config, rows: list[dict], best: list[dict]) -> list[Path]:
    """CSV, JSON and PNG under ``out``; returns the paths."""
    from matplotlib.figure import Figure

    out.mkdir(parents=True, exist_ok=True)
    paths = [out / "power_curve.csv", out / "power_curve.json", out / "power_curve.png"]
    with open(paths[0], "w", newline="", encoding="utf-8") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    meta = {"scene": SCENE, "safety_factor": SAFETY_FACTOR, "config": dataclasses.asdict(cfg),
            "tail_rule": "the scene's elevators for every case (tail_rule)", "rows": rows, "best_per_wind": best}
    paths[1].write_text(json.dumps(meta, indent=1), encoding="utf-8")
    fig = Figure(figsize=(11, 4.2))
    ax1, ax2 = fig.subplots(1, 2)
    paper = [r for r in rows if r["v0_m_s"] == PAPER_V0 and r["v_c_m_s"] in cfg.speeds]
    for flag, mk, lab in ((True, "o-", "periodic"), (False, "x", "not periodic (last period)")):
        sel = [r for r in paper if r["periodic"] == flag]
        if sel:
            ax1.plot([r["v_c_m_s"] for r in sel], [r["power_kW"] for r in sel], mk, label=lab)
    ax1.axhline(PAPER_POWER_W / 1e3, color="grey", ls="--", label="paper: of the order of 200 kW")
    ax1.set(xlabel="cable speed V_c [m/s]", ylabel="mean electrical power [kW]",
            title=f"{SCENE}, in plane, V0 = {PAPER_V0:g} m/s")
    ax1.legend(fontsize=8)
    okb = [b for b in best if b["power_kW"] is not None]
    over = [r for r in rows if r["periodic"] and not r["within_limit"]]
    ax2.plot([r["v0_m_s"] for r in over], [r["power_kW"] for r in over], "x", color="grey",
             label="periodic, tension over the limit")
    ax2.plot([b["v0_m_s"] for b in okb], [b["power_kW"] for b in okb], "o-", color="C0", label="best within the limit")
    ax2.legend(fontsize=8)
    ax2.set(xlabel="wind speed V0 at 50 m [m/s]", ylabel="best mean power [kW]", title="best V_c per wind")
    ax3 = ax2.twinx()
    ax3.plot([b["v0_m_s"] for b in okb], [b["best_v_c_m_s"] for b in okb], "s--", color="C1")
    ax3.set_ylabel("best V_c [m/s]", color="C1")
    fig.tight_layout()
    fig.savefig(paths[2], dpi=110)
    return paths


def _config(args) -> Config:
    """The sweep's settings: ``--quick`` or the full one, with the options given replacing its fields."""
    cfg = QUICK if args.quick else Config()
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


def main(argv=None) -> int:

    p = Parser(prog="laddermill power-curve", description=__doc__.splitlines()[0])
    p.add_argument("--out", default="results/power_curve", help="output folder (CSV, JSON, PNG)")
    p.add_argument("--quick", action="store_true", help="one case, V_c = 2 m/s at the paper's wind, 70 s search")
    p.add_argument("--speeds", type=float, nargs="+", default=None, metavar="V_C",
                   help="cable speeds [m/s] at the paper's wind (default: the full sweep's)")
    p.add_argument("--winds", type=float, nargs="+", default=None, metavar="V0", help="winds V0 [m/s] of the sweep")
    p.add_argument("--wind-speeds", type=float, nargs="+", default=None, metavar="V_C",
                   help="cable speeds [m/s] tried per wind")
    p.add_argument("--max-time", type=float, default=None, help="periodic search per case [s]")
    parallel.add_arguments(p)
    args = p.parse_args(argv)
    parallel.check_arguments(args, p.prog)
    try:
        cfg = _config(args)
    except UsageError as err:
        p.error(str(err))
    rows, best = run(cfg, workers=args.workers)
    print(f"{SCENE}, in plane; tension limit breaking load / {SAFETY_FACTOR} = {rows[0]['t_limit_kN']:.0f} kN")
    print("   V0   V_c  elev up/down  periodic     P [kW]  (T1-Tn)V_c [kW]  T_max [kN]  within limit  "
          "search peak [kN]")
    for r in rows:
        print(f"{r['v0_m_s']:5.1f} {r['v_c_m_s']:5.2f}  {r['elevator_up_deg']:5.1f}/{r['elevator_down_deg']:5.1f}  "
              f"{str(r['periodic']):8s} {r['power_kW']:9.1f} {r['hand_estimate_kW']:15.1f} {r['t_max_kN']:11.1f}  "
              f"{str(r['within_limit']):12s}  {r['t_peak_search_kN']:8.1f}")
    for b in best:
        txt = "no periodic case within the limit" if b["power_kW"] is None else \
            f"best V_c {b['best_v_c_m_s']:.1f} m/s, {b['power_kW']:.1f} kW"
        print(f"V0 = {b['v0_m_s']:.1f} m/s: {txt}")
    for path in write(Path(args.out), cfg, rows, best):
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
