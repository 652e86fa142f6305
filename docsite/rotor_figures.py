"""The figures docs/rotorcraft_design.md's prose quotes from ``python -m
laddermill_gym.studies.rotorcraft.rotor_design``, parsed from its printed output (the text
:func:`docsite.page_figures.rotor_design` captures): per altitude the summary lines and the sensitivity rows, and
the craft estimates."""

from __future__ import annotations

import re

SENSITIVITY = {"no profile drag (delta = 0)": "no_drag", "weightless tethers": "weightless",
               "tether elevation 20 deg": "elev20", "craft mass x0.7": "mass07", "no tether stress limit": "no_limit",
               "solidity 0.075": "solidity"}


def parse_rotor_design(out: str) -> dict:
    """{"15kft"/"30kft": {peak_MW, stress_wind, stress_MW (15,000 ft only), cp_rated, ideal_wind, need_cp: {"atV":
    C_p}, sensitivity: {key: wind [m/s]}}, "craft_t": {"tipV": craft mass [t]}}, as the page rounds them (keys
    that are not all digits: str.format reads those as list indices)."""
    found = {}
    for alt in ("15,000", "30,000"):
        key = alt.replace(",000", "kft")
        summary = _get(rf"^{alt} ft: cut-in .*\n(?:    .*\n)+", out)
        sens = _get(rf"^Sensitivity at {alt} ft: .*\n(?:    .*\n)+", out)
        stress = re.search(r"first binds at (\d+) m/s \(([\d.]+) MW\)", summary)
        found[key] = {"peak_MW": _get(r"peak over 5-45 m/s ([\d.]+) MW at 45 m/s", summary, 1),
                      "stress_wind": stress.group(1) if stress else "", "stress_MW": stress.group(2) if stress else "",
                      "cp_rated": _get(r"3\.13 MW at [\d.]+ m/s: C_p ([\d.]+)", summary, 1),
                      "ideal_wind": _get(r"would give 3\.13 MW at ([\d.]+) m/s", summary, 1),
                      "need_cp": {f"at{v}": cp for v, cp in re.findall(r"(\d+) m/s (\d\.\d+)",
                                                                           _get(r"C_p that gives.*", summary))},
                      "sensitivity": {name: _get(rf"^ +{re.escape(label)} +[-\d.]+ MW +([\d.]+) m/s", sens, 1)
                                      for label, name in SENSITIVITY.items()}}
    found["craft_t"] = {f"tip{tip}": f"{int(kg) / 1000:.1f}" for tip, kg in
                        re.findall(r"Omega R (\d+) m/s: .*; craft (\d+) kg", out)}
    return found


def _get(pattern: str, text: str, group: int = 0) -> str:
    m = re.search(pattern, text, re.M)
    if m is None:
        raise RuntimeError(f"rotor_design printed nothing matching {pattern!r}")
    return m.group(group)
