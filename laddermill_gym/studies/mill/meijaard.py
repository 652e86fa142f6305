"""Meijaard, Ockels & Schwab (1999), "Examples of application", redone with the moving cable: Figs. 6, 7 and 8 beside
the paper's words about them.

Run ``python -m laddermill_gym.studies.mill.meijaard [--scene laddermill_v1] [--out results/meijaard] [--quick]``.
Default scene ``laddermill_v1`` (LadderMill-v1's mill: the v1 wing, docs/wing_data.md "Design study"); ``--scene
laddermill`` redoes the v0 reproduction (LadderMill-v0's wing) as before; any other moving-cable scene name works
the same way. 101 wings on 70 m pieces, V_c ramped from rest in 30 s, then held. Printed and written as CSV and PNG:

* Fig. 6 / 7: the in-plane (2D) mill run to its periodic stationary motion
  (:func:`laddermill_gym.ladder.periodic.run_to_periodic`) for V_c = 1, 2, 5 m/s: the shape at the last transfer
  (x against height, ascending and descending legs), the loop's mean width (enclosed area / height of the top),
  and the tension per element over the last period (mean, min, max). A case that is not periodic within the
  maximal time is drawn anyway (its shape at the end of the search) and says "NOT PERIODIC".
* Power: the mean generator power over the last period (energy delivered / period) beside the paper's estimate
  (T_first - T_last) V_c from the mean tensions, and the period means over the second half of the search (what a
  motion that is not periodic delivers); 3D at 2 m/s from the 2D state mapped to 3D.
* Cable strength: every periodic search checks each step's tensions against the cable's breaking load
  (``sim/overload.py``) and each case's line says whether and where it was exceeded.
* Fig. 8: from the 3D periodic state at 2 m/s, a 0.01 rad step of the wind direction; roll, pitch, yaw, alpha
  and beta of the wing in slot 40 (the paper's "node 40"), followed to its physical end
  (:mod:`laddermill_gym.studies.mill.divergence`: aerodynamic data out of range for a stated time, a wing below
  a height, or cable overload) with RK4 at the scene's dt and dt/4 and with ROS34PW2 under error control; with
  RK4 at dt/4 judged on height and overload only; and, for comparison, RK4 at dt with no end criterion, run until
  the integrator breaks down (a separate, named outcome) or ``after_step`` seconds.
* The paper's claims next to ours (:mod:`laddermill_gym.studies.mill.meijaard_claims`): printed, ``claims.csv``,
  ``claims.png``, and beside each figure.

The periodic searches (minutes each) are saved under ``<out>/states/`` and reused by a later run with the same
settings (:mod:`laddermill_gym.studies.mill.meijaard_store`); ``--fresh`` recomputes them.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import math
import time
from pathlib import Path
from typing import NamedTuple

import numpy as np

from laddermill_gym import Simulator, load_scene
from laddermill_gym.ladder.periodic import PeriodicResult, run_to_periodic
from laddermill_gym.ladder.scene import scene_path
from laddermill_gym.model.states import planar_to_3d
from laddermill_gym.studies.mill import meijaard_store as store
from laddermill_gym.studies.mill.divergence import (
    BREAKDOWN,
    DEFAULT_END,
    EndCriteria,
    describe,
    follow,
    undisturbed_spell,
)
from laddermill_gym.studies.mill.meijaard_claims import all_claims, claims_text, min_tension_place
from laddermill_gym.studies.mill.meijaard_plots import plot_claims, plot_shapes, plot_step, plot_tensions

PAPER_POWER_W = 200e3  # [W] "of the order of 200 kW" (2D, the paper's unoptimised configuration)
SLOT = 40  # the paper's "node 40, in the ascending part close to the top"
SCENE = "laddermill_v1"  # LadderMill-v1's mill, the design the issue's other points and the README use
#: [-] periodic-search tolerance (shape change / l0 and relative power change over a period) per scene: v1 as its
#: design study (docs/wing_data.md, 1e-3); v0 as its published reproduction was made (run_to_periodic's 1e-2)
SCENE_TOL = {"laddermill": 1e-2}
DEFAULT_TOL = 1e-3


@dataclasses.dataclass(frozen=True)
class Config:
    """Study settings. n_wings: None for the scene's 101. max_time [s]: periodic search per 2D speed (from the
    first transfer after the ramp); max_time_3d [s]: 3D search from the mapped 2D state; extra_s [s]: span after
    the search over which the loop width is sampled; after_step [s]: the longest run after the direction step;
    dp54_wall [s]: wall-clock limit of the error-controlled (ROS34PW2) run; sample_s [s]: output interval (and the
    end criteria's sampling); speeds [m/s]; ramp_s [s]; slot: the wing slot followed after the direction step;
    rtol: the error-controlled run's relative tolerance [-] (chosen: 1e-4; docs/work_precision.md);
    end: the physical end criteria of the direction step; scene: the scene file's name; tol [-]: the periodic
    search's shape and power tolerance (None: SCENE_TOL's for the scene, else DEFAULT_TOL)."""

    n_wings: int | None = None
    max_time: float = 3000.0
    max_time_3d: float = 600.0
    extra_s: float = 140.0
    after_step: float = 300.0
    dp54_wall: float = 300.0
    sample_s: float = 0.1
    speeds: tuple[float, ...] = (1.0, 2.0, 5.0)
    ramp_s: float = 30.0
    slot: int = SLOT
    progress: bool = True
    rtol: float = 1e-4
    end: EndCriteria = DEFAULT_END
    scene: str = SCENE
    tol: float | None = None

    @property
    def periodic_tol(self) -> float:
        """The periodic search's tolerance [-] (see the class docstring)."""
        return self.tol if self.tol is not None else SCENE_TOL.get(self.scene, DEFAULT_TOL)


class Case(NamedTuple):
    """One periodic case: the search's result, its table row and the two ground points [m]."""

    res: PeriodicResult
    row: dict
    ground: tuple[np.ndarray, np.ndarray]


QUICK = Config(max_time=100.0, max_time_3d=60.0, extra_s=14.0, after_step=15.0, dp54_wall=20.0)


def mill(dimension: int, v_c: float, cfg: Config) -> Simulator:
    """The scene's mill (2D or 3D) at rest with V_c ramped linearly from 0 to ``v_c`` [m/s] in ``cfg.ramp_s``."""
    sc = load_scene(cfg.scene, dimension=dimension, n_wings=cfg.n_wings)
    st = dataclasses.replace(sc.assembly.station, speed_times=(0.0, cfg.ramp_s), speed_values=(0.0, v_c))
    x0, u0 = sc.initial_state()
    return Simulator(dataclasses.replace(sc.assembly, station=st), x0, sc.settings, u0)


def loop_width(shape: np.ndarray, ground: tuple[np.ndarray, np.ndarray]) -> float:
    """Mean width of the loop [m]: area enclosed by veered ground point, wings (slot order, x and z of
    ``shape`` (n, 3) [m]) and hauled ground point (shoelace), over the height of the top above the station."""
    pts = np.vstack([ground[0], shape, ground[1]])
    x, h = pts[:, 0], -pts[:, 2]
    area = 0.5 * abs(np.dot(x, np.roll(h, -1)) - np.dot(h, np.roll(x, -1)))
    return float(area / (h.max() - 0.5 * (h[0] + h[-1])))


def _ground(sim: Simulator) -> tuple[np.ndarray, np.ndarray]:
    """The veered and hauled ground points [m] (ends of the first and last element)."""
    a, i = sim.assembly, sim.assembly.elements.end_index
    return a.fixed_points[i[0, 0]].copy(), a.fixed_points[i[-1, 1]].copy()


def width_span(sim: Simulator, seconds: float) -> np.ndarray:
    """Loop widths [m] sampled every second over ``seconds`` [s] of further running."""
    out, n = [], max(1, int(round(1.0 / sim.settings.dt)))
    for _ in range(max(1, int(seconds))):
        sim.step(n_steps=n)
        out.append(loop_width(sim.wing_positions(), _ground(sim)))
    return np.array(out)


def case_row(label: str, dim: int, v_c: float, res: PeriodicResult, ground, widths: np.ndarray) -> dict:
    """One row of the power table (units in the keys); ``ground`` the two ground points [m], ``widths`` the loop
    widths [m] sampled after the search; ``late_power_*``: the period means over the second half of the search."""
    tm, k = res.tension_mean_N, int(np.argmin(res.tension_mean_N))
    late = np.array([h["mean_power_W"] for h in res.history[len(res.history) // 2:]]) / 1e3
    return {"case": label, "dimension": dim, "V_c_m_s": v_c, "periodic": res.converged, "t_end_s": res.t_s,
            "period_s": res.period_s, "mean_power_kW": res.mean_power_W / 1e3,
            "tension_estimate_kW": (tm[0] - tm[-1]) * v_c / 1e3, "paper_power_kW": PAPER_POWER_W / 1e3,
            "late_periods": late.size, "late_power_mean_kW": late.mean(), "late_power_min_kW": late.min(),
            "late_power_max_kW": late.max(),
            "T_first_kN": tm[0] / 1e3, "T_last_kN": tm[-1] / 1e3, "T_min_kN": tm[k] / 1e3, "T_min_element": k,
            "loop_width_m": loop_width(res.shape_m, ground), "width_min_m": widths.min(), "width_max_m": widths.max(),
            "breakdown": res.breakdown or "", "peak_tension_ratio": res.peak_tension_ratio,
            "overload": res.overload.text() if res.overload else ""}


def periodic_case(v_c: float, dim: int, cfg: Config, start=None, max_time: float | None = None,
                  folder: Path | None = None):
    """Run a mill (a new one at ``v_c`` [m/s], or ``start()``'s simulator) to its periodic motion, then ``extra_s``
    further seconds sampling the loop width; returns (simulator reset to the end of the search, :class:`Case`, True
    when the case was read from ``folder`` instead). With ``folder`` the case is saved there and a saved case with
    the same settings is reused (:mod:`~laddermill_gym.studies.mill.meijaard_store`)."""
    max_time = cfg.max_time if max_time is None else max_time
    sim = mill(dim, v_c, cfg)
    key = store.case_key(cfg.scene, dim, v_c, cfg.n_wings, cfg.ramp_s, max_time, cfg.periodic_tol, cfg.extra_s,
                         store.fingerprint(scene_path(cfg.scene), sim))
    path = store.case_path(folder, key) if folder is not None else None
    saved = store.load_case(path, key) if path is not None else None
    if saved is not None:
        state, t, controls, ground, res, row = saved
        sim.reset(state, t=t, controls=controls, check=res.breakdown is None)
        return sim, Case(res, row, ground), True
    if start is not None:
        sim = start()
    res = run_to_periodic(sim, shape_tol=cfg.periodic_tol, power_tol=cfg.periodic_tol, max_time=max_time,
                          progress=cfg.progress)
    state, t, controls, ground = sim.state.copy(), sim.t, sim.controls.copy(), _ground(sim)
    # a run that broke down cannot go on: its width is the last good state's
    widths = (np.array([loop_width(sim.wing_positions(), ground)]) if res.breakdown else width_span(sim, cfg.extra_s))
    sim.reset(state, t=t, controls=controls, check=res.breakdown is None)
    case = Case(res, case_row(f"{dim}D V_c={v_c:g}", dim, v_c, res, ground, widths), ground)
    if path is not None:
        store.save_case(path, key, state, t, controls, ground, res, case.row)
    return sim, case, False


def to_3d(sim2: Simulator, cfg: Config) -> Simulator:
    """A 3D simulator at the 2D one's state (mapped in plane, station block appended), time and controls."""
    a2, sc = sim2.assembly, load_scene(cfg.scene, dimension=3, n_wings=cfg.n_wings)
    nb = a2.body_state_size
    x3 = np.concatenate([planar_to_3d(sim2.state[:nb], a2.n_wings, a2.n_nodes), sim2.state[nb:]])
    sim3 = Simulator(dataclasses.replace(sc.assembly, station=a2.station), x3, sc.settings, sim2.controls)
    sim3.reset(x3, t=sim2.t, controls=sim2.controls)
    return sim3


def direction_step(sim: Simulator, cfg: Config, label: str, wall_limit: float = math.inf,
                   criteria: EndCriteria | None = DEFAULT_END) -> dict:
    """From ``sim``'s state (3D), the 0.01 rad direction step followed to its end
    (:func:`laddermill_gym.studies.mill.divergence.follow`: a physical criterion of ``criteria``, a numerical
    breakdown, ``cfg.after_step`` [s] or ``wall_limit`` [s] of wall time) with the simulator's integrator. Adds
    ``outcome``, ``physical_end``, ``broke_down``, ``message``, the method and its (first) step ``dt_s`` [s]."""
    method, dt = sim.settings.method, sim.settings.dt
    run = follow(sim, label, cfg.slot, cfg.after_step, cfg.sample_s, criteria, wall_limit, cfg.progress)
    end = run["end"]
    return {**run, "method": method, "dt_s": dt, "outcome": end.outcome, "physical_end": end.physical,
            "broke_down": end.outcome == BREAKDOWN,
            "end_bodies": " ".join(str(b) for b in end.bodies), "message": end.text}


def write_csv(path: Path, rows: list[dict]) -> None:
    """Rows (dicts with the same keys, units in the keys) to a CSV file."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def tension_rows(cases: list[Case]) -> list[dict]:
    """Per element: mean, min, max tension [kN] over the last period of every case."""
    return [{"element": k, **{f"{c.row['case']} T_{n}_kN": getattr(c.res, f"tension_{n}_N")[k] / 1e3
                              for c in cases for n in ("mean", "min", "max")}}
            for k in range(len(cases[0].res.tension_mean_N))]


def describe_case(row: dict) -> str:
    """The printed line of one periodic case."""
    state = "periodic" if row["periodic"] else "NOT PERIODIC (last period shown)"
    if row.get("breakdown"):
        state = f"NOT PERIODIC: broke down ({row['breakdown']}; the last, partial period shown)"
    return (f"{row['case']}: {state}, t = {row['t_end_s']:.0f} s; mean power {row['mean_power_kW']:.1f} kW "
            f"(tension estimate (T_first - T_last) V_c = {row['tension_estimate_kW']:.1f} kW; paper ~200 kW; the "
            f"last {row['late_periods']} periods: mean {row['late_power_mean_kW']:.1f} kW, period means "
            f"{row['late_power_min_kW']:.1f} to {row['late_power_max_kW']:.1f} kW); "
            f"smallest mean tension {row['T_min_kN']:.1f} kN in element {row['T_min_element']}; first - last = "
            f"{row['T_first_kN']:.1f} - {row['T_last_kN']:.1f} = {row['T_first_kN'] - row['T_last_kN']:.1f} kN; "
            f"loop width {row['loop_width_m']:.0f} m (sampled after it: {row['width_min_m']:.0f}-"
            f"{row['width_max_m']:.0f} m); " + (f"CABLE OVERLOAD at {row['overload']}" if row["overload"] else
                                               "no cable overload") +
            f" (peak tension {row['peak_tension_ratio']:.3g} x the breaking load)")


def run_periodic_cases(cfg: Config, out: Path):
    """Sections 1-3: the 2D speeds and the 3D case at 2 m/s (from the 2D state; each search saved under
    ``out/states`` and reused when its settings match); writes power.csv, tension.csv, history.csv and shapes.csv;
    returns (cases, the 3D simulator at its periodic state)."""
    cases, sims, folder = [], {}, out / "states"
    for v in cfg.speeds:
        sims[v], case, reused = periodic_case(v, 2, cfg, folder=folder)
        cases.append(case)
        print(describe_case(case.row) + (" [saved search reused]" if reused else ""), flush=True)
    v3 = 2.0 if 2.0 in sims else cfg.speeds[0]
    sim3, case3, reused = periodic_case(v3, 3, cfg, start=lambda: to_3d(sims[v3], cfg), max_time=cfg.max_time_3d,
                                        folder=folder)
    print(describe_case(case3.row) + " [started from the 2D state]" + (" [saved search reused]" if reused else ""),
          flush=True)
    cases.append(case3)
    write_csv(out / "power.csv", [c.row for c in cases])
    write_csv(out / "tension.csv", tension_rows(cases))
    write_csv(out / "history.csv", [{"case": c.row["case"], **h} for c in cases for h in c.res.history])
    write_csv(out / "shapes.csv", [{"case": c.row["case"], "slot": k, "x_m": p[0], "y_m": p[1], "height_m": -p[2]}
                                   for c in cases for k, p in enumerate(c.res.shape_m)])
    return cases, sim3


def write_figures(cases: list[Case], runs: list[dict], cfg: Config, out: Path) -> list[dict]:
    """The claims (printed, claims.csv, claims.png) and Figs. 6-8 with the paper's words and our numbers beside
    them; Figs. 6-7 show the 2D cases at 1 and 5 m/s (else the first case). Returns the claims."""
    two = [c for c in cases if c.row["dimension"] == 2]
    rows2d = {c.row["V_c_m_s"]: c.row for c in two}
    places = {c.row["V_c_m_s"]: min_tension_place(c.res.shape_m, c.ground, c.res.tension_mean_N) for c in two}
    claims = all_claims(rows2d, places, runs)
    print("The paper's claims and ours (agrees: yes / no / - where the paper states no yes-or-no claim):")
    print(claims_text(claims), flush=True)
    write_csv(out / "claims.csv", [{"scene": cfg.scene, **c} for c in claims])
    plot_claims(claims, out / "claims.png", cfg.scene)
    figs = [c for c in two if c.row["V_c_m_s"] in (1.0, 5.0)] or cases[:1]
    plot_shapes(figs, out / "fig6_shapes.png", cfg.slot, cfg.scene, claims)
    plot_tensions(figs, out / "fig7_tension.png", cfg.scene, claims)
    plot_step(runs, out / "fig8_direction_step.png", cfg.scene, claims)
    return claims


def run_direction_steps(sim3: Simulator, cfg: Config, out: Path) -> list[dict]:
    """Section 4: the direction step from the 3D periodic state, followed to its physical end with RK4 at dt and
    dt/4 and with ROS34PW2 under error control; with RK4 at dt/4 and only the height and overload criteria (what
    ends the run when the wing data are trusted beyond their range); and with RK4 at dt and no end criterion (to its
    breakdown, the figure before issue 30)."""
    dt = sim3.settings.dt
    ref = undisturbed_spell(sim3, cfg.end, sim3.assembly.station.piece_length / sim3.cable_speed(), cfg.sample_s)
    print(f"undisturbed periodic motion over one period: the longest spell outside the aerodynamic data "
          f"{ref['longest_out_s']:.2f} s (wing {ref['wing']}; the criterion's hold: {cfg.end.aero_hold_s:g} s), lowest "
          f"wing CG {ref['lowest_wing_m']:.1f} m, peak tension {ref['peak_tension_ratio']:.3g} x the breaking load; "
          f"{'no end criterion holds' if ref['end'] is None else 'END CRITERION HOLDS: ' + ref['end'].text}",
          flush=True)
    runs = []
    for label, method, h, wall, crit in (
            (f"RK4 dt = {dt * 1e3:g} ms", "rk4", dt, math.inf, cfg.end),
            (f"RK4 dt/4 = {dt * 250:g} ms", "rk4", dt / 4, math.inf, cfg.end),
            (f"ROS34PW2, rtol {cfg.rtol:g}", "ros34pw2a", dt, cfg.dp54_wall, cfg.end),
            (f"RK4 dt/4 = {dt * 250:g} ms, aerodynamic range not judged", "rk4", dt / 4, math.inf,
             dataclasses.replace(cfg.end, aero_wings=())),
            (f"RK4 dt = {dt * 1e3:g} ms, no end criterion", "rk4", dt, math.inf, None)):
        # atol [state units]: 1e-6 (um, um/s) where a state is near 0 (the lateral offsets the step starts from)
        settings = dataclasses.replace(sim3.settings, method=method, dt=h, rtol=cfg.rtol, atol=1e-6)
        s = Simulator(sim3.assembly, sim3.state, settings, sim3.controls)
        s.reset(sim3.state, t=sim3.t, controls=sim3.controls)
        run = direction_step(s, cfg, label, wall, crit)
        runs.append(run)
        print(describe(run), flush=True)
    write_csv(out / "direction_step.csv", [{"run": r["label"], **x} for r in runs for x in r["rows"]])
    write_csv(out / "breakdown.csv", [{k: v for k, v in r.items() if k not in ("rows", "end")} for r in runs])
    return runs


def notes(scene: str) -> str:
    """What the paper does not give and the study chose, with the scene's elevators."""
    ini = load_scene(scene, dimension=2).initial
    return (f"Notes. What the paper does not give is ours: the wing's coefficients and inertia (docs/wing_data.md), "
            f"the tail settings (scene {scene}: elevator {math.degrees(ini.elevator_up):g} deg ascending, "
            f"{math.degrees(ini.elevator_down):g} deg descending), the 100 m between the two sheaves and the new "
            "wing's attitude. The paper's ~200 kW estimates an unoptimised design by (T_first - T_last) V_c, as "
            "ours. Accurate data: alpha within -14..18 deg (the tail's and the wing's stall), |beta| within the "
            "fins' 21 deg (docs/wing_data.md).")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=SCENE, help=f"moving-cable scene (default {SCENE}, LadderMill-v1's mill; "
                    "'laddermill': the v0 reproduction)")
    ap.add_argument("--out", type=Path, default=Path("results/meijaard"), help="folder for PNG and CSV")
    ap.add_argument("--quick", action="store_true", help="short smoke version (a few minutes)")
    ap.add_argument("--fresh", action="store_true", help="recompute the periodic searches saved under OUT/states")
    ap.add_argument("--no-progress", action="store_true", help="no tqdm bars")
    args = ap.parse_args(argv)
    cfg = dataclasses.replace(QUICK if args.quick else Config(), progress=not args.no_progress, scene=args.scene)
    from laddermill_gym.model.configio import ConfigError
    from laddermill_gym.studies.commands import UsageError, writable_folder

    try:  # an unknown scene, one without a moving cable (a point-mass one has no assembly) and a bad --out: one line
        if getattr(getattr(load_scene(cfg.scene), "assembly", None), "station", None) is None:
            raise UsageError(f"--scene {cfg.scene!r}: no moving cable through a station (the study's periodic "
                             "searches need a mill's: laddermill, laddermill_v1, laddermill_v2)")
        load_scene(cfg.scene, dimension=2)  # the study's in-plane mill: a scene it cannot make is named here
        writable_folder(args.out)
    except (UsageError, ConfigError) as err:
        ap.error(str(err))
    if args.fresh:
        for f in (args.out / "states").glob("*.npz"):
            f.unlink()
    t0 = time.perf_counter()
    print(f"scene {cfg.scene}, periodic tolerance {cfg.periodic_tol:g}", flush=True)
    cases, sim3 = run_periodic_cases(cfg, args.out)
    runs = run_direction_steps(sim3, cfg, args.out)
    write_figures(cases, runs, cfg, args.out)
    print(notes(cfg.scene))
    print(f"wrote {sorted(p.name for p in args.out.iterdir())} to {args.out} in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
