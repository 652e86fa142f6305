"""Root finding on the rotor: autorotation angles, the collective that puts the retreating blade tip at
its incidence limit, the best power within the limit, and the solidity for a given autorotation angle.
Brackets are found by a scan and refined by scipy's ``brentq``; an unbracketed root raises
:class:`~laddermill_gym.rotorcraft.rotor_params.RotorSolveError`."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.rotorcraft import rotor_kernels as _k
from laddermill_gym.rotorcraft.rotor_aero import RotorState, state_from_kernel
from laddermill_gym.rotorcraft.rotor_params import (
    BLADE_INCIDENCE_LIMIT,
    INFLOW_MAX_ITER,
    INFLOW_TOL,
    RotorParams,
    RotorSolveError,
    check_alpha,
    check_limit,
    check_mu,
    check_number,
    check_params,
    check_theta,
)

# search ranges of the root finders [rad]
_THETA_RANGE = (math.radians(-60.0), math.radians(40.0))
_ALPHA_RANGE = (math.radians(0.2), math.radians(89.0))
_N_SCAN = 177  # grid points of the bracket scans (0.5 deg over the incidence range)


def _scan_root(fun, lo: float, hi: float, n: int, rising: bool | None = None) -> tuple[float, float] | None:
    """First sub-interval of a uniform n-point grid on [lo, hi] where fun changes sign (nan points skipped).

    rising = True only accepts a change from negative to positive, False only positive to negative.
    """
    xs = np.linspace(lo, hi, n)
    prev_x, prev_f = None, None
    for x in xs:
        f = fun(x)
        if not math.isfinite(f):
            prev_x, prev_f = None, None
            continue
        if prev_f is not None and (prev_f > 0.0) != (f > 0.0):
            if rising is None or rising == (f > 0.0):
                return prev_x, x
        prev_x, prev_f = x, f
    return None


def autorotation_angle(params: RotorParams, mu: float, theta0: float) -> float:
    """Smallest craft incidence alpha_c [rad] at which the rotor autorotates (C_Q = 0) at fixed collective.

    Below it the shaft must be driven (C_Q > 0), above it the rotor generates power. The incidence range
    0.2..89 deg is scanned in 0.5 deg steps for the first change of C_Q from + to -, then refined by Brent's
    method to 1e-12 rad. Raises RotorSolveError when there is none.
    """
    from scipy.optimize import brentq
    p = check_params(params).packed()
    mu, theta0 = check_mu(mu), check_theta(theta0)
    out = np.empty(_k.N_OUT)

    def cq(alpha):
        _k.rotor_state(p, mu, alpha, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
        return out[_k.O_CQ]

    bracket = _scan_root(cq, *_ALPHA_RANGE, _N_SCAN, rising=False)
    if bracket is None:
        raise RotorSolveError(f"no autorotation (C_Q = 0) for mu = {mu}, theta0 = {theta0} rad, {params}")
    return brentq(cq, *bracket, xtol=1e-12, rtol=1e-12)


def collective_at_limit(params: RotorParams, mu: float, alpha_c: float,
                        limit: float = BLADE_INCIDENCE_LIMIT) -> float:
    """Collective theta0 [rad] that puts the retreating blade tip at the incidence limit [rad].

    Solves tip_aoa(theta0) = limit over theta0 in [-60, 40] deg by a scan and Brent's method: the first
    collective from below at which the tip reaches the limit (tip_aoa rises with theta0, except in near-axial
    flow past momentum theory's fold, where it falls back when the light branch of the inflow ends). Raises
    RotorSolveError when the limit cannot be reached in that range.
    """
    p = check_params(params).packed()
    mu, alpha_c, limit = check_mu(mu), check_alpha(alpha_c), check_limit(limit)
    return _collective_at_limit(p, mu, alpha_c, limit, np.empty(_k.N_OUT))


def _collective_at_limit(p, mu, alpha_c, limit, out) -> float:
    from scipy.optimize import brentq
    def excess(theta0):
        _k.rotor_state(p, mu, alpha_c, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
        return out[_k.O_TIP_AOA] - limit

    lo, hi = _THETA_RANGE
    f_lo, f_hi = excess(lo), excess(hi)
    if math.isfinite(f_lo) and math.isfinite(f_hi) and f_lo < 0.0 < f_hi:
        bracket = (lo, hi)
    else:
        bracket = _scan_root(excess, lo, hi, 101, rising=True)
    if bracket is None:
        raise RotorSolveError(f"blade-incidence limit {limit} rad not reached for theta0 in {_THETA_RANGE} rad "
                              f"at mu = {mu}, alpha_c = {alpha_c} rad")
    root = brentq(excess, *bracket, xtol=1e-13, rtol=1e-13)
    # near-axial flow (mu of a few hundredths) past momentum theory's fold: the tip incidence is not monotone in
    # theta0 and the whole range's bracket may hold a later crossing; the limit is the first one (a review of
    # 2026-12-07: 13.3 deg on the reversed-flow branch where 7 deg is the light branch's crossing)
    earlier = _scan_root(excess, lo, root - 1e-9 * (1.0 + abs(root)), 101, rising=True)
    return root if earlier is None else brentq(excess, *earlier, xtol=1e-13, rtol=1e-13)


def max_power_at_limit(params: RotorParams, mu: float, alpha_c: float,
                       limit: float = BLADE_INCIDENCE_LIMIT) -> RotorState:
    """Rotor state at the blade-incidence limit: the collective of :func:`collective_at_limit` and its C_p.

    This is how every point of Roberts' Fig. 3 is built ("all points on the U-shaped curves have been
    constructed at a blade incidence limit of 13 deg"). ``state.theta0`` is the collective, ``state.cp`` the
    power coefficient. Near the peak and on the right branch of a curve this is also the largest power
    within the limit; on the left branch (low incidence) a lower collective gives more power, see
    :func:`best_power_within_limit`.
    """
    p = check_params(params).packed()
    mu, alpha_c, limit = check_mu(mu), check_alpha(alpha_c), check_limit(limit)
    out = np.empty(_k.N_OUT)
    theta0 = _collective_at_limit(p, mu, alpha_c, limit, out)
    return state_from_kernel(p, mu, alpha_c, theta0, out)


def best_power_within_limit(params: RotorParams, mu: float, alpha_c: float,
                            limit: float = BLADE_INCIDENCE_LIMIT, span: float = math.radians(30.0)) -> RotorState:
    """Largest C_p over the collectives that keep the retreating tip within the limit [rad].

    The tip incidence rises with collective, so the admissible collectives are theta0 <= theta_limit
    (:func:`collective_at_limit`). C_p is sampled at 31 collectives on [theta_limit - span, theta_limit]
    and the best interior sample refined by bounded Brent minimisation (1e-10 rad); the state at the limit
    is returned when the limit itself is best.
    """
    from scipy.optimize import minimize_scalar
    p = check_params(params).packed()
    mu, alpha_c, limit = check_mu(mu), check_alpha(alpha_c), check_limit(limit)
    span = check_number("span", span, 0.0, math.pi / 2, lo_open=True)
    out = np.empty(_k.N_OUT)
    theta_lim = _collective_at_limit(p, mu, alpha_c, limit, out)
    grid = np.linspace(max(theta_lim - span, _THETA_RANGE[0]), theta_lim, 31)

    def neg_cp(theta0):
        _k.rotor_state(p, mu, alpha_c, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
        cp = out[_k.O_CP]
        return -cp if math.isfinite(cp) else math.inf

    values = np.array([neg_cp(t) for t in grid])
    i = int(np.argmin(values))
    if i == grid.size - 1:
        return state_from_kernel(p, mu, alpha_c, theta_lim, out)
    res = minimize_scalar(neg_cp, bounds=(grid[max(i - 1, 0)], grid[i + 1]), method="bounded",
                          options={"xatol": 1e-10})
    theta_best = float(res.x) if res.fun <= values[i] else float(grid[i])
    return state_from_kernel(p, mu, alpha_c, theta_best, out)


def min_autorotation_angle(params: RotorParams, mu: float,
                           theta_range: tuple[float, float] = (math.radians(-4.0), math.radians(12.0))
                           ) -> tuple[float, float]:
    """Lowest incidence [rad] at which the rotor can autorotate at some collective, and that collective [rad].

    Minimises :func:`autorotation_angle` over theta0 in theta_range (a 17-point scan, then bounded Brent,
    1e-9 rad): the least incidence at which the craft stays up without power from the ground.
    """
    from scipy.optimize import minimize_scalar
    check_params(params)
    mu = check_mu(mu)
    if not (isinstance(theta_range, (tuple, list, np.ndarray)) and len(theta_range) == 2):
        raise ValueError(f"argument 'theta_range' = {theta_range!r}: must be a pair (lowest, highest collective) [rad]")
    lo, hi = (check_number("theta_range", t, -0.5 * math.pi, 0.5 * math.pi, lo_open=True, hi_open=True)
              for t in theta_range)
    if not lo < hi:
        raise ValueError(f"argument 'theta_range' = {tuple(theta_range)!r}: its lower collective must be below its "
                         "upper one [rad]")

    def angle(theta0):
        try:
            return autorotation_angle(params, mu, theta0)
        except RotorSolveError:
            return math.inf

    grid = np.linspace(lo, hi, 17)
    values = np.array([angle(t) for t in grid])
    i = int(np.argmin(values))
    if not math.isfinite(values[i]):
        raise RotorSolveError(f"no autorotation for theta0 in {theta_range} rad at mu = {mu}, {params}")
    res = minimize_scalar(angle, bounds=(grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]),
                          method="bounded", options={"xatol": 1e-9})
    if res.fun <= values[i]:
        return float(res.fun), float(res.x)
    return float(values[i]), float(grid[i])


def _cp_at_limit(p, mu, alpha_c, limit, out) -> float:
    try:
        theta0 = _collective_at_limit(p, mu, alpha_c, limit, out)
    except RotorSolveError:
        return math.nan
    _k.rotor_state(p, mu, alpha_c, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
    return out[_k.O_CP]


def autorotation_angle_at_limit(params: RotorParams, mu: float, limit: float = BLADE_INCIDENCE_LIMIT) -> float:
    """Incidence alpha_c [rad] where the left branch of a Fig. 3 curve (blade at the limit) crosses C_p = 0.

    Roberts, section 5: "C_p = 0 at alpha_c = 22.5 deg when mu = 0.1". The first change of C_p from - to +
    on a 0.5 deg scan of 0.2..89 deg, refined by Brent's method to 1e-10 rad.
    """
    from scipy.optimize import brentq
    p = check_params(params).packed()
    mu, limit = check_mu(mu), check_limit(limit)
    out = np.empty(_k.N_OUT)

    def cp(alpha):
        return _cp_at_limit(p, mu, alpha, limit, out)

    bracket = _scan_root(cp, *_ALPHA_RANGE, _N_SCAN, rising=True)
    if bracket is None:
        raise RotorSolveError(f"C_p at the blade limit does not cross zero for mu = {mu}, {params}")
    return brentq(cp, *bracket, xtol=1e-10, rtol=1e-10)


def solidity_for_autorotation(params: RotorParams, mu: float, alpha_c: float,
                              limit: float = BLADE_INCIDENCE_LIMIT,
                              sigma_range: tuple[float, float] = (0.01, 0.3)) -> float:
    """Solidity sigma [-] that puts :func:`autorotation_angle_at_limit` at alpha_c [rad] (other blade data
    from params). Brent's method on sigma_range; raises RotorSolveError when alpha_c is not bracketed."""
    from scipy.optimize import brentq
    check_params(params)
    mu, alpha_c, limit = check_mu(mu), check_alpha(alpha_c), check_limit(limit)

    def miss(sigma):
        return autorotation_angle_at_limit(params.with_solidity(sigma), mu, limit) - alpha_c

    lo, hi = sigma_range
    f_lo, f_hi = miss(lo), miss(hi)
    if (f_lo > 0.0) == (f_hi > 0.0):
        raise RotorSolveError(f"autorotation at {alpha_c} rad is not bracketed by sigma in {sigma_range} "
                              f"(misses {f_lo:.4g}, {f_hi:.4g} rad)")
    return brentq(miss, lo, hi, xtol=1e-8, rtol=1e-10)
