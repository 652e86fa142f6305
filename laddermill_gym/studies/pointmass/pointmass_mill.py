"""The laddermill's moving cable at the point-mass fidelity against the rigid mill (docs/pointmass.md, "The moving
cable"): real-time factor, periodic motion, mean power and tensions.

``python -m laddermill_gym.studies.pointmass.pointmass_mill [--element-lengths 70 1] [--threads 1] [--timing 100]``

For every element length: the rigid mill's periodic operating point mapped to point masses (``mill_simulator``'s
default start; the rigid run is done once), ``--timing`` seconds of simulation timed (real-time factor, the wall
time of the steps only), then the run to the point-mass mill's own periodic motion (``run_pointmass_periodic``),
and one line per fidelity: mean power, the first and last elements' mean tension, the smallest mean tension below
a kite and where.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from laddermill_gym.ladder.pointmass_mill import mill_simulator, rigid_periodic, run_pointmass_periodic
from laddermill_gym.ladder.scene import load_scene


def measure(element_length: float, threads: int | None, timing: float, max_time: float) -> dict:
    """Real-time factor and periodic motion of the point-mass mill at one element length [m]."""
    sc = load_scene("laddermill", fidelity="pointmass", element_length=element_length)
    sim = mill_simulator(sc)
    if threads is not None:
        sim.threads = threads
    sim.advance(10 * sim.dt)  # compile
    t0 = time.perf_counter()
    sim.advance(timing)
    wall = time.perf_counter() - t0
    res = run_pointmass_periodic(sim, max_time=max_time)
    return {"element_length": element_length, "nodes": sc.string.n_nodes, "dt": sim.dt, "threads": sim.threads,
            "real_time_factor": timing / wall, "step_ms": 1e3 * wall / round(timing / sim.dt), "result": res}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--element-lengths", type=float, nargs="+", default=[70.0, 1.0], help="[m]")
    ap.add_argument("--threads", type=int, default=1, help="numba threads of the string's loops (0: numba's)")
    ap.add_argument("--timing", type=float, default=100.0, help="simulated seconds timed [s]")
    ap.add_argument("--max-time", type=float, default=3000.0, help="longest periodic search [s]")
    a = ap.parse_args(argv)
    sc = load_scene("laddermill")
    _, t_rigid, rigid = rigid_periodic(str(sc.file), sc.assembly.n_wings)
    k = int(np.argmin(rigid.tension_mean_N))
    print(f"rigid (one element per piece, RK4 dt {sc.settings.dt} s): periodic at t = {rigid.t_s:.0f} s, mean power "
          f"{rigid.mean_power_W / 1e3:.1f} kW, first element {rigid.tension_mean_N[0] / 1e3:.1f} kN, last "
          f"{rigid.tension_mean_N[-1] / 1e3:.1f} kN, smallest mean tension {rigid.tension_mean_N[k] / 1e3:.1f} kN "
          f"(element {k})")
    for el in a.element_lengths:
        m = measure(el, a.threads or None, a.timing, a.max_time)
        r = m["result"]
        print(f"point mass l_e = {el:g} m ({m['nodes']} nodes, implicit dt {m['dt']} s, {m['threads']} thread(s)): "
              f"{m['real_time_factor']:.1f}x real time ({m['step_ms']:.3f} ms per step); {r.summary()}")


if __name__ == "__main__":
    main()
