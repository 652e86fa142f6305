"""Linearise a scene with python-control: the tethered wing's lateral mode, its response to the wind, and an LQR.

``plant_system`` wraps the simulator as a python-control ``nlsys`` in minimal coordinates (Euler angles, not the
simulator's quaternions), with the environments' observation as its output and the wind's speed factor and
direction offset as two disturbance inputs after the controls. ``control.linearize`` then gives (A, B, C, D).
The wing on its tether has an unstable lateral oscillation; a continuous LQR on the tail surfaces moves it into
the left half-plane. Run it as ``python tutorials/linearise_with_control.py``; it writes
``linearise_with_control.png``.
"""

import control
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from laddermill_gym.control.plant import plant_system  # noqa: E402
from laddermill_gym.envs.task import scene_trim  # noqa: E402

T_END = 20.0  # length of the linear response [s]

# the scene as TetheredWing-v0 has it (one cable element), at its trim
scene, x0, u0 = scene_trim("tethered_wing", (("elements_per_piece", 1),))
plant = plant_system(scene, x0, u0)
lin = control.linearize(plant, plant.z0, plant.u0, copy_names=True)
n_controls = len(u0)  # elevator, rudder, aileron [rad]; then wind speed factor [-] and direction offset [rad]
print(f"states {lin.nstates}, inputs {lin.ninputs} ({n_controls} controls + 2 wind), outputs {lin.noutputs}")

poles = np.linalg.eigvals(lin.A)
unstable = poles[poles.real > 1e-6]
print("open-loop poles with positive real part [1/s]:", np.array2string(unstable, precision=3))

# an LQR on the controls only: unit state weights, tail deflections weighted by 100 per rad^2
B_u = lin.B[:, :n_controls]
K, _, closed = control.lqr(lin.A, B_u, np.eye(lin.nstates), 100.0 * np.eye(n_controls))
print(f"closed-loop largest real part {closed.real.max():.3f} 1/s")

# response of the observation to a 0.01 rad wind-direction offset, open and closed loop
t = np.linspace(0.0, T_END, 401)
d = np.zeros((lin.ninputs, t.size))
d[n_controls + 1] = 0.01
y_open = control.forced_response(lin, t, d).outputs
cl = control.ss(lin.A - B_u @ K, lin.B, lin.C - lin.D[:, :n_controls] @ K, lin.D)
y_closed = control.forced_response(cl, t, d).outputs
dy = next(i for i, name in enumerate(plant.output_labels) if name.endswith("dy"))  # the lateral offset [m]
print(f"lateral offset after {T_END:g} s: open loop {y_open[dy, -1]:.3f} m, LQR {y_closed[dy, -1]:.4f} m")

fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
ax[0].plot(poles.real, poles.imag, "x", label="open loop")
ax[0].plot(closed.real, closed.imag, "o", mfc="none", label="LQR")
ax[0].axvline(0.0, color="k", lw=0.5)
ax[0].set_xlim(-3, 1)
ax[0].set_ylim(-3, 3)
ax[0].set_xlabel("real [1/s]")
ax[0].set_ylabel("imaginary [1/s]")
ax[0].legend()
ax[1].plot(t, y_open[dy], label="open loop")
ax[1].plot(t, y_closed[dy], label="LQR")
ax[1].set_xlabel("t [s]")
ax[1].set_ylabel(f"{plant.output_labels[dy]} [m]")
ax[1].legend()
fig.suptitle("tethered_wing linearised: 0.01 rad wind-direction offset")
fig.tight_layout()
fig.savefig("linearise_with_control.png", dpi=90)
print("wrote linearise_with_control.png")
