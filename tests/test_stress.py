"""``laddermill stress`` (``studies/numerics/stress.py``, ``studies/numerics/stress_cases.py``): the small version.

Oracles: the eigenvalue estimate of the stable step (``studies/numerics/stable_step.py``) for the bisection by
simulation (two independent routes to one number); the injected entry's own name for the failure reports; the kinetic
energy of a hand-built state in closed form; the env's documented failure codes for the episodes.
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from laddermill_gym.kernels.contract import B3_RATE, B3_VEL
from laddermill_gym.studies.numerics import stress, stress_cases
from laddermill_gym.studies.numerics.scenes import build_simulator


def test_bisection_agrees_with_the_eigenvalue_estimate():
    rows = stress_cases.stable_step_rows("tethered_wing", horizon=2.0, iters=5)
    rk4 = rows[0]
    assert rk4["passed"] and abs(rk4["ratio_bisection_to_estimate"] - 1) < 0.05, rk4
    dp = rows[1]
    assert dp["passed"] and 0.8 < dp["ratio_step_to_estimate"] < 1.05, dp  # DP5(4) sits at its stability limit
    w = {r["case"]: r for r in rows[2:]}  # the linearly implicit methods hold steps well beyond RK4's limit
    assert set(w) == {"largest stable step ros1", "largest stable step ros2", "largest stable step ros34pw2"}
    assert all(r["passed"] and r["ratio_to_rk4_limit"] >= 2.0 for r in w.values()), w
    for r in rows:  # the figures held above (pytest -s; numpy scalars as plain numbers)
        print({k: float(v) if isinstance(v, float) else v for k, v in r.items()})


def test_injections_are_reported_with_time_body_and_quantity():
    rows = stress_cases.injection_rows("tethered_wing")
    assert len(rows) == 3 * len(stress_cases.INJECTIONS)  # RK4, DP5(4), ROS34PW2
    for r in rows:
        assert r["passed"], r
        assert "t = 0.05 s" in r["outcome"]
    names = {r["case"]: r["outcome"] for r in rows if r["method"] == "rk4"}
    assert "wing 0 q0 is nan" in names["inject quaternion NaN"]
    assert "node 0 x [m] is nan" in names["inject node position NaN"]
    print(names["inject node position NaN"])  # the report the test holds (pytest -s)


def test_kinetic_energy_closed_form():
    sim = build_simulator("tethered_wing")
    x = sim.initial_state.copy()
    x[B3_VEL: B3_VEL + 3] = [3.0, 0.0, 4.0]
    x[B3_RATE: B3_RATE + 3] = [0.0, 2.0, 0.0]
    wt = sim.assembly.wing_types[0]
    expected = 0.5 * wt.mass * 25.0 + 0.5 * wt.inertia[1] * 4.0  # node masses of this scene are 0
    assert stress_cases.kinetic_energy(sim, x) == pytest.approx(expected, rel=1e-12)


def test_winds_controls_and_slack_run_or_terminate_documented():
    rows = stress.wind_rows("tethered_wing", 2.0) + stress.control_rows("tethered_wing", 2.0)
    assert {r["case"] for r in rows} >= {"wind to zero and back", "wind 40 m/s", "bang-bang controls"}
    for r in rows:
        assert r["passed"], r
        assert math.isfinite(r["max_tension_N"]) and r["max_kinetic_energy_J"] >= 0


def test_env_episodes_end_documented():
    row = stress.episode_rows("laddermill_gym/TetheredWing-v0", 40, 1.0, n_copies=8)[0]
    assert row["passed"], row
    assert row["solver_failure_codes"] == "[1]"


def test_command_table(tmp_path, capsys):
    code = stress.main(["tethered_wing", "--hours", "0.002", "--envs", "--quick", "--out", str(tmp_path), "--quiet"])
    with open(tmp_path / "stress.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    cases = {r["case"]: r for r in rows}
    assert cases["hold 0.002 h"]["passed"] == "True"
    # 8 elements per piece has an initial state since issue 13 (catenary guess, Newton on forces: ladder/initial.py);
    # the scene's 5 ms RK4 step is above the estimated stable step (1.35 ms), which the case flags, and the run at
    # half the estimate holds
    row = cases["8 element(s) per piece"]
    assert row["passed"] == "True" and row["scene_dt_flagged"] == "True", row
    assert code == 0 and "FAIL" not in capsys.readouterr().out
    assert np.all([r["scene"] == "tethered_wing" for r in rows])


def test_rotorcraft_is_held_by_its_lqr():
    """The craft is open-loop unstable at its trim (growth +0.127 1/s, rotorcraft.md): the hour is held by its
    eq. (6) LQR, at the design's control period, and the kinetic energy stays at the trim's roundoff level."""
    row = stress.long_run_rows("roberts_flying_model", 120.0, progress=False)[0]
    assert row["held_by"] == "eq. (6) LQR" and row["passed"], row
    assert row["t_end_s"] == pytest.approx(120.0)
    assert row["kinetic_energy_last_J"] < 1e-6 and abs(row["height_drift_m"]) < 1e-6


def test_a_refused_scene_step_counts_as_detected(tmp_path):
    # the tethered wing's scene with a 50 ms RK4 step: at 8 elements per piece the loader refuses it (beyond twice the
    # stiffest element's closed-form bound); the case must find the equilibrium below the bound and hold at half the
    # estimate
    from laddermill_gym.ladder.scene import scene_path

    src = scene_path("tethered_wing")
    text = src.read_text().replace("dt: 0.005 ", "dt: 0.05  ")
    for folder in ("wings", "cables"):
        text = text.replace(f"../{folder}/", f"{src.parent.parent / folder}/")
    path = tmp_path / "tethered_wing_50ms.yaml"
    path.write_text(text)
    rows = {r["case"]: r for r in stress.element_rows(str(path), 2.0)}
    row = rows["8 element(s) per piece"]
    assert "refused at load" in row["outcome"] and row["scene_dt_flagged"], row
    assert row["passed"] and "half the estimate: ok" in row["outcome"], row
    assert row["dt_scene_s"] == 0.05


def test_injections_on_a_scene_whose_step_is_beyond_rk4s_limit():
    # the rotorcraft steps ROS34PW2 at 50 ms, eight times RK4's limit: the RK4 injections run at half its estimate
    rows = stress_cases.injection_rows("roberts_flying_model")
    assert len(rows) == 3 * len(stress_cases.INJECTIONS) and all(r["passed"] for r in rows), rows


def test_wing_scenes_are_held_by_their_lateral_lqr():
    """The tethered wing's hour is held by its env's lateral LQR on the env observation of the simulator's state. At
    the equilibrium the observation's deviations are zero, so the LQR must give back the equilibrium controls (the
    action map's oracle: mid + a half-range inverts the trim); a short hold passes."""
    sim = build_simulator("tethered_wing")
    period, controls, name = stress.scene_holder("tethered_wing", sim)
    assert (period, name) == (0.05, "lateral LQR")
    np.testing.assert_allclose(controls(sim), sim.initial_controls, rtol=0, atol=1e-9)
    row = stress.long_run_rows("tethered_wing", 60.0, progress=False)[0]
    assert row["passed"] and row["held_by"] == "lateral LQR" and abs(row["height_drift_m"]) < 1e-6, row
