"""The parts of a scene file that every fidelity reads alike (``ladder/scene.py`` picks the fidelity): where a
scene file is, opening it with its overrides merged in, and the wing type, cable, wind and ground-station
readers. Errors are :class:`~laddermill_gym.model.configio.ConfigError` naming the file, the field and the value.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from laddermill_gym.model.aero_table import load_aero_table
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, Section, config_path, read_yaml
from laddermill_gym.model.params import N_CONTROLS, WindParams, WingType
from laddermill_gym.model.station import MODES, StationParams

#: The wing models a scene file's ``fidelity.wing`` may name.
FIDELITIES = ("rigid", "pointmass")
SCENE_DIR = CONFIG_DIR / "scenes"


def scene_path(name_or_path: str | Path) -> Path:
    """The shipped configs/scenes/NAME.yaml for a bare name, else the path itself."""
    return config_path("scenes", name_or_path)


def available_scenes() -> list[str]:
    return sorted(p.stem for p in SCENE_DIR.glob("*.yaml"))


# ---------------------------------------------------------------------------------------- parts
def load_wing_type(path: Path) -> WingType:
    """Read a wing type YAML (mass, inertia, geometry, attachment, control limits, table file)."""
    s = read_yaml(path)
    inertia = s.section("inertia")
    J = (inertia.number("Jxx", positive=True), inertia.number("Jyy", positive=True),
         inertia.number("Jzz", positive=True), inertia.number("Jxz"))
    inertia.done()
    if J[0] * J[2] - J[3] ** 2 <= 0:
        raise ConfigError(f"{path}: field 'inertia' = {J}: Jxx Jzz - Jxz^2 must be > 0")
    lim = s.section("control_limits_deg")
    limits = np.zeros((N_CONTROLS, 2))
    for i, name in enumerate(("elevator", "rudder", "aileron")):
        lo_hi = lim.vector(name, 2)
        if not lo_hi[0] < lo_hi[1]:
            raise lim.error(name, list(lo_hi), "lower limit must be below the upper limit")
        limits[i] = np.radians(lo_hi)
    lim.done()
    table_name = s.text("aero_table")
    table_file = config_path("wings", table_name, path.parent)
    if not table_file.is_file():
        raise s.error("aero_table", table_name, f"no such file {table_file}")
    wt = WingType(
        name=s.text("name"), mass=s.number("mass", positive=True), inertia=J,
        area=s.number("area", positive=True), span=s.number("span", positive=True),
        chord=s.number("chord", positive=True), r_ref=s.vector("aero_reference", 3),
        attachment=s.vector("attachment", 3), control_limits=limits, aero=load_aero_table(table_file))
    s.done()
    return wt


def load_cable(path: Path) -> CableSpec:
    """Read a cable YAML (diameter, mass per length, EA, DA, breaking load, cn0, ct0)."""
    s = read_yaml(path)
    c = CableSpec(diameter=s.number("diameter", positive=True),
                  mass_per_length=s.number("mass_per_length", positive=True),
                  EA=s.number("EA", positive=True), DA=s.number("DA", nonneg=True),
                  breaking_load=s.number("breaking_load", positive=True), cn0=s.number("cn0", nonneg=True),
                  ct0=s.number("ct0", nonneg=True))
    s.done()
    return c


def read_wind(s: Section) -> WindParams:
    # v0 and rho0 > 0: without wind or air no wing or rotor here can hold an equilibrium (the trim would fail)
    w = WindParams(
        v0=s.number("v0", positive=True), h0=s.number("h0", positive=True), v1=s.number("v1"),
        exponent=s.number("exponent", nonneg=True), direction_inf=s.number("direction_inf_rad", 0.0),
        direction_height=s.number("direction_height", 500.0, positive=True),
        rho0=s.number("rho0", positive=True), density_model=s.text("density_model", "barometric",
                                                                 choices=("barometric", "isa")),
        scale_height=s.number("scale_height", 8400.0, positive=True))
    s.done()
    return w

def read_station(s: Section, piece: float) -> StationParams:
    """The moving cable's ground station (``station:`` section; ``model/station.py``), errors naming the field."""
    mode = s.text("mode", "prescribed", choices=MODES)
    times = s.vector("speed_times_s", default=[0.0])
    speeds = s.vector("speed_m_s", default=[0.0])
    kw = dict(piece_length=piece, first_fraction=s.number("first_fraction", 0.1, positive=True),
              last_fraction=s.number("last_fraction", 1.1, positive=True), mode=mode,
              speed_times=tuple(times), speed_values=tuple(speeds),
              efficiency=s.number("efficiency", 1.0, positive=True))
    if mode == "drum":
        kw.update(drum_radius=s.number("drum_radius", positive=True),
                  drum_inertia=s.number("drum_inertia", positive=True),
                  torque_limits=tuple(s.vector("torque_limits", 2)))
    if mode == "commanded":
        kw.update(speed_time_constant=s.number("speed_time_constant", positive=True),
                  speed_limits=tuple(s.vector("speed_limits", 2)))
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
