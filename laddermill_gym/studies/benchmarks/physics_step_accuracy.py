"""How far an env's trajectory moves when its physics step changes (issue 32 point 3): one copy of an env id over
a short episode of seeded actions (the open-loop action plus uniform noise, the same for every step), its wings'
CG and cable nodes' positions after every control period, against RK4 at a quarter of the scene's RK4 step
(``REGISTERED_DT``: 3.125 ms for the chains and TetheredWing-v1, 2.5 ms for the mills; the reference). Prints the extent
(the largest distance of a point from the origin over the reference run) and, per physics step, the largest position
error [m], as a share of the extent, and its CPU time and rate on this process's
thread (one copy, so one thread). A label ``METHOD:K`` (``ros2t:8``) keeps the W-method's iteration matrix for K
steps (the env argument ``jacobian_every``; not ``whip_spectrum --methods``' METHOD:DT, a step size).
tests/test_fast_physics_step.py holds the 1e-3 bound for ``physics_step="ros34pw2"`` and for ``"ros2"`` with
``jacobian_every=4``.

Command: ``python -m laddermill_gym.studies.benchmarks.physics_step_accuracy laddermill_gym/LadderChain-v0
--time 10 --steps ros34pw2 ros2`` (seconds per run; LadderMill-v2's operating point first, 100-140 s).
``--controller SPEC`` (a harness controller: ``lqr``, ``lqr:PATH``, a run folder) runs it closed loop instead (seed
0, the paper's 0.01 rad direction step at 1 s, ``--time`` seconds): per physics step the episode's length, mean
power and largest lateral offset, and their differences from the registered step's (:func:`closed_loop`).
"""

from __future__ import annotations

import argparse
import math
import time
import warnings

import gymnasium as gym
import numpy as np

import laddermill_gym.envs  # noqa: F401 (registers the ids)
from laddermill_gym.control.factory import make_controller
from laddermill_gym.envs.physics_step import check_physics_step, jacobian_settings
from laddermill_gym.kernels.contract import B3_POS, B3_SIZE, N3_POS, N3_SIZE
from laddermill_gym.sim.simulator import IntegratorSettings

#: amplitude [-] of the uniform noise added to the open-loop action every control period (seeded; the mill's
#: random actions at full amplitude end a median episode at 17.6 s, docs of LadderMill-v2)
ACTION_NOISE = 0.3
#: the RK4 steps [s] of the 101-wing envs' scenes (configs/scenes/ladder_chain.yaml: RK4 12.5 ms, laddermill*.yaml:
#: RK4 10 ms): the registered physics step of every id but LadderMill-v3, which registers ROS2 on v2's scene, and
#: LadderChain-v1, RK4 at 1/60 s on v0's; the reference is RK4 at a quarter of it. TetheredWing-v1 (RK4 at 25 ms):
#: 12.5 ms, so its reference is RK4 at 3.125 ms, as the chain's (the wing's RK4 is stable to about 0.11 s at the
#: trim). Not TetheredWing-v0, whose scene options name its method (ROS34PW2): its step is v1's ``ros34pw2`` label.
REGISTERED_DT = {"laddermill_gym/TetheredWing-v1": 0.0125,
                 "laddermill_gym/LadderChain-v0": 0.0125, "laddermill_gym/LadderChain-v1": 0.0125,
                 "laddermill_gym/LadderMill-v0": 0.01, "laddermill_gym/LadderMill-v1": 0.01,
                 "laddermill_gym/LadderMill-v2": 0.01, "laddermill_gym/LadderMill-v3": 0.01}


def positions(task) -> np.ndarray:
    """(wings + nodes, 3) positions [m] of copy 0 of a task: the wings' CGs, then the cable nodes."""
    a, x, nw = task.batch.assembly, task.batch.states[0], task.n_wings
    bodies = x[: B3_SIZE * nw].reshape(nw, B3_SIZE)[:, B3_POS: B3_POS + 3]
    nodes = x[B3_SIZE * nw: a.body_state_size].reshape(-1, N3_SIZE)[:, N3_POS: N3_POS + 3]
    return np.vstack([bodies, nodes])


def episode(env_id: str, n_periods: int, **kwargs) -> tuple[np.ndarray, float, np.ndarray]:
    """(positions (periods run + 1, points, 3) [m], CPU time of the steps [s], rewards (periods run,) [-]) of one
    copy over ``n_periods`` control periods of the seeded actions; stops early (shorter arrays) at the end of the
    episode (the last reward, the ending step's, left out)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # LadderMill-v1 'out of date' and the like
        env = gym.make_vec(env_id, num_envs=1, vectorization_mode="vector_entry_point", **kwargs)
    obs, _ = env.reset(seed=0)
    a0 = np.asarray(make_controller("open_loop", env_id).predict(obs)[0], dtype=np.float32)
    rng = np.random.default_rng(1)
    out = [positions(env.task)]
    rewards = []
    cpu = 0.0
    for _ in range(n_periods):
        a = np.clip(a0 + ACTION_NOISE * rng.uniform(-1.0, 1.0, a0.shape), -1.0, 1.0).astype(np.float32)
        t0 = time.process_time()
        _, r, terminated, truncated, _ = env.step(a)
        if terminated.any() or truncated.any():  # a period not kept: its CPU not counted with the kept ones
            break
        cpu += time.process_time() - t0
        out.append(positions(env.task))
        rewards.append(float(r[0]))
    env.close()
    return np.array(out), cpu, np.array(rewards)


def step_arguments(label: str) -> dict:
    """The env arguments of a physics-step label: "registered" (none), a ``physics_step`` value ("ros2t", its
    matrix formed every step: ``jacobian_every`` = 1, whatever the id registers), or one with the W-method's
    iteration matrix kept for k steps ("ros2t:8": ``jacobian_every`` = 8). A label's step is the method's default
    whatever the id registers (``physics_dt`` None: one step per control period for a W-method, the scene's step
    for RK4; LadderChain-v1's "rk4" is LadderChain-v0's step). ValueError naming the label otherwise."""
    if label == "registered":
        return {}
    method, sep, every = label.partition(":")
    if not sep:
        return {"physics_step": method, "physics_dt": None, "jacobian_every": 1}
    if not every.isdigit() or int(every) < 1:
        raise ValueError(f"physics step {label!r}: write METHOD or METHOD:K with K >= 1 steps per Jacobian")
    return {"physics_step": method, "physics_dt": None, "jacobian_every": int(every)}


def check_labels(steps) -> None:
    """ValueError naming the first label of ``steps`` that :func:`step_arguments` refuses, whose method is not a
    fixed-step method of the envs (``envs/physics_step.check_physics_step``) or that keeps the matrix of a method
    that is not a W-method (``jacobian_settings``' rule): before the reference run, not after."""
    for label in steps:
        args = step_arguments(label)
        if label != "registered":
            check_physics_step(args["physics_step"])
            jacobian_settings(IntegratorSettings(method=args["physics_step"], dt=0.05),
                              args.get("jacobian_every", 1))


def compare(env_id: str, episode_time: float, steps=("ros34pw2",), echo=print, **kwargs) -> dict:
    """The study: {"extent": m, "periods": control periods asked, label: {"error_m", "share", "periods",
    "cpu_s"}} for the registered step ("registered") and each ``physics_step`` of ``steps`` (once per control
    period), against RK4 at a quarter of the scene's RK4 step (``REGISTERED_DT``); ``kwargs`` go to every env (e.g.
    the operating point)."""
    check_labels(steps)
    n = int(round(episode_time / 0.05))
    ref, _, r_ref = episode(env_id, n, physics_step="rk4", jacobian_every=1, physics_dt=REGISTERED_DT[env_id] / 4,
                            **kwargs)
    extent = float(np.max(np.linalg.norm(ref, axis=2)))
    echo(f"{env_id}: {episode_time:g} s, extent {extent:.1f} m; reference RK4 at {REGISTERED_DT[env_id] / 4:g} s "
         f"ran {len(ref) - 1} periods, mean reward {np.mean(r_ref):.4f}")
    res = {"extent": extent, "periods": n}
    for label in ("registered", *steps):
        P, cpu, r = episode(env_id, n, **step_arguments(label), **kwargs)
        m = min(len(P), len(ref))
        err = float(np.max(np.linalg.norm(P[:m] - ref[:m], axis=2)))
        k = min(len(r), len(r_ref))
        r_err = float(np.max(np.abs(r[:k] - r_ref[:k]))) if k else float("nan")
        res[label] = {"error_m": err, "share": err / extent, "periods": len(P) - 1, "cpu_s": cpu,
                      "reward_error": r_err, "mean_reward": float(np.mean(r)) if len(r) else float("nan")}
        echo(f"  {label:10s}: largest position error {err:.4g} m = {err / extent:.3g} of the extent over "
             f"{len(P) - 1} periods; largest reward error {r_err:.4g}, mean reward {res[label]['mean_reward']:.4f}; "
             f"CPU {cpu:.2f} s ({(len(P) - 1) / cpu:,.0f} steps/s, one copy)")
    return res


#: the closed-loop runs' disturbance: the paper's 0.01 rad wind-direction step at t = 1 s [rad], [s]
PAPER_STEP = {"type": "DirectionStep", "step": 0.01, "time": 1.0}


def closed_loop(env_id: str, spec: str, episode_time: float, steps=("ros2:4",), echo=print) -> dict:
    """The controller ``spec`` (``make_controller``'s specs) on one episode (seed 0) of ``episode_time`` [s] with
    the paper's step (:data:`PAPER_STEP`), with the registered physics step and each of ``steps``:
    {label: {"length_s", "power_W" (mean over the episode), "max_lateral_m" (largest |lateral offset| of any
    wing), "wall_s"}}, printed with each step's differences from the registered step's (power relative, offset
    in m). The episodes are the gust benchmark's (``gusts/gust_bench.run_episodes``)."""
    from laddermill_gym.studies.gusts.gust_bench import run_episodes

    check_labels(steps)
    res = {}
    for label in ("registered", *steps):
        t0 = time.perf_counter()
        kw = step_arguments(label)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # LadderMill-v1 'out of date' and the like
            rec = run_episodes(make_controller(spec, env_id, kw), env_id, kw, [0], episode_time, [PAPER_STEP])
        res[label] = {"length_s": float(rec["t_end"][0]),
                      "power_W": float(rec["energy_J"][0] / (rec["steps"][0] * rec["control_dt"])),
                      "max_lateral_m": float(np.nanmax(rec["lateral"])), "wall_s": time.perf_counter() - t0}
    ref = res["registered"]
    echo(f"{env_id}, {spec}, {episode_time:g} s (seed 0):")
    for label, v in res.items():
        diff = "" if label == "registered" else (
            f"; against the registered step: power {(v['power_W'] - ref['power_W']) / ref['power_W']:+.2e} "
            f"(relative), largest offset {v['max_lateral_m'] - ref['max_lateral_m']:+.2e} m")
        echo(f"  {label:10s}: ran {v['length_s']:g} s, mean power {v['power_W'] / 1e3:.3f} kW, largest lateral "
             f"offset {v['max_lateral_m']:.5f} m, wall {v['wall_s']:.1f} s{diff}")
    return res


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("env_id", choices=sorted(REGISTERED_DT))
    p.add_argument("--time", type=float, default=10.0, help="episode time [s] (default 10)")
    p.add_argument("--steps", nargs="+", default=["ros34pw2", "ros2"],
                   help="physics_step values compared; METHOD:K keeps a W-method's iteration matrix K steps "
                        "(jacobian_every), e.g. ros2:4")
    p.add_argument("--controller", metavar="SPEC", help="run this harness controller closed loop instead (lqr, "
                   "lqr:PATH, a run folder; laddermill evaluate's specs): each step's length, power and lateral offset")
    args = p.parse_args(argv)
    n = round(args.time / 0.05) if math.isfinite(args.time) else 0
    if not (n >= 1 and abs(n * 0.05 - args.time) <= 1e-9 * args.time):  # not after the reference run
        p.error(f"--time {args.time!r}: must be a whole number (>= 1) of the 0.05 s control period")
    try:
        check_labels(args.steps)
    except ValueError as err:
        p.error(f"--steps: {err}")
    if args.controller:
        try:
            closed_loop(args.env_id, args.controller, args.time, tuple(args.steps))
        except ValueError as err:  # a spec make_controller refuses, named with its value
            p.error(f"--controller: {err}")
    else:
        compare(args.env_id, args.time, tuple(args.steps))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
