"""Site wind readers: unit conversions and interpolation checked by hand, the shipped files' own published
numbers (read here with the csv module), and bad files rejected naming the file, line and field."""

from __future__ import annotations

import csv
import gzip
import math

import numpy as np
import pytest

from laddermill_gym.atmosphere.site_wind import SiteWindError, daily, read_profiles_csv
from laddermill_gym.atmosphere.site_wind_formats import read_two_heights, read_wyoming
from laddermill_gym.quasisteady.site_data import WIND_DIR, load_wind, shipped_wind

CSV_TEXT = """# two profiles; the second in other heights
time,height [km],speed [knot],direction [deg]
2020-01-01T00:00,0.01,10,350
2020-01-01T00:00,0.1,20,10
2020-01-01T00:00,0.3,30,20
2020-01-02T00:00,0.1,40,180
2020-01-02T00:00,0.02,20,180
"""


def test_profiles_csv_units_grid_and_interpolation(tmp_path):
    p = tmp_path / "profiles.csv"
    p.write_text(CSV_TEXT)
    w = read_profiles_csv(p, grid_step=5.0)
    assert w.n == 2 and w.labels == ("2020-01-01T00:00", "2020-01-02T00:00")
    assert w.weight == pytest.approx([0.5, 0.5])
    kn = 1852.0 / 3600.0
    assert w.at(10.0)[0] == pytest.approx(10 * kn, rel=1e-12) and w.at(100.0)[1] == pytest.approx(40 * kn)
    # 55 m: halfway between 10 m (10 kn) and 100 m (20 kn) for the first profile; 20..100 m for the second
    assert w.at(55.0)[0] == pytest.approx(15.0 * kn, rel=1e-5)
    assert w.at(55.0)[1] == pytest.approx((20 + 35.0 / 80.0 * 20) * kn, rel=1e-5)
    assert np.isnan(w.at(200.0)[1])  # above the second profile's top
    assert w.at(300.0)[0] == pytest.approx(30.0 * kn, rel=1e-5)
    # the direction turns through north, not through south: at 20 m (a height of the second profile) the first
    # profile's direction is 1/9 of the way from 350 to 10 deg, through the unit vectors
    j = int(np.flatnonzero(w.heights == 20.0)[0])
    t = 10.0 / 90.0
    a, b = math.radians(350.0), math.radians(10.0)
    want = math.degrees(math.atan2((1 - t) * math.sin(a) + t * math.sin(b), (1 - t) * math.cos(a) + t * math.cos(b)))
    assert w.direction[0, j] == pytest.approx(want % 360.0, rel=1e-12)
    assert 350.0 < w.direction[0, j] < 360.0
    with pytest.raises(ValueError, match="outside"):
        w.at(400.0)


def test_a_profiles_own_lowest_height_reads_its_value(tmp_path):
    """On a grid height a state reads its own value, even where the height is its profile's lowest (linear
    interpolation from the cell below gave 0 x NaN = NaN there)."""
    p = tmp_path / "profiles.csv"
    p.write_text("time,height [m],speed [m/s]\nA,0,5\nA,50,7.5\nA,100,10\nB,50,7\nB,100,9.5\nB,150,12\n")
    w = read_profiles_csv(p, grid_step=50.0)
    np.testing.assert_array_equal(w.heights, [0.0, 50.0, 100.0, 150.0])
    np.testing.assert_array_equal(w.at(50.0), [7.5, 7.0])
    np.testing.assert_array_equal(w.at(150.0)[1], 12.0)
    assert np.isnan(w.at(150.0)[0]) and np.isnan(w.at(25.0)[1])  # outside a profile: no data
    assert w.at(75.0) == pytest.approx([8.75, 8.25], rel=1e-12)


def test_profiles_csv_gzip_and_semicolons(tmp_path):
    p = tmp_path / "p.csv.gz"
    with gzip.open(p, "wt") as fh:
        fh.write("time;height [m];speed [m/s]\nA;10;3\nA;50;7\n")
    w = read_profiles_csv(p)
    assert w.at(20.0) == pytest.approx([4.0], rel=1e-12)


@pytest.mark.parametrize("text, where", [
    ("time,height [yd],speed [m/s]\nA,10,3\nA,20,4\n", ["line 1", "height [yd]", "unit 'yd'"]),
    ("time,height [m],speed [m/s]\nA,10,3\nA,20,fast\n", ["line 3", "'speed [m/s]'", "'fast'"]),
    ("time,height [m],speed [m/s]\nA,10,3\nA,20,-4\n", ["line 3", "'speed [m/s]'", "'-4'"]),
    ("time,height [m],speed [m/s]\nA,10,3\nA,10,4\n", ["line 3", "'height [m]'", "twice"]),
    ("time,height [m]\nA,10\n", ["line 1", "speed"]),
    ("time,height [m],speed [m/s]\nA,10,3,9\n", ["line 2", "4 fields"]),
])
def test_bad_profiles_csv_named(tmp_path, text, where):
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(SiteWindError) as err:
        read_profiles_csv(p)
    msg = str(err.value)
    assert str(p) in msg
    for part in where:
        assert part in msg


# Two soundings typed by hand in the archive's TEXT:LIST layout (7-character columns), one with HTML tags
WYOMING = """<HTML><TITLE>University of Wyoming - Radiosonde Data</TITLE>
<H2>06260 EHDB De Bilt Observations at 00Z 01 Jan 2007</H2>
<PRE>
-----------------------------------------------------------------------------
   PRES   HGHT   TEMP   DWPT   RELH   MIXR   DRCT   SKNT   THTA   THTE   THTV
    hPa     m      C      C      %    g/kg    deg   knot     K      K      K
-----------------------------------------------------------------------------
 1000.0     94
 1011.0      4    9.8    8.3     90   6.72    220     10  281.5  299.9  282.6
  997.0    120    8.6    7.0     90   6.20    230     20  281.4  298.3  282.5
  950.0    520    6.0    4.1     88   5.40    250     40  282.7  297.8  283.7
</PRE><H3>Station information and sounding indices</H3><PRE>
                         Station identifier: EHDB
                          Station elevation: 4.0
</PRE>
<H2>06260 EHDB De Bilt Observations at 12Z 01 Jan 2007</H2>
<PRE>
-----------------------------------------------------------------------------
   PRES   HGHT   TEMP   DWPT   RELH   MIXR   DRCT   SKNT   THTA   THTE   THTV
    hPa     m      C      C      %    g/kg    deg   knot     K      K      K
-----------------------------------------------------------------------------
 1012.0      4   10.0    8.0     87   6.67    200      6  281.6  299.8  282.7
  990.0    200    8.4    6.6     88   6.00    210     16  281.9  298.6  283.0
</PRE><H3>Station information and sounding indices</H3><PRE>
                          Station elevation: 4.0
</PRE>
"""


def test_wyoming_soundings(tmp_path):
    p = tmp_path / "debilt.html"
    p.write_text(WYOMING)
    w = read_wyoming(p)
    kn = 1852.0 / 3600.0
    assert w.labels == ("2007-01-01T00:00Z", "2007-01-01T12:00Z")
    assert w.heights[0] == 0.0  # the surface level, 4 m above sea level
    assert w.at(0.0) == pytest.approx([10 * kn, 6 * kn], rel=1e-9)
    # 116 m above ground is the 997 hPa level of the first sounding; the second: 6 kn at 0 m, 16 kn at 196 m
    assert w.at(116.0)[0] == pytest.approx(20 * kn, rel=1e-9)
    assert w.at(116.0)[1] == pytest.approx((6 + 10 * 116 / 196) * kn, rel=1e-9)
    assert w.at(316.0)[0] == pytest.approx((20 + 20 * 200 / 400) * kn, rel=1e-9)
    assert np.isnan(w.at(316.0)[1])
    # one sounding a day: daily() averages the two
    d = daily(w)
    assert d.n == 1 and d.at(0.0)[0] == pytest.approx(8 * kn, rel=1e-9)


def test_wyoming_bad_files_named(tmp_path):
    p = tmp_path / "bad.txt"
    p.write_text(WYOMING.replace("    230     20", "    230     2x"))
    with pytest.raises(SiteWindError, match=r"line 10, field 'SKNT' = '2x'"):
        read_wyoming(p)
    q = tmp_path / "none.txt"
    q.write_text("PRES HGHT\n1000 100\n")
    with pytest.raises(SiteWindError, match="line 1: no sounding title"):
        read_wyoming(q)


def _rows(name, delimiter):
    path = WIND_DIR / name
    opener = gzip.open(path, "rt") if name.endswith(".gz") else open(path, newline="")
    with opener as fh:
        return list(csv.reader(fh, delimiter=delimiter))


def test_shipped_cabauw_clusters():
    w = shipped_wind("cabauw")
    freq = _rows("cabauw_8clusters_frequency.csv", ";")[1:]
    assert w.n == len(freq) == 800
    assert w.weight.sum() == pytest.approx(sum(float(r[4]) for r in freq) / 100, rel=1e-12)
    assert w.weight.sum() == pytest.approx(0.566, abs=5e-4)  # the README's 56.6 %
    # cluster 3, bin 40: speed at 10 m = bin centre x |(u, v)| at 10 m of cluster 3's shape
    row = next(r for r in freq if r[0] == "3" and r[1] == "40")
    shape = _rows("cabauw_8clusters_profile3.csv", ";")[1]
    v100 = 0.5 * (float(row[2]) + float(row[3]))
    k = w.labels.index("cluster 3 bin 40")
    assert w.at(10.0)[k] == pytest.approx(v100 * math.hypot(float(shape[1]), float(shape[2])), rel=1e-12)
    assert w.at(100.0)[k] == pytest.approx(v100, rel=1e-12)


def test_shipped_two_heights_extrapolation_labelled():
    w = shipped_wind("weather2010")
    rows = _rows("windpowerlib_weather_2010.csv.gz", ",")
    v10, v80 = float(rows[2][3]), float(rows[2][6])
    assert rows[1][3] == "10" and rows[1][6] == "80"
    alpha = math.log(v80 / v10) / math.log(8.0)
    assert w.n == 8760
    assert w.at(80.0)[0] == pytest.approx(v80, rel=1e-12)
    assert w.at(45.0)[0] == pytest.approx(v10 + (v80 - v10) * 35 / 70, rel=1e-12)
    assert w.at(200.0)[0] == pytest.approx(v80 * (200 / 80) ** alpha, rel=1e-12)
    assert w.measured_top == 80.0 and w.is_extrapolated(200.0) and not w.is_extrapolated(80.0)
    assert "power law above 80 m" in w.extrapolation
    d = shipped_wind("weather2010-daily")
    assert d.n == 365
    day1 = [float(r[6]) for r in rows[2:] if r[0].startswith("2010-01-01")]
    assert len(day1) == 24 and d.at(80.0)[0] == pytest.approx(np.mean(day1), rel=1e-12)


def test_two_heights_bad_value_named(tmp_path):
    p = tmp_path / "weather.csv"
    p.write_text("variable_name,wind_speed,wind_speed\nheight,10,80\n2010-01-01 00:00:00,3,5\n2010-01-01 01:00:00,"
                 "x,5\n")
    with pytest.raises(SiteWindError, match=r"line 4, field 'wind_speed' at 10 m = 'x'"):
        read_two_heights(p)


def test_two_heights_blank_lines_are_skipped_and_lines_keep_their_numbers(tmp_path):
    """A trailing blank line stopped the reader ("line 7, field 'wind_speed' at 10 m = '(missing)'"); a blank line
    inside is skipped too, and a bad value after it is named by its line in the file."""
    p = tmp_path / "weather.csv"
    p.write_text("variable_name,wind_speed,wind_speed\nheight,10,80\n2010-01-01 00:00:00,3,5\n\n"
                 "2010-01-01 01:00:00,4,6\n\n")
    w = read_two_heights(p, top=100.0)
    assert w.n == 2 and w.at(80.0).tolist() == [5.0, 6.0]
    p.write_text("variable_name,wind_speed,wind_speed\nheight,10,80\n\n2010-01-01 00:00:00,3,5\n"
                 "2010-01-01 01:00:00,x,5\n")
    with pytest.raises(SiteWindError, match=r"line 5, field 'wind_speed' at 10 m = 'x'"):
        read_two_heights(p)


@pytest.mark.parametrize("heights", ["10,10", "0,80", "-10,80"])
def test_two_heights_that_cannot_give_a_power_law_named(tmp_path, heights):
    p = tmp_path / "weather.csv"
    p.write_text(f"variable_name,wind_speed,wind_speed\nheight,{heights}\n2010-01-01 00:00:00,3,5\n")
    with pytest.raises(SiteWindError, match=r"weather.csv: line 2, field 'height' = .*must be finite, > 0 and differ"):
        read_two_heights(p)


def test_load_wind_detects_formats(tmp_path):
    p = tmp_path / "debilt.txt"
    p.write_text(WYOMING)
    assert load_wind(str(p)).labels[0] == "2007-01-01T00:00Z"
    assert load_wind("daily:" + str(p)).n == 1
    with pytest.raises(ValueError, match="unknown shipped"):
        shipped_wind("nowhere")


def test_bad_cluster_files_named(tmp_path):
    from laddermill_gym.atmosphere.site_wind_formats import read_clusters

    shape = tmp_path / "shape.csv"
    shape.write_text("h [m];u1 [-];v1 [-];scale factor1 [-]\n10.0;0.7;0.0;1.1\n100.0;1.0;0.0;1.1\n")
    freq = tmp_path / "freq.csv"
    freq.write_text("cluster;bin;v100_low [m/s];v100_high [m/s];frequency [%]\n1;0;5.0;6.0;2.5\n1;1;6.0;7.0;n/a\n")
    with pytest.raises(SiteWindError, match=r"freq.csv: line 3, field 'frequency \[%\]' = 'n/a'"):
        read_clusters([shape], freq)
    freq.write_text("cluster;bin;v100_low [m/s];v100_high [m/s];frequency [%]\n2;0;5.0;6.0;2.5\n")
    with pytest.raises(SiteWindError, match="field 'cluster': clusters 2..2, but 1 profile files"):
        read_clusters([shape], freq)
    shape.write_text("h [m];u1 [-];v1 [-];scale factor1 [-]\n10.0;0.7;0.0;1.1\n100.0;0.9;0.0;1.1\n")
    with pytest.raises(SiteWindError, match="shape.csv: the shape must be 1 at h = 100 m"):
        read_clusters([shape], freq)


def test_cluster_tables_refuse_what_would_change_the_data(tmp_path):
    """Each bad entry of a cluster frequency table or shape file is named by file, line, field and value, where the
    reader used to truncate a cluster number 1.7 to cluster 1, or leave a sum of 150 % to a message without the
    file."""
    from laddermill_gym.atmosphere.site_wind_formats import read_clusters

    shape = tmp_path / "shape.csv"
    shape.write_text("h [m];u1 [-];v1 [-];sf [-]\n10.0;0.7;0.0;1\n100.0;1.0;0.0;1\n")
    freq = tmp_path / "freq.csv"
    head = "cluster;bin;v100_low [m/s];v100_high [m/s];frequency [%]\n"
    cases = {"1;0;5;6;10\n1.7;1;6;7;10\n": r"freq.csv: line 3, field 'cluster' = 1.7: a cluster number must be a whole",
             "1;0;5;6;-3\n": r"freq.csv: line 2, field 'frequency \[%\]' = -3: a frequency must be >= 0",
             "1;0;6;6;3\n": r"freq.csv: line 2, field 'v100_high \[m/s\]' = 6: the bin's upper wind speed must be",
             "1;0;5;6;90\n1;1;6;7;60\n": r"freq.csv: field 'frequency \[%\]': the frequencies add up to 150 %, more "}
    for rows, message in cases.items():
        freq.write_text(head + rows)
        with pytest.raises(SiteWindError, match=message):
            read_clusters([shape], freq)
    freq.write_text(head + "1;0;5;6;40\n1;1;6;7;60\n")  # exactly 100 %: accepted, weights 0.4 and 0.6
    np.testing.assert_allclose(read_clusters([shape], freq).weight, [0.4, 0.6])
    shape.write_text("h [m];u1 [-];v1 [-];sf [-]\n100.0;1.0;0.0;1\n10.0;0.7;0.0;1\n")
    with pytest.raises(SiteWindError, match=r"shape.csv: line 3, field 'h \[m\]' = 10: heights must rise"):
        read_clusters([shape], freq)
    # blank lines count: the lines named are the file's, where the rows after a blank line were named one short
    shape.write_text("h [m];u1 [-];v1 [-];sf [-]\n10.0;0.7;0.0;1\n100.0;1.0;0.0;1\n")
    freq.write_text(head + "\n1;0;5;6;40\n\n1;1;6;7;-1\n")
    with pytest.raises(SiteWindError, match=r"freq.csv: line 5, field 'frequency \[%\]' = -1"):
        read_clusters([shape], freq)
    shape.write_text("h [m];u1 [-];v1 [-];sf [-]\n\n100.0;1.0;0.0;1\n\n10.0;0.7;0.0;1\n")
    with pytest.raises(SiteWindError, match=r"shape.csv: line 5, field 'h \[m\]' = 10: heights must rise"):
        read_clusters([shape], freq)


def test_site_wind_refuses_a_weight_that_is_not_a_number():
    from laddermill_gym.atmosphere.site_wind import SiteWind

    with pytest.raises(ValueError, match=r"weight nan of state 'b': weights must be finite"):
        SiteWind(np.array([10.0, 100.0]), np.ones((2, 2)), np.array([0.5, np.nan]), ("a", "b"))


def test_a_calm_lower_height_under_wind_takes_the_upper_exponent_limit(tmp_path):
    """v1 = 0, v2 > 0: ln(v2 / v1) / ln(h2 / h1) is +inf, so the limited exponent is the upper limit 0.6 and the
    speed at 600 m is v2 (600 / 80)^0.6 (it was the lower limit 0: v2, as if the shear were none)."""
    p = tmp_path / "two.csv"
    p.write_text("variable_name,wind_speed,wind_speed\nheight,10,80\n2010-01-01 00:00:00,0.0,5\n"
                 "2010-01-01 01:00:00,4.0,0.0\n2010-01-01 02:00:00,0.0,0.0\n")
    w = read_two_heights(p, top=600.0)
    np.testing.assert_allclose(w.at(600.0), [5.0 * (600.0 / 80.0) ** 0.6, 0.0, 0.0], rtol=1e-12)
    np.testing.assert_allclose(w.at(45.0), [2.5, 2.0, 0.0], rtol=1e-12)  # linear between the two heights
    assert "in 3 of 3 hours" in w.notes[0]


def test_daily_means_say_what_they_do_to_the_mean_cube():
    """Two days of two hours, 4 and 8 m/s, then 6 and 6 m/s at 80 m: the daily means' mean cube is (6^3 + 6^3) / 2
    = 216 against the hours' (4^3 + 8^3 + 6^3 + 6^3) / 4 = 252, a ratio of 0.857, which the daily data state."""
    from laddermill_gym.atmosphere.site_wind import SiteWind

    hours = SiteWind(np.array([10.0, 80.0, 200.0]), np.array([[2.0, 4.0, 5.0], [4.0, 8.0, 9.0], [3.0, 6.0, 7.0],
                                                              [3.0, 6.0, 7.0]]), np.full(4, 0.25),
                     ("2010-01-01 00", "2010-01-01 01", "2010-01-02 00", "2010-01-02 01"), measured_top=80.0)
    notes = daily(hours).notes
    assert notes == (f"daily means: the time mean of w^3 at 80 m is {216 / 252:.3f} of the 4 states' (a day's mean "
                     "wind has less than its mean cube; one profile a day, as the paper's soundings, would not lower "
                     "it)",)


def test_a_sounding_level_without_direction_keeps_its_speed_and_a_wrong_speed_unit_is_named(tmp_path):
    """The second sounding's 200 m level has its DRCT blank: its 16 kn count (the speed at 196 m above ground),
    where the level used to be dropped; a speed column in m/s instead of knots is refused by name."""
    p = tmp_path / "debilt.txt"
    row = "  990.0    200    8.4    6.6     88   6.00    210     16  281.9  298.6  283.0"
    assert WYOMING.count(row) == 1
    p.write_text(WYOMING.replace(row, row.replace("    210", "       ")))
    w = read_wyoming(p)
    assert w.at(196.0)[1] == pytest.approx(16 * 1852.0 / 3600.0, rel=1e-12)
    p.write_text(WYOMING.replace("deg   knot", "deg    m/s"))
    with pytest.raises(SiteWindError, match=r"debilt.txt: line \d+, field 'SKNT': unit 'm/s', expected knot"):
        read_wyoming(p)
