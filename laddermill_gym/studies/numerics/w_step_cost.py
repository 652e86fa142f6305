"""Where a ROS34PW2 step's time goes, against an RK4 step: ``python -m laddermill_gym.studies.numerics.w_step_cost
SCENE``.

Times (CPU, one numba thread, the least of five repeats: other load only adds to it) per step of the compiled
ROS34PW2 and RK4 steppers from the scene's initial state, one right-hand side, and the three parts of a W step
that build its iteration matrix: the bodies' load Jacobian (finite differences of each wing's loads,
``kernels/rigid/body_jacobian.py``), the cable's stiffness and damping blocks (``kernels/rigid/cable_jacobian.py``)
and the block-tree factorisation (``kernels/rigid/blocks.py``). A Jacobian reused over steps (a W-method keeps its
order with any Jacobian) saves at most those three parts: the printed "W step without them" is that bound, in RK4
steps. Each part is timed through its own call from Python (about 10 us of dispatch, included: on a one-wing scene
that is most of a part's time, on the 101-wing scenes a tenth or less), so the bound is, if anything, generous.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def _least(f, reps: int, rounds: int = 5) -> float:
    """The least mean CPU time [s] of ``reps`` calls of ``f`` over ``rounds`` rounds (after one warm call)."""
    f()
    best = np.inf
    for _ in range(rounds):
        t0 = time.process_time()
        for _ in range(reps):
            f()
        best = min(best, (time.process_time() - t0) / reps)
    return best


def step_costs(scene: str, dt_w: float, dt_rk4: float, n_steps: int = 20) -> dict[str, float]:
    """CPU times [s] per call: "w_step", "rk4_step", "rhs", "body_jacobian", "cable_jacobian", "factor" on
    ``scene`` (W steps of ``dt_w`` [s], RK4 steps of ``dt_rk4`` [s], within RK4's stable step)."""
    import numba

    from laddermill_gym.kernels.integrate import rhs, rk4_advance
    from laddermill_gym.kernels.rigid.blocks import tree_factor
    from laddermill_gym.kernels.rigid.body_jacobian import add_body_jacobian
    from laddermill_gym.kernels.rigid.cable_jacobian import add_cable_stiffness
    from laddermill_gym.kernels.rigid.rosenbrock import ROS34PW2, w_advance
    from laddermill_gym.studies.numerics.scenes import build_simulator

    numba.set_num_threads(1)
    sim = build_simulator(scene, method="ros34pw2", dt=dt_w)
    M, W, lim, u = sim.model, sim.work, sim.limits, sim.controls.copy()
    x0 = sim.state.copy()
    out = {"w_step": _least(lambda: w_advance(0.0, x0.copy(), u, dt_w, n_steps, M, W, lim, ROS34PW2), 3) / n_steps,
           "rk4_step": _least(lambda: rk4_advance(0.0, x0.copy(), u, dt_rk4, n_steps, M, W, lim, None), 3) / n_steps}
    x, dx = x0.copy(), np.zeros_like(x0)
    w_advance(0.0, x, u, dt_w, 1, M, W, lim, ROS34PW2)  # fills the rotations and the factored blocks the parts use
    gh = ROS34PW2[0][0] * dt_w
    out["rhs"] = _least(lambda: rhs(0.0, x, u, dx, M, W), 50)
    out["body_jacobian"] = _least(lambda: add_body_jacobian(0.0, x, u, M, W, gh, gh * gh), 50)
    out["cable_jacobian"] = _least(lambda: add_cable_stiffness(0.0, x, M, W, gh, gh * gh), 50)
    out["factor"] = _least(lambda: tree_factor(W.Ds, W.Us, W.Yw, W.pivw, M.order, M.parent, M.bsz), 50)
    return out


def summary(scene: str, c: dict[str, float]) -> str:
    """One line: the costs [ms], the parts' shares of a W step and the bound of a reused Jacobian in RK4 steps."""
    w, r = c["w_step"], c["rk4_step"]
    parts = c["body_jacobian"] + c["cable_jacobian"] + c["factor"]
    return (f"{scene}: CPU per step ROS34PW2 {w * 1e3:.3f} ms, RK4 {r * 1e3:.3f} ms ({w / r:.2f} RK4 steps); one "
            f"right-hand side {c['rhs'] * 1e3:.3f} ms; body Jacobian {c['body_jacobian'] * 1e3:.3f} ms "
            f"({c['body_jacobian'] / w:.0%}), cable Jacobian {c['cable_jacobian'] * 1e3:.3f} ms "
            f"({c['cable_jacobian'] / w:.0%}), factorisation {c['factor'] * 1e3:.3f} ms ({c['factor'] / w:.0%}); "
            f"W step without them {(w - parts) / r:.2f} RK4 steps")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.numerics.w_step_cost", description=__doc__)
    p.add_argument("scene", nargs="+", help="scene names (3D rigid scenes: the W-methods need the block assembly)")
    p.add_argument("--dt-w", type=float, default=0.0667, help="ROS34PW2 step [s] (default 0.0667: a third of 0.2 s)")
    p.add_argument("--dt-rk4", type=float, default=0.01, help="RK4 step [s], within its stable step (default 0.01)")
    args = p.parse_args(argv)
    for name, v in (("--dt-w", args.dt_w), ("--dt-rk4", args.dt_rk4)):
        if not 0.0 < v <= 1.0:
            p.error(f"{name} = {v}: must be in (0, 1] s")
    for scene in args.scene:
        print(summary(scene, step_costs(scene, args.dt_w, args.dt_rk4)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
