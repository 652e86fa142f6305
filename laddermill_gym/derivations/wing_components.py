"""Building blocks of the wing's component model: the textbook formulas (Helmbold lift slope, Oswald
efficiency, skin-friction drag, Viterna flat plate, flap effectiveness), the all-angle :class:`Polar` of a
surface, the strips of a lifting :class:`Surface` and their elliptic lift weights."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laddermill_gym.derivations.wing_parameters import (
    A0_SECTION,
    M_BLEND,
    NU,
    V_REF,
)


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
