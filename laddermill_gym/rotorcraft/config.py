"""Roberts' tethered twin-rotor craft: its configuration (configs/rotorcraft/*.yaml), loaded and validated.

The file's fields, units and sources are listed in ``configs/rotorcraft/roberts_flying_model.yaml`` and
derived in ``laddermill_gym/docs/rotorcraft.md``. Every error names the file, the field and the value.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.ladder.scene_files import load_cable, read_wind
from laddermill_gym.model.builders import CableSpec
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, config_path, read_yaml
from laddermill_gym.model.params import WindParams
from laddermill_gym.rotorcraft.rotor import RotorParams, load_rotor_config
from laddermill_gym.sim.breakpoints import INTEGRATOR_METHODS
from laddermill_gym.sim.reports import GROUND_MODES
from laddermill_gym.sim.simulator import IntegratorSettings

#: Folder of the craft YAML files; the default craft.
CRAFT_CONFIG_DIR = CONFIG_DIR / "rotorcraft"
DEFAULT_CRAFT = "roberts_flying_model"


@dataclass(frozen=True)
class TetherSpec:
    """Three tethers, two rear (mirrored in y) and one forward, placed for parallel tethers at a design pitch.

    length [m] of the rear tethers; elevation [rad] design cable angle beta above the ground; design_pitch
    [rad] craft pitch at which the tethers are parallel; attach_rear, attach_front [m] body-frame attachment
    points, shape (3,) (the left rear one is attach_rear mirrored in y); elements: truss elements per tether.
    """

    cable: CableSpec
    length: float
    elevation: float
    design_pitch: float
    attach_rear: np.ndarray
    attach_front: np.ndarray
    elements: int


@dataclass(frozen=True)
class CraftConfig:
    """A twin-rotor craft: rotors, frame, fins, limits, tethers, wind and integrator.

    Units: lengths [m], mass [kg], inertia (Jxx, Jyy, Jzz, Jxz) [kg m^2] about the CG in body axes (x forward,
    y right, z down), rotor_speed [rad/s], areas [m^2], fin_lift_slope [1/rad], angles and limits [rad].
    hub_height is the hubs' height above the CG along the shaft (body -z); hub_spacing hub to hub.
    """

    name: str
    file: Path
    description: str
    gravity: float
    rotor: RotorParams
    blade_incidence_limit: float
    rotor_radius: float
    rotor_speed: float
    hub_spacing: float
    hub_height: float
    hub_x: float
    mass: float
    inertia: tuple[float, float, float, float]
    fin_area: float
    fin_lift_slope: float
    fin_x: float
    fin_z: float
    drag_area: float
    electrical_efficiency: float
    collective_limits: np.ndarray
    differential_limits: np.ndarray
    tethers: TetherSpec
    wind: WindParams
    sag: bool
    cable_aero: bool
    initial_collective: float
    settings: IntegratorSettings

    def replace(self, **changes) -> CraftConfig:
        """A copy with some fields changed (e.g. ``wind=cfg.wind_with_speed(8.0)``)."""
        return dataclasses.replace(self, **changes)

    def with_wind_speed(self, v0: float) -> CraftConfig:
        """A copy with the wind speed v0 [m/s] at h0 changed."""
        if not (math.isfinite(v0) and v0 >= 0.0):
            raise ValueError(f"wind speed v0 must be finite and >= 0, got {v0!r}")
        return self.replace(wind=dataclasses.replace(self.wind, v0=float(v0)))


def craft_path(name_or_path: str | Path) -> Path:
    """Path of a craft YAML: a file path, or a name in configs/rotorcraft/."""
    return config_path("rotorcraft", name_or_path)


def _limits(s, key):
    v = s.vector(key, 2)
    if not v[0] < v[1]:
        raise s.error(key, list(v), "lower limit must be below the upper limit")
    return np.radians(v)


def _differential_limits(s) -> np.ndarray:
    """The differential collective's limits [rad]: ordered, and holding 0 (the trim flies with none)."""
    lim, deg = _limits(s, "differential_limits_deg"), s.vector("differential_limits_deg", 2)
    if not deg[0] <= 0.0 <= deg[1]:
        raise s.error("differential_limits_deg", list(deg), "must hold 0 (lower <= 0 <= upper): "
                      "the trim and the zero action fly with no differential collective")
    return lim


def _read_tethers(t, path: Path) -> TetherSpec:
    """The ``tethers`` section (cable files relative to the craft file's folder ``path.parent``), checked."""
    tethers = TetherSpec(
        cable=load_cable(config_path("cables", t.text("cable"), path.parent)), length=t.number("length", positive=True),
        elevation=math.radians(t.number("elevation_deg", positive=True)),
        design_pitch=math.radians(t.number("design_pitch_deg")),
        attach_rear=t.vector("attach_rear", 3), attach_front=t.vector("attach_front", 3),
        elements=t.number("elements", positive=True, integer=True))
    t.done()
    if not tethers.elevation < math.pi / 2:
        raise t.error("elevation_deg", math.degrees(tethers.elevation), "must be below 90")
    if not abs(tethers.design_pitch) < math.pi / 2:
        raise t.error("design_pitch_deg", math.degrees(tethers.design_pitch), "must lie in (-90, 90) deg: the craft's "
                      "pitch at its design pose, where the tethers are parallel (past 90 deg the rotors face down)")
    if tethers.attach_rear[1] <= 0:
        raise t.error("attach_rear", list(tethers.attach_rear), "y must be > 0 (the right rear tether)")
    return tethers


def load_craft_config(name_or_path: str | Path = DEFAULT_CRAFT) -> CraftConfig:
    """Read and validate a craft YAML (see configs/rotorcraft/roberts_flying_model.yaml for the fields)."""
    path = craft_path(name_or_path)
    s = read_yaml(path)
    rotor_cfg = load_rotor_config(config_path("rotors", s.text("rotor"), path.parent))
    J = s.vector("inertia", 4)
    if np.any(J[:3] <= 0) or J[0] * J[2] - J[3] ** 2 <= 0:
        raise s.error("inertia", list(J), "Jxx, Jyy, Jzz must be > 0 and Jxx Jzz - Jxz^2 > 0")
    principal = np.linalg.eigvalsh(np.array([[J[0], 0.0, -J[3]], [0.0, J[1], 0.0], [-J[3], 0.0, J[2]]]))
    if principal[0] + principal[1] < principal[2] * (1.0 - 1e-12):  # a rigid body's: each <= the sum of the others
        raise s.error("inertia", list(J), f"principal moments {principal.round(6).tolist()}: the largest exceeds the "
                      "sum of the other two, which no rigid body has")
    tethers = _read_tethers(s.section("tethers"), path)
    fid = s.section("fidelity")
    sag, cable_aero = fid.flag("sag"), fid.flag("cable_aero")
    fid.done()
    ini = s.section("initial")
    collective = math.radians(ini.number("collective_deg"))
    ini.done()
    integ = s.section("integrator")
    if integ.data.get("ground_contact") is False:  # YAML 1.1 reads a bare `off` as false
        integ.data["ground_contact"] = "off"
    settings = IntegratorSettings(method=integ.text("method", "rk4", choices=INTEGRATOR_METHODS),
                                  dt=integ.number("dt", positive=True),
                                  max_speed=integ.number("max_speed", 100.0, positive=True),
                                  max_rate=integ.number("max_rate", 50.0, positive=True),
                                  ground_height=integ.number("ground_height", 0.0),
                                  ground_contact=integ.text("ground_contact", "stop", choices=GROUND_MODES))
    integ.done()
    eta = s.number("electrical_efficiency", positive=True)
    if eta > 1.0:
        raise s.error("electrical_efficiency", eta, "must be <= 1")
    cfg = CraftConfig(
        name=s.text("name"), file=path, description=s.text("description", ""),
        gravity=s.number("gravity", positive=True), rotor=rotor_cfg.params,
        blade_incidence_limit=rotor_cfg.blade_incidence_limit,
        rotor_radius=s.number("rotor_radius", positive=True), rotor_speed=s.number("rotor_speed", positive=True),
        hub_spacing=s.number("hub_spacing", positive=True), hub_height=s.number("hub_height"),
        hub_x=s.number("hub_x", 0.0), mass=s.number("mass", positive=True), inertia=tuple(float(j) for j in J),
        fin_area=s.number("fin_area", nonneg=True), fin_lift_slope=s.number("fin_lift_slope", nonneg=True),
        fin_x=s.number("fin_x"), fin_z=s.number("fin_z"), drag_area=s.number("drag_area", nonneg=True),
        electrical_efficiency=eta, collective_limits=_limits(s, "collective_limits_deg"),
        differential_limits=_differential_limits(s), tethers=tethers,
        wind=read_wind(s.section("wind")), sag=sag, cable_aero=cable_aero, initial_collective=collective,
        settings=settings)
    s.done()
    if cfg.hub_spacing < 2.0 * cfg.rotor_radius:
        raise ConfigError(f"{path}: field 'hub_spacing' = {cfg.hub_spacing!r}: the disks overlap "
                          f"(must be >= 2 rotor_radius = {2 * cfg.rotor_radius})")
    lo, hi = cfg.collective_limits
    d_lo, d_hi = cfg.differential_limits
    reach = np.degrees([lo + min(d_lo, -d_hi), hi + max(d_hi, -d_lo)])  # each rotor's pitch: collective -+ differential
    if not (-90.0 < reach[0] and reach[1] < 90.0):
        raise ConfigError(f"{path}: fields 'collective_limits_deg' and 'differential_limits_deg' reach blade pitches "
                          f"of {reach[0]:.4g} to {reach[1]:.4g} deg: the rotor model takes |pitch| < 90 deg")
    if not lo <= collective <= hi:
        raise ConfigError(f"{path}: field 'initial.collective_deg' = {math.degrees(collective)!r}: outside "
                          f"collective_limits_deg {np.degrees(cfg.collective_limits).tolist()}")
    return cfg
