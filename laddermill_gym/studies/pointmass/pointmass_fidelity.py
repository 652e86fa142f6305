"""Between fidelities: the static shape and the tension along the cable of ``ladder_chain`` in the rigid
fidelity (Meijaard: rigid wings, one sag-corrected truss element per 70 m piece) and in the point-mass fidelity
(Podgaets: point masses at the wings' CG with the rigid equilibrium's attitude commanded, the cable an elastic
string of ``element_length`` elements).
``python -m laddermill_gym.studies.pointmass.pointmass_fidelity [--element-length M]``.

The point-mass equilibrium is found from the rigid one by kinetic relaxation: implicit steps of a long dt with
the velocities zeroed after each (a Newton-like iteration on the string's stiffness), until the largest node
displacement per iteration is below ``tol``.
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

from laddermill_gym.kernels.contract import CTRL_ELEVATOR, N_CONTROLS
from laddermill_gym.ladder.fidelity import rigid_static
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.params import AERO_INDEX


def pointmass_static(pm, x0, u, dt=1.0, tol=1e-6, max_iter=2000):
    """Static equilibrium of a point-mass scene by kinetic relaxation from x0; returns (simulator, iterations)."""
    sim = pm.simulator(x0, u, dt=dt)
    for it in range(max_iter):
        before = sim.positions.copy()
        sim.step(1)
        sim.velocities[:] = 0.0
        if np.abs(sim.positions - before).max() < tol:
            return sim, it + 1
    raise RuntimeError(f"no static equilibrium after {max_iter} relaxation steps")


def compare(element_length: float = 1.0) -> dict:
    """Kite positions and piece tensions of both fidelities at the same trim (see the module docstring)."""
    pm = load_scene("ladder_chain", fidelity="pointmass", element_length=element_length)
    sim_r, rigid = rigid_static(pm)
    x0, u = pm.initial_state()
    sim_p, iters = pointmass_static(pm, x0, u)
    kn = pm.string.kite_nodes
    per = int(kn[0] + 1)
    dpos = sim_p.positions[kn] - sim_r.wing_positions()
    t_r = sim_r.tensions()  # one element per piece
    t_p_all = sim_p.tensions(damped=False)
    t_p = t_p_all[per // 2::per][: t_r.size]  # the element at each piece's middle
    # the elevator's share of the rigid wing's lift: dC_L = C_Lde(alpha) * elevator, which the point mass lacks
    wt = rigid.assembly.wing_types[0]
    tab = wt.aero
    alpha = sim_r.wing_euler()[:, 1]  # at rest in a level wind the pitch is the angle of attack
    elev = sim_r.controls[CTRL_ELEVATOR::N_CONTROLS]
    cl = np.interp(alpha, tab.alpha, tab.values[:, AERO_INDEX["CL"]])
    dcl = np.interp(alpha, tab.alpha, tab.values[:, AERO_INDEX["CLde"]]) * elev
    # the same lift: each kite pitched to the alpha where its C_L equals the rigid wing's C_L with the elevator
    grid = np.linspace(np.radians(-10.0), np.radians(18.0), 2801)  # the table's rising branch [rad]
    cl_grid = np.interp(grid, tab.alpha, tab.values[:, AERO_INDEX["CL"]])
    u_match = u.copy()
    u_match[1::3] = np.interp(cl + dcl, cl_grid, grid)
    sim_m, _ = pointmass_static(pm, sim_p.x.copy(), u_match)
    t_m = sim_m.tensions(damped=False)[per // 2::per][: t_r.size]
    dpos_m = sim_m.positions[kn] - sim_r.wing_positions()
    return {"element_length": element_length, "iterations": iters,
            "matched_offset_max_m": float(np.abs(dpos_m).max()), "tension_matched_N": t_m,
            "matched_rel_diff_first_last": (float(t_m[0] / t_r[0] - 1), float(t_m[-1] / t_r[-1] - 1)),
            "kite_offset_max_m": float(np.abs(dpos).max()),
            "kite_offset_rms_m": float(np.sqrt((dpos ** 2).sum(1).mean())),
            "top_height_rigid_m": float(-sim_r.wing_positions()[:, 2].min()),
            "top_height_pointmass_m": float(-sim_p.positions[kn, 2].min()),
            "tension_rigid_N": t_r, "tension_pointmass_N": t_p,
            "tension_rel_diff_max": float(np.max(np.abs(t_p - t_r) / t_r)),
            "cl_rigid_tail_share": dcl / (cl + dcl), "elevator_rad": elev}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.pointmass.pointmass_fidelity",
                                description=__doc__)
    p.add_argument("--element-length", type=float, default=1.0, help="point-mass string element length [m]")
    a = p.parse_args(sys.argv[1:] if argv is None else argv)
    r = compare(a.element_length)
    tr, tp = r["tension_rigid_N"], r["tension_pointmass_N"]
    print(f"ladder_chain, point-mass string at {r['element_length']} m ({r['iterations']} relaxation steps)")
    print(f"kite positions: largest offset {r['kite_offset_max_m']:.2f} m, RMS {r['kite_offset_rms_m']:.2f} m; "
          f"top height rigid {r['top_height_rigid_m']:.1f} m, point mass {r['top_height_pointmass_m']:.1f} m")
    print(f"tension: first piece rigid {tr[0] / 1e3:.1f} kN, point mass {tp[0] / 1e3:.1f} kN; last piece "
          f"{tr[-1] / 1e3:.1f} / {tp[-1] / 1e3:.1f} kN; smallest {tr.min() / 1e3:.1f} / {tp.min() / 1e3:.1f} kN; "
          f"largest relative difference {100 * r['tension_rel_diff_max']:.1f} %")
    tm = r["tension_matched_N"]
    print(f"same lift (each kite pitched to the rigid wing's C_L with its elevator): first piece {tm[0] / 1e3:.1f} kN, "
          f"last {tm[-1] / 1e3:.1f} kN (relative {100 * r['matched_rel_diff_first_last'][0]:+.2f} %, "
          f"{100 * r['matched_rel_diff_first_last'][1]:+.2f} %), largest kite offset {r['matched_offset_max_m']:.2f} m")
    share = r["cl_rigid_tail_share"]
    print(f"elevator's share of the rigid wings' C_L (absent in the point mass): ascending "
          f"{100 * share[0]:.1f} %, descending {100 * share[-1]:.1f} %")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
