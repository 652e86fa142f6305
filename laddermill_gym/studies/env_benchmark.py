"""Environment throughput benchmark: env steps per second of the native batched vector env against
Gymnasium's ``SyncVectorEnv`` over single envs, measured in the same run (``laddermill bench-envs``).

Every copy steps with the trim action (the work per step does not depend on the action); copies whose
episode ends are reset by the vector envs' autoreset, as in training. Times are medians over repeats.
"""

from __future__ import annotations

import json
import os
import time

import gymnasium as gym
import numpy as np

from laddermill_gym.envs import ENV_IDS, WingEnv, WingVectorEnv


def _steps_per_second(env, action: np.ndarray, n_steps: int, repeats: int) -> float:
    env.reset(seed=0)
    env.step(action)  # warm-up
    rates = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(n_steps):
            env.step(action)
        rates.append(n_steps * env.num_envs / (time.perf_counter() - t0))
    return float(np.median(rates))


def bench_vector(env_id: str, counts=(1, 8, 64, 512), quick: bool = False, echo=print) -> list[dict]:
    """Steps/s of the native vector env and of SyncVectorEnv for each number of copies."""
    kwargs = ENV_IDS[env_id]
    rows = []
    for n in counts:
        native = WingVectorEnv(n, **kwargs)
        act = np.tile(native.task.actions.nominal_action, (n, 1)).astype(np.float32)
        budget = 2e5 if quick else 1e6  # copy-steps per repeat for the native env
        native_rate = _steps_per_second(native, act, max(5, int(budget / n) // 10), 3 if quick else 5)
        native.close()
        sync = gym.vector.SyncVectorEnv([lambda: WingEnv(**kwargs) for _ in range(n)])
        sync_rate = _steps_per_second(sync, act, max(3, int((2e3 if quick else 1e4) / n)), 3)
        sync.close()
        row = {"env": env_id, "copies": n, "native_steps_per_s": native_rate, "sync_steps_per_s": sync_rate,
               "ratio": native_rate / sync_rate}
        echo(f"  {n:5d} copies: native {native_rate:12,.0f} steps/s   SyncVectorEnv {sync_rate:10,.0f} steps/s"
             f"   ratio {row['ratio']:7.1f}x")
        rows.append(row)
    return rows


def run_env_benchmark(quick: bool = False, json_path: str | None = None, echo=print) -> dict:
    """The full env benchmark: TetheredWing-v0 at 1, 8, 64, 512 copies; LadderChain-v0 at 1 and 8."""
    threads = os.environ.get("NUMBA_NUM_THREADS", "default")
    echo(f"Environment throughput (medians; numba threads: {threads}; cpus: {os.cpu_count()})")
    res = {"cpus": os.cpu_count(), "numba_threads": threads}
    echo("laddermill_gym/TetheredWing-v0 (20 Hz control):")
    res["tethered_wing"] = bench_vector("laddermill_gym/TetheredWing-v0", quick=quick, echo=echo)
    echo("laddermill_gym/LadderChain-v0 (101 wings, 20 Hz control):")
    res["ladder_chain"] = bench_vector("laddermill_gym/LadderChain-v0", counts=(1, 8), quick=True, echo=echo)
    if json_path:
        with open(json_path, "w") as fh:
            json.dump(res, fh, indent=2)
        echo(f"figures written to {json_path}")
    return res
