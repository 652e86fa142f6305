"""``laddermill stable-step SCENE``: the largest stable step of the explicit methods (RK4, DP5(4)) of a scene from the
eigenvalues of its Jacobian at the initial state, or (``--after-transfer``, a moving cable) right after the first wing
transfer, when the station's first element is shortest and stiffest. The estimate itself lives in
``sim/stable_step.py``."""

from __future__ import annotations

import argparse
import math

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
from laddermill_gym.studies.commands import UsageError, check_number, run_subcommand


def add_parser(sub) -> argparse.ArgumentParser:
    p = sub.add_parser("stable-step", help="estimate the largest stable explicit step of a scene")
    p.add_argument("scene", help="scene name or YAML path, or 'roberts_flying_model' (the rotorcraft)")
    p.add_argument("--elements-per-piece", type=int, default=None, help="override the scene's cable division")
    p.add_argument("--after-transfer", action="store_true",
                   help="step the scene at its own method and step until its first wing transfer (a moving cable: "
                        "the mill's first comes after some 50 s, 5000 RK4 steps) and estimate there")
    p.set_defaults(func=_cmd)
    return p


def _cmd(args) -> int:
    from laddermill_gym.studies.numerics.scenes import (
        CRAFT_NAMES,
        build_simulator,
        check_scene_names,
        refuse_scene_kinds,
    )

    check_scene_names([args.scene])
    refuse_scene_kinds([args.scene], "scene", {"pointmass": "the point-mass string's explicit step limit is "
                                                            "l0 / c (sim/pointmass.py explicit_stable_dt)"})
    check_number("--elements-per-piece", args.elements_per_piece, low=1, integer=True, strict=False)
    # the estimate needs no step that works: a scene whose RK4 step is too long for its cable (the case this command
    # is for) is loaded with DP5(4); --after-transfer steps the scene at its own method
    craft = args.scene in CRAFT_NAMES
    sim = build_simulator(args.scene, elements_per_piece=args.elements_per_piece,
                          scene_method=None if (args.after_transfer or craft) else "dp54")
    print(f"{args.scene}: {sim.n_state} states, dt {sim.settings.dt:g} s")
    if args.after_transfer:
        t = step_to_first_transfer(sim)
        print(f"  after the first wing transfer, at t = {t:.2f} s:")
    for m in ("rk4", "dp54"):
        print("  " + str(estimate_stable_step(sim, m)))
    return 0


def step_to_first_transfer(sim, t_max: float = 300.0) -> float:
    """Step ``sim`` (a scene with a moving cable) at its own method and step until the station's transfer count
    first changes; return that time [s]. Raises ValueError naming the scene's state when none comes by ``t_max``
    [s] or the scene has no station (a UsageError: the command prints it as one line)."""
    from laddermill_gym.ladder.periodic import advance_to_transfer

    try:
        advance_to_transfer(sim, int(math.ceil((t_max - sim.t) / sim.settings.dt)))
    except (ValueError, RuntimeError) as err:  # no station; no transfer within t_max
        raise UsageError(f"--after-transfer: {err}") from None
    return float(sim.t)


def main(argv=None) -> int:
    return run_subcommand(add_parser, "stable-step", argv)


if __name__ == "__main__":
    raise SystemExit(main())
