"""Tail settings per case of the power curve (issue 30 point 3): the rules that set the mill's elevators from the
wind speed V0 (the wind at h0 = 50 m).

``scene``: the scene's own elevators for every V0 and V_c (v2: ascending +1.3, descending +2.5 deg).

``depower``: at and below the paper's wind (V0 <= 8 m/s) the scene's elevators; above it each leg's elevator is set
so that the wing's trim lift coefficient falls with the wind as

    C_L,trim(d(V0), V0) = C_L,trim(d_s, 8 m/s) (8 / V0)^n,   n = 2 ascending, n = 1.75 descending,

d_s the scene's elevator of the leg, C_L,trim(d, V) the lift coefficient C_L(alpha) + C_L,de(alpha) d from the wing's
table at the trim alpha of a wing at rest on the cable in a horizontal wind V at sea-level density (the zero of the
moment of aerodynamics and weight about the attachment, ``sim.statics.pitch_trim_alpha``; docs/mill_fast.md, "The
trim on the cable, by analysis"). The ascending wings keep the aerodynamic load q C_L of the paper's wind (their
pull sets the largest tension, the first element's at the ground); the descending wings' load grows as V0^0.25
(DEPOWER_EXPONENTS: with n = 2 the v2 scene gets no rest state at 10 and 12 m/s, with n = 1 the descending leg
outpulls the ascending one and the mill takes power). C_L and
C_m are linear in the elevator (the table's CLde, Cmde columns), so for a target C_L the trim is one equation in
alpha, d = (C_L,target - C_L(alpha)) / C_L,de(alpha) with M_P(alpha, d, q) = 0; the elevator is found by a bracketed
root search on the trim's C_L against d on the attached-flow trim branch (the C_L falls as d grows: a larger
elevator trims a lower alpha). The wind above h0 (V0 + V1 (h - h0), whose second part does not scale with V0) loads
the high wings a little less than the rule's reference wind.
"""

from __future__ import annotations

import math

from scipy.optimize import brentq

from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.statics import pitch_trim_alpha, table_spline

RULES = ("scene", "depower")  # tail rules; `laddermill power-curve` flies depower by default (the scene's up to 8 m/s)
REF_V0 = 8.0  # [m/s] Meijaard et al. 1999, the example's wind at h0 = 50 m: the load the depower rule keeps
RHO0 = 1.225  # [kg/m^3] ISA sea level, the scenes' wind.rho0: the trim's dynamic pressure 0.5 RHO0 V0^2
BRACKET_STEP = math.radians(0.1)  # [rad] the scan that brackets the elevator on the attached-flow trim branch
#: [-] (ascending, descending) exponents n of the depower rule's C_L (8 / V0)^n: the ascending wings keep the load of
#: the paper's wind (n = 2; their pull sets the largest tension, the first element's); the descending wings' load grows
#: as V0^0.25 (n = 1.75, chosen by measurement, docs/power_curve.md: with n = 2 the v2 scene gets no rest state at 10
#: and 12 m/s, the chain layout's shooting missing the ground point by 0.34 and 12.9 m; with n = 1 the descending leg
#: outpulls the ascending one, -47.9 kW periodic at V0 12 m/s, V_c 2 m/s)
DEPOWER_EXPONENTS = (2.0, 1.75)
ELEVATOR_MAX = math.radians(15.0)  # [rad] the wing's elevator travel, +-15 deg (docs/wing_data.md, control limits)


def trim_lift_coefficient(wing_type, elevator: float, speed: float, gravity: float = 9.80665) -> float:
    """C_L [-] of a wing at rest on the cable in a horizontal wind ``speed`` [m/s] at sea-level density, trimmed at
    ``elevator`` [rad]: the table's C_L + C_L,de d at ``pitch_trim_alpha``."""
    a = pitch_trim_alpha(wing_type, elevator, 0.5 * RHO0 * speed ** 2, gravity)
    c = table_spline(wing_type.aero)(a)
    return float(c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * elevator)


def depowered_elevator(wing_type, scene_elevator: float, v0: float, exponent: float,
                       gravity: float = 9.80665) -> float:
    """The elevator [rad] whose trim C_L at ``v0`` [m/s] is the scene elevator's at REF_V0 times
    (REF_V0 / v0)^exponent; the scene's elevator for v0 <= REF_V0. Raises ValueError when the target is not reached
    on the attached-flow trim within the elevator's travel."""
    if not v0 > REF_V0:
        return float(scene_elevator)
    target = trim_lift_coefficient(wing_type, scene_elevator, REF_V0, gravity) * (REF_V0 / v0) ** exponent

    def f(d):
        return trim_lift_coefficient(wing_type, d, v0, gravity) - target

    lo, hi = _attached_bracket(wing_type, float(scene_elevator), v0, f, gravity)
    return float(brentq(f, lo, hi, xtol=1e-10))


def _attached_bracket(wing_type, lo: float, v0: float, f, gravity: float) -> tuple[float, float]:
    """(d_i, d_i+1) [rad]: the first step of BRACKET_STEP from ``lo`` up to ELEVATOR_MAX over which ``f`` changes
    sign while the trim alpha falls (the attached-flow branch: beyond it pitch_trim_alpha jumps to a post-stall trim
    near 23 deg, whose C_L is again about 0.7). ValueError when the branch ends before the target."""
    q = 0.5 * RHO0 * v0 ** 2
    d, a, fd = lo, pitch_trim_alpha(wing_type, lo, q, gravity), f(lo)
    while d < ELEVATOR_MAX:
        dn = min(d + BRACKET_STEP, ELEVATOR_MAX)
        an, fn = pitch_trim_alpha(wing_type, dn, q, gravity), f(dn)
        if an > a:
            break
        if fd >= 0.0 > fn:
            return d, dn
        d, a, fd = dn, an, fn
    raise ValueError(f"depower rule at V0 = {v0:g} m/s: the target trim C_L is not reached on the attached-flow "
                     f"trim between {math.degrees(lo):.2f} and {math.degrees(d):.2f} deg of elevator (the trim C_L "
                     f"there is still {fd:+.3f} above it)")


def tail_rule(scene_initial, wing_type, v0: float, rule: str = RULES[0]) -> tuple[float, float]:
    """(ascending, descending) elevator [deg] of a case at wind ``v0`` [m/s] by the tail rule (module docstring):
    ``scene``, the scene's own settings for every V0 and V_c; ``depower``, the scene's up to the paper's 8 m/s and
    above it the elevators whose trim C_L is the scene's at 8 m/s times (8 / V0)^n, n = 2 ascending and 1.75
    descending (DEPOWER_EXPONENTS, :func:`depowered_elevator`)."""
    up, down = float(scene_initial.elevator_up), float(scene_initial.elevator_down)
    if rule == "depower":
        up, down = (depowered_elevator(wing_type, e, v0, p) for e, p in zip((up, down), DEPOWER_EXPONENTS, strict=True))
    elif rule != "scene":
        raise ValueError(f"tail rule {rule!r}: use one of {RULES}")
    return math.degrees(up), math.degrees(down)


__all__ = ["DEPOWER_EXPONENTS", "ELEVATOR_MAX", "REF_V0", "RULES", "depowered_elevator", "tail_rule",
           "trim_lift_coefficient"]
