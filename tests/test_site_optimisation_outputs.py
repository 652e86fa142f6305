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


def test_figs_19_20_mean_is_the_time_mean(tmp_path, capsys):
    """The Figs. 19-20 mean is sum_i p_i P_i, as eq. 16's P-bar: on Cabauw's clusters, whose bins cover 56.6 % of
    the time, the rest counts as no power (dividing by the weights' sum printed 1.78x the time mean). The oracle:
    the per-state powers of the printed design, averaged here with the time shares."""
    from laddermill_gym.quasisteady.site_data import load_wind
    from laddermill_gym.quasisteady.site_optimise import TABLE2, operate
    from laddermill_gym.quasisteady.site_problem import Design

    out = tmp_path / "site"
    assert main(["--wind", "cabauw", "--case", "table2", "--no-turbine", "--out", str(out)]) == 0
    line = next(s for s in capsys.readouterr().out.splitlines() if "figs. 19-20" in s)
    printed = [float(line.split(f"{lab} mean ")[1].split(" MW")[0]) for lab in ("1/3", "1/2")]
    design = Design(**json.loads((out / "results.json").read_text())["table2/cabauw"]["design"])
    ev = load_wind("cabauw")
    w = ev.at(design.h)
    ok = np.isfinite(w)
    for got, f in zip(printed, (1 / 3, 0.5), strict=True):
        P = operate(TABLE2, design, w[ok], f)[0]
        assert got == pytest.approx(np.sum(ev.weight[ok] * P) / 1e6, abs=6e-4)
        assert 0.5 < ev.weight.sum() < 0.6 and got < 0.7 * np.sum(ev.weight[ok] * P) / ev.weight[ok].sum() / 1e6


@pytest.mark.parametrize("args, needle", [
    (["--wind", "LOW", "--no-turbine"], "every state has data at 10-40 m only .* outside table1's altitude bounds "
                                        "50-1000 m"),
    (["--wind", "cabauw", "--case", "table2", "--hub-height", "1000"], "--hub-height = 1000 m: outside the heights"),
    (["--out", "FILE"], "--out '.*afile': cannot make the folder"),
])
def test_inputs_the_site_cannot_use_are_named_before_any_run(tmp_path, capsys, args, needle):
    low = tmp_path / "low.csv"
    low.write_text("time,height [m],speed [m/s]\nA,10,5\nA,40,7\n")
    (tmp_path / "afile").write_text("")
    args = [str(low) if a == "LOW" else str(tmp_path / "afile") if a == "FILE" else a for a in args]
    if "--out" not in args:
        args += ["--out", str(tmp_path / "out")]
    with pytest.raises(SystemExit) as exc:
        main(args)
    assert exc.value.code == 2
    import re

    assert re.search(needle, capsys.readouterr().err)


def test_models_line_names_the_ratios_and_the_first_flown_wind():
    """``laddermill site``'s models line on hand-made curves: Schmehl half of Lansdorp where its loop flies (from
    5.5 m/s), none below; a Lansdorp power of 0 gives n/a, not a division by zero."""
    from laddermill_gym.quasisteady.site_outputs import model_ratio_text

    speeds = np.linspace(3.0, 25.0, 45)
    lans = np.where(speeds < 3.2, 0.0, 2.0 * speeds)
    curves = {"Lansdorp et al. 2008": lans, "Schmehl / van der Vlugt": np.where(speeds >= 5.5, speeds, 0.0)}
    text = model_ratio_text(curves, speeds, at=(3.0, 4.0, 6.0, 25.0))
    assert text == ("Schmehl's best power / Lansdorp's at 3, 4, 6, 25 m/s: n/a 0.00 0.50 0.50; Schmehl's loop flown "
                    "from 5.5 m/s (3-25 m/s)")


def _profiles(tmp_path, days=28, speeds=(5.0, 14.0)) -> Path:
    rng = np.random.default_rng(3)
    lines = ["time,height [m],speed [m/s]"]
    for day in range(1, days + 1):
        v = rng.uniform(*speeds)
        lines += [f"2021-02-{day:02d}T12:00,{h:g},{v * (h / 100) ** 0.2:.3f}" for h in (10.0, 100.0, 300.0, 600.0)]
    wfile = tmp_path / "wind.csv"
    wfile.write_text("\n".join(lines) + "\n")
    return wfile


def test_a_power_target_no_design_meets_is_marked_and_exits_1(tmp_path, capsys):
    """100 MW from a few days of 5-14 m/s wind: the optimisation ends on its bounds. The table says the target is
    missed (it showed the last design tried as a design), stderr says so and the exit status is 1 (it was 0)."""
    out = tmp_path / "site"
    code = main(["--wind", str(_profiles(tmp_path)), "--out", str(out), "--no-turbine", "--quiet", "--case", "table2",
                 "--power-mw", "100"])
    assert code == 1
    assert "| Power target met (eq. 19) | - | | **NO** (infeasible) |" in (out / "tables.md").read_text()
    assert "no design within the bounds delivers the 100 MW mean power for table2" in capsys.readouterr().err
    assert not json.loads((out / "results.json").read_text())[f"table2/{tmp_path / 'wind.csv'}"]["feasible"]


def test_the_evaluation_data_are_read_in_the_format_given(tmp_path, monkeypatch):
    """--format reached the first read only: the design's evaluation (Figs. 19-20) and the hub-height check read the
    file again with format detection, which failed on a Wyoming file whose title comes late."""
    import laddermill_gym.quasisteady.cli as cli

    formats = []
    real = cli.load_wind

    def spy(spec, fmt="auto"):
        formats.append(fmt)
        return real(spec, "auto")

    monkeypatch.setattr(cli, "load_wind", spy)
    assert main(["--wind", str(_profiles(tmp_path)), "--out", str(tmp_path / "o"), "--quiet", "--case", "table2",
                 "--format", "csv", "--no-turbine"]) == 0
    assert formats and set(formats) == {"csv"}


def test_histograms_show_each_state_at_its_share_of_the_whole_time(tmp_path):
    """Bins that cover 56.6 % of the time (the Cabauw frequency table's sum, read here with the csv module) draw
    bars that add up to 56.6 %, each state at its own time share, and the axis says what the bars cover (they were
    scaled to 100 % under the label 'share of time'); states that cover the whole time add up to 100 %."""
    from laddermill_gym.figure_files import subplots
    from laddermill_gym.quasisteady.site_data import shipped_wind
    from laddermill_gym.quasisteady.site_outputs import time_histogram

    freq = next(Path(__file__).resolve().parents[1].glob("configs/wind/**/*freq*.csv"))
    with open(freq, newline="") as fh:
        rows = [r for r in csv.reader(fh, delimiter=";") if r][1:]
    share = sum(float(r[4]) for r in rows)  # [%]
    wind = shipped_wind("cabauw")
    _, ax = subplots(1, 2)
    x = np.arange(wind.n) % 7
    heights = time_histogram(ax[0], x, wind.weight, np.arange(8) - 0.5, "x")
    assert heights.sum() == pytest.approx(share, rel=1e-12)
    np.testing.assert_allclose(heights, [100 * wind.weight[x == k].sum() for k in range(7)], rtol=1e-12)
    assert ax[0].get_ylabel() == f"share of time [%] (bars: {share:.1f} %, the data)"
    whole = time_histogram(ax[1], np.zeros(4), np.full(4, 0.25), 3, "x")
    assert whole.sum() == pytest.approx(100.0) and ax[1].get_ylabel() == "share of time [%]"
