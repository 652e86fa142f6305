"""The mill's target of the kernel warm-up (``envs/kernel_warmup.py``, ``envs/laddermill/kernel_warmup.py``, issue
32 point 1): :func:`compile_for`, called in the second process (``python -m laddermill_gym.envs.warmup_run``; ``python
-m laddermill_gym.envs.laddermill.warmup_child`` reads the arguments pickled on stdin too) with the arguments of a
:class:`~laddermill_gym.envs.laddermill.task.MillTask`, compiles the in-plane static equilibrium's kernel and prints a
line (``kernel_warmup.STATICS_DONE``), then builds that task around :func:`stand_in_point` and resets and steps it
once, so that numba compiles the kernels those calls reach and writes them to its on-disk cache for the process that
started it."""

from __future__ import annotations

import math
import pickle
import sys

import numpy as np

__all__ = ["compile_for", "stand_in_point"]


def stand_in_point(scene, cable_speed: float):
    """An :class:`~laddermill_gym.envs.laddermill.operating_point.OperatingPoint` of the 3D ``scene``'s shapes for
    compiling only: the state zero but for unit quaternions, zero controls, ``cable_speed`` [m/s] > 0, unit powers
    and a two-sample orbit. Its values mean nothing and are never used for a result."""
    from laddermill_gym.envs.laddermill.operating_point import OperatingPoint, scene_digest
    from laddermill_gym.kernels.contract import B3_QUAT, B3_SIZE, N_CONTROLS

    a = scene.assembly
    n, l0 = a.n_wings, a.station.piece_length
    state = np.zeros(a.state_size)
    state[B3_QUAT: B3_SIZE * n: B3_SIZE] = 1.0
    arrays = dict(state=state, controls=np.zeros(N_CONTROLS * n), orbit_moved=np.array([0.0, l0]),
                  orbit_positions=np.zeros((2, n, 3)), alpha_range_rad=np.zeros(2))
    for v in arrays.values():
        v.setflags(write=False)
    return OperatingPoint(cable_speed=cable_speed, period_s=l0 / cable_speed, power_W=1.0, mechanical_power_W=1.0,
                          reference_power_W=1.0, tension_first_N=1.0, tension_last_N=1.0, converged=True,
                          t_settle_s=0.0, note="a stand-in for compiling the kernels (kernel_warmup.py)",
                          scene_digest=scene_digest(scene), **arrays)


def compile_for(task_kwargs: dict) -> None:
    """Compile the static equilibrium's kernel of the task's in-plane scene (``kernel_warmup.compile_statics``) and
    print ``kernel_warmup.STATICS_DONE``, then build the task of ``task_kwargs`` around :func:`stand_in_point`,
    reset every copy and take one step with the zero action: numba compiles (and caches) the kernels those calls
    reach."""
    from laddermill_gym.envs.laddermill.kernel_warmup import STATICS_DONE, compile_statics
    from laddermill_gym.envs.laddermill.operating_point import mill_scene
    from laddermill_gym.envs.laddermill.task import MillTask
    from laddermill_gym.ladder.scene import options_key

    name = str(task_kwargs.get("scene", "laddermill"))
    options = options_key({k: v for k, v in dict(task_kwargs.get("scene_options") or {}).items() if k != "dimension"})
    compile_statics(name, options)
    print(STATICS_DONE, flush=True)  # the first process waits for it before its static equilibrium
    scene = mill_scene(name, options, 3)
    speed = float(scene.assembly.station.speed_values[-1])
    op = stand_in_point(scene, speed if math.isfinite(speed) and speed > 0 else 1.0)
    task = MillTask(**dict(task_kwargs, operating_point=op))
    B = task.n_copies
    task.reset(np.ones(B, dtype=bool), [np.random.default_rng(0) for _ in range(B)])
    task.step(np.zeros((B, task.n_actions)))


def main() -> int:
    """The warm-up process: the task's arguments pickled on stdin."""
    import warnings

    warnings.simplefilter("ignore")
    compile_for(pickle.loads(sys.stdin.buffer.read()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
