"""Readers of three site-wind formats into ``site_wind.SiteWind``: the University of Wyoming upper-air text list
(the soundings Lansdorp et al. 2008 used), the clustered wind-profile shapes with their frequency per cluster and
wind-speed bin (Schelbergen et al. 2020), and hourly series at two heights (the windpowerlib example weather
file). Written here because no maintained reader of these layouts exists as a light dependency (siphon reads the
Wyoming archive over the network only; pandas would read the CSVs but not name file, line and field in errors)."""

from __future__ import annotations

import csv
import math
import re
from datetime import datetime
from pathlib import Path

import numpy as np

from laddermill_gym.atmosphere.site_wind import SiteWind, SiteWindError, common_grid, open_text, parse_number

KNOT = 1852.0 / 3600.0  # [m/s] one international knot (1852 m per hour)

# ------------------------------------------------------------------------------------------- Wyoming soundings
_TITLE = re.compile(r"(\d+)\s+(.*?)\s*Observations at (\d{2})Z (\d{1,2}) (\w{3}) (\d{4})")
_ELEV = re.compile(r"Station elevation:\s*(-?[\d.]+)")
_TAG = re.compile(r"<[^>]*>")
WIDTH = 7  # characters per column of the archive's TEXT:LIST table


def _wyoming_rows(lines, start, path):
    """Column names and the data rows (line number, text) of the table that follows a title line."""
    i = start + 1
    while i < len(lines) and "PRES" not in lines[i][1]:
        i += 1
    if i >= len(lines):
        raise SiteWindError(f"{path}: line {lines[start][0]}: a sounding title with no table header (PRES HGHT ...)")
    names = lines[i][1].split()
    for need in ("HGHT", "DRCT", "SKNT"):
        if need not in names:
            raise SiteWindError(f"{path}: line {lines[i][0]}: no column {need} in the table header {names}")
    units = lines[i + 1][1].split() if i + 1 < len(lines) else []
    if len(units) >= 2 and units[names.index("HGHT")] != "m":
        raise SiteWindError(f"{path}: line {lines[i + 1][0]}, field 'HGHT': unit {units[1]!r}, expected m")
    if len(units) == len(names) and units[names.index("SKNT")] != "knot":
        raise SiteWindError(f"{path}: line {lines[i + 1][0]}, field 'SKNT': unit {units[names.index('SKNT')]!r}, "
                            "expected knot")
    j = i + 2
    while j < len(lines) and set(lines[j][1].strip()) == {"-"}:
        j += 1
    rows = []
    while j < len(lines) and lines[j][1].strip() and not _TITLE.search(lines[j][1]) \
            and not lines[j][1].lstrip().startswith(("Station", "-")):
        rows.append(lines[j])
        j += 1
    return names, rows, j


def _wyoming_one(lines, start, path, end):
    """One sounding: (label, heights above ground [m], speed [m/s], direction [deg])."""
    m = _TITLE.search(lines[start][1])
    hour, day, mon, year = m.group(3), int(m.group(4)), m.group(5), m.group(6)
    try:
        when = datetime.strptime(f"{year} {mon} {day} {hour}", "%Y %b %d %H")
    except ValueError:
        raise SiteWindError(f"{path}: line {lines[start][0]}: date '{day} {mon} {year}' not understood") from None
    names, rows, after = _wyoming_rows(lines, start, path)
    elevation = None
    for _, text in lines[after:end]:
        e = _ELEV.search(text)
        if e:
            elevation = float(e.group(1))
            break
    table = []
    for ln, text in rows:
        fields = [text[k * WIDTH:(k + 1) * WIDTH].strip() for k in range(len(names))]
        rec = {}
        for name in ("PRES", "HGHT", "DRCT", "SKNT"):
            if name not in names:
                continue
            f = fields[names.index(name)]
            if f == "":
                rec[name] = np.nan
                continue
            try:
                rec[name] = float(f)
            except ValueError:
                raise SiteWindError(f"{path}: line {ln}, field '{name}' = {f!r}: not a number") from None
        table.append(rec)
    # a level with a speed but no direction keeps its speed (the power needs only the speed; its direction is NaN)
    good = [r for r in table if np.isfinite(r["HGHT"]) and np.isfinite(r["SKNT"])]
    if len(good) < 2:
        raise SiteWindError(f"{path}: line {lines[start][0]}: sounding {when:%Y-%m-%d %HZ} has fewer than two "
                            f"levels with height and speed")
    if elevation is None:  # no station block: the surface is the level with the highest pressure
        elevation = max(good, key=lambda r: r.get("PRES", -np.inf))["HGHT"]
    good = sorted((r for r in good if r["HGHT"] >= elevation), key=lambda r: r["HGHT"])
    h = np.array([r["HGHT"] - elevation for r in good])
    keep = np.concatenate(([True], np.diff(h) > 0))  # the archive sometimes repeats a level
    return (when.strftime("%Y-%m-%dT%H:00Z"), h[keep], np.array([r["SKNT"] for r in good])[keep] * KNOT,
            np.array([r.get("DRCT", np.nan) for r in good])[keep])


def read_wyoming(path: Path | str, grid_step: float = 5.0) -> SiteWind:
    """Read soundings in the University of Wyoming upper-air text format (the TEXT:LIST page, saved as text or
    HTML; several soundings in one file). Height above ground = HGHT - station elevation [m]; speed SKNT [knot]
    -> m/s; direction DRCT [deg]. Levels without wind are skipped. Each sounding is a state of equal weight."""
    path = Path(path)
    with open_text(path) as fh:
        lines = [(i + 1, _TAG.sub("", ln.rstrip("\r\n"))) for i, ln in enumerate(fh)]
    starts = [k for k, (_, t) in enumerate(lines) if _TITLE.search(t)]
    if not starts:
        raise SiteWindError(f"{path}: line 1: no sounding title ('NNNNN NAME Observations at HHZ DD Mon YYYY'); "
                            f"not a University of Wyoming upper-air text file")
    soundings = [_wyoming_one(lines, s, path, e) for s, e in zip(starts, starts[1:] + [len(lines)], strict=True)]
    grid, speed, direction = common_grid([(h, v, d) for _, h, v, d in soundings], grid_step)
    n = len(soundings)
    return SiteWind(grid, speed, np.full(n, 1.0 / n), tuple(s[0] for s in soundings), direction,
                    source=f"{path.name} (University of Wyoming soundings)")


# ------------------------------------------------------------------------------------------- clustered profiles
def _read_semicolon(path: Path, need: int):
    """(header, (n, columns) values, (n,) the file's line number of each row) of a ';' table; blank lines skipped."""
    with open_text(path) as fh:
        reader = csv.reader(fh, delimiter=";")
        rows = [(reader.line_num, r) for r in reader if r]
    if len(rows) < 2:
        raise SiteWindError(f"{path}: no data rows")
    header = [c.strip() for c in rows[0][1]]
    out = []
    for k, row in rows[1:]:
        if len(row) != len(header) or len(row) < need:
            raise SiteWindError(f"{path}: line {k}: {len(row)} fields, expected {len(header)}")
        out.append([parse_number(text, path, k, name) for name, text in zip(header, row, strict=True)])
    return header, np.array(out), np.array([k for k, _ in rows[1:]])


def read_clusters(profile_paths: list[Path | str], frequency_path: Path | str) -> SiteWind:
    """Clustered wind resource: one file per cluster with columns ``h [m]; u [-]; v [-]; scale factor [-]`` (the
    shape, 1 at 100 m) and a frequency file ``cluster; bin; v100_low [m/s]; v100_high [m/s]; frequency [%]``.
    Each (cluster, bin) is a state: speed(h) = v100 |(u, v)(h)| with v100 the bin's centre; weight = frequency."""
    shapes, heights = [], None
    for p in map(Path, profile_paths):
        header, a, line = _read_semicolon(p, 3)
        if not header[0].startswith("h"):
            raise SiteWindError(f"{p}: line 1, field '{header[0]}': expected the height column 'h [m]'")
        if np.any(np.diff(a[:, 0]) <= 0):
            bad = int(np.flatnonzero(np.diff(a[:, 0]) <= 0)[0]) + 1
            raise SiteWindError(f"{p}: line {line[bad]}, field '{header[0]}' = {a[bad, 0]:g}: heights must rise "
                                f"line by line (the line before has {a[bad - 1, 0]:g})")
        if heights is None:
            heights = a[:, 0]
        elif not np.array_equal(heights, a[:, 0]):
            raise SiteWindError(f"{p}: column '{header[0]}': heights differ from {profile_paths[0]}")
        mag = np.hypot(a[:, 1], a[:, 2])
        j = np.flatnonzero(heights == 100.0)
        if j.size != 1 or abs(mag[j[0]] - 1.0) > 1e-6:
            raise SiteWindError(f"{p}: the shape must be 1 at h = 100 m (a row 'h [m]' = 100 with |(u, v)| = 1)")
        shapes.append(mag)
    fpath = Path(frequency_path)
    header, f, line = _read_semicolon(fpath, 5)
    _check_frequencies(fpath, header, f, line)
    cl = f[:, 0].astype(int)
    if cl.min() < 1 or cl.max() > len(shapes):
        raise SiteWindError(f"{fpath}: field '{header[0]}': clusters {cl.min()}..{cl.max()}, "
                            f"but {len(shapes)} profile files")
    v100 = 0.5 * (f[:, 2] + f[:, 3])
    speed = v100[:, None] * np.array(shapes)[cl - 1]
    labels = tuple(f"cluster {c} bin {int(b)}" for c, b in zip(cl, f[:, 1], strict=True))
    return SiteWind(heights, speed, f[:, 4] / 100.0, labels, None,
                    source=f"{fpath.name} and {len(shapes)} cluster shapes (Schelbergen et al. 2020)",
                    notes=(f"wind-speed bins cover {f[:, 4].sum():.1f} % of the time; the rest (below cut-in or "
                           f"above cut-out) is outside the data",))


def _check_frequencies(path: Path, header: list[str], f: np.ndarray, line: np.ndarray) -> None:
    """SiteWindError naming the file, line, field and value of the first bad entry of a cluster frequency table
    ``f`` (rows: cluster, bin, v100_low, v100_high, frequency [%]; every entry finite, ``parse_number``; ``line``
    each row's line in the file): a cluster
    number that is not a whole number, a negative frequency, a bin whose upper speed is not above its lower one, or
    frequencies that add up to more than 100 %."""
    checks = ((0, f[:, 0] == np.round(f[:, 0]), "a cluster number must be a whole number"),
              (4, f[:, 4] >= 0, "a frequency must be >= 0"),
              (3, f[:, 3] > f[:, 2], "the bin's upper wind speed must be above its lower one"))
    for col, ok, why in checks:
        bad = np.flatnonzero(~ok)
        if bad.size:
            k = int(bad[0])
            raise SiteWindError(f"{path}: line {line[k]}, field '{header[col]}' = {f[k, col]:g}: {why}")
    total = float(f[:, 4].sum())
    if total > 100.0 + 1e-6:
        raise SiteWindError(f"{path}: field '{header[4]}': the frequencies add up to {total:g} %, more than 100 %")


# ------------------------------------------------------------------------------------------- two-height series
def read_two_heights(path: Path | str, top: float = 1000.0, step: float = 10.0,
                     alpha_range: tuple[float, float] = (0.0, 0.6)) -> SiteWind:
    """Hourly wind at two heights in the windpowerlib weather layout (two header rows: variable name, height [m];
    a time column first; columns ``wind_speed`` at two heights; .gz allowed). Between the two heights the speed
    is linear in height (as the paper interpolates); above the upper one it is extrapolated with the power law
    whose exponent each hour's two speeds give, alpha = ln(v2/v1) / ln(h2/h1), limited to ``alpha_range``; the
    result says so (``measured_top``, ``extrapolation``, ``notes``)."""
    path = Path(path)
    with open_text(path) as fh:
        rows = list(csv.reader(fh))
    # blank lines (a trailing newline left by an editor) carry no data: dropped, as the profiles CSV reader does;
    # ``line`` keeps each remaining row's line number in the file for the messages
    line = [i + 1 for i, row in enumerate(rows) if any(cell.strip() for cell in row)]
    rows = [rows[i - 1] for i in line]
    if len(rows) < 3 or rows[0][0] != "variable_name" or rows[1][0] != "height":
        raise SiteWindError(f"{path}: line 1: expected the header rows 'variable_name,...' and 'height,...'")
    cols = [k for k, name in enumerate(rows[0]) if name == "wind_speed"]
    if len(cols) != 2:
        raise SiteWindError(f"{path}: line 1: expected two 'wind_speed' columns, found {len(cols)}")
    try:
        h1, h2 = sorted(float(rows[1][k]) for k in cols)
    except ValueError:
        raise SiteWindError(f"{path}: line 2, field 'height': not numbers {[rows[1][k] for k in cols]}") from None
    if not 0.0 < h1 < h2 < math.inf:
        raise SiteWindError(f"{path}: line 2, field 'height' = {[rows[1][k] for k in cols]}: the two wind_speed "
                            "heights must be finite, > 0 and differ (the power law above takes ln(h2 / h1))")
    c1, c2 = (cols if float(rows[1][cols[0]]) == h1 else cols[::-1])
    v = np.empty((len(rows) - 2, 2))
    for k, row in enumerate(rows[2:]):
        for j, c in enumerate((c1, c2)):
            try:
                v[k, j] = float(row[c])
            except (ValueError, IndexError):
                text = row[c] if c < len(row) else "(missing)"
                raise SiteWindError(f"{path}: line {line[k + 2]}, field 'wind_speed' at {(h1, h2)[j]:g} m = {text!r}: "
                                    f"not a number") from None
            if not (np.isfinite(v[k, j]) and v[k, j] >= 0):
                raise SiteWindError(f"{path}: line {line[k + 2]}, field 'wind_speed' at {(h1, h2)[j]:g} m = "
                                    f"{row[c]!r}: must be finite and >= 0")
    with np.errstate(divide="ignore", invalid="ignore"):
        raw = np.log(v[:, 1] / v[:, 0]) / np.log(h2 / h1)
    # a calm hour at both heights (nan) takes the lower limit (its speeds are 0 anyway); a calm lower height under
    # wind (+inf) or a calm upper one (-inf) is limited as any other exponent
    alpha = np.clip(np.where(np.isnan(raw), alpha_range[0], raw), *alpha_range)
    n_clip = int(np.sum(~(raw == alpha)))  # limited, or undefined (a calm hour)
    grid = np.concatenate((np.arange(h1, h2, step), np.arange(h2, top + 0.5 * step, step)))
    t = np.clip((grid - h1) / (h2 - h1), 0.0, 1.0)
    speed = np.where(grid <= h2, (1 - t) * v[:, :1] + t * v[:, 1:], v[:, 1:] * (grid / h2) ** alpha[:, None])
    n = v.shape[0]
    labels = tuple(row[0][:19] for row in rows[2:])
    return SiteWind(grid, speed, np.full(n, 1.0 / n), labels, None, measured_top=h2,
                    extrapolation=f"power law above {h2:g} m, exponent from each hour's {h1:g} m and {h2:g} m speeds",
                    source=f"{path.name} (hourly wind at {h1:g} and {h2:g} m)",
                    notes=(f"exponent limited to {alpha_range} in {n_clip} of {n} hours",))
