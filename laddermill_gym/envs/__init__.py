"""Gymnasium environments of laddermill_gym.

Registered on ``import laddermill_gym``:

* ``laddermill_gym/TetheredWing-v0``: one wing on a 100 m tether (scene ``tethered_wing`` with one cable
  element, one RK4 step of 0.05 s per 20 Hz control period, 300 s episodes, the paper's 0.01 rad direction step at 1 s);
* ``laddermill_gym/LadderChain-v0``: the paper's 101-wing chain between two ground points (scene
  ``ladder_chain``, its own RK4 step, 20 Hz control, 120 s episodes), per-wing actions by default;
* ``laddermill_gym/Rotorcraft-v0``: Roberts' tethered twin-rotor craft (configs/rotorcraft/, its own 2 ms
  RK4 step, 20 Hz control of collective and differential collective, 120 s episodes, a 0.01 rad direction
  step at 1 s), :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv`.

The wing environments have a native batched ``vector_entry_point`` (:class:`~laddermill_gym.envs.vector.WingVectorEnv`):
``gymnasium.make_vec(id, num_envs=n, vectorization_mode="vector_entry_point")``.
"""

from laddermill_gym.atmosphere.disturbances import DirectionStep, OneMinusCosineGust, RandomPerturbation, Schedule
from laddermill_gym.envs.rotorcraft.env import RotorcraftEnv
from laddermill_gym.envs.task import FAILURES, RewardConfig, TerminationConfig, WingTask
from laddermill_gym.envs.vector import WingVectorEnv
from laddermill_gym.envs.wing_env import WingEnv

__all__ = ["DirectionStep", "OneMinusCosineGust", "RandomPerturbation", "Schedule", "FAILURES", "RewardConfig",
           "TerminationConfig", "WingTask", "WingEnv", "WingVectorEnv", "RotorcraftEnv", "ENV_IDS", "register_envs"]

#: Registered environment ids and their default arguments (units: seconds).
ENV_IDS: dict[str, dict] = {
    "laddermill_gym/TetheredWing-v0": dict(scene="tethered_wing", scene_options={"elements_per_piece": 1},
                                           physics_dt=0.05, control_dt=0.05, episode_time=300.0),
    "laddermill_gym/LadderChain-v0": dict(scene="ladder_chain", control_dt=0.05, episode_time=120.0,
                                          groups="per_wing"),
    "laddermill_gym/Rotorcraft-v0": dict(craft="roberts_flying_model", control_dt=0.05, episode_time=120.0),
}
#: Entry points of the environments that are not wing scenes (no batched vector entry point).
_ENTRY_POINTS: dict[str, str] = {"laddermill_gym/Rotorcraft-v0": "laddermill_gym.envs.rotorcraft.env:RotorcraftEnv"}


def register_envs() -> None:
    """Register :data:`ENV_IDS` with Gymnasium (idempotent).

    No ``max_episode_steps``: the environments truncate themselves at their ``episode_time`` argument, and a
    TimeLimit wrapper fixed at registration would silently cut an episode made longer with
    ``gym.make(id, episode_time=...)``."""
    import gymnasium as gym

    for env_id, kwargs in ENV_IDS.items():
        if env_id in gym.registry:
            continue
        if env_id in _ENTRY_POINTS:
            gym.register(id=env_id, entry_point=_ENTRY_POINTS[env_id], kwargs=kwargs, disable_env_checker=False)
            continue
        gym.register(id=env_id, entry_point="laddermill_gym.envs.wing_env:WingEnv",
                     vector_entry_point="laddermill_gym.envs.vector:WingVectorEnv", kwargs=kwargs,
                     disable_env_checker=False)
