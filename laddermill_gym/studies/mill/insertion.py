"""What each wing-insertion rule (``station.insertion``: paper | cable) does to the first element's tension.

Run ``python -m laddermill_gym.studies.mill.insertion [--speed 0.5] [--dimension 2]``. The 11-wing mill is run at
5 m/s to near its first transfer and slowed to ``--speed`` (so that the dip stays below the tension), then each
rule steps through the transfer from the same state at 0.1 ms. Printed per rule: the velocity mismatch dv [m/s]
of the inserted wing along the first element (the cable material's speed at the ground point, V_c l / l1, less the
wing's attachment velocity along it), the jump of the first element's tension at the insertion and its dip over
the next 30 ms [kN], beside the closed forms of a spring-mass hit: the Voigt jump DA dv / l1 (plus one 0.1 ms step
of the spring) and the spring's dip k1 dv / omega, omega = sqrt((k1 + k2) / m), a quarter period later
(docs/moving_cable.md, "Transfers").
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

from laddermill_gym import Simulator, load_scene
from laddermill_gym.kernels.contract import SX_MOVED
from laddermill_gym.model.station import INSERTIONS

DT = 1e-4  # [s] the step through the transfer (the spring-mass quarter period is about 6 ms)


def before_transfer(dimension: int, speed: float, n_wings: int = 11):
    """(assembly, settings, controls, (state, time) one scene step before the first transfer): V_c ramped to 5 m/s
    in 5 s, held to 10 s, slowed to ``speed`` [m/s] at 13 s (chosen: the first transfer then comes at about 61 s)."""
    sc = load_scene("laddermill", dimension=dimension, n_wings=n_wings)
    st = dataclasses.replace(sc.assembly.station, speed_times=(0.0, 5.0, 10.0, 13.0),
                             speed_values=(0.0, 5.0, 5.0, speed))
    asm = dataclasses.replace(sc.assembly, station=st)
    x0, u0 = sc.initial_state()
    sim = Simulator(asm, x0, sc.settings, u0)
    prev = (sim.state.copy(), sim.t)
    while sim.transfers() == 0:
        prev = (sim.state.copy(), sim.t)
        sim.step()
    return asm, sc.settings, u0, prev


def through_transfer(before, rule: str, n_after: int = 300):
    """Step with ``rule`` at :data:`DT` from the state before the transfer: (element 0's tension just before [N],
    a simulator at the state right after the transfer, element 0's tension right after and over the next
    ``n_after`` steps [N])."""
    asm, settings, u0, (x, t) = before
    a = dataclasses.replace(asm, station=dataclasses.replace(asm.station, insertion=rule))
    sim = Simulator(a, x, dataclasses.replace(settings, dt=DT), u0)
    sim.reset(x, t=t, controls=u0)
    while True:
        t_before = sim.tensions()[0]
        sim.step()
        if sim.transfers() == 1:
            break
    after = Simulator(a, sim.state, sim.settings, u0)
    after.reset(sim.state, t=sim.t, controls=u0)
    ten = [sim.tensions()[0]]
    for _ in range(n_after):
        sim.step()
        ten.append(sim.tensions()[0])
    return t_before, after, np.array(ten)


def mismatch(sim: Simulator) -> tuple[float, float]:
    """(dv [m/s]: the cable material's speed at the ground point along the first element less the new wing's
    attachment velocity along it; l1 [m], the first element's unstretched length) of the state after a transfer."""
    a, st = sim.assembly, sim.assembly.station
    g = a.fixed_points[a.elements.end_index[0, 0]]
    R = sim.wing_rotations()[0]
    att = sim.wing_positions()[0] + R @ a.elements.attach[0, 1]
    v = R @ sim.wing_velocities()[0]  # the new wing does not rotate: this is its attachment's velocity
    e = (att - g) / np.linalg.norm(att - g)
    l1 = st.first_fraction * st.piece_length + sim.state[a.body_state_size + SX_MOVED]
    return sim.cable_speed() * np.linalg.norm(att - g) / l1 - float(v @ e), l1


def spring_mass(asm, dv: float, l1: float) -> tuple[float, float, float]:
    """Closed forms of a mismatch dv [m/s] on a first element of l1 [m]: (the Voigt jump plus one step of the
    spring [N], the spring's dip k1 dv / omega [N], a quarter period [s])."""
    el = asm.elements
    k1, k2 = el.EA[0] / l1, el.EA[1] / el.l0[1]
    omega = math.sqrt((k1 + k2) / asm.wing_types[0].mass)
    return el.DA[0] * dv / l1 + k1 * dv * DT, k1 * dv / omega, 0.5 * math.pi / omega


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--speed", type=float, default=0.5, help="cable speed at the transfer [m/s] (default 0.5)")
    ap.add_argument("--dimension", type=int, choices=(2, 3), default=2, help="in plane (2, default) or 3D")
    args = ap.parse_args(argv)
    if not 0 < args.speed <= 10:
        ap.error(f"--speed = {args.speed!r}: must be in (0, 10] m/s")
    before = before_transfer(args.dimension, args.speed)
    print(f"11-wing mill, {args.dimension}D, V_c = {args.speed:g} m/s at the first transfer (t = "
          f"{before[3][1]:.2f} s)")
    for rule in INSERTIONS:
        t0, after, ten = through_transfer(before, rule)
        dv, l1 = mismatch(after)
        jump, dip, quarter = spring_mass(before[0], dv, l1)
        print(f"insertion {rule}: dv = {dv:.3g} m/s on l1 = {l1:.3g} m; element 0 tension {t0 / 1e3:.2f} kN before, "
              f"jump {(t0 - ten[0]) / 1e3:.3g} kN (Voigt + one step: {jump / 1e3:.3g} kN), dip "
              f"{(t0 - ten.min()) / 1e3:.3g} kN at {np.argmin(ten) * DT * 1e3:.1f} ms (spring: "
              f"{dip / 1e3:.3g} kN at {quarter * 1e3:.1f} ms), largest {ten.max() / 1e3:.3g} kN in "
              f"{len(ten) * DT * 1e3:.0f} ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
