"""Stepping onto the kinks of the wind modulation (``sim/breakpoints.py``).

Oracles: the kink times of a piecewise-linear schedule in closed form; scipy's DOP853 integrating the same
right-hand side piece by piece between the kinks (its own error control, no knowledge of our steppers); and
RK4's theoretical fourth order, which a step across a kink destroys and a split step restores.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from laddermill_gym import Simulator, load_scene
from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.kernels.fixed_steps import step_kinks
from laddermill_gym.sim.batch import BatchSimulator
from laddermill_gym.sim.breakpoints import modulation_kinks

T_STEP = 0.2037  # [s] start of the 1 ms direction ramp: inside a step of every dt used here
T_END = 0.45  # [s]


def ramp_sim(bp: str, dt: float, method: str = "rk4") -> Simulator:
    scene = load_scene("tethered_wing")
    start = scene.simulator()
    wind = scene.assembly.wind.with_modulation(T_STEP, 1e-3, np.ones(2), np.array([0.0, 0.05]))
    settings = dataclasses.replace(scene.settings, dt=dt, method=method, breakpoints=bp)
    return Simulator(dataclasses.replace(scene.assembly, wind=wind), start.initial_state, settings,
                     start.initial_controls)


def test_kink_times_closed_form():
    f = WindField(0.0, 0.5, np.array([1.0, 1.0, 1.1, 1.1, 1.1]), np.array([0.0, 0.0, 0.0, 0.0, 0.02]))
    tmod, ms, md, _, _ = pack_wind_field(f, n_modulation=8)  # padding with the last sample adds no kink
    # speed ramps on [0.5, 1.0]; direction ramps on [1.5, 2.0] and holds after
    assert np.allclose(modulation_kinks(tmod, ms, md), [0.5, 1.0, 1.5, 2.0])
    assert modulation_kinks(*pack_wind_field(WindField())[:3]).size == 0
    # a kink on a step's end is no split; one inside is (roundoff of a grid aligned with dt ignored): steps of
    # 0.1 s from 0 meet the kinks 0.5 and 1.0 (speed ramp) and 1.5, 2.0 (direction ramp) on their ends only
    tmod, ms, md, _, _ = pack_wind_field(f, n_modulation=8)
    assert [step_kinks(0.0, 0.1, j, tmod, ms, md) for j in (3, 4, 5, 6, 9, 10, 14, 15, 20, 21)] == [
        (0, False), (0, True), (0, True), (0, False), (0, True), (0, True), (0, True), (0, True), (0, True),
        (0, False)]
    # kinks at 0.55, 0.56 (speed ramp) and 0.80, 0.81 (direction ramp) on a 0.01 s grid from 0.55
    md = np.zeros(27)
    md[26] = 0.01
    tmod, ms, md, _, _ = pack_wind_field(WindField(0.55, 0.01, np.r_[1.0, np.full(26, 1.1)], md))
    assert np.allclose(modulation_kinks(tmod, ms, md), [0.55, 0.56, 0.8, 0.81])
    got = [step_kinks(0.0, 0.1, j, tmod, ms, md) for j in range(10)]
    assert got == [(0, False)] * 5 + [(2, False), (0, False), (0, True), (1, True), (0, False)], got


def dop853_reference() -> np.ndarray:
    """scipy DOP853 between the kinks; inside a piece the time passed to the rhs stays below the piece's end, so
    the rhs follows the piece's own linear segment up to its end."""
    sim = ramp_sim("inside", 0.005)
    x = sim.state.copy()
    ends = [0.0, T_STEP, T_STEP + 1e-3, T_END]
    for ta, tb in zip(ends[:-1], ends[1:], strict=True):
        top = tb - 1e-12
        sol = solve_ivp(lambda t, y: sim.rhs(min(t, top), y), (ta, tb), x, method="DOP853", rtol=1e-11,
                        atol=1e-11)
        assert sol.success
        x = sol.y[:, -1]
    return x


@pytest.fixture(scope="module")
def reference():
    return dop853_reference()


def test_rk4_fourth_order_across_a_ramp(reference):
    errs = {}
    for bp in ("inside", "off"):
        errs[bp] = []
        for dt in (0.005, 0.0025, 0.00125):
            sim = ramp_sim(bp, dt)
            sim.step(n_steps=int(round(T_END / dt)))
            assert abs(sim.t - T_END) < 1e-12
            errs[bp].append(np.max(np.abs(sim.state - reference)))
    e = np.array(errs["inside"])
    order = np.log2(e[:-1] / e[1:])
    for bp in ("inside", "off"):
        print(f"{bp}: largest error against DOP853 at dt 0.005, 0.0025, 0.00125 s: "
              + ", ".join(f"{x:.2g}" for x in errs[bp]))
    print("inside: ratios per halving " + ", ".join(f"{x:.1f}" for x in e[:-1] / e[1:]))
    assert np.all(order > 3.6), (errs, order)
    assert np.all(e < 1e-2 * np.array(errs["off"])), errs  # split steps: at least 100x more accurate here


def test_dp54_ends_steps_on_kinks(reference):
    sim = ramp_sim("inside", 0.005, "dp54")
    sim.advance_to(T_END, rtol=1e-10, atol=1e-10)
    assert np.max(np.abs(sim.state - reference)) < 1e-6


def test_aligned_grid_unchanged():
    """A modulation grid on the step grid splits nothing: the run is the run without breakpoint stepping."""
    runs = []
    for bp in ("inside", "off"):
        scene = load_scene("tethered_wing")
        start = scene.simulator()
        wind = scene.assembly.wind.with_modulation(0.1, 0.05, np.array([1.0, 1.1, 1.1]), np.zeros(3))
        sim = Simulator(dataclasses.replace(scene.assembly, wind=wind), start.initial_state,
                        dataclasses.replace(scene.settings, breakpoints=bp), start.initial_controls)
        sim.step(n_steps=int(round(0.3 / sim.settings.dt)))
        runs.append(sim.state.copy())
    assert np.array_equal(runs[0], runs[1])


def test_breakpoints_setting_checked():
    from laddermill_gym.sim.simulator import IntegratorSettings

    with pytest.raises(ValueError, match="breakpoints"):
        IntegratorSettings(breakpoints=True)


@pytest.mark.parametrize("runner", ["single", "batch"])
def test_aligned_kinks_fourth_order_with_all(runner):
    """A gust sampled on the step grid: every step ends on a kink. "all" gives each step its own segment's line
    (RK4's fourth order: error ratio near 16 per halving); across the kinks ("inside" = "off" here) the end stage
    sees the next segment's slope and the error falls far slower. The same for a copy of the batched kernel."""
    scene = load_scene("tethered_wing")
    start = scene.simulator()
    tt = np.arange(0.0, 0.4001, 0.02)
    speed = 1.0 + 0.15 * (1.0 - np.cos(2 * np.pi * tt / 0.4))
    asm = dataclasses.replace(scene.assembly, wind=scene.assembly.wind.with_modulation(0.1, 0.02, speed,
                                                                                     np.zeros_like(speed)))

    def run(mode, dt, method="rk4"):
        sim = Simulator(asm, start.initial_state, dataclasses.replace(scene.settings, dt=dt, method=method,
                                                                      breakpoints=mode), start.initial_controls)
        if method == "dp54":
            for t in np.arange(0.02, 0.6001, 0.02):  # stop on every kink: DOP853-like reference pieces
                sim.advance_to(t, rtol=1e-12, atol=1e-12)
        elif runner == "batch":
            b = BatchSimulator(asm, 1, sim.settings)
            b.states[0], b.controls[0] = sim.state, sim.controls
            assert np.all(b.step(int(round(0.6 / dt))) == 0)
            return b.states[0].copy()
        else:
            sim.step(n_steps=int(round(0.6 / dt)))
        return sim.state.copy()

    ref = run("all", 0.005, "dp54")
    err = {m: [np.max(np.abs(run(m, dt) - ref)) for dt in (0.0025, 0.00125)] for m in ("all", "inside")}
    print(f"{runner}: error ratio per halving, all {err['all'][0] / err['all'][1]:.1f}, "
          f"inside {err['inside'][0] / err['inside'][1]:.1f}")
    assert err["all"][0] / err["all"][1] > 12, err
    assert err["inside"][0] / err["inside"][1] < 8, err  # measured 5.4: far from fourth order
    assert err["all"][1] < 0.05 * err["inside"][1], err
