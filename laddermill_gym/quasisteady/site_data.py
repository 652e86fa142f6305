"""The site wind data shipped in ``configs/wind`` (found through ``model.configio.CONFIG_DIR``), by name."""

from __future__ import annotations

from pathlib import Path

from laddermill_gym.atmosphere.site_wind import SiteWind, daily, read_profiles_csv
from laddermill_gym.atmosphere.site_wind_formats import read_clusters, read_two_heights, read_wyoming
from laddermill_gym.model.configio import CONFIG_DIR

WIND_DIR: Path = CONFIG_DIR / "wind"

#: shipped data sets: name -> what it is
SHIPPED = {
    "cabauw": "Cabauw (NL) 8 clustered profiles x 100 bins of the 100 m speed, 10-600 m, frequency weights "
              "(Schelbergen et al. 2020; MIT)",
    "weather2010": "hourly wind 2010 at 10 m and 80 m (windpowerlib example data; MIT); power-law extrapolation "
                   "from 80 m up to 600 m",
    "weather2010-daily": "the same, daily mean profiles (one state per day, as Lansdorp et al. 2008)",
}


def shipped_wind(name: str) -> SiteWind:
    """A shipped data set by name (see ``SHIPPED``)."""
    if name == "cabauw":
        return read_clusters([WIND_DIR / f"cabauw_8clusters_profile{k}.csv" for k in range(1, 9)],
                             WIND_DIR / "cabauw_8clusters_frequency.csv")
    if name in ("weather2010", "weather2010-daily"):
        # extrapolated up to 600 m only: the Cabauw data's top and the altitudes pumping systems use; a power law
        # fitted at 10 and 80 m says little about the wind higher up
        wind = read_two_heights(WIND_DIR / "windpowerlib_weather_2010.csv.gz", top=600.0)
        return daily(wind) if name.endswith("daily") else wind
    raise ValueError(f"unknown shipped wind data {name!r}; known: {sorted(SHIPPED)}")


def load_wind(spec: str, fmt: str = "auto") -> SiteWind:
    """A shipped name, or a file: ``fmt`` "csv" (profiles CSV), "wyoming", "two-heights", or "auto" (by the
    file's first line). Prefix "daily:" for daily means (e.g. ``daily:soundings.txt``)."""
    make_daily = spec.startswith("daily:")
    spec = spec[len("daily:"):] if make_daily else spec
    if spec in SHIPPED:
        wind = shipped_wind(spec)
    else:
        path = Path(spec)
        if fmt == "auto":
            from laddermill_gym.atmosphere.site_wind import open_text

            with open_text(path) as fh:
                head = fh.read(4000)
            fmt = ("two-heights" if head.startswith("variable_name") else
                   "wyoming" if "Observations at" in head else "csv")
        readers = {"csv": read_profiles_csv, "wyoming": read_wyoming, "two-heights": read_two_heights}
        if fmt not in readers:
            raise ValueError(f"wind format {fmt!r}: must be one of {sorted(readers)} or 'auto'")
        wind = readers[fmt](path)
    return daily(wind) if make_daily else wind
