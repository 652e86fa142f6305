"""The round-off floor of the golden runs, measured with the code of commit 16b454f against its own output: each run
of make_golden_16b454f.py again, its start with every entry moved by one ulp (relative 2^-52, a random sign per
entry), and the largest componentwise difference from golden_rk4_16b454f.npz, max |x - r| / max(|r|, 1).
At that commit (``git worktree add /tmp/old 16b454f``), from the repository root of this one:
``PYTHONPATH=/tmp/old python tests/data/ulp_floor_16b454f.py SEED`` (seeds 0, 1, 2 for the figures quoted in
tests/test_golden_trajectories.py). It imports the module paths of that commit, which later commits moved."""
import dataclasses, sys
import numpy as np
from laddermill_gym.craft import load_craft
from laddermill_gym import load_scene
from laddermill_gym.simulator import Simulator
GOLD = np.load("tests/data/golden_rk4_16b454f.npz")
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 0  # the perturbation's seed
rng = np.random.default_rng(seed)
def run(name, sim, steps, u=None):
    x0 = sim.state.copy()
    x0 = x0 * (1 + rng.choice([-1.0, 1.0], x0.shape) * 2.0 ** -52)
    sim.reset(state=x0)
    xs = [sim.state.copy()]
    for n in steps:
        sim.step(u, n_steps=n)
        xs.append(sim.state.copy())
    xs = np.array(xs); ref = GOLD[name]
    err = np.max(np.abs(xs - ref) / np.maximum(np.abs(ref), 1.0))
    print(f"{name:22s} seed {seed}: largest difference from golden {err:.2e}", flush=True)
sc = load_scene("tethered_wing")
w = sc.assembly.wind.with_modulation(0.0, 0.5, np.array([1.0, 1.0, 1.0, 1.1, 1.1]), np.array([0, 0, 0.01, 0.01, 0.01]))
s0 = sc.simulator()
sim = Simulator(dataclasses.replace(sc.assembly, wind=w), s0.initial_state, sc.settings, s0.initial_controls)
u = sim.controls.copy(); u[1] = 0.01; u[2] = -0.005
run("tethered_wing", sim, [200, 200, 200], u)
run("tethered_wing_plain", load_scene("tethered_wing", sag=False, cable_aero=False, elements_per_piece=1).simulator(), [100, 100])
run("tethered_wing_2d", load_scene("tethered_wing", dimension=2).simulator(), [200, 200])
sc = load_scene("ladder_chain")
asm = dataclasses.replace(sc.assembly, wind=sc.assembly.wind.with_modulation(0.0, 0.25, np.array([1.0, 1.0, 1.05]), np.array([0.0, 0.01, 0.01])))
s0 = sc.simulator()
run("ladder_chain", Simulator(asm, s0.initial_state, sc.settings, s0.initial_controls), [20, 20])
run("ladder_chain_2d", load_scene("ladder_chain", dimension=2).simulator(), [40, 40])
sim = load_craft("roberts_flying_model").simulator()
u = sim.controls.copy(); u[1] = 0.002
run("rotorcraft", sim, [250, 250], u)
