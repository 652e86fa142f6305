"""Design data of the 35 m rotorcraft study (``laddermill_gym.studies.rotorcraft.rotor_design``): Roberts' numbers, the
craft configs of the two altitudes, the tether material, and :class:`RotorcraftDesign` read from a craft YAML.

Units: SI (m, s, kg, N, W, Pa); angles in radians unless a name ends in ``_deg``."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.model.configio import CONFIG_DIR, config_path, read_yaml
from laddermill_gym.rotorcraft.rotor import RotorParams, load_rotor_config

#: Roberts' Table 1: peak electrical power output, the same at both altitudes [W].
ROBERTS_PEAK_POWER = 3.13e6
#: The two altitudes of Roberts' sec. 6 [ft].
ALTITUDES_FT: tuple[int, ...] = (15000, 30000)
#: Craft config of each altitude [ft].
CRAFT_CONFIGS: dict[int, Path] = {
    15000: CONFIG_DIR / "rotorcraft" / "roberts_35m_15kft.yaml",
    30000: CONFIG_DIR / "rotorcraft" / "roberts_35m_30kft.yaml",
}
#: Allowed top tension over the rope breaking load [-]; chosen: design factor 2 (rotorcraft_design.md).
SAFE_FRACTION = 0.5
#: Kevlar 49 density [kg/m^3] (DuPont, Kevlar aramid fiber technical guide).
KEVLAR_DENSITY = 1440.0
#: Share of the cable mass in the Kevlar tensile member [-] (Roberts sec. 6: "half of this figure").
KEVLAR_MASS_FRACTION = 0.5
#: Wind speeds at the craft of the study [m/s].
DEFAULT_WINDS = np.arange(5.0, 45.5, 1.0)
DEFAULT_OUT = Path("runs/rotor_design")


# ------------------------------------------------------------------------------------------ design data
@dataclass(frozen=True)
class RotorcraftDesign:
    """What the steady study needs of a craft config (:func:`load_design`).

    Attributes
    ----------
    name : str
    rotor : RotorParams
        Blade data of each rotor.
    blade_limit : float
        Retreating-tip incidence limit [rad].
    radius, rotor_speed : float
        Rotor radius R [m]; rotor speed Omega [rad/s], held by the generators.
    mass, gravity : float
        Craft mass without tethers [kg]; [m/s^2].
    drag_area : float
        Frame C_D A [m^2] (drag 1/2 rho V^2 C_D A, horizontal).
    efficiency : float
        Electrical efficiency from shaft to grid [-].
    tether_length, tether_elevation : float
        Length of each tether [m]; design cable angle beta [rad]. Design altitude = length sin(beta).
    cable_mass_per_length, breaking_load : float
        [kg/m]; rope breaking load of one tether [N].
    n_rotors, n_tethers : int
        2 rotors; 3 tethers sharing the net force equally.
    """

    name: str
    rotor: RotorParams
    blade_limit: float
    radius: float
    rotor_speed: float
    mass: float
    gravity: float
    drag_area: float
    efficiency: float
    tether_length: float
    tether_elevation: float
    cable_mass_per_length: float
    breaking_load: float
    n_rotors: int = 2
    n_tethers: int = 3

    @property
    def altitude(self) -> float:
        """Design altitude above the anchors [m]."""
        return self.tether_length * math.sin(self.tether_elevation)

    @property
    def tip_speed(self) -> float:
        """Omega R [m/s]."""
        return self.rotor_speed * self.radius

    @property
    def disk_area(self) -> float:
        """pi R^2 of one rotor [m^2]."""
        return math.pi * self.radius ** 2

    @property
    def kevlar_area(self) -> float:
        """Cross-section of one tether's Kevlar member [m^2]: its mass share over the Kevlar density."""
        return KEVLAR_MASS_FRACTION * self.cable_mass_per_length / KEVLAR_DENSITY

    def with_altitude_elevation(self, elevation: float) -> RotorcraftDesign:
        """The same craft at the same altitude on tethers at another design elevation [rad]."""
        return dataclasses.replace(self, tether_elevation=elevation, tether_length=self.altitude / math.sin(elevation))


def load_design(path: Path | str) -> RotorcraftDesign:
    """Read the study's numbers from a craft YAML (the schema of ``configs/rotorcraft/roberts_flying_model.yaml``)
    and the rotor and cable files it names. Only the fields used here are read (the full loader is
    ``laddermill_gym.rotorcraft.config``); errors name the file, the field and the value (ConfigError)."""
    path = Path(path)
    s = read_yaml(path)
    rotor_cfg = load_rotor_config(config_path("rotors", s.text("rotor"), path.parent))
    t = s.section("tethers")
    c = read_yaml(config_path("cables", t.text("cable"), path.parent))
    elevation_deg = t.number("elevation_deg", positive=True)
    if not elevation_deg < 90.0:
        raise t.error("elevation_deg", elevation_deg, "must be < 90")
    efficiency = s.number("electrical_efficiency", positive=True)
    if efficiency > 1.0:
        raise s.error("electrical_efficiency", efficiency, "must be <= 1")
    return RotorcraftDesign(
        name=s.text("name"), rotor=rotor_cfg.params, blade_limit=rotor_cfg.blade_incidence_limit,
        radius=s.number("rotor_radius", positive=True), rotor_speed=s.number("rotor_speed", positive=True),
        mass=s.number("mass", positive=True), gravity=s.number("gravity", positive=True),
        drag_area=s.number("drag_area", nonneg=True), efficiency=efficiency,
        tether_length=t.number("length", positive=True), tether_elevation=math.radians(elevation_deg),
        cable_mass_per_length=c.number("mass_per_length", positive=True),
        breaking_load=c.number("breaking_load", positive=True))


def check_design(design) -> RotorcraftDesign:
    """``design`` when it is a RotorcraftDesign (ValueError naming the argument otherwise)."""
    if not isinstance(design, RotorcraftDesign):
        raise ValueError(f"argument 'design' = {design!r}: must be a RotorcraftDesign")
    return design
