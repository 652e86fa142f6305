"""The fixed-step integrator is the classic fourth-order Runge-Kutta method on the full model.

Oracle: the global error of classic RK4 on a smooth ODE falls as dt^4 (Hairer, Norsett & Wanner, "Solving
Ordinary Differential Equations I", sec. II.3), measured against an independent high-accuracy solution,
here the error-controlled Dormand-Prince 5(4) integrator at rtol = atol = 1e-12 (shared/design/oracles.md,
"Numerics": reference at a much tighter tolerance, error at the final time, log-log axes).

Model: one wing with a smooth synthetic aerodynamic table (every column non-zero, lateral derivatives
included) on a 2-element cable with sag correction and cable aerodynamics, in the default wind, released
off-equilibrium with sideslip, yaw, roll and small rates. All points stay clear of the wind profile's
kink at h0 = 50 m (the cable node stays below it, the wing above), so the right-hand side is smooth.
"""

from __future__ import annotations

import functools

import numpy as np

from laddermill_gym.model.builders import build_chain, chain_state
from laddermill_gym.model.params import WindParams
from laddermill_gym.sim.simulator import IntegratorSettings, Simulator
from tests.conftest import cable_spec, make_wing_type, smooth_aero_table

T_END = 3.0  # [s]
DTS = np.array([0.01, 0.005, 0.0025, 0.00125])  # [s]


@functools.cache
def tethered_wing():
    wt = make_wing_type(mass=5.0, inertia=(4.0, 1.5, 5.0, 0.3), attachment=(0.3, 0.0, 0.6),
                        aero=smooth_aero_table(), area=5.0, span=5.0, chord=1.0, r_ref=(-0.1, 0.0, 0.0))
    wing_pos = np.array([-60.0, 3.0, -90.0])  # downwind of the ground point (wind blows along -x), 90 m up
    cable = cable_spec(mass_per_length=0.05, EA=1.0e5, DA=1.0e3, diameter=0.01)
    asm, layout = build_chain((wt,), [0], [0.99 * np.linalg.norm(wing_pos)], 2, cable, [[0.0, 0.0, 0.0]], 0,
                              None, WindParams(), sag=True, cable_aero=True)
    x0 = chain_state(asm, layout, [wing_pos], [(0.05, 0.15, 0.12)], [0.0, 0.0, 0.0],
                     wing_velocities=[(0.5, 0.3, 0.2)], wing_rates=[(0.05, -0.02, 0.03)])
    return asm, x0


def test_rk4_fourth_order():
    """Final-time error of RK4 for dt = 10, 5, 2.5, 1.25 ms against DP5(4) at 1e-12: fitted log-log slope
    4 +- 0.3 and the finest pair's slope 4 +- 0.2 (measured: errors 1.1e-5 ... 1.7e-9, slope 4.20,
    pairwise 4.36, 4.18, 4.09)."""
    asm, x0 = tethered_wing()
    ref_sim = Simulator(asm, x0, IntegratorSettings(method="dp54", dt=1e-3))
    # the run is a genuine 3D, tethered, aerodynamic motion: taut cable, sideslip, lateral drift
    ab = ref_sim.wing_alpha_beta()[0]
    assert abs(ab[1]) > 0.02
    assert np.all(ref_sim.tensions() > 10.0)
    ref = ref_sim.advance_to(T_END, rtol=1e-12, atol=1e-12).copy()
    assert np.all(ref_sim.tensions() > 10.0)
    assert abs(ref[1] - x0[1]) > 1.0  # lateral drift [m]
    assert np.linalg.norm(ref[10:13] - x0[10:13]) > 0.05  # the rates changed

    errs = []
    for dt in DTS:
        sim = Simulator(asm, x0, IntegratorSettings(method="rk4", dt=float(dt)))
        sim.step(n_steps=int(round(T_END / dt)))
        assert abs(sim.t - T_END) < 1e-12
        errs.append(np.max(np.abs(sim.state - ref)))
    errs = np.array(errs)
    # still far above the reference's own error (1e-12: it moves by that much at rtol = atol = 1e-13)
    assert errs[-1] > 1e-10
    slope = np.polyfit(np.log(DTS), np.log(errs), 1)[0]
    assert abs(slope - 4.0) <= 0.3, f"slope {slope:.3f}, errors {errs}"
    last = np.log(errs[-2] / errs[-1]) / np.log(DTS[-2] / DTS[-1])
    assert abs(last - 4.0) <= 0.2, f"finest-pair slope {last:.3f}, errors {errs}"
