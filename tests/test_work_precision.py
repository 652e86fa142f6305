"""``laddermill work-precision`` (``studies/numerics/work_precision.py``) on a short run of the tethered wing.

Oracles: scipy's DOP853 (an independent implementation) agreeing with our DP5(4) reference; RK4's theoretical
fourth order (error ratio (dt1/dt2)^4 between grid steps) with breakpoint stepping, which the run across the
1 ms direction ramp does not reach; and DP5(4)'s error falling with its tolerance.
"""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from laddermill_gym.studies.numerics import work_precision as wp


@pytest.fixture(scope="module")
def result():
    return wp.run_scene("tethered_wing", forcings=("step",), duration=1.0, n_samples=5, repeats=1, n_dt=5,
                        progress=False)


def _rows(res, method):
    rows = [r for r in res["rows"] if r["method"] == method]
    assert rows and all(r["status"] == "ok" for r in rows), rows
    return rows


def test_references_agree(result):
    assert result["references"]["step"]["reference_agreement_state"] < 1e-8
    assert 0.015 < result["dt_stable_s"] < 0.025  # the issue's -13 +- 154i mode: 2.8 / 155 = 0.018 s


def test_rk4_order_with_and_without_breakpoints(result):
    rk4 = sorted(_rows(result, "rk4"), key=lambda r: -r["dt_s"])
    assert rk4[0]["dt_s"] <= result["dt_stable_s"]
    # in the asymptotic range (the two smallest steps; the largest are near the stability limit)
    a, b = rk4[-2], rk4[-1]
    order = np.log(a["err_final_state"] / b["err_final_state"]) / np.log(a["dt_s"] / b["dt_s"])
    assert order > 3.3, [(r["dt_s"], r["err_final_state"]) for r in rk4]
    off = {r["dt_s"]: r for r in _rows(result, "rk4-off")}
    for r in rk4:  # across the ramp: orders of magnitude worse at every step
        assert off[r["dt_s"]]["err_final_pos_m"] > 100 * r["err_final_pos_m"]


def test_dp54_error_follows_tolerance(result):
    dp = sorted(_rows(result, "dp54"), key=lambda r: -r["tol"])
    errs = [r["err_rms_state"] for r in dp]
    assert errs[-1] < 1e-3 * errs[0]
    assert all(r["wall_s"] > 0 for r in dp)


def test_command_writes_outputs(tmp_path):
    assert wp.main(["tethered_wing", "--forcing", "smooth", "--time", "0.5", "--samples", "2", "--repeats", "1",
                    "--n-dt", "2", "--out", str(tmp_path), "--quiet"]) == 0
    with open(tmp_path / "tethered_wing.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert {r["method"] for r in rows} == {"rk4", "dp54", "ros1", "ros2", "ros2t", "ros34pw2", "ros34pw2a"}
    assert all(r["err_max_pos_rel"] != "" for r in rows if r["status"] == "ok")
    assert json.loads((tmp_path / "tethered_wing.json").read_text())["scene"] == "tethered_wing"
    assert (tmp_path / "tethered_wing.png").stat().st_size > 1000


def test_gust_forcing_references_and_error_control():
    """The 1-cos gust (+30 %, a speed modulation sampled every 0.1 s): the two references agree, and the
    error-controlled methods' errors follow their tolerances over four decades (DP5(4) and ROS34PW2 under
    error control)."""
    res = wp.run_scene("tethered_wing", forcings=("gust",), duration=1.0, n_samples=5, repeats=1, n_dt=4,
                       progress=False)
    assert res["references"]["gust"]["reference_agreement_state"] < 1e-8
    for method in ("dp54", "ros34pw2a"):
        rows = {r["tol"]: r["err_final_state"] for r in _rows(res, method)}
        assert rows[1e-8] < 3e-4 * rows[1e-4] and rows[1e-8] < 1e-6, (method, rows)
