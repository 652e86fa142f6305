"""Simulate a scene and plot it: the tethered wing after the paper's 0.01 rad wind-direction step.

Loads the shipped scene ``tethered_wing`` (one wing on a 100 m cable), turns the wind by 0.01 rad at t = 1 s
(the disturbance of Meijaard et al. 1999, as ``laddermill simulate tethered_wing --direction-step 0.01`` does),
records the named views and plots the wing's lateral offset, altitude and the cable tension. The glider on a
cable is laterally unstable: the small turn of the wind grows into an oscillation. Run it as
``python tutorials/simulate_and_plot.py``; it writes ``simulate_and_plot.png``.
"""

import dataclasses

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from laddermill_gym import load_scene  # noqa: E402
from laddermill_gym.sim.recording import record  # noqa: E402

T_END = 60.0  # simulated time [s]
STEP_RAD = 0.01  # wind-direction step [rad] at t = 1 s

scene = load_scene("tethered_wing")
x0, u0 = scene.initial_state()  # the trimmed equilibrium, found in the steady wind
asm = scene.assembly
# the wind's time modulation: (t0, dt, speed factors, direction offsets), here a 1 ms ramp to the step
wind = asm.wind.with_modulation(1.0 - 1e-3, 1e-3, np.ones(2), np.array([0.0, STEP_RAD]))
scene = scene.replace(assembly=dataclasses.replace(asm, wind=wind))
sim = scene.simulator(x0, u0)
rec = record(sim, T_END, sample_dt=0.1, progress=False)
print(f"{scene.name}: {asm.n_wings} wing, {asm.state_size} states, RK4 at dt = {scene.settings.dt} s")
print(f"recorded {len(rec.t)} samples to t = {rec.t[-1]:.2f} s; stopped early: {rec.error}")
print("views:", ", ".join(rec.views))

pos = rec.views["wing_position_m"][:, 0]  # x north (into the wind: the wing flies at x < 0), y east, z down
tension = rec.views["element_tension_N"]
print(f"largest lateral offset {np.abs(pos[:, 1]).max():.2f} m, tension {tension[:, 0].min() / 1e3:.2f}"
      f" to {tension[:, 0].max() / 1e3:.2f} kN")

fig, ax = plt.subplots(3, 1, sharex=True, figsize=(7, 6))
ax[0].plot(rec.t, pos[:, 1])
ax[0].set_ylabel("lateral y [m]")
ax[1].plot(rec.t, -pos[:, 2])
ax[1].set_ylabel("altitude [m]")
ax[2].plot(rec.t, tension[:, 0] / 1e3)
ax[2].set_ylabel("ground tension [kN]")
ax[2].set_xlabel("t [s]")
fig.suptitle(f"tethered_wing after a {STEP_RAD} rad wind-direction step")
fig.tight_layout()
fig.savefig("simulate_and_plot.png", dpi=90)
print("wrote simulate_and_plot.png")
