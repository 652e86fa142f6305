"""Where one copy's control period goes in the single-craft envs' vector step (issue 32 point 2): ``python -m
laddermill_gym.studies.benchmarks.env_step_cost laddermill_gym/TetheredWing-v0 laddermill_gym/Rotorcraft-v0``;
the 101-wing chain's model on one W step: ``... laddermill_gym/LadderChain-v0 --physics-step ros34pw2 --copies 8``.

Each part of the compiled step is timed in a compiled loop over one copy of the env's own batch (its model, wind,
workspace and a state it reached under the zero action, a = 0), so no Python dispatch enters a part's time (the
older ``studies/numerics/w_step_cost.py`` calls each part from Python: about 10 us each, most of a one-wing part):

* the Rosenbrock-W step the env registers (ROS34PW2: one assembly, three right-hand sides, the body and cable
  Jacobians, one factorisation, four eliminations), as ``kernels/rigid/rosenbrock.w_advance`` runs it, and those
  parts on their own; "rest of the W step" is the step less them (stage sums, the mass-matrix products, the
  stage increments);
* the observation the step kernel writes after the step (``kernels/rigid/observe._observe_stepped``: the tensions
  and the observation rows);
* the whole step kernel per copy (the env's ``_kernel`` on all copies, one thread) and the whole vector
  ``step`` per copy: kernel less W step and observation is the kernel's own work (the wind's kinks, the copy's
  views) and what the parts, timed on one copy's state again and again, do not pay (caches and branch
  predictors over 512 different copies); step less kernel is the Python and numpy work (actions, rewards,
  terminations, infos), shared by all copies.

CPU time of one numba thread (``numba.set_num_threads(1)``), the least of ``--repeats`` rounds (other load only
adds). The figure a throughput target asks for follows: on two threads that split the copies perfectly, N env
steps/s need a copy-step of at most 2 / N s of one thread's time.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from numba import njit

from laddermill_gym.kernels.batch import copy_views
from laddermill_gym.kernels.dispatch import model_assemble, model_rhs
from laddermill_gym.kernels.rigid.blocks import copy_blocks, tree_factor, tree_solve_factored
from laddermill_gym.kernels.rigid.body_jacobian import add_body_jacobian
from laddermill_gym.kernels.rigid.cable_jacobian import add_cable_stiffness
from laddermill_gym.kernels.rigid.rosenbrock import w_advance
from laddermill_gym.studies.cpu_time import least_cpu

_FM = {"contract", "nsz", "arcp"}
#: the parts timed in compiled loops, in the order of the printed table
PARTS = ("w_step", "assembly", "rhs", "body_jacobian", "cable_jacobian", "factorisation", "elimination")


# One loop per part, on copy 0, restarting from the saved state x0 where the part changes the state. The bodies are
# inlined into two sets of loops, with the fastmath flags of the wing step kernels and without (the rotorcraft's):
# the step's callees are inlined into each loop as into the env's kernel, so each loop compiles them as it does.
# The W step is w_advance's one step (with its state check), the callee the env's kernel runs. w_step inlined into
# the same function as copy_views (both inline="always") gave wrong states, while w_step inlined into a function
# that takes the views as arguments (as w_advance does) gave the env's (2026-12-03): numba's inlining of the two
# together, not a path the envs take; tests/test_env_step_cost.py would catch it here.
@njit(cache=True, error_model="numpy", inline="always")
def _w_steps(n, t, x0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    Mb, Wb = copy_views(0, M, kind, vehicle, WB, AB)
    x = X[0]
    for _ in range(n):
        for i in range(x.size):
            x[i] = x0[i]
        w_advance(t, x, U[0], dt, 1, Mb, Wb, limits, tableau)


@njit(cache=True, error_model="numpy", inline="always")
def _parts(which, n, t, x0, bv0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    Mb, Wb = copy_views(0, M, kind, vehicle, WB, AB)
    x = X[0]
    for i in range(x.size):
        x[i] = x0[i]
    u = U[0]
    gh = tableau[0][0] * dt
    nb = Wb.bv.shape[0]
    for b in range(nb):  # the elimination restarts from these right-hand sides
        for i in range(6):
            bv0[b, i] = Wb.bv[b, i]
    for _ in range(n):
        if which == 1:
            model_assemble(Mb.kind, t, x, u, Wb.k5, Mb, Wb)
        elif which == 2:
            model_rhs(Mb.kind, t, x, u, Wb.k5, Mb, Wb)
        elif which == 3:
            add_body_jacobian(t, x, u, Mb, Wb, gh, gh * gh)
        elif which == 4:
            add_cable_stiffness(t, x, Mb, Wb, gh, gh * gh)
        elif which == 5:
            copy_blocks(Wb.D, Wb.U, Wb.Ds, Wb.Us, Mb.order, Mb.bsz)
            tree_factor(Wb.Ds, Wb.Us, Wb.Yw, Wb.pivw, Mb.order, Mb.parent, Mb.bsz)
        else:
            for b in range(nb):
                for i in range(6):
                    Wb.bv[b, i] = bv0[b, i]
            tree_solve_factored(Wb.Ds, Wb.Us, Wb.Yw, Wb.pivw, Wb.bv, Mb.order, Mb.parent, Mb.bsz)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _w_steps_fm(n, t, x0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    """``n`` W steps of copy 0 from x0 (wing kernels' flags)."""
    _w_steps(n, t, x0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau)


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def _parts_fm(which, n, t, x0, bv0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    """``n`` calls of part ``which`` (an index of :data:`PARTS` from 1) at x0 on copy 0, whose workspace a W
    step from x0 has just filled (rotations, blocks, factorisation); bv0 (blocks, 6) scratch; wing kernels'
    flags."""
    _parts(which, n, t, x0, bv0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau)


@njit(cache=True, error_model="numpy", _nrt=False, fastmath=False)
def _w_steps_plain(n, t, x0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    """:func:`_w_steps_fm` without fastmath (the rotorcraft's kernels' flags)."""
    _w_steps(n, t, x0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau)


@njit(cache=True, error_model="numpy", _nrt=False, fastmath=False)
def _parts_plain(which, n, t, x0, bv0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau):
    """:func:`_parts_fm` without fastmath (the rotorcraft's kernels' flags)."""
    _parts(which, n, t, x0, bv0, X, U, dt, M, kind, vehicle, WB, AB, limits, tableau)


def loops_for(kernel) -> tuple:
    """(W-step loop, parts loop) compiled with the fastmath flags of the env's step ``kernel`` (a numba
    dispatcher, or the task's ``CopyThreads`` around it): the wing kernels' or the rotorcraft's (none). The W-step
    loop takes (n, t [s], x0, X, U, dt [s], model, kind, vehicle, batched workspace, batched air, limits, tableau)
    and leaves in X[0] one W step from x0."""
    if getattr(kernel, "kernel", kernel).targetoptions.get("fastmath"):
        return _w_steps_fm, _parts_fm
    return _w_steps_plain, _parts_plain


def part_costs(env_id: str, n_copies: int = 512, periods: int = 40, loops: int = 5000,
               rounds: int = 5, physics_step: str | None = None) -> dict[str, float]:
    """CPU seconds of one thread per copy and control period of ``env_id``'s native vector env at ``n_copies``
    copies: each part of :data:`PARTS` per call (copy 0), "kernel" (the env's step kernel over all copies, per copy),
    "observe" (the same kernel observing without a step: the observation and the kernel's per-copy work) and "step"
    (the vector ``step``, per copy); "stages" is the W method's stage count. ``periods`` vector steps per round for
    the last three, ``loops`` calls per round for the parts; ``physics_step``: the env argument (None: the id's
    registered step; ``"ros34pw2"`` times a 101-wing env on one W step per period, the model's own cost of a
    right-hand side, a factorisation and an elimination). ValueError naming the env for one whose control period
    is not one W step."""
    import gymnasium as gym
    import numba

    numba.set_num_threads(1)
    kwargs = {} if physics_step is None else {"physics_step": physics_step}
    env = gym.make_vec(env_id, num_envs=n_copies, vectorization_mode="vector_entry_point", **kwargs)
    task = env.unwrapped.task
    b = task.batch
    if b.tableau is None or task.n_substeps != 1:
        env.close()
        raise ValueError(f"{env_id}: {task.n_substeps} {'RK4' if b.tableau is None else 'W'} step(s) per control "
                         "period; this study times the envs whose control period is one W step (TetheredWing-v0, "
                         "Rotorcraft-v0; another id with --physics-step ros34pw2)")
    action = np.zeros((n_copies, task.n_actions))
    env.reset(seed=0)
    kernel, captured, spent = task._kernel, [], [0.0]

    def timed(*args):
        captured[:] = [args]
        t0 = time.process_time()
        kernel(*args)
        spent[0] += time.process_time() - t0

    task._kernel = timed
    for _ in range(5):
        env.step(action)
    steps, kern = [], []
    for _ in range(rounds):
        spent[0] = 0.0
        t0 = time.process_time()
        for _ in range(periods):
            env.step(action)
        steps.append((time.process_time() - t0) / (periods * n_copies))
        kern.append(spent[0] / (periods * n_copies))
    task._kernel = kernel
    observe_args = list(captured[0])
    observe_args[4] = np.zeros_like(observe_args[4])  # nsteps 0: observe only

    def observe():
        for _ in range(periods):
            kernel(*observe_args)

    out = {"step": min(steps), "kernel": min(kern), "stages": float(b.tableau[4].size),
           "observe": least_cpu(observe, rounds) / (periods * n_copies)}
    w_steps, parts = loops_for(kernel)
    args = (float(b.t[0]), b.states[0].copy(), b.states, b.controls, b.settings.dt, *b.detached, b.work, b.air,
            b.limits, b.tableau)
    out["w_step"] = least_cpu(lambda: w_steps(loops, *args), rounds) / loops
    bv0 = np.empty_like(b.work.bv[0])  # scratch: the loops run without numba's runtime (no allocation, no reference
    # counting of the ~40 arrays each call passes: with it, the parts timed alone cost up to 20 % more)
    for which, name in enumerate(PARTS[1:], start=1):
        w_steps(1, *args)  # the part's workspace as a W step from x0 leaves it
        out[name] = least_cpu(lambda: parts(which, loops, args[0], args[1], bv0, *args[2:]), rounds) / loops
    env.close()
    return out


def table(env_id: str, c: dict[str, float], n_copies: int, target: float | None) -> str:
    """The printed breakdown [us per copy and control period] with each line's share of the vector step, the bound
    that the serial Python share puts on the speed-up on 16 threads (Amdahl: 1 / (s + (1 - s) / 16); memory
    bandwidth and the thread pool's own cost come on top), and the one-thread cost that ``target`` env steps/s on
    two perfectly shared threads would allow."""
    s = int(c["stages"])
    parts = {"assembly": c["assembly"], f"{s - 1} right-hand sides": (s - 1) * c["rhs"],
             "body Jacobian": c["body_jacobian"], "cable Jacobian": c["cable_jacobian"],
             "factorisation": c["factorisation"], f"{s} eliminations": s * c["elimination"]}
    rows = [("vector step, per copy", c["step"]), ("  step kernel", c["kernel"]), ("    W step", c["w_step"])]
    rows += [("      " + k, v) for k, v in parts.items()]
    rows += [("      rest of the W step", c["w_step"] - sum(parts.values())),
             ("    observation (kernel without a step)", c["observe"]),
             ("    rest of the kernel", c["kernel"] - c["w_step"] - c["observe"]),
             ("  Python and numpy", c["step"] - c["kernel"])]
    lines = [f"{env_id} at {n_copies} copies (CPU of one thread per copy and control period, least of the rounds):"]
    lines += [f"  {name:<42s} {v * 1e6:7.2f} us  {v / c['step']:6.1%}" for name, v in rows]
    lines.append(f"  one thread: {1.0 / c['step']:,.0f} env steps/s; two threads sharing perfectly: "
                 f"{2.0 / c['step']:,.0f}")
    py = (c["step"] - c["kernel"]) / c["step"]
    lines.append(f"  Python and numpy's {py:.1%} of the step (not parallel) bound the speed-up on 16 threads to "
                 f"{1.0 / (py + (1.0 - py) / 16.0):.1f}x (Amdahl; 12x needs at most 2.2 %)")
    if target:
        allow = 2.0 / target
        lines.append(f"  {target:,.0f} env steps/s on two threads needs at most {allow * 1e6:.2f} us per copy-step "
                     f"({allow / c['step']:.2f} of today's; the W step alone is {c['w_step'] / allow:.2f}x that)")
    return "\n".join(lines)


#: issue 32 point 2's targets at 512 copies on two threads [env steps/s]
TARGETS = {"laddermill_gym/TetheredWing-v0": 400_000.0, "laddermill_gym/Rotorcraft-v0": 150_000.0}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.benchmarks.env_step_cost",
                                description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("envs", nargs="+", help="env ids whose control period is one W step")
    p.add_argument("--copies", type=int, default=512, help="copies of the native vector env (default 512)")
    p.add_argument("--rounds", type=int, default=5, help="rounds; the least is kept (default 5)")
    p.add_argument("--physics-step", choices=("ros34pw2", "ros2"),
                   help="the env argument physics_step (default: the registered step), e.g. ros34pw2 for the chain")
    args = p.parse_args(argv)
    if args.copies < 1 or args.rounds < 1:
        p.error(f"--copies {args.copies}, --rounds {args.rounds}: both must be at least 1")
    for env_id in args.envs:
        try:
            c = part_costs(env_id, n_copies=args.copies, rounds=args.rounds, physics_step=args.physics_step)
        except ValueError as exc:
            p.error(str(exc))
        print(table(env_id, c, args.copies, TARGETS.get(env_id)), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
