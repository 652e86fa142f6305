"""Dynamic pumping cycle against the quasi-steady prediction (issue part 4): the crosswind controller
(``control/crosswind.py``, figure eights; default) or the LQR-assisted static scripted cycle
(``control/pumping_cycle.py``, ``--controller lqr``) flies ``laddermill_gym/PumpingKite-v0``'s task (steady
wind after the envs' 0.01 rad direction step at 1 s) for several cycles;
each complete cycle's net electrical mean power is compared with Lansdorp et al. (2008) eqs. 1-14 and the
Schmehl / van der Vlugt model (``quasisteady/``) at the same parameters (wind at the wing, cable angle, C_L and
C_D at the flown angle of attack, Delta L, reel-in speed, efficiency), with a static-kite variant of eq. 9, and
with eqs. 10-14 fed the simulated phase means. docs/pumping.md explains the differences.

Run: ``python -m laddermill_gym.studies.pumping.pumping_cycle [--cycles 3] [--controller crosswind|lqr]
[--out results/pumping_cycle]``; with ``--out``: the table as JSON and the figures of ``cycle_figures.py``.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
from pathlib import Path

import numpy as np
from tqdm import tqdm

from laddermill_gym.control.crosswind import PHASE_NAMES, CrosswindController
from laddermill_gym.control.crosswind_config import load_crosswind_config
from laddermill_gym.control.lqr import DEFAULT_CONFIG
from laddermill_gym.control.pumping_cycle import PHASE_IN, PHASE_OUT, PumpingCycleController, lateral_lqr
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.model.reel import ground_contacts, is_reel
from laddermill_gym.quasisteady import lansdorp, schmehl
from laddermill_gym.quasisteady.lansdorp import PumpingParams
from laddermill_gym.quasisteady.schmehl import SchmehlParams
from laddermill_gym.reference.wind import air_density
from laddermill_gym.sim.statics import table_spline
from laddermill_gym.studies.commands import Command, check_number, writable_folder
from laddermill_gym.studies.pumping.cycle_figures import cycle_figures

__all__ = ["run_cycles", "cycle_stats", "quasi_steady", "add_parser", "main"]


def run_cycles(task: PumpingTask, controller, n_cycles: int, t_max: float | None = None,
               progress: bool = True, probe=None) -> dict[str, np.ndarray]:
    """Fly copy 0 of ``task`` (reset with seed 0) until ``n_cycles`` reel-ins have ended (or ``t_max`` [s]); per
    control step: t [s], phase, paid out s [m], winch speed [m/s], drum tension [N], electrical and mechanical
    energy of the step [J], wing position (3) [m], alpha [rad], wind speed and along-tether wind [m/s], |dy| [m],
    and with ``probe`` (a function of the task returning a dict of numbers) its entries."""
    task.reset(np.ones(task.n_copies, bool), [np.random.default_rng(0) for _ in range(task.n_copies)])
    t_max = t_max if t_max is not None else task.episode_time
    rows, ends, prev = [], 0, PHASE_OUT
    bar = tqdm(total=n_cycles, unit="cycle", disable=not progress, leave=False)
    while ends < n_cycles and task.batch.t[0] < t_max - 1e-9:
        obs = task.obs.copy()
        a, _ = controller.predict(obs)
        phase = int(controller.last_phase[0])
        _, term, trunc, info = task.step(a)
        ro = task.raw_obs[0]
        rows.append([task.batch.t[0], phase, info["paid_out_m"][0], info["winch_speed_m_s"][0],
                     info["drum_tension_N"][0], task.electrical_energy[0],
                     info["mechanical_power_W"][0] * task.control_dt, *task.batch.states[0, :3],
                     ro[OBS_INDEX["alpha"]], ro[-1], ro[-2], abs(ro[OBS_INDEX["dy"]]),
                     *(probe(task).values() if probe else ())])
        if prev == PHASE_IN and phase != PHASE_IN:
            ends += 1
            bar.update(1)
        prev = phase
        if term[0]:
            raise RuntimeError(f"the cycle failed: {task.failure_text(0, int(info['failure'][0]))}; before it: "
                           f"{sum(r[5] for r in rows) / 1e3:.0f} kJ net electrical, largest |dy| "
                           f"{max(r[-1] for r in rows):.1f} m, largest drum tension {max(r[4] for r in rows):.0f} N")
        if trunc[0]:
            break
    bar.close()
    r = np.array(rows)
    names = ["t", "phase", "s", "v", "tension", "e_el", "e_mech", "x", "y", "z", "alpha", "wind", "radial_wind",
             "abs_dy", *(probe(task).keys() if probe else ())]
    out = {k: r[:, i] for i, k in enumerate(names)}
    out["phase"] = out["phase"].astype(int)
    return out


def cycle_stats(rec: dict[str, np.ndarray], dt: float) -> list[dict[str, float]]:
    """Per complete cycle (the end of a reel-in to the next): duration [s], reel-out / reel-in durations [s] (winch
    speed sign), mechanical energy out / in [J], net electrical energy [J] and mean power [W], mean reel-out
    tension and speed (time means over V > 0), mean reel-in tension [N], tether reeled [m], mean altitude [m],
    cable angle from the vertical [rad], wind at the wing [m/s], alpha [rad] over reel-out, max |dy| [m], the
    RMS azimuth over reel-out and the mean elevation over reel-in [rad]."""
    ph = rec["phase"]
    starts = np.flatnonzero((ph[1:] != PHASE_IN) & (ph[:-1] == PHASE_IN)) + 1
    out = []
    for a, b in zip(starts[:-1], starts[1:], strict=True):
        sl = slice(a, b)
        v, ten = rec["v"][sl], rec["tension"][sl]
        o, i = v > 0, v < 0
        x, z = rec["x"][sl][o], rec["z"][sl][o]
        out.append(dict(
            t_cycle=(b - a) * dt, t_out=o.sum() * dt, t_in=i.sum() * dt,
            e_out=float(np.sum(rec["e_mech"][sl][rec["e_mech"][sl] > 0])),
            e_in=float(-np.sum(rec["e_mech"][sl][rec["e_mech"][sl] < 0])),
            e_el=float(np.sum(rec["e_el"][sl])), power=float(np.sum(rec["e_el"][sl]) / ((b - a) * dt)),
            tension_out=float(np.mean(ten[o])), speed_out=float(np.mean(v[o])), tension_in=float(np.mean(ten[i])),
            speed_in=float(-np.mean(v[i])), reeled=float(np.ptp(rec["s"][sl])), altitude=float(np.mean(-z)),
            theta=float(np.mean(np.arctan2(np.hypot(x, rec["y"][sl][o]), -z))), wind=float(np.mean(rec["wind"][sl][o])),
            alpha=float(np.mean(rec["alpha"][sl][o])), max_dy=float(np.max(rec["abs_dy"][sl])),
            azimuth_rms=float(np.sqrt(np.mean(np.arctan2(rec["y"][sl][o], -x) ** 2))),
            elevation_in=float(np.mean(np.arctan2(-rec["z"][sl][i], np.hypot(rec["x"][sl][i], rec["y"][sl][i]))))))
    return out


def quasi_steady(c: dict[str, float], task: PumpingTask) -> dict[str, float]:
    """Mean cycle power [W] of the quasi-steady models at cycle ``c``'s parameters (see the module)."""
    ps, wing = task.pumping, task.scene.assembly.wing(0)
    coef = table_spline(wing.aero)(c["alpha"])
    cl, cd = float(coef[AERO_INDEX["CL"]]), float(coef[AERO_INDEX["CD"]])
    d, S, cyc = task.scene.cable.diameter, wing.area, ps.cycle
    rho = air_density(task.scene.assembly.wind, c["altitude"])  # at the cycle's mean altitude, as the wing sees it
    params = PumpingParams(rho=rho, eta=ps.winch.efficiency, reel_length=cyc.reel_length,
                           reel_in_speed=cyc.reel_in_speed)
    w, h, th = np.array([c["wind"]]), c["altitude"], c["theta"]
    kw = dict(params=params, reel_out_factor=cyc.reel_out_factor, reel_out_rule="radial")
    lans = lansdorp.cycle_power(w, h, th, d, S, cl, cd, **kw)
    sch = schmehl.cycle_power(w, h, th, d, S, cl, cd, **kw)
    # a static kite at the flown cable angle: the aerodynamic resultant 1/2 rho S C_R |v_a|^2 along the tether, the
    # apparent wind v_a the wind less the reel-out velocity (radial w sin(theta) - v_out, tangential w cos(theta));
    # no crosswind speed (Lansdorp's G^2 of eq. 9 is 1 here), no weight; tether drag with the 1/2 rule of a static
    # tether (oracles.md, "Tethered wing, quasi-steady power")
    L = h / math.cos(th)
    cdt = cd + d * L * params.cable_cd / (2.0 * S)
    v_out = cyc.reel_out_factor * c["wind"] * math.sin(th)
    va2 = max(c["wind"] * math.sin(th) - v_out, 0.0) ** 2 + (c["wind"] * math.cos(th)) ** 2
    t_static = 0.5 * rho * S * math.hypot(cl, cdt) * va2
    static = lansdorp.cycle(np.array([t_static]), v_out, params)[4]
    fed_params = dataclasses.replace(params, reel_length=c["reeled"], reel_in_speed=c["speed_in"])
    fed = lansdorp.cycle(np.array([c["tension_out"]]), c["speed_out"], fed_params,
                         tension_in=np.array([c["tension_in"]]))[4]
    # Schmehl's model at the simulated cycle's own operating point (issue 29 point 3): its reel-out factor v_out / w,
    # reeled length and mean reel-in speed, the RMS azimuth of the figure, the reel-in elevation, the wing's mass
    matched = dataclasses.replace(params, reel_length=c["reeled"], reel_in_speed=c["speed_in"])
    qs = SchmehlParams(kite_mass_per_area=wing.mass / S, azimuth=c["azimuth_rms"],
                       retraction_elevation=max(c["elevation_in"], 0.5 * math.pi - th))
    mat = schmehl.cycle_power(w, h, th, d, S, cl, cd, params=matched, reel_out_factor=c["speed_out"] / c["wind"],
                              reel_out_rule="wind", qs=qs)
    return {"schmehl_matched_W": float(mat.power[0]), "schmehl_matched_tension_N": float(mat.tension_out[0]),
            "schmehl_matched_in_N": float(mat.tension_in[0]), "schmehl_matched_cycle_s": float(mat.time_cycle[0]),
            "lansdorp_W": float(lans.power[0]), "schmehl_W": float(sch.power[0]), "static_kite_W": float(static[0]),
            "eqs10_14_fed_W": float(fed[0]), "lansdorp_tension_N": float(lans.tension_out[0]),
            "static_tension_N": t_static, "cl": cl, "cd": cd}


def _arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--config", default="pumping_kite", help="pumping config (configs/pumping/NAME.yaml or a path)")
    p.add_argument("--cycles", type=int, default=3, help="complete cycles to fly (the first starts from the trim)")
    p.add_argument("--out", type=Path, default=None, help="folder for pumping_cycle.json and .png (default: none)")
    p.add_argument("--reel-in-speed", type=float, help="[m/s] override the config's cycle.reel_in_speed")
    p.add_argument("--alpha-in-deg", type=float, help="[deg] override the config's cycle.alpha_in_deg")
    p.add_argument("--elements", type=int, help="tether elements (scene elements_per_piece; the winch changes the "
                   "lowest one's length)")
    p.add_argument("--reel-element-length", type=float, help="[m] a reeling tether (configs/pumping/"
                   "pumping_kite_reeling.yaml, docs/reeling_tether.md) of elements of this nominal "
                   "length (default: the config's tether)")
    p.add_argument("--wind", type=float, help="[m/s] override the scene's wind speed v0 at its h0 (50 m)")
    p.add_argument("--no-lqr", action="store_true", help="the scripted cycle alone (rudder and aileron at trim)")
    p.add_argument("--controller", choices=("crosswind", "lqr"), default="crosswind",
                   help="crosswind: figure eights (control/crosswind.py, configs/agents/crosswind_pumping.yaml); lqr: "
                   "the static scripted cycle with the lateral LQR (--no-lqr: without it)")


def _run(args) -> int:
    from laddermill_gym.model.configio import find_config

    check_number("--cycles", args.cycles, low=2, high=1000, integer=True, strict=False)
    check_number("--reel-in-speed", args.reel_in_speed, low=0, high=150, unit="m/s")
    check_number("--alpha-in-deg", args.alpha_in_deg, low=-90, high=90, strict=False, unit="deg")
    check_number("--elements", args.elements, low=1, high=1000, integer=True, strict=False)
    find_config("pumping", args.config, "--config")
    check_number("--wind", args.wind, low=0, high=60, unit="m/s")
    check_number("--reel-element-length", args.reel_element_length, low=1, high=1000, unit="m")
    if args.out is not None:
        writable_folder(args.out)  # a bad folder named now, not after the cycles
    options = {} if args.elements is None else {"elements_per_piece": args.elements}
    if args.reel_element_length is not None:
        options["reeling"] = {"element_length": args.reel_element_length}
        if args.config == "pumping_kite":
            args.config = "pumping_kite_reeling"
    if args.wind is not None:
        options["overrides"] = {"wind": {"v0": args.wind}}
    task = PumpingTask(1, config=args.config, episode_time=2000.0, scene_options=options)  # the 0.01 rad step at 1 s
    changes = {k: v for k, v in (("reel_in_speed", args.reel_in_speed),
                                 ("alpha_in", None if args.alpha_in_deg is None else math.radians(args.alpha_in_deg)))
               if v is not None}
    if changes:
        task.pumping = dataclasses.replace(task.pumping, cycle=dataclasses.replace(task.pumping.cycle, **changes))
    ctl, names, title = _controller(task, args)
    reeling = is_reel(task.batch.assembly.station)
    try:
        rec = run_cycles(task, ctl, args.cycles + 1, probe=_contacts_probe if reeling else None)
    except RuntimeError as err:
        print(err)
        return 1
    stats = cycle_stats(rec, task.control_dt)
    rows = []
    print(f"{'cycle':>5} {'T_c s':>7} {'sim W':>8} {'matched W':>9} {'m. T_out N':>10} {'Lansdorp W':>11} "
          f"{'Schmehl W':>10} {'static W':>9} {'eq10-14 fed W':>13} {'T_out N':>8} {'v_out':>6} {'T_in N':>7} "
          f"{'alpha':>6} {'max|dy|':>7}")
    for k, c in enumerate(stats):
        q = quasi_steady(c, task)
        rows.append({**c, **q})
        print(f"{k:5d} {c['t_cycle']:7.1f} {c['power']:8.0f} {q['schmehl_matched_W']:9.0f} "
              f"{q['schmehl_matched_tension_N']:10.0f} {q['lansdorp_W']:11.0f} "
              f"{q['schmehl_W']:10.0f} "
              f"{q['static_kite_W']:9.0f} {q['eqs10_14_fed_W']:13.0f} {c['tension_out']:8.0f} {c['speed_out']:6.2f} "
              f"{c['tension_in']:7.0f} {math.degrees(c['alpha']):6.2f} {c['max_dy']:7.2f}")
    if reeling:
        print(contact_summary(rec, names))
    if args.out is not None:
        (args.out / "pumping_cycle.json").write_text(json.dumps(rows, indent=1))
        print(args.out / "pumping_cycle.json")
        for path in cycle_figures(rec, task.control_dt, names, PHASE_IN, title, args.out):
            print(path)
    return 0


def _contacts_probe(task: PumpingTask) -> dict[str, float]:
    """Tether nodes on the ground in copy 0 now (a reeling tether's, ``model/reel.ground_contacts``)."""
    return {"contacts": float(ground_contacts(task.batch.assembly, task.batch.states[0]))}


def contact_summary(rec: dict[str, np.ndarray], names) -> str:
    """A line on the ground contacts of a run recorded with the contact probe: the most nodes on the ground at once,
    the share of the control steps with any, and the first such step's time, phase (``names[phase]``) and cycle
    (1 + the reel-ins ended before it)."""
    on = rec["contacts"] > 0
    if not on.any():
        return f"ground contacts: no tether node touched the ground in {on.size} control steps"
    i = int(np.argmax(on))
    ph = rec["phase"][: i + 1]
    cycle = 1 + int(np.sum((ph[1:] != PHASE_IN) & (ph[:-1] == PHASE_IN)))
    changes = np.flatnonzero(ph[1:] != ph[:-1])
    since = rec["t"][changes[-1]] if changes.size else 0.0  # the end of the step before the phase began
    return (f"ground contacts: up to {int(rec['contacts'].max())} nodes on the ground at once, in "
            f"{100.0 * on.mean():.1f} % of the {on.size} control steps; the first at t = {rec['t'][i]:.2f} s, "
            f"{rec['t'][i] - since:.2f} s into the {names[int(ph[-1])]} phase of cycle {cycle} (cycle 1: from the "
            f"start to the end of the first reel-in)")


def _controller(task: PumpingTask, args):
    """(controller, its phase names, a figure title) of the command's options."""
    if args.controller == "lqr" or args.no_lqr:
        names = ("reel_out", "depower", "reel_in")
        if args.no_lqr:
            return PumpingCycleController(task), names, "PumpingKite: scripted static cycle"
        return (PumpingCycleController(task, lateral_lqr(task, DEFAULT_CONFIG)), names,
                "PumpingKite: LQR-assisted static cycle")
    cfg = load_crosswind_config()
    winch = dataclasses.replace(cfg.winch, reel_in_speed=args.reel_in_speed or cfg.winch.reel_in_speed)
    alpha_in = cfg.phases.alpha_in if args.alpha_in_deg is None else math.radians(args.alpha_in_deg)
    cfg = dataclasses.replace(cfg, winch=winch, phases=dataclasses.replace(cfg.phases, alpha_in=alpha_in))
    return (CrosswindController(task, lateral_lqr(task, DEFAULT_CONFIG), cfg), PHASE_NAMES,
            "PumpingKite: crosswind cycle (figure eights)")


#: ``laddermill pumping-cycle``
COMMAND = Command("pumping-cycle", "dynamic pumping cycle vs the quasi-steady prediction",
                  __doc__.split("\n\n")[0].replace("``", ""), _arguments, _run)
add_parser = COMMAND.add_parser
main = COMMAND.main


if __name__ == "__main__":
    raise SystemExit(main())
