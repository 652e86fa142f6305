"""Design checks of the derived wing table: the table as the simulator sees it, the pitch moment of a wing
held by its cable, trims and elevator authority (printed by ``derive_wing --check``)."""

from __future__ import annotations

import numpy as np

from laddermill_gym.derivations.wing_model import (
    Wing,
)
from laddermill_gym.derivations.wing_parameters import (
    ATT_ANGLE,
    C_W,
    D_ATT,
    DEG,
    MASS,
    RHO_REF,
    S_W,
    V_REF,
    G,
)
from laddermill_gym.model.params import AERO_COLUMNS


def attachment_vector(angle: float = ATT_ANGLE):
    """Cable attachment [m], body axes from the CG: D_ATT at ``angle`` [rad] below the body x axis."""
    return D_ATT * np.array([np.cos(angle), 0.0, np.sin(angle)])


class TableModel:
    """The table as the simulator sees it (periodic cubic spline) for the longitudinal checks."""

    def __init__(self, a_deg, rows, r_ref):
        from scipy.interpolate import CubicSpline
        self.sp = CubicSpline(np.radians(a_deg), rows, bc_type="periodic")
        self.r_ref = r_ref

    def col(self, alpha, name):
        return self.sp(alpha)[AERO_COLUMNS.index(name)]

    def aero(self, alpha, de, V, rho=RHO_REF):
        """Body force (X, Z) [N] and moment about the CG [N m] in a steady horizontal wind."""
        c = self.sp(alpha)
        ix = AERO_COLUMNS.index
        cl = c[ix("CL")] + c[ix("CLde")] * de
        cd = c[ix("CD")]
        cm = c[ix("Cm")] + c[ix("Cmde")] * de
        qs = 0.5 * rho * V**2 * S_W
        X = qs * (cl * np.sin(alpha) - cd * np.cos(alpha))
        Z = qs * (-cl * np.cos(alpha) - cd * np.sin(alpha))
        M = qs * C_W * cm + self.r_ref[2] * X - self.r_ref[0] * Z
        return X, Z, M, qs * cl


def moment_kite(tm, alpha, de, V, att_angle: float = ATT_ANGLE):
    """Pitch moment about the CG [N m] of a wing held by its cable in steady horizontal wind (the attachment at
    ``att_angle`` [rad] below body x). It equals the moment of aerodynamics and weight about the attachment.

    Pitch = alpha; the net cable force balances aerodynamics and weight, F_c = -(F_aero + W).
    """
    a = attachment_vector(att_angle)
    X, Z, M, _ = tm.aero(alpha, de, V)
    Wx, Wz = -MASS * G * np.sin(alpha), MASS * G * np.cos(alpha)
    Fx, Fz = -(X + Wx), -(Z + Wz)
    return M + a[2] * Fx - a[0] * Fz, (Fx, Fz)


def moment_fixed_tether(tm, alpha, de, V, elev):
    """Pitch moment about the CG [N m] with a tether force of magnitude L toward a ground point
    at elevation angle ``elev`` below the horizontal (ahead of the wing)."""
    a = attachment_vector()
    X, Z, M, L = tm.aero(alpha, de, V)
    Fx, Fz = L * np.cos(elev + alpha), L * np.sin(elev + alpha)
    return M + a[2] * Fx - a[0] * Fz


def solve_alpha(fun, lo=-8.0 * DEG, hi=22.0 * DEG):
    from scipy.optimize import brentq
    grid = np.linspace(lo, hi, 121)
    vals = [fun(x) for x in grid]
    roots = []
    for i in range(len(grid) - 1):
        if vals[i] > 0 >= vals[i + 1]:       # a stable root: moment falls through zero
            roots.append(brentq(fun, grid[i], grid[i + 1]))
    return roots


def run_checks(tm: TableModel, wing: Wing, limits_deg, att_angle: float = ATT_ANGLE):
    """Print the design checks (key numbers, trims, elevator authority) for the attachment at ``att_angle`` [rad]
    below body x."""
    from scipy.optimize import brentq
    deg = np.degrees
    al = np.radians(np.arange(-10, 30.01, 0.05))
    cl = np.array([tm.col(a, "CL") for a in al])
    i = np.argmax(cl)
    print(f"CL_max = {cl[i]:.3f} at alpha = {deg(al[i]):.2f} deg")
    a0 = np.radians(5.0)
    h = 1e-4
    cla = (tm.col(a0 + h, "CL") - tm.col(a0 - h, "CL")) / (2 * h)
    def cm_cg(a, de=0.0):
        X, Z, M, _ = tm.aero(a, de, 1.0, 1.0)
        return M / (0.5 * S_W * C_W)
    cma = (cm_cg(a0 + h) - cm_cg(a0 - h)) / (2 * h)
    print(f"aircraft CL_alpha = {cla:.3f} /rad, Cm_alpha about CG = {cma:.3f} /rad, static margin = "
          f"{-cma / cla:.3f} c = {-cma / cla * C_W:.3f} m (neutral point behind the CG)")
    cd_min = min(tm.col(a, "CD") for a in al)
    print(f"CD at CL=0: {tm.col(brentq(lambda a: tm.col(a, 'CL'), -0.2, 0.1), 'CD'):.4f}, CD_min = {cd_min:.4f}")
    ld = [tm.col(a, "CL") / tm.col(a, "CD") for a in al]
    j = int(np.argmax(ld))
    print(f"(L/D)_max = {ld[j]:.1f} at alpha = {deg(al[j]):.1f} deg")
    for name in ("Cnb", "Clb", "Clp", "Cnr", "Cmq", "CYb", "Cnp", "Clr", "CLq", "CLad", "Cmad", "CLde", "Cmde",
                 "Clda", "Cnda", "CYdr", "Cndr", "Cldr"):
        vals = [tm.col(np.radians(x), name) for x in (0.0, 7.0, 14.0, 30.0, 90.0)]
        print(f"  {name:5s} at 0/7/14/30/90 deg: " + " ".join(f"{v:8.4f}" for v in vals))
    ff = solve_alpha(lambda a: cm_cg(a))
    print(f"free-flight trim (no cable) at de=0: alpha = {[round(deg(x), 2) for x in ff]} deg")
    for V in (6.0, 10.0, 15.0, 20.0):
        r = solve_alpha(lambda a: moment_kite(tm, a, 0.0, V, att_angle)[0])
        s = []
        for x in r:
            _, (Fx, Fz) = moment_kite(tm, x, 0.0, V, att_angle)
            elev = deg(np.arctan2(Fz * np.cos(x) - Fx * np.sin(x), Fx * np.cos(x) + Fz * np.sin(x)))
            L = tm.aero(x, 0.0, V)[3]
            s.append(f"alpha={deg(x):.2f} deg, cable force {np.hypot(Fx, Fz):.0f} N (L={L:.0f} N) at "
                     f"{elev:.1f} deg below horizontal")
        print(f"kite trim (cable force from force balance), V={V:4.1f} m/s, de=0: " + "; ".join(s))
    lo, hi = np.radians(limits_deg)
    for target in (0.0, 7.0, 15.0):
        def f(de, target=target):
            return moment_kite(tm, np.radians(target), de, V_REF, att_angle)[0]
        try:
            de = brentq(f, lo, hi)
            print(f"elevator for kite trim at alpha={target:4.1f} deg (V={V_REF} m/s): de = {deg(de):6.2f} deg")
        except ValueError:
            print(f"elevator for kite trim at alpha={target:4.1f} deg: outside limits {limits_deg}")
    for de_deg in (limits_deg[0], -5.0, 0.0, 5.0, limits_deg[1]):
        r = solve_alpha(lambda a: moment_kite(tm, a, np.radians(de_deg), V_REF, att_angle)[0], np.radians(-20),
                        np.radians(30))
        print(f"  de = {de_deg:6.1f} deg -> kite trim alpha = {[round(deg(x), 2) for x in r]} deg")
    for elev in (30.0, 40.0, 50.0):
        r = solve_alpha(lambda a: moment_fixed_tether(tm, a, 0.0, V_REF, np.radians(elev)))
        def f(de, elev=elev):
            return moment_fixed_tether(tm, np.radians(7.0), de, V_REF, np.radians(elev))
        try:
            de7 = f"{deg(brentq(f, lo, hi)):.2f} deg"
        except ValueError:
            de7 = "outside limits"
        print(f"tether force = L toward elevation {elev:.0f} deg: trim at de=0 alpha = "
              f"{[round(deg(x), 2) for x in r]} deg; de for alpha=7 deg: {de7}")
