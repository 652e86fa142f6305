"""The wing's component model (:class:`Wing`): main wing, horizontal tail and twin fins as strips, their
force and moment coefficients, and the aerodynamic table built from them (numerical derivatives)."""

from __future__ import annotations

import numpy as np

from laddermill_gym.derivations.wing_components import (
    Polar,
    Surface,
    elliptic_strips,
    flap_effectiveness,
    helmbold_lift_slope,
    oswald_e,
    skin_friction_cd0,
    viterna_cdmax,
)
from laddermill_gym.derivations.wing_parameters import (
    A_W,
    AIL_CF,
    AIL_ETA,
    ALPHA0_W,
    AR_V_EFF,
    B_H,
    B_W,
    C_W,
    CM0_W,
    D_AC,
    D_BOOM,
    DIHEDRAL,
    ETA_H,
    H_V,
    L_BOOM,
    N_STRIP,
    NU,
    RUD_CF,
    S_H,
    S_V1,
    S_W,
    STALL_H,
    STALL_V,
    STALL_W,
    TC_H,
    TC_V,
    TC_W,
    V_REF,
    Y_BOOM,
)
from laddermill_gym.model.params import AERO_COLUMNS


class Wing:
    """The component model, built from the parameters of :mod:`laddermill_gym.derivations.wing_parameters`."""

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
