"""LadderMill-v0 in gusts-v2's grid scenarios (docs/wind.md, the mill's table and the paragraph below it): the slots'
heights at the operating point, the EWS's shear at the bottom and the top of its grid, and slot 0's roll in the
open loop's first second of NTM_IB seed 0.

Oracles: the IEC 61400-1 ed. 3 EWS amplitude (6.3.2.6, eq. 26) and NTM sigma_1 (eq. 11) written out here with the
standard's constants (I_ref 0.16 for class A, Lambda_1 = 42 m above 60 m, beta = 6.4, 1 - cos at its peak 2); the
scene file's wind profile above the boundary layer in closed form (Meijaard et al. 1999 eq. 1); the lateral gust at
slot 0 by an interpolation of the grid the kernels read (scipy's, on the unpacked values) times the fade-in's closed
form 0.5 (1 - cos(pi t / T_f)); slot 0's roll against the same first second without the turbulence (in plane: none).
"""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest
from scipy.interpolate import RegularGridInterpolator

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_spec
from laddermill_gym.envs.laddermill.gust_extent import point_positions
from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.wind import gust_at
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.studies.gusts.gust_suite import load_suite

LM = "laddermill_gym/LadderMill-v0"
SCENARIOS = {s.name: s for s in load_suite("gusts-v2").envs[LM][1]}


def test_mill_ews_takes_its_amplitude_off_the_bottom_and_adds_it_at_the_top():
    """EWS_IA of LadderMill-v0: the grid spans z_hub -+ D/2 and at the event's peak its rows are -A and +A, A of eq.
    26 at the scenario's class, hub speed, height and D; the scene's wind at the bottom row printed beside it."""
    (spec,) = SCENARIOS["EWS_IA"].disturbances
    ews = disturbance_from_spec(dict(spec))
    grid = ews.gust_grid(SCENARIOS["EWS_IA"].duration, np.random.default_rng(0))
    bottom, top = grid.h0, grid.h0 + (grid.values.shape[1] - 1) * grid.dh
    z_hub, d, v_hub = spec["hub_height"], spec["diameter"], spec["wind_speed"]
    assert (bottom, top) == pytest.approx((z_hub - d / 2, z_hub + d / 2), abs=1e-9)
    sigma1 = 0.16 * (0.75 * v_hub + 5.6)  # class A, NTM eq. 11
    lambda1 = 42.0  # eq. 5, z_hub > 60 m
    amplitude = (2.5 + 0.2 * 6.4 * sigma1 * (d / lambda1) ** 0.25) * 0.5 * 2.0  # (z - z_hub) / D = 1/2; 1 - cos = 2
    low, high = grid.values[:, 0, 0].min(), grid.values[:, -1, 0].max()
    w = load_scene("laddermill").assembly.wind
    assert bottom > w.h0
    wind = w.v0 + w.v1 * (bottom - w.h0)
    print(f"EWS_IA of LadderMill-v0: rows at {bottom:.1f} and {top:.1f} m; at the peak {low:.3f} m/s at the bottom "
          f"(the scene's wind there {wind:.3f} m/s) and {high:+.3f} m/s at the top; IEC eq. 26: {amplitude:.3f} m/s")
    assert -low == pytest.approx(amplitude, rel=1e-3) and high == pytest.approx(amplitude, rel=1e-3)
    assert -low > wind  # the event more than stops the bottom of the loop's wind


def _lateral_gust(task, p, t):
    """The global y gust [m/s] at p (global, z down) and time t from the unpacked grid of copy 0 (scipy's bilinear
    interpolation, held at the edges) times the fade-in's closed form."""
    gp, gv = task.batch.air.gp[0], task.batch.air.gv[0]
    nxi, nh = int(gp[C.GP_NXI]), int(gp[C.GP_NH])
    values = gv[: nxi * nh * C.GV_SIZE].reshape(nxi, nh, C.GV_SIZE)
    xi_axis, h_axis = gp[C.GP_XI0] + gp[C.GP_DXI] * np.arange(nxi), gp[C.GP_H0] + gp[C.GP_DH] * np.arange(nh)
    xi = p[0] * gp[C.GP_EX] + p[1] * gp[C.GP_EY] - gp[C.GP_ADVECTION] * t
    q = (np.clip(xi, xi_axis[0], xi_axis[-1]), np.clip(-p[2], h_axis[0], h_axis[-1]))
    u, v = (RegularGridInterpolator((xi_axis, h_axis), values[:, :, c])(q).item() for c in (C.GV_U, C.GV_V))
    fade = 0.5 * (1.0 - math.cos(math.pi * t / gp[C.GP_FADE])) if t < gp[C.GP_FADE] else 1.0
    return fade * (u * gp[C.GP_EY] + v * gp[C.GP_EX])


def _first_second(disturbances):
    """Slot 0's roll rates [rad/s], lateral gusts [m/s] (kernel) and times [s] over the first 1 s of LadderMill-v0
    (60 s episode as the suite's, seed 0, the zero action: the open loop), and the env's task before closing."""
    env = gym.make_vec(LM, num_envs=1, vectorization_mode="vector_entry_point", episode_time=60.0,
                       disturbances=[dict(d) for d in disturbances])
    task = env.task
    env.reset(seed=[0])
    rates, gusts, times = [], [], []
    while not times or times[-1] < 1.0 - 1e-9:
        _, _, term, _, info = env.step(np.zeros((1, task.n_actions), np.float32))
        assert not term[0]
        times.append(float(info["t"][0]))
        p = point_positions(task.batch.assembly, task.batch.states)[0][0]
        rates.append(task.batch.states[0][C.B3_RATE])
        if disturbances:
            gusts.append(gust_at(*p, times[-1], task.batch.air.gp[0], task.batch.air.gv[0])[1])
            assert gusts[-1] == pytest.approx(_lateral_gust(task, p, times[-1]), abs=1e-12)
    env.close()
    return np.array(rates), np.array(gusts), np.array(times), task


@pytest.mark.slow
def test_mill_slot_heights_and_slot_0_rolling_in_the_first_second_of_ntm():
    """The operating point's slot heights (rising from slot 0 by the veered station to the top, falling to the last
    slot by the hauled one); NTM_IB seed 0 in the open loop: slot 0 rolls within the first second in a lateral gust
    of hundredths of a m/s (faded in), while without the turbulence it does not roll at all (in plane)."""
    rates, gusts, times, task = _first_second(SCENARIOS["NTM_IB"].disturbances)
    calm, _, _, _ = _first_second(())
    h = -point_positions(task.batch.assembly, task.op.state)[0][: task.n_wings, 2]
    top = int(np.argmax(h))
    assert np.all(np.diff(h[: top + 1]) > 0.0) and np.all(np.diff(h[top:]) < 0.0)
    print(f"LadderMill-v0 at its operating point: slot 0 at {h[0]:.1f} m, slot 23 at {h[23]:.1f} m, slot {top} (the "
          f"top) at {h[top]:.1f} m, slots 99 and 100 at {h[99]:.1f} and {h[100]:.1f} m")
    k = int(np.argmax(np.abs(rates)))
    print(f"NTM_IB seed 0, open loop: slot 0's largest roll rate within the first {times[-1]:.1f} s is "
          f"{abs(rates[k]):.1f} rad/s ({rates[k]:.3f} at t = {times[k]:.2f} s), the lateral gust at its CG then "
          f"{gusts[k]:.3f} m/s ({gusts[-1]:.3f} at {times[-1]:.2f} s); without the turbulence at most "
          f"{np.abs(calm).max():.1e} rad/s")
    assert np.abs(calm).max() < 1e-9 and np.abs(rates).max() > 1.0
    assert np.abs(gusts).max() < 0.1
