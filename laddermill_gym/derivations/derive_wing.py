"""Derive the default aerodynamic table and mass properties of the Meijaard et al. (1999) wing.

Run ``python -m laddermill_gym.derivations.derive_wing [--out-dir configs/wings] [--check]``.

Method (written out with sources in ``laddermill_gym/docs/wing_data.md``): a component build-up.
Each lifting surface (main wing with dihedral, all-moving horizontal tail, twin fins) is cut into
spanwise strips; every strip sees the local air-relative velocity of its point (CG velocity plus
angular velocity x position), turns it into a local angle of attack in its own chord plane
(cross-flow along the span is ignored, the "independence principle"), and produces lift, drag and
moment from the surface's 3-D coefficient curves. The curves are attached-flow theory (Helmbold lift
slope, Prandtl/Oswald induced drag, skin-friction zero-lift drag) blended smoothly into a flat-plate
normal-force model (Viterna & Corrigan) over the whole -180..180 deg range. Spanwise lift is weighted
elliptically, which reproduces the classical strip-theory results (Clp = -CLa/8, Cnp = -CL/8,
Clb = -0.21 CLa Gamma for an elliptic load). The horizontal tail sees the wing's downwash
eps = 2 CL_w/(pi A) and its lag gives the alpha-rate derivatives.

All coefficients are obtained as forces and moments of this model (numerical derivatives for the
rate, sideslip and control columns), in body axes, about the aerodynamic reference point, and in the
non-dimensionalisation of ``docs/model.md``.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.model.params import AERO_COLUMNS

# ------------------------------------------------------------------------------------------- geometry
# Paper (Meijaard, Ockels & Schwab 1999, "Results"): S, b, m, CG-ac 0.75 m, CG-attachment 1.5 m, booms 5 m.
S_W = 54.0            # [m^2]  main-wing area, paper
B_W = 20.0            # [m]    main-wing span, paper
MASS = 54.0           # [kg]   total mass, paper
D_AC = 0.75           # [m]    CG to aerodynamic centre of the main wing, paper (we put the ac AHEAD of the CG)
D_ATT = 1.50          # [m]    CG to cable attachment, paper
L_BOOM = 5.0          # [m]    tail-boom length, paper (from the wing's quarter-chord spar to the tail pivot/ac)
C_W = S_W / B_W       # [m]    chord of the rectangular, untapered, unswept main wing (choice) = MAC
A_W = B_W**2 / S_W    # [-]    aspect ratio 7.41
DIHEDRAL = np.radians(3.0)   # [rad] main-wing dihedral, choice (Raymer Ch. 4 guideline for a mid wing, 2-4 deg)
TC_W = 0.14           # [-]    wing thickness ratio, choice (cambered kite/glider section)
A0_SECTION = 6.0      # [1/rad] section lift slope, choice (kappa = a0/2pi = 0.955, DATCOM/Helmbold input)
ALPHA0_W = np.radians(-3.0)  # [rad] zero-lift angle of the cambered section, choice
CM0_W = -0.07         # [-]    section moment about the quarter chord, choice (moderate camber)
AIL_ETA = (0.55, 0.95)       # [-] aileron span stations (fraction of semispan), choice
AIL_CF = 0.25         # [-]    aileron chord / wing chord, choice

# [m^2] horizontal tail area, choice: static margin about 0.08 c with the CG 0.75 m behind the wing ac
DEG = np.pi / 180.0  # [rad/deg]
S_H = 25.0
B_H = 11.2            # [m]    horizontal tail span, choice (aspect ratio 5.0)
TC_H = 0.10           # [-]    tail thickness ratio, choice (symmetric section)
ETA_H = 0.95          # [-]    tail dynamic-pressure ratio q_t/q, typical value (Etkin & Reid Ch. 2)
S_V1 = 3.0            # [m^2]  area of ONE of the twin fins, choice (vertical tail volume 0.024)
H_V = 1.8             # [m]    fin height above the boom, choice (chord 1.67 m)
AR_V_EFF = 2.0        # [-]    effective fin aspect ratio (geometric 1.08 raised by the tail plane end plate), choice
TC_V = 0.10           # [-]    fin thickness ratio, choice
Y_BOOM = 1.0          # [m]    lateral position of the two booms (at the wing's central splitting), choice
D_BOOM = 0.08         # [m]    boom diameter, choice
RUD_CF = 0.35         # [-]    rudder chord / fin chord, choice

ATT_ANGLE = np.radians(80.0)  # [rad] attachment direction below the body x axis (ahead of and below the CG), choice
RHO_REF, V_REF, NU = 1.225, 10.0, 1.5e-5   # [kg/m^3], [m/s], [m^2/s] design point for Reynolds numbers and trim
G = 9.81              # [m/s^2]

# blending of attached flow into the flat plate (logistic weights), stall angles and sharpness
# [rad] wing: blend midpoints (CL peaks about 3.5 deg earlier), choice
STALL_W = (np.radians(18.0), np.radians(-16.0))
STALL_H = (np.radians(17.0), np.radians(-17.0))    # [rad] horizontal tail, choice
STALL_V = (np.radians(21.0), np.radians(-21.0))    # [rad] fins (low aspect ratio stall later), choice
M_BLEND = 25.0        # [1/rad] sharpness of the blend (10-90 % over 10 deg), choice: smooth on a 2 deg grid

# mass build-up [kg]
M_WING = 38.0         # main wing structure and skin (0.70 kg/m^2), choice
AREAL_TAIL = 0.20     # [kg/m^2] tail surfaces, choice (light kite-type construction)
M_BOOM = 1.2          # [kg] each carbon boom, choice
N_STRIP = 200         # strips per wing semispan / tail span (numerical resolution)

# ------------------------------------------------------------------------------------------- formulas


def helmbold_lift_slope(aspect: float, a0: float = A0_SECTION) -> float:
    """Finite-wing lift slope [1/rad] of an unswept wing, incompressible (Helmbold; DATCOM Sec. 4.1.3.2).

    CLa = 2 pi A / (2 + sqrt(A^2 / kappa^2 + 4)), kappa = a0 / (2 pi).
    """
    kappa = a0 / (2 * np.pi)
    return 2 * np.pi * aspect / (2 + np.sqrt(aspect**2 / kappa**2 + 4))


def oswald_e(aspect: float) -> float:
    """Oswald span efficiency of a straight wing [-] (Raymer, Ch. 12: e = 1.78 (1 - 0.045 A^0.68) - 0.64)."""
    return 1.78 * (1 - 0.045 * aspect**0.68) - 0.64


def skin_friction_cd0(chord: float, tc: float, q_factor: float = 1.1) -> float:
    """Zero-lift drag of a surface referred to its own area [-] (Raymer Ch. 12 component build-up).

    Turbulent flat-plate Cf = 0.455 / log10(Re)^2.58, Hoerner's form factor 1 + 2 t/c + 60 (t/c)^4,
    wetted area S_wet = (1.977 + 0.52 t/c) S, interference factor Q.
    """
    re = V_REF * chord / NU
    cf = 0.455 / np.log10(re) ** 2.58
    ff = 1 + 2 * tc + 60 * tc**4
    return cf * ff * q_factor * (1.977 + 0.52 * tc)


def viterna_cdmax(aspect: float) -> float:
    """Flat-plate drag at 90 deg of a finite wing [-] (Viterna & Corrigan 1982: 1.11 + 0.018 A)."""
    return 1.11 + 0.018 * aspect


def flap_effectiveness(cf_ratio: float, empirical: float = 0.8) -> float:
    """d(alpha)/d(delta) of a plain flap [-]: Glauert thin-aerofoil theory times an empirical factor.

    tau = 1 - (theta_f - sin theta_f)/pi, cos theta_f = 2 c_f/c - 1.
    """
    th = np.arccos(2 * cf_ratio - 1)
    return empirical * (1 - (th - np.sin(th)) / np.pi)


@dataclass(frozen=True)
class Polar:
    """3-D coefficient curves of one surface, valid for any angle [rad] (periodic).

    Attached flow: CL = CLa (a - a0), CD = CD0 + CL^2/(pi A e), Cm = Cm0 (about the quarter chord).
    Flat plate: CN = CDmax sin a, CL = CN cos a, CD = CD0 + CN sin a, centre of pressure at
    x/c = 0.5 - 0.25 cos a (1/4 chord at 0, 1/2 at 90 deg, 3/4 at 180 deg).
    Blend weight s = 1/(1+exp(M (a - a_pos))) * 1/(1+exp(-M (a - a_neg))).
    """

    cla: float
    alpha0: float
    cd0: float
    k_ind: float
    cm0: float
    cdmax: float
    stall: tuple[float, float]
    m: float = M_BLEND

    def weight(self, a):
        a = np.mod(np.asarray(a) + np.pi, 2 * np.pi) - np.pi
        s = 1 / (1 + np.exp(np.clip(self.m * (a - self.stall[0]), -700, 700)))
        return s / (1 + np.exp(np.clip(-self.m * (a - self.stall[1]), -700, 700)))

    def __call__(self, a):
        a = np.mod(np.asarray(a, dtype=float) + np.pi, 2 * np.pi) - np.pi
        s = self.weight(a)
        cl_att = self.cla * (a - self.alpha0)
        cd_att = self.cd0 + self.k_ind * cl_att**2
        cn = self.cdmax * np.sin(a)
        cl = s * cl_att + (1 - s) * cn * np.cos(a)
        cd = s * cd_att + (1 - s) * (self.cd0 + cn * np.sin(a))
        cm = s * self.cm0 + (1 - s) * (-cn * 0.25 * (1 - np.cos(a)))
        return cl, cd, cm


@dataclass
class Surface:
    """Strips of one lifting surface: positions (force/velocity points), chord axis, normal, areas."""

    pos: np.ndarray       # (n, 3) force application point (quarter chord) [m]
    pos_v: np.ndarray     # (n, 3) point where the velocity is taken [m]
    normal: np.ndarray    # (n, 3) unit normal, "down" side (lift acts along -normal)
    area: np.ndarray      # (n,) strip area [m^2]
    wlift: np.ndarray     # (n,) spanwise lift weight (mean 1 over the area)
    chord: float
    polar: Polar
    qfac: float = 1.0     # dynamic-pressure factor
    downwash: bool = False

    def loads(self, v, w, eps, dalpha):
        """Force [N] and moment about the CG [N m] at rho = 1 for body velocity v, rates w, downwash eps."""
        ex = np.array([1.0, 0.0, 0.0])
        vp = v + np.cross(w, self.pos_v)
        vx = vp[:, 0]
        vn = np.einsum("ij,ij->i", vp, self.normal)
        phi = np.arctan2(vn, vx) - (eps if self.downwash else 0.0)
        q = 0.5 * (vx**2 + vn**2) * self.qfac
        cl, cd, cm = self.polar(phi + dalpha)
        lift, drag = q * self.area * self.wlift * cl, q * self.area * cd
        sp, cp = np.sin(phi)[:, None], np.cos(phi)[:, None]
        f = lift[:, None] * (sp * ex - cp * self.normal) - drag[:, None] * (cp * ex + sp * self.normal)
        span_axis = np.cross(self.normal, ex)
        m = np.cross(self.pos, f).sum(0) + ((q * self.area * self.chord * cm)[:, None] * span_axis).sum(0)
        return f.sum(0), m


def elliptic_strips(n):
    """Midpoints eta in (-1, 1), widths d(eta) and elliptic lift weights (4/pi) sqrt(1 - eta^2)."""
    edges = np.linspace(-1.0, 1.0, 2 * n + 1)
    eta = 0.5 * (edges[1:] + edges[:-1])
    deta = np.diff(edges)
    w = 4 / np.pi * np.sqrt(1 - eta**2)
    w *= 2 / np.sum(w * deta)        # exact normalisation on the grid
    return eta, deta, w


# ------------------------------------------------------------------------------------------- the wing
class Wing:
    """The component model, built from the parameters at the top of this module."""

    def __init__(self, i_t: float):
        self.i_t = i_t                                 # [rad] tail incidence (rigging) at zero elevator
        self.cla_w = helmbold_lift_slope(A_W)
        self.e_w = oswald_e(A_W)
        a_h = B_H**2 / S_H
        self.cla_h = helmbold_lift_slope(a_h)
        self.cla_v = helmbold_lift_slope(AR_V_EFF)
        self.cd0_w = skin_friction_cd0(C_W, TC_W)
        c_h, c_v = S_H / B_H, S_V1 / H_V
        self.c_h, self.c_v = c_h, c_v
        self.cd0_h = skin_friction_cd0(c_h, TC_H)
        self.cd0_v = skin_friction_cd0(c_v, TC_V)
        # booms (skin friction along, cylinder cross-flow) and the nose pod, referred to S_W
        re_b = V_REF * L_BOOM / NU
        cf_b = 0.455 / np.log10(re_b) ** 2.58
        self.cd_misc0 = (2 * cf_b * np.pi * D_BOOM * L_BOOM + 0.15 * 0.15) / S_W
        self.cd_cross = 2 * 1.1 * D_BOOM * L_BOOM / S_W
        self.pw = Polar(self.cla_w, ALPHA0_W, self.cd0_w, 1 / (np.pi * A_W * self.e_w), CM0_W,
                        viterna_cdmax(A_W), STALL_W)
        self.ph = Polar(self.cla_h, 0.0, self.cd0_h, 1 / (np.pi * a_h * oswald_e(a_h)), 0.0,
                        viterna_cdmax(a_h), STALL_H)
        self.pv = Polar(self.cla_v, 0.0, self.cd0_v, 1 / (np.pi * AR_V_EFF * 0.9), 0.0,
                        viterna_cdmax(AR_V_EFF), STALL_V)
        self.tau_a = flap_effectiveness(AIL_CF)
        self.tau_r = flap_effectiveness(RUD_CF)
        # sidewash and fin dynamic pressure, Nelson Ch. 2 (DATCOM): eta_v (1 + d sigma/d beta)
        s_v = 2 * S_V1
        self.eta_v = 0.724 + 3.06 * (s_v / S_W) / 2 + 0.009 * A_W
        # geometry: x of the wing ac, of the tail ac; z of the wing root (chosen so the wing's lift centroid is at z=0)
        self.x_w = D_AC
        self.x_h = D_AC - L_BOOM
        eta, deta, w = elliptic_strips(N_STRIP)
        self.eta, self.deta, self.wl = eta, deta, w
        lift_centroid_rise = np.tan(DIHEDRAL) * B_W / 2 * np.sum(np.abs(eta) * w * deta) / 2
        self.z_root = lift_centroid_rise
        y = eta * B_W / 2
        z = self.z_root - np.abs(y) * np.tan(DIHEDRAL)
        n = len(eta)
        pos = np.column_stack([np.full(n, self.x_w), y, z])
        pos_v = pos - np.array([C_W / 4, 0, 0])       # pitch rate taken at mid-chord (DATCOM CLq of the wing)
        sg = np.sign(y)
        normal = np.column_stack([np.zeros(n), sg * np.sin(DIHEDRAL), np.full(n, np.cos(DIHEDRAL))])
        self.wing = Surface(pos, pos_v, normal, deta * S_W / 2, w, C_W, self.pw)
        self.ail = np.where((np.abs(eta) >= AIL_ETA[0]) & (np.abs(eta) <= AIL_ETA[1]), -sg, 0.0)
        eta_h, deta_h, w_h = elliptic_strips(N_STRIP // 2)
        nh = len(eta_h)
        pos_h = np.column_stack([np.full(nh, self.x_h), eta_h * B_H / 2, np.full(nh, self.z_root)])
        self.htail = Surface(pos_h, pos_h, np.tile([0.0, 0.0, 1.0], (nh, 1)), deta_h * S_H / 2, w_h, c_h,
                             self.ph, ETA_H, downwash=True)
        self.z_v = self.z_root - 0.45 * H_V            # fin aerodynamic centre height
        pos_v = np.array([[self.x_h, Y_BOOM, self.z_v], [self.x_h, -Y_BOOM, self.z_v]])
        self.fins = Surface(pos_v, pos_v, np.array([[0.0, 1.0, 0.0]] * 2), np.full(2, S_V1), np.ones(2), c_v,
                            self.pv, self.eta_v)
        self.r_ref = np.array([self.x_w, 0.0, 0.0])

    def downwash(self, alpha):
        """Downwash angle at the tail [rad]: lifting-line eps = 2 CL_w/(pi A) of the attached-flow lift,
        faded out with the attached-flow weight (no trailing-vortex downwash model for a stalled wing)."""
        return 2 * self.pw.weight(alpha) * self.cla_w * (alpha - ALPHA0_W) / (np.pi * A_W)

    # -- loads ---------------------------------------------------------------------------------
    def coefficients(self, alpha, beta=0.0, rates=(0.0, 0.0, 0.0), de=0.0, dr=0.0, da=0.0, deps=0.0):
        """Force and moment coefficients about the CG in body axes: (CX, CY, CZ, Cl, Cm, Cn).

        rates are the non-dimensional (phat, qhat, rhat) of docs/model.md; deps [rad] is an extra
        downwash at the tail (used for the alpha-rate derivatives).
        """
        v = np.array([np.cos(alpha) * np.cos(beta), np.sin(beta), np.sin(alpha) * np.cos(beta)])
        w = np.array([rates[0] * 2 / B_W, rates[1] * 2 / C_W, rates[2] * 2 / B_W])
        eps = self.downwash(alpha) + deps
        f1, m1 = self.wing.loads(v, w, 0.0, self.tau_a * da * self.ail)
        f2, m2 = self.htail.loads(v, w, eps, self.i_t + de)
        f3, m3 = self.fins.loads(v, w, 0.0, -self.tau_r * dr)
        cd_misc = self.cd_misc0 + self.cd_cross * np.sin(alpha) ** 2
        f4 = -0.5 * S_W * cd_misc * v
        f, m = f1 + f2 + f3 + f4, m1 + m2 + m3
        qs = 0.5 * S_W
        return np.array([f[0] / qs, f[1] / qs, f[2] / qs, m[0] / (qs * B_W), m[1] / (qs * C_W), m[2] / (qs * B_W)])

    def row(self, alpha):
        """One table row (AERO_COLUMNS order) at alpha [rad]."""
        sa, ca = np.sin(alpha), np.cos(alpha)
        rx, rz = self.r_ref[0], self.r_ref[2]

        def wind(c):      # CL, CD, CY, Cl_ref, Cm_ref, Cn_ref from CG body coefficients
            cx, cy, cz, cl, cm, cn = c
            CL = cx * sa - cz * ca
            CD = -(cx * ca + cz * sa)
            return np.array([CL, CD, cy, cl + rz * cy / B_W, cm - (rz * cx - rx * cz) / C_W, cn - rx * cy / B_W])

        h = 1e-5

        def d(name):      # central difference of wind() in one model input (rates, beta, controls, deps)
            if name in ("p", "q", "r"):
                e = np.eye(3)["pqr".index(name)] * h
                up, dn = {"rates": tuple(e)}, {"rates": tuple(-e)}
            else:
                up, dn = {name: h}, {name: -h}
            return (wind(self.coefficients(alpha, **up)) - wind(self.coefficients(alpha, **dn))) / (2 * h)

        base = wind(self.coefficients(alpha))
        dq, dde, db, dp, dr_, ddr, dda = (d(k) for k in ("q", "de", "beta", "p", "r", "dr", "da"))
        # alpha-rate: lag of the downwash, d eps = -(d eps/d alpha) (2 l_t / c) adhat (Etkin & Reid Ch. 5);
        # the attached-flow gradient faded with the attached weight keeps CLad >= 0 (no negative apparent mass)
        deps_da = 2 * self.cla_w / (np.pi * A_W) * self.pw.weight(alpha)
        dad = -d("deps") * deps_da * 2 * L_BOOM / C_W
        # the q, alpha-rate and elevator forces act at r_ref along the lift direction (docs/model.md); their
        # drag parts (tiny) are dropped with the CD column having no rate terms
        out = {
            "CL": base[0], "CD": base[1], "Cm": base[4],
            "CLq": dq[0], "CLad": dad[0], "CLde": dde[0],
            "Cmq": dq[4], "Cmad": dad[4], "Cmde": dde[4],
            "CYb": db[2], "CYp": dp[2], "CYr": dr_[2], "CYdr": ddr[2],
            "Clb": db[3], "Clp": dp[3], "Clr": dr_[3], "Clda": dda[3], "Cldr": ddr[3],
            "Cnb": db[5], "Cnp": dp[5], "Cnr": dr_[5], "Cnda": dda[5], "Cndr": ddr[5],
        }
        return np.array([out[k] for k in AERO_COLUMNS])

    def table(self, step_deg=2.0):
        a_deg = np.arange(-180.0, 180.0 + 0.5 * step_deg, step_deg)
        rows = np.array([self.row(np.radians(a)) for a in a_deg[:-1]])
        rows = np.vstack([rows, rows[:1]])
        return a_deg, rows


# ------------------------------------------------------------------------------------------- mass
def mass_properties(wing: Wing):
    """Component build-up of mass, CG and inertia about the CG (body axes).

    Returns (components, J) where J = (Jxx, Jyy, Jzz, Jxz) [kg m^2] and components is a list of
    (name, mass, x, y-extent description) for the documentation. The pod's position is solved so the
    CG is at the origin.
    """
    # wing: uniform mass per span, strips on the dihedral line, chordwise centroid at 40 % chord
    x_wcg = wing.x_w + C_W / 4 - 0.40 * C_W
    y = wing.eta * B_W / 2
    z = wing.z_root - np.abs(y) * np.tan(DIHEDRAL)
    dm = M_WING * wing.deta / 2
    Jw = np.zeros(4)
    Jw[0] = np.sum(dm * (y**2 + z**2))
    Jw[1] = np.sum(dm * (x_wcg**2 + z**2)) + M_WING * C_W**2 / 12
    Jw[2] = np.sum(dm * (x_wcg**2 + y**2)) + M_WING * C_W**2 / 12
    Jw[3] = np.sum(dm * x_wcg * z)
    mx_w, mz_w = M_WING * x_wcg, np.sum(dm * z)
    m_h, m_v = AREAL_TAIL * S_H, AREAL_TAIL * S_V1
    c_h, c_v = wing.c_h, wing.c_v
    x_h = wing.x_h - 0.25 * c_h       # plate centroid (tail pivot at its quarter chord)
    x_v = wing.x_h - 0.25 * c_v
    z_h, z_vc = wing.z_root, wing.z_root - H_V / 2
    x_b = wing.x_w - L_BOOM / 2
    items = [  # (mass, x, y, z, own Jxx, own Jyy, own Jzz)
        (m_h, x_h, 0.0, z_h, m_h * B_H**2 / 12, m_h * c_h**2 / 12, m_h * (B_H**2 + c_h**2) / 12),
        (m_v, x_v, Y_BOOM, z_vc, m_v * H_V**2 / 12, m_v * (c_v**2 + H_V**2) / 12, m_v * c_v**2 / 12),
        (m_v, x_v, -Y_BOOM, z_vc, m_v * H_V**2 / 12, m_v * (c_v**2 + H_V**2) / 12, m_v * c_v**2 / 12),
        (M_BOOM, x_b, Y_BOOM, wing.z_root, 0.0, M_BOOM * L_BOOM**2 / 12, M_BOOM * L_BOOM**2 / 12),
        (M_BOOM, x_b, -Y_BOOM, wing.z_root, 0.0, M_BOOM * L_BOOM**2 / 12, M_BOOM * L_BOOM**2 / 12),
    ]
    m_known = M_WING + sum(it[0] for it in items)
    m_pod = MASS - m_known
    x_pod = -(mx_w + sum(it[0] * it[1] for it in items)) / m_pod
    z_pod = -(mz_w + sum(it[0] * it[3] for it in items)) / m_pod
    # pod: a 1.2 m x 0.3 m x 0.3 m box (nose fairing with attachment hardware, actuators, battery)
    lp, wp = 1.2, 0.3
    items.append((m_pod, x_pod, 0.0, z_pod, m_pod * 2 * wp**2 / 12, m_pod * (lp**2 + wp**2) / 12,
                  m_pod * (lp**2 + wp**2) / 12))
    J = Jw.copy()
    for m, x, yy, zz, jx, jy, jz in items:
        J += [jx + m * (yy**2 + zz**2), jy + m * (x**2 + zz**2), jz + m * (x**2 + yy**2), m * x * zz]
    names = ["main wing", "horizontal tail", "fin right", "fin left", "boom right", "boom left", "pod"]
    comps = [(names[0], M_WING, x_wcg, mz_w / M_WING)]
    comps += [(nm, it[0], it[1], it[3]) for nm, it in zip(names[1:], items, strict=True)]
    return comps, tuple(J)


# ------------------------------------------------------------------------------------------- checks
def attachment_vector():
    return D_ATT * np.array([np.cos(ATT_ANGLE), 0.0, np.sin(ATT_ANGLE)])


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


def moment_kite(tm, alpha, de, V):
    """Pitch moment about the CG [N m] of a wing held by its cable in steady horizontal wind.

    Pitch = alpha; the net cable force balances aerodynamics and weight, F_c = -(F_aero + W).
    """
    a = attachment_vector()
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


def run_checks(tm: TableModel, wing: Wing, limits_deg):
    """Print the design checks (key numbers, trims, elevator authority)."""
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
        r = solve_alpha(lambda a: moment_kite(tm, a, 0.0, V)[0])
        s = []
        for x in r:
            _, (Fx, Fz) = moment_kite(tm, x, 0.0, V)
            elev = deg(np.arctan2(Fz * np.cos(x) - Fx * np.sin(x), Fx * np.cos(x) + Fz * np.sin(x)))
            L = tm.aero(x, 0.0, V)[3]
            s.append(f"alpha={deg(x):.2f} deg, cable force {np.hypot(Fx, Fz):.0f} N (L={L:.0f} N) at "
                     f"{elev:.1f} deg below horizontal")
        print(f"kite trim (cable force from force balance), V={V:4.1f} m/s, de=0: " + "; ".join(s))
    lo, hi = np.radians(limits_deg)
    for target in (0.0, 7.0, 15.0):
        def f(de, target=target):
            return moment_kite(tm, np.radians(target), de, V_REF)[0]
        try:
            de = brentq(f, lo, hi)
            print(f"elevator for kite trim at alpha={target:4.1f} deg (V={V_REF} m/s): de = {deg(de):6.2f} deg")
        except ValueError:
            print(f"elevator for kite trim at alpha={target:4.1f} deg: outside limits {limits_deg}")
    for de_deg in (limits_deg[0], -5.0, 0.0, 5.0, limits_deg[1]):
        r = solve_alpha(lambda a: moment_kite(tm, a, np.radians(de_deg), V_REF)[0], np.radians(-20), np.radians(30))
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


# ------------------------------------------------------------------------------------------- main
TRIM_ALPHA_DEG = 7.0  # [deg] design kite angle of attack at zero elevator (sets the tail rigging incidence)
ELEVATOR_LIMITS = (-15.0, 15.0)   # [deg] horizontal-tail angle range, choice (trim alpha spans about -20..16 deg)


def design_incidence(target_deg=TRIM_ALPHA_DEG):
    """Tail incidence [rad] that makes the cable-held wing trim at target alpha with zero elevator."""
    from scipy.optimize import brentq

    def f(it):
        w = Wing(it)
        a = np.radians(target_deg)
        # evaluate the cable-held pitch moment (see moment_kite) directly from the component model
        c = w.coefficients(a)
        qs = 0.5 * RHO_REF * V_REF**2 * S_W
        X, Z, M = qs * c[0], qs * c[2], qs * C_W * c[4]
        att = attachment_vector()
        Wx, Wz = -MASS * G * np.sin(a), MASS * G * np.cos(a)
        return M + att[2] * (-(X + Wx)) - att[0] * (-(Z + Wz))
    return brentq(f, np.radians(-10), np.radians(10))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out-dir", default="configs/wings")
    ap.add_argument("--check", action="store_true", help="print the design checks")
    args = ap.parse_args(argv)
    i_t = design_incidence()
    print(f"tail rigging incidence for a {TRIM_ALPHA_DEG} deg kite trim at {V_REF} m/s: {np.degrees(i_t):.3f} deg")
    wing = Wing(i_t)
    a_deg, rows = wing.table()
    out = Path(args.out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / "meijaard_wing_aero.csv"
    head = [
        "# Aerodynamic table of the Meijaard et al. (1999) laddermill wing (S = 54 m^2, b = 20 m, c = 2.7 m).",
        "# Made by: python -m laddermill_gym.derivations.derive_wing  (component build-up; derivation in",
        "# laddermill_gym/docs/wing_data.md). Do not edit by hand: change the script's parameters and rerun.",
        "# Units: alpha_deg in deg; coefficients dimensionless, body axes, Cm/Cl/Cn about the aero_reference point",
        "# of meijaard_wing.yaml; rate derivatives per non-dimensional rate (p b/2V, q c/2V, r b/2V, alpha' c/2V);",
        "# control derivatives per rad (elevator = horizontal-tail angle, rudder, aileron; signs in docs/model.md).",
        "# Beta derivatives per rad. Rows at -180 and 180 deg are equal (periodic cubic spline in the simulator).",
    ]
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(head) + "\n")
        fh.write(",".join(["alpha_deg", *AERO_COLUMNS]) + "\n")
        for a, r in zip(a_deg, rows, strict=True):
            fh.write(f"{a:.1f}," + ",".join(f"{v if abs(v) > 1e-12 else 0.0:.6g}" for v in r) + "\n")
    print(f"wrote {path} ({len(a_deg)} rows)")
    comps, J = mass_properties(wing)
    print("mass build-up (name, kg, x [m], z [m]):")
    for nm, m, x, z in comps:
        print(f"  {nm:16s} {m:6.2f} {x:7.3f} {z:7.3f}")
    print(f"inertia about CG: Jxx={J[0]:.1f} Jyy={J[1]:.1f} Jzz={J[2]:.1f} Jxz={J[3]:.2f} kg m^2")
    print(f"chord {C_W:.3f} m, aero_reference {wing.r_ref.tolist()}, "
          f"attachment {np.round(attachment_vector(), 4).tolist()}")
    print(f"CLa_w={wing.cla_w:.3f} CLa_h={wing.cla_h:.3f} CLa_v={wing.cla_v:.3f} e={wing.e_w:.3f} "
          f"CD0_w={wing.cd0_w:.4f} CD0_h={wing.cd0_h:.4f} CD0_v={wing.cd0_v:.4f} misc={wing.cd_misc0:.4f} "
          f"tau_a={wing.tau_a:.3f} tau_r={wing.tau_r:.3f} eta_v(1+ds/db)={wing.eta_v:.3f} z_root={wing.z_root:.3f}")
    vh = S_H * L_BOOM / (S_W * C_W)
    vv = 2 * S_V1 * (L_BOOM - D_AC) / (S_W * B_W)
    print(f"tail volumes: V_H (from wing ac) = {vh:.3f}, V_V (from CG) = {vv:.4f}; d eps/d alpha = "
          f"{2 * wing.cla_w / (np.pi * A_W):.3f}")
    if args.check:
        run_checks(TableModel(a_deg, rows, wing.r_ref), wing, ELEVATOR_LIMITS)


if __name__ == "__main__":
    main()
