"""Physics and estimates behind the 35 m rotorcraft design study (``laddermill_gym.studies.rotorcraft.rotor_design``):
the ISA troposphere, the heavy inextensible catenary of a tether, and the component mass build-up of a twin-rotor
craft. Units SI; sources and choices in ``laddermill_gym/docs/rotorcraft_design.md``."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: International foot [m].
FOOT = 0.3048

# ISA troposphere (ICAO Doc 7488): sea-level temperature [K] and pressure [Pa], lapse rate [K/m], gas constant of
# air [J/(kg K)], standard gravity [m/s^2], ratio of specific heats [-], tropopause [m].
_T0, _P0, _LAPSE, _R_AIR, _G0, _GAMMA, _H_TROPO = 288.15, 101325.0, 0.0065, 287.05287, 9.80665, 1.4, 11000.0


def number(name: str, value, lo: float = -math.inf, hi: float = math.inf, *, lo_open: bool = False) -> float:
    """``value`` as a float when it is a finite number in [lo, hi] (lo excluded with ``lo_open``); a ValueError
    naming the argument ``name`` and the value otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise ValueError(f"argument '{name}' = {value!r}: must be a number")
    v = float(value)
    if not math.isfinite(v) or v < lo or v > hi or (lo_open and v == lo):
        raise ValueError(f"argument '{name}' = {value!r}: must be finite and lie in {'(' if lo_open else '['}"
                         f"{lo}, {hi}]")
    return v


# ------------------------------------------------------------------------------------------ atmosphere
def isa_temperature(altitude: float) -> float:
    """ISA temperature [K] at geopotential altitude [m] (troposphere, -500 m .. 11 km)."""
    return _T0 - _LAPSE * number("altitude", altitude, -500.0, _H_TROPO)


def isa_density(altitude: float) -> float:
    """ISA air density [kg/m^3] at geopotential altitude [m] (troposphere, -500 m .. 11 km).

    rho = p / (R T) with T = T0 - L h and p = p0 (T / T0)^(g0 / (R L)) (ICAO standard atmosphere).
    """
    t = isa_temperature(altitude)
    return _P0 * (t / _T0) ** (_G0 / (_R_AIR * _LAPSE)) / (_R_AIR * t)


def speed_of_sound(altitude: float) -> float:
    """ISA speed of sound sqrt(gamma R T) [m/s] at altitude [m] (troposphere)."""
    return math.sqrt(_GAMMA * _R_AIR * isa_temperature(altitude))


# ------------------------------------------------------------------------------------------ catenary
@dataclass(frozen=True)
class Catenary:
    """A heavy inextensible cable from its anchor (origin) to its upper end at (span, height); no wind on it.

    Attributes
    ----------
    horizontal : float
        Horizontal tension H [N], the same all along the cable (>= 0).
    top_vertical : float
        Vertical tension at the upper end V_t [N] (> 0: the craft pulls the cable up).
    anchor_vertical : float
        Vertical tension at the anchor V_a = V_t - w L [N]: the anchor is pulled up by V_a; V_a >= 0 means
        the cable leaves the anchor upwards (none of it would lie on the ground).
    weight : float
        Cable weight w L [N].
    span, height : float
        Horizontal and vertical distance from the anchor to the upper end [m].
    """

    horizontal: float
    top_vertical: float
    anchor_vertical: float
    weight: float
    span: float
    height: float

    @property
    def top_tension(self) -> float:
        """Tension at the upper end [N], the largest along the cable."""
        return math.hypot(self.horizontal, self.top_vertical)

    @property
    def anchor_tension(self) -> float:
        """Tension at the anchor [N] (= top tension - w height)."""
        return math.hypot(self.horizontal, self.anchor_vertical)

    @property
    def top_angle(self) -> float:
        """Cable angle above the horizontal at the upper end [rad]."""
        return math.atan2(self.top_vertical, self.horizontal)

    @property
    def anchor_angle(self) -> float:
        """Cable angle above the horizontal at the anchor [rad] (< 0: the cable dips below the anchor)."""
        return math.atan2(self.anchor_vertical, self.horizontal)

    @property
    def chord_angle(self) -> float:
        """Elevation of the straight line from the anchor to the upper end [rad]."""
        return math.atan2(self.height, self.span)


def catenary(horizontal: float, top_vertical: float, weight_per_length: float, length: float) -> Catenary:
    """Shape and end forces of a heavy inextensible cable, given the tension vector at its upper end.

    Parameters
    ----------
    horizontal : float
        Horizontal component H of the upper-end tension [N], >= 0.
    top_vertical : float
        Vertical component V_t of the upper-end tension [N] (any sign).
    weight_per_length : float
        Cable weight per length w = m' g [N/m], > 0.
    length : float
        Cable length L [m], > 0.

    Returns
    -------
    Catenary
        V_a = V_t - w L, span = (H/w) [asinh(V_t/H) - asinh(V_a/H)],
        height = [sqrt(H^2 + V_t^2) - sqrt(H^2 + V_a^2)] / w. With H = 0 the cable hangs straight (V_a >= 0).

    Raises
    ------
    ValueError
        On a bad argument (naming it and its value), or for H = 0 with V_a < 0 (a slack cable has no shape).
    """
    h = number("horizontal", horizontal, 0.0)
    vt = number("top_vertical", top_vertical)
    w = number("weight_per_length", weight_per_length, 0.0, lo_open=True)
    length = number("length", length, 0.0, lo_open=True)
    va = vt - w * length
    if h == 0.0:
        if va < 0.0:
            raise ValueError(f"argument 'top_vertical' = {top_vertical!r}: with horizontal = 0 it must be at least "
                             f"the cable weight {w * length!r} N (a slack vertical cable has no single shape)")
        return Catenary(0.0, vt, va, w * length, 0.0, length)
    span = h / w * (math.asinh(vt / h) - math.asinh(va / h))
    height = (math.hypot(h, vt) - math.hypot(h, va)) / w
    return Catenary(h, vt, va, w * length, span, height)


# ------------------------------------------------------------------------------------------ craft estimate
#: Layout of the mass build-up [m], origin at the midpoint between the hubs, x forward, z down: drive and
#: generator below each hub, frame beams below that, keel from fins to nose; share of the frame in the lateral
#: beam [-]; generator speed [rpm]; generator mass per power [kg/kW]; frame over the rest [-]. All chosen
#: (rotorcraft_design.md, "Mass and inertia").
NACELLE_DROP, FRAME_DROP, KEEL_X, LATERAL_SHARE = 1.5, 3.0, (-14.0, 9.5), 0.6
#: Hub-to-hub distance of the 35 m craft [m]; chosen: 3 m between the disks (rotorcraft_design.md).
HUB_SPACING = 38.0
#: Tip speeds of the command's rotor-speed scan [m/s].
TIP_SPEEDS: tuple[float, ...] = tuple(float(v) for v in range(160, 261, 10))
GENERATOR_RPM, GENERATOR_KG_PER_KW, FRAME_FRACTION = 1500.0, 0.8, 0.3


def craft_estimate(radius: float, tip_speed: float, sigma: float, n_blades: int, shaft_power: float,
                   hub_spacing: float) -> dict[str, float]:
    """Masses [kg], CG, inertia [kg m^2] of a twin-rotor craft by component weight models and a point build-up.

    Blades, hub and drive (gearbox) per rotor from the AFDD weight equations in Johnson, *NDARC Theory*
    (NASA/TP-2015-218751): blades 0.02606 b^0.6592 R^1.3371 c^0.9959 V_tip^0.6682, hub 0.003722 b^0.2807
    R^1.5377 V_tip^0.4290 W_blades^0.5505, drive 95.7634 P^0.78137 N_gen^0.09899 / N_rotor^0.80686 (lb, ft,
    ft/s, hp, rpm; flap frequency 1/rev, technology factors 1). Generators GENERATOR_KG_PER_KW; frame, fins
    and systems FRAME_FRACTION of the rest. Blades are uniform rods for their own inertia (m R^2/3 about the
    shaft, m R^2/6 about a disk diameter); the other parts are points and thin rods at the layout positions.

    Parameters
    ----------
    radius [m], tip_speed [m/s], sigma [-], n_blades [-], shaft_power (drive rating per rotor) [W],
    hub_spacing [m].

    Returns
    -------
    dict
        blades, hub, drive, generator (per rotor), frame, mass (craft) [kg]; hub_height, hub_x (hubs above and
        ahead of the CG) [m]; Jxx, Jyy, Jzz, Jxz about the CG in body axes [kg m^2].
    """
    lb = 0.45359237
    r_ft, vt_fps = radius / FOOT, tip_speed / FOOT
    chord_ft = sigma * math.pi * radius / n_blades / FOOT
    blades = 0.02606 * n_blades ** 0.6592 * r_ft ** 1.3371 * chord_ft ** 0.9959 * vt_fps ** 0.6682
    hub = 0.003722 * n_blades ** 0.2807 * r_ft ** 1.5377 * vt_fps ** 0.4290 * blades ** 0.5505
    rotor_rpm = tip_speed / radius * 30.0 / math.pi
    drive = 95.7634 * (shaft_power / 745.69987) ** 0.78137 * GENERATOR_RPM ** 0.09899 / rotor_rpm ** 0.80686
    m = {"blades": blades * lb, "hub": hub * lb, "drive": drive * lb,
         "generator": GENERATOR_KG_PER_KW * shaft_power / 1e3}
    m_rotor = sum(m.values())
    m_frame = FRAME_FRACTION * 2.0 * m_rotor
    y = 0.5 * hub_spacing
    # (mass, x, y, z) points, plus rods: lateral beam along y, keel along x
    pts = [(m["blades"] + m["hub"], 0.0, sy * y, 0.0) for sy in (1, -1)]
    pts += [(m["drive"] + m["generator"], 0.0, sy * y, NACELLE_DROP) for sy in (1, -1)]
    m_lat, m_keel = LATERAL_SHARE * m_frame, (1.0 - LATERAL_SHARE) * m_frame
    keel_len, keel_x = KEEL_X[1] - KEEL_X[0], 0.5 * (KEEL_X[0] + KEEL_X[1])
    pts += [(m_lat, 0.0, 0.0, FRAME_DROP), (m_keel, keel_x, 0.0, FRAME_DROP)]
    total = sum(p[0] for p in pts)
    xc = sum(p[0] * p[1] for p in pts) / total
    zc = sum(p[0] * p[3] for p in pts) / total
    jxx = jyy = jzz = jxz = 0.0
    for mm, px, py, pz in pts:
        dx, dz = px - xc, pz - zc
        jxx += mm * (py ** 2 + dz ** 2)
        jyy += mm * (dx ** 2 + dz ** 2)
        jzz += mm * (dx ** 2 + py ** 2)
        jxz += mm * dx * dz
    disk = 2.0 * m["blades"] * radius ** 2
    jxx += disk / 6.0 + m_lat * hub_spacing ** 2 / 12.0
    jyy += disk / 6.0 + m_keel * keel_len ** 2 / 12.0
    jzz += disk / 3.0 + m_lat * hub_spacing ** 2 / 12.0 + m_keel * keel_len ** 2 / 12.0
    return {**m, "frame": m_frame, "mass": total, "hub_height": zc, "hub_x": -xc, "Jxx": jxx, "Jyy": jyy,
            "Jzz": jzz, "Jxz": jxz}
