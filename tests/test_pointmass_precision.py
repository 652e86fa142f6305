"""``laddermill work-precision podgaets_5km`` (``studies/numerics/pointmass_precision.py``) on a short run.

Oracles: two independent scipy integrators (DOP853 and RK45) agreeing as the reference; the first order of both
methods (error ratio dt1 / dt2 between steps, asymptotically).
"""

from __future__ import annotations

import csv
import math

import pytest

from laddermill_gym.studies.numerics import pointmass_precision as pp
from laddermill_gym.studies.numerics import work_precision as wp


@pytest.fixture(scope="module")
def result():
    return pp.run_scene("podgaets_5km", forcings=("step",), duration=0.5, n_samples=2, repeats=1,
                        element_length=50.0, progress=False)


def _rows(res, method):
    rows = sorted((r for r in res["rows"] if r["method"] == method), key=lambda r: -r["dt_s"])
    assert rows and all(r["status"] == "ok" for r in rows), rows
    return rows


def test_references_agree(result):
    assert result["references"]["step"]["reference_agreement_state"] < 1e-6


def test_both_methods_converge_at_first_order(result):
    for method in ("explicit", "implicit"):
        rows = _rows(result, method)
        a, b = rows[-2], rows[-1]  # the two smallest steps
        ratio = a["err_final_state"] / b["err_final_state"]
        order = math.log(ratio) / math.log(a["dt_s"] / b["dt_s"])
        assert 0.7 < order < 1.5, (method, order)
    assert _rows(result, "explicit")[0]["dt_s"] <= result["dt_stable_s"]
    assert max(r["dt_s"] for r in _rows(result, "implicit")) > 20 * result["dt_stable_s"]


def test_command_routes_pointmass_scenes(tmp_path):
    assert pp.is_pointmass_scene("podgaets_5km") and not pp.is_pointmass_scene("ladder_chain")
    assert not pp.is_pointmass_scene("roberts_flying_model")
    assert wp.main(["podgaets_5km", "--forcing", "smooth", "--time", "0.2", "--samples", "1", "--repeats", "1",
                    "--element-length", "50", "--out", str(tmp_path), "--quiet"]) == 0
    with open(tmp_path / "podgaets_5km.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert {r["method"] for r in rows} == {"explicit", "implicit"}
    assert (tmp_path / "podgaets_5km.png").stat().st_size > 1000
