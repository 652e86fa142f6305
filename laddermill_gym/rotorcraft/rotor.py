"""Rotor aerodynamics of Roberts' tethered twin-rotor craft: the Python layer over ``kernels/rotor.py``.

Gessow & Myers' closed forms for an untwisted, centrally hinged rotor with uniform (Glauert) inflow, as
Roberts uses them for his power-coefficient chart (his Fig. 3). All angles are in radians and all
coefficients non-dimensional (helicopter convention: velocities over the tip speed Omega R, forces over
rho pi R^2 (Omega R)^2). Formulas, sources and choices: ``laddermill_gym/docs/rotor.md``.

The functions here validate their inputs (``ValueError`` naming the argument and its value), pack the
parameters and call the numba kernels; root finding over collective or incidence uses scipy's ``brentq`` on
brackets found by a scan. A failed inflow solution is reported through :attr:`RotorState.converged`; a root
that cannot be bracketed raises :class:`RotorSolveError`.

Examples
--------
>>> import math
>>> from laddermill_gym.rotorcraft.rotor import RotorParams, autorotation_angle
>>> p = RotorParams(sigma=0.05, a=5.73, delta=0.01, B=0.97, gamma=8.0)
>>> round(math.degrees(autorotation_angle(p, mu=0.1, theta0=0.0)), 1)  # oracles.md: 21.7 deg
21.7
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from laddermill_gym.model.configio import CONFIG_DIR, read_yaml
from laddermill_gym.rotorcraft import rotor_kernels as _k

__all__ = [
    "BLADE_INCIDENCE_LIMIT",
    "DEFAULT_ROTOR_CONFIG",
    "RotorParams",
    "RotorConfig",
    "RotorState",
    "InflowSolution",
    "RotorSolveError",
    "load_rotor_config",
    "solve_inflow",
    "rotor_coefficients",
    "power_coefficient",
    "craft_incidence",
    "cable_angle",
    "ideal_power_coefficient",
    "autorotation_angle",
    "collective_at_limit",
    "max_power_at_limit",
    "best_power_within_limit",
    "min_autorotation_angle",
    "autorotation_angle_at_limit",
    "solidity_for_autorotation",
]

#: Folder of the rotor YAML files and the default rotor (Roberts' craft).
ROTOR_CONFIG_DIR = CONFIG_DIR / "rotors"
DEFAULT_ROTOR_CONFIG = ROTOR_CONFIG_DIR / "roberts_rotor.yaml"

#: Blade-incidence limit of Roberts' Fig. 3 (section 4: "a blade incidence limit of 13 deg") [rad].
BLADE_INCIDENCE_LIMIT = math.radians(13.0)

#: Tolerance and iteration cap of the inflow solver (see kernels.rotor.solve_inflow).
INFLOW_TOL = 1e-13
INFLOW_MAX_ITER = 300

# search ranges of the root finders [rad]
_THETA_RANGE = (math.radians(-60.0), math.radians(40.0))
_ALPHA_RANGE = (math.radians(0.2), math.radians(89.0))
_N_SCAN = 177  # grid points of the bracket scans (0.5 deg over the incidence range)


class RotorSolveError(RuntimeError):
    """A root (autorotation angle, collective at the limit, solidity) could not be bracketed or solved."""


# ------------------------------------------------------------------------------------------- parameters
def _field_problem(name: str, value: float) -> str | None:
    """Why ``value`` is not valid for the RotorParams field ``name`` (None when it is)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        return "must be a number"
    v = float(value)
    if not math.isfinite(v):
        return "must be finite"
    if name == "sigma" and not 0.0 < v < 1.0:
        return "solidity must lie in (0, 1)"
    if name == "a" and not v > 0.0:
        return "lift-curve slope must be > 0"
    if name == "delta" and not v >= 0.0:
        return "profile-drag coefficient must be >= 0"
    if name == "B" and not 0.0 < v <= 1.0:
        return "tip-loss factor must lie in (0, 1]"
    if name == "gamma" and not v > 0.0:
        return "Lock number must be > 0"
    return None


@dataclass(frozen=True)
class RotorParams:
    """Blade and rotor constants of an untwisted rotor (Gessow & Myers' notation, as in Roberts eq. 1).

    Attributes
    ----------
    sigma : float
        Solidity b c / (pi R) [-]: blade area over disk area (b blades of chord c, radius R); in (0, 1).
    a : float
        Blade-section lift-curve slope [1/rad]; 5.73 is Gessow & Myers' usual value.
    delta : float
        Mean blade-section profile-drag coefficient [-] (constant over the disk); 0 is the ideal rotor.
    B : float
        Tip-loss factor [-]: the blade lifts only out to r = B R; in (0, 1].
    gamma : float
        Lock number rho a c R^4 / I_b [-] (aerodynamic over inertial flapping moment); sets the coning.

    Raises
    ------
    ValueError
        On a non-finite or out-of-range field; the message names the field and the value.
    """

    sigma: float
    a: float = 5.73
    delta: float = 0.01
    B: float = 0.97
    gamma: float = 8.0

    def __post_init__(self) -> None:
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            why = _field_problem(f.name, value)
            if why is not None:
                raise ValueError(f"RotorParams: field '{f.name}' = {value!r}: {why}")
            object.__setattr__(self, f.name, float(value))

    def packed(self) -> np.ndarray:
        """The kernels' packed parameter array, float64[N_PARAMS] (kernels.rotor.P_* order)."""
        p = np.empty(_k.N_PARAMS)
        p[_k.P_SIGMA], p[_k.P_A], p[_k.P_DELTA], p[_k.P_B], p[_k.P_GAMMA] = (
            self.sigma, self.a, self.delta, self.B, self.gamma)
        return p

    def ideal(self) -> RotorParams:
        """The same rotor without profile drag (delta = 0)."""
        return dataclasses.replace(self, delta=0.0)

    def with_solidity(self, sigma: float) -> RotorParams:
        """The same blades at another solidity [-]."""
        return dataclasses.replace(self, sigma=sigma)


@dataclass(frozen=True)
class RotorConfig:
    """A rotor read from ``configs/rotors/*.yaml``: its parameters and the blade-incidence limit [rad]."""

    name: str
    params: RotorParams
    blade_incidence_limit: float


def load_rotor_config(path: Path | str) -> RotorConfig:
    """Read a rotor YAML file strictly (unknown keys and invalid values raise ConfigError naming the field).

    Expected fields: ``name``, ``sigma`` [-], ``lift_slope`` [1/rad], ``profile_drag`` [-], ``tip_loss`` [-],
    ``lock_number`` [-], ``blade_incidence_limit_deg`` [deg].
    """
    s = read_yaml(path)
    name = s.text("name")
    values = {}
    for field, key in (("sigma", "sigma"), ("a", "lift_slope"), ("delta", "profile_drag"), ("B", "tip_loss"),
                       ("gamma", "lock_number")):
        v = s.number(key)
        why = _field_problem(field, v)
        if why is not None:
            raise s.error(key, v, why)
        values[field] = v
    limit_deg = s.number("blade_incidence_limit_deg", positive=True)
    if not limit_deg < 90.0:
        raise s.error("blade_incidence_limit_deg", limit_deg, "must be < 90")
    s.done()
    return RotorConfig(name=name, params=RotorParams(**values), blade_incidence_limit=math.radians(limit_deg))


# ------------------------------------------------------------------------------------------- validation
def _check_number(name: str, value, lo: float = -math.inf, hi: float = math.inf, *, lo_open: bool = False,
                  hi_open: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"argument '{name}' = {value!r}: must be a number")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"argument '{name}' = {value!r}: must be finite")
    if (v < lo or (lo_open and v == lo)) or (v > hi or (hi_open and v == hi)):
        lb = "(" if lo_open else "["
        rb = ")" if hi_open else "]"
        raise ValueError(f"argument '{name}' = {value!r}: must lie in {lb}{lo}, {hi}{rb}")
    return v


def _check_params(params) -> RotorParams:
    if not isinstance(params, RotorParams):
        raise ValueError(f"argument 'params' = {params!r}: must be a RotorParams")
    return params


def _check_mu(mu) -> float:
    return _check_number("mu", mu, 0.0, 1.0, lo_open=True, hi_open=True)


def _check_alpha(alpha_c) -> float:
    return _check_number("alpha_c", alpha_c, -0.5 * math.pi, 0.5 * math.pi, lo_open=True, hi_open=True)


def _check_theta(theta0) -> float:
    return _check_number("theta0", theta0, -0.5 * math.pi, 0.5 * math.pi, lo_open=True, hi_open=True)


def _check_limit(limit) -> float:
    return _check_number("limit", limit, 0.0, 0.5 * math.pi, lo_open=True, hi_open=True)


# ------------------------------------------------------------------------------------------- results
@dataclass(frozen=True)
class InflowSolution:
    """Glauert inflow consistent with C_T (kernels.rotor.solve_inflow).

    Attributes: lam (inflow ratio, > 0 up through the disk) [-], nu (induced-velocity ratio) [-], ct [-],
    iterations (residual evaluations), status (kernels.rotor.STATUS_*), converged (status == STATUS_OK).
    """

    lam: float
    nu: float
    ct: float
    iterations: int
    status: int

    @property
    def converged(self) -> bool:
        return self.status == _k.STATUS_OK


@dataclass(frozen=True)
class RotorState:
    """Rotor at (mu, alpha_c, theta0) with its consistent inflow (kernels.rotor.rotor_state).

    Attributes
    ----------
    mu, alpha_c, theta0 : float
        Advance ratio [-], craft incidence [rad], collective pitch [rad] (the inputs).
    lam, nu : float
        Inflow ratio (up through the disk > 0) and induced-velocity ratio [-].
    ct, ch, cq : float
        Thrust, H-force and torque coefficients [-] (C_Q < 0: power generated).
    a0, a1, b1 : float
        Coning, longitudinal and lateral flapping [rad].
    tip_aoa : float
        Angle of attack of the retreating blade tip (x = 1, psi = 270 deg) [rad].
    cp : float
        Windmill power coefficient P / (rho pi R^2 V^3 / 2) [-] (Roberts eq. 4).
    iterations, status : int
        Inflow-solver evaluations and status; every coefficient is nan unless ``converged``.
    """

    mu: float
    alpha_c: float
    theta0: float
    lam: float
    nu: float
    ct: float
    ch: float
    cq: float
    a0: float
    a1: float
    b1: float
    tip_aoa: float
    cp: float
    iterations: int
    status: int

    @property
    def converged(self) -> bool:
        return self.status == _k.STATUS_OK


def _state(p: np.ndarray, mu: float, alpha_c: float, theta0: float, out: np.ndarray) -> RotorState:
    _k.rotor_state(p, mu, alpha_c, theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
    v = [float(x) for x in out]
    return RotorState(mu=mu, alpha_c=alpha_c, theta0=theta0, lam=v[_k.O_LAMBDA], nu=v[_k.O_NU], ct=v[_k.O_CT],
                      ch=v[_k.O_CH], cq=v[_k.O_CQ], a0=v[_k.O_A0], a1=v[_k.O_A1], b1=v[_k.O_B1],
                      tip_aoa=v[_k.O_TIP_AOA], cp=v[_k.O_CP], iterations=int(v[_k.O_ITER]),
                      status=int(v[_k.O_STATUS]))


# ------------------------------------------------------------------------------------------- public API
def solve_inflow(params: RotorParams, mu: float, alpha_c: float, theta0: float) -> InflowSolution:
    """Inflow ratio lam = mu tan(alpha_c) - nu with Glauert's nu = C_T / (2 sqrt(mu^2 + lam^2)).

    Parameters
    ----------
    params : RotorParams
    mu : float
        Advance ratio V cos(alpha_c) / (Omega R) [-], in (0, 1).
    alpha_c : float
        Craft (disk) incidence to the wind [rad], in (-pi/2, pi/2).
    theta0 : float
        Collective pitch [rad].
    """
    p = _check_params(params).packed()
    mu, alpha_c, theta0 = _check_mu(mu), _check_alpha(alpha_c), _check_theta(theta0)
    out = np.empty(_k.N_OUT)
    _k.solve_inflow(p, mu, mu * math.tan(alpha_c), theta0, INFLOW_TOL, INFLOW_MAX_ITER, out)
    return InflowSolution(lam=float(out[_k.O_LAMBDA]), nu=float(out[_k.O_NU]), ct=float(out[_k.O_CT]),
                          iterations=int(out[_k.O_ITER]), status=int(out[_k.O_STATUS]))


def rotor_coefficients(params: RotorParams, mu: float, alpha_c: float, theta0: float) -> RotorState:
    """All rotor coefficients at advance ratio mu [-], incidence alpha_c [rad] and collective theta0 [rad].

    See :class:`RotorState`. Check ``converged`` before using the numbers.
    """
    p = _check_params(params).packed()
    mu, alpha_c, theta0 = _check_mu(mu), _check_alpha(alpha_c), _check_theta(theta0)
    return _state(p, mu, alpha_c, theta0, np.empty(_k.N_OUT))


def power_coefficient(cq: float, mu: float, alpha_c: float) -> float:
    """Roberts eq. 4 from the torque coefficient: C_p = -2 C_Q (cos(alpha_c)/mu)^3 [-]."""
    return _k.power_coefficient(_check_number("cq", cq), _check_mu(mu), _check_alpha(alpha_c))


def craft_incidence(mu: float, lam: float, ct: float) -> float:
    """Roberts eq. 2: alpha_c = atan(lam/mu + C_T / (2 mu sqrt(mu^2 + lam^2))) [rad]."""
    return _k.craft_incidence(_check_mu(mu), _check_number("lam", lam), _check_number("ct", ct))


def cable_angle(thrust: float, h_force: float, weight: float, alpha_c: float, n_rotors: int = 2) -> float:
    """Roberts eq. 3: equilibrium angle [rad] of the (massless) cables above the horizontal.

    Parameters
    ----------
    thrust, h_force : float
        Thrust and H-force of ONE rotor [N].
    weight : float
        Craft weight m g [N], > 0.
    alpha_c : float
        Craft incidence [rad].
    n_rotors : int
        Number of rotors (2 for Roberts' craft, whose eq. 3 reads 2T/mg and 2H/mg).
    """
    weight = _check_number("weight", weight, 0.0, lo_open=True)
    if isinstance(n_rotors, bool) or not isinstance(n_rotors, (int, np.integer)) or n_rotors < 1:
        raise ValueError(f"argument 'n_rotors' = {n_rotors!r}: must be an integer >= 1")
    t = _check_number("thrust", thrust) * n_rotors / weight
    h = _check_number("h_force", h_force) * n_rotors / weight
    return _k.cable_angle(t, h, _check_alpha(alpha_c))


def ideal_power_coefficient(alpha_c):
    """Ideal power coefficient [-] at incidence alpha_c [rad] (scalar or array; any shape).

    Actuator disk with Glauert inflow and no profile drag, best induced velocity: 16/27 at alpha_c = pi/2,
    0 at alpha_c = 0 (kernels.rotor.ideal_power_coefficient).
    """
    arr = np.asarray(alpha_c, dtype=float)
    if not np.all(np.isfinite(arr)) or np.any(np.abs(arr) > 0.5 * math.pi + 1e-12):
        raise ValueError(f"argument 'alpha_c' = {alpha_c!r}: must be finite and within [-pi/2, pi/2]")
    flat = arr.ravel()
    res = np.array([_k.ideal_power_coefficient(float(x)) for x in flat]).reshape(arr.shape)
    return float(res) if res.ndim == 0 else res


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
    p = _check_params(params).packed()
    mu, theta0 = _check_mu(mu), _check_theta(theta0)
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

    Solves tip_aoa(theta0) = limit (tip_aoa rises with theta0) over theta0 in [-60, 40] deg by a scan and
    Brent's method. Raises RotorSolveError when the limit cannot be reached in that range.
    """
    p = _check_params(params).packed()
    mu, alpha_c, limit = _check_mu(mu), _check_alpha(alpha_c), _check_limit(limit)
    return _collective_at_limit(p, mu, alpha_c, limit, np.empty(_k.N_OUT))


def _collective_at_limit(p, mu, alpha_c, limit, out) -> float:
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
    return brentq(excess, *bracket, xtol=1e-13, rtol=1e-13)


def max_power_at_limit(params: RotorParams, mu: float, alpha_c: float,
                       limit: float = BLADE_INCIDENCE_LIMIT) -> RotorState:
    """Rotor state at the blade-incidence limit: the collective of :func:`collective_at_limit` and its C_p.

    This is how every point of Roberts' Fig. 3 is built ("all points on the U-shaped curves have been
    constructed at a blade incidence limit of 13 deg"). ``state.theta0`` is the collective, ``state.cp`` the
    power coefficient. Near the peak and on the right branch of a curve this is also the largest power
    within the limit; on the left branch (low incidence) a lower collective gives more power, see
    :func:`best_power_within_limit`.
    """
    p = _check_params(params).packed()
    mu, alpha_c, limit = _check_mu(mu), _check_alpha(alpha_c), _check_limit(limit)
    out = np.empty(_k.N_OUT)
    theta0 = _collective_at_limit(p, mu, alpha_c, limit, out)
    return _state(p, mu, alpha_c, theta0, out)


def best_power_within_limit(params: RotorParams, mu: float, alpha_c: float,
                            limit: float = BLADE_INCIDENCE_LIMIT, span: float = math.radians(30.0)) -> RotorState:
    """Largest C_p over the collectives that keep the retreating tip within the limit [rad].

    The tip incidence rises with collective, so the admissible collectives are theta0 <= theta_limit
    (:func:`collective_at_limit`). C_p is sampled at 31 collectives on [theta_limit - span, theta_limit]
    and the best interior sample refined by bounded Brent minimisation (1e-10 rad); the state at the limit
    is returned when the limit itself is best.
    """
    p = _check_params(params).packed()
    mu, alpha_c, limit = _check_mu(mu), _check_alpha(alpha_c), _check_limit(limit)
    span = _check_number("span", span, 0.0, math.pi / 2, lo_open=True)
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
        return _state(p, mu, alpha_c, theta_lim, out)
    res = minimize_scalar(neg_cp, bounds=(grid[max(i - 1, 0)], grid[i + 1]), method="bounded",
                          options={"xatol": 1e-10})
    theta_best = float(res.x) if res.fun <= values[i] else float(grid[i])
    return _state(p, mu, alpha_c, theta_best, out)


def min_autorotation_angle(params: RotorParams, mu: float,
                           theta_range: tuple[float, float] = (math.radians(-4.0), math.radians(12.0))
                           ) -> tuple[float, float]:
    """Lowest incidence [rad] at which the rotor can autorotate at some collective, and that collective [rad].

    Minimises :func:`autorotation_angle` over theta0 in theta_range (a 17-point scan, then bounded Brent,
    1e-9 rad): the least incidence at which the craft stays up without power from the ground.
    """
    _check_params(params)
    mu = _check_mu(mu)
    lo, hi = (_check_theta(t) for t in theta_range)

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
    p = _check_params(params).packed()
    mu, limit = _check_mu(mu), _check_limit(limit)
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
    _check_params(params)
    mu, alpha_c, limit = _check_mu(mu), _check_alpha(alpha_c), _check_limit(limit)

    def miss(sigma):
        return autorotation_angle_at_limit(params.with_solidity(sigma), mu, limit) - alpha_c

    lo, hi = sigma_range
    f_lo, f_hi = miss(lo), miss(hi)
    if (f_lo > 0.0) == (f_hi > 0.0):
        raise RotorSolveError(f"autorotation at {alpha_c} rad is not bracketed by sigma in {sigma_range} "
                              f"(misses {f_lo:.4g}, {f_hi:.4g} rad)")
    return brentq(miss, lo, hi, xtol=1e-8, rtol=1e-10)

