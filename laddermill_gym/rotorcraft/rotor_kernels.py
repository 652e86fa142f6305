"""Rotor aerodynamics of the tethered twin-rotor craft (Roberts; Gessow & Myers), untwisted blades.

Everything here is non-dimensional in the helicopter way: velocities divided by the tip speed Omega R,
forces by rho pi R^2 (Omega R)^2, torque by rho pi R^2 (Omega R)^2 R. Angles are in radians. The formulas,
their sources and the choices made where the paper is silent are in ``laddermill_gym/docs/rotor.md``.

Sign conventions (Gessow & Myers): the inflow ratio ``lam`` > 0 is up-flow through the disk (windmill /
autogyro state); the thrust T acts along the control (shaft) axis, upwards; the H-force lies in the disk
plane and points downwind; the blade flaps as beta(psi) = a0 - a1 cos(psi) - b1 sin(psi), psi measured from
the downwind position in the direction of rotation (advancing blade at psi = 90 deg); C_Q > 0 is torque the
shaft must supply, C_Q < 0 is power generated.

Packed parameters ``p`` (float64[N_PARAMS]): solidity sigma [-], lift-curve slope a [1/rad], profile-drag
coefficient delta [-], tip-loss factor B [-], Lock number gamma [-] (indices P_*). Results of
:func:`rotor_state` go into ``out`` (float64[N_OUT], indices O_*). No kernel allocates, raises or uses
Python objects; a failed inflow solution is reported through ``out[O_STATUS]``.
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    N_OUT,
    N_PARAMS,
    O_A0,
    O_A1,
    O_B1,
    O_CH,
    O_CP,
    O_CQ,
    O_CT,
    O_ITER,
    O_LAMBDA,
    O_NU,
    O_STATUS,
    O_TIP_AOA,
    P_A,
    P_B,
    P_DELTA,
    P_GAMMA,
    P_SIGMA,
    STATUS_MAX_ITER,
    STATUS_NO_BRACKET,
    STATUS_NOT_FINITE,
    STATUS_OK,
)
from laddermill_gym.rotorcraft.ideal_disk import ideal_power_coefficient, ideal_through_flow  # noqa: F401 (the API's)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def thrust_coefficient(sigma, a, tip_loss, mu, lam, theta0):
    """C_T of an untwisted rotor (Roberts eq. 1; Gessow & Myers), about the control axis.

    C_T = (sigma a / 2) [theta0 (B^3/3 + B mu^2/2) + lam B^2/2]. Exact for uniform inflow and small angles
    whatever the flapping (the flapping terms cancel about the axis of no feathering).
    """
    b = tip_loss
    return 0.5 * sigma * a * (theta0 * (b * b * b / 3.0 + 0.5 * b * mu * mu) + 0.5 * lam * b * b)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def coning_angle(gamma, mu, lam, theta0):
    """Coning a0 [rad] of a centrally hinged blade, blade weight neglected (Gessow & Myers, B = 1).

    a0 = (gamma/8) [theta0 (1 + mu^2) + 4 lam / 3].
    """
    return 0.125 * gamma * (theta0 * (1.0 + mu * mu) + 4.0 * lam / 3.0)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def longitudinal_flapping(mu, lam, theta0):
    """Longitudinal flapping a1 [rad] (blade flapped up over the upwind side when positive; B = 1).

    a1 = 2 mu (4 theta0/3 + lam) / (1 - mu^2/2).
    """
    return 2.0 * mu * (4.0 * theta0 / 3.0 + lam) / (1.0 - 0.5 * mu * mu)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def lateral_flapping(mu, a0):
    """Lateral flapping b1 [rad] (B = 1): b1 = (4/3) mu a0 / (1 + mu^2/2)."""
    return 4.0 * mu * a0 / (3.0 * (1.0 + 0.5 * mu * mu))


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def h_force_coefficient(sigma, a, delta, tip_loss, mu, lam, theta0, a0, a1, b1):
    """C_H, the in-plane force along the downwind direction (Gessow & Myers; oracles.md).

    C_H/sigma = delta mu/4 + (a/2)[theta0 (B^3 a1/3 - B lam mu/2) + (3/4) B^2 lam a1 - (B^3/6) a0 b1
    + (B^2 mu/4)(a0^2 + a1^2)].
    """
    b = tip_loss
    b2 = b * b
    b3 = b2 * b
    lift = (theta0 * (b3 * a1 / 3.0 - 0.5 * b * lam * mu) + 0.75 * b2 * lam * a1 - b3 * a0 * b1 / 6.0
            + 0.25 * b2 * mu * (a0 * a0 + a1 * a1))
    return sigma * (0.25 * delta * mu + 0.5 * a * lift)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def torque_coefficient(sigma, delta, mu, lam, ct, ch):
    """C_Q from the energy identity: C_Q = sigma delta (1 + 3 mu^2)/8 - lam C_T - mu C_H.

    C_Q > 0: torque to be supplied (profile losses exceed what the flow delivers); C_Q < 0: power generated.
    """
    return 0.125 * sigma * delta * (1.0 + 3.0 * mu * mu) - lam * ct - mu * ch


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def glauert_inflow(ct, mu, lam):
    """Glauert's induced-velocity ratio nu = C_T / (2 sqrt(mu^2 + lam^2)); inf when mu = lam = 0."""
    r = math.sqrt(mu * mu + lam * lam)
    if r == 0.0:
        return math.inf if ct != 0.0 else 0.0
    return ct / (2.0 * r)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def power_coefficient(cq, mu, alpha_c):
    """Windmill power coefficient C_p = P / (rho pi R^2 V^3 / 2) of one rotor (Roberts eq. 4).

    With P = -Q Omega and Omega R / V = cos(alpha_c) / mu (Roberts eq. 5): C_p = -2 C_Q (cos(alpha_c)/mu)^3.
    """
    k = math.cos(alpha_c) / mu
    return -2.0 * cq * k * k * k


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def craft_incidence(mu, lam, ct):
    """Craft incidence alpha_c [rad] from Roberts eq. 2: tan(alpha_c) = lam/mu + C_T / (2 mu sqrt(mu^2 + lam^2)).

    Written as atan2(lam + nu, mu), i.e. the free-stream inflow V sin(alpha_c)/(Omega R) = lam + nu over the
    advance ratio mu = V cos(alpha_c)/(Omega R).
    """
    return math.atan2(lam + glauert_inflow(ct, mu, lam), mu)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def cable_angle(thrust_ratio, h_ratio, alpha_c):
    """Equilibrium cable angle beta [rad] above the horizontal (Roberts eq. 3), massless cables.

    thrust_ratio = n T/(m g) and h_ratio = n H/(m g): the thrust and H-force of all n rotors (n = 2 for
    Roberts' twin-rotor craft, whose eq. 3 reads 2T/mg, 2H/mg) over the craft's weight. The rotor force
    minus the weight is carried by the cables: vertical part n T cos(alpha_c) - n H sin(alpha_c) - m g,
    downwind part n T sin(alpha_c) + n H cos(alpha_c); beta is the angle of that vector, atan2(vertical,
    downwind) (the paper's arctangent of the ratio, with the quadrant kept).
    """
    ca, sa = math.cos(alpha_c), math.sin(alpha_c)
    return math.atan2(thrust_ratio * ca - h_ratio * sa - 1.0, thrust_ratio * sa + h_ratio * ca)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def section_aoa(theta0, mu, lam, a0, a1, b1, x, psi):
    """Blade-section angle of attack [rad] at radius x = r/R and azimuth psi [rad], small angles.

    alpha = theta0 + U_P/U_T with U_T = x + mu sin(psi) and U_P = lam - x dbeta/dpsi - mu beta cos(psi)
    (Gessow & Myers). Undefined (inf) where U_T = 0, the edge of the reversed-flow circle.
    """
    s, c = math.sin(psi), math.cos(psi)
    beta = a0 - a1 * c - b1 * s
    dbeta = a1 * s - b1 * c
    ut = x + mu * s
    up = lam - x * dbeta - mu * beta * c
    if ut == 0.0:
        return math.inf
    return theta0 + up / ut


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def tip_incidence(theta0, mu, lam, a1):
    """Angle of attack [rad] of the retreating blade tip (x = 1, psi = 270 deg), the blade-incidence check.

    section_aoa at x = 1, psi = 3 pi/2: alpha = theta0 + (lam + a1)/(1 - mu) (coning and b1 drop out).
    """
    return theta0 + (lam + a1) / (1.0 - mu)


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def _inflow_residual(c0, c1, mu, lam_inf, lam):
    """f(lam) = lam - lam_inf + nu(lam) with C_T = c0 + c1 lam, and df/dlam."""
    r2 = mu * mu + lam * lam
    r = math.sqrt(r2)
    if r == 0.0:
        r = 1e-300
        r2 = r * r
    ct = c0 + c1 * lam
    f = lam - lam_inf + ct / (2.0 * r)
    df = 1.0 + c1 / (2.0 * r) - ct * lam / (2.0 * r2 * r)
    return f, df


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def _inflow_turn(c0, c1, mu, lam_inf, x0, x1, f1, direction, n_eval, max_iter):
    """Where |f| of the bracket search grew again at x1 (f1) before f changed sign: bisection on the sign of
    d|f|/ds between x0 and x1 (s along ``direction``) for the smallest |f|. A point there where f has the other sign
    bounds the nearer of two close roots that the growing steps stepped over. Returns (found, x, f, n_eval): found
    with the first such point x (the nearer root in (x0, x)), else the search ends at the turn with f's sign kept."""
    fa, dfa = _inflow_residual(c0, c1, mu, lam_inf, x0)
    n_eval += 1
    if (fa > 0.0) == (direction * dfa > 0.0):  # |f| grows from x0 on: its least on (x0, x1) is at x0, already seen
        return False, x1, f1, n_eval
    lo, hi = x0, x1  # |f| falls at lo, grows at hi
    tol = 1e-14 * (1.0 + abs(x0) + abs(x1))
    while n_eval < max_iter and abs(hi - lo) > tol:
        mid = 0.5 * (lo + hi)
        fm, dfm = _inflow_residual(c0, c1, mu, lam_inf, mid)
        n_eval += 1
        if (fm > 0.0) != (fa > 0.0) or fm == 0.0:
            return True, mid, fm, n_eval
        if (fm > 0.0) == (direction * dfm > 0.0):
            hi = mid
        else:
            lo = mid
    return False, x1, f1, n_eval


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def _inflow_bracket(c0, c1, mu, lam_inf, f0, n_eval, max_iter):
    """Bracket search of :func:`solve_inflow`: from lam_inf (residual f0) in the direction that reduces |f|, steps
    growing by 1.25 until f changes sign. Where |f| grows again before that (momentum theory's heavily loaded
    windmill state, whose two close roots a growing step can pass over), :func:`_inflow_turn` looks between the
    last two points for the nearer root first. Returns (found, x0, f0, x1, f1, n_eval): the last two points and
    their residuals (a sign change between them when found) and the residual evaluations so far."""
    x0 = lam_inf
    direction = -1.0 if f0 > 0.0 else 1.0
    scale = max(abs(lam_inf), mu, 1e-3)
    h = 1e-3 * scale
    x1 = x0
    f1 = f0
    found = False
    while n_eval < max_iter:
        x1 = x0 + direction * h
        f1, df1 = _inflow_residual(c0, c1, mu, lam_inf, x1)
        n_eval += 1
        if not math.isfinite(f1):
            break
        if (f1 > 0.0) != (f0 > 0.0) or f1 == 0.0:
            found = True
            break
        if (f1 > 0.0) == (direction * df1 > 0.0):  # |f| turned: a root pair may lie between x0 and x1
            found, xm, fm, n_eval = _inflow_turn(c0, c1, mu, lam_inf, x0, x1, f1, direction, n_eval, max_iter)
            if found:
                x1, f1 = xm, fm
                break
        x0, f0 = x1, f1
        h *= 1.25
    return found, x0, f0, x1, f1, n_eval


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def _inflow_refine(c0, c1, mu, lam_inf, x0, f0, x1, f1, n_eval, max_iter, tol, ftol):
    """Root of the inflow residual in the bracket (x0, x1) of :func:`_inflow_bracket`: Newton steps that fall back
    to bisection when they leave the bracket. Returns (lam, status, n_eval)."""
    # orient: f(lo) < 0 < f(hi)
    if f0 < 0.0:
        lo, hi = x0, x1
    else:
        lo, hi = x1, x0
    lam = x1 if abs(f1) < abs(f0) else x0
    status = STATUS_MAX_ITER
    while n_eval < max_iter:
        f, df = _inflow_residual(c0, c1, mu, lam_inf, lam)
        n_eval += 1
        if f == 0.0 or abs(f) <= ftol:
            status = STATUS_OK
            break
        if f < 0.0:
            lo = lam
        else:
            hi = lam
        if abs(hi - lo) <= tol * (1.0 + abs(lam)):
            lam = 0.5 * (lo + hi)
            status = STATUS_OK
            break
        step_ok = False
        if df != 0.0 and math.isfinite(df):
            trial = lam - f / df
            if (trial - lo) * (trial - hi) < 0.0:
                lam = trial
                step_ok = True
        if not step_ok:
            lam = 0.5 * (lo + hi)
    return lam, status, n_eval


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def solve_inflow(p, mu, lam_inf, theta0, tol, max_iter, out):
    """Inflow ratio lam consistent with C_T: lam = lam_inf - C_T(lam) / (2 sqrt(mu^2 + lam^2)).

    lam_inf = V sin(alpha_c)/(Omega R) is the free-stream part (Roberts eq. 5 with its normal component).
    Method: starting at lam_inf (no induced velocity) the residual f(lam) = lam - lam_inf + nu(lam) is
    followed in the direction that reduces |f| (downwards when C_T > 0) with steps growing by 1.25 until it
    changes sign; the root in that bracket is refined by Newton steps that fall back to bisection when they
    leave the bracket. Of several roots (momentum theory has up to three in the heavily loaded windmill
    state) this picks the one nearest lam_inf on the physical side: the lightly loaded branch, continuous
    with nu = 0 at zero thrust.

    Writes out[O_LAMBDA], out[O_NU], out[O_CT], out[O_ITER] (residual evaluations) and out[O_STATUS]
    (STATUS_*). Requires mu > 0 (at mu = 0 the residual is singular at lam = 0). Converged when the bracket
    is narrower than tol (1 + |lam|) or |f| < tol (1 + |lam_inf|).
    """
    sigma, a, tip_loss = p[P_SIGMA], p[P_A], p[P_B]
    c1 = 0.25 * sigma * a * tip_loss * tip_loss
    c0 = thrust_coefficient(sigma, a, tip_loss, mu, 0.0, theta0)
    out[O_LAMBDA] = math.nan
    out[O_NU] = math.nan
    out[O_CT] = math.nan
    out[O_ITER] = 0.0
    if not (math.isfinite(mu) and math.isfinite(lam_inf) and math.isfinite(theta0) and math.isfinite(c0)):
        out[O_STATUS] = STATUS_NOT_FINITE
        return
    ftol = tol * (1.0 + abs(lam_inf))
    f0, _ = _inflow_residual(c0, c1, mu, lam_inf, lam_inf)
    n_eval = 1
    status = STATUS_NO_BRACKET
    lam = lam_inf
    if abs(f0) <= ftol:
        status = STATUS_OK
    else:
        found, x0, f0, x1, f1, n_eval = _inflow_bracket(c0, c1, mu, lam_inf, f0, n_eval, max_iter)
        if found:
            lam, status, n_eval = _inflow_refine(c0, c1, mu, lam_inf, x0, f0, x1, f1, n_eval, max_iter, tol, ftol)
    if status == STATUS_OK or status == STATUS_MAX_ITER:
        ct = c0 + c1 * lam
        out[O_LAMBDA] = lam
        out[O_CT] = ct
        out[O_NU] = lam_inf - lam
    out[O_ITER] = n_eval
    out[O_STATUS] = status


@njit(cache=True, _nrt=False, fastmath={"contract", "nsz", "arcp"}, error_model="numpy")
def rotor_state(p, mu, alpha_c, theta0, tol, max_iter, out):
    """Trimmed rotor at advance ratio mu, craft incidence alpha_c [rad] and collective theta0 [rad].

    Solves the Glauert inflow (:func:`solve_inflow` with lam_inf = mu tan(alpha_c), Roberts eq. 5), then
    writes into out: O_LAMBDA, O_NU, O_CT, O_ITER, O_STATUS as solve_inflow, O_CH (H-force), O_CQ (torque,
    energy identity), O_A0, O_A1, O_B1 (flapping [rad]), O_TIP_AOA (retreating-tip angle of attack [rad])
    and O_CP (power coefficient, Roberts eq. 4). Everything but O_ITER and O_STATUS is nan when the inflow
    did not converge (status other than STATUS_OK).
    """
    for k in range(N_OUT):
        out[k] = math.nan
    lam_inf = mu * math.tan(alpha_c)
    solve_inflow(p, mu, lam_inf, theta0, tol, max_iter, out)
    if out[O_STATUS] != STATUS_OK:
        out[O_LAMBDA] = math.nan
        out[O_NU] = math.nan
        out[O_CT] = math.nan
        return
    sigma, a, delta, tip_loss, gamma = p[P_SIGMA], p[P_A], p[P_DELTA], p[P_B], p[P_GAMMA]
    lam = out[O_LAMBDA]
    ct = out[O_CT]
    a0 = coning_angle(gamma, mu, lam, theta0)
    a1 = longitudinal_flapping(mu, lam, theta0)
    b1 = lateral_flapping(mu, a0)
    ch = h_force_coefficient(sigma, a, delta, tip_loss, mu, lam, theta0, a0, a1, b1)
    cq = torque_coefficient(sigma, delta, mu, lam, ct, ch)
    out[O_CH] = ch
    out[O_CQ] = cq
    out[O_A0] = a0
    out[O_A1] = a1
    out[O_B1] = b1
    out[O_TIP_AOA] = tip_incidence(theta0, mu, lam, a1)
    out[O_CP] = power_coefficient(cq, mu, alpha_c)
