"""The cost of sampling turbulence in the kernels: environment steps with and without a frozen turbulence field
(everything else equal), interleaved repeats, medians and their ratio, plus the field's memory and the time to
draw it per reset. The field's values are set to zero after each reset, so both runs fly the same trajectory
(the open-loop chain leaves the aerodynamic tables within a second in class-A turbulence) while the kernels
still look up and interpolate the whole field at every wing and cable node: the cost does not depend on the
values.

    python -m laddermill_gym.studies.gusts.turbulence_cost [--env laddermill_gym/LadderChain-v0] [--steps 200]
"""

from __future__ import annotations

import argparse
import statistics
import time

import gymnasium as gym
import numpy as np
from tqdm import tqdm

import laddermill_gym  # noqa: F401  (registers the ids)

#: A turbulence field covering the 3.5 km chain of LadderChain-v0 (wings at heights 120-3580 m, p . e from
#: -90 to 540 m): IEC NTM class IA at the scene's 8 m/s, rows every 25 m, columns every 10 m.
CHAIN_TURBULENCE = {"type": "Turbulence", "model": "NTM", "wind_class": "IA", "wind_speed": 8.0,
                    "heights": [0.0, 3650.0], "dh": 25.0, "along_wind": [-700.0, 700.0], "dxi": 10.0}


def _time_steps(env, n: int) -> float:
    a = np.zeros(env.action_space.shape, dtype=np.float32)
    t0 = time.perf_counter()
    for _ in range(n):
        _, _, term, trunc, _ = env.step(a)
        if term or trunc:
            raise RuntimeError(f"the episode ended within the {n} timed steps; time fewer steps")
    return (time.perf_counter() - t0) / n


def measure(env_id: str, steps: int, repeats: int, turbulence: dict) -> dict:
    """Median seconds per env step without (``off``) and with (``on``) the field, their ratio, the field's bytes
    and the median time to draw it at a reset."""
    base = [{"type": "DirectionStep", "step": 0.01}]
    envs = {"off": gym.make(env_id, disturbances=base), "on": gym.make(env_id, disturbances=base + [turbulence])}
    for e in envs.values():
        e.reset(seed=0)
        _time_steps(e, 5)  # compile and warm up
    times = {k: [] for k in envs}
    for _ in tqdm(range(repeats), desc=f"{env_id} on/off"):
        for k, e in envs.items():
            e.reset(seed=1)
            air = e.unwrapped.task.batch.air
            if air.gv is not None:
                air.gv[:] = 0.0  # same flight as without the field; the lookups remain
            times[k].append(_time_steps(e, steps))
    task = envs["on"].unwrapped.task
    from laddermill_gym.atmosphere.disturbances import sample_wind_field

    draws = []
    for s in range(5):
        t0 = time.perf_counter()
        field = sample_wind_field(task.disturbances, task.episode_time, task.wind_dt, np.random.default_rng(s))
        draws.append(time.perf_counter() - t0)
    off, on = statistics.median(times["off"]), statistics.median(times["on"])
    return {"env": env_id, "off_s": off, "on_s": on, "ratio": on / off, "field_bytes": field.grid.values.nbytes,
            "field_shape": field.grid.values.shape, "draw_s": statistics.median(draws),
            "episode_time": task.episode_time}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.studies.gusts.turbulence_cost", description=__doc__)
    p.add_argument("--env", default="laddermill_gym/LadderChain-v0")
    p.add_argument("--steps", type=int, default=100, help="env steps per timing")
    p.add_argument("--repeats", type=int, default=5, help="interleaved on/off repeats")
    args = p.parse_args(argv)
    r = measure(args.env, args.steps, args.repeats, CHAIN_TURBULENCE)
    print(f"{r['env']}: step without turbulence {1e3 * r['off_s']:.3f} ms, with {1e3 * r['on_s']:.3f} ms, "
          f"ratio {r['ratio']:.3f} (medians of {args.repeats} interleaved runs of {args.steps} steps)")
    print(f"field {r['field_shape']} = {r['field_bytes'] / 1e6:.2f} MB for {r['episode_time']:.0f} s, drawn in "
          f"{1e3 * r['draw_s']:.1f} ms per reset")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
