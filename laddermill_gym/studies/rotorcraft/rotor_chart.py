"""Roberts' power-coefficient chart (his Fig. 3): C_p against craft incidence at the blade-incidence limit.

Run ``python -m laddermill_gym.studies.rotorcraft.rotor_chart [--out laddermill_gym/docs/figures/rotor_power_chart.png]
[--csv results/rotor_power_chart.csv] [--config configs/rotors/roberts_rotor.yaml] [--mu 0.05,0.1,...]``.

For every advance ratio mu and craft incidence alpha_c on a 0.5 deg grid the collective is set so that the
retreating blade tip sits at the blade-incidence limit (13 deg), and the rotor's power coefficient
(Roberts eq. 4) is drawn (:func:`laddermill_gym.rotorcraft.rotor.max_power_at_limit`). The ideal curve is the actuator
disk without profile drag (16/27 at 90 deg, 0 at 0 deg). The points where the left branches cross C_p = 0
are the autorotation points (Roberts section 5: 22.5 deg for mu = 0.1). The paper's text names only
mu = 0.1; the other advance ratios are a choice that spans the family (docs/rotor.md).

The command also prints the solidity that puts the mu = 0.1 autorotation point at 22.5 deg, at the limit
and at fixed collective, and the fixed-collective autorotation angles beside the blade-element values of
shared/design/oracles.md.
"""

from __future__ import annotations

import argparse
import csv
import math
import textwrap
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from laddermill_gym.rotorcraft.rotor import (
    DEFAULT_ROTOR_CONFIG,
    RotorParams,
    RotorSolveError,
    autorotation_angle,
    autorotation_angle_at_limit,
    best_power_within_limit,
    ideal_power_coefficient,
    load_rotor_config,
    max_power_at_limit,
    min_autorotation_angle,
    solidity_for_autorotation,
)
from laddermill_gym.studies.commands import UsageError, writable_file

__all__ = [
    "DEFAULT_CONFIG",
    "DEFAULT_OUT",
    "DEFAULT_CSV",
    "DEFAULT_MUS",
    "ORACLE_AUTOROTATION_DEG",
    "LimitCurve",
    "limit_curve",
    "solidity_at_fixed_collective",
    "solidity_for_min_autorotation",
    "write_csv",
    "plot_chart",
    "main",
]

DEFAULT_CONFIG = DEFAULT_ROTOR_CONFIG
DEFAULT_OUT = Path("results/rotor_power_chart.png")  # the docs' figure: --out laddermill_gym/docs/figures/...
DEFAULT_CSV = Path("results/rotor_power_chart.csv")
#: Advance ratios drawn by default (mu = 0.1 is the paper's; the others are a choice, docs/rotor.md).
DEFAULT_MUS: tuple[float, ...] = (0.05, 0.075, 0.1, 0.15, 0.2)
#: Roberts, section 5: C_p = 0 at alpha_c = 22.5 deg for mu = 0.1.
ROBERTS_MU, ROBERTS_AUTOROTATION_DEG = 0.1, 22.5
#: oracles.md, blade-element autorotation angles [deg] at mu = 0.1 (a 5.73, delta 0.01, B 0.97, gamma 8),
#: keyed by solidity, for collective theta0 = 0, 2, 4, 6 deg.
ORACLE_THETA_DEG: tuple[float, ...] = (0.0, 2.0, 4.0, 6.0)
ORACLE_AUTOROTATION_DEG: dict[float, tuple[float, ...]] = {
    0.05: (21.7, 19.0, 18.4, 19.2),
    0.08: (24.5, 23.2, 24.3, 26.8),
}
#: Collective below which the small-angle theory is stretched; drawn dotted [deg].
STRETCHED_THETA_DEG = -20.0
_FIGURE_SUFFIXES = (".png", ".pdf", ".svg")


@dataclass(frozen=True)
class LimitCurve:
    """One Fig. 3 curve: arrays over the incidence grid (nan where the limit cannot be reached).

    alpha_c_deg [deg], cp [-], theta0_deg [deg], ct, ch, cq, lam, nu [-] at the limit; autorotation_deg [deg]
    (nan if none); cp_best [-] and theta0_best_deg [deg]: the largest C_p over collectives within the limit
    (:func:`laddermill_gym.rotorcraft.rotor.best_power_within_limit`).
    """

    mu: float
    alpha_c_deg: np.ndarray
    cp: np.ndarray
    theta0_deg: np.ndarray
    ct: np.ndarray
    ch: np.ndarray
    cq: np.ndarray
    lam: np.ndarray
    nu: np.ndarray
    autorotation_deg: float
    cp_best: np.ndarray
    theta0_best_deg: np.ndarray


def limit_curve(params: RotorParams, mu: float, alpha_c_deg: np.ndarray, limit: float) -> LimitCurve:
    """C_p and the trimmed rotor at the blade-incidence limit [rad] over the incidence grid [deg]."""
    n = alpha_c_deg.size
    cols = {k: np.full(n, np.nan) for k in ("cp", "theta0_deg", "ct", "ch", "cq", "lam", "nu", "cp_best",
                                             "theta0_best_deg")}
    for i, a in enumerate(alpha_c_deg):
        try:
            st = max_power_at_limit(params, mu, math.radians(a), limit)
            best = best_power_within_limit(params, mu, math.radians(a), limit)
        except RotorSolveError:
            continue
        if best.converged:
            cols["cp_best"][i], cols["theta0_best_deg"][i] = best.cp, math.degrees(best.theta0)
        if not st.converged:
            continue
        cols["cp"][i], cols["theta0_deg"][i] = st.cp, math.degrees(st.theta0)
        cols["ct"][i], cols["ch"][i], cols["cq"][i] = st.ct, st.ch, st.cq
        cols["lam"][i], cols["nu"][i] = st.lam, st.nu
    try:
        auto = math.degrees(autorotation_angle_at_limit(params, mu, limit))
    except RotorSolveError:
        auto = math.nan
    return LimitCurve(mu=mu, alpha_c_deg=alpha_c_deg, autorotation_deg=auto, **cols)


def solidity_at_fixed_collective(params: RotorParams, mu: float, alpha_c: float, theta0: float,
                                 sigma_range: tuple[float, float] = (0.01, 0.3)) -> float:
    """Solidity [-] whose autorotation angle at collective theta0 [rad] is alpha_c [rad] (Brent's method)."""

    def miss(sigma):
        return autorotation_angle(params.with_solidity(sigma), mu, theta0) - alpha_c

    return brentq(miss, *sigma_range, xtol=1e-8, rtol=1e-10)


def solidity_for_min_autorotation(params: RotorParams, mu: float, alpha_c: float,
                                  sigma_range: tuple[float, float] = (0.02, 0.2)) -> float:
    """Solidity [-] whose lowest autorotation incidence over collective
    (:func:`laddermill_gym.rotorcraft.rotor.min_autorotation_angle`) is alpha_c [rad] (Brent's method)."""

    def miss(sigma):
        return min_autorotation_angle(params.with_solidity(sigma), mu)[0] - alpha_c

    return brentq(miss, *sigma_range, xtol=1e-7, rtol=1e-10)


def write_csv(path: Path, curves: list[LimitCurve], ideal_deg: np.ndarray, ideal_cp: np.ndarray) -> None:
    """Long-format table: kind (limit | best | ideal | autorotation), mu, alpha_c_deg, cp, theta0_deg, ct, ch,
    cq, lam, nu (empty where not applicable; 'best' rows carry only cp and theta0_deg)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    head = ["kind", "mu", "alpha_c_deg", "cp", "theta0_deg", "ct", "ch", "cq", "lam", "nu"]

    def fmt(v):
        return "" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.10g}"

    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(head)
        for c in curves:
            for i, a in enumerate(c.alpha_c_deg):
                if math.isnan(c.cp[i]):
                    continue
                w.writerow(["limit", fmt(c.mu), fmt(float(a))] + [fmt(float(getattr(c, k)[i])) for k in head[3:]])
        for c in curves:
            for i, a in enumerate(c.alpha_c_deg):
                if not math.isnan(c.cp_best[i]):
                    w.writerow(["best", fmt(c.mu), fmt(float(a)), fmt(float(c.cp_best[i])),
                                fmt(float(c.theta0_best_deg[i]))] + [""] * 5)
        for a, cp in zip(ideal_deg, ideal_cp, strict=True):
            w.writerow(["ideal", "", fmt(float(a)), fmt(float(cp))] + [""] * 6)
        for c in curves:
            if not math.isnan(c.autorotation_deg):
                w.writerow(["autorotation", fmt(c.mu), fmt(c.autorotation_deg), "0"] + [""] * 6)


def plot_chart(path: Path, curves: list[LimitCurve], ideal_deg: np.ndarray, ideal_cp: np.ndarray,
               params: RotorParams, limit_deg: float) -> None:
    """Draw the chart: limit curves (dotted where theta0 < -20 deg), the best-collective curve for mu = 0.1
    (dashed), the ideal curve, the Betz line and the autorotation points."""
    import matplotlib

    from laddermill_gym.figure_files import subplots
    from laddermill_gym.plotting import save_figure

    fig, ax = subplots(figsize=(8.5, 6.0))
    ax.plot(ideal_deg, ideal_cp, "k-", lw=2.2, label="ideal (actuator disk, no profile drag)")
    ax.axhline(16.0 / 27.0, color="0.4", ls="--", lw=0.9)
    ax.text(1.0, 16.0 / 27.0 + 0.008, "Betz 16/27", color="0.3", fontsize=8)
    ax.axhline(0.0, color="0.6", lw=0.8)
    colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    for j, c in enumerate(curves):
        col = colors[j % len(colors)]
        ok = c.theta0_deg >= STRETCHED_THETA_DEG
        ax.plot(c.alpha_c_deg, np.where(ok, c.cp, np.nan), "-", color=col, lw=1.5, label=f"mu = {c.mu:g}")
        ax.plot(c.alpha_c_deg, np.where(~ok | np.roll(~ok, -1), c.cp, np.nan), ":", color=col, lw=1.2)
        if c.mu == ROBERTS_MU:  # one example keeps the chart readable; the CSV has all of them
            differs = np.abs(c.cp_best - c.cp) > 1e-4
            show = differs | np.roll(differs, 1) | np.roll(differs, -1)
            ax.plot(c.alpha_c_deg, np.where(show, c.cp_best, np.nan), "--", color=col, lw=1.0)
        if not math.isnan(c.autorotation_deg):
            ax.plot([c.autorotation_deg], [0.0], "o", color=col, ms=6, mfc="white", mew=1.5)
            if c.mu == ROBERTS_MU:
                ax.annotate(f"autorotation {c.autorotation_deg:.1f} deg\n(Roberts: {ROBERTS_AUTOROTATION_DEG} deg)",
                            (c.autorotation_deg, 0.0), xytext=(c.autorotation_deg - 2.0, -0.17), fontsize=8,
                            arrowprops={"arrowstyle": "->", "lw": 0.8})
    ax.set(xlim=(0.0, 90.0), ylim=(-0.3, 0.65), xlabel="craft incidence alpha_c [deg]",
           ylabel="power coefficient C_p = P / (rho pi R^2 V^3 / 2) [-]",
           title=f"Tethered rotor at the {limit_deg:g} deg blade-incidence limit (Roberts Fig. 3)\n"
                 f"sigma = {params.sigma:g}, a = {params.a:g}/rad, delta = {params.delta:g}, B = {params.B:g}, "
                 f"gamma = {params.gamma:g}\ndotted: theta0 < {STRETCHED_THETA_DEG:g} deg; "
                 f"dashed (mu = {ROBERTS_MU:g}): best collective within the limit")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=8)
    save_figure(fig, path)


def _parse_mus(text: str) -> tuple[float, ...]:
    try:
        mus = tuple(float(t) for t in text.split(",") if t.strip())
    except ValueError:
        raise ValueError(f"--mu {text!r}: must be a comma-separated list of numbers") from None
    if not mus or any(not 0.0 < m < 1.0 for m in mus):
        raise ValueError(f"--mu {text!r}: every advance ratio must lie in (0, 1)")
    return mus


def main(argv: list[str] | None = None) -> list[LimitCurve]:
    """Command line: compute the curves, print the findings, write the PNG and the CSV; returns the curves."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(DEFAULT_OUT), help="figure file (.png, .pdf or .svg)")
    ap.add_argument("--csv", default=str(DEFAULT_CSV), help="table of the curves")
    ap.add_argument("--config", default=str(DEFAULT_CONFIG), help="rotor YAML (configs/rotors/)")
    ap.add_argument("--mu", default=",".join(f"{m:g}" for m in DEFAULT_MUS), help="comma-separated advance ratios")
    ap.add_argument("--step-deg", type=float, default=0.5, help="incidence grid spacing [deg]")
    args = ap.parse_args(argv)
    if not 0.0 < args.step_deg <= 10.0:
        raise UsageError(f"--step-deg {args.step_deg!r}: must lie in (0, 10]")
    out, csv_path = writable_file(args.out, "--out", _FIGURE_SUFFIXES), writable_file(args.csv, "--csv")
    mus = _parse_mus(args.mu)
    t0 = time.perf_counter()
    cfg = load_rotor_config(args.config)
    params, limit = cfg.params, cfg.blade_incidence_limit
    limit_deg = math.degrees(limit)

    alpha_deg = np.arange(args.step_deg, 90.0, args.step_deg)
    curves = [limit_curve(params, mu, alpha_deg, limit) for mu in mus]
    ideal_deg = np.linspace(0.0, 90.0, 181)
    ideal_cp = ideal_power_coefficient(np.radians(ideal_deg))

    print(f"rotor '{cfg.name}' from {args.config}: {params}, blade-incidence limit {limit_deg:g} deg")
    print(f"ideal C_p: {ideal_cp[-1]:.6f} at 90 deg (Betz 16/27 = {16 / 27:.6f}), "
          f"{ideal_power_coefficient(math.radians(1.0)):.2e} at 1 deg, {ideal_cp[0]:.1f} at 0 deg")
    print("\nmu     autorotation [deg]   peak C_p at [deg]   collective at autorotation [deg]")
    for c in curves:
        i = int(np.nanargmax(c.cp))
        th = math.nan
        if not math.isnan(c.autorotation_deg):
            th = math.degrees(max_power_at_limit(params, c.mu, math.radians(c.autorotation_deg), limit).theta0)
        print(f"{c.mu:<6g} {c.autorotation_deg:>18.2f}   {c.cp[i]:>8.4f} at {c.alpha_c_deg[i]:>5.1f}   {th:>12.2f}")

    target = math.radians(ROBERTS_AUTOROTATION_DEG)
    sigma_limit = solidity_for_autorotation(params, ROBERTS_MU, target, limit)
    print(f"\nSolidity for autorotation at {ROBERTS_AUTOROTATION_DEG} deg, mu = {ROBERTS_MU} "
          f"(a, delta, B, gamma as above):")
    print(f"  at the {limit_deg:g} deg tip limit (the chart's construction): sigma = {sigma_limit:.4f}")
    sigma_min = solidity_for_min_autorotation(params, ROBERTS_MU, target)
    theta_min = math.degrees(min_autorotation_angle(params.with_solidity(sigma_min), ROBERTS_MU)[1])
    print(f"  as the lowest autorotation incidence over all collectives (best theta0 = {theta_min:.1f} deg): "
          f"sigma = {sigma_min:.4f}")
    for th in ORACLE_THETA_DEG:
        s = solidity_at_fixed_collective(params, ROBERTS_MU, target, math.radians(th))
        print(f"  at fixed collective theta0 = {th:g} deg: sigma = {s:.4f}")
    p_lo, p_hi = params.with_solidity(sigma_limit - 0.005), params.with_solidity(sigma_limit + 0.005)
    slope = math.degrees(autorotation_angle_at_limit(p_hi, ROBERTS_MU, limit)
                         - autorotation_angle_at_limit(p_lo, ROBERTS_MU, limit))
    theta_auto = math.degrees(max_power_at_limit(params.with_solidity(sigma_limit), ROBERTS_MU, target, limit).theta0)
    why = (
        "why: C_Q = 0 needs lam C_T + mu C_H = sigma delta (1 + 3 mu^2)/8. More solidity means more thrust, hence a "
        "larger Glauert induced velocity nu ~ C_T / (2 mu) that the free stream lam_inf = mu tan(alpha_c) must "
        f"overcome: the autorotation angle rises with sigma ({slope:.1f} deg per 0.01 of sigma at the limit). The "
        f"angle also depends on the collective, with a minimum near theta0 = {theta_min:.0f} deg. At the tip limit "
        f"the collective at autorotation is {theta_auto:.1f} deg, where the angle is larger for the same sigma, so "
        f"the chart's construction needs sigma = {sigma_limit:.3f}. Read as the lowest incidence at which the craft "
        f"can autorotate at all (best collective), 22.5 deg needs sigma = {sigma_min:.3f}: the 0.07-0.08 of "
        "oracles.md."
    )
    print(textwrap.fill(why, width=110, initial_indent="  ", subsequent_indent="  "))
    print(f"\nAutorotation angle [deg] at mu = {ROBERTS_MU}, fixed collective, this model vs oracles.md "
          "(blade-element integration):")
    for sig, ref in ORACLE_AUTOROTATION_DEG.items():
        ours = [math.degrees(autorotation_angle(params.with_solidity(sig), ROBERTS_MU, math.radians(t)))
                for t in ORACLE_THETA_DEG]
        pairs = ", ".join(f"{t:g}: {o:.2f}/{r:.1f}" for t, o, r in zip(ORACLE_THETA_DEG, ours, ref, strict=True))
        print(f"  sigma {sig:g} (theta0 deg: ours/oracle): {pairs}")

    write_csv(csv_path, curves, ideal_deg, ideal_cp)
    plot_chart(out, curves, ideal_deg, ideal_cp, params, limit_deg)
    print(f"\nwrote {out} and {csv_path} ({time.perf_counter() - t0:.1f} s)")
    return curves


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("rotor_chart", lambda: main() and 0))
