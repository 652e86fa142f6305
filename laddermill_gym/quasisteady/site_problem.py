"""The site problem of Lansdorp et al. (2008), eqs. 16-20, for one design: the best lift coefficient of every
wind state in closed form.

With the paper's assumptions the reel-out tension of state i scales with one function of C_L for all states,
T_i = c_i g(C_L) (eq. 9: c_i = rho S w_e,i^2 / 2, g = (C_L^2 + C_Dt^2)^(3/2) / C_Dt^2, C_Dt = C_D(C_L) + d L C_Dc /
(4 S)), and the useful power is proportional to it, P_i = k_i T_i (eqs. 10-14 with T_r = T / 50 and v_out = f w_i:
k_i depends on the wind only). Choosing C_L_i is therefore choosing T_i in [T_lo,i, T_hi,i] (C_L from 0 to C_L,max,
capped by eq. 15), and maximising mean power per cost, P / (T + c0) (eq. 16: c0 = k1 S; eq. 20: c0 = 0 and the
design's S d m_c as a constant factor), subject to P = P_d (eq. 19) or P >= P_d, is a linear-fractional
knapsack: raise the tension of the states with the largest k_i first (Dantzig's greedy rule); the optimum lies at
P = P_d or where a further state no longer raises the ratio. One sort per design, no per-state optimiser; C_L_i
follows from the tabulated inverse of g. Means are time averages: sum_i p_i x_i over the states' time shares p_i
(time outside the data counts as no power and no tension).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.quasisteady.lansdorp import (
    PumpingParams,
    cable_drag_share,
    cable_length,
    max_cable_force,
    speed_per_tension,
)


@dataclass(frozen=True)
class SiteCase:
    """One site optimisation problem (SI units, radians). Defaults: Lansdorp et al. (2008), design 1 (Table 1)."""

    name: str = "table1"
    cost: str = "eq16"                  # "eq16": J = -P / (T + k1 S); "eq20": J = -P / (T S d m_c)
    power_target: float = 1.0e6         # [W] P_d, eq. 19
    power_mode: str = "equal"           # "equal": P = P_d (eq. 19); "at_least": P >= P_d (design 2)
    k1: float = 1000.0                  # [N/m^2] kite-area weight of eq. 16 (not given in the paper: our choice)
    cl_max: float = 1.2                 # [-] largest kite C_L (section V)
    drag: str = "glide"                 # "glide": C_D = C_L / kite_glide; "polar": C_D = cd0 + cd2 C_L^2
    kite_glide: float = 16.0            # [-] kite L/D of design 1 ("G = 16", read as the kite's own L/D)
    cd0: float = 0.03                   # [-] polar of design 2 (section V)
    cd2: float = 0.04                   # [-]
    reel_out_factor: float = 1.0 / 3.0  # [-] v_out / w ("1/3 of the wind speed")
    theta_bounds: tuple[float, float] = (np.radians(45.0), np.radians(80.0))  # [rad] cable angle from vertical
    h_bounds: tuple[float, float] = (50.0, 1000.0)     # [m] altitude (also limited by the data's heights)
    d_bounds: tuple[float, float] = (0.002, 0.2)       # [m] cable diameter
    S_bounds: tuple[float, float] = (1.0, 5000.0)      # [m^2] kite area
    params: PumpingParams = field(default_factory=PumpingParams)

    def __post_init__(self):
        if self.cost not in ("eq16", "eq20"):
            raise ValueError(f"SiteCase.cost = {self.cost!r}: must be 'eq16' or 'eq20'")
        if self.power_mode not in ("equal", "at_least"):
            raise ValueError(f"SiteCase.power_mode = {self.power_mode!r}: must be 'equal' or 'at_least'")
        if self.drag not in ("glide", "polar"):
            raise ValueError(f"SiteCase.drag = {self.drag!r}: must be 'glide' or 'polar'")

    def kite_cd(self, cl):
        """Kite drag coefficient [-] at lift coefficient ``cl``."""
        cl = np.asarray(cl, dtype=float)
        return cl / self.kite_glide if self.drag == "glide" else self.cd0 + self.cd2 * cl * cl


@dataclass(frozen=True)
class Design:
    """Design variables of eqs. 16-20 (SI units): altitude, cable angle from the vertical, cable diameter, kite
    area."""

    h: float
    theta: float
    d: float
    S: float

    @property
    def length(self) -> float:
        return float(cable_length(self.h, self.theta))

    def cable_mass(self, params: PumpingParams) -> float:
        """[kg] cable mass m_c of eq. 20 (solid Dyneema, ``params.cable_density``)."""
        return params.cable_density * np.pi * self.d**2 / 4.0 * self.length


@dataclass(frozen=True)
class StateSolution:
    """The best operation of one design over the wind states (arrays (n,)) and its means."""

    wind: np.ndarray        # [m/s] wind at the kite
    cl: np.ndarray          # [-] lift coefficient per state
    tension: np.ndarray     # [N] reel-out tension
    power: np.ndarray       # [W] useful power (eq. 14)
    mean_power: float       # [W] sum p_i P_i
    mean_tension: float     # [N] sum p_i T_i
    max_mean_power: float   # [W] with every state at its largest tension
    ratio: float            # mean power per cost (the larger the better; -J)
    f_max: float            # [N] eq. 15


def tension_table(case: SiteCase, design: Design, n: int = 1201):
    """(C_L grid, g(C_L)) with T = 1/2 rho S w_e^2 g: g increasing in C_L (checked)."""
    share = cable_drag_share(design.d, design.length, design.S, case.params.cable_cd)
    cl = np.linspace(0.0, case.cl_max, n)
    cdt = case.kite_cd(cl) + share
    if np.any(cdt <= 0):
        raise ValueError(f"{case.name}: system drag must be > 0 (C_D(0) = {case.kite_cd(0.0)}, no cable drag)")
    g = (cl * cl + cdt * cdt) ** 1.5 / (cdt * cdt)
    if np.any(np.diff(g) <= 0):
        raise ValueError(f"{case.name}: tension not increasing in C_L up to {case.cl_max} for this polar")
    return cl, g


def best_fill(p, k, t_lo, t_hi, target, c0, mode):
    """Tensions maximising sum(p k T) / (sum(p T) + c0) over t_lo <= T <= t_hi with sum(p k T) = target ('equal')
    or >= target ('at_least'). Greedy in decreasing k; returns T (n,)."""
    order = np.argsort(-k, kind="stable")
    dp = (p * k * (t_hi - t_lo))[order]                    # power each state can add
    dt = (p * (t_hi - t_lo))[order]                        # tension it adds
    P0, T0 = float(np.sum(p * k * t_lo)), float(np.sum(p * t_lo))
    cum_p, cum_t = np.cumsum(dp), np.cumsum(dt)
    need = target - P0
    T = t_lo.copy()
    if need <= 0:                                          # the least tension already gives P_d
        j, frac = -1, 0.0
    elif need >= cum_p[-1]:                                # P_d out of reach: every state at its largest tension
        return t_hi.copy()
    else:
        j = int(np.searchsorted(cum_p, need))              # the state that reaches P_d, partly
        before = cum_p[j - 1] if j > 0 else 0.0
        frac = (need - before) / dp[j] if dp[j] > 0 else 0.0
    if mode == "at_least":                                 # go on while a whole state raises the ratio
        p_at = P0 + (cum_p[j - 1] if j > 0 else 0.0) + frac * (dp[j] if j >= 0 else 0.0)
        t_at = T0 + (cum_t[j - 1] if j > 0 else 0.0) + frac * (dt[j] if j >= 0 else 0.0)
        ratios = (P0 + cum_p) / (T0 + cum_t + c0)
        ratios[: max(j, 0)] = -np.inf                      # prefixes below P_d are not allowed
        best = int(np.argmax(ratios))
        if ratios[best] > p_at / (t_at + c0):
            j, frac = best + 1, 0.0
    full = order[: max(j, 0)]
    T[full] = t_hi[full]
    if 0 <= j < order.size and frac > 0:
        T[order[j]] = t_lo[order[j]] + frac * (t_hi[order[j]] - t_lo[order[j]])
    return T


def solve_states(case: SiteCase, design: Design, wind: np.ndarray, weight: np.ndarray) -> StateSolution:
    """Best C_L per state for one design: wind [m/s] at the kite (n,), time shares p (n,)."""
    par = case.params
    cl_tab, g_tab = tension_table(case, design)
    v_out = case.reel_out_factor * wind
    w_e = np.maximum(wind * np.sin(design.theta) - v_out, 0.0)
    c = 0.5 * par.rho * design.S * w_e * w_e
    k = speed_per_tension(v_out, par)
    f_max = float(max_cable_force(design.d, par))
    t_lo = c * g_tab[0]
    t_hi = np.minimum(c * g_tab[-1], f_max)
    parked = t_lo > f_max                                  # even C_L = 0 overloads the cable: the kite is landed
    t_lo, t_hi = np.where(parked, 0.0, t_lo), np.where(parked, 0.0, t_hi)
    c0 = case.k1 * design.S if case.cost == "eq16" else 0.0
    T = best_fill(weight, k, t_lo, t_hi, case.power_target, c0, case.power_mode)
    with np.errstate(divide="ignore", invalid="ignore"):
        cl = np.where(c > 0, np.interp(T / np.where(c > 0, c, 1.0), g_tab, cl_tab), 0.0)
    P = k * T
    mean_p, mean_t = float(np.sum(weight * P)), float(np.sum(weight * T))
    if case.cost == "eq16":
        ratio = mean_p / (mean_t + c0) if mean_t + c0 > 0 else 0.0
    else:  # [W / (N m^2 m kg)]: only ratios between designs matter
        cost = mean_t * design.S * design.d * design.cable_mass(par)
        ratio = mean_p / cost if cost > 0 else 0.0
    return StateSolution(wind, np.where(parked, 0.0, cl), T, P, mean_p, mean_t, float(np.sum(weight * k * t_hi)),
                         ratio, f_max)
