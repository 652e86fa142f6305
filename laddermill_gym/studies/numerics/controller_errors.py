"""What a controller sees, and how far a run's is from the reference's: the work-precision study's
controller-relevant errors (issue 32 point 4).

At every output time of a run (the study's ``--samples`` equally spaced times) the quantities a controller of the
envs observes or is rewarded by are read from the state:

* the element tensions [N] (every element; the envs observe the tension below each wing),
* the generator power [W]: with a ground station (the mill) its mechanical power (tension difference across the
  station times the cable speed, ``StationViews.generator_power``); otherwise the envs' reward power
  (T_first ground element - T_last ground element) times their constant reel speed, so relative to its largest
  value the reel speed cancels and the tension difference is what is compared,
* the wings' lateral offsets, the CG's global y [m] (the envs observe dy = y - y_nominal: the same error),
* the wings' attitudes, the 3-2-1 Euler angles (roll, pitch, yaw) the envs observe [rad].

Errors, max over time (and elements or wings): tension and power as the largest absolute error over the largest
absolute reference value over the run [-]; lateral offset [m] and attitude [rad] absolute (angles wrapped into
(-pi, pi]). A run *meets the controller tolerances* when all four are within :data:`TOLERANCES`.
"""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.kernels.contract import END_FIXED

#: the controller tolerances of issue 32 point 4: tension and power within 1 % [-] of their largest reference value
#: over the run, lateral offsets within 0.1 m, attitudes within 0.01 rad (max over wings and output times)
TOLERANCES = {"err_tension_rel": 0.01, "err_power_rel": 0.01, "err_lateral_m": 0.1, "err_attitude_rad": 0.01}


def ground_elements(assembly) -> tuple[int, int]:
    """(first, last) element with an end on a fixed (ground) point; last is -1 when only one element is anchored
    (a one-ended tether: the envs' power is then that element's tension times the reel speed)."""
    el = assembly.elements
    anchored = np.flatnonzero(np.any(el.end_kind == END_FIXED, axis=1))
    if anchored.size == 0:
        return -1, -1
    return int(anchored[0]), (int(anchored[-1]) if anchored.size > 1 else -1)


def quantities_at(sim, t: float, x: np.ndarray) -> tuple[np.ndarray, float, np.ndarray, np.ndarray]:
    """(tensions (n_elements,) [N], power [W] (or the tension difference [N] without a station: see the module
    doc), lateral CG offsets y (n_wings,) [m], Euler angles (n_wings, 3) [rad]) of state ``x`` at time ``t`` [s],
    with ``sim``'s controls (``sim`` is reset to (t, x): an evaluator, not the run's simulator)."""
    sim.reset(state=x, t=t, controls=sim.controls, check=False)
    ten = sim.tensions()
    if sim.assembly.station is not None:
        power = sim.generator_power()["mechanical_W"]
    else:
        g0, g1 = ground_elements(sim.assembly)
        power = (ten[g0] if g0 >= 0 else 0.0) - (ten[g1] if g1 >= 0 else 0.0)
    return ten, float(power), sim.wing_positions()[:, 1].copy(), sim.wing_euler()


def controller_quantities(sim, times, xs) -> dict[str, np.ndarray]:
    """The quantities of :func:`quantities_at` at every output time: {"tension" (n, n_el), "power" (n,),
    "lateral" (n, n_wings), "attitude" (n, n_wings, 3)}."""
    rows = [quantities_at(sim, float(t), x) for t, x in zip(times, xs, strict=True)]
    return {"tension": np.array([r[0] for r in rows]), "power": np.array([r[1] for r in rows]),
            "lateral": np.array([r[2] for r in rows]), "attitude": np.array([r[3] for r in rows])}


def _relative(a: np.ndarray, ref: np.ndarray) -> float:
    """max |a - ref| / max |ref| [-] (inf when the reference is zero throughout and a is not)."""
    num, den = float(np.max(np.abs(a - ref))), float(np.max(np.abs(ref)))
    return num / den if den > 0 else (0.0 if num == 0 else math.inf)


def wrapped(d: np.ndarray) -> np.ndarray:
    """Angle differences wrapped into (-pi, pi] [rad]."""
    return -np.remainder(-d + math.pi, 2 * math.pi) + math.pi


def controller_errors(q: dict, ref: dict) -> dict:
    """The errors of run quantities ``q`` against the reference's ``ref`` (both from :func:`controller_quantities`
    at the same times) and whether they meet :data:`TOLERANCES` (``meets_controller``)."""
    out = {"err_tension_rel": _relative(q["tension"], ref["tension"]),
           "err_power_rel": _relative(q["power"], ref["power"]),
           "err_lateral_m": float(np.max(np.abs(q["lateral"] - ref["lateral"]), initial=0.0)),
           "err_attitude_rad": float(np.max(np.abs(wrapped(q["attitude"] - ref["attitude"])), initial=0.0))}
    out["meets_controller"] = bool(all(out[k] <= tol for k, tol in TOLERANCES.items()))
    return out


def fastest_meeting(res: dict) -> list[dict]:
    """Per forcing and method the run that meets the controller tolerances in the least CPU time (one numba
    thread: the integration's own time, robust to other load; wall time for rows without it), with its speed-up
    over the fastest such run of the baseline (``res["baseline"]``, default RK4 with breakpoints "inside") in CPU
    time (``speedup_vs_rk4``) and in wall time (``speedup_wall``)."""
    out = []
    for f in res["references"]:
        best: dict[str, dict] = {}
        for r in res["rows"]:
            if r["forcing"] == f and r["status"] == "ok" and r.get("meets_controller"):
                if r["method"] not in best or _cost(r) < _cost(best[r["method"]]):
                    best[r["method"]] = r
        base = best.get(res.get("baseline", "rk4"))
        for r in best.values():
            out.append({**{k: r[k] for k in ("forcing", "method", "dt_s", "tol", "wall_s", "real_time_factor")},
                        **{k: r[k] for k in TOLERANCES}, "cpu_s": _cost(r),
                        "speedup_vs_rk4": _cost(base) / _cost(r) if base else math.nan,
                        "speedup_wall": base["wall_s"] / r["wall_s"] if base else math.nan,
                        "rk4_dt_s": base["dt_s"] if base else math.nan})
    return out


def _cost(r: dict) -> float:
    """A row's CPU time [s], or its wall time where it has none."""
    return r.get("cpu_s", r["wall_s"])
