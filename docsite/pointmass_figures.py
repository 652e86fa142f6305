"""The page group of docs/pointmass.md's closed forms (no command to run): the explicit method's two stable-step
bounds for the shipped 2.5 cm Dyneema (``configs/cables/dyneema_25mm.yaml``) at 1 cm and at 70 m, the state's memory,
the checkpoint spacing, the partition model's speed-ups, the base tension's share of the breaking load, the kites'
C_L and C_L/C_D at 6 deg from the shipped table, and the point-mass kite's sideways move under a 0.01 rad turn."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent
CABLE = ROOT / "configs" / "cables" / "dyneema_25mm.yaml"
TABLE = ROOT / "configs" / "wings" / "meijaard_wing_aero.csv"


def _table_row(alpha_deg: float) -> dict:
    with open(TABLE) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return next(r for r in rows if float(r["alpha_deg"]) == alpha_deg)


def pointmass_data() -> dict:
    """The figures as the page rounds them (strings)."""
    with open(CABLE) as f:
        cable = {k: float(v) for k, v in yaml.safe_load(f).items()}
    ea, da, mu = cable["EA"], cable["DA"], cable["mass_per_length"]
    wave = math.sqrt(ea / mu)  # [m/s] axial wave speed
    nodes = 500_000
    row = _table_row(6.0)
    cl, cd = float(row["CL"]), float(row["CD"])
    return {"EA": f"{ea:.3g}", "DA": f"{da:.3g}", "mu": f"{mu:g}", "wave_dt_1cm": f"{0.01 / wave:.1e}",
            "damp_dt_1cm": f"{mu * 0.01 ** 2 / (2 * da):.1e}", "wave_dt_70m_ms": f"{70.0 / wave * 1e3:.2f}",
            "state_MB": f"{48 * nodes / 1e6:g}", "tension_MB": f"{8 * nodes / 1e6:g}", "flag_MB": f"{nodes / 1e6:g}",
            "seg": f"{int(math.sqrt(nodes))}", "speedup": [f"{(3 * p + 4) / 5:g}" for p in (2, 4, 8, 16)],
            "base_share_pct": f"{100 * 195e3 / cable['breaking_load']:.0f}", "cl6": f"{cl:.2f}",
            "ld6": f"{cl / cd:.1f}", "sideways_m": f"{0.01 * 14.3:.3f}"}
