"""``laddermill work-precision podgaets_5km``: error against wall time of the point-mass fidelity's integrators.

The point-mass string (``podgaets_5km`` re-divided into ``element_length`` elements; default 25 m: 200 nodes, 100
of them kites) runs T seconds from its quasi-static start under the forcings of ``studies/numerics/work_precision.py``
(``smooth``: the start itself, which is near but not at rest; ``step``: a 0.1 rad direction step ramped over 1 ms
at 0.3037 T; ``gust``: the 1-cosine +30 % gust sampled every 0.1 s) by its two fixed-step methods:

* ``explicit`` (symplectic Euler) on the steps period / m from its stability limit
  (``sim/pointmass.explicit_stable_dt``: the symplectic Euler step's limit on the damped string's highest mode,
  below l0 / c and mu l0^2 / (2 DA)) down, halving every two;
* ``implicit`` (linearly implicit Euler, block-tridiagonal along the string, docs/pointmass.md) on the steps
  period / k, k = 1, 2, 4, 5, 10, 20, 40 (period: the time between samples), far beyond that limit.

Both are first order and neither stops on the forcing's kinks (a kink inside a step costs a local error of the
method's own order). The references are two independent tight solutions of the same right-hand side
(``kernels/pointmass/explicit.accelerations``): scipy's DOP853 at rtol = atol = 1e-10 and scipy's RK45 (another
method and order) at 1e-11, each integrated piece by piece between the wind's kinks; their agreement is reported.
Errors, wall time (median of warm repeats, one numba thread) and output are those of ``work_precision.py``, the
speed-up against the fastest explicit run within 1e-3 of the extent.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from laddermill_gym.kernels.contract import N3_SIZE
from laddermill_gym.kernels.pointmass.explicit import accelerations
from laddermill_gym.sim.breakpoints import modulation_kinks
from laddermill_gym.sim.pointmass import PointMassError, PointMassSimulator, explicit_stable_dt
from laddermill_gym.studies.numerics import precision

#: the implicit method runs at the sample period divided by these
IMPLICIT_DIVISORS = (1, 2, 4, 5, 10, 20, 40)
#: explicit steps on the grid (halving every two)
N_EXPLICIT = 5
REFERENCES = (("DOP853", 1e-10), ("RK45", 1e-11))


def is_pointmass_scene(name: str) -> bool:
    """True when scene ``name`` (a name or YAML path) is at the point-mass fidelity."""
    from laddermill_gym.ladder.scene import scene_path
    from laddermill_gym.model.configio import read_yaml

    try:  # ConfigError (a ValueError) for a name that is no scene file, e.g. the rotorcraft's config
        fid = read_yaml(scene_path(name)).data.get("fidelity")
    except (OSError, ValueError):
        return False
    return isinstance(fid, dict) and fid.get("wing") == "pointmass"


def _rhs(sim: PointMassSimulator):
    """f(t, y) of the string for scipy: node velocities and accelerations (the anchors are not in the state)."""
    acc = np.empty(3 * sim.string.n_nodes)
    tension = sim.W.tension

    def f(t, y):
        accelerations(t, y, sim.u, sim.M, tension, acc)
        out = np.empty_like(y)
        v = y.reshape(-1, N3_SIZE)
        o = out.reshape(-1, N3_SIZE)
        o[:, :3] = v[:, 3:]
        o[:, 3:] = acc.reshape(-1, 3)
        return out

    return f


def reference(sim: PointMassSimulator, times: np.ndarray, method: str, tol: float) -> np.ndarray:
    """States at ``times`` from scipy's ``method`` at rtol = atol = ``tol``, piece by piece between the kinks of the
    wind modulation (inside a piece the right-hand side sees times just below its end, so its own segment)."""
    kinks = modulation_kinks(sim.M.tmod, sim.M.ms, sim.M.md)
    return precision.piecewise_reference(_rhs(sim), sim.x.copy(), times, kinks, method, tol)


def _trajectory(sim: PointMassSimulator, times: np.ndarray):
    xs, ps = [sim.x.copy()], [sim.positions.copy()]
    for t in times[1:]:
        sim.step(int(round((t - sim.t) / sim.dt)))
        xs.append(sim.x.copy())
        ps.append(sim.positions.copy())
    return np.array(xs), np.array(ps)


def run_forcing(scene, forcing: str, duration: float, n_samples: int, repeats: int, dt_stable: float, bar=None):
    """Both methods on one forcing: (rows, reference summary)."""
    x0, u = scene.initial_state()
    wind = precision.forcing_wind(scene.string.wind, forcing, duration)
    string = scene.string if wind is None else dataclasses.replace(scene.string, wind=wind)
    times = np.linspace(0.0, duration, n_samples + 1)

    def make(method, dt):
        return PointMassSimulator(string, x0, u, dt, method, threads=1)

    refs = [reference(make("explicit", 1.0), times, m, tol) for m, tol in REFERENCES]
    agree = float(np.max(np.abs(precision.scaled_difference(refs[1], refs[0]))))
    xr = refs[0]
    pr = xr.reshape(xr.shape[0], -1, N3_SIZE)[:, :, :3]
    ref = {f"scipy_{m.lower()}_rtol": tol for m, tol in REFERENCES}
    ref["reference_agreement_state"] = agree
    period = duration / n_samples
    cases = [("explicit", period / m) for m in precision.explicit_step_counts(period, dt_stable, N_EXPLICIT)]
    cases += [("implicit", period / k) for k in IMPLICIT_DIVISORS]
    rows = []
    for method, dt in cases:
        once = precision.timed(lambda: make(method, dt), lambda sim: _trajectory(sim, times))
        row = {"forcing": forcing, "method": method, "dt_s": dt, "tol": math.nan}
        rows.append(precision.measure(row, once, xr, pr, duration, repeats, PointMassError, bar))
    return rows, ref


def run_scene(name: str, forcings=precision.FORCINGS, duration: float = 5.0, n_samples: int = 20, repeats: int = 3,
              element_length: float = 25.0, progress: bool = True) -> dict:
    """The study on a point-mass scene, in the result format of ``work_precision.run_scene`` (baseline
    ``explicit``; its stable step and the limiting eigenvalue of the undamped chain, 2 c / l0 [1/s])."""
    import numba

    from laddermill_gym.ladder.pointmass_scene import load_pointmass_scene

    numba.set_num_threads(1)
    scene = load_pointmass_scene(name, element_length=element_length)
    c = scene.string.cable
    dt_stable = explicit_stable_dt(scene.string)
    out = {"scene": f"{scene.name} ({scene.string.n_nodes} nodes)", "duration_s": duration, "samples": n_samples,
           "repeats": repeats, "baseline": "explicit", "dt_stable_s": dt_stable,
           "limiting_eigenvalue": [0.0, 2.0 * math.sqrt(c.EA / c.mass_per_length) / scene.string.element_length],
           "references": {}, "rows": []}
    return precision.run_forcings(out, forcings, f"work-precision {scene.name}", progress,
                                  lambda f, bar: run_forcing(scene, f, duration, n_samples, repeats, dt_stable, bar))
