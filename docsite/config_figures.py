"""Page groups that read the shipped configuration files (no command to run: the files are the model's inputs, an
independent source for the pages that derive or summarise them) and rework the pages' hand arithmetic in closed
form from the inputs the pages give."""

from __future__ import annotations

import math
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
CABLE = ROOT / "configs" / "cables" / "dyneema_25mm.yaml"
CRAFT = ROOT / "configs" / "rotorcraft" / "roberts_flying_model.yaml"
KEVLAR = ROOT / "configs" / "cables" / "kevlar_2p5mm.yaml"
#: docs/rotorcraft.md's mass build-up, as its table gives it: (part, mass [kg], x, y, z [m] from the hub line, z down,
#: own inertia: "rotor" a blade disk of radius R (m R^2/6 about a diameter, m R^2/3 about the shaft, body z),
#: ("rod", L, axis) a thin rod m L^2/12 about the two axes across it, "point" none); mirrored parts twice at +-y
CRAFT_PARTS = (("blades", 2.0, 0.0, 2.0, 0.0, "rotor"), ("blades", 2.0, 0.0, -2.0, 0.0, "rotor"),
               ("generator", 3.0, 0.0, 2.0, 0.25, "point"), ("generator", 3.0, 0.0, -2.0, 0.25, "point"),
               ("cross beam", 4.0, 0.0, 0.0, 0.3, ("rod", 4.0, "y")), ("boom", 3.0, -0.25, 0.0, 0.4, ("rod", 2.5, "x")),
               ("fins", 1.0, -1.5, 0.0, 0.1, "point"), ("electronics", 2.0, 0.2, 0.0, 0.7, "point"))


def cable_dyneema() -> dict:
    """``configs/cables/dyneema_25mm.yaml`` (diameter [m], mass_per_length [kg/m], EA [N], DA [N s], breaking_load
    [N], cn0, ct0, and tau = DA / EA [s]), and docs/cable_data.md's worked numbers from its given inputs: the paper's
    21 kg per 70 m piece and 2.5 cm, DSM's 120 N/tex modulus and 3.5 N/tex tenacity, 975 kg/m^3, the rope
    efficiencies 0.6 and 0.5, a 10 kN load on 70 m, the 54 kg wing (+ 1/3 of the piece), k = 4 and RK4's 2.78."""
    with open(CABLE) as f:
        cfg = yaml.safe_load(f)
    cfg = {k: float(v) for k, v in cfg.items()}
    cfg["tau"] = cfg["DA"] / cfg["EA"]
    mu = 21.0 / 70.0  # [kg/m] the paper's piece
    tex = mu * 1e6  # [tex] 1 tex = 1 g/km
    fibre_area = mu / 975.0  # [m^2]
    circle = math.pi * 0.025 ** 2 / 4  # [m^2]
    ea_fibre = 120.0 * tex  # [N] 120 N/tex x tex
    ea = 0.6 * ea_fibre
    mass = 54.0 + mu * 70.0 / 3  # [kg] the wing plus a third of the piece (consistent mass)
    omega = math.sqrt(ea / 70.0 / mass)
    lam70, lam7 = (4 * cfg["tau"] * ea / (mu * ll ** 2) for ll in (70.0, 7.0))
    worked = {"mu": mu, "tex": tex, "fibre_area": fibre_area, "fill": fibre_area / circle, "circle": circle,
              "ea_fibre": ea_fibre, "fibre_GPa": ea_fibre / fibre_area / 1e9, "ea": ea, "rope_GPa": ea / circle / 1e9,
              "stretch_cm": 1e4 * 70.0 / ea * 100, "strain_pct": 1e4 / ea * 100, "strength": 3.5 * tex,
              "breaking": 0.5 * 3.5 * tex, "k70": ea / 70.0, "mass": mass, "omega": omega,
              "loss": omega * cfg["tau"], "lam70": lam70, "dt70": 2.78 / lam70, "lam7": lam7,
              "dt7_ms": 2.78 / lam7 * 1e3}
    return {"config": cfg, "worked": worked, "page": {
        "mu": f"{mu:.2f}", "tex": sci(tex, 1), "fibre_area": sci(fibre_area, 2), "fill": f"{worked['fill']:.2f}",
        "circle": sci(circle, 2), "ea_fibre": sci(ea_fibre, 1), "fibre_GPa": f"{worked['fibre_GPa']:.0f}",
        "ea": sci(ea, 2), "rope_GPa": f"{worked['rope_GPa']:.0f}", "stretch_cm": f"{worked['stretch_cm']:.1f}",
        "strain_pct": f"{worked['strain_pct']:.2f}", "strength": sci(worked["strength"], 2),
        "breaking": sci(worked["breaking"], 2), "k70": sci(worked["k70"], 1), "mass": f"{mass:.0f}",
        "omega": f"{omega:.0f}", "loss": f"{worked['loss']:.2f}", "lam70": f"{lam70:.0f}",
        "dt70": f"{worked['dt70']:.3f}", "lam7": f"{round(lam7, -2):.0f}", "dt7_ms": f"{worked['dt7_ms']:.2f}"}}


def craft_data() -> dict:
    """docs/rotorcraft.md's data: ``config`` (configs/rotorcraft/roberts_flying_model.yaml's mass, inertia, hub and fin
    positions, rotor speed, fin slope, and its tether cable's EA [kN], mass [g/m], breaking load [kN]) and ``worked``
    (the same reworked in closed form from the page's inputs: the mass table summed about its CG, the hub and fin
    positions from the CG, Omega = V cos(alpha_c) / (mu R) at 10 m/s, 25 deg, mu 0.15, Helmbold's 2 pi A / (2 +
    sqrt(A^2 + 4)) at A = 1.5, and RK4's 2.78 / 473 1/s [ms]), each as the page rounds it."""
    with open(CRAFT) as f:
        cfg = yaml.safe_load(f)
    with open(KEVLAR) as f:
        cable = yaml.safe_load(f)
    radius = float(cfg["rotor_radius"])
    total = sum(p[1] for p in CRAFT_PARTS)
    xc, zc = (sum(p[1] * p[i] for p in CRAFT_PARTS) / total for i in (2, 4))
    j = {"xx": 0.0, "yy": 0.0, "zz": 0.0, "xz": 0.0}
    for _, m, x, y, z, own in CRAFT_PARTS:
        dx, dz = x - xc, z - zc
        j["xx"] += m * (y * y + dz * dz)
        j["yy"] += m * (dx * dx + dz * dz)
        j["zz"] += m * (dx * dx + y * y)
        j["xz"] += m * dx * dz
        if own == "rotor":
            j["xx"] += m * radius ** 2 / 6
            j["yy"] += m * radius ** 2 / 6
            j["zz"] += m * radius ** 2 / 3
        elif own != "point":
            across = {"x": ("yy", "zz"), "y": ("xx", "zz")}[own[2]]
            for axis in across:
                j[axis] += m * own[1] ** 2 / 12
    fin_x, fin_z = -1.5 - xc, 0.1 - zc  # the fins' point in the table
    worked = {"mass": f"{total:.1f}", "cg_x": f"{xc:.3f}", "cg_z": f"{zc:.2f}", "hub_height": f"{zc:.2f}",
              "hub_x": f"{-xc:.2f}", "fin_x": f"{fin_x:.2f}", "fin_z": f"{fin_z:.2f}",
              **{f"J{k}": f"{v:.{2 if k == 'xz' else 1}f}" for k, v in j.items()},
              "rotor_speed": f"{10 * math.cos(math.radians(25)) / (0.15 * radius):.1f}",
              "fin_slope": f"{2 * math.pi * 1.5 / (2 + math.sqrt(1.5 ** 2 + 4)):.1f}",
              "clearance": f"{cfg['hub_spacing'] - 2 * radius:.1f}"}
    inertia = dict(zip(("Jxx", "Jyy", "Jzz", "Jxz"), cfg["inertia"], strict=True))
    config = {"mass": f"{cfg['mass']:.1f}", "hub_height": f"{cfg['hub_height']:.2f}", "hub_x": f"{cfg['hub_x']:.2f}",
              "fin_x": f"{cfg['fin_x']:.2f}", "fin_z": f"{cfg['fin_z']:.2f}",
              **{k: f"{v:.{2 if k == 'Jxz' else 1}f}" for k, v in inertia.items()},
              "rotor_speed": f"{cfg['rotor_speed']:.1f}", "fin_slope": f"{cfg['fin_lift_slope']:.1f}",
              "fin_area": f"{cfg['fin_area']:.2f}", "drag_area": f"{cfg['drag_area']:.1f}",
              "diameter": f"{2 * radius:.1f}", "hub_spacing": f"{cfg['hub_spacing']:.1f}",
              "tether_length": f"{cfg['tethers']['length']:.0f}", "EA_kN": f"{cable['EA'] / 1e3:.0f}",
              "g_per_m": f"{cable['mass_per_length'] * 1e3:.1f}", "breaking_kN": f"{cable['breaking_load'] / 1e3:.1f}",
              "cable_mm": f"{cable['diameter'] * 1e3:.1f}", "collective_min": f"{cfg['collective_limits_deg'][0]:.0f}",
              "collective_max": f"{cfg['collective_limits_deg'][1]:.0f}",
              "differential": f"{cfg['differential_limits_deg'][1]:.0f}",
              "trim_collective": f"{cfg['initial']['collective_deg']:.0f}",
              "pitch": f"{cfg['tethers']['design_pitch_deg']:.0f}", "beta": f"{cfg['tethers']['elevation_deg']:.0f}",
              "attach_y": f"{cfg['tethers']['attach_rear'][1]:.1f}", "elements": str(cfg["tethers"]["elements"])}
    return {"config": config, "worked": worked}


def sci(x: float, digits: int) -> str:
    """``x`` in the pages' scientific notation: 3.0e5, 3.08e-4 (no plus sign, no leading zero in the exponent)."""
    mantissa, exponent = f"{x:.{digits}e}".split("e")
    return f"{mantissa}e{int(exponent)}"
