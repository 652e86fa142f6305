"""Wall time of the 1-year daily site optimisation (Tables 1 and 2 on the shipped 2010 data, 365 daily states):
median of 5 runs each. ``python -m laddermill_gym.quasisteady.timing``."""

from __future__ import annotations

import time

import numpy as np

from laddermill_gym.quasisteady.site_data import shipped_wind
from laddermill_gym.quasisteady.site_optimise import TABLE1, TABLE2, optimise


def main(repeats: int = 5) -> int:
    wind = shipped_wind("weather2010-daily")
    for case in (TABLE1, TABLE2):
        times, res = [], None
        for _ in range(repeats):
            t0 = time.perf_counter()
            res = optimise(case, wind)
            times.append(time.perf_counter() - t0)
        med = float(np.median(times))
        print(f"{case.name}: {wind.n} daily states, median {med:.2f} s of {repeats} (min {min(times):.2f}, "
              f"max {max(times):.2f}), {res.evaluations} inner solves, {1e3 * med / res.evaluations:.3f} ms each")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
