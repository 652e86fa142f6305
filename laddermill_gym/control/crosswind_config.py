"""Configuration of the crosswind pumping controller (``configs/agents/crosswind_pumping.yaml``): the path
(:class:`~laddermill_gym.control.crosswind_guidance.PathSpec`), the course and bank loops, the winch and the
cycle's phases; strict reader (unknown keys and bad values refused naming file, field and value) and the checks
against the flown scene (:func:`check_against_scene`: the path inside the wind window and above the ground at the
tether's shortest length, the tension set-point below the tether's strength)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from laddermill_gym.control.crosswind_guidance import PathSpec
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, config_path, find_config, read_yaml

__all__ = ["CourseGains", "WinchLaw", "PhaseSettings", "CrosswindConfig", "load_crosswind_config",
           "check_against_scene", "DEFAULT_CROSSWIND_CONFIG"]

DEFAULT_CROSSWIND_CONFIG = CONFIG_DIR / "agents" / "crosswind_pumping.yaml"


@dataclass(frozen=True)
class CourseGains:
    """The course loop (turn rate command chi_dot = turn_gain x course error, at most max_turn_rate [rad/s]), the
    bank it needs (sin mu = lift_factor m (v chi_dot - g_n) / T, at most max_bank [rad]) and the wing's loops:
    aileron = bank_gain (mu_c - mu) + integral - roll_damping p; rudder = yaw_rate_gain (r - chi_dot) -
    sideslip_gain beta [rad]. Below heading_speed [m/s] the course is the wing's heading; the bank law uses at
    least min_speed [m/s]."""

    turn_gain: float
    max_turn_rate: float
    lift_factor: float
    max_bank: float
    bank_gain: float
    bank_integral: float
    roll_damping: float
    sideslip_gain: float
    yaw_rate_gain: float
    min_speed: float
    heading_speed: float


@dataclass(frozen=True)
class WinchLaw:
    """Reel-out at reel_out_factor x the wind along the tether at the wing (Loyd's 1/3), plus overload_gain
    [m/s per N] x the tension above max_tension [N]; reel-in at reel_in_speed [m/s] (> 0), plus overload_gain x
    the tension above reel_in_tension [N]."""

    reel_out_factor: float
    max_tension: float
    overload_gain: float
    reel_in_speed: float
    reel_in_tension: float


@dataclass(frozen=True)
class PhaseSettings:
    """The cycle: reel out ``reel_length`` [m], then the retraction transition (still at alpha_out, fly up to
    park_elevation [rad] at the path's centre azimuth, the winch still reeling out at most ``overrun`` [m] more)
    until the drum tension is below depower_tension [N] or the wing is within 5 deg of the park elevation; reel in
    to the start length at alpha_in; then the reel-out transition (elevator at alpha_out, winch stopped) until the
    wing is within ``entry_distance`` [rad] of the path. alpha_out, alpha_in [rad]."""

    reel_length: float
    overrun: float
    park_elevation: float
    depower_tension: float
    entry_distance: float
    alpha_out: float
    alpha_in: float


@dataclass(frozen=True)
class CrosswindConfig:
    file: Path
    path: PathSpec
    course: CourseGains
    winch: WinchLaw
    phases: PhaseSettings


def _deg(sec, key, **kw) -> float:
    return math.radians(sec.number(key, **kw))


def load_crosswind_config(name_or_path: str | Path = DEFAULT_CROSSWIND_CONFIG) -> CrosswindConfig:
    """Read a crosswind controller config (a path or a name of ``configs/agents``)."""
    path = config_path("agents", name_or_path)
    find_config("agents", path, "crosswind config")
    s = read_yaml(path)
    p = s.section("path")
    shape = p.text("shape", choices=("figure_eight", "circle"))
    spec = PathSpec(shape=shape, elevation=_deg(p, "elevation_deg", positive=True), azimuth=_deg(p, "azimuth_deg"),
                    width=_deg(p, "width_deg", positive=True) if shape == "figure_eight" else _deg(p, "width_deg", 0.0),
                    height=_deg(p, "height_deg", positive=True),
                    direction=p.text("direction", choices=("up_at_sides", "down_at_sides") if shape == "figure_eight"
                                     else ("positive", "negative")),
                    lookahead=_deg(p, "lookahead_deg", positive=True))
    p.done()
    c = s.section("course")
    course = CourseGains(turn_gain=c.number("turn_gain", positive=True), max_turn_rate=c.number("max_turn_rate",
                         positive=True), lift_factor=c.number("lift_factor", positive=True),
                         max_bank=_deg(c, "max_bank_deg", positive=True), bank_gain=c.number("bank_gain", nonneg=True),
                         bank_integral=c.number("bank_integral", nonneg=True),
                         roll_damping=c.number("roll_damping", nonneg=True),
                         sideslip_gain=c.number("sideslip_gain", nonneg=True),
                         yaw_rate_gain=c.number("yaw_rate_gain", nonneg=True),
                         min_speed=c.number("min_speed", positive=True),
                         heading_speed=c.number("heading_speed", nonneg=True))
    c.done()
    w = s.section("winch")
    winch = WinchLaw(reel_out_factor=w.number("reel_out_factor", positive=True),
                     max_tension=w.number("max_tension", positive=True),
                     overload_gain=w.number("overload_gain", nonneg=True),
                     reel_in_speed=w.number("reel_in_speed", positive=True),
                     reel_in_tension=w.number("reel_in_tension", positive=True))
    w.done()
    f = s.section("phases")
    phases = PhaseSettings(reel_length=f.number("reel_length", positive=True), overrun=f.number("overrun", nonneg=True),
                           park_elevation=_deg(f, "park_elevation_deg", positive=True),
                           depower_tension=f.number("depower_tension", positive=True),
                           entry_distance=_deg(f, "entry_distance_deg", positive=True),
                           alpha_out=_deg(f, "alpha_out_deg"), alpha_in=_deg(f, "alpha_in_deg"))
    f.done()
    s.done()
    for key, value, bad in (("path.elevation_deg", spec.elevation, spec.elevation >= math.pi / 2),
                            ("phases.park_elevation_deg", phases.park_elevation, phases.park_elevation >= math.pi / 2),
                            ("course.max_bank_deg", course.max_bank, course.max_bank >= math.pi / 2),
                            ("winch.reel_out_factor", winch.reel_out_factor, winch.reel_out_factor >= 1.0)):
        if bad:
            deg = key.endswith("_deg")
            limit = "90 deg" if deg else "1 (the wing would reel out faster than the wind)"
            shown = math.degrees(value) if deg else value
            raise ConfigError(f"{path}: field '{key}' = {shown:g}: must be below {limit}")
    if phases.alpha_in >= phases.alpha_out:
        raise ConfigError(f"{path}: field 'phases.alpha_in_deg' = {math.degrees(phases.alpha_in):g}: must be below "
                          f"alpha_out_deg = {math.degrees(phases.alpha_out):g} (reel in at low lift)")
    return CrosswindConfig(file=path, path=spec, course=course, winch=winch, phases=phases)


def check_against_scene(cfg: CrosswindConfig, tether_length: float, breaking_load: float, min_altitude: float,
                        winch_speed_limits: tuple[float, float], drum_capacity: float | None = None) -> None:
    """Refuse (ConfigError naming the file, field and value) a path that leaves the wind window (elevation outside
    (0, 90) deg, azimuth beyond +-90 deg), a path whose lowest point on the tether's shortest length
    ``tether_length`` [m] is below ``min_altitude`` [m], a tension set-point at or above the tether's
    ``breaking_load`` [N], a reel-in speed beyond the winch's reel-in limit, a reel length the drum does not hold
    (``drum_capacity`` [m], the env's ``max_paid_out``: the controller would wait in reel-out for good)."""
    f = cfg.file
    lo, hi, az_lo, az_hi = cfg.path.extent()
    if hi >= math.pi / 2 or lo <= 0.0:
        key = "path.elevation_deg" if lo > 0.0 or hi >= math.pi / 2 else "path.height_deg"
        raise ConfigError(f"{f}: field '{key}' = {math.degrees(cfg.path.elevation):g} (height "
                          f"{math.degrees(cfg.path.height):g} deg): the path spans elevations {math.degrees(lo):.1f} "
                          f"to {math.degrees(hi):.1f} deg, outside the wind window (0, 90) deg")
    if max(abs(az_lo), abs(az_hi)) >= math.pi / 2:
        raise ConfigError(f"{f}: field 'path.width_deg' = {math.degrees(cfg.path.width):g}: the path reaches azimuth "
                          f"{math.degrees(max(abs(az_lo), abs(az_hi))):.1f} deg, outside the wind window (+-90 deg)")
    if tether_length * math.sin(lo) <= min_altitude:
        raise ConfigError(f"{f}: field 'path.elevation_deg' = {math.degrees(cfg.path.elevation):g}: the path's lowest "
                          f"elevation {math.degrees(lo):.1f} deg on the {tether_length:.0f} m tether is "
                          f"{tether_length * math.sin(lo):.1f} m high, not above the minimum altitude "
                          f"{min_altitude:g} m (the tether is too short for it)")
    if cfg.winch.max_tension >= breaking_load:
        raise ConfigError(f"{f}: field 'winch.max_tension' = {cfg.winch.max_tension:g}: at or above the tether's "
                          f"breaking load {breaking_load:g} N")
    if drum_capacity is not None and cfg.phases.reel_length >= drum_capacity:
        raise ConfigError(f"{f}: field 'phases.reel_length' = {cfg.phases.reel_length:g}: the drum holds "
                          f"{drum_capacity:g} m (the env's max_paid_out), so the reel-out would never end")
    if cfg.winch.reel_in_speed > -winch_speed_limits[0] + 1e-12:
        raise ConfigError(f"{f}: field 'winch.reel_in_speed' = {cfg.winch.reel_in_speed:g}: beyond the winch's reel-in "
                          f"limit {-winch_speed_limits[0]:g} m/s")
