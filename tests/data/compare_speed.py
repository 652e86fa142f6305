"""Before/after speed of the architecture change (issue 11): run once per code version, in alternation.

Usage (from the repository root; the old code checked out with ``git worktree add /tmp/old 16b454f``)::

    for i in 1 2 3; do PYTHONPATH=/tmp/old python tests/data/compare_speed.py old; \
                       python tests/data/compare_speed.py new; done

Prints one JSON line per run: median right-hand side and RK4 step times [us] of ``tethered_wing`` and
``ladder_chain`` and TetheredWing-v0 native vector-env steps/s at 64 copies (one thread). Not a test.
"""
import json
import os
import sys
import time

os.environ.setdefault("NUMBA_NUM_THREADS", "1")
import gymnasium as gym  # noqa: E402
import numpy as np  # noqa: E402

import laddermill_gym  # noqa: E402

try:
    from laddermill_gym.studies.benchmarks import benchmark as bm
except ImportError:
    from laddermill_gym import benchmark as bm


def env_rate(n_copies=64, steps=300):
    env = gym.make_vec("laddermill_gym/TetheredWing-v0", num_envs=n_copies, vectorization_mode="vector_entry_point")
    env.reset(seed=0)
    a = np.zeros((n_copies, *env.single_action_space.shape), dtype=env.single_action_space.dtype)
    for _ in range(20):
        env.step(a)
    times = []
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(steps):
            env.step(a)
        times.append(time.perf_counter() - t0)
    return n_copies * steps / float(np.median(times))


out = {"version": sys.argv[1]}
for name in ("tethered_wing", "ladder_chain"):
    sim = laddermill_gym.load_scene(name).simulator()
    n = 2000 if name == "tethered_wing" else 100
    out[f"{name}_rhs_us"] = 1e6 * bm.time_rhs(sim, n, 15)
    out[f"{name}_rk4_us"] = 1e6 * bm.time_step(sim, n // 4, 15)
out["env64_steps_s"] = env_rate()
print(json.dumps(out))
