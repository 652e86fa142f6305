"""Steady-state design study of Roberts' twin 35 m rotorcraft at 15,000 ft and 30,000 ft (Roberts sec. 6, Table 1).

Run ``python -m laddermill_gym.studies.rotorcraft.rotor_design [--out runs/rotor_design]`` (about 8 s).

For each craft config (``configs/rotorcraft/roberts_35m_15kft.yaml``, ``..._30kft.yaml``) and each wind speed V
at the craft, the craft incidence alpha_c and the collective theta0 are chosen to maximise the electrical
power 2 (-Q Omega) 0.95 subject to

* the blade-incidence limit: retreating-tip incidence <= 13 deg (``laddermill_gym.rotorcraft.rotor``);
* lift: the three tethers of the config length, heavy inextensible catenaries each loaded at the craft end by
  a third of the craft's net force (rotor forces and frame drag less the weight), must reach the design
  altitude and must leave their anchors upwards: the craft carries its own weight and all of the tethers';
* tether stress: the top tension (the largest along a hanging cable) <= ``SAFE_FRACTION`` x breaking load.

The density is the ISA troposphere at the design altitude; the rotor speed is the config's. The command prints
the craft estimate, the power table, the peak power at each altitude beside Roberts' 3.13 MW, what reproduces
3.13 MW and a sensitivity table, and writes ``design_study.csv`` and ``power_curves.png``. Method, sources and
choices: ``laddermill_gym/docs/rotorcraft_design.md``. This module is the command and re-exports the study's names;
the code lives in ``design_physics`` (atmosphere, catenary, craft estimate), ``rotor_design_data`` (the design),
``rotor_design_points`` (operating points), ``rotor_design_sweeps`` (wind and design sweeps) and
``rotor_design_output`` (CSV and figure).

Units: SI (m, s, kg, N, W, Pa); angles in radians unless a name ends in ``_deg``.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

from laddermill_gym.rotorcraft.rotor import ideal_power_coefficient
from laddermill_gym.studies.rotorcraft.design_physics import (
    FOOT,
    HUB_SPACING,
    Catenary,
    catenary,
    craft_estimate,
    isa_density,
    isa_temperature,
    speed_of_sound,
)
from laddermill_gym.studies.rotorcraft.rotor_design_data import (
    ALTITUDES_FT,
    CRAFT_CONFIGS,
    DEFAULT_OUT,
    DEFAULT_WINDS,
    KEVLAR_DENSITY,
    KEVLAR_MASS_FRACTION,
    ROBERTS_PEAK_POWER,
    SAFE_FRACTION,
    RotorcraftDesign,
    load_design,
)
from laddermill_gym.studies.rotorcraft.rotor_design_output import plot_power_curves, write_csv
from laddermill_gym.studies.rotorcraft.rotor_design_points import (
    OperatingPoint,
    best_operating_point,
    cp_for_power,
    evaluate_point,
    power_for_cp,
    wind_for_power,
)
from laddermill_gym.studies.rotorcraft.rotor_design_sweeps import (
    AltitudeStudy,
    sensitivity,
    study_altitude,
    tip_speed_scan,
)

__all__ = [
    "FOOT", "ROBERTS_PEAK_POWER", "ALTITUDES_FT", "CRAFT_CONFIGS", "SAFE_FRACTION", "KEVLAR_DENSITY",
    "KEVLAR_MASS_FRACTION", "DEFAULT_WINDS", "DEFAULT_OUT", "isa_temperature", "isa_density", "speed_of_sound",
    "Catenary", "catenary", "RotorcraftDesign", "load_design", "OperatingPoint", "evaluate_point",
    "best_operating_point", "wind_for_power", "AltitudeStudy", "study_altitude", "power_for_cp", "cp_for_power",
    "craft_estimate", "sensitivity", "tip_speed_scan", "write_csv", "plot_power_curves", "main",
]



def _print_design(st: AltitudeStudy) -> None:
    d = st.design
    allowed = SAFE_FRACTION * d.breaking_load
    print(f"{st.altitude_ft:,} ft ({d.name}): altitude {d.altitude:.0f} m, ISA density {isa_density(d.altitude):.4f} "
          f"kg/m^3, speed of sound {speed_of_sound(d.altitude):.1f} m/s; R {d.radius} m, Omega R {d.tip_speed:.1f} "
          f"m/s; craft {d.mass:.0f} kg; 3 tethers {d.tether_length:.0f} m at {math.degrees(d.tether_elevation):g} "
          f"deg, {d.cable_mass_per_length * d.tether_length:.0f} kg each; allowed tension {allowed / 1e3:.1f} kN "
          f"({allowed / d.kevlar_area / 1e6:.0f} MPa in the Kevlar)")


def _print_table(studies: list[AltitudeStudy]) -> None:
    head = " P [MW]    C_p  a_c  th0     mu  T [kN] util binding     "
    print("   V |" + "|".join(f" {st.altitude_ft:,} ft:".ljust(len(head)) for st in studies))
    print("m/s  |" + "|".join(head for _ in studies))
    for i, v in enumerate(studies[0].winds):
        cells = []
        for st in studies:
            p = st.points[i]
            cells.append(" landed: cannot hold the altitude".ljust(len(head)) if p is None else
                         f"{p.power / 1e6:7.3f} {p.cp:6.3f} {math.degrees(p.alpha_c):4.1f} "
                         f"{math.degrees(p.theta0):4.1f} {p.mu:6.3f} {p.tether.top_tension / 1e3:7.1f} "
                         f"{p.utilisation:4.2f} {p.binding or '-':<12}")
        print(f"{v:4.0f} |" + "|".join(cells))


def main(argv: list[str] | None = None) -> list[AltitudeStudy]:
    """Command line: run the study at both altitudes, print the results, write the CSV and the PNG."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=str(DEFAULT_OUT), help="output folder (design_study.csv, power_curves.png)")
    out = Path(ap.parse_args(argv).out)
    t0 = time.perf_counter()
    studies = [study_altitude(load_design(CRAFT_CONFIGS[a]), a) for a in ALTITUDES_FT]

    print(f"Craft estimate (drive rated 3.13 MW / 0.95 / 2 per rotor, 4 blades, hub spacing {HUB_SPACING:g} m):")
    for st in studies:
        d = st.design
        e = craft_estimate(d.radius, d.tip_speed, d.rotor.sigma, 4, ROBERTS_PEAK_POWER / 0.95 / 2, HUB_SPACING)
        print(f"  Omega R {d.tip_speed:.0f} m/s: per rotor blades {e['blades']:.0f}, hub {e['hub']:.0f}, drive "
              f"{e['drive']:.0f}, generator {e['generator']:.0f} kg; frame {e['frame']:.0f} kg; craft {e['mass']:.0f}"
              f" kg; hubs {e['hub_height']:.2f} m above and {e['hub_x']:.2f} m ahead of the CG; J = "
              f"[{e['Jxx']:.3g}, {e['Jyy']:.3g}, {e['Jzz']:.3g}, {e['Jxz']:.3g}] kg m^2")
    print()
    for st in studies:
        _print_design(st)
    print()
    _print_table(studies)
    print()
    for st in studies:
        pk, d, rp, onset = st.peak, st.design, st.roberts_point, st.stress_onset
        rho = isa_density(d.altitude)
        top = ", the top of the range" if pk.wind == st.winds[-1] else ""
        print(f"{st.altitude_ft:,} ft: cut-in {st.cut_in:g} m/s; peak over {st.winds[0]:g}-{st.winds[-1]:g} m/s "
              f"{pk.power / 1e6:.2f} MW at {pk.wind:g} m/s{top} (binding: {pk.binding or 'none'}); tether stress limit "
              + (f"first binds at {onset.wind:g} m/s ({onset.power / 1e6:.2f} MW)." if onset else "never binds."))
        if rp is not None:
            cp_ideal = float(ideal_power_coefficient(rp.alpha_c))
            unit = power_for_cp(cp_ideal, 1.0, rho, d.radius, d.n_rotors, d.efficiency)
            v_ideal = (ROBERTS_PEAK_POWER / unit) ** (1.0 / 3.0)
            print(f"    3.13 MW at {st.wind_for_roberts:.1f} m/s: C_p {rp.cp:.3f}, alpha_c "
                  f"{math.degrees(rp.alpha_c):.1f} deg, theta0 {math.degrees(rp.theta0):.2f} deg, mu {rp.mu:.3f}, tip "
                  f"{math.degrees(rp.tip_aoa):.2f} deg, tension {rp.tether.top_tension / 1e3:.1f} kN = "
                  f"{rp.stress / 1e6:.0f} MPa (utilisation {rp.utilisation:.2f}), chord "
                  f"{math.degrees(rp.tether.chord_angle):.1f} deg, binding: {rp.binding or 'none'}.")
            print(f"    ideal C_p at that incidence {cp_ideal:.3f} would give 3.13 MW at {v_ideal:.1f} m/s.")
        cps = ", ".join(f"{v:g} m/s {cp_for_power(ROBERTS_PEAK_POWER, v, rho, d.radius):.3f}"
                        for v in (15.0, 20.0, 25.0, 30.0, 35.0))
        print(f"    C_p that gives 3.13 MW at {cps} (Betz 16/27 = 0.593).")
    for st in studies:
        v_ref = float(math.ceil(st.wind_for_roberts)) if math.isfinite(st.wind_for_roberts) else float(st.peak.wind)
        print(f"\nSensitivity at {st.altitude_ft:,} ft: best power at {v_ref:g} m/s, and the wind that gives 3.13 MW")
        scan = ", ".join(f"{vt:g}: {p / 1e6:.2f}" if math.isfinite(p) else f"{vt:g}: -"
                         for vt, _, p in tip_speed_scan(st.design, v_ref))
        print(f"    tip speed [m/s]: power [MW] (craft mass re-estimated; -: cannot hold the altitude): {scan}")
        for label, p, v in sensitivity(st.design, v_ref):
            reach = f"{v:6.1f} m/s" if math.isfinite(v) else "not reached below 60 m/s"
            print(f"    {label:<30} {p / 1e6:7.2f} MW   {reach}")
    write_csv(out / "design_study.csv", studies)
    plot_power_curves(out / "power_curves.png", studies)
    print(f"\nwrote {out / 'design_study.csv'} and {out / 'power_curves.png'} ({time.perf_counter() - t0:.1f} s)")
    return studies


if __name__ == "__main__":
    main()
