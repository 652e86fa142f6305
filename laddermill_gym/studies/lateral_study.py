"""Parameter study of the lateral (sideways) instability of one wing on a tether (scene ``tethered_wing``).

Run ``python -m laddermill_gym.studies.lateral_study [--out laddermill_gym/docs/figures/lateral_study.png]
[--quick] [--sweeps NAME,NAME,...]``.

Method: for every variant the scene is rebuilt with one parameter changed (all others at the default of
``configs/scenes/tethered_wing.yaml`` and ``configs/wings/meijaard_wing.yaml``), trimmed at the scene's target
angle of attack (the elevator is solved for), linearised, and the eigenvalues of the 6-state lateral model
(y, vy, phi, psi, p, r) are computed with :func:`laddermill_gym.control.lqr.design_tethered_wing`. The
tether is one truss element (``elements_per_piece = 1``, the environments' and the LQR's model). A variant
whose trim fails is recorded as nan.

Sweeps (one at a time around the default):

* ``attach_x``  cable attachment point, body x (forward) from the CG [m]
* ``attach_z``  cable attachment point, body z (down) from the CG [m]
* ``weathercock`` scale [-] of Cnb alone (yaw moment due to sideslip, the fins' weathercock stiffness)
* ``fin``       vertical-tail scale [-]: multiplies the aerodynamic columns the twin fins dominate,
  CYb, CYr (side force from sideslip and yaw rate) and Cnb, Cnr (weathercock stiffness and yaw damping)
* ``dihedral``  dihedral-effect scale [-]: multiplies Clb (roll moment from sideslip)
* ``wind``      wind speed v0 at the top of the boundary layer [m/s]
* ``tether``    unstretched tether length [m]

The scene caches the attachment point in its cable elements when it is built, so variants are rebuilt with
:func:`laddermill_gym.model.builders.build_chain`, never patched.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.ladder.scene import Scene, load_scene
from laddermill_gym.model.builders import build_chain
from laddermill_gym.model.params import AERO_INDEX

__all__ = [
    "SCENE",
    "SWEEP_NAMES",
    "FIN_COLUMNS",
    "WEATHERCOCK_COLUMNS",
    "DIHEDRAL_COLUMNS",
    "SweepSpec",
    "VariantResult",
    "SweepResult",
    "sweep_specs",
    "locate_sign_change",
    "sign_changes",
    "base_scene",
    "make_variant",
    "lateral_eigenvalues",
    "mode_summary",
    "evaluate",
    "run_sweep",
    "format_table",
    "plot_sweeps",
    "main",
]

SCENE = "tethered_wing"
#: Aerodynamic columns scaled by the vertical-tail sweep (fin-dominated side force and yaw derivatives).
FIN_COLUMNS: tuple[str, ...] = ("CYb", "CYr", "Cnb", "Cnr")
#: Aerodynamic column scaled by the weathercock sweep (yaw moment due to sideslip alone).
WEATHERCOCK_COLUMNS: tuple[str, ...] = ("Cnb",)
#: Aerodynamic columns scaled by the dihedral sweep (roll moment due to sideslip).
DIHEDRAL_COLUMNS: tuple[str, ...] = ("Clb",)
#: Names of the sweeps, in the order they are run and drawn.
SWEEP_NAMES: tuple[str, ...] = ("attach_x", "attach_z", "weathercock", "fin", "dihedral", "wind", "tether")
DEFAULT_OUT = Path("laddermill_gym/docs/figures/lateral_study.png")
_FIGURE_SUFFIXES = (".png", ".pdf", ".svg")


# ------------------------------------------------------------------------------------ sweep definitions
@dataclass(frozen=True)
class SweepSpec:
    """One parameter sweep.

    Attributes
    ----------
    name : str           short key, one of SWEEP_NAMES
    label : str          axis label with unit
    default : float      the default scene's value (same unit as ``values``)
    values : ndarray     the swept values (unit of ``label``)
    """

    name: str
    label: str
    default: float
    values: np.ndarray


def sweep_specs(scene: Scene, quick: bool = False) -> dict[str, SweepSpec]:
    """The seven sweeps around ``scene``'s defaults: 7 points each (4 with ``quick``), default included."""
    wing = scene.assembly.wing_types[0]
    ax, az = float(wing.attachment[0]), float(wing.attachment[2])
    v0 = float(scene.assembly.wind.v0)
    length = float(scene.piece_length)
    specs = [
        SweepSpec("attach_x", "attachment x, ahead of CG [m]", ax,
                  ax + np.array([-1.0, -0.5, -0.25, 0.0, 0.5, 1.0, 1.5])),
        SweepSpec("attach_z", "attachment z, below CG [m]", az, az * np.array([-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0])),
        SweepSpec("weathercock", "weathercock scale (Cnb) [-]", 1.0, np.array([0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.5])),
        SweepSpec("fin", "vertical-tail scale (CYb, CYr, Cnb, Cnr) [-]", 1.0,
                  np.array([0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0])),
        SweepSpec("dihedral", "dihedral-effect scale (Clb) [-]", 1.0, np.array([0.0, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0])),
        SweepSpec("wind", "wind speed v0 [m/s]", v0, np.array([5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 16.0])),
        SweepSpec("tether", "tether length [m]", length, np.array([10.0, 25.0, 50.0, 100.0, 200.0, 300.0, 400.0])),
    ]
    if quick:
        specs = [dataclasses.replace(s, values=_quick_values(s)) for s in specs]
    return {s.name: s for s in specs}


def _quick_values(spec: SweepSpec) -> np.ndarray:
    """Four points of a sweep: both ends, the default and the point next to it."""
    v = spec.values
    i = int(np.argmin(np.abs(v - spec.default)))
    keep = sorted({0, len(v) - 1, i, min(i + 1, len(v) - 1)})
    return v[keep]


# ------------------------------------------------------------------------------------ variants
def base_scene() -> Scene:
    """The default ``tethered_wing`` scene with a one-element tether (the LQR's and environments' model)."""
    return load_scene(SCENE, elements_per_piece=1)


def make_variant(base: Scene, *, attachment=None, aero_scale: dict[str, float] | None = None,
                 v0: float | None = None, piece_length: float | None = None) -> Scene:
    """``base`` rebuilt with one or more parameters changed.

    Parameters
    ----------
    base : Scene                     a single-wing scene (from :func:`base_scene` or ``load_scene``)
    attachment : array (3,), optional  cable attachment point from the CG, body axes (x fwd, z down) [m]
    aero_scale : dict, optional      column name (``params.AERO_COLUMNS``) -> factor [-] applied to the whole
                                     column of the aerodynamic table (all angles of attack)
    v0 : float, optional             wind speed at the top of the boundary layer [m/s]
    piece_length : float, optional   unstretched tether length [m]

    The assembly is built again with :func:`~laddermill_gym.model.builders.build_chain` because the cable elements
    carry their own copy of the attachment point.
    """
    asm = base.assembly
    if asm.n_wings != 1 or len(asm.wing_types) != 1:
        raise ValueError(f"make_variant: scene {base.name} must have exactly one wing, it has {asm.n_wings}")
    wing = asm.wing_types[0]
    if attachment is not None:
        att = np.asarray(attachment, dtype=float).reshape(-1)
        if att.shape != (3,) or not np.all(np.isfinite(att)):
            raise ValueError(f"make_variant: attachment must be 3 finite numbers [m], got {attachment!r}")
        wing = dataclasses.replace(wing, attachment=att)
    if aero_scale:
        values = wing.aero.values.copy()
        for col, factor in aero_scale.items():
            if col not in AERO_INDEX:
                raise ValueError(f"make_variant: unknown aerodynamic column {col!r}; known: {sorted(AERO_INDEX)}")
            if not math.isfinite(factor):
                raise ValueError(f"make_variant: scale of {col} must be finite, got {factor!r}")
            values[:, AERO_INDEX[col]] *= factor
        wing = dataclasses.replace(wing, aero=dataclasses.replace(wing.aero, values=values))
    wind = asm.wind
    if v0 is not None:
        if not (math.isfinite(v0) and v0 > 0):
            raise ValueError(f"make_variant: v0 must be a positive wind speed [m/s], got {v0!r}")
        wind = dataclasses.replace(wind, v0=float(v0))
    length = base.piece_length
    if piece_length is not None:
        if not (math.isfinite(piece_length) and piece_length > 0):
            raise ValueError(f"make_variant: piece_length must be a positive length [m], got {piece_length!r}")
        length = float(piece_length)
    names = list(base.ground_points)
    epp = len(base.layout.piece_elements[0])
    new_asm, layout = build_chain(
        (wing,), asm.wing_type_index, length, epp, base.cable, asm.fixed_points, names.index(base.start),
        None if base.end is None else names.index(base.end), wind, dim=asm.dim, sag=asm.sag,
        cable_aero=asm.cable_aero, gravity=asm.gravity)
    return base.replace(assembly=new_asm, layout=layout, piece_length=length)


def _variant_for(base: Scene, name: str, value: float) -> Scene:
    wing = base.assembly.wing_types[0]
    if name == "attach_x":
        return make_variant(base, attachment=[value, wing.attachment[1], wing.attachment[2]])
    if name == "attach_z":
        return make_variant(base, attachment=[wing.attachment[0], wing.attachment[1], value])
    if name == "weathercock":
        return make_variant(base, aero_scale=dict.fromkeys(WEATHERCOCK_COLUMNS, value))
    if name == "fin":
        return make_variant(base, aero_scale=dict.fromkeys(FIN_COLUMNS, value))
    if name == "dihedral":
        return make_variant(base, aero_scale=dict.fromkeys(DIHEDRAL_COLUMNS, value))
    if name == "wind":
        return make_variant(base, v0=value)
    if name == "tether":
        return make_variant(base, piece_length=value)
    raise ValueError(f"unknown sweep {name!r}")


# ------------------------------------------------------------------------------------ analysis
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
        return getattr(evaluate(_variant_for(base, name, v), v), quantity)

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
    rel = x[:3] - scene.ground_points[scene.start]
    elevation = math.degrees(math.atan2(-rel[2], math.hypot(rel[0], rel[1])))
    lo, hi = scene.assembly.wing_types[0].control_limits[0]
    return VariantResult(float(value), max_real, period, osc_real, math.degrees(u[0]), elevation, ev,
                         elevator_in_limits=bool(lo <= u[0] <= hi))


def run_sweep(base: Scene, spec: SweepSpec) -> SweepResult:
    """Evaluate every value of ``spec`` (one parameter changed at a time from ``base``)."""
    return SweepResult(spec, tuple(evaluate(_variant_for(base, spec.name, float(v)), float(v)) for v in spec.values))


# ------------------------------------------------------------------------------------ output
def format_table(results: list[SweepResult], crossings: dict[str, dict[str, list[float]]] | None = None) -> str:
    """Text table: one line per variant (value, largest real part [1/s], period [s], growth rate of the
    oscillation [1/s], time to double [s], trim elevator [deg], tether elevation [deg]); ``crossings`` maps a
    sweep name to {quantity: parameter values where it is zero} (from :func:`sign_changes`)."""
    lines = ["(* default; ! trim elevator outside the wing's control limits)"]
    for res in results:
        lines.append(f"\n{res.spec.name}: {res.spec.label} (default {res.spec.default:.4g})")
        lines.append("     value   max Re [1/s]  period [s]  osc Re [1/s]  t2x [s]  elevator [deg]  elevation [deg]")
        for v in res.variants:
            mark = " *" if math.isclose(v.value, res.spec.default, rel_tol=1e-9, abs_tol=1e-12) else "  "
            if v.error:
                lines.append(f"{v.value:10.4g}{mark}  trim failed: {v.error[:80]}")
                continue
            t2 = math.log(2) / v.max_real if v.max_real > 0 else float("inf")
            flag = " " if v.elevator_in_limits else "!"
            lines.append(f"{v.value:10.4g}{mark} {v.max_real:12.4f} {v.period:11.2f} {v.osc_real:13.4f} {t2:8.1f} "
                         f"{v.elevator_deg:14.2f}{flag} {v.elevation_deg:16.1f}")
        for quantity, label in (("max_real", "max Re"), ("osc_real", "Re of the slow oscillation")):
            changes = (crossings or {}).get(res.spec.name, {}).get(quantity, [])
            if changes:
                lines.append(f"  {label} = 0 at {res.spec.name} = " + ", ".join(f"{c:.3g}" for c in changes))
    return "\n".join(lines)


def plot_sweeps(results: list[SweepResult], out: Path) -> Path:
    """One panel per sweep: largest real part of the lateral eigenvalues [1/s] versus the parameter, with
    the zero line and the default value marked. Saved to ``out`` (png, pdf or svg)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from laddermill_gym.plotting import save_figure

    n = len(results)
    ncol = min(3, n)
    nrow = math.ceil(n / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.3 * nrow), squeeze=False)
    for ax, res in zip(axes.flat, results, strict=False):
        x, y = res.values, res.max_real
        ax.axhline(0.0, color="k", lw=0.8)
        ax.plot(x, y, "o-", color="C0", label="max Re")
        osc = np.array([v.osc_real for v in res.variants])
        ax.plot(x, osc, "s--", color="C1", ms=3, lw=0.8, label="Re of slow oscillation")
        ax.axvline(res.spec.default, color="C3", ls=":", lw=1.2, label="default")
        at = np.isclose(x, res.spec.default, rtol=1e-9, atol=1e-12)
        ax.plot(x[at], y[at], "*", color="C3", ms=12)
        bad = ~np.isfinite(y)
        if bad.any():
            ax.plot(x[bad], np.zeros(bad.sum()), "x", color="C3", label="trim failed")
        ax.set_xlabel(res.spec.label)
        ax.set_ylabel("largest Re(lambda) [1/s]")
        ax.grid(alpha=0.3)
    for ax in list(axes.flat)[n:]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("tethered_wing: open-loop lateral eigenvalues, one parameter at a time (> 0: unstable)")
    return save_figure(fig, out)


def _parse_sweeps(text: str | None, known: list[str]) -> list[str]:
    if text is None:
        return known
    names = [t.strip() for t in text.split(",") if t.strip()]
    bad = [n for n in names if n not in known]
    if not names or bad:
        raise ValueError(f"--sweeps: unknown or empty sweep names {bad or text!r}; choose from {known}")
    return names


def main(argv: list[str] | None = None) -> list[SweepResult]:
    """Command line: run the sweeps, print the table, save the figure; returns the results."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(DEFAULT_OUT), help="figure file (.png, .pdf or .svg)")
    ap.add_argument("--quick", action="store_true", help="4 points per sweep instead of 7")
    ap.add_argument("--sweeps", default=None,
                    help="comma-separated subset of: " + ",".join(SWEEP_NAMES))
    args = ap.parse_args(argv)
    out = Path(args.out)
    if out.suffix.lower() not in _FIGURE_SUFFIXES:
        raise ValueError(f"--out {args.out!r}: the figure file must end in one of {_FIGURE_SUFFIXES}")
    if out.exists() and out.is_dir():
        raise ValueError(f"--out {args.out!r} is a directory; give a file name")
    names = _parse_sweeps(args.sweeps, list(SWEEP_NAMES))
    t0 = time.perf_counter()
    base = base_scene()
    specs = sweep_specs(base, quick=args.quick)
    ref = evaluate(base, float("nan"))
    if ref.error:
        raise RuntimeError(f"the default scene does not trim: {ref.error}")
    print(f"default: max Re = {ref.max_real:.4f} 1/s, slow oscillation period {ref.period:.2f} s")
    print("default lateral eigenvalues [1/s]: " + ", ".join(f"{e.real:.4f}{e.imag:+.4f}j" for e in ref.eigenvalues))
    results = [run_sweep(base, specs[n]) for n in names]
    crossings = {r.spec.name: {q: sign_changes(base, r, q) for q in ("max_real", "osc_real")} for r in results}
    print(format_table(results, crossings))
    plot_sweeps(results, out)
    print(f"\nwrote {out} ({time.perf_counter() - t0:.1f} s)")
    return results


if __name__ == "__main__":
    main()
