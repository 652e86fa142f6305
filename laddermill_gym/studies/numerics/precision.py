"""What the work-precision study shares between the rigid scenes (``work_precision.py``) and the point-mass scenes
(``pointmass_precision.py``): the forcings' wind, the grid of explicit steps, the piecewise scipy reference, the
errors against it, one timed row, and the loop over forcings."""

from __future__ import annotations

import math
import statistics
import time

import numpy as np

from laddermill_gym.sim.simulator import SimulationError

FORCINGS = ("smooth", "step", "gust")


def forcing_wind(wind, forcing: str, duration: float):
    """The ``WindParams`` of a non-smooth forcing over ``duration`` [s] (``work_precision.forcing_setup``), None
    for smooth."""
    if forcing == "smooth":
        return None
    if forcing == "step":
        return wind.with_modulation(0.3037 * duration, 1e-3, np.ones(2), np.array([0.0, 0.1]))
    if forcing == "gust":
        t0, length = 0.2 * duration, 0.4 * duration
        tt = np.arange(0.0, length + 1e-9, 0.1)
        speed = 1.0 + 0.15 * (1.0 - np.cos(2 * np.pi * tt / length))
        return wind.with_modulation(t0, 0.1, speed, np.zeros_like(speed))
    raise ValueError(f"forcing = {forcing!r}: must be one of {FORCINGS}")


def explicit_step_counts(period: float, dt_stable: float, n: int) -> list[int]:
    """Steps per sample ``period`` [s] of an explicit method: from the fewest within its stable step ``dt_stable``
    [s] up, the step halving every two of the ``n`` entries (equal counts merged)."""
    m0 = max(1, math.ceil(period / dt_stable - 1e-9))
    return sorted({int(round(m0 * 2 ** (k / 2))) for k in range(n)})


def scaled_difference(xs: np.ndarray, xr: np.ndarray) -> np.ndarray:
    """States ``xs`` less the reference ``xr``, each entry over max(1, |reference|) [-]."""
    return (xs - xr) / np.maximum(1.0, np.abs(xr))


def piecewise_reference(f, x0: np.ndarray, times: np.ndarray, kinks, method: str, tol: float) -> np.ndarray:
    """States at ``times`` from scipy's ``method`` at rtol = atol = ``tol`` on ``f(t, y)`` from ``x0``, integrated
    piece by piece between the wind's ``kinks`` [s] (inside a piece ``f`` sees times just below its end, so its
    own segment). RuntimeError naming the piece when scipy fails."""
    from scipy.integrate import solve_ivp

    x = x0
    out = [x.copy()]
    for ta, tb in zip(times[:-1], times[1:], strict=True):
        ends = [ta, *[float(b) for b in kinks if ta < b < tb], tb]
        for a, b in zip(ends[:-1], ends[1:], strict=True):
            top = b - 1e-12 * max(1.0, abs(b))
            sol = solve_ivp(lambda t, y, top=top: f(min(t, top), y), (a, b), x, method=method, rtol=tol, atol=tol)
            if not sol.success:
                raise RuntimeError(f"scipy {method} reference failed on [{a}, {b}] s: {sol.message}")
            x = sol.y[:, -1]
        out.append(x.copy())
    return np.array(out)


def errors(xs, ps, xr, pr) -> dict:
    """Final-time, RMS and largest errors of positions [m] (per body Euclidean; the largest also relative to the
    reference's extent, the largest distance of a body from the origin) and of the scaled full state [-]."""
    dp = np.linalg.norm(ps - pr, axis=2)
    dx = scaled_difference(xs, xr)
    extent = float(np.max(np.linalg.norm(pr, axis=2)))
    return {"err_final_pos_m": float(np.max(dp[-1])), "err_rms_pos_m": float(np.sqrt(np.mean(dp**2))),
            "err_max_pos_m": float(np.max(dp)), "err_max_pos_rel": float(np.max(dp)) / extent,
            "err_final_state": float(np.max(np.abs(dx[-1]))), "err_rms_state": float(np.sqrt(np.mean(dx**2)))}


def timed(start, go):
    """One run for :func:`measure`: a fresh simulator from ``start()``, then ``go(sim)``'s (states, positions) at
    the sample times, the wall time [s] and the process CPU time [s] of ``go`` alone (the integration, not the
    set-up; with one numba thread the CPU time is the integration's own, whatever else loads the machine)."""

    def once():
        sim = start()
        t0, c0 = time.perf_counter(), time.process_time()
        xs, ps = go(sim)
        return xs, ps, time.perf_counter() - t0, time.process_time() - c0

    return once


def measure(row: dict, once, xr, pr, duration: float, repeats: int, failure=SimulationError, bar=None) -> dict:
    """Fill ``row`` for one run: ``once()`` gives (states, positions, wall time [s], CPU time [s]); the errors of
    its first call against the reference (xr, pr), the median wall time and the least CPU time of ``repeats``
    more and the real-time factor (wall); a ``failure`` raised becomes the row's status (its first line), with
    no time. The progress ``bar`` (if any) counts the run."""
    try:
        xs, ps = once()[:2]
        row.update(errors(xs, ps, xr, pr), status="ok")
        timings = [once()[2:] for _ in range(repeats)]
        row["wall_s"] = statistics.median(w for w, _ in timings)
        row["cpu_s"] = min(c for _, c in timings)  # other load only adds to it (cache and memory contention)
        row["real_time_factor"] = duration / row["wall_s"]
    except failure as err:
        row.update(status=f"failed: {str(err).splitlines()[0][:160]}", wall_s=math.nan, cpu_s=math.nan)
    if bar is not None:
        bar.update(1)
    return row


def run_forcings(out: dict, forcings, desc: str, progress: bool, run) -> dict:
    """Add ``run(forcing, bar)``'s (rows, reference summary) of every forcing to the result ``out`` (its
    "references" and "rows"), with a progress bar counting the runs when ``progress``."""
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(desc=desc, unit="run", leave=False)
    try:
        for f in forcings:
            rows, ref = run(f, bar)
            out["references"][f] = ref
            out["rows"] += rows
    finally:
        if bar is not None:
            bar.close()
    return out
