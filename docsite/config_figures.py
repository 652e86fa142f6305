"""Page groups that read the shipped configuration files (no command to run: the files are the model's inputs, an
independent source for the pages that derive or summarise them) and rework the pages' hand arithmetic in closed
form from the inputs the pages give."""

from __future__ import annotations

import math
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
CABLE = ROOT / "configs" / "cables" / "dyneema_25mm.yaml"


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


def sci(x: float, digits: int) -> str:
    """``x`` in the pages' scientific notation: 3.0e5, 3.08e-4 (no plus sign, no leading zero in the exponent)."""
    mantissa, exponent = f"{x:.{digits}e}".split("e")
    return f"{mantissa}e{int(exponent)}"
