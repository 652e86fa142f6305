"""The 35 m rotorcraft study over wind speed at one altitude (:func:`study_altitude`), and one-at-a-time
design changes at one wind speed (:func:`sensitivity`, :func:`tip_speed_scan`)."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.rotorcraft.rotor import RotorSolveError
from laddermill_gym.studies.rotorcraft.design_physics import HUB_SPACING, TIP_SPEEDS, craft_estimate
from laddermill_gym.studies.rotorcraft.rotor_design_data import (
    DEFAULT_WINDS,
    ROBERTS_PEAK_POWER,
    SAFE_FRACTION,
    RotorcraftDesign,
    check_design,
)
from laddermill_gym.studies.rotorcraft.rotor_design_points import OperatingPoint, best_operating_point, wind_for_power


# ------------------------------------------------------------------------------------------ the study
@dataclass(frozen=True)
class AltitudeStudy:
    """Power curve and summary of one craft config.

    Attributes
    ----------
    altitude_ft : int
        Nominal altitude [ft].
    design : RotorcraftDesign
    winds : np.ndarray
        Wind speeds [m/s], shape (n,).
    points : list
        Best :class:`OperatingPoint` at each wind speed, None where none is feasible; length n.
    peak : OperatingPoint
        The largest power over the wind range.
    stress_onset : OperatingPoint | None
        The first point at which the tether stress limit binds (None if it never does).
    wind_for_roberts : float
        Wind speed [m/s] at which the best power first reaches 3.13 MW (:func:`wind_for_power`; nan if never).
    roberts_point : OperatingPoint | None
        The best point at that wind speed.
    cut_in : float
        Lowest wind speed [m/s] with positive power (nan if none).
    """

    altitude_ft: int
    design: RotorcraftDesign
    winds: np.ndarray
    points: list
    peak: OperatingPoint
    stress_onset: OperatingPoint | None
    wind_for_roberts: float
    roberts_point: OperatingPoint | None
    cut_in: float


def study_altitude(design: RotorcraftDesign, altitude_ft: int, winds=DEFAULT_WINDS,
                   safe_fraction: float = SAFE_FRACTION) -> AltitudeStudy:
    """Best operating point at each wind speed [m/s] (increasing 1-D array) and the summary."""
    design = check_design(design)
    winds = np.asarray(winds, dtype=float)
    if winds.ndim != 1 or winds.size < 2 or not np.all(np.isfinite(winds)) or np.any(winds <= 0.0) \
            or np.any(np.diff(winds) <= 0.0):
        raise ValueError(f"argument 'winds' = {winds!r}: must be two or more increasing positive speeds")
    points = [best_operating_point(design, float(v), safe_fraction) for v in winds]
    ok = [p for p in points if p is not None]
    if not ok:
        raise RotorSolveError(f"{design.name}: no feasible operating point for winds {winds[0]}..{winds[-1]} m/s")
    power = np.array([p.power if p is not None else -np.inf for p in points])
    above = np.flatnonzero(power >= ROBERTS_PEAK_POWER)
    v_r = wind_for_power(design, ROBERTS_PEAK_POWER, float(winds[above[0]]), safe_fraction) if above.size else math.nan
    return AltitudeStudy(
        altitude_ft=altitude_ft, design=design, winds=winds, points=points, peak=max(ok, key=lambda p: p.power),
        stress_onset=next((p for p in ok if "stress" in p.binding), None), wind_for_roberts=v_r,
        roberts_point=best_operating_point(design, v_r, safe_fraction) if math.isfinite(v_r) else None,
        cut_in=next((p.wind for p in ok if p.power > 0.0), math.nan))


# ------------------------------------------------------------------------------------------ sensitivity
def sensitivity(design: RotorcraftDesign, wind: float, safe_fraction: float = SAFE_FRACTION
                ) -> list[tuple[str, float, float]]:
    """Best power [W] at wind [m/s] and the wind [m/s] that gives 3.13 MW for one-at-a-time design changes.

    Returns (label, power [W] or nan if infeasible, wind for 3.13 MW [m/s] or nan) for: the baseline, solidity
    0.075 (rotor.md's other reading of Roberts' 22.5 deg), no profile drag, tip speed -/+ 20 m/s, tether
    elevation 20 and 40 deg at the same altitude, craft mass x0.7 and x1.3, weightless tethers, and no tether
    stress limit.
    """
    d = check_design(design)
    cases = [
        ("baseline", d, safe_fraction),
        ("solidity 0.075", dataclasses.replace(d, rotor=d.rotor.with_solidity(0.075)), safe_fraction),
        ("no profile drag (delta = 0)", dataclasses.replace(d, rotor=d.rotor.ideal()), safe_fraction),
        ("tip speed -20 m/s", dataclasses.replace(d, rotor_speed=(d.tip_speed - 20.0) / d.radius), safe_fraction),
        ("tip speed +20 m/s", dataclasses.replace(d, rotor_speed=(d.tip_speed + 20.0) / d.radius), safe_fraction),
        ("tether elevation 20 deg", d.with_altitude_elevation(math.radians(20.0)), safe_fraction),
        ("tether elevation 40 deg", d.with_altitude_elevation(math.radians(40.0)), safe_fraction),
        ("craft mass x0.7", dataclasses.replace(d, mass=0.7 * d.mass), safe_fraction),
        ("craft mass x1.3", dataclasses.replace(d, mass=1.3 * d.mass), safe_fraction),
        ("weightless tethers", dataclasses.replace(d, cable_mass_per_length=1e-9), safe_fraction),
        ("no tether stress limit", dataclasses.replace(d, breaking_load=math.inf), safe_fraction),
    ]
    out = []
    for label, dd, sf in cases:
        p = best_operating_point(dd, wind, sf)
        out.append((label, p.power if p is not None else math.nan,
                    wind_for_power(dd, ROBERTS_PEAK_POWER, wind, sf)))
    return out


def tip_speed_scan(design: RotorcraftDesign, wind: float, tip_speeds=TIP_SPEEDS,
                   n_blades: int = 4, safe_fraction: float = SAFE_FRACTION) -> list[tuple[float, float, float]]:
    """Best power [W] at wind [m/s] for other tip speeds [m/s], the craft mass re-estimated by
    :func:`craft_estimate` for each (drive rated at Roberts' 3.13 MW). Returns (tip speed, mass [kg], power [W]
    or nan if infeasible)."""
    d = check_design(design)
    out = []
    for vt in tip_speeds:
        m = craft_estimate(d.radius, vt, d.rotor.sigma, n_blades, ROBERTS_PEAK_POWER / d.efficiency / d.n_rotors,
                           HUB_SPACING)["mass"]
        p = best_operating_point(dataclasses.replace(d, rotor_speed=vt / d.radius, mass=m), wind, safe_fraction)
        out.append((vt, m, p.power if p is not None else math.nan))
    return out
