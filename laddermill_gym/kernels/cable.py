"""Cable truss element: tension with or without sag correction, and the aerodynamic load per length.

Meijaard et al. 1999 eqs. (16)-(24); see docs/model.md, "Cable elements".
"""

import math

from numba import njit

SAG_TOL = 1e-13
SAG_MAX_ITER = 60


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def tension_plain(EA, DA, l0, eps, eps_dot):
    """Tension-only Hookean truss with Voigt damping [N]: zero when slack or when pushing."""
    if eps <= 0.0:
        return 0.0
    s = (EA * eps + DA * eps_dot) / l0
    return max(0.0, s)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def tension_sag(EA, DA, l0, eps, eps_dot, eps_p):
    """Sag-corrected tension [N]: the positive root of s^3 - s0 s^2 - EA eps_p/l0 (eqs. 19-22).

    Newton-Raphson from the start value of eq. (21). The iterates approach the root from above after
    the first step (f is convex right of s0/3), so the loop ends on a small step or after
    SAG_MAX_ITER steps. With no lateral load the plain clipped value max(s0, 0) is returned.
    """
    s0 = (EA * eps + DA * eps_dot) / l0
    c = EA * eps_p / l0
    if not (c > 1e-300):
        return max(0.0, s0)
    s = c ** (1.0 / 3.0)
    s = max(s, s0)
    for _ in range(SAG_MAX_ITER):
        f = s * s * (s - s0) - c
        df = s * (3.0 * s - 2.0 * s0)
        step = f / df
        s -= step
        if abs(step) <= SAG_TOL * s:
            break
    return s


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def lateral_elongation(length, ex, ey, ez, prx, pry, prz, psx, psy, psz):
    """eps_p of eq. (18) [m N^2]: loads per length at r and s (global), made lateral to e."""
    dr = prx * ex + pry * ey + prz * ez
    ds = psx * ex + psy * ey + psz * ez
    ax, ay, az = prx - dr * ex, pry - dr * ey, prz - dr * ez
    bx, by, bz = psx - ds * ex, psy - ds * ey, psz - ds * ez
    aa = ax * ax + ay * ay + az * az
    bb = bx * bx + by * by + bz * bz
    ab = ax * bx + ay * by + az * bz
    return length * length * length * ((aa + bb) / 90.0 + 7.0 / 360.0 * ab)


@njit(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"}, _nrt=False)
def aero_load(ux, uy, uz, ex, ey, ez, rho, d, cn0, ct0):
    """Aerodynamic load per unit length [N/m] on a cable with tangent e in relative air velocity u.

    rho d/2 (C_N0 |u_n| u_n + C_T0 |u| u): the normal force C_N0 sin^2 a_c of eq. (24) plus the
    tangential friction C_T0; identical to drag C_N0 sin^3 a_c + C_T0 and lift C_N0 sin^2 a_c cos a_c.
    """
    ut = ux * ex + uy * ey + uz * ez
    nx, ny, nz = ux - ut * ex, uy - ut * ey, uz - ut * ez
    un = math.sqrt(nx * nx + ny * ny + nz * nz)
    uu = math.sqrt(ux * ux + uy * uy + uz * uz)
    k = 0.5 * rho * d
    fn = k * cn0 * un
    ft = k * ct0 * uu
    return fn * nx + ft * ux, fn * ny + ft * uy, fn * nz + ft * uz
