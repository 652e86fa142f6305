"""Capacity factor and annual energy of a conventional wind turbine on the same wind states, from windpowerlib's
turbine library (the open_energy database power curves it ships in its package data, read offline), beside the
pumping laddermill's. windpowerlib is the optional extra ``site``; it is imported only here."""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from laddermill_gym.atmosphere.site_wind import SiteWind

HOURS_PER_YEAR = 8766.0  # [h] a mean year (365.25 days)


@dataclass(frozen=True)
class Yield:
    """Energy yield of one machine on a site's wind states."""

    name: str
    rated_power: float      # [W]
    mean_power: float       # [W] time mean: sum of weight x power (time outside the data counts as no power)
    capacity_factor: float  # [-] mean / rated
    annual_energy: float    # [Wh] mean power x one year
    height: float           # [m] hub height or kite altitude

    def row(self) -> str:
        return (f"| {self.name} | {self.rated_power / 1e6:.2f} | {self.height:.0f} | {self.mean_power / 1e6:.3f} | "
                f"{100 * self.capacity_factor:.1f} | {self.annual_energy / 1e9:.2f} |")


def _windpowerlib():
    try:
        import windpowerlib
    except ImportError as err:  # pragma: no cover - depends on the install
        raise ImportError("the turbine comparison needs windpowerlib: pip install 'laddermill_gym[site]'") from err
    return windpowerlib


def turbine_library():
    """windpowerlib's turbine list (a pandas DataFrame: turbine_type, nominal_power [W], has_power_curve, ...)
    from the files shipped with the package (no network)."""
    _windpowerlib()
    from windpowerlib.data import get_turbine_types

    return get_turbine_types(print_out=False, filter_=True)


def nearest_turbine(rated_power: float) -> str:
    """The library turbine with a power curve whose nominal power is nearest to ``rated_power`` [W] (ties: the
    first in the library's order)."""
    from windpowerlib import WindTurbine

    lib = turbine_library()
    lib = lib[lib["has_power_curve"]]
    best, err = None, np.inf
    for name in lib["turbine_type"]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FutureWarning)
            warnings.simplefilter("ignore", DeprecationWarning)
            p = WindTurbine(turbine_type=name, hub_height=100.0).nominal_power
        if abs(p - rated_power) < err:
            best, err = name, abs(p - rated_power)
    return best


def turbine_yield(wind: SiteWind, turbine_type: str, hub_height: float) -> Yield:
    """Mean power of the windpowerlib turbine ``turbine_type`` at ``hub_height`` [m] over the wind states
    (power curve without density correction, at the curve's standard 1.225 kg/m^3, as the kite's side uses the
    paper's 1.225 kg/m^3; the 2010 data carry pressure and temperature, the Cabauw clusters no density)."""
    _windpowerlib()
    import pandas as pd
    from windpowerlib import WindTurbine
    from windpowerlib.power_output import power_curve

    with warnings.catch_warnings():  # windpowerlib 0.2 calls a pandas method pandas 3 deprecates
        warnings.simplefilter("ignore", FutureWarning)
        warnings.simplefilter("ignore", DeprecationWarning)
        t = WindTurbine(turbine_type=turbine_type, hub_height=hub_height)
    v = wind.at(hub_height)
    ok = np.isfinite(v)
    pc = t.power_curve
    p = power_curve(pd.Series(v[ok]), pc["wind_speed"], pc["value"]).to_numpy()
    mean = float(np.sum(wind.weight[ok] * p))
    name = f"{turbine_type} (windpowerlib)" + (" *" if wind.is_extrapolated(hub_height) else "")
    return Yield(name, float(t.nominal_power), mean, mean / t.nominal_power, mean * HOURS_PER_YEAR, hub_height)


def laddermill_yield(name: str, power: np.ndarray, weight: np.ndarray, rated_power: float, height: float,
                     extrapolated: bool) -> Yield:
    """Yield of the laddermill whose state powers [W] are ``power`` with a generator rated ``rated_power`` [W]
    (the power above it is lost); ``weight`` the states' time shares (time outside the data: no power)."""
    mean = float(np.sum(weight * np.minimum(power, rated_power)))
    return Yield(name + (" *" if extrapolated else ""), rated_power, mean, mean / rated_power,
                 mean * HOURS_PER_YEAR, height)
