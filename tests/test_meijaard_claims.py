"""The claims panel of the Meijaard study (``studies/mill/meijaard_claims.py``) on hand-made inputs whose answers
are known in closed form: a symmetric loop whose element midpoints sit at chosen heights, a yaw that wraps through
180 deg, rows whose widths, tensions and powers are set to either side of each criterion."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.studies.mill import meijaard_claims as mc
from laddermill_gym.studies.mill.divergence import AERO, BREAKDOWN, End


def _loop(n_wings: int = 17, top_m: float = 1050.0):
    """A symmetric inverted V: ground points at 50 m, wings rising linearly to ``top_m`` at the middle slot."""
    half = n_wings // 2
    h = np.concatenate([np.linspace(150.0, top_m, half + 1), np.linspace(top_m, 150.0, half + 1)[1:]])
    shape = np.stack([np.zeros(n_wings), np.zeros(n_wings), -h], axis=1)
    return shape, (np.array([0.0, 0.0, -50.0]), np.array([100.0, 0.0, -50.0]))


def test_min_tension_place_heights():
    """17 wings at 150..1050 m, 112.5 m apart: element 8 joins wings at 937.5 and 1050 m (midpoint 993.75 m,
    (993.75 - 50) / 1000 = 0.94375 of the loop's 1000 m height: near the top); element 1 joins 150 and 262.5 m
    (0.15625: not)."""
    shape, ground = _loop()
    ten = np.full(18, 50e3)
    ten[8] = 3e3
    p = mc.min_tension_place(shape, ground, ten)
    assert p["element"] == 8 and p["tension_N"] == 3e3
    assert p["height_fraction"] == pytest.approx(0.94375) and p["near_top"] and p["loop_height_m"] == 1000.0
    ten[1] = 1e3
    p = mc.min_tension_place(shape, ground, ten)
    assert p["element"] == 1 and p["height_fraction"] == pytest.approx(0.15625) and not p["near_top"]
    with pytest.raises(ValueError, match="one element per piece"):
        mc.min_tension_place(shape, ground, np.ones(20))


def test_yaw_excursion_unwraps_and_stops_at_the_end():
    """Yaw 170 -> -170 deg is a 20 deg turn (unwrapped), not 340; samples after ``until_s`` are not counted."""
    rows = [{"t_after_step_s": t, "yaw_deg": y} for t, y in ((0.0, 170.0), (1.0, 179.0), (2.0, -170.0), (3.0, 0.0))]
    assert mc.yaw_excursion_deg(rows, 2.0) == pytest.approx(20.0)
    assert mc.yaw_excursion_deg(rows, 1.0) == pytest.approx(9.0)
    assert mc.yaw_excursion_deg(rows, 3.0) == pytest.approx(190.0)


def _row(v, width, periodic=True, p_kw=100.0, est_kw=100.0):
    return {"case": f"2D V_c={v:g}", "V_c_m_s": v, "periodic": periodic, "width_min_m": width[0],
            "width_max_m": width[1], "loop_width_m": sum(width) / 2, "late_periods": 3, "late_power_min_kW": -5.0,
            "late_power_max_kW": 7.0, "late_power_mean_kW": 1.0,
            "mean_power_kW": p_kw, "tension_estimate_kW": est_kw, "T_first_kN": 1.0,
            "T_last_kN": 0.5}


def test_fig6_7_claims_either_side():
    """Widens only when the smallest width at 5 m/s passes the largest at 1 m/s; the smallest tension grows."""
    places = {1.0: {"element": 50, "tension_N": 4e3, "height_fraction": 0.99, "near_top": True, "loop_height_m": 2e3},
              5.0: {"element": 74, "tension_N": 9e3, "height_fraction": 0.6, "near_top": False, "loop_height_m": 2e3}}
    c = mc.fig6_7_claims(_row(1.0, (270, 290)), _row(5.0, (291, 900), periodic=False), places)
    assert [x["agrees"] for x in c] == ["-", "yes", "yes", "no", "yes"]
    assert "width / height 0.140" in c[0]["ours"]  # 280 m / 2000 m
    assert "NOT periodic" in c[1]["ours"] and "NOT periodic" in c[3]["ours"]
    c = mc.fig6_7_claims(_row(1.0, (270, 290)), _row(5.0, (289, 900)), {1.0: places[5.0], 5.0: places[1.0]})
    assert [x["agrees"] for x in c] == ["-", "no", "no", "yes", "no"]


def test_power_claims_criteria():
    """Estimate within 3 % of the generator's power: yes at 2.9 %, no at 3.1 %; 200 kW's order: periodic and at
    least 150 kW."""
    c = mc.power_claims([_row(2.0, (0, 0), p_kw=160.0, est_kw=160.0 * 1.029),
                         _row(5.0, (0, 0), periodic=False, p_kw=400.0, est_kw=400.0 * 0.969),
                         _row(1.0, (0, 0), p_kw=149.0, est_kw=149.0)])
    assert [x["agrees"] for x in c] == ["yes", "yes", "no", "no", "yes", "no"]
    assert "the last 3 period means -5 to 7 kW, mean 1.0 kW" in c[3]["ours"]


def _run(label, end, t, dt=0.01, method="rk4", rows=None, exits=(5.0, 4.0, float("nan"), 4.5)):
    keys = ("alpha_exit_any_s", "beta_exit_any_s", "alpha_exit_slot_s", "beta_exit_slot_s")
    rows = rows or [{"t_after_step_s": k, "yaw_deg": 5.0 * k} for k in range(40)]
    return {"label": label, "slot": 40, "end": end, "t_reached_s": t, "dt_s": dt, "method": method, "rows": rows,
            **dict(zip(keys, exits, strict=True))}


def test_fig8_claims():
    """The yaw excursion is read up to the reference run's physical end and over the longest run ('large': more than
    the fins' stall sideslip, 21 deg); the smaller fixed step goes longer; the data's range is left before the end."""
    ref = _run("RK4", End(AERO, 4.0), 4.0)
    long = _run("RK4 dt/4", End(BREAKDOWN, 39.0), 39.0, dt=0.0025)
    short = _run("RK4 no end", End(BREAKDOWN, 25.0), 25.0)
    c = mc.fig8_claims([ref, long, short])
    assert "20 deg before the end at 4.0 s" in c[0]["ours"] and "195 deg over 39.0 s" in c[0]["ours"]
    assert [x["agrees"] for x in c] == ["yes", "-", "yes", "yes"]  # beta left at 4.0 s, the end at 4.0 s
    assert "physical end first at 4.0 s" in c[1]["ours"]
    assert "RK4 no end: numerical breakdown at 25.0 s; RK4 dt/4: numerical breakdown at 39.0 s" in c[2]["ours"]
    c = mc.fig8_claims([ref, _run("RK4 dt/4", End(BREAKDOWN, 20.0), 20.0, dt=0.0025), short])
    assert c[2]["agrees"] == "no"
    late = _run("RK4", End(AERO, 4.0), 4.0, exits=(4.5, float("nan"), float("nan"), float("nan")))
    c = mc.fig8_claims([late])
    assert [x["agrees"] for x in c] == ["no", "-", "no"]  # 20 deg is not beyond 21; alpha left after the end
