"""Golden RK4 trajectories, produced ONCE by the code at commit 16b454f (before the architecture change of
issue 11) with `python tests/data/make_golden_16b454f.py` from the repository root. Kept as the record of how
golden_rk4_16b454f.npz was made; it imports the module paths of that commit, which later commits moved."""
import numpy as np
from laddermill_gym.craft import load_craft

from laddermill_gym import load_scene

out = {}
def run(name, sim, steps, u=None):
    xs = [sim.state.copy()]
    for _ in range(len(steps)):
        sim.step(u, n_steps=steps[_])
        xs.append(sim.state.copy())
    out[name] = np.array(xs)
    print(name, out[name].shape, sim.t)

# tethered wing, direction step through the wind modulation
sc = load_scene("tethered_wing")
w = sc.assembly.wind.with_modulation(0.0, 0.5, np.array([1.0, 1.0, 1.0, 1.1, 1.1]), np.array([0, 0, 0.01, 0.01, 0.01]))
import dataclasses

asm = dataclasses.replace(sc.assembly, wind=w)
from laddermill_gym.simulator import Simulator

s0 = sc.simulator()
sim = Simulator(asm, s0.initial_state, sc.settings, s0.initial_controls)
u = sim.controls.copy(); u[1] = 0.01; u[2] = -0.005
run("tethered_wing", sim, [200, 200, 200], u)
# tethered wing, no sag, no cable aero, one element per piece
sim = load_scene("tethered_wing", sag=False, cable_aero=False, elements_per_piece=1).simulator()
run("tethered_wing_plain", sim, [100, 100])
# tethered wing in-plane
sim = load_scene("tethered_wing", dimension=2).simulator()
run("tethered_wing_2d", sim, [200, 200])
# ladder chain
sc = load_scene("ladder_chain")
asm = dataclasses.replace(sc.assembly, wind=sc.assembly.wind.with_modulation(0.0, 0.25, np.array([1.0, 1.0, 1.05]), np.array([0.0, 0.01, 0.01])))
s0 = sc.simulator()
sim = Simulator(asm, s0.initial_state, sc.settings, s0.initial_controls)
run("ladder_chain", sim, [20, 20])
sim = load_scene("ladder_chain", dimension=2).simulator()
run("ladder_chain_2d", sim, [40, 40])
# rotorcraft flying model
craft = load_craft("roberts_flying_model")
sim = craft.simulator()
u = sim.controls.copy(); u[1] = 0.002
run("rotorcraft", sim, [250, 250], u)
np.savez_compressed("tests/data/golden_rk4_16b454f.npz", **out)
