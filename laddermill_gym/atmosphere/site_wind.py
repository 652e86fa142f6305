"""Site wind data for the quasi-steady site studies: many wind profiles (wind states) with the share of time each
stands for, read from a plain CSV of profiles (this file), the University of Wyoming upper-air text format, the
clustered-profile representation and two-height hourly series (``site_wind_formats.py``).

A ``SiteWind`` holds n profiles on one height grid (m heights, ascending): ``speed`` has shape (n, m) [m/s], NaN
where a profile has no data. ``at(h)`` interpolates linearly in height, as Lansdorp et al. (2008, section V) do
with their soundings. Heights above ``measured_top`` come from an extrapolation (``extrapolation`` says which);
a study that uses them says so. Plain numpy; bad input raises ``SiteWindError`` naming the file, line and field.
"""

from __future__ import annotations

import csv
import gzip
import io
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


class SiteWindError(ValueError):
    """A wind-data file that cannot be read: the message names the file, the line and the field."""


#: accepted units of the CSV columns: factor to SI
HEIGHT_UNITS = {"m": 1.0, "km": 1000.0, "ft": 0.3048}
SPEED_UNITS = {"m/s": 1.0, "knot": 1852.0 / 3600.0, "kt": 1852.0 / 3600.0, "km/h": 1.0 / 3.6}  # 1 knot = 1852 m/h
DIRECTION_UNITS = {"deg": 1.0}


@dataclass(frozen=True)
class SiteWind:
    """Wind states of a site.

    heights : (m,) [m] above ground, ascending
    speed : (n, m) [m/s] horizontal wind speed, NaN where a profile has no data
    weight : (n,) [-] share of the time each state stands for (they add up to at most 1; the rest of the time
        is outside the data, e.g. the clusters' wind-speed bins cover 56.6 % of the time)
    labels : (n,) time stamp or cluster and bin of each state
    direction : (n, m) [deg] wind direction (from which it blows) or None
    measured_top : [m] highest measured height; above it the profiles are an extrapolation
    extrapolation : how the profile above ``measured_top`` was made ("" when nothing is extrapolated)
    source : where the data came from (file names, citation)
    """

    heights: np.ndarray
    speed: np.ndarray
    weight: np.ndarray
    labels: tuple[str, ...]
    direction: np.ndarray | None = None
    measured_top: float = np.inf
    extrapolation: str = ""
    source: str = ""
    notes: tuple[str, ...] = field(default_factory=tuple)

    def __post_init__(self):
        h, v, w = self.heights, self.speed, self.weight
        if h.ndim != 1 or v.shape != (w.size, h.size) or len(self.labels) != w.size:
            raise ValueError(f"SiteWind: shapes heights {h.shape}, speed {v.shape}, weight {w.shape}, "
                             f"labels {len(self.labels)} do not match")
        if np.any(np.diff(h) <= 0):
            raise ValueError("SiteWind: heights must be strictly ascending")
        bad = np.flatnonzero(~np.isfinite(w))
        if bad.size:
            raise ValueError(f"SiteWind: weight {float(w[bad[0]])} of state {self.labels[int(bad[0])]!r}: weights must "
                             "be finite")
        if np.any(w < 0) or w.sum() > 1.0 + 1e-9:
            raise ValueError(f"SiteWind: weights must be >= 0 and add up to <= 1 (sum {w.sum():.6g})")

    @property
    def n(self) -> int:
        return self.weight.size

    def at(self, h: float) -> np.ndarray:
        """Wind speed [m/s] of every state at height ``h`` [m] (shape (n,)), linear in height between the grid
        heights; NaN where a state has no data there. Raises outside the grid."""
        hs = self.heights
        if not hs[0] <= h <= hs[-1]:
            raise ValueError(f"height {h:g} m outside the data's {hs[0]:g}-{hs[-1]:g} m ({self.source})")
        j = int(np.clip(np.searchsorted(hs, h) - 1, 0, hs.size - 2))
        t = (h - hs[j]) / (hs[j + 1] - hs[j])
        if t == 0.0 or t == 1.0:  # on a grid height: its own values (0 x NaN below a profile's start is NaN)
            return self.speed[:, j + int(t)].copy()
        return (1.0 - t) * self.speed[:, j] + t * self.speed[:, j + 1]

    def is_extrapolated(self, h: float) -> bool:
        return h > self.measured_top

    def subset(self, index) -> SiteWind:
        """The states ``index`` (a slice, mask or index array); weights kept as they are."""
        idx = np.arange(self.n)[index]
        return SiteWind(self.heights, self.speed[idx], self.weight[idx], tuple(self.labels[i] for i in idx),
                        None if self.direction is None else self.direction[idx], self.measured_top,
                        self.extrapolation, self.source, self.notes)


def open_text(path: Path | str):
    """Open a text file, gzip-compressed when its name ends in .gz."""
    path = Path(path)
    if not path.is_file():
        raise SiteWindError(f"{path}: no such file")
    if path.suffix == ".gz":
        return io.TextIOWrapper(gzip.open(path, "rb"), encoding="utf-8")
    return open(path, encoding="utf-8", newline="")


_UNIT = re.compile(r"^\s*([A-Za-z_ ]+?)\s*(?:\[(.*)\])?\s*$")


def _column(header: list[str], name: str, units: dict, path, required=True):
    """(index, factor) of the column ``name [unit]``; None when optional and absent."""
    for i, text in enumerate(header):
        m = _UNIT.match(text)
        if m and m.group(1).strip().lower() == name:
            unit = (m.group(2) or "").strip()
            if unit not in units:
                raise SiteWindError(f"{path}: line 1, field '{text}': unit '{unit}' not one of {sorted(units)} "
                                    f"(write the unit in brackets, e.g. '{name} [{next(iter(units))}]')")
            return i, units[unit]
    if required:
        raise SiteWindError(f"{path}: line 1: no column '{name} [...]' in the header {header}")
    return None


def parse_number(text: str, path, line: int, name: str) -> float:
    """The finite number in the text of field ``name`` on ``line`` of the file ``path``; SiteWindError naming the
    file, line, field and text otherwise."""
    try:
        v = float(text)
    except ValueError:
        raise SiteWindError(f"{path}: line {line}, field '{name}' = {text!r}: not a number") from None
    if not np.isfinite(v):
        raise SiteWindError(f"{path}: line {line}, field '{name}' = {text!r}: must be finite")
    return v


#: at most this many distinct heights are kept exactly; more are resampled every ``step`` metres
MAX_EXACT_HEIGHTS = 2000


def common_grid(profiles: list[tuple[np.ndarray, np.ndarray, np.ndarray | None]], step: float):
    """Put profiles (heights, speeds, directions) of differing heights on one grid: the union of their heights
    when it has at most ``MAX_EXACT_HEIGHTS`` (then ``SiteWind.at`` is exactly each profile's own linear
    interpolation), else every ``step`` metres from the lowest to the highest height (years of soundings: the
    resampling moves a value by at most the change of the profile's slope over one step); linear interpolation
    within each profile, NaN outside it. Returns (grid (m,), speed (n, m), direction (n, m) or None)."""
    union = np.unique(np.concatenate([p[0] for p in profiles]))
    if union.size <= MAX_EXACT_HEIGHTS:
        grid = union
    else:
        lo = min(p[0][0] for p in profiles)
        hi = max(p[0][-1] for p in profiles)
        grid = np.arange(lo, hi + step, step)
        grid = grid[grid <= hi + 1e-9]
    speed = np.full((len(profiles), grid.size), np.nan)
    has_dir = all(p[2] is not None for p in profiles)
    direction = np.full_like(speed, np.nan) if has_dir else None
    for k, (h, v, d) in enumerate(profiles):
        inside = (grid >= h[0]) & (grid <= h[-1])
        speed[k, inside] = np.interp(grid[inside], h, v)
        if has_dir:  # interpolate the direction through its unit vector (no jump at 360 -> 0 deg)
            rad = np.radians(d)
            s, c = np.interp(grid[inside], h, np.sin(rad)), np.interp(grid[inside], h, np.cos(rad))
            direction[k, inside] = np.degrees(np.arctan2(s, c)) % 360.0
    return grid, speed, direction


def read_profiles_csv(path: Path | str, grid_step: float = 5.0) -> SiteWind:
    """Read a CSV of wind profiles, one row per (time, height): columns ``time``, ``height [m|km|ft]``,
    ``speed [m/s|knot|km/h]`` and optionally ``direction [deg]``, comma- or semicolon-separated, '#' comment lines
    allowed. Every time stamp is a wind state of equal weight; heights ascending or not, no height twice."""
    path = Path(path)
    with open_text(path) as fh:
        lines = [(i + 1, ln) for i, ln in enumerate(fh) if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise SiteWindError(f"{path}: no header and no data")
    delim = ";" if lines[0][1].count(";") > lines[0][1].count(",") else ","
    rows = list(csv.reader([ln for _, ln in lines], delimiter=delim))
    header = [c.strip() for c in rows[0]]
    ti = _column(header, "time", {"": 1.0}, path)[0]
    hi, hf = _column(header, "height", HEIGHT_UNITS, path)
    vi, vf = _column(header, "speed", SPEED_UNITS, path)
    di = _column(header, "direction", DIRECTION_UNITS, path, required=False)
    data: dict[str, list] = {}
    for (line, _), row in zip(lines[1:], rows[1:], strict=True):
        if len(row) != len(header):
            raise SiteWindError(f"{path}: line {line}: {len(row)} fields, the header has {len(header)}")
        h = parse_number(row[hi], path, line, header[hi]) * hf
        v = parse_number(row[vi], path, line, header[vi]) * vf
        if h < 0:
            raise SiteWindError(f"{path}: line {line}, field '{header[hi]}' = {row[hi]!r}: must be >= 0")
        if v < 0:
            raise SiteWindError(f"{path}: line {line}, field '{header[vi]}' = {row[vi]!r}: must be >= 0")
        d = parse_number(row[di[0]], path, line, header[di[0]]) if di else np.nan
        entry = data.setdefault(row[ti].strip(), [])
        if any(h == e[0] for e in entry):
            raise SiteWindError(f"{path}: line {line}, field '{header[hi]}' = {row[hi]!r}: height given twice "
                                f"for time {row[ti].strip()!r}")
        entry.append((h, v, d))
    if not data:
        raise SiteWindError(f"{path}: a header but no data rows")
    profiles = []
    for t, entry in data.items():
        if len(entry) < 2:
            raise SiteWindError(f"{path}: time {t!r}: a profile needs at least two heights, got {len(entry)}")
        e = np.array(sorted(entry))
        profiles.append((e[:, 0], e[:, 1], e[:, 2] if di else None))
    grid, speed, direction = common_grid(profiles, grid_step)
    n = len(profiles)
    return SiteWind(grid, speed, np.full(n, 1.0 / n), tuple(data), direction,
                    source=f"{path.name} (profiles CSV)")


def daily(wind: SiteWind) -> SiteWind:
    """One state per calendar day (the first 10 characters of the label, YYYY-MM-DD): the mean profile of that
    day's states (NaN-aware), each day of equal weight. Lansdorp et al. (2008) use one profile a day."""
    days = [lab[:10] for lab in wind.labels]
    if not all(re.fullmatch(r"\d{4}-\d{2}-\d{2}", d) for d in days):
        raise ValueError(f"daily: labels must start with a date YYYY-MM-DD ({wind.source}), got {wind.labels[0]!r}")
    keys, inverse = np.unique(np.array(days), return_inverse=True)
    speed = np.full((keys.size, wind.heights.size), np.nan)
    for k in range(keys.size):
        rows = wind.speed[inverse == k]
        with np.errstate(invalid="ignore"):
            if np.all(np.isnan(rows), axis=0).any():
                cols = ~np.all(np.isnan(rows), axis=0)
                speed[k, cols] = np.nanmean(rows[:, cols], axis=0)
            else:
                speed[k] = np.nanmean(rows, axis=0)
    weight = np.full(keys.size, 1.0 / keys.size)
    return SiteWind(wind.heights, speed, weight, tuple(keys), None, wind.measured_top, wind.extrapolation,
                    wind.source + ", daily means", wind.notes + _cube_note(wind, speed, weight))


def _cube_note(wind: SiteWind, speed: np.ndarray, weight: np.ndarray) -> tuple[str, ...]:
    """What averaging a day's profiles does to the power's measure: the daily means' time mean of w^3 over the
    states' own, at the highest measured height where every state has data (() when there is none)."""
    full = np.all(np.isfinite(wind.speed), axis=0) & np.all(np.isfinite(speed), axis=0)
    full &= wind.heights <= wind.measured_top
    if not full.any():
        return ()
    j = int(np.flatnonzero(full)[-1])
    ratio = np.sum(weight * speed[:, j] ** 3) / np.sum(wind.weight * wind.speed[:, j] ** 3) * np.sum(wind.weight)
    return (f"daily means: the time mean of w^3 at {wind.heights[j]:g} m is {ratio:.3f} of the {wind.n} states' "
            "(a day's mean wind has less than its mean cube; one profile a day, as the paper's soundings, would not "
            "lower it)",)
