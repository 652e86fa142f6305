"""The parts of a scene file that every fidelity reads alike (``ladder/scene.py`` picks the fidelity): where a
scene file is, opening it with its overrides merged in, and the wing type, cable, wind and ground-station
readers. Errors are :class:`~laddermill_gym.model.configio.ConfigError` naming the file, the field and the value.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from laddermill_gym.ladder.bounds import (
    BOUNDS,
    CABLE_DENSITY,
    CHORD_RATIO,
    MAX_CABLE_LENGTH,
    MAX_MODULUS,
    MAX_RETARDATION,
    MAX_STRENGTH,
)
from laddermill_gym.model.aero_table import load_aero_table
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, Section, config_path, read_yaml
from laddermill_gym.model.params import N_CONTROLS, WindParams, WingType
from laddermill_gym.model.station import INSERTIONS, MODES, StationParams

#: The wing models a scene file's ``fidelity.wing`` may name.
FIDELITIES = ("rigid", "pointmass")
SCENE_DIR = CONFIG_DIR / "scenes"


def scene_path(name_or_path: str | Path) -> Path:
    """The shipped configs/scenes/NAME.yaml for a bare name, else the path itself."""
    return config_path("scenes", name_or_path)


def available_scenes() -> list[str]:
    return sorted(p.stem for p in SCENE_DIR.glob("*.yaml"))


# ---------------------------------------------------------------------------------------- parts
def _principal_moments(J) -> np.ndarray:
    """Principal moments of inertia [kg m^2] of (Jxx, Jyy, Jzz, Jxz): the body's tensor has -Jxz off the diagonal."""
    Jxx, Jyy, Jzz, Jxz = J
    return np.linalg.eigvalsh(np.array([[Jxx, 0.0, -Jxz], [0.0, Jyy, 0.0], [-Jxz, 0.0, Jzz]]))


def load_wing_type(path: Path) -> WingType:
    """Read a wing type YAML (mass, inertia, geometry, attachment, control limits, table file); the numbers within
    their physical bounds (``ladder/bounds.py``)."""
    s = read_yaml(path)
    inertia = s.section("inertia")
    J = (inertia.number("Jxx", positive=True), inertia.number("Jyy", positive=True),
         inertia.number("Jzz", positive=True), inertia.number("Jxz"))
    inertia.done()
    if J[0] * J[2] - J[3] ** 2 <= 0:
        raise ConfigError(f"{path}: field 'inertia' = {J}: Jxx Jzz - Jxz^2 must be > 0")
    p = _principal_moments(J)
    if p[0] + p[1] < p[2] * (1.0 - 1e-9):
        key = ("Jxx", "Jyy", "Jzz")[int(np.argmax(J[:3]))]
        raise inertia.error(key, J[("Jxx", "Jyy", "Jzz").index(key)],
                            f"no rigid body has the moments (Jxx, Jyy, Jzz, Jxz) = {J} kg m^2: its principal moments "
                            f"{p[0]:.6g}, {p[1]:.6g}, {p[2]:.6g} break the triangle inequality J1 + J2 >= J3")
    lim = s.section("control_limits_deg")
    limits = np.zeros((N_CONTROLS, 2))
    for i, name in enumerate(("elevator", "rudder", "aileron")):
        lo_hi = lim.vector(name, 2)
        if not lo_hi[0] < lo_hi[1]:
            raise lim.error(name, list(lo_hi), "lower limit must be below the upper limit")
        if np.any(np.abs(lo_hi) > 90.0):
            raise lim.error(name, list(lo_hi), "must be between -90 and 90 "
                                               f"({BOUNDS['wing.control_limit_deg']['why']})")
        limits[i] = np.radians(lo_hi)
    lim.done()
    table_name = s.text("aero_table")
    table_file = config_path("wings", table_name, path.parent)
    if not table_file.is_file():
        raise s.error("aero_table", table_name, f"no such file {table_file}")
    span = s.number("span", positive=True, **BOUNDS["wing.span"])
    area, chord = s.number("area", positive=True), s.number("chord", positive=True)
    ratio = span * chord / area
    if not CHORD_RATIO[0] <= ratio <= CHORD_RATIO[1]:
        raise s.error("area", area, f"span x chord / area = {span:g} m x {chord:g} m / {area:g} m^2 = {ratio:.3g}: "
                                    f"must be between {CHORD_RATIO[0]:g} and {CHORD_RATIO[1]:g} (the mean aerodynamic "
                                    "chord of any planform is 1 to 4/3 of area / span)")
    points = {k: s.vector(k, 3) for k in ("aero_reference", "attachment")}
    for k, r in points.items():
        if np.linalg.norm(r) > span:
            raise s.error(k, list(r), f"a point on the wing's body: must be within a span ({span:g} m) of the CG")
    wt = WingType(
        name=s.text("name"), mass=s.number("mass", positive=True, **BOUNDS["wing.mass"]), inertia=J,
        area=area, span=span, chord=chord, r_ref=points["aero_reference"],
        attachment=points["attachment"], control_limits=limits, aero=load_aero_table(table_file))
    s.done()
    return wt


def load_cable(path: Path) -> CableSpec:
    """Read a cable YAML (diameter, mass per length, EA, DA, breaking load, cn0, ct0); the material within the
    physical bounds of ``ladder/bounds.py`` (density, modulus, strength, retardation time)."""
    s = read_yaml(path)
    c = CableSpec(diameter=s.number("diameter", positive=True),
                  mass_per_length=s.number("mass_per_length", positive=True),
                  EA=s.number("EA", positive=True), DA=s.number("DA", nonneg=True),
                  breaking_load=s.number("breaking_load", positive=True),
                  cn0=s.number("cn0", nonneg=True, **BOUNDS["cable.cn0"]),
                  ct0=s.number("ct0", nonneg=True, **BOUNDS["cable.ct0"]))
    s.done()
    area = math.pi * c.diameter ** 2 / 4.0
    checks = (("mass_per_length", c.mass_per_length, c.mass_per_length / area, CABLE_DENSITY, "kg/m^3",
               "its density (mass_per_length over the cross-section of the diameter)",
               "a rope of fibre and voids (the 25 mm Dyneema rope: 611 kg/m^3) to osmium (22,590 kg/m^3)"),
              ("EA", c.EA, c.EA / area, (0.0, MAX_MODULUS), "Pa", "its modulus (EA over the cross-section)",
               "no material is stiffer than diamond or graphene, about 1 TPa"),
              ("breaking_load", c.breaking_load, c.breaking_load / area, (0.0, MAX_STRENGTH), "Pa",
               "its strength (breaking_load over the cross-section)", "no material is stronger than graphene"),
              ("DA", c.DA, c.DA / c.EA, (0.0, MAX_RETARDATION), "s", "its retardation time DA / EA",
               "the shipped cables: 1 ms; beyond 1 s the cable creeps instead of vibrating"))
    for key, value, derived, (lo, hi), unit, what, why in checks:
        if not lo <= derived <= hi:
            raise ConfigError(f"{path}: field '{key}' = {value!r}: {what} is {derived:.4g} {unit}, must be between "
                              f"{lo:g} and {hi:g} {unit} ({why}; diameter = {c.diameter!r} m)")
    return c


def read_parts(s: Section, path: Path) -> tuple[WingType, CableSpec]:
    """The wing type and the cable the scene ``path`` names (``wing_type``, ``cable``); ConfigError naming the
    scene file and the field (not only the missing file) when one is not found."""
    parts = {}
    for key, kind in (("wing_type", "wings"), ("cable", "cables")):
        value = s.text(key)
        parts[key] = config_path(kind, value, path.parent)
        if not parts[key].is_file():
            shown = parts[key] if parts[key].is_absolute() else path.parent / parts[key]
            raise s.error(key, value, f"no such file {shown} (a path is relative to the scene's folder, a bare "
                                      f"name is {CONFIG_DIR / kind}/NAME.yaml, 'package:{kind}/FILE' the shipped data)")
    return load_wing_type(parts["wing_type"]), load_cable(parts["cable"])


def read_wind(s: Section) -> WindParams:
    """The ``wind:`` section; every number within its bounds (``ladder/bounds.py``)."""
    # v0 and rho0 > 0: without wind or air no wing or rotor here can hold an equilibrium (the trim would fail)
    w = WindParams(
        v0=s.number("v0", positive=True, **BOUNDS["wind.v0"]), h0=s.number("h0", positive=True, **BOUNDS["wind.h0"]),
        v1=s.number("v1", **BOUNDS["wind.v1"]), exponent=s.number("exponent", nonneg=True, **BOUNDS["wind.exponent"]),
        direction_inf=s.number("direction_inf_rad", 0.0, **BOUNDS["wind.direction_inf_rad"]),
        direction_height=s.number("direction_height", 500.0, positive=True, **BOUNDS["wind.direction_height"]),
        rho0=s.number("rho0", positive=True, **BOUNDS["wind.rho0"]),
        density_model=s.text("density_model", "barometric", choices=("barometric", "isa")),
        scale_height=s.number("scale_height", 8400.0, positive=True, **BOUNDS["wind.scale_height"]))
    s.done()
    return w


def read_ground_points(s: Section) -> dict[str, np.ndarray]:
    """The ``ground_points:`` section: {name: (3,) [m]}, at least one, each coordinate within 100 km."""
    gp = s.section("ground_points")
    points = {k: gp.vector(k, 3) for k in list(gp.data)}
    gp.done()
    if not points:
        raise s.error("ground_points", gp.data, "must name at least one point (name: [x, y, z] in m)")
    for k, p in points.items():
        if np.any(np.abs(p) > BOUNDS["coordinate"]["high"]):
            raise gp.error(k, list(p), "every coordinate must be between -100 and 100 km "
                                       f"({BOUNDS['coordinate']['why']})")
    return points


def check_cable_length(ch: Section, piece: float, n_wings: int, has_end: bool, cable: CableSpec, gravity: float,
                       n_wings_override: bool = False) -> None:
    """ConfigError naming ``chain.piece_length`` when a piece [m] is longer than the cable's breaking length
    F_b / (mu g) (it cannot carry its own weight), and ``chain.n_wings`` (or its keyword override) when the
    ``n_wings + has_end`` pieces hold more than :data:`MAX_CABLE_LENGTH` of cable."""
    breaking = cable.breaking_load / (cable.mass_per_length * gravity)
    if piece > breaking:
        raise ch.error("piece_length", piece, "longer than the cable's breaking length F_b / (mu g) = "
                                              f"{breaking:.4g} m: the piece cannot carry its own weight")
    n_pieces = n_wings + bool(has_end)
    if piece * n_pieces > MAX_CABLE_LENGTH:
        why = (f"{n_pieces} pieces of chain.piece_length = {piece:g} m are {piece * n_pieces:.4g} m of cable, more "
               f"than {MAX_CABLE_LENGTH:g} m (the edge of the atmosphere, the Karman line: the barometric air there is "
               "e^-12 of sea level's)")
        if n_wings_override:
            raise ConfigError(f"{ch.file}: n_wings = {n_wings!r} (override): {why}")
        raise ch.error("n_wings", n_wings, why)


def read_station(s: Section, piece: float, insertion: str = "paper") -> StationParams:
    """The moving cable's ground station (``station:`` section; ``model/station.py``), errors naming the field:
    the end elements' fractions of a piece (they change by one piece between transfers), a speed schedule of
    increasing times with one speed each, speeds within the fastest wind (``ladder/bounds.py``), an efficiency of at
    most 1, the insertion rule of a transferred wing (``insertion``: "paper" or "cable"; absent: ``insertion``,
    the fidelity's own default)."""
    speed = dict(low=-BOUNDS["wind.v0"]["high"], high=BOUNDS["wind.v0"]["high"],
                 why="m/s: the cable cannot outrun the fastest wind that drives it")
    mode = s.text("mode", "prescribed", choices=MODES)
    times = s.vector("speed_times_s", default=[0.0])
    speeds = s.vector("speed_m_s", default=[0.0])
    if times.size != speeds.size:
        raise s.error("speed_times_s", times.tolist(), f"need one time per speed of speed_m_s ({speeds.tolist()})")
    if np.any(np.diff(times) <= 0) or np.any(np.abs(times) > 1e7):
        raise s.error("speed_times_s", times.tolist(), "must increase strictly, within 1e7 s")
    if np.any(np.abs(speeds) > speed["high"]):
        raise s.error("speed_m_s", speeds.tolist(), f"must be between -150 and 150 ({speed['why']})")
    why = "the end elements change by one piece between transfers (Meijaard: 1/10 and 11/10)"
    kw = dict(piece_length=piece, first_fraction=s.number("first_fraction", 0.1, positive=True, high=1.0, why=why),
              last_fraction=s.number("last_fraction", 1.1, positive=True, high=2.0, why=why), mode=mode,
              speed_times=tuple(times), speed_values=tuple(speeds),
              efficiency=s.number("efficiency", 1.0, positive=True, high=1.0,
                                  why="electrical over mechanical power"),
              insertion=s.text("insertion", insertion, choices=INSERTIONS))
    if mode == "drum":
        kw.update(drum_radius=s.number("drum_radius", positive=True, high=100.0, why="m"),
                  drum_inertia=s.number("drum_inertia", positive=True),
                  torque_limits=tuple(s.vector("torque_limits", 2)))
    if mode == "commanded":
        kw.update(speed_time_constant=s.number("speed_time_constant", positive=True, high=3600.0, why="s"),
                  speed_limits=tuple(s.vector("speed_limits", 2)))
        lo, hi = kw["speed_limits"]
        if lo <= hi and not lo <= speeds[0] <= hi:
            raise s.error("speed_m_s", speeds.tolist(), f"the commanded station starts at its first speed, which "
                          f"must lie within speed_limits [{lo:g}, {hi:g}] m/s")
    if mode != "prescribed" and speeds.size > 1:
        raise s.error("speed_times_s", times.tolist(), f"a {mode} station takes only its initial speed "
                      "(speed_m_s[0]); a schedule of several speeds needs mode: prescribed")
    s.done()
    try:
        return StationParams(**kw)
    except ValueError as err:
        raise ConfigError(f"{s.file}: {err}") from None


def _merged(data: dict, overrides, where: str) -> dict:
    """A copy of the YAML mapping ``data`` with the nested mapping ``overrides`` merged in (mappings merge, other
    values replace); ConfigError naming the override's path if it is not a mapping with text keys."""
    if not isinstance(overrides, dict) or not all(isinstance(k, str) for k in overrides):
        raise ConfigError(f"{where} = {overrides!r}: must be a mapping with text keys")
    out = dict(data)
    for k, v in overrides.items():
        if isinstance(v, dict) and isinstance(out.get(k), dict):
            out[k] = _merged(out[k], v, f"{where}.{k}")
        else:
            out[k] = v
    return out


def open_scene(name_or_path: str | Path, overrides: dict | None = None, **counts) -> tuple[Path, Section]:
    """(path, its contents as a Section) of a scene file (a bare name: the shipped configs/scenes/NAME.yaml) with
    the nested mapping ``overrides`` merged in (errors naming the field and "(with overrides)"), after checking that
    the whole-number overrides ``counts`` (``n_wings``, ``elements_per_piece``; None: the file's) are >= 1."""
    path = scene_path(name_or_path)
    s = read_yaml(path)
    if overrides:
        s = Section(_merged(s.data, overrides, "overrides"), f"{path} (with overrides)")
    for key, v in counts.items():
        if v is not None and (isinstance(v, bool) or int(v) != v or v < 1):
            raise ConfigError(f"{path}: {key} = {v!r} (override): must be a whole number >= 1")
    return path, s
