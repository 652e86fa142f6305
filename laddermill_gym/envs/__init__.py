"""Gymnasium environments: tasks of B copies, single and native vector envs, the SB3 adapter; one sub-package per
system beside the wing envs. Imports the systems, ``sim``, ``model``, ``kernels`` and ``atmosphere``, never ``control``.

Registered on ``import laddermill_gym``:

* ``laddermill_gym/TetheredWing-v0``: one wing on a 100 m tether (scene ``tethered_wing`` with one cable
  element, one linearly implicit ROS34PW2 step of 0.05 s per 20 Hz control period, 300 s episodes, the paper's
  0.01 rad direction step at 1 s);
* ``laddermill_gym/TetheredWing-v1``: TetheredWing-v0 stepped by two RK4 steps of 25 ms per control period instead
  of one ROS34PW2 step of 50 ms (its rewards within 3e-4 of RK4 at 3.125 ms, v0's 0.056;
  docs/scorecard_physics_step.md), :class:`~laddermill_gym.envs.tethered_wing_v1.TetheredWingV1Env`;
* ``laddermill_gym/LadderChain-v0``: the paper's 101-wing chain between two ground points (scene
  ``ladder_chain``, its own RK4 step, 20 Hz control, 120 s episodes), per-wing actions by default;
* ``laddermill_gym/LadderChain-v1``: LadderChain-v0 stepped by three RK4 steps of 1/60 s per control period instead
  of four of 12.5 ms (its rewards as close to RK4 at a quarter of v0's step; docs/benchmarks.md),
  :class:`~laddermill_gym.envs.ladder_chain_v1.LadderChainV1Env`;
* ``laddermill_gym/LadderMill-v0``: the paper's laddermill, 101 wings on the endless cable moving through the
  ground generator (scene ``laddermill``, 20 Hz control of the tails by slot, 120 s episodes from the periodic
  stationary motion, the 0.01 rad direction step at 1 s), :class:`~laddermill_gym.envs.laddermill.env.LadderMillEnv`;
* ``laddermill_gym/LadderMill-v1``: the same mill with the v1 wing (scene ``laddermill_v1``, 152.9 kW at 2 m/s,
  docs/wing_data.md) and tail actions at a fifth of the surfaces' half ranges (``authority=0.2``), so random actions
  survive seconds, :class:`~laddermill_gym.envs.laddermill.env_v1.LadderMillV1Env`;
* ``laddermill_gym/LadderMill-v2``: the same mill with the v2 wing, whose lift falls with its air speed (scene
  ``laddermill_v2``: periodic in plane at 1-5 m/s, 102.2 kW at 2 m/s; docs/wing_data.md) and v1's ``authority=0.2``,
  :class:`~laddermill_gym.envs.laddermill.env_v2.LadderMillV2Env`;
* ``laddermill_gym/LadderMill-v3``: LadderMill-v2 stepped by one linearly implicit ROS2 step per control period
  (``physics_step="ros2"``: its rewards and power as close to RK4 at a quarter of v2's step as v2's own; docs/
  benchmarks.md), :class:`~laddermill_gym.envs.laddermill.env_v3.LadderMillV3Env`;
* ``laddermill_gym/PumpingKite-v0``: Lansdorp et al.'s (2008) pumping kite, one wing on a 300 m tether wound on a
  winch (configs/pumping/pumping_kite.yaml, 20 Hz control of the tails and the winch speed, 400 s episodes of about
  two reel-out / reel-in cycles, the 0.01 rad direction step at 1 s), :class:`~laddermill_gym.envs.pumping.env.
  PumpingKiteEnv`;
* ``laddermill_gym/PumpingKite-v1``: the same pumping kite flown crosswind (figure eights during reel-out): v0's
  physics and actions, a flight controller's observation (position on the wind window, course, bank, apparent wind,
  the cycle's fraction), net electrical power over 10 kW with sideslip and tether-force penalties, 600 s episodes,
  :class:`~laddermill_gym.envs.pumping.crosswind_env.CrosswindKiteEnv`;
* ``laddermill_gym/PointMassChain-v0``: the paper's 101-wing chain (scene ``ladder_chain``) at the point-mass
  fidelity of Podgaets & Ockels (2007): point-mass kites whose pitch and roll are the actions, one 70 m element per
  piece, the implicit point-mass step of 0.025 s, 20 Hz control, 120 s episodes from the chain settled for 600 s,
  the 0.01 rad direction step at 1 s), :class:`~laddermill_gym.envs.pointmass.env.PointMassEnv`;
* ``laddermill_gym/Rotorcraft-v0``: Roberts' tethered twin-rotor craft (configs/rotorcraft/, its config's step:
  one ROS34PW2 step of 50 ms, 20 Hz control of collective and differential collective, 120 s episodes, a 0.01 rad
  direction step at 1 s), :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv`;
* ``laddermill_gym/Rotorcraft-v1``: v0 whose episode also ends when a retreating blade tip passes the craft's 13 deg
  blade-incidence limit (the rotor model's lift is linear, without stall: past it the model overstates the power),
  :class:`~laddermill_gym.envs.rotorcraft.env_v1.RotorcraftV1Env`.

Every environment has a native batched ``vector_entry_point`` (:class:`~laddermill_gym.envs.wing_env.WingVectorEnv`,
:class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftVectorEnv`): one compiled kernel steps all copies,
``gymnasium.make_vec(id, num_envs=n, vectorization_mode="vector_entry_point")`` (PointMassChain-v0's
:class:`~laddermill_gym.envs.pointmass.env.PointMassVectorEnv` steps its copies one after another by the compiled
point-mass kernels within one call). Each is a task with B copies (:class:`~laddermill_gym.envs.task.WingTask`,
:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`, :class:`~laddermill_gym.envs.pointmass.task.PointMassTask`
...), whose arguments are the environment's (:func:`env_arguments`).

``gymnasium.make(id, **kwargs)`` and ``make_vec`` build the env from the id's registered defaults merged with
``kwargs`` (:func:`registered_arguments`): a dict-valued argument is merged key by key at every depth, so
``scene_options={"overrides": {"wind": {"v0": 10.0}}}`` keeps TetheredWing-v0's registered ``scene_options``.
Gymnasium's entry points are ``envs/registration.py``'s, which build the classes of :data:`ENTRY_POINTS` so.
"""

import copy
import importlib
import inspect
from collections.abc import Mapping

__all__ = ["ActionError", "DirectionStep", "OneMinusCosineGust", "RandomPerturbation", "Schedule", "FAILURES",
           "RewardConfig", "TerminationConfig", "WingTask", "WingEnv", "WingVectorEnv", "RotorcraftEnv",
           "RotorcraftVectorEnv", "LadderMillEnv", "LadderMillVectorEnv", "PumpingKiteEnv", "PumpingKiteVectorEnv",
           "PointMassEnv", "PointMassVectorEnv", "ENV_IDS", "ENTRY_POINTS", "register_envs", "task_class",
           "env_arguments", "merge_arguments", "registered_arguments", "PHYSICS_STEP_OF", "same_task"]

#: the public names of the systems' modules, imported on first use (PEP 562): ``import laddermill_gym`` registers
#: the ids without importing any env, so a process that makes one env pays only for that env's modules (the
#: warm start, issue 32 point 1: the mill's and the pumping kite's modules and the scipy solver these import)
_LAZY = {
    **dict.fromkeys(("DirectionStep", "OneMinusCosineGust", "RandomPerturbation", "Schedule"),
                    "laddermill_gym.atmosphere.disturbances"),
    "ActionError": "laddermill_gym.envs.actions",
    **dict.fromkeys(("FAILURES", "RewardConfig", "TerminationConfig", "WingTask"), "laddermill_gym.envs.task"),
    **dict.fromkeys(("WingEnv", "WingVectorEnv"), "laddermill_gym.envs.wing_env"),
    **dict.fromkeys(("RotorcraftEnv", "RotorcraftVectorEnv"), "laddermill_gym.envs.rotorcraft.env"),
    **dict.fromkeys(("LadderMillEnv", "LadderMillVectorEnv"), "laddermill_gym.envs.laddermill.env"),
    **dict.fromkeys(("PumpingKiteEnv", "PumpingKiteVectorEnv"), "laddermill_gym.envs.pumping.env"),
    **dict.fromkeys(("PointMassEnv", "PointMassVectorEnv"), "laddermill_gym.envs.pointmass.env"),
}


def __getattr__(name: str):
    """The names of :data:`_LAZY` are imported on first use: importing the package (and so any env) must not load
    the other systems' modules and kernels (a scene pays only for what it uses)."""
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


#: Registered environment ids and their default arguments (units: seconds).
ENV_IDS: dict[str, dict] = {
    # one element and one ROS34PW2 step (docs/numerics.md) per 50 ms control period: RK4 at 50 ms, the env's step
    # before, is past its stability limit once the wind stiffens the tether (after a 5x wind step the LQR episode
    # ended at 1.3 s with alpha = -86 deg from a corrupted state; it flies 20 s with ROS34PW2 at 50 ms and with RK4
    # at 10 ms), tests/test_env_substeps.py
    "laddermill_gym/TetheredWing-v0": dict(scene="tethered_wing",
                                           scene_options={"elements_per_piece": 1, "method": "ros34pw2"},
                                           physics_dt=0.05, control_dt=0.05, episode_time=300.0),
    # issue 31 point 4: v0 on two RK4 steps of 25 ms per control period. Over 10 s of seeded actions its largest
    # reward error against RK4 at 3.125 ms is 0.00027 (v0's ROS34PW2 at 50 ms: 0.056), and on the gust suite the
    # LQR's and the shipped policy's lost episodes are the reference's (v0's step changes them); RK4's estimated
    # stable step at the trim is 0.11 s, and the env steps finer in stronger wind (envs/physics_step.py).
    # About v0's cost: 2 x 4 right-hand sides against ROS34PW2's 4 and two Jacobians (docs/scorecard_physics_step.md)
    "laddermill_gym/TetheredWing-v1": dict(scene="tethered_wing", scene_options={"elements_per_piece": 1},
                                           physics_step="rk4", physics_dt=0.025, control_dt=0.05, episode_time=300.0),
    "laddermill_gym/LadderChain-v0": dict(scene="ladder_chain", control_dt=0.05, episode_time=120.0,
                                          groups="per_wing"),
    # issue 32 point 3: v0 on three RK4 steps per control period, physics_dt 0.05 / 3 s = 1/60 s: the longest RK4
    # step dividing the 50 ms period within ENV_STEP_MARGIN (0.9) of RK4's estimated stable step at the chain's
    # equilibrium (24.6 ms; 25 ms is past it, envs/physics_step.py). Over 10 s of seeded actions its largest reward
    # error against RK4 at 3.125 ms is 0.0041 (v0's 0.0016), its mean reward the reference's; every W step once per
    # period lowered the mean reward by 4-5 % (docs/benchmarks.md; tests/test_chain_v1.py)
    "laddermill_gym/LadderChain-v1": dict(scene="ladder_chain", control_dt=0.05, episode_time=120.0,
                                          groups="per_wing", physics_step="rk4", physics_dt=0.05 / 3),
    "laddermill_gym/Rotorcraft-v0": dict(craft="roberts_flying_model", control_dt=0.05, episode_time=120.0),
    # v0 with the rotor model's validity as a termination: a retreating blade tip past the craft's 13 deg
    # blade-incidence limit (Roberts; configs/rotors/) ends the episode. v0's linear, stall-free lift paid a policy
    # for flying past it (the shipped PPO policy spends a third of its steps there; docs/rotorcraft.md)
    "laddermill_gym/Rotorcraft-v1": dict(craft="roberts_flying_model", control_dt=0.05, episode_time=120.0,
                                         termination={"blade_stall": True}),
    "laddermill_gym/LadderMill-v0": dict(scene="laddermill", control_dt=0.05, episode_time=120.0),
    # issue 30's v1 wing (scene laddermill_v1: periodic in plane at 2 m/s, 152.9 kW) and issue 31 point 3's
    # learnable default: authority 0.2 [-] of each surface's half range per unit action (random actions survive a
    # median 6.75 s over 10 seeds against 0.82 s at 1.0; envs/laddermill/env_v1.py, tests/test_laddermill_v1.py)
    "laddermill_gym/LadderMill-v1": dict(scene="laddermill_v1", control_dt=0.05, episode_time=120.0,
                                         authority=0.2),
    # issue 30's v2 wing (scene laddermill_v2: periodic in plane at 1-5 m/s, 102.2 kW at 2 m/s; its 200 s ramp is
    # the scene's, the default settle finds the periodic motion at t = 975 s) with v1's authority 0.2 [-]
    # (envs/laddermill/env_v2.py, tests/test_laddermill_v2.py)
    "laddermill_gym/LadderMill-v2": dict(scene="laddermill_v2", control_dt=0.05, episode_time=120.0,
                                         authority=0.2),
    # issue 32 point 3: v2 with one ROS2 step per control period: over 10 s of seeded actions its rewards and power
    # are as close to RK4 at a quarter of v2's step as v2's RK4 (largest reward error 0.0052 against 0.0065); the
    # matrix kept 4 periods (faster) biased the power by -2 % (docs/benchmarks.md; tests/test_fast_ids.py) and ended
    # the mill at 5 m/s on the breaking load in the review's runs of 2026-11-30. No W-step chain id: every W step at
    # 50 ms lowered the chain's open-loop mean reward by 4-5 % (LadderChain-v1 registers RK4 at 1/60 s instead).
    "laddermill_gym/LadderMill-v3": dict(scene="laddermill_v2", control_dt=0.05, episode_time=120.0,
                                         authority=0.2, physics_step="ros2"),
    "laddermill_gym/PumpingKite-v0": dict(config="pumping_kite", control_dt=0.05, episode_time=400.0),
    # crosswind pumping (issue 29): v0's kite; 600 s, about two cycles of the crosswind controller (267 s each)
    "laddermill_gym/PumpingKite-v1": dict(config="pumping_kite", control_dt=0.05, episode_time=600.0),
    # ladder_chain at the point-mass fidelity. element_length 70 m: one element per 70 m piece, as LadderChain-v0
    # (elements_per_piece 1, Meijaard et al. 1999); its settled base tension 178.7 kN against 178.9 kN at 1 m
    # (docs/pointmass.md, "Between fidelities"). method implicit, dt 0.025 s: the explicit step must stay below
    # 7.31 ms (l0/c = 8.25 ms, c = sqrt(EA/mu) = 8485 m/s, Dyneema 25 mm, less its damping;
    # sim.pointmass.explicit_stable_dt), 7 steps per
    # 50 ms period; the implicit one ran 60 s from the rigid start at 0.05 s too (at 7 m elements it failed
    # there, 0.025 s held), 2 steps per period, kite positions within 0.5 m of 5 ms steps after 20 s. control_dt
    # 0.05 s (20 Hz) and episode_time 120 s: LadderChain-v0's. settle_time 600 s: from the rigid equilibrium the
    # point-mass chain moves ~800 m and comes to rest (node speeds 0.14 m/s at 400 s, measured).
    "laddermill_gym/PointMassChain-v0": dict(scene="ladder_chain", scene_options={"element_length": 70.0,
                                             "method": "implicit", "dt": 0.025}, settle_time=600.0,
                                             control_dt=0.05, episode_time=120.0, groups="per_kite"),
}
_WING = ("laddermill_gym.envs.wing_env:WingEnv", "laddermill_gym.envs.wing_env:WingVectorEnv",
         "laddermill_gym.envs.task:WingTask")
#: Entry points of every registered id: (single env, native vector env, the task with B copies behind both).
ENTRY_POINTS: dict[str, tuple[str, str, str]] = {
    "laddermill_gym/TetheredWing-v0": _WING,
    "laddermill_gym/TetheredWing-v1": ("laddermill_gym.envs.tethered_wing_v1:TetheredWingV1Env",
                                       "laddermill_gym.envs.tethered_wing_v1:TetheredWingV1VectorEnv",
                                       "laddermill_gym.envs.task:WingTask"),
    "laddermill_gym/LadderChain-v0": _WING,
    "laddermill_gym/LadderChain-v1": ("laddermill_gym.envs.ladder_chain_v1:LadderChainV1Env",
                                      "laddermill_gym.envs.ladder_chain_v1:LadderChainV1VectorEnv",
                                      "laddermill_gym.envs.task:WingTask"),
    "laddermill_gym/Rotorcraft-v0": ("laddermill_gym.envs.rotorcraft.env:RotorcraftEnv",
                                     "laddermill_gym.envs.rotorcraft.env:RotorcraftVectorEnv",
                                     "laddermill_gym.envs.rotorcraft.task:CraftTask"),
    "laddermill_gym/Rotorcraft-v1": ("laddermill_gym.envs.rotorcraft.env_v1:RotorcraftV1Env",
                                     "laddermill_gym.envs.rotorcraft.env_v1:RotorcraftV1VectorEnv",
                                     "laddermill_gym.envs.rotorcraft.task:CraftTask"),
    "laddermill_gym/LadderMill-v0": ("laddermill_gym.envs.laddermill.env:LadderMillEnv",
                                     "laddermill_gym.envs.laddermill.env:LadderMillVectorEnv",
                                     "laddermill_gym.envs.laddermill.task:MillTask"),
    "laddermill_gym/LadderMill-v1": ("laddermill_gym.envs.laddermill.env_v1:LadderMillV1Env",
                                     "laddermill_gym.envs.laddermill.env_v1:LadderMillV1VectorEnv",
                                     "laddermill_gym.envs.laddermill.task:MillTask"),
    "laddermill_gym/LadderMill-v2": ("laddermill_gym.envs.laddermill.env_v2:LadderMillV2Env",
                                     "laddermill_gym.envs.laddermill.env_v2:LadderMillV2VectorEnv",
                                     "laddermill_gym.envs.laddermill.task:MillTask"),
    "laddermill_gym/LadderMill-v3": ("laddermill_gym.envs.laddermill.env_v3:LadderMillV3Env",
                                     "laddermill_gym.envs.laddermill.env_v3:LadderMillV3VectorEnv",
                                     "laddermill_gym.envs.laddermill.task:MillTask"),
    "laddermill_gym/PumpingKite-v0": ("laddermill_gym.envs.pumping.env:PumpingKiteEnv",
                                      "laddermill_gym.envs.pumping.env:PumpingKiteVectorEnv",
                                      "laddermill_gym.envs.pumping.task:PumpingTask"),
    "laddermill_gym/PumpingKite-v1": ("laddermill_gym.envs.pumping.crosswind_env:CrosswindKiteEnv",
                                      "laddermill_gym.envs.pumping.crosswind_env:CrosswindKiteVectorEnv",
                                      "laddermill_gym.envs.pumping.crosswind_task:CrosswindTask"),
    "laddermill_gym/PointMassChain-v0": ("laddermill_gym.envs.pointmass.env:PointMassEnv",
                                         "laddermill_gym.envs.pointmass.env:PointMassVectorEnv",
                                         "laddermill_gym.envs.pointmass.task:PointMassTask"),
}


#: ids that step another id's task on another physics step (scene, start, spaces and rewards the same), or end its
#: episodes by a further limit (Rotorcraft-v1: the blade incidence) -> that id: a policy trained on one of them runs
#: on the other (``control/sb3_policy.py``, ``control/shared_controller.py``)
PHYSICS_STEP_OF: dict[str, str] = {"laddermill_gym/TetheredWing-v1": "laddermill_gym/TetheredWing-v0",
                                   "laddermill_gym/LadderChain-v1": "laddermill_gym/LadderChain-v0",
                                   "laddermill_gym/Rotorcraft-v1": "laddermill_gym/Rotorcraft-v0"}


def same_task(a: str, b: str) -> bool:
    """Whether the ids ``a`` and ``b`` are the same task, perhaps on different physics steps (:data:`PHYSICS_STEP_OF`):
    a policy trained on one is given the same observations and actions on the other."""
    return PHYSICS_STEP_OF.get(a, a) == PHYSICS_STEP_OF.get(b, b)


def _check_id(env_id: str) -> None:
    if env_id not in ENV_IDS:
        raise ValueError(f"env_id = {env_id!r}: must be one of {sorted(ENV_IDS)}")


def task_class(env_id: str) -> type:
    """The task class behind the registered environment ``env_id`` (``WingTask``, ``CraftTask``, ``MillTask``,
    ``PumpingTask`` or ``PointMassTask``): its first
    argument is the number of copies, the others are the environment's."""
    _check_id(env_id)
    module, name = ENTRY_POINTS[env_id][2].split(":")
    return getattr(importlib.import_module(module), name)


def env_arguments(env_id: str) -> tuple[str, ...]:
    """The keyword arguments the registered environment ``env_id`` takes (single and vector env alike; the task's
    arguments but the number of copies and the thread-pool switch ``parallel``)."""
    return tuple(p for p in inspect.signature(task_class(env_id)).parameters if p not in ("n_copies", "parallel"))


def merge_arguments(defaults: Mapping, kwargs: Mapping) -> dict:
    """``defaults`` updated with ``kwargs`` (a new dict; neither is changed): where both hold a dict under the same
    key, the two are merged the same way, at every depth; None where the default is a dict keeps the default (the
    envs read None as "the defaults": ``termination=None`` on Rotorcraft-v1 dropped its ``blade_stall`` before); any
    other value in ``kwargs`` replaces the default."""
    out = dict(defaults)
    for key, value in kwargs.items():
        if value is None and isinstance(out.get(key), Mapping):
            continue
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merge_arguments(out[key], value)
        else:
            out[key] = value
    return out


def registered_arguments(env_id: str, kwargs: Mapping | None = None) -> dict:
    """The arguments ``gymnasium.make(env_id, **kwargs)`` builds its env with: the registered defaults
    (:data:`ENV_IDS`, deep-copied) merged with ``kwargs`` by :func:`merge_arguments`."""
    _check_id(env_id)
    return merge_arguments(copy.deepcopy(ENV_IDS[env_id]), kwargs or {})


def episode_argument_error(env_id: str, kwargs: Mapping | None = None) -> str:
    """Why ``gymnasium.make(env_id, **kwargs)`` would refuse its episode length ('' if it would not): ``episode_time``
    not a whole number of ``control_dt`` (each the argument, else the registered value, else the task's default;
    ``envs/task_base.episode_periods``). Lets a config or suite name its own file and field before building."""
    from laddermill_gym.envs.task_base import episode_periods

    args = registered_arguments(env_id, kwargs)
    params = inspect.signature(task_class(env_id)).parameters
    times = [float(args.get(k, params[k].default)) for k in ("episode_time", "control_dt")]
    try:
        episode_periods(*times)
    except (TypeError, ValueError) as err:
        return str(err)
    return ""


def register_envs() -> None:
    """Register :data:`ENV_IDS` with Gymnasium (idempotent), each id's entry points those of
    ``envs/registration.py`` (its classes of :data:`ENTRY_POINTS` built from :func:`registered_arguments`).

    No ``max_episode_steps``: the environments truncate themselves at their ``episode_time`` argument, and a
    TimeLimit wrapper fixed at registration would silently cut an episode made longer with
    ``gym.make(id, episode_time=...)``."""
    import gymnasium as gym

    for env_id, kwargs in ENV_IDS.items():
        if env_id in gym.registry:
            continue
        name = "laddermill_gym.envs.registration:" + env_id.split("/")[-1].replace("-", "_")
        gym.register(id=env_id, entry_point=name, vector_entry_point=name + "_vector", kwargs=kwargs,
                     disable_env_checker=False)
