"""The reader of a wing's aerodynamic coefficient table (CSV: alpha_deg and the AERO_COLUMNS, '#' comments): strict,
errors naming the file, the line and the column."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.input_cache import note_read
from laddermill_gym.model.params import AERO_COLUMNS, AeroTable

__all__ = ["load_aero_table"]


def load_aero_table(path: Path) -> AeroTable:
    """Read a wing's coefficient table (CSV: alpha_deg and the AERO_COLUMNS, '#' comments); ConfigError naming the
    file, line and column of a bad entry."""
    note_read(path)  # in-process caches check these bytes on a hit (model/input_cache.py)
    try:
        with open(path, encoding="utf-8") as fh:
            lines = [(i + 1, ln) for i, ln in enumerate(fh) if ln.strip() and not ln.lstrip().startswith("#")]
    except OSError as err:
        raise ConfigError(f"{path}: cannot read aerodynamic table: {err}") from None
    want = ["alpha_deg", *AERO_COLUMNS]
    if not lines:
        raise ConfigError(f"{path}: no header and no rows (empty or only comments); the header must be {want}")
    header = [h.strip() for h in lines[0][1].split(",")]
    if header != want:
        raise ConfigError(f"{path}: line {lines[0][0]}: header {header} must be {want}")
    rows = []
    for lineno, ln in lines[1:]:
        cells = [c.strip() for c in ln.split(",")]
        if len(cells) != len(want):
            raise ConfigError(f"{path}: line {lineno}: {len(cells)} entries, the header has {len(want)}")
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            j = next(j for j, c in enumerate(cells) if not _is_float(c))
            raise ConfigError(f"{path}: line {lineno}, column '{want[j]}' = {cells[j]!r}: must be a number") from None
    data = np.array(rows).reshape(-1, len(want))
    if data.shape[0] < 8:
        raise ConfigError(f"{path}: table must have >= 8 rows of {len(want)} numbers, got {data.shape[0]}")
    if not np.all(np.isfinite(data)):
        r, c = np.argwhere(~np.isfinite(data))[0]
        raise ConfigError(f"{path}: line {lines[r + 1][0]}, column '{want[c]}' = {float(data[r, c])!r}: must be finite")
    step = np.diff(data[:, 0])
    bad = np.flatnonzero(np.abs(step - step[0]) > 1e-9)
    if step[0] <= 0 or bad.size:
        r = 1 if step[0] <= 0 else int(bad[0]) + 1
        raise ConfigError(f"{path}: line {lines[r + 1][0]}, column 'alpha_deg' = {float(data[r, 0])!r}: alpha must "
                          f"rise on a uniform grid (step {step[0]:g} deg from the first row) from -180 to 180 deg")
    a = data[:, 0]
    if abs(a[0] + 180) > 1e-9 or abs(a[-1] - 180) > 1e-9:
        raise ConfigError(f"{path}: column 'alpha_deg' runs from {a[0]:g} to {a[-1]:g} deg: it must run from -180 "
                          "to 180 deg")
    if not np.allclose(data[0, 1:], data[-1, 1:], rtol=0, atol=1e-12):
        raise ConfigError(f"{path}: rows at -180 and 180 deg must be equal (periodic table)")
    return AeroTable(alpha=np.radians(a), values=np.ascontiguousarray(data[:, 1:]), source=str(path))


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
