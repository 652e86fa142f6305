"""The mill in plane at V_c = 1-5 m/s (issue 30 point 1): the v1 near-top elevator rule, the loop's downwind drift, and
the v2 wing's periodic motions.

Three measurements, printed as the doc (docs/mill_fast.md, "Not solved with the v1 wing: 5 m/s" and "A wing whose lift
falls with its air speed (v2)") quotes them:

* ``case``: the scene ``laddermill_v1`` (or ``--scene laddermill_v2``) in plane from rest, V_c ramped from 0 over
  ``--start-ramp`` s (default 30 s, v1's scene) to V_c [m/s], with the scene's elevators (or ``--elevators``) and the
  near-top rule (``initial.top_slots`` slots past the top at ``initial.elevator_top_deg``; 0 slots: the scene as
  shipped), run to
  its periodic motion (:func:`laddermill_gym.ladder.periodic.run_to_periodic`, shape and power to 1e-3, at most
  ``max_time`` s); prints the summary, the last period's tension extremes, the period-mean end tensions and the
  range of the last ten period means of power and shape change.
* ``drift``: the scene's periodic motion at 2 m/s (t = 1,345 s), then the cable speed ramped to V_c over ``ramp``
  s and the rule switched on at the ramp's start; every ``every`` s: V_c, the power over the interval, the first,
  last and top (element 51) tensions, the smallest tension of the interval and its element, and the downwind
  position x [m] of slots 10, 25, 40, 50, 60, 75 and 90 (the loop leaning downwind: x falls).
* ``step``: from rest (V_c ramped at 0.01 m/s^2) to the periodic motion, then a cable-speed step (``--new-speed``)
  and / or a wind step (``--wind-factor``) over 1 s, run to the new periodic motion (the paper's claim).

``python -m laddermill_gym.studies.mill.fast_mill case --speed 4 --top-slots 7 --top-deg -4``;
``python -m laddermill_gym.studies.mill.fast_mill case --scene laddermill_v2 --speed 5 --start-ramp 500
--max-time 3000``;
``python -m laddermill_gym.studies.mill.fast_mill drift --speed 4 --time 400``;
``python -m laddermill_gym.studies.mill.fast_mill step --scene laddermill_v2 --speed 2 --wind-factor 1.125``.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.model.configio import ConfigError
from laddermill_gym.studies.commands import Parser, UsageError, check_number

SCENE = "laddermill_v1"
SLOTS = (10, 25, 40, 50, 60, 75, 90)  # [-] slots whose downwind position the drift prints


def _overrides(speed_times, speeds, top_slots, top_deg):
    return {"station": {"speed_times_s": list(speed_times), "speed_m_s": list(speeds)},
            "initial": {"top_slots": int(top_slots), "elevator_top_deg": float(top_deg)}}


def case(speed: float, top_slots: int, top_deg: float, max_time: float, scene: str = SCENE,
         start_ramp: float = 30.0, elevators: tuple | None = None, dimension: int = 2,
         elevation: float | None = None) -> None:
    """One case from rest (a ramp of ``start_ramp`` s to ``speed``) run to its periodic motion; prints the figures.
    In 3D: the in-plane periodic state embedded (``periodic_start``), then run to the periodic motion in 3D."""
    from laddermill_gym import load_scene
    from laddermill_gym.ladder.periodic import periodic_start, run_to_periodic

    ov = _overrides([0.0, start_ramp], [0.0, speed], top_slots, top_deg)
    if elevators is not None:
        ov["initial"].update(elevator_up_deg=elevators[0], elevator_down_deg=elevators[1])
    if elevation is not None:  # the rest layout's first guess (initial.elevation_deg)
        ov["initial"]["elevation_deg"] = elevation
    sc = load_scene(scene, dimension=dimension, overrides=ov)
    sim = sc.simulator()
    if dimension == 3:
        x, u, t, res2 = periodic_start(sc, progress=True, max_time=max_time)
        print(f"in plane: {res2.summary()}")
        sim.reset(state=x, t=t, controls=u)
    res = run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=True)
    last = res.history[-10:]
    p = [h["mean_power_W"] / 1e3 for h in last]
    s = [h["shape_change"] for h in last]
    print(f"{scene} ({dimension}D): V_c {speed:g} m/s (ramp {start_ramp:g} s, elevators {elevators or 'the scene'}), "
          f"top slots {top_slots} at {top_deg:g} deg: {res.summary()}")
    print(f"last period: largest tension {np.max(res.tension_max_N) / 1e3:.1f} kN, smallest "
          f"{np.min(res.tension_min_N) / 1e3:.1f} kN; period means T_first {res.tension_mean_N[0] / 1e3:.1f} kN, "
          f"T_last {res.tension_mean_N[-1] / 1e3:.1f} kN, (T_first - T_last) V_c "
          f"{(res.tension_mean_N[0] - res.tension_mean_N[-1]) * speed / 1e3:.1f} kW")
    print(f"last {len(last)} periods: mean power {min(p):.1f} .. {max(p):.1f} kW, shape change "
          f"{min(s):.2e} .. {max(s):.2e} l0")


def step(scene: str, speed: float, new_speed: float, wind_factor: float, max_time: float) -> None:
    """From rest (V_c ramped at 0.01 m/s^2 to ``speed``) to the periodic motion, then in 1 s the cable speed to
    ``new_speed`` and the whole wind profile scaled by ``wind_factor``, and on to the new periodic motion; prints
    both summaries and the new period's largest tension (the paper: "the mill comes to a new stationary motion")."""
    from laddermill_gym import load_scene
    from laddermill_gym.atmosphere.field import WindField
    from laddermill_gym.ladder.periodic import run_to_periodic

    ramp = [0.0, 100.0 * speed]
    sim = load_scene(scene, dimension=2, overrides={"station": {"speed_times_s": ramp, "speed_m_s": [0.0, speed]}}
                     ).simulator()
    before = run_to_periodic(sim, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=True)
    print(f"{scene}, before the step: {before.summary()}")
    t1, x, u = sim.t, sim.state.copy(), sim.controls.copy()
    ov = {"station": {"speed_times_s": ramp + [t1, t1 + 1.0], "speed_m_s": [0.0, speed, speed, new_speed]}}
    sim2 = load_scene(scene, dimension=2, overrides=ov).simulator()
    sim2.reset(state=x, t=t1, controls=u)
    if wind_factor != 1.0:
        sim2.set_wind(WindField(t0=t1, dt=1.0, speed=np.array([1.0, wind_factor]), direction=np.zeros(2)))
    after = run_to_periodic(sim2, shape_tol=1e-3, power_tol=1e-3, max_time=max_time, progress=True)
    print(f"after V_c {speed:g} -> {new_speed:g} m/s, wind x {wind_factor:g} at t = {t1:.1f} s: {after.summary()}; "
          f"largest tension of its period {np.max(after.tension_max_N) / 1e3:.1f} kN, smallest "
          f"{np.min(after.tension_min_N) / 1e3:.1f} kN")


def drift(speed: float, ramp: float, duration: float, every: float, top_slots: int, top_deg: float) -> None:
    """From the periodic motion at 2 m/s, V_c ramped to ``speed`` over ``ramp`` s; prints the loop every ``every`` s."""
    from laddermill_gym import load_scene
    from laddermill_gym.ladder.periodic import run_to_periodic

    sim0 = load_scene(SCENE, dimension=2).simulator()
    res = run_to_periodic(sim0, shape_tol=1e-3, power_tol=1e-3, max_time=3000.0, progress=True)
    t1 = sim0.t
    print(f"2 m/s: {res.summary()}")
    sc = load_scene(SCENE, dimension=2, overrides=_overrides([0.0, 30.0, t1, t1 + ramp], [0.0, 2.0, 2.0, speed],
                                                             top_slots, top_deg))
    u = sc.initial_state()[1]  # the rule's elevators (those of the periodic state when the rule is off)
    sim = sc.simulator(initial_state=sim0.state.copy(), controls=u)
    sim.reset(state=sim0.state.copy(), t=t1, controls=u)
    e0, t0 = sim.generator_energy(), sim.t
    n = max(1, int(round(every / sim.settings.dt / 10)))
    print("t - t1 [s]  V_c [m/s]  P [kW]  T_first  T_last  T_top  [kN]  min T [kN] @ element  x of slots "
          f"{', '.join(map(str, SLOTS))} [m]")
    while sim.t < t1 + duration - 1e-9:
        tmin = np.full(sim.assembly.elements.count, np.inf)
        for _ in range(n):
            sim.step(n_steps=10)
            tmin = np.minimum(tmin, sim.tensions())
        ten = sim.tensions()
        p = (sim.generator_energy() - e0) / (sim.t - t0)
        e0, t0 = sim.generator_energy(), sim.t
        x = sim.wing_positions()[list(SLOTS), 0]
        print(f"{sim.t - t1:6.0f} {sim.cable_speed():9.2f} {p / 1e3:8.1f} {ten[0] / 1e3:8.0f} {ten[-1] / 1e3:7.0f} "
              f"{ten[51] / 1e3:6.0f} {tmin.min() / 1e3:12.1f} @ {int(tmin.argmin()):3d}  "
              + " ".join(f"{v:6.0f}" for v in x), flush=True)


def main(argv=None) -> int:
    p = Parser(prog="python -m laddermill_gym.studies.mill.fast_mill", description=__doc__.split("\n\n")[0])
    p.add_argument("what", choices=("case", "drift", "step"))
    p.add_argument("--new-speed", type=float, default=None, help="step: cable speed after the step [m/s]")
    p.add_argument("--wind-factor", type=float, default=1.0, help="step: wind profile scaled by [-]")
    p.add_argument("--speed", type=float, default=5.0, help="cable speed V_c [m/s]")
    p.add_argument("--top-slots", type=int, default=0, help="descending slots past the top at --top-deg [-]")
    p.add_argument("--top-deg", type=float, default=-0.5, help="their elevator [deg]")
    p.add_argument("--scene", default=SCENE, help="case: the scene (laddermill_v1 or laddermill_v2)")
    p.add_argument("--dimension", type=int, choices=(2, 3), default=2, help="case: 2 (in plane) or 3")
    p.add_argument("--elevation", type=float, default=None, help="case: the rest layout's first guess [deg]")
    p.add_argument("--start-ramp", type=float, default=30.0, help="case: ramp of V_c from rest [s]")
    p.add_argument("--elevators", type=float, nargs=2, default=None, help="case: ascending, descending [deg]")
    p.add_argument("--max-time", type=float, default=1500.0, help="case: periodic search [s]")
    p.add_argument("--ramp", type=float, default=100.0, help="drift: ramp from 2 m/s [s]")
    p.add_argument("--time", type=float, default=400.0, help="drift: time after the periodic motion at 2 m/s [s]")
    p.add_argument("--every", type=float, default=25.0, help="drift: print interval [s]")
    a = p.parse_args(argv)
    try:
        check_number("--speed", a.speed, low=0.0, high=30.0, unit="m/s")
        for opt, v in (("--max-time", a.max_time), ("--ramp", a.ramp), ("--time", a.time), ("--every", a.every)):
            check_number(opt, v, low=0.0, unit="s")
        if a.what == "case":
            case(a.speed, a.top_slots, a.top_deg, a.max_time, a.scene, a.start_ramp, a.elevators, a.dimension,
                 a.elevation)
        elif a.what == "step":
            step(a.scene, a.speed, a.speed if a.new_speed is None else a.new_speed, a.wind_factor, a.max_time)
        else:
            drift(a.speed, a.ramp, a.time, a.every, a.top_slots, a.top_deg)
    except (UsageError, ConfigError) as err:
        p.error(str(err))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
