"""Analysis of the lateral study: trim and linearise a scene (open-loop lateral eigenvalues), summarise the
modes, run a sweep and locate where the largest real part or the slow oscillation changes sign."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels.contract import B3_POS
from laddermill_gym.ladder.scene import Scene
from laddermill_gym.studies.lateral.lateral_variants import SweepSpec, base_scene, variant_for


def lateral_eigenvalues(scene: Scene) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Trim ``scene`` and return (open-loop continuous lateral eigenvalues [1/s] (6,), trim state, trim controls).

    Raises whatever the trim raises (RuntimeError when Newton does not converge)."""
    from laddermill_gym.control.lqr import design_tethered_wing, load_lqr_config

    d = design_tethered_wing(load_lqr_config(), scene=scene)
    return np.asarray(d.lqr.open_loop, dtype=complex), d.x_trim, d.u_trim


def mode_summary(eigenvalues: np.ndarray) -> tuple[float, float]:
    """(largest real part [1/s], period [s] of the least-damped oscillatory mode) of continuous eigenvalues.

    The period is 2 pi / Im of the complex pair with the largest real part; nan if all eigenvalues are real."""
    ev = np.asarray(eigenvalues, dtype=complex)
    max_real = float(np.max(ev.real))
    osc = ev[ev.imag > 1e-9]
    if osc.size == 0:
        return max_real, float("nan")
    s = osc[np.argmax(osc.real)]
    return max_real, float(2 * math.pi / s.imag)


@dataclass(frozen=True)
class VariantResult:
    """Result for one variant: swept value, largest real part [1/s], oscillation period [s], its growth rate
    [1/s], trim elevator [deg], tether elevation [deg], all eigenvalues [1/s] (nan when the trim failed), the
    error message of a failed trim, and whether the trim elevator lies within the wing's control limits."""

    value: float
    max_real: float
    period: float
    osc_real: float
    elevator_deg: float
    elevation_deg: float
    eigenvalues: np.ndarray
    error: str = ""
    elevator_in_limits: bool = True


@dataclass(frozen=True)
class SweepResult:
    spec: SweepSpec
    variants: tuple[VariantResult, ...]

    @property
    def values(self) -> np.ndarray:
        return np.array([v.value for v in self.variants])

    @property
    def max_real(self) -> np.ndarray:
        return np.array([v.max_real for v in self.variants])

    @property
    def period(self) -> np.ndarray:
        return np.array([v.period for v in self.variants])

    def brackets(self, quantity: str = "max_real") -> list[tuple[float, float]]:
        """Neighbouring swept values (a, b) between which ``quantity`` (``max_real`` or ``osc_real``) changes
        sign (failed variants skipped)."""
        x = self.values
        y = np.array([getattr(v, quantity) for v in self.variants])
        ok = np.isfinite(y)
        x, y = x[ok], y[ok]
        return [(float(x[i]), float(x[i + 1])) for i in range(len(x) - 1) if y[i] * y[i + 1] <= 0 and y[i] != y[i + 1]]


def locate_sign_change(base: Scene, name: str, a: float, b: float, quantity: str = "max_real",
                       tol: float = 1e-3) -> float:
    """Parameter value [unit of sweep ``name``] between ``a`` and ``b`` where ``quantity`` of the lateral
    eigenvalues (``max_real``: largest real part; ``osc_real``: real part of the least-damped oscillation)
    is zero, by bisection to a relative width ``tol`` of the bracket. nan if a trim fails on the way or the
    bracket does not change sign."""
    def f(v: float) -> float:
        return getattr(evaluate(variant_for(base, name, v), v), quantity)

    fa, fb = f(a), f(b)
    if not (np.isfinite(fa) and np.isfinite(fb)) or fa * fb > 0:
        return float("nan")
    width = tol * abs(b - a)
    while abs(b - a) > width:
        m = 0.5 * (a + b)
        fm = f(m)
        if not np.isfinite(fm):
            return float("nan")
        if fa * fm <= 0:
            b, fb = m, fm
        else:
            a, fa = m, fm
    return 0.5 * (a + b)


def sign_changes(base: Scene, result: SweepResult, quantity: str = "max_real") -> list[float]:
    """All parameter values of ``result``'s sweep where ``quantity`` changes sign (bisection in every
    bracket of :meth:`SweepResult.brackets`)."""
    return [locate_sign_change(base, result.spec.name, a, b, quantity) for a, b in result.brackets(quantity)]


def evaluate(scene: Scene, value: float = float("nan")) -> VariantResult:
    """Trim and analyse one scene; a failed trim gives a result full of nan with the error message."""
    try:
        ev, x, u = lateral_eigenvalues(scene)
    except (RuntimeError, ValueError, ArithmeticError, np.linalg.LinAlgError) as err:
        nan = float("nan")
        return VariantResult(float(value), nan, nan, nan, nan, nan, np.full(6, nan, dtype=complex),
                             f"{type(err).__name__}: {err}")
    max_real, period = mode_summary(ev)
    osc = ev[ev.imag > 1e-9]
    osc_real = float(np.max(osc.real)) if osc.size else float("nan")
    # CG position relative to the ground station: elevation of the tether line above the horizon
    rel = x[B3_POS: B3_POS + 3] - scene.ground_points[scene.start]
    elevation = math.degrees(math.atan2(-rel[2], math.hypot(rel[0], rel[1])))
    lo, hi = scene.assembly.wing_types[0].control_limits[0]
    return VariantResult(float(value), max_real, period, osc_real, math.degrees(u[0]), elevation, ev,
                         elevator_in_limits=bool(lo <= u[0] <= hi))


def run_sweep(base: Scene, spec: SweepSpec) -> SweepResult:
    """Evaluate every value of ``spec`` (one parameter changed at a time from ``base``)."""
    return SweepResult(spec, tuple(evaluate(variant_for(base, spec.name, float(v)), float(v)) for v in spec.values))


# The default scene, built once per process (a worker's tasks share it).
_BASE: dict[str, Scene] = {}


def _base() -> Scene:
    if "scene" not in _BASE:
        _BASE["scene"] = base_scene()
    return _BASE["scene"]


def warm_base() -> VariantResult:
    """The per-worker warm-up: build the default scene and analyse it (compiles or loads the trim and
    linearisation kernels)."""
    _BASE.clear()
    return evaluate(_base(), float("nan"))


def variant_task(name: str, value: float) -> VariantResult:
    """A picklable task: :func:`evaluate` of the default scene with sweep ``name`` at ``value``."""
    return evaluate(variant_for(_base(), name, float(value)), float(value))


def sign_change_task(name: str, a: float, b: float, quantity: str) -> float:
    """A picklable task: :func:`locate_sign_change` on the default scene."""
    return locate_sign_change(_base(), name, a, b, quantity)


def run_sweeps(specs: dict[str, SweepSpec], names, workers: int = 0, ray: str | None = None,
               progress: bool = True) -> tuple[list[SweepResult], dict]:
    """Every value of the sweeps ``names`` (one task each), then every sign change (one bisection task per
    bracket), serially or on workers (:func:`laddermill_gym.studies.parallel.run_tasks`): the same results
    either way. Returns (results in the order of ``names``, {sweep: {quantity: [values]}})."""
    from laddermill_gym.studies.parallel import Pool

    tasks = [(variant_task, {"name": n, "value": float(v)}) for n in names for v in specs[n].values]
    quantities = ("max_real", "osc_real")
    with Pool(workers, ray, warmup=[(warm_base, {})], cap=len(tasks)) as pool:  # no more actors than variants
        out = iter(pool.run(tasks, desc="lateral variants", unit="variant", progress=progress))
        results = [SweepResult(specs[n], tuple(next(out) for _ in specs[n].values)) for n in names]
        brackets = [(r.spec.name, q, a, b) for r in results for q in quantities for a, b in r.brackets(q)]
        found = pool.run([(sign_change_task, {"name": n, "a": a, "b": b, "quantity": q}) for n, q, a, b in brackets],
                         desc="lateral sign changes", unit="bisection", progress=progress)
    crossings: dict = {n: {q: [] for q in quantities} for n in names}
    for (n, q, _, _), v in zip(brackets, found, strict=True):
        crossings[n][q].append(v)
    return results, crossings
