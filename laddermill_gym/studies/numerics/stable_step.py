"""``laddermill stable-step SCENE``: the largest stable step of the explicit methods (RK4, DP5(4)) of a scene from the
eigenvalues of its Jacobian at the initial state. The estimate itself lives in ``sim/stable_step.py``."""

from __future__ import annotations

import argparse

from laddermill_gym.sim.stable_step import (  # noqa: F401  (re-exported: the studies' and tests' names)
    DENSE_MAX,
    SAFETY,
    TABLEAUX,
    StableStep,
    UnstableStepWarning,
    check_step,
    estimate_stable_step,
    jacobian_eigenvalues,
    ray_limit,
    stability_function,
)
from laddermill_gym.studies.commands import check_number, run_subcommand


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("stable-step", help="estimate the largest stable explicit step of a scene")
    p.add_argument("scene", help="scene name or YAML path, or 'roberts_flying_model' (the rotorcraft)")
    p.add_argument("--elements-per-piece", type=int, default=None, help="override the scene's cable division")
    p.set_defaults(func=_cmd)
    return p


def _cmd(args) -> int:
    from laddermill_gym.studies.numerics.scenes import build_simulator, check_scene_names

    check_scene_names([args.scene])
    check_number("--elements-per-piece", args.elements_per_piece, low=1, integer=True, strict=False)
    sim = build_simulator(args.scene, elements_per_piece=args.elements_per_piece)
    print(f"{args.scene}: {sim.n_state} states, dt {sim.settings.dt:g} s")
    for m in ("rk4", "dp54"):
        print("  " + str(estimate_stable_step(sim, m)))
    return 0


def main(argv=None) -> int:
    return run_subcommand(add_parser, "stable-step", argv)


if __name__ == "__main__":
    raise SystemExit(main())
