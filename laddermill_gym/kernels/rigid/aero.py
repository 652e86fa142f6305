"""Quasi-steady wing aerodynamics (docs/model.md, "Wing aerodynamics").

Packed wing-type parameters ``tf[k]`` (float64[16]): mass [kg], Jxx, Jyy, Jzz, Jxz [kg m^2], S [m^2],
b [m], c [m], r_ref (3) [m], attachment (3) [m], unused (2). Aerodynamic spline coefficients
``ac[k, i, p, j]``: interval i of the uniform alpha grid (start ``a0`` [rad], spacing ``da`` [rad]),
power p (3, 2, 1, 0 for p = 0..3, scipy.interpolate.CubicSpline's layout), column j (AERO_COLUMNS order).
"""

import math

from numba import njit

from laddermill_gym.kernels.contract import (  # noqa: F401 (also read as attributes of this module)
    AO2_FORCE_X,
    AO2_FORCE_Z,
    AO2_G,
    AO2_KAPPA,
    AO2_MOMENT,
    AO_FORCE,
    AO_G,
    AO_KAPPA,
    AO_MOMENT,
    AO_SIZE,
    CD,
    CL,
    CLAD,
    CLB,
    CLDA,
    CLDE,
    CLDR,
    CLP,
    CLQ,
    CLR,
    CM,
    CMAD,
    CMDE,
    CMQ,
    CNB,
    CNDA,
    CNDR,
    CNP,
    CNR,
    CYB,
    CYDR,
    CYP,
    CYR,
    N_COLUMNS,
    N_LONGITUDINAL,
    TF_AREA,
    TF_CHORD,
    TF_RREF,
    TF_SPAN,
)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def spline_eval(ac, k, alpha, a0, da, out):
    """Evaluate all table columns of wing type k at alpha [rad] into out (float64[N_COLUMNS])."""
    n_int = ac.shape[1]
    two_pi = 2.0 * math.pi
    a = alpha - a0
    if not abs(a) < 1e300:  # NaN or infinite alpha (a non-finite state, reported by the integrator's check)
        a = 0.0  # never a NaN index
    elif a < 0.0 or a >= two_pi:
        a = a - two_pi * math.floor(a / two_pi)
    i = int(a / da)
    if i >= n_int:
        i = n_int - 1
    x = a - i * da
    for j in range(out.size):
        out[j] = ((ac[k, i, 0, j] * x + ac[k, i, 1, j]) * x + ac[k, i, 2, j]) * x + ac[k, i, 3, j]


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def wing_aero(k, tf, ac, a0, da, rho, ua, va, wa, p, q, r, de, dr, dal, ad0, coef, out):
    """Aerodynamic force and moment about the CG, body axes, for one wing.

    Inputs: wing type k, air density rho, air-relative body velocity (ua, va, wa) [m/s], body rates
    (p, q, r) [rad/s], controls (de, dr, dal) [rad], the known part of the alpha rate ad0 [rad/s].
    Writes out[0:3] force [N], out[3:6] moment about the CG [N m], out[6:12] the alpha-rate force
    vector k (generalised force per rad/s of alpha rate), out[12:15] g (d alpha/d v_a, [rad s/m]).
    Everything is zero when the airspeed is below 1e-9 m/s or rho == 0.
    """
    for j in range(AO_SIZE):
        out[j] = 0.0
    V2 = ua * ua + va * va + wa * wa
    if V2 < 1e-18 or rho == 0.0:
        return
    V = math.sqrt(V2)
    S, b, c = tf[k, TF_AREA], tf[k, TF_SPAN], tf[k, TF_CHORD]
    rx, ry, rz = tf[k, TF_RREF], tf[k, TF_RREF + 1], tf[k, TF_RREF + 2]
    alpha = math.atan2(wa, ua)
    sb = va / V
    if sb > 1.0:
        sb = 1.0
    elif sb < -1.0:
        sb = -1.0
    beta = math.asin(sb)
    spline_eval(ac, k, alpha, a0, da, coef)
    qbar = 0.5 * rho * V2
    hb = 0.5 * b / V
    hc = 0.5 * c / V
    ph, qh, rh, adh = p * hb, q * hc, r * hb, ad0 * hc
    cl = coef[CL] + coef[CLQ] * qh + coef[CLAD] * adh + coef[CLDE] * de
    cd = coef[CD]
    cm = coef[CM] + coef[CMQ] * qh + coef[CMAD] * adh + coef[CMDE] * de
    cy = coef[CYB] * beta + coef[CYP] * ph + coef[CYR] * rh + coef[CYDR] * dr
    cr = coef[CLB] * beta + coef[CLP] * ph + coef[CLR] * rh + coef[CLDA] * dal + coef[CLDR] * dr
    cn = coef[CNB] * beta + coef[CNP] * ph + coef[CNR] * rh + coef[CNDA] * dal + coef[CNDR] * dr
    sa, ca = math.sin(alpha), math.cos(alpha)
    qs = qbar * S
    X = qs * (cl * sa - cd * ca)
    Y = qs * cy
    Z = qs * (-cl * ca - cd * sa)
    out[AO_FORCE], out[AO_FORCE + 1], out[AO_FORCE + 2] = X, Y, Z
    out[AO_MOMENT] = qs * b * cr + ry * Z - rz * Y
    out[AO_MOMENT + 1] = qs * c * cm + rz * X - rx * Z
    out[AO_MOMENT + 2] = qs * b * cn + rx * Y - ry * X
    # alpha-rate pieces: force per rad/s of alpha rate, and d alpha / d v_a
    f = qs * hc * coef[CLAD]
    kx, kz = f * sa, -f * ca
    out[AO_KAPPA], out[AO_KAPPA + 1], out[AO_KAPPA + 2] = kx, 0.0, kz
    out[AO_KAPPA + 3] = ry * kz
    out[AO_KAPPA + 4] = qs * c * hc * coef[CMAD] + rz * kx - rx * kz
    out[AO_KAPPA + 5] = -ry * kx
    d2 = ua * ua + wa * wa
    if d2 > 1e-18:
        out[AO_G] = -wa / d2
        out[AO_G + 2] = ua / d2




@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def wing_aero_long(k, tf, ac, a0, da, rho, ua, wa, q, de, ad0, coef, out):
    """In-plane aerodynamics: only the longitudinal columns are evaluated.

    Writes out[0] X, out[1] Z [N], out[2] pitch moment about the CG [N m], out[3:6] alpha-rate vector
    (X, Z, M per rad/s) and out[6:8] g = d alpha/d(u_a, w_a) [rad s/m]; zero below 1e-9 m/s airspeed.
    """
    for j in range(AO2_G + 2):
        out[j] = 0.0
    V2 = ua * ua + wa * wa
    if V2 < 1e-18 or rho == 0.0:
        return
    V = math.sqrt(V2)
    S, c = tf[k, TF_AREA], tf[k, TF_CHORD]
    rx, rz = tf[k, TF_RREF], tf[k, TF_RREF + 2]
    alpha = math.atan2(wa, ua)
    for j in range(N_LONGITUDINAL):
        coef[j] = 0.0
    spline_eval(ac, k, alpha, a0, da, coef[:N_LONGITUDINAL])
    qs = 0.5 * rho * V2 * S
    hc = 0.5 * c / V
    qh, adh = q * hc, ad0 * hc
    cl = coef[CL] + coef[CLQ] * qh + coef[CLAD] * adh + coef[CLDE] * de
    cd = coef[CD]
    cm = coef[CM] + coef[CMQ] * qh + coef[CMAD] * adh + coef[CMDE] * de
    sa, ca = math.sin(alpha), math.cos(alpha)
    X = qs * (cl * sa - cd * ca)
    Z = qs * (-cl * ca - cd * sa)
    out[AO2_FORCE_X], out[AO2_FORCE_Z] = X, Z
    out[AO2_MOMENT] = qs * c * cm + rz * X - rx * Z
    f = qs * hc * coef[CLAD]
    kx, kz = f * sa, -f * ca
    out[AO2_KAPPA], out[AO2_KAPPA + 1] = kx, kz
    out[AO2_KAPPA + 2] = qs * c * hc * coef[CMAD] + rz * kx - rx * kz
    out[AO2_G] = -wa / V2
    out[AO2_G + 1] = ua / V2
