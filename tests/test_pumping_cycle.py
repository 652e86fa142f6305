"""The scripted pumping cycle (control/pumping_cycle.py) and its quasi-steady comparison
(studies/pumping/pumping_cycle.py): phase logic against hand-built observations, the lateral instability the LQR cures,
and the simulated cycle against Lansdorp et al. (2008) eqs. 10-14 fed with its own phase means."""

import math

import numpy as np
import pytest

from laddermill_gym.control.lqr import DEFAULT_CONFIG
from laddermill_gym.control.pumping_cycle import (
    PHASE_DEPOWER,
    PHASE_IN,
    PHASE_OUT,
    PumpingCycleController,
    lateral_lqr,
    reel_in_elevator,
)
from laddermill_gym.envs.pumping.observation import N_OBS, WINCH_OBS_INDEX
from laddermill_gym.envs.pumping.task import PumpingTask
from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.statics import table_spline
from laddermill_gym.studies.pumping.pumping_cycle import contact_summary, cycle_stats, quasi_steady, run_cycles


@pytest.fixture(scope="module")
def task():
    return PumpingTask(1, episode_time=400.0)


def _obs(v, s, tension, radial_wind):
    o = np.zeros((len(v), N_OBS))
    i = WINCH_OBS_INDEX
    o[:, i["winch_speed"]], o[:, i["paid_out"]] = v, s
    o[:, i["drum_tension"]], o[:, i["radial_wind"]] = tension, radial_wind
    return o


def test_phases_from_observations(task):
    """Delta L = 200 m, f = 1/3, depower below 300 N or 20 m after Delta L, reel-in at 5 m/s."""
    ctl = PumpingCycleController(task)
    obs = _obs(v=[0.0, 1.0, 1.0, 1.0, 1.0, 0.2, -3.0, -3.0, 1.0],
               s=[0.0, 100.0, 205.0, 205.0, 221.0, 205.0, 100.0, -0.1, 205.0],
               tension=[2000, 2000, 2000, 200, 2000, 2000, 300, 300, 2000],
               radial_wind=[3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, -3.0])
    phase, v_out = ctl.phases(obs)
    assert phase.tolist() == [PHASE_OUT, PHASE_OUT, PHASE_DEPOWER, PHASE_IN, PHASE_IN, PHASE_IN, PHASE_IN,
                              PHASE_OUT, PHASE_DEPOWER]
    np.testing.assert_allclose(v_out[:8], 1.0, rtol=1e-9)  # f w_r = 3 / 3
    assert v_out[8] == 0.0  # a wind blowing towards the winch never commands reel-in during reel-out
    u = ctl.controls(obs)
    np.testing.assert_allclose(u[phase == PHASE_IN, 3], -5.0)
    print(f"reel-out elevator (the scene's trim) {math.degrees(task.u_trim[0]):+.2f} deg, reel-in elevator "
          f"{math.degrees(ctl.u_in[0]):+.2f} deg")
    np.testing.assert_allclose(u[phase == PHASE_OUT, 0], task.u_trim[0])
    np.testing.assert_allclose(u[phase != PHASE_OUT, 0], ctl.u_in[0])
    a, _ = ctl.predict(obs)
    np.testing.assert_allclose(task.actions.controls(a)[:, 3], u[:, 3], atol=1e-6)


def test_reel_in_elevator_balances_the_pitching_moment(task):
    """At the reel-in elevator the aerodynamic moment about the cable attachment vanishes at alpha_in: the moment
    of the table's force at the reference point plus the table's Cm, evaluated here from the coefficients."""
    wt = task.scene.assembly.wing(0)
    alpha = task.pumping.cycle.alpha_in
    e = reel_in_elevator(wt, alpha)
    print(f"reel-in elevator at alpha_in {math.degrees(alpha):.1f} deg: {math.degrees(e):+.2f} deg")
    c = table_spline(wt.aero)(alpha)
    k = AERO_INDEX
    cl = c[k["CL"]] + c[k["CLde"]] * e
    cd = c[k["CD"]]  # the table has no elevator drag derivative
    cm = c[k["Cm"]] + c[k["Cmde"]] * e
    ca, sa = math.cos(alpha), math.sin(alpha)
    fx, fz = cl * sa - cd * ca, -cl * ca - cd * sa  # body axes, wind along the body x axis tilted by alpha
    ax = wt.r_ref[0] - wt.attachment[0]
    az = wt.r_ref[2] - wt.attachment[2]
    assert cm * wt.chord + az * fx - ax * fz == pytest.approx(0.0, abs=1e-6)


def test_lqr_holds_the_cycle_scripted_alone_diverges(task):
    """The Meijaard wing on its tether is laterally unstable (Meijaard et al. 1999): after the 0.01 rad direction
    step the scripted cycle alone drifts tens of metres sideways within 120 s; with the lateral LQR it stays within
    a few metres through a whole cycle."""
    short = PumpingTask(1, episode_time=120.0)
    rec = run_cycles(short, PumpingCycleController(short), 1, progress=False)
    assert rec["abs_dy"].max() > 20.0
    rec = run_cycles(task, PumpingCycleController(task, lateral_lqr(task, DEFAULT_CONFIG)), 1, progress=False)
    assert rec["abs_dy"].max() < 10.0
    assert rec["phase"].max() == PHASE_IN


def test_cycle_against_quasi_steady_equations():
    """A complete cycle (the second, the first starts from the trim): eqs. 10-14 of Lansdorp et al. fed with the
    simulated mean reel-out tension and speed, reel-in tension and speed and the reeled length give its mean power
    within 25 % (the rest: tension and speed vary together within reel-out, not in the means); the crosswind
    prediction (eq. 9, kite speed G w_e) is more than ten times higher, the wing flying static in the wind plane."""
    task = PumpingTask(1, episode_time=600.0)
    ctl = PumpingCycleController(task, lateral_lqr(task, DEFAULT_CONFIG))
    rec = run_cycles(task, ctl, 2, progress=False)
    stats = cycle_stats(rec, task.control_dt)
    c = stats[-1]
    q = quasi_steady(c, task)
    assert c["power"] > 0
    assert q["eqs10_14_fed_W"] == pytest.approx(c["power"], rel=0.25)
    # eq. 13-14 by hand from the same means
    eta = task.winch.efficiency
    e = eta * c["tension_out"] * c["reeled"] - c["tension_in"] * c["reeled"] / eta
    assert q["eqs10_14_fed_W"] == pytest.approx(e / (c["reeled"] / c["speed_out"] + c["reeled"] / c["speed_in"]))
    assert q["lansdorp_W"] > 10 * c["power"]


def test_quasi_steady_models_use_the_air_density_at_the_cycle_altitude(task):
    """The wing flies in the scene's barometric air (Meijaard eq. 3: rho0 exp(-h / H_b), configs/scenes/
    pumping_kite.yaml: 1.225 kg/m^3, 8400 m); the models compared with it get the density at the cycle's mean
    altitude: Lansdorp's eq. 9 tension by hand at a hand-made cycle's parameters."""
    c = dict(wind=9.0, altitude=400.0, theta=math.radians(60.0), alpha=math.radians(6.0), reeled=150.0,
             speed_in=5.0, speed_out=2.0, azimuth_rms=0.3, elevation_in=math.radians(70.0), tension_out=9e3,
             tension_in=1e3)
    q = quasi_steady(c, task)
    wing = task.scene.assembly.wing(0)
    coef = table_spline(wing.aero)(c["alpha"])
    cl, cd = float(coef[AERO_INDEX["CL"]]), float(coef[AERO_INDEX["CD"]])
    L = c["altitude"] / math.cos(c["theta"])
    cdt = cd + task.scene.cable.diameter * L * 1.2 / (4.0 * wing.area)  # eq. 6, C_Dc 1.2 (PumpingParams)
    w_e = c["wind"] * math.sin(c["theta"]) * (1.0 - task.pumping.cycle.reel_out_factor)
    rho = 1.225 * math.exp(-400.0 / 8400.0)
    eq9 = 0.5 * rho * wing.area * (cl * cl + cdt * cdt) ** 1.5 / (cdt * cdt) * w_e * w_e
    assert q["lansdorp_tension_N"] == pytest.approx(eq9, rel=1e-12)


def test_contact_summary_of_a_hand_made_record():
    """pumping-cycle's ground-contact line (a reeling tether) against a record built by hand: steps at 0.5 s, a
    reel-out, a reel-in ending at t = 2.0 s, contacts (0, 0, 0, 0, 0, 2, 3, 0) from t = 3.0 s, 1.0 s into the second
    reel-out: 3 at most, 2 of 8 steps (25.0 %); none at all is said so."""
    ph = np.array([PHASE_OUT, PHASE_OUT, PHASE_IN, PHASE_IN, PHASE_OUT, PHASE_OUT, PHASE_OUT, PHASE_OUT])
    rec = {"t": 0.5 * np.arange(1, 9), "phase": ph, "contacts": np.array([0, 0, 0, 0, 0, 2, 3, 0], float)}
    line = contact_summary(rec, ("reel_out", "depower", "reel_in"))
    assert line == ("ground contacts: up to 3 nodes on the ground at once, in 25.0 % of the 8 control steps; the "
                    "first at t = 3.00 s, 1.00 s into the reel_out phase of cycle 2 (cycle 1: from the start to the "
                    "end of the first reel-in)")
    assert "no tether node" in contact_summary({**rec, "contacts": np.zeros(8)}, ("reel_out", "depower", "reel_in"))
