"""The mill LQR's closed loop just after a transfer, control step by control step.

``design_mill_lqr`` checks its gain at a few phases of the orbit (8 by default, s / l0 = j / 8) and composes the
period's transition matrix from those frozen models. Just after a transfer the newly inserted slot's wing changes
fast (its tether element is short and its attitude is its neighbour's), which those phases do not sample. This study
linearises the orbit at every control step of the period's first ``steps`` steps (the simulator's own orbit, steady
air, from the operating point just after a transfer) and prints, per step, the cable phase, the open-loop lateral
model's largest growth rate [1/s] and the slot whose own 6 x 6 block has it, and the frozen closed loop's largest
|z|; then the period's transition matrix with those per-step models over the first ``steps`` steps and
``n_phases`` frozen phases after them, its spectral radius with the transfer (Floquet), against the design's own.

    python -m laddermill_gym.studies.mill.transfer_transient --config configs/agents/lqr_laddermill.yaml

The models, the gain, the ZOH and the transfer's Jacobian are those of ``control/mill_lqr.py``; only the sampling
differs. About 3 minutes on one core (the operating point, the design, and some 100 linearisations of 606 lateral
states).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.control.lqr import full_gain
from laddermill_gym.control.lqr_config import load_lqr_config
from laddermill_gym.control.mill_lqr import design_mill_lqr, mill_lateral_model, orbit_states, transfer_jacobian
from laddermill_gym.kernels.contract import SX_MOVED

__all__ = ["transfer_transient", "main"]

_NLAT = 6  # lateral states per slot (y, vy, phi, psi, p, r)


def _closed_loop(A: np.ndarray, B: np.ndarray, K: np.ndarray, dt: float) -> np.ndarray:
    """Ad - Bd K of the ZOH at dt [s] (python-control's ``c2d``, as the design's check)."""
    import control

    sysd = control.c2d(control.ss(A, B, np.eye(A.shape[0]), np.zeros(B.shape)), dt, "zoh")
    return np.asarray(sysd.A) - np.asarray(sysd.B) @ K


def _worst_block(A: np.ndarray) -> tuple[float, int]:
    """(largest real part [1/s] of any slot's own 6 x 6 block, that slot)."""
    n = A.shape[0] // _NLAT
    g = [float(np.max(np.linalg.eigvals(A[_NLAT * k:_NLAT * (k + 1), _NLAT * k:_NLAT * (k + 1)]).real))
         for k in range(n)]
    return max(g), int(np.argmax(g))


def transfer_transient(config: str = "configs/agents/lqr_laddermill.yaml", steps: int = 70, n_phases: int = 40,
                       progress=print) -> dict:
    """The per-step check of the mill LQR of ``config`` over the period's first ``steps`` control steps after a
    transfer, and the period's transition matrix with them. Returns ``phase`` (steps,) [s / l0], ``growth`` (steps,)
    [1/s] (the whole lateral model's largest real part), ``block_growth`` and ``block_slot`` (steps,) (the largest
    of the slots' own blocks and its slot), ``frozen`` (steps,) (largest |z| of the frozen closed loop),
    ``transient_norm`` (the 2-norm of the first ``steps`` steps' transition matrix), ``monodromy`` (its radius with
    the transfer), ``design_monodromy`` and ``design_frozen`` (the design's own, at its 8 phases)."""
    from laddermill_gym.atmosphere.field import WindField
    from laddermill_gym.envs.laddermill.task import MillTask

    cfg = load_lqr_config(config)
    task = MillTask(1, scene=cfg.scene, scene_options={"elements_per_piece": cfg.elements_per_piece},
                    control_dt=cfg.control_period)
    d = design_mill_lqr(cfg, task, progress=progress)
    K, dt, u = full_gain(d.gains), cfg.control_period, np.array(task.u_op)
    sim = task.simulator(0)
    sim.set_wind(WindField())
    sim.reset(state=np.array(task.op.state), t=0.0, controls=u)
    lp = sim.assembly.station.piece_length
    n_period = int(round(lp / task.op.cable_speed / dt))
    if not 1 <= steps < n_period:
        raise ValueError(f"steps = {steps}: must lie in 1 .. {n_period - 1} (the period's control steps)")
    sub = int(round(dt / sim.settings.dt))
    moved = sim.assembly.body_state_size + SX_MOVED  # the cable's moved length s [m] among the station's states
    out = {k: np.empty(steps) for k in ("phase", "growth", "block_growth", "frozen")}
    out["block_slot"] = np.empty(steps, dtype=np.int64)
    phi = np.eye(K.shape[1])
    progress(f"linearising at each of the first {steps} control steps after a transfer")
    for k in range(steps):
        A, B = mill_lateral_model(sim, sim.state, u)
        M = _closed_loop(A, B, K, dt)
        out["phase"][k] = sim.state[moved] / lp
        out["growth"][k] = float(np.max(np.linalg.eigvals(A).real))
        out["block_growth"][k], out["block_slot"][k] = _worst_block(A)
        out["frozen"][k] = float(np.max(np.abs(np.linalg.eigvals(M))))
        phi = M @ phi
        sim.step(n_steps=sub)
    out["transient_norm"] = float(np.linalg.norm(phi, 2))
    progress(f"the rest of the period at {n_phases} frozen phases")
    sim.reset(state=np.array(task.op.state), t=0.0, controls=u)
    states, before = orbit_states(sim, n_phases)
    for j, x in enumerate(states):
        lo, hi = round(j * n_period / n_phases), round((j + 1) * n_period / n_phases)
        if hi > max(lo, steps):
            phi = np.linalg.matrix_power(_closed_loop(*mill_lateral_model(sim, x, u), K, dt),
                                         hi - max(lo, steps)) @ phi
    out["monodromy"] = float(np.max(np.abs(np.linalg.eigvals(transfer_jacobian(sim, before) @ phi))))
    out["design_monodromy"], out["design_frozen"] = d.monodromy_radius, d.frozen_radius
    return out


def main(argv: list[str] | None = None) -> int:
    from laddermill_gym.studies.commands import Parser, check_number

    p = Parser(prog="python -m laddermill_gym.studies.mill.transfer_transient", description=__doc__.split("\n\n")[0])
    p.add_argument("--config", default="configs/agents/lqr_laddermill.yaml", help="a mill LQR config")
    p.add_argument("--steps", type=int, default=70, help="control steps after a transfer, each linearised [-]")
    p.add_argument("--phases", type=int, default=40, help="frozen phases for the rest of the period [-]")
    a = p.parse_args(argv)
    check_number("--steps", a.steps, low=1, high=100000, integer=True, strict=False)
    check_number("--phases", a.phases, low=1, high=1000, integer=True, strict=False)
    r = transfer_transient(a.config, a.steps, a.phases)
    print("  step   s/l0    open-loop growth [1/s]   worst slot block [1/s] (slot)   frozen closed loop max |z|")
    for k in range(a.steps):
        print(f"  {k:4d}  {r['phase'][k]:6.4f}   {r['growth'][k]:22.3f}   {r['block_growth'][k]:15.3f} "
              f"({r['block_slot'][k]:3d})   {r['frozen'][k]:26.4f}")
    above = np.flatnonzero(r["frozen"] >= 1.0)
    print(f"frozen closed loop max |z| >= 1 at {above.size} of the first {a.steps} steps"
          + (f" (steps {above[0]} to {above[-1]}), largest {r['frozen'].max():.4f}" if above.size else ""))
    print(f"the first {a.steps} steps' transition matrix: 2-norm {r['transient_norm']:.3g}")
    print(f"the period's transition matrix with the transfer, these {a.steps} per-step models and {a.phases} phases: "
          f"spectral radius {r['monodromy']:.3g} (the design's, at its {r['design_frozen'].size} phases: "
          f"{r['design_monodromy']:.3g})")
    return 0


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("transfer_transient", main))
