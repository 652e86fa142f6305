"""The site command end to end on a small profiles file, and the turbine comparison against windpowerlib's own
power-curve file read here with the csv module and interpolated with numpy."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

from laddermill_gym.atmosphere.site_wind import SiteWind
from laddermill_gym.quasisteady.cli import main


def test_turbine_yield_against_the_library_file():
    pytest.importorskip("windpowerlib")
    import windpowerlib

    from laddermill_gym.quasisteady import turbine as tb

    path = Path(windpowerlib.__file__).parent / "oedb" / "power_curves.csv"
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    row = next(r for r in rows if r[0] == "E-82/2350")
    pts = [(float(v), float(p)) for v, p in zip(rows[0][1:], row[1:], strict=True) if p != ""]
    v_tab, p_tab = np.array(pts).T
    speeds = np.array([3.3, 7.7, 11.2, 14.0])
    wind = SiteWind(np.array([10.0, 80.0, 150.0]), np.repeat(speeds[:, None], 3, axis=1), np.full(4, 0.2),
                    ("a", "b", "c", "d"), measured_top=80.0)
    y = tb.turbine_yield(wind, "E-82/2350", 80.0)
    want = 0.2 * np.sum(np.interp(speeds, v_tab, p_tab))
    assert y.rated_power == pytest.approx(2.35e6)
    assert y.mean_power == pytest.approx(want, rel=1e-12)   # 80 % of the time covered, the rest no power
    assert y.capacity_factor == pytest.approx(want / 2.35e6, rel=1e-12)
    assert "*" not in y.name and "*" in tb.turbine_yield(wind, "E-82/2350", 120.0).name
    lm = tb.laddermill_yield("lm", np.array([1e6, 3e6, 0.0, 2e6]), wind.weight, 2.35e6, 300.0, True)
    assert lm.mean_power == pytest.approx(0.2 * (1e6 + 2.35e6 + 2e6), rel=1e-12)


def test_site_command_writes_tables_and_figures(tmp_path):
    rng = np.random.default_rng(3)
    hs = np.array([10.0, 100.0, 300.0, 600.0])
    lines = ["time,height [m],speed [m/s]"]
    for day in range(1, 29):
        v = rng.uniform(5.0, 14.0)
        lines += [f"2021-02-{day:02d}T12:00,{h:g},{v * (h / 100) ** 0.2:.3f}" for h in hs]
    wfile = tmp_path / "wind.csv"
    wfile.write_text("\n".join(lines) + "\n")
    out = tmp_path / "site"
    assert main(["--wind", str(wfile), "--out", str(out), "--no-turbine", "--quiet"]) == 0
    text = (out / "tables.md").read_text()
    assert "| Kite altitude | m | 353.6 |" in text and "| Kite area | m^2 | 168.8 |" in text  # the paper's values
    rec = json.loads((out / "results.json").read_text())
    for case in ("table1", "table2"):
        r = rec[f"{case}/{wfile}"]
        assert r["feasible"] and r["mean_power_W"] >= 1e6 * (1 - 1e-6)
        assert r["design"]["h"] / np.cos(r["design"]["theta"]) >= 500.0 * (1 - 1e-6)      # eq. 18
        assert r["mean_tension_N"] <= r["F_max_N"] * (1 + 1e-9)                             # eq. 17 on average
    assert len(list(out.glob("*.png"))) >= 5
