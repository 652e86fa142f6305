"""Site optimisation of Lansdorp et al. (2008), eqs. 16-20: altitude, cable angle, cable diameter and kite area
of the design that maximises mean power per cost over a site's wind states, each state's C_L solved in closed form
(``site_problem``). The outer problem has four variables; SLSQP with finite-difference gradients from a few
starting points (the greedy inner solution is piecewise smooth in the design), constraints eq. 17 (inside the
inner problem: no state above F_max), eq. 18 (L / Delta L >= gamma) and eq. 19 (mean power = or >= P_d). The
result is the best feasible design met in any evaluation (starts included), not SLSQP's last iterate: on the
piecewise-smooth objective SLSQP may stop at an infeasible point one rounding away from a feasible optimum."""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize

from laddermill_gym.atmosphere.site_wind import SiteWind
from laddermill_gym.quasisteady.lansdorp import max_cable_force, speed_per_tension
from laddermill_gym.quasisteady.site_problem import Design, SiteCase, StateSolution, solve_states, tension_table

NAMES = ("h", "theta", "d", "S")
#: variable scales: the optimiser sees h / 100 m, theta [rad], d / 1 cm, S / 100 m^2
SCALE = np.array([100.0, 1.0, 0.01, 100.0])

#: Lansdorp et al. (2008), section V: design 1 (Table 1) and design 2 (Table 2)
TABLE1 = SiteCase()
TABLE2 = SiteCase(name="table2", cost="eq20", power_mode="at_least", drag="polar",
                  theta_bounds=(np.radians(57.0), np.radians(80.0)))
#: the paper's published designs (De Bilt soundings 1998-2007): altitude [m], angle [deg], d [mm], S [m^2], mean C_L
PAPER = {"table1": (353.6, 45.0, 29.68, 312.4, 0.5), "table2": (272.3, 57.0, 32.43, 168.8, 1.01)}


@dataclass(frozen=True)
class SiteResult:
    case: SiteCase
    design: Design
    solution: StateSolution
    feasible: bool
    wall_time: float        # [s] optimisation wall time
    evaluations: int        # inner problems solved
    states: int             # wind states used
    at_bounds: tuple[str, ...] = ()  # free variables on a bound of the search, each with its value and source


def _usable(wind: SiteWind, h: float):
    """Wind at h [m/s] and the time shares, states without data at h given no weight."""
    w = wind.at(h)
    ok = np.isfinite(w)
    return np.where(ok, w, 0.0), np.where(ok, wind.weight, 0.0)


def covered_heights(wind: SiteWind) -> tuple[float, float]:
    """(lowest, highest) grid height [m] of the span in which every state with weight has data, from the lowest
    such height up; ValueError naming the data when no height has data in every state. Outside it a state without
    data would count as calm (no power) and bias the design against the heights the data miss."""
    full = np.all(np.isfinite(wind.speed[wind.weight > 0]), axis=0)
    if not full.any():
        raise ValueError(f"{wind.source}: no height at which every wind state has data")
    first = int(np.argmax(full))
    gap = np.flatnonzero(~full[first:])
    last = first + (int(gap[0]) - 1 if gap.size else full.size - 1 - first)
    return float(wind.heights[first]), float(wind.heights[last])


def _bounds(case: SiteCase, wind: SiteWind):
    bottom, top = covered_heights(wind)
    lo_h = max(case.h_bounds[0], bottom)
    hi_h = min(case.h_bounds[1], top)
    if lo_h > hi_h:
        raise ValueError(f"{wind.source}: every state has data at {bottom:g}-{top:g} m only (data heights "
                         f"{wind.heights[0]:g}-{wind.heights[-1]:g} m), outside the altitude bounds "
                         f"{case.h_bounds[0]:g}-{case.h_bounds[1]:g} m")
    return [(lo_h, hi_h), case.theta_bounds, case.d_bounds, case.S_bounds]


def optimise(case: SiteCase, wind: SiteWind, fixed: dict | None = None, starts: int = 4) -> SiteResult:
    """Best design for ``case`` on ``wind``; ``fixed`` holds design variables kept at given values
    (e.g. ``{"h": 300.0, "theta": np.radians(60)}`` for Fig. 14)."""
    fixed = dict(fixed or {})
    bad = set(fixed) - set(NAMES)
    if bad:
        raise ValueError(f"optimise: unknown fixed variables {sorted(bad)}; known {NAMES}")
    free = [k for k, n in enumerate(NAMES) if n not in fixed]
    bounds = _bounds(case, wind)
    if "h" in fixed and not bounds[0][0] <= fixed["h"] <= bounds[0][1]:  # a state without data there would be calm
        raise ValueError(f"optimise: fixed h = {fixed['h']:g} m is outside {bounds[0][0]:g}-{bounds[0][1]:g} m, the "
                         f"altitudes where every wind state of {wind.source or 'the data'} has data and the case "
                         "allows")
    par, count = case.params, [0]
    t0 = time.perf_counter()

    def design_of(z):
        x = [fixed.get(n, np.nan) for n in NAMES]
        for j, k in enumerate(free):
            x[k] = float(np.clip(z[j] * SCALE[k], *bounds[k]))
        return Design(*x)

    incumbent = [None]                       # (ratio, design, solution): the best feasible point evaluated

    def feasible(des, sol):
        if sol.mean_power < case.power_target * (1.0 - 1e-9):
            return False
        if case.power_mode == "equal" and abs(sol.mean_power / case.power_target - 1.0) >= 1e-6:
            return False
        return des.length >= par.reel_length * par.min_length_ratio * (1.0 - 1e-9)

    def solve(z):
        count[0] += 1
        des = design_of(z)
        w, p = _usable(wind, des.h)
        sol = solve_states(case, des, w, p)
        if feasible(des, sol) and (incumbent[0] is None or sol.ratio > incumbent[0][0]):
            incumbent[0] = (sol.ratio, des, sol)
        return des, sol

    def objective(z):
        return -np.log(max(solve(z)[1].ratio, 1e-300))

    def power_margin(z):
        return solve(z)[1].max_mean_power / case.power_target - 1.0

    cons = [{"type": "ineq", "fun": power_margin}]
    if "h" not in fixed or "theta" not in fixed:
        cons.append({"type": "ineq", "fun": lambda z: design_of(z).length / (par.reel_length *
                                                                             par.min_length_ratio) - 1.0})
    zb = [(bounds[k][0] / SCALE[k], bounds[k][1] / SCALE[k]) for k in free]

    def max_power(*x):
        des = Design(*[fixed.get(nm, v) for nm, v in zip(NAMES, x, strict=True)])
        w, p = _usable(wind, des.h)
        return solve_states(case, des, w, p).max_mean_power

    for z0 in starting_points(case, bounds, free, starts, max_power):
        solve(z0)                            # a feasible start is a candidate whatever SLSQP makes of it
        minimize(objective, z0, method="SLSQP", bounds=zb, constraints=cons,
                 options={"maxiter": 200, "ftol": 1e-10})
    if incumbent[0] is not None:
        _, des, sol = incumbent[0]
        best = ((True, sol.ratio), des, sol)
    else:                                    # nothing feasible met: report the last start's design, infeasible
        des, sol = solve(z0)
        best = ((False, sol.ratio), des, sol)
    (ok, _), des, sol = best
    return SiteResult(case, des, sol, bool(ok), time.perf_counter() - t0, count[0], int(np.sum(wind.weight > 0)),
                      bound_notes(des, case, bounds, fixed))


#: how each design variable is written in a bound's note: (unit, factor from SI)
_SHOWN = {"h": ("m", 1.0), "theta": ("deg", 180.0 / np.pi), "d": ("mm", 1e3), "S": ("m^2", 1.0)}


def bound_notes(design: Design, case: SiteCase, bounds: list, fixed: dict | None = None) -> tuple[str, ...]:
    """The free variables of ``design`` that lie on a bound of the search ``bounds`` (the (low, high) of ``NAMES``,
    as :func:`optimise` searched them; within 1e-6 of the range), each as 'h = 600 m: the upper bound, the top of the
    data (every state has data up to 600 m)': an optimum there is the bound's, not the site's (moving the bound moves
    it). The altitude's bounds are ``case.h_bounds`` narrowed to the heights at which every wind state has data
    (:func:`covered_heights`): a bound inside the case's is the data's; the others are the case's."""
    bounds = dict(zip(NAMES, bounds, strict=True))
    (bottom, top), (case_lo, case_hi) = bounds["h"], case.h_bounds
    source = {("h", 0): ("the case's h_bounds" if bottom <= case_lo else
                         f"the lowest height with data in every state ({bottom:g} m)"),
              ("h", 1): ("the case's h_bounds" if top >= case_hi else
                         f"the top of the data (every state has data up to {top:g} m)")}
    notes = []
    for name in NAMES:
        if name in (fixed or {}):
            continue
        value, (lo, hi) = getattr(design, name), bounds[name]
        for side, b in ((0, lo), (1, hi)):
            if abs(value - b) <= 1e-6 * (hi - lo):
                unit, k = _SHOWN[name]
                why = source.get((name, side), f"the case's {name}_bounds")
                notes.append(f"{name} = {k * value:.4g} {unit}: the {('lower', 'upper')[side]} bound, {why}")
    return tuple(notes)


def starting_points(case, bounds, free, n, max_power):
    """Starting points: altitude just above the shortest cable and higher, angle low and mid, a thick cable, and
    the kite area at which the largest mean power is 1.5 P_d (bisection in log S), so that SLSQP starts feasible
    where it can. ``max_power(h, theta, d, S)`` [W]."""
    (h0, h1), (t0, t1), (d0, d1), (s0, s1) = bounds
    h_len = case.params.reel_length * case.params.min_length_ratio
    pts = []
    for th in (t0 + 0.02, 0.5 * (t0 + t1)):
        for scale in (1.05, 1.6):
            h = float(np.clip(h_len * np.cos(th) * scale, h0, h1))
            for d in (0.03, 0.06):
                d = float(np.clip(d, d0, d1))
                lo, hi = np.log(s0), np.log(s1)
                for _ in range(30):
                    mid = 0.5 * (lo + hi)
                    if max_power(h, th, d, np.exp(mid)) > 1.5 * case.power_target:
                        hi = mid
                    else:
                        lo = mid
                pts.append(np.array([h, th, d, np.exp(hi)]))
    pts = pts[: max(n, 1) * 2]
    return [p[free] / SCALE[free] for p in pts]


def operate(case: SiteCase, design: Design, wind: np.ndarray, reel_max: float, n_f: int = 61):
    """Run a fixed design through wind states, each state's C_L <= C_L,max and reel-out factor f in
    (0, reel_max] chosen for the largest useful power with the tension within eq. 15 (Figs. 19-20).
    Returns (power [W], C_L [-], tension [N], f [-]), arrays (n,)."""
    par = case.params
    cl_tab, g_tab = tension_table(case, design)
    f = np.linspace(reel_max / n_f, reel_max, n_f)[:, None]
    v_out = f * wind[None, :]
    w_e = np.maximum(wind[None, :] * np.sin(design.theta) - v_out, 0.0)
    c = 0.5 * par.rho * design.S * w_e * w_e
    f_max = float(max_cable_force(design.d, par))
    T = np.minimum(c * g_tab[-1], f_max)
    T = np.where(c * g_tab[0] > f_max, 0.0, T)
    P = speed_per_tension(v_out, par) * T
    j = np.argmax(P, axis=0)
    cols = np.arange(wind.size)
    Tb, cb = T[j, cols], c[j, cols]
    with np.errstate(divide="ignore", invalid="ignore"):
        cl = np.where(cb > 0, np.interp(Tb / np.where(cb > 0, cb, 1.0), g_tab, cl_tab), 0.0)
    return P[j, cols], np.where(Tb > 0, cl, 0.0), Tb, f[j, 0]


def sweep(case: SiteCase, wind: SiteWind, what: str, values, progress=None) -> list[SiteResult]:
    """Re-optimise with one parameter changed (Figs. 15-18): ``what`` is 'kite_glide', 'reel_in_speed',
    'reel_length' or 'reel_in_tension_ratio'."""
    out = []
    for v in values:
        if what == "kite_glide":
            c = dataclasses.replace(case, kite_glide=float(v))
        elif what in ("reel_in_speed", "reel_length", "reel_in_tension_ratio"):
            c = dataclasses.replace(case, params=dataclasses.replace(case.params, **{what: float(v)}))
        else:
            raise ValueError(f"sweep: unknown parameter {what!r}")
        out.append(optimise(c, wind))
        if progress is not None:
            progress.update(1)
    return out


def altitude_angle_grid(case: SiteCase, wind: SiteWind, hs, thetas, progress=None):
    """Fig. 14: the best d and S for fixed altitude and cable angle; ``results[i][j]`` for ``hs[i]``,
    ``thetas[j]`` (None where the cable would be shorter than gamma Delta L, eq. 18)."""
    need = case.params.reel_length * case.params.min_length_ratio
    grid = []
    for h in hs:
        row = []
        for th in thetas:
            row.append(optimise(case, wind, fixed={"h": float(h), "theta": float(th)}, starts=1)
                       if h / np.cos(th) >= need - 1e-9 else None)
            if progress is not None:
                progress.update(1)
        grid.append(row)
    return grid
