"""Parameter study of the lateral (sideways) instability of one wing on a tether (scene ``tethered_wing``).

Run ``python -m laddermill_gym.studies.lateral.lateral_study [--out laddermill_gym/docs/figures/lateral_study.png]
[--quick] [--sweeps NAME,NAME,...] [--workers N] [--ray auto|local|ADDRESS]``: every variant and every
bisection is a task of :mod:`laddermill_gym.studies.parallel` (serial by default; the same table either way).

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

This module is the command and re-exports the study's names; the code lives in ``lateral_variants`` (sweeps and
scene variants), ``lateral_analysis`` (eigenvalues, sweeps, sign changes) and ``lateral_output`` (table, figure).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from laddermill_gym.studies.commands import writable_file
from laddermill_gym.studies.lateral.lateral_analysis import (
    SweepResult,
    VariantResult,
    evaluate,
    lateral_eigenvalues,
    locate_sign_change,
    mode_summary,
    run_sweep,
    run_sweeps,
    sign_changes,
)
from laddermill_gym.studies.lateral.lateral_output import format_table, plot_sweeps
from laddermill_gym.studies.lateral.lateral_variants import (
    DIHEDRAL_COLUMNS,
    FIN_COLUMNS,
    SCENE,
    SWEEP_NAMES,
    WEATHERCOCK_COLUMNS,
    SweepSpec,
    base_scene,
    make_variant,
    sweep_specs,
)
from laddermill_gym.studies.parallel import add_arguments, check_arguments

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
    "run_sweeps",
    "format_table",
    "plot_sweeps",
    "main",
]

DEFAULT_OUT = Path("results/lateral_study.png")  # the docs' figure: --out laddermill_gym/docs/figures/...
_FIGURE_SUFFIXES = (".png", ".pdf", ".svg")


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
    add_arguments(ap)
    args = ap.parse_args(argv)
    check_arguments(args, ap.prog)
    out = writable_file(args.out, "--out", _FIGURE_SUFFIXES)
    names = _parse_sweeps(args.sweeps, list(SWEEP_NAMES))
    t0 = time.perf_counter()
    base = base_scene()
    specs = sweep_specs(base, quick=args.quick)
    ref = evaluate(base, float("nan"))
    if ref.error:
        raise RuntimeError(f"the default scene does not trim: {ref.error}")
    print(f"default: max Re = {ref.max_real:.4f} 1/s, slow oscillation period {ref.period:.2f} s")
    print("default lateral eigenvalues [1/s]: " + ", ".join(f"{e.real:.4f}{e.imag:+.4f}j" for e in ref.eigenvalues))
    results, crossings = run_sweeps(specs, names, workers=args.workers, ray=args.ray)
    print(format_table(results, crossings))
    plot_sweeps(results, out)
    print(f"\nwrote {out} ({time.perf_counter() - t0:.1f} s)")
    return results


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    raise SystemExit(run_guarded("lateral_study", lambda: main() and 0))
