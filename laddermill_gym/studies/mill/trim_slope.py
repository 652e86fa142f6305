"""How a cable-held wing's trim angle of attack falls with its air speed (issue 30 point 1 at V_c = 5 m/s; the design
study of docs/mill_fast.md, "A wing whose lift falls with its air speed (v2)").

A wing at rest on the mill's cable in a horizontal wind V (pitch = alpha) pivots about its attachment P, where the
resultant of its two elements' tensions acts, so the tension has no moment about P; the moment of aerodynamics and
weight about P,

    M_P(alpha, q) = q S c C_m,P(alpha) + W m_w(alpha),   m_w = x_P cos(alpha) + z_P sin(alpha)

(x_P, z_P: P ahead of and below the CG, body axes; m_w: how far the CG lies behind P, horizontally), vanishes at the
trim. With k = -dM_P/d alpha the pitch stiffness about P, the implicit-function theorem gives

    d alpha / dV = -2 W m_w / (V k),   k = q S C_L,alpha h - W (z_P cos(alpha) - x_P sin(alpha)),

h the distance from P back to the neutral point (where an increment of lift acts). Only the weight's moment makes
the trim depend on speed. A lift constant with speed (C_L V^2 constant) asks d alpha / dV = -2 C_L / (V C_L,alpha),
i.e. W m_w = L h + W z_P C_L / C_L,alpha: the CG must lie L / W times as far behind P as the neutral point does
(3.8 at C_L 0.61 and 10 m/s for the 54 kg wing), which no airframe stable in free flight (CG ahead of its neutral
point) can do: the v1 wing's slope, -0.25 deg per m/s, is near that bound. The v2 wing moves the CG 0.86 m aft.

``python -m laddermill_gym.studies.mill.trim_slope`` prints, for the v1 and v2 wings at their scenes' elevators
(``--variants v0``: the v0 wing at ``ladder_chain``'s, docs/numerics.md; elevators with their sign): the trim alpha
and C_L at air speeds 6-18 m/s, the slope at 10 m/s from the trims (``sim.statics.pitch_trim_alpha``) and in closed
form, the geometry (m_w, h, the free-flight margin), and each leg's trim at the air speed
10 m/s -+ V_c for V_c = 1, 2, 5 m/s (ascending wings meet the wind less the cable speed, descending ones more).
``--lost`` prints instead, per air speed, the elevators at which the attached-flow trim is lost (:func:`lost_bounds`).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.statics import pitch_trim_alpha, table_spline
from laddermill_gym.studies.commands import Parser

RHO = 1.225  # [kg/m^3] ISA sea level, the scenes' wind.rho0
G = 9.80665  # [m/s^2] standard gravity, the scenes' gravity
V_REF = 10.0  # [m/s] design air speed (derive_wing's V_REF, docs/wing_data.md)
SPEEDS = (6.0, 8.0, 10.0, 12.0, 15.0, 18.0)  # [m/s] air speeds of the printed trims
CABLE_SPEEDS = (1.0, 2.0, 5.0)  # [m/s] the paper's cable speeds (issue 30 point 1)
NEUTRAL_POINT_BEHIND_AC = 0.97  # [m] the airframe's neutral point behind the main wing's ac (docs/wing_data.md, "Key
#                                 numbers": 0.22 m behind v1's CG, which lies 0.75 m behind the ac)
WINGS = {"v1": ("meijaard_wing_v1.yaml", "laddermill_v1.yaml"), "v2": ("meijaard_wing_v2.yaml", "laddermill_v2.yaml"),
         # the v0 wing of the chain at rest (ladder_chain, docs/numerics.md's elevators), printed only when asked
         "v0": ("meijaard_wing.yaml", "ladder_chain.yaml")}
DEFAULT_VARIANTS = ("v1", "v2")  # the mill's wings (the command's default)


def load(variant: str):
    """The wing type and the (ascending, descending) elevators [rad] of a variant's scene."""
    from laddermill_gym.ladder.scene_files import load_wing_type
    from laddermill_gym.model.configio import config_path, read_yaml

    wing_file, scene_file = WINGS[variant]
    wing = load_wing_type(Path(config_path("wings", wing_file)))
    ini = read_yaml(Path(config_path("scenes", scene_file))).section("initial")
    return wing, (math.radians(ini.number("elevator_up_deg")), math.radians(ini.number("elevator_down_deg")))


def trim(wing, elevator: float, speed: float) -> float:
    """Trim alpha [rad] of the wing at rest in a horizontal wind ``speed`` [m/s] (the simulator's statics)."""
    return pitch_trim_alpha(wing, elevator, 0.5 * RHO * speed**2, G)


def lift_coefficient(wing, alpha: float, elevator: float) -> float:
    c = table_spline(wing.aero)(alpha)
    return float(c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * elevator)


def moment_about_attachment(wing, alpha: float, elevator: float, speed: float) -> float:
    """M_P [N m], nose up, of aerodynamics and weight about the attachment (module docstring)."""
    c = table_spline(wing.aero)(alpha)
    cl = c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * elevator
    cd, cm = c[AERO_INDEX["CD"]], c[AERO_INDEX["Cm"]] + c[AERO_INDEX["Cmde"]] * elevator
    qs = 0.5 * RHO * speed**2 * wing.area
    fx, fz = qs * (cl * math.sin(alpha) - cd * math.cos(alpha)), qs * (-cl * math.cos(alpha) - cd * math.sin(alpha))
    rx, rz = wing.r_ref[0] - wing.attachment[0], wing.r_ref[2] - wing.attachment[2]  # aero reference from P
    return float(qs * wing.chord * cm + rz * fx - rx * fz + wing.mass * G * weight_lever(wing, alpha))


def weight_lever(wing, alpha: float) -> float:
    """m_w [m]: how far the CG lies behind the attachment, horizontally, at pitch = alpha."""
    return float(wing.attachment[0] * math.cos(alpha) + wing.attachment[2] * math.sin(alpha))


def closed_form_slope(wing, elevator: float, speed: float) -> float:
    """d alpha / dV [rad per m/s] at the trim: -2 W m_w / (V k), k = -dM_P/d alpha."""
    a, h = trim(wing, elevator, speed), 1e-5
    k = -(moment_about_attachment(wing, a + h, elevator, speed)
          - moment_about_attachment(wing, a - h, elevator, speed)) / (2 * h)
    return -2.0 * wing.mass * G * weight_lever(wing, a) / (speed * k)


def geometry(wing) -> dict:
    """Lengths along body x [m]: the CG behind P (m_w at alpha 0), the neutral point behind P and behind the CG."""
    x_np = wing.r_ref[0] - NEUTRAL_POINT_BEHIND_AC
    return {"cg_behind_P": float(wing.attachment[0]), "np_behind_P": float(wing.attachment[0] - x_np),
            "np_behind_cg": float(-x_np)}


LOST_SEARCH_DEG = (0.0, 12.0)  # [deg] elevators searched by lost_bounds (v2's scene: +1.3 / +2.5 deg)
STALL_DEG = 15.0  # [deg] a trim above this angle of attack is post-stall (the v2 table's C_L peaks near 12 deg)


def trim_kind(wing, elevator: float, speed: float) -> tuple[str, float]:
    """("attached" | "post-stall" | "none", alpha [rad]) of :func:`trim`'s answer: a root of M_P (to 1e-6 of q S c)
    below :data:`STALL_DEG` and above the search's lower end (-10 deg), a root above it, or no root (pitch_trim_alpha
    then returns its grid point of least moment)."""
    a = trim(wing, elevator, speed)
    qsc = 0.5 * RHO * speed**2 * wing.area * wing.chord
    if abs(moment_about_attachment(wing, a, elevator, speed)) > 1e-6 * qsc:
        return "none", a
    if a > math.radians(STALL_DEG):
        return "post-stall", a
    return ("attached" if a > math.radians(-9.999) else "none"), a


def _bisect(pred, lo: float, hi: float, tol: float = math.radians(1e-3)) -> float:
    """The elevator [rad] where ``pred`` turns from False (at lo) to True (at hi), to ``tol``."""
    while hi - lo > tol:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if pred(mid) else (mid, hi)
    return hi


def lost_bounds(wing, speed: float) -> dict:
    """Where the attached trim is lost at air speed ``speed`` [m/s], elevators [rad] bisected in
    :data:`LOST_SEARCH_DEG`: ``attached_up_to``, the largest elevator with an attached trim (above it the attached
    root's alpha falls below -10 deg, out of the search), and ``post_stall_from``, the smallest with a post-stall
    root (None: none in the range), each with its trim alpha [rad] and C_L."""
    lo, hi = (math.radians(e) for e in LOST_SEARCH_DEG)
    if trim_kind(wing, lo, speed)[0] != "attached" or trim_kind(wing, hi, speed)[0] == "attached":
        raise ValueError(f"{wing.name} at {speed} m/s: the attached trim is not lost between {LOST_SEARCH_DEG} deg")
    up = _bisect(lambda e: trim_kind(wing, e, speed)[0] != "attached", lo, hi)
    up -= math.radians(1e-3)  # the last attached elevator of the bracket
    post = None
    if trim_kind(wing, hi, speed)[0] == "post-stall":
        post = _bisect(lambda e: trim_kind(wing, e, speed)[0] == "post-stall", up, hi)
    out = {}
    for key, e in (("attached_up_to", up), ("post_stall_from", post)):
        if e is not None:
            a = trim(wing, e, speed)
            out[key] = (e, a, lift_coefficient(wing, a, e))
        else:
            out[key] = None
    return out


def report_lost(variant: str) -> None:
    wing, _ = load(variant)
    print(f"{variant} ({wing.name}): where the attached trim is lost (pitch_trim_alpha, search -10..25 deg; elevators "
          f"bisected to 0.001 deg in {LOST_SEARCH_DEG[0]:g}..{LOST_SEARCH_DEG[1]:g} deg; post-stall above "
          f"{STALL_DEG:g} deg)")
    for v in SPEEDS:
        b = lost_bounds(wing, v)
        e, a, cl = b["attached_up_to"]
        text = (f"  {v:4.0f} m/s: attached up to {math.degrees(e):5.2f} deg (alpha {math.degrees(a):6.2f} deg, "
                f"C_L {cl:5.2f}); ")
        if b["post_stall_from"] is None:
            text += f"no post-stall trim up to {LOST_SEARCH_DEG[1]:g} deg"
        else:
            e, a, cl = b["post_stall_from"]
            text += f"post-stall trim from {math.degrees(e):5.2f} deg (alpha {math.degrees(a):5.2f} deg, C_L {cl:4.2f})"
        print(text)


def report(variant: str, elevators_deg=None) -> None:
    wing, (up, down) = load(variant)
    if elevators_deg is not None:
        up, down = (math.radians(e) for e in elevators_deg)
    g = geometry(wing)
    print(f"{variant} ({wing.name}): CG {g['cg_behind_P']:.3f} m behind P, neutral point {g['np_behind_P']:.3f} m "
          f"behind P (h), {g['np_behind_cg']:+.3f} m behind the CG "
          f"(free-flight margin {g['np_behind_cg'] / wing.chord:+.3f} c)")
    print("  leg         elevator  " + "  ".join(f"{v:4.0f} m/s  " for v in SPEEDS)
          + "  d alpha/dV at 10 m/s: trims | closed form [deg per m/s]")
    for leg, de in (("ascending", up), ("descending", down)):
        cells = []
        for v in SPEEDS:
            a = trim(wing, de, v)
            cells.append(f"{math.degrees(a):5.2f}/{lift_coefficient(wing, a, de):4.2f}")
        num = (trim(wing, de, V_REF + 0.05) - trim(wing, de, V_REF - 0.05)) / 0.1
        print(f"  {leg:11s} {math.degrees(de):+6.2f}    " + "  ".join(cells)
              + f"    {math.degrees(num):6.3f} | {math.degrees(closed_form_slope(wing, de, V_REF)):6.3f}")
    print("  (cells: trim alpha [deg] / C_L)")
    for vc in CABLE_SPEEDS:
        parts = []
        for leg, de, v in (("ascending", up, V_REF - vc), ("descending", down, V_REF + vc)):
            a = trim(wing, de, v)
            cl = lift_coefficient(wing, a, de)
            parts.append(f"{leg} at {v:4.1f} m/s: alpha {math.degrees(a):5.2f} deg, C_L {cl:4.2f}, "
                         f"lift {0.5 * RHO * v * v * wing.area * cl / 1e3:5.2f} kN")
        print(f"  V_c {vc:g} m/s: " + "; ".join(parts))


def main(argv=None) -> int:
    p = Parser(prog="python -m laddermill_gym.studies.mill.trim_slope", description=__doc__.split("\n\n")[0])
    p.add_argument("--variants", nargs="+", choices=sorted(WINGS), default=list(DEFAULT_VARIANTS),
                   help="v1, v2: the mill's wings (default); v0: the chain's wing at ladder_chain's elevators")
    p.add_argument("--elevators", type=float, nargs=2, default=None,
                   help="ascending, descending elevators [deg] instead of the scenes'")
    p.add_argument("--lost", action="store_true",
                   help="print where the attached trim is lost instead, per air speed (the elevator range searched: "
                        f"{LOST_SEARCH_DEG[0]:g}..{LOST_SEARCH_DEG[1]:g} deg)")
    a = p.parse_args(argv)
    if a.lost and a.elevators is not None:
        p.error("--lost searches the elevators itself: leave out --elevators")
    if a.elevators is not None and not all(abs(e) < 90.0 for e in a.elevators):  # NaN too: a table of nan before
        p.error(f"--elevators = {a.elevators}: each must be a finite angle within +-90 deg")
    for v in a.variants:
        report_lost(v) if a.lost else report(v, a.elevators)
    return 0


__all__ = ["closed_form_slope", "geometry", "load", "lost_bounds", "moment_about_attachment", "trim", "trim_kind",
           "weight_lever"]

if __name__ == "__main__":
    np.set_printoptions(precision=4)
    raise SystemExit(main())
