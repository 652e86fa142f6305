"""docs/rotorcraft_design.md's inputs and hand arithmetic: the two 35 m craft configs, their tether cable and rotor
files read as shipped, and the page's worked figures recomputed in closed form from the inputs the page gives (no
command to run: the files are the study's inputs, an independent source for the page that derives them)."""

from __future__ import annotations

import math
from pathlib import Path

import yaml

from docsite.config_figures import sci

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = ROOT / "configs"
FT = 0.3048  # [m] the international foot
R_AIR, GAMMA, T0, LAPSE, P_EXP = 287.05, 1.4, 288.15, 0.0065, 5.256  # ISA (ICAO): J/(kg K), -, K, K/m, -
P0 = 101325.0  # [Pa] ISA sea-level pressure


def _yaml(path: Path) -> dict:
    with open(path) as f:
        return yaml.safe_load(f)


def _isa(h: float) -> tuple[float, float]:
    """ISA troposphere at ``h`` [m]: (density [kg/m^3], speed of sound [m/s])."""
    t = T0 - LAPSE * h
    return P0 * (t / T0) ** P_EXP / (R_AIR * t), math.sqrt(GAMMA * R_AIR * t)


def _tether() -> dict:
    """The Kevlar-aluminium tether worked from the page's inputs: 0.115 kg/m each of Kevlar (1440 kg/m^3, 112 GPa,
    3.6 GPa, rope efficiency 0.67) and aluminium (2705 kg/m^3, 2.83e-8 ohm m), fill factor 0.8, design factor 2."""
    kevlar, alu = 0.115 / 1440.0, 0.115 / 2705.0  # [m^2]
    solid = kevlar + alu
    breaking = 3.6e9 * kevlar * 0.67  # [N]
    return {"kevlar_m2": sci(kevlar, 2), "EA_N": sci(112e9 * kevlar, 2), "breaking_kN": f"{breaking / 1e3:.0f}",
            "alu_m2": sci(alu, 2), "solid_m2": sci(solid, 2),
            "solid_mm": f"{2e3 * math.sqrt(solid / math.pi):.1f}",
            "cable_mm": f"{2e3 * math.sqrt(solid / 0.8 / math.pi):.0f}",
            "alu10_kg_m": f"{math.pi * 0.01 ** 2 / 4 * 2705.0:.3f}", "allowed_kN": f"{breaking / 2 / 1e3:.1f}",
            "allowed_MPa": f"{breaking / 2 / kevlar / 1e6:.0f}", "ohm_m": sci(2.83e-8 / alu, 1)}


def design_data() -> dict:
    """``config`` (per altitude "15kft"/"30kft": configs/rotorcraft/roberts_35m_*.yaml's rotor speed, tether length,
    v1, fin and drag areas, fin position, attachments, mass [t], hub height, collective and pitch; and the cable's EA,
    breaking load, mass per length) and ``worked`` (the same and the page's other arithmetic in closed form: ISA
    densities and tip Mach numbers, h / sin 30 deg, the wind gradients, the tip speeds over R, the flying model
    scaled by 17.5/1.85, the tether's sections and strengths, Table 1's energy, the drive rating and chord, the
    generators' kg/kW), each as the page rounds it."""
    cable = _yaml(CONFIGS / "cables" / "kevlar_aluminium_10mm.yaml")
    sigma = float(_yaml(CONFIGS / "rotors" / "roberts_rotor.yaml")["sigma"])
    k, radius = 17.5 / 1.85, 17.5
    config, worked = {}, {"scale": f"{k:.2f}", "fin_area": f"{0.15 * k * k:.1f}", "fin_x": f"{-1.5 * k:.1f}",
                          "fin_z": f"{-0.3 * k:.2f}", "drag_area": f"{0.3 * k * k:.1f}", "rear_x": f"{-0.5 * k:.2f}",
                          "rear_y": f"{0.3 * k:.2f}", "front_x": f"{1.0 * k:.2f}",
                          "scaled_t": f"{20.0 * k ** 3 / 1e3:.1f}",
                          "disk_m2": f"{13.3e6 / 6910:.0f}", "two_disks_m2": f"{2 * math.pi * radius ** 2:.0f}",
                          "energy48": f"{3.13 * 8760 * 0.48 / 1e3:.1f}", "energy67": f"{3.13 * 8760 * 0.67 / 1e3:.1f}",
                          "drive_MW": f"{3.13 / 0.95 / 2:.2f}", "chord": f"{sigma * math.pi * radius / 4:.2f}",
                          "gen_kg_kW": f"{6.47 * 1650 ** 0.9223 / 1650:.1f}", "motor_kg_kW": f"{50 / 260:.2f}",
                          "mi26_tip": f"{132 * 2 * math.pi / 60 * 16:.0f}", **_tether()}
    for key, feet, wind, tip in (("15kft", 15000, 26, 180), ("30kft", 30000, 33, 230)):
        cfg = _yaml(CONFIGS / "rotorcraft" / f"roberts_35m_{key}.yaml")
        h = feet * FT
        rho, sound = _isa(h)
        length = h / math.sin(math.radians(30))
        alpha = float(cfg["tethers"]["design_pitch_deg"])
        worked[key] = {"h": f"{h:.0f}", "rho": f"{rho:.4f}", "length": f"{length:.0f}",
                       "length_km": f"{length / 1e3:.1f}", "tether_t": f"{0.23 * length / 1e3:.1f}",
                       "tethers_t": f"{3 * 0.23 * length / 1e3:.1f}", "v1": sci((wind - 10) / (h - 1000), 3),
                       "v1_den": f"{h - 1000:.0f}", "omega": f"{tip / radius:.3f}",
                       "mach": f"{(tip + wind * math.cos(math.radians(alpha))) / sound:.2f}"}
        t = cfg["tethers"]
        config[key] = {"omega": f"{cfg['rotor_speed']:.3f}", "length": f"{t['length']:.0f}",
                       "v1": sci(cfg["wind"]["v1"], 3), "fin_area": f"{cfg['fin_area']:.1f}",
                       "fin_x": f"{cfg['fin_x']:.1f}", "fin_z": f"{cfg['fin_z']:.2f}",
                       "drag_area": f"{cfg['drag_area']:.1f}", "rear_x": f"{t['attach_rear'][0]:.2f}",
                       "rear_y": f"{t['attach_rear'][1]:.2f}", "front_x": f"{t['attach_front'][0]:.2f}",
                       "mass_t": f"{cfg['mass'] / 1e3:.1f}", "hub_height": f"{cfg['hub_height']:.2f}",
                       "collective": f"{cfg['initial']['collective_deg']:.1f}", "pitch": f"{alpha:.1f}",
                       "elevation": f"{t['elevation_deg']:.0f}"}
    config["cable"] = {"EA_N": sci(cable["EA"], 2),
                       "breaking_kN": f"{cable['breaking_load'] / 1e3:.0f}", "mu": f"{cable['mass_per_length']:.2f}",
                       "cable_mm": f"{cable['diameter'] * 1e3:.0f}"}
    return {"config": config, "worked": worked}
