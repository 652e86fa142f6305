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

The pieces live beside this command: ``wing_parameters`` (the numbers), ``wing_components`` (formulas, polars,
strips), ``wing_model`` (the component model and its table), ``wing_mass`` (mass build-up) and ``wing_checks``
(the design checks of ``--check``).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from laddermill_gym.derivations.pitch_stability import pitch_mode, print_design_study
from laddermill_gym.derivations.wing_checks import (
    TableModel,
    attachment_vector,
    moment_fixed_tether,
    moment_kite,
    run_checks,
    solve_alpha,
)
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
from laddermill_gym.derivations.wing_mass import (
    mass_properties,
)
from laddermill_gym.derivations.wing_model import (
    Wing,
)
from laddermill_gym.derivations.wing_parameters import (
    A0_SECTION,
    A_W,
    AIL_CF,
    AIL_ETA,
    ALPHA0_W,
    AR_V_EFF,
    AREAL_TAIL,
    ATT_ANGLE,
    ATT_ANGLE_V1,
    B_H,
    B_W,
    C_W,
    CM0_W,
    D_AC,
    D_ATT,
    D_BOOM,
    DEG,
    DIHEDRAL,
    ETA_H,
    H_V,
    L_BOOM,
    M_BLEND,
    M_BOOM,
    M_WING,
    MASS,
    N_STRIP,
    NU,
    RHO_REF,
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
    G,
)
from laddermill_gym.model.params import AERO_COLUMNS

__all__ = [
    "attachment_vector",
    "TableModel",
    "moment_kite",
    "moment_fixed_tether",
    "solve_alpha",
    "run_checks",
    "helmbold_lift_slope",
    "oswald_e",
    "skin_friction_cd0",
    "viterna_cdmax",
    "flap_effectiveness",
    "Polar",
    "Surface",
    "elliptic_strips",
    "mass_properties",
    "Wing",
    "S_W",
    "B_W",
    "MASS",
    "D_AC",
    "D_ATT",
    "L_BOOM",
    "C_W",
    "A_W",
    "DIHEDRAL",
    "TC_W",
    "A0_SECTION",
    "ALPHA0_W",
    "CM0_W",
    "AIL_ETA",
    "AIL_CF",
    "DEG",
    "S_H",
    "B_H",
    "TC_H",
    "ETA_H",
    "S_V1",
    "H_V",
    "AR_V_EFF",
    "TC_V",
    "Y_BOOM",
    "D_BOOM",
    "RUD_CF",
    "ATT_ANGLE",
    "RHO_REF",
    "V_REF",
    "NU",
    "G",
    "STALL_W",
    "STALL_H",
    "STALL_V",
    "M_BLEND",
    "M_WING",
    "AREAL_TAIL",
    "M_BOOM",
    "N_STRIP",
    "TRIM_ALPHA_DEG",
    "ELEVATOR_LIMITS",
    "VARIANTS",
    "design_incidence",
    "main",
]

TRIM_ALPHA_DEG = 7.0  # [deg] design kite angle of attack at zero elevator (sets the tail rigging incidence)
ELEVATOR_LIMITS = (-15.0, 15.0)   # [deg] horizontal-tail angle range, choice (trim alpha spans about -20..16 deg)
#: the variants the command checks: attachment angle below body x [rad] and the (ascending, descending) elevators
#: [deg] of their scenes (configs/scenes/laddermill.yaml for v0, laddermill_v1.yaml for v1)
VARIANTS = {"v0": (ATT_ANGLE, (-4.0, -1.0)), "v1": (ATT_ANGLE_V1, (-8.0, -0.5))}


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


def print_quoted_extras(tm: TableModel, wing: Wing) -> None:
    """Print figures docs/wing_data.md quotes beside the design checks (printing only): the side-force rate
    derivatives CYp, CYr and the aileron's yaw in stability axes (Cn cos alpha - Cl sin alpha, per rad) at 0/7/14/30/90
    deg in the derivative lines' format, the main wing's own 3-D curve's C_L,max and its alpha (no tail, no dihedral),
    the booms' cross-flow drag coefficient (times sin^2 alpha, referred to S_W) and the v0 wing's trim and C_L on the
    cable at elevator 0 (:func:`pitch_mode`)."""
    angles = np.radians([0.0, 7.0, 14.0, 30.0, 90.0])
    for name in ("CYp", "CYr"):
        print(f"  {name:5s} at 0/7/14/30/90 deg: " + " ".join(f"{tm.col(a, name):8.4f}" for a in angles))
    stab = [tm.col(a, "Cnda") * np.cos(a) - tm.col(a, "Clda") * np.sin(a) for a in angles]
    print("  Cnda_stability at 0/7/14/30/90 deg: " + " ".join(f"{v:8.4f}" for v in stab))
    al = np.radians(np.arange(-10, 30.01, 0.05))
    cl = wing.pw(al)[0]
    i = int(np.argmax(cl))
    print(f"wing alone (main wing's 3-D curve): C_L,max = {cl[i]:.3f} at alpha = {np.degrees(al[i]):.2f} deg; boom "
          f"cross-flow drag {wing.cd_cross:.4f} sin^2 alpha")
    zero = pitch_mode(tm, 0.0, ATT_ANGLE)  # the v0 wing on the cable at elevator 0 (the pitch check's trim)
    print(f"v0 attachment at elevator 0 deg (steady 10 m/s): trim alpha {zero[0]:.2f} deg, C_L {zero[1]:.3f}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out-dir", default="configs/wings")
    ap.add_argument("--check", action="store_true", help="print the design checks")
    ap.add_argument("--variant", choices=sorted(VARIANTS), default="v0",
                    help="the attachment whose trims --check prints (the table is the same for both)")
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
        tm = TableModel(a_deg, rows, wing.r_ref)
        run_checks(tm, wing, ELEVATOR_LIMITS, VARIANTS[args.variant][0])
        print_quoted_extras(tm, wing)
        print_design_study(tm, {k: (att, {"ascending": np.radians(up), "descending": np.radians(dn)})
                                for k, (att, (up, dn)) in VARIANTS.items()})


if __name__ == "__main__":
    main()
