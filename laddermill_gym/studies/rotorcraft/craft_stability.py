"""Roll / lateral stability of Roberts' tethered twin-rotor craft: eq. (6) against the simulator's Jacobian,
the critical wind speed, and the eq. (6) LQR on the full nonlinear simulator.

Run ``python -m laddermill_gym.studies.rotorcraft.craft_stability [--out DIR] [--quick]``. It prints

1. eq. (6) at the design trim (M, D, K, alpha, beta) and its check against the full simulator's Jacobian
   restricted to (y, phi) (straight single-element tethers, as the derivation assumes), entry by entry;
2. the growth rate of the least stable mode of the full linearised craft (all states, minimal coordinates)
   against the wind speed, and the critical wind speed where it crosses zero (bisection);
3. open loop against the eq. (6) LQR after a 0.01 rad wind-direction step, 120 s of the nonlinear simulator;

and writes ``rotorcraft_stability.png`` and ``rotorcraft_stability.json`` to ``--out`` (default
runs/craft_stability). Method and results: laddermill_gym/docs/rotorcraft.md.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.control.craft_lqr import design_craft_lqr
from laddermill_gym.control.linearize import linearize
from laddermill_gym.kernels.contract import B3_POS, CU_DIFFERENTIAL
from laddermill_gym.rotorcraft.craft import Craft, CraftSimulator, load_craft
from laddermill_gym.rotorcraft.roll_lateral import derive_roll_lateral, lateral_state, restricted_jacobian, sim_euler
from laddermill_gym.sim.simulator import SimulationError
from laddermill_gym.studies.commands import writable_folder


def straight_tether_variant(craft: Craft) -> Craft:
    """The craft with one element per tether, no sag correction and no cable aerodynamics: the tethers eq. (6)
    assumes (straight, Roberts' massless cables up to the element's consistent mass)."""
    cfg = craft.config
    t = dataclasses.replace(cfg.tethers, elements=1)
    return load_craft(config=cfg.replace(tethers=t, sag=False, cable_aero=False))


def jacobian_check(craft: Craft) -> dict:
    """Eq. (6) against the restricted Jacobian at the trim of ``craft``: the blocks -M^-1 K, -M^-1 D, M^-1 b
    both ways and the largest relative entry error (entries below 1e-3 of their block's largest are skipped)."""
    sim = craft.simulator()
    model = derive_roll_lateral(sim)
    Kn, Dn, Bn = restricted_jacobian(sim)
    Mi = np.linalg.inv(model.M)
    pairs = {"stiffness": (-Mi @ model.K, Kn), "damping": (-Mi @ model.D, Dn), "input": (Mi @ model.b, Bn)}
    worst = 0.0
    out = {"M": model.M.tolist(), "D": model.D.tolist(), "K": model.K.tolist(), "alpha_beta": model.b.tolist()}
    for name, (a, n) in pairs.items():
        big = np.max(np.abs(n))
        mask = np.abs(n) > 1e-3 * big
        rel = np.abs(a - n)[mask] / np.abs(n)[mask]
        worst = max(worst, float(rel.max()))
        out[name] = {"eq6": np.atleast_1d(a).tolist(), "jacobian": np.atleast_1d(n).tolist(),
                     "max_rel_error": float(rel.max())}
    out["max_rel_error"] = worst
    return out


def lateral_mode(craft: Craft, x: np.ndarray, collective: float) -> complex:
    """Eigenvalue [1/s] of the craft's lateral mode at the trim x: of the slow oscillatory eigenvalues
    (0.05 < |Im| < 5 rad/s) of the full linearisation (minimal coordinates), the one whose eigenvector moves the CG
    sideways the most."""
    u = np.array([collective, 0.0])
    sim = CraftSimulator(craft.config, craft.assembly, craft.layout, x, u)
    lin = linearize(sim, x, u)
    w, V = np.linalg.eig(lin.A)
    iy = list(lin.state_names).index("wing0_y")
    share = np.abs(V[iy]) / np.linalg.norm(V, axis=0)
    slow = (np.abs(w.imag) < 5.0) & (np.abs(w.imag) > 0.05)
    return complex(w[np.argmax(np.where(slow, share, -1.0))])


def growth_rate(craft: Craft, x_guess: np.ndarray | None = None) -> tuple[float, np.ndarray, complex, float]:
    """Growth rate [1/s] of the lateral mode at the blade-limited operating point (:meth:`Craft.operating_collective`),
    the trim state, the eigenvalue and the collective [rad]."""
    th, x = craft.operating_collective(x_guess)
    ev = lateral_mode(craft, x, th)
    return ev.real, x, ev, th


def growth_scan(craft: Craft, speeds) -> dict[str, np.ndarray]:
    """Lateral-mode growth rate [1/s], frequency [rad/s] and operating collective [rad] at the wind speeds
    ``speeds`` [m/s] (trims continued from one speed to the next)."""
    xg, out = None, {"growth": [], "frequency": [], "collective": [], "trims": []}
    for v in speeds:
        c = load_craft(config=craft.config.with_wind_speed(float(v)))
        r, xg, ev, th = growth_rate(c, xg)
        out["growth"].append(r)
        out["frequency"].append(abs(ev.imag))
        out["collective"].append(th)
        out["trims"].append(xg)
    return {k: np.array(v) for k, v in out.items()}


def critical_wind_speed(craft: Craft, lo: float, hi: float, tol: float = 0.01,
                        x_guess: np.ndarray | None = None) -> float:
    """Wind speed v0 [m/s] in [lo, hi] where the lateral mode's growth rate crosses zero (Brent's method); the
    growth rate must change sign over the bracket. ``x_guess``: a trim near the bracket (continued)."""
    last = [x_guess]

    def g(v):
        r, last[0], _, _ = growth_rate(load_craft(config=craft.config.with_wind_speed(v)), last[0])
        return r

    return float(brentq(g, lo, hi, xtol=tol))


def direction_step(sim: CraftSimulator, step: float = 0.01, at: float = 1.0) -> None:
    """Turn the wind direction by ``step`` [rad] at time ``at`` [s] (the model's wind modulation series)."""
    n = int(round(at / 0.01))
    md = np.zeros(n + 1)
    md[-1] = step
    sim.set_wind(WindField(0.0, 0.01, np.ones(n + 1), md))


def closed_loop_run(design, t_end: float = 120.0, controller: bool = True, step: float = 0.01) -> dict:
    """The design's trimmed craft after a direction step of ``step`` [rad] at 1 s, open loop or with the eq. (6) LQR
    (differential collective clipped to its limits). Returns time series (t, y, phi, psi, dtheta) and the
    failure time (nan if none)."""
    sim = CraftSimulator(design.sim.config, design.sim.assembly, design.sim.layout, design.x_trim, design.u_trim)
    direction_step(sim, step)
    dt = design.config.control_period
    n_sub = int(round(dt / sim.settings.dt))
    rec = {k: [] for k in ("t", "y", "phi", "psi", "dtheta")}
    fail = math.nan
    for _ in range(int(round(t_end / dt))):
        z = lateral_state(sim.state, design.x_trim)
        d = design.state_controls(sim.state)[1] if controller else 0.0
        for k, v in zip(rec, (sim.t, z[0], z[1], sim_euler(sim.state)[2], d), strict=True):
            rec[k].append(v)
        try:
            u = design.u_trim.copy()
            u[CU_DIFFERENTIAL] = d
            sim.step(u, n_sub)
        except SimulationError:
            fail = sim.t
            break
        if sim.state[B3_POS + 2] > -1.0:  # CG within 1 m of the ground (z down)
            fail = sim.t
            break
    out = {k: np.array(v) for k, v in rec.items()}
    out["failure_time"] = fail
    return out


def plot(scan_v, scan_rate, v_crit, runs, path: Path) -> None:
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    fig, ax = subplots(1, 3, figsize=(13, 3.8))
    ax[0].plot(scan_v, scan_rate, "o-")
    ax[0].axhline(0.0, color="k", lw=0.8)
    ax[0].axvline(v_crit, color="r", ls="--", label=f"critical {v_crit:.2f} m/s")
    ax[0].set(xlabel="wind speed v0 [m/s]", ylabel="growth rate of the lateral mode [1/s]",
              title="open loop, full linearised craft, blade-limited collective")
    ax[0].legend()
    for name, r in runs.items():
        ax[1].plot(r["t"], r["y"], label=name)
        ax[2].plot(r["t"], np.degrees(r["dtheta"]), label=name)
    ax[1].set(xlabel="t [s]", ylabel="lateral offset y [m]", title="wind direction step at t = 1 s", ylim=(-12, 12))
    ax[2].set(xlabel="t [s]", ylabel="differential collective [deg]", title="control")
    ax[1].legend()
    save_figure(fig, path, dpi=110)


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=Path("runs/craft_stability"))
    ap.add_argument("--quick", action="store_true", help="coarser wind-speed scan, 60 s runs")
    args = ap.parse_args(argv)
    writable_folder(args.out, "--out")
    design = design_craft_lqr()
    craft = load_craft(design.config.craft)
    np.set_printoptions(precision=4, suppress=False, linewidth=120)

    chk = jacobian_check(straight_tether_variant(load_craft(config=craft.config.with_wind_speed(
        design.config.wind_speed))))
    print(f"1. eq. (6) at the trim (v0 = {design.config.wind_speed:.1f} m/s), straight single-element tethers")
    print("   M =", np.array(chk["M"]).tolist(), "\n   D =", np.array(chk["D"]).tolist(),
          "\n   K =", np.array(chk["K"]).tolist(), "\n   (alpha, beta) =", chk["alpha_beta"])
    for name in ("stiffness", "damping", "input"):
        print(f"   {name:9s} eq6 {np.round(chk[name]['eq6'], 4).tolist()}")
        print(f"   {'':9s} jac {np.round(chk[name]['jacobian'], 4).tolist()}  max rel error "
              f"{chk[name]['max_rel_error']:.2e}")

    speeds = np.arange(7.0, 22.1, 1.5 if args.quick else 1.0)
    scan = growth_scan(craft, speeds)
    rates = scan["growth"]
    sign = np.flatnonzero(np.diff(np.sign(rates)) != 0)
    if sign.size == 0:
        raise RuntimeError(f"no sign change of the growth rate over {speeds[0]}..{speeds[-1]} m/s: {rates}")
    v_crit = critical_wind_speed(craft, speeds[sign[0]], speeds[sign[0] + 1], x_guess=scan["trims"][sign[0]])
    print("2. lateral mode of the full craft against the wind speed (blade-limited collective, rotor speed "
          f"{craft.config.rotor_speed} rad/s)")
    for v, r, f, th in zip(speeds, rates, scan["frequency"], scan["collective"], strict=True):
        print(f"   v0 = {v:5.1f} m/s  collective {math.degrees(th):5.2f} deg  growth {r:+.4f} 1/s  "
              f"frequency {f:.3f} rad/s")
    print(f"   critical wind speed: {v_crit:.2f} m/s (unstable below)")

    t_end = 60.0 if args.quick else 120.0
    runs = {}
    for step in (0.01, 0.1):
        runs[f"open loop, {step} rad"] = closed_loop_run(design, t_end, controller=False, step=step)
        runs[f"eq. (6) LQR, {step} rad"] = closed_loop_run(design, t_end, controller=True, step=step)
    zmax = float(np.max(np.abs(design.lqr.closed_loop)))
    print(f"3. direction steps at t = 1 s, v0 = {design.config.wind_speed:.1f} m/s, {t_end:g} s; LQR gain "
          f"K = {np.round(design.gain, 4).tolist()}, discrete closed loop max |z| = {zmax:.4f}")
    summary = {}
    for name, r in runs.items():
        late = r["t"] > r["t"][-1] / 2
        summary[name] = {"failure_time_s": r["failure_time"], "max_abs_y_m": float(np.max(np.abs(r["y"]))),
                         "max_abs_y_second_half_m": float(np.max(np.abs(r["y"][late]))),
                         "max_abs_dtheta_deg": float(np.degrees(np.max(np.abs(r["dtheta"]))))}
        sm = summary[name]
        head = (f"failure at {r['failure_time']:.1f} s" if math.isfinite(r["failure_time"]) else "no failure")
        print(f"   {name:22s} {head} | max |y| {sm['max_abs_y_m']:.3f} m, second half "
              f"{sm['max_abs_y_second_half_m']:.4f} m, max |dtheta| {sm['max_abs_dtheta_deg']:.2f} deg")
    plot(speeds, rates, v_crit, runs, args.out / "rotorcraft_stability.png")
    result = {"jacobian_check": chk, "speeds": speeds.tolist(), "growth": rates.tolist(),
              "collective_deg": np.degrees(scan["collective"]).tolist(),
              "critical_wind_speed": v_crit, "gain": design.gain.tolist(),
              "closed_loop_max_abs_z": float(np.max(np.abs(design.lqr.closed_loop))), "runs": summary}
    (args.out / "rotorcraft_stability.json").write_text(json.dumps(result, indent=1))
    print(f"wrote {args.out / 'rotorcraft_stability.png'} and .json")
    return result


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("craft_stability", lambda: main() and 0))
