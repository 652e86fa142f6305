"""The work-precision study's closed-loop forcing (``studies/numerics/closed_loop.py``, ``--controller lqr``).

Oracle: the harness's own closed-loop run, ``control.rollout.run_direction_step`` with the package's
``LQRController`` (observations from the environments' kernel, actions through the environments' normalisation and
clip), a loop written independently of the study's (which reads the lateral coordinates from the state with
``control.linearize``): at one step size both must give the same wing path to rounding. And the study's closed-loop
reference (our DP5(4)) against scipy's DOP853 run through the same loop.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.studies.numerics import closed_loop as cl
from laddermill_gym.studies.numerics import work_precision as wp
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings


def _compare_with_rollout(scene: str, duration: float, n_samples: int) -> tuple[float, float, float]:
    """(largest position difference [m], largest Euler difference [rad], largest lateral excursion [m]) of the
    study's closed loop against ``run_direction_step`` with the same design, at the scene's own integrator."""
    from laddermill_gym.control.lqr import design_ladder_chain, design_tethered_wing, load_lqr_config
    from laddermill_gym.control.rollout import run_direction_step
    from laddermill_gym.ladder.scene import load_scene

    base = build_simulator(scene)
    fb = cl.design_feedback(scene, base, "lqr")
    x0, wind = wp.forcing_setup(base, "step", duration)
    times = np.linspace(0.0, duration, n_samples + 1)
    s = base.settings
    xs, ps = cl.closed_loop_trajectory(with_settings(base, state=x0, wind=wind), times, s.method, s.dt, fb,
                                       wp.positions)
    cfg, sc = load_lqr_config(cl.LQR_CONFIGS[scene]), load_scene(scene)
    trim = (base.initial_state.copy(), base.initial_controls.copy())
    design = design_tethered_wing(cfg, sc, trim) if sc.assembly.n_wings == 1 else design_ladder_chain(cfg, sc, trim)
    # the study's step: a 1 ms ramp from 0.3037 T (run_direction_step ramps over the 1 ms before step_time)
    roll = run_direction_step(sc, *trim, design.controller(np.float64), duration, fb.period, 0.1,
                              0.3037 * duration + 1e-3)
    assert roll.completed, roll.error
    per = cl.periods_per_sample(times, fb.period)
    nw = base.assembly.n_wings
    ev = with_settings(base)
    euler = []
    for t, x in zip(times, xs, strict=True):
        ev.reset(state=x, t=float(t), check=False)
        euler.append(ev.wing_euler())
    dp = np.abs(ps[:, :nw] - roll.positions[::per]).max()
    de = np.abs(np.array(euler) - roll.euler[::per]).max()
    return float(dp), float(de), float(np.abs(ps[:, :nw, 1]).max())


def test_closed_loop_is_the_harness_rollout_tethered_wing():
    dp, de, lateral = _compare_with_rollout("tethered_wing", 2.0, 4)
    print(f"tethered wing (2 s): wing paths within {dp:.2g} m and {de:.2g} rad of the harness rollout")
    assert lateral > 0.05  # the step moved the wing: the comparison is not of two rest states
    assert dp < 1e-9 and de < 1e-11, (dp, de)


@pytest.mark.slow
def test_closed_loop_is_the_harness_rollout_chain():
    dp, de, lateral = _compare_with_rollout("ladder_chain", 4.0, 4)
    print(f"chain (4 s): wing paths within {dp:.2g} m and {de:.2g} rad of the harness rollout")
    assert lateral > 0.01
    assert dp < 1e-8 and de < 1e-10, (dp, de)


def test_closed_loop_rows_and_references():
    res = wp.run_scene("tethered_wing", forcings=("step",), duration=1.0, n_samples=4, repeats=1, n_dt=2,
                       progress=False, controllers=("none", "lqr"))
    assert set(res["references"]) == {"step", "step+lqr"}
    assert res["references"]["step+lqr"]["reference_agreement_state"] < 1e-8  # DP5(4) against scipy's DOP853
    assert res["control_period_s"] == 0.05 and res["lqr_design_s"] > 0
    closed = [r for r in res["rows"] if r["forcing"] == "step+lqr"]
    steps = [r["dt_s"] for r in closed if r["method"] in ("rk4", "ros34pw2")]
    assert steps and all(abs(0.05 / h - round(0.05 / h)) < 1e-9 for h in steps)  # every step divides the period
    assert any(r["meets_controller"] for r in closed if r["method"] == "rk4" and r["status"] == "ok")


def test_bad_controller_names_raise(capsys):
    with pytest.raises(ValueError, match="'pid'"):
        cl.check_controller("pid")
    base = build_simulator("tethered_wing")
    with pytest.raises(ValueError, match="'pid'"):
        cl.design_feedback("tethered_wing", base, "pid")
    with pytest.raises(ValueError, match="'rotorcraft_x'"):
        cl.design_feedback("rotorcraft_x", base, "lqr")
    with pytest.raises(SystemExit):
        wp.main(["tethered_wing", "--controller", "pid", "--quiet"])
    assert wp.main(["pumping_kite", "--controller", "lqr", "--quiet"]) == 2  # one line, as laddermill's
    assert "pumping_kite" in capsys.readouterr().err


def test_kept_matrix_rows(capsys):
    """``--jacobian-every 4``: rows "METHOD/j4" beside the every-step rows, on the same step grid, with other last
    bits and, at the 0.05 s control period, within the controller tolerances of the DP5(4) / DOP853 reference."""
    assert wp.case_settings("ros2/j4", 0.05) == ("ros2", dict(method="ros2", breakpoints="inside", dt=0.05,
                                                                jacobian_every=4))
    assert wp.case_settings("rk4-all", 0.01) == ("rk4", dict(method="rk4", breakpoints="all", dt=0.01))
    res = wp.run_scene("tethered_wing", forcings=("step",), duration=1.0, n_samples=4, repeats=1, n_dt=2,
                       progress=False, controllers=("lqr",), jacobian_every=(1, 4))
    rows = {(r["method"], r["dt_s"]): r for r in res["rows"]}
    kept, every = rows[("ros34pw2/j4", 0.05)], rows[("ros34pw2", 0.05)]
    assert {m for m, _ in rows} >= {"ros1/j4", "ros2/j4", "ros2t/j4", "ros34pw2/j4"}
    assert kept["status"] == every["status"] == "ok" and kept["meets_controller"]
    assert 0.0 < kept["err_max_pos_m"] != every["err_max_pos_m"]
    assert wp.main(["tethered_wing", "--jacobian-every", "0", "--quiet"]) == 2
    assert "--jacobian-every = 0" in capsys.readouterr().err
