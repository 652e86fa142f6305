"""Linearised pitch check of a wing held at its cable attachment (issue 30's design study, docs/wing_data.md,
"Design study: a stable in-plane mill").

In the mill the two cable elements at a wing carry tens of kN over 70 m: the attachment is held against sideways
motion far more stiffly than the wing's pitch (a normal stiffness of 2 T / l0, several kN/m, against a pitch
stiffness of a few kN m/rad on a 1.5 m lever), so for pitch the wing pivots about its attachment P. In a steady
horizontal wind V (pitch = alpha) the moment about P of aerodynamics and weight is ``wing_checks.moment_kite``;
linearised at a trim alpha_0 (moment zero):

    J_P theta'' = -k theta - c theta',   k = -dM_P/d alpha,   J_P = J_yy + m |r_P|^2,

with c the aerodynamic pitch damping about the aero reference, q S c (c / 2V) (-(C_mq + C_mad)) (the tail's
damping; the pivot's own translation is left out, which only adds damping when P lies ahead of the wing's ac).
Printed per leg: the trim alpha and C_L at the leg's elevator, k, the margin about the attachment
h_P = k / (q S c C_L,alpha) (the distance, in chords, from P back to the point where an increment of lift acts
when the wing pivots about P), the frequency and the damping ratio. A pitch mode with small k on the lightly
loaded descending leg is what the v0 wing shows in the mill (docs/moving_cable.md).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.derivations.wing_checks import TableModel, attachment_vector, moment_kite, solve_alpha
from laddermill_gym.derivations.wing_parameters import C_W, DEG, MASS, RHO_REF, S_W

__all__ = ["PitchMode", "pitch_mode", "print_design_study"]

JYY = 245.3  # [kg m^2] pitch inertia about the CG, configs/wings/meijaard_wing.yaml (derive_wing's mass build-up)
STUDY_SPEED = 10.0  # [m/s] apparent wind of the printed study (derive_wing's design point V_REF)


class PitchMode(tuple):
    """(alpha_deg, CL, k [N m/rad], h_P [chords], omega [rad/s], zeta [-]) of one trim."""

    __slots__ = ()

    def __new__(cls, *values):
        return super().__new__(cls, values)


def pitch_mode(tm: TableModel, de: float, att_angle: float, V: float = STUDY_SPEED) -> PitchMode | None:
    """The linearised pitch mode of a wing pivoting about its attachment (``att_angle`` [rad] below body x) at the
    elevator ``de`` [rad] in a steady wind V [m/s]; None when the moment has no stable root in -20..30 deg."""
    roots = solve_alpha(lambda a: moment_kite(tm, a, de, V, att_angle)[0], np.radians(-20), np.radians(30))
    if not roots:
        return None
    a0, h = roots[0], 1e-4
    k = -(moment_kite(tm, a0 + h, de, V, att_angle)[0] - moment_kite(tm, a0 - h, de, V, att_angle)[0]) / (2 * h)
    qs = 0.5 * RHO_REF * V**2 * S_W
    cla = (tm.col(a0 + h, "CL") - tm.col(a0 - h, "CL")) / (2 * h)
    cl = tm.col(a0, "CL") + tm.col(a0, "CLde") * de
    damp = -qs * C_W * (C_W / (2 * V)) * (tm.col(a0, "Cmq") + tm.col(a0, "Cmad"))
    j_p = JYY + MASS * float(np.sum(attachment_vector(att_angle) ** 2))
    omega = np.sqrt(max(k, 0.0) / j_p)
    zeta = damp / (2 * np.sqrt(k * j_p)) if k > 0 else float("nan")
    return PitchMode(a0 / DEG, cl, k, k / (qs * C_W * cla), omega, zeta)


def print_design_study(tm: TableModel, variants: dict, V: float = STUDY_SPEED) -> None:
    """Print the pitch mode per variant and leg: ``variants`` maps a name to (attachment angle [rad],
    {leg: elevator [rad]})."""
    print(f"pitch about the attachment (linearised, steady wind {V:.0f} m/s; derivations/pitch_stability.py):")
    print("  variant  leg         elevator  alpha   CL     k [kN m/rad]  h_P [c]  omega [rad/s]  zeta")
    for name, (att, legs) in variants.items():
        for leg, de in legs.items():
            m = pitch_mode(tm, de, att, V)
            if m is None:
                print(f"  {name:8s} {leg:11s} {de / DEG:6.1f}   no stable trim in -20..30 deg")
                continue
            a, cl, k, hp, om, ze = m
            print(f"  {name:8s} {leg:11s} {de / DEG:6.1f}  {a:6.2f} {cl:6.3f}  {k / 1e3:10.2f}  {hp:8.3f}  "
                  f"{om:10.2f}  {ze:8.3f}")
