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


def scan_figures(out: str) -> dict:
    """The figures docs/rotorcraft_design.md works from rotor_design's scan and sensitivity lines, as the page rounds
    them: per altitude the two best tip speeds ("170 and 180") and how far apart [%, whole], the drop at 160 m/s
    against the design tip [%, whole], the smallest tip that holds the altitude [m/s], the collectives' range over the
    wind scan [deg, "-0.4..8.4"], the tether utilisation's shortfall from ``from_wind`` m/s on ("2-4" %), and the
    rated wind's gain without the stress limit [m/s]; the density ratio of 30,000 to 15,000 ft, the 30,000 ft
    tethers' mass [t] and the rated winds' difference [m/s, whole]."""
    found = {}
    for alt, col in (("15,000", 0), ("30,000", 1)):
        key = alt.replace(",000", "kft")
        line = _get(rf"^Sensitivity at {alt} ft:.*\n +tip speed .*altitude\): (.*)$", out, 1)
        tips = dict(re.findall(r"(\d+): ([\d.]+|-)", line))
        held = {int(t): float(p) for t, p in tips.items() if p != "-"}
        top = sorted(sorted(held, key=held.get)[-2:])
        design = int(float(_get(rf"^{alt} ft \(.*Omega R ([\d.]+) m/s", out, 1)))
        rows = [line.split("|")[1 + col].split() for line in out.splitlines() if re.match(r"^ +\d+ \| +-?\d", line)]
        theta = [float(r[3]) for r in rows]
        util = [float(r[6]) for r, v in zip(rows, re.findall(r"^ +(\d+) \|", out, re.M), strict=True) if int(v) >= 24]
        summary = _get(rf"^{alt} ft: cut-in .*\n(?:    .*\n)+", out)
        rated = float(_get(r"3\.13 MW at ([\d.]+) m/s", summary, 1))
        no_limit = float(_get(rf"^Sensitivity at {alt} ft: .*\n(?:    .*\n)*? +no tether stress limit +[\d.]+ MW "
                              r"+([\d.]+) m/s", out, 1))
        found[key] = {"best": f"{top[0]} and {top[1]}",
                      "apart_pct": f"{100 * abs(held[top[1]] / held[top[0]] - 1):.0f}",
                      "drop160_pct": f"{100 * (1 - held[160] / held[design]):.0f}" if 160 in held else "-",
                      "lowest_tip": str(min(held)), "low_best": str(top[0]),
                      "design_tip": str(design), "theta": f"{min(theta)}..{max(theta)}", "rated": rated,
                      "short_pct": f"{100 * (1 - max(util)):.0f}-{100 * (1 - min(util)):.0f}",
                      "earlier": f"{rated - no_limit:.1f}"}
    rho = [float(r) for r in re.findall(r"ISA density ([\d.]+) kg/m\^3", out)]
    kg = re.findall(r"^30,000 ft \(.*?(\d) tethers .*?, (\d+) kg each", out, re.M)[0]
    found.update(rho_ratio=f"{rho[1] / rho[0]:.2f}", tethers_t=f"{int(kg[0]) * int(kg[1]) / 1000:.1f}",
                 rated_gap=f"{found['30kft']['rated'] - found['15kft']['rated']:.0f}")
    return found


def _get(pattern: str, text: str, group: int = 0) -> str:
    m = re.search(pattern, text, re.M)
    if m is None:
        raise RuntimeError(f"rotor_design printed nothing matching {pattern!r}")
    return m.group(group)
