"""The point-mass string (Podgaets & Ockels 2007): the 101-wing chain as point-mass kites on an elastic string.

Any scene loads at the point-mass fidelity: kites are point masses whose attitude is the control, the cable an
elastic string of many small elements (tension only, Voigt damping, cable drag), stepped by a linearly implicit
method whose cost is linear in the number of elements. Here the paper's 101-wing chain (scene ``ladder_chain``:
7.1 km of cable between two ground points, up to 3.5 km high) on 10 m elements starts from the rigid model's
static equilibrium (its wings' positions and attitudes) and is let go; it is not an equilibrium of the point-mass
model, so the string moves off it. Scene ``podgaets_5km`` is the paper's 5 km string at 1 cm (500,000 elements).
Run it as ``python tutorials/pointmass_string.py``; it writes ``pointmass_string.png``.
"""

import time

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from laddermill_gym import load_scene  # noqa: E402

T_END = 60.0  # simulated time [s]
ELEMENT_LENGTH = 10.0  # [m]

scene = load_scene("ladder_chain", fidelity="pointmass", element_length=ELEMENT_LENGTH)
sim = scene.simulator()
print(sim.describe())
print(f"held: {sum(sim.held_bytes().values()) / 1e6:.2f} MB")
start = sim.positions.copy()
t0 = time.perf_counter()
sim.advance(T_END)
wall = time.perf_counter() - t0
end = sim.positions
print(f"simulated {sim.t:.1f} s in {wall:.1f} s wall (first call includes numba's compilation)")
tension = sim.tensions()
print(f"tension: {tension.min() / 1e3:.1f} to {tension.max() / 1e3:.1f} kN; "
      f"largest node displacement {np.linalg.norm(end - start, axis=1).max():.1f} m")

fig, ax = plt.subplots(1, 2, figsize=(10, 4), gridspec_kw={"width_ratios": [1, 2]})
ax[0].plot(start[:, 0], -start[:, 2], "--", color="0.6", label="t = 0 (rigid equilibrium)")
ax[0].plot(end[:, 0], -end[:, 2], label=f"t = {sim.t:.0f} s")
ax[0].set_xlabel("x (north) [m]")
ax[0].set_ylabel("altitude [m]")
ax[0].legend(fontsize="small")
ax[1].plot(np.arange(tension.size) * ELEMENT_LENGTH, tension / 1e3)
ax[1].set_xlabel("along the string [m]")
ax[1].set_ylabel("tension [kN]")
fig.suptitle("ladder_chain at the point-mass fidelity")
fig.tight_layout()
fig.savefig("pointmass_string.png", dpi=90)
print("wrote pointmass_string.png")
