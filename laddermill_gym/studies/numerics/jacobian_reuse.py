"""What keeping a W-method's iteration matrix over steps saves and costs on an env's scene:
``python -m laddermill_gym.studies.numerics.jacobian_reuse --every 1 2 4 8``.

For each k (``IntegratorSettings.jacobian_every``; ``kernels/rigid/rosenbrock.py`` ``with_jacobian_reuse``) it
prints the CPU time of one ROS34PW2 step of the env's physics step (one copy, one numba thread, in-kernel loops
of ``--steps`` steps, the least of seven repeats: other load only adds to it; a timed run whose wing leaves the
flight envelope before its last step raises, since a failed kernel returns early and its time per requested step
would read low: with the default offset the wing flies about 130 s, and 4000 steps of 50 ms read 4.6 against 7.1
us per step flown on 2026-11-30) and the largest wing-position error
of a ``--time`` s run at that step against classic RK4 at a step ``--fine`` times smaller (its own error printed
beside, from a run at twice that), from the env's trim with every control moved by ``--offset`` (a moving state).
"""

from __future__ import annotations

import argparse

import numpy as np

from laddermill_gym.studies.cpu_time import least_cpu


def wing_positions(sim_args, method: str, dt: float, every: int, t_end: float, sample: float) -> np.ndarray:
    """Wing positions (n_samples, 3) [m] every ``sample`` s of a run of ``t_end`` s."""
    from laddermill_gym.kernels.integrate import rk4_advance
    from laddermill_gym.kernels.rigid.rosenbrock import ROS34PW2, w_advance, with_jacobian_reuse

    M, W, lim, u, x0 = sim_args
    tab = with_jacobian_reuse(ROS34PW2, every)
    W.wjac[0] = 0.0
    x, t, out = x0.copy(), 0.0, []
    n = int(round(sample / dt))
    for _ in range(int(round(t_end / sample))):
        st = (w_advance(t, x, u, dt, n, M, W, lim, tab) if method == "w"
              else rk4_advance(t, x, u, dt, n, M, W, lim, None))
        if st[0] != 0:
            raise RuntimeError(f"{method} at {dt:g} s failed with status {st[0]} after t = {t:g} s")
        t += n * dt
        out.append(x[:3].copy())
    return np.array(out)


def reuse_table(env_id: str, every, steps: int, t_end: float, fine: int, offset: float) -> list[dict]:
    """One row per k: CPU per step [s] and the largest position error [m] against the fine RK4 run."""
    import gymnasium as gym
    import numba

    import laddermill_gym  # noqa: F401 (registers the ids)
    from laddermill_gym.kernels.rigid.rosenbrock import ROS34PW2, w_advance, with_jacobian_reuse
    from laddermill_gym.sim.simulator import Simulator

    numba.set_num_threads(1)
    task = gym.make(env_id).unwrapped.task
    dt = task.scene.settings.dt
    sim = Simulator(task.scene.assembly, task.x_trim, task.scene.settings, task.u_trim)
    args = (sim.model, sim.work, sim.limits, sim.controls + offset, sim.state.copy())
    ref = wing_positions(args, "rk4", dt / fine, 1, t_end, 0.5)
    ref2 = wing_positions(args, "rk4", dt / (2 * fine), 1, t_end, 0.5)
    rows = []
    for k in every:
        M, W, lim, u, x0 = args
        tab = with_jacobian_reuse(ROS34PW2, k)

        def run(tab=tab, k=k):
            W.wjac[0] = 0.0
            status, done = w_advance(0.0, x0.copy(), u, dt, steps, M, W, lim, tab)
            if status != 0 or done != steps:
                raise RuntimeError(f"jacobian_every {k}: the timed run failed with status {status} after {done} of "
                                   f"{steps} steps ({done * dt:g} s): time fewer --steps")

        err = np.abs(wing_positions(args, "w", dt, k, t_end, 0.5) - ref2).max()
        rows.append({"every": k, "cpu_per_step": least_cpu(run) / steps, "error": float(err),
                     "reference_error": float(np.abs(ref - ref2).max()), "dt": dt})
    return rows


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.numerics.jacobian_reuse", description=__doc__)
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0", help="a wing env id on a W-method")
    p.add_argument("--every", type=int, nargs="+", default=[1, 2, 4, 8], help="steps per iteration matrix")
    p.add_argument("--steps", type=int, default=1000, help="steps per timed kernel call (flown in full)")
    p.add_argument("--time", type=float, default=60.0, help="length of the accuracy run [s]")
    p.add_argument("--fine", type=int, default=64, help="RK4 reference step = the env's step / FINE")
    p.add_argument("--offset", type=float, default=0.01, help="added to every trim control")
    a = p.parse_args(argv)
    if min(a.every) < 1 or a.steps < 1 or not a.time > 0 or a.fine < 1:
        p.error(f"--every {a.every} (>= 1), --steps {a.steps} (>= 1), --time {a.time} (> 0 s), --fine {a.fine} "
                "(>= 1): out of range")
    for r in reuse_table(a.env, a.every, a.steps, a.time, a.fine, a.offset):
        print(f"jacobian_every {r['every']}: {r['cpu_per_step'] * 1e6:.2f} us CPU per {r['dt']:g} s step; largest "
              f"position error over {a.time:g} s {r['error']:.3g} m (RK4 reference's own {r['reference_error']:.2g} m)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
