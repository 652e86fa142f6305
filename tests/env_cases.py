"""Small arguments for every registered environment id, shared by the tests that run each id (the skeleton's
contract, the Gymnasium conventions, the fuzz test): random winds (and start noise) so that seeds matter, an action
amplitude, and a rollout length. Builds nothing and computes no test answer."""

from __future__ import annotations

import warnings

import gymnasium as gym

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS, DirectionStep, RandomPerturbation

TW, LC, RC = "laddermill_gym/TetheredWing-v0", "laddermill_gym/LadderChain-v0", "laddermill_gym/Rotorcraft-v0"
LM, PK, PMC = "laddermill_gym/LadderMill-v0", "laddermill_gym/PumpingKite-v0", "laddermill_gym/PointMassChain-v0"
#: the small mill of tests/test_laddermill_env.py (11 wings, short settling) and alpha / beta ranges that never end it
MILL = dict(scene="laddermill", scene_options={"n_wings": 11}, settle={"max_time": 100.0}, control_dt=0.05,
            termination={"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0})
#: per id: the env's arguments with random winds (and start noise) so that seeds matter, the action amplitude and
#: the number of control periods of a rollout
CASES = {
    TW: (dict(ENV_IDS[TW], episode_time=20.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05),
                                                            DirectionStep(step=(-0.1, 0.1))]), 0.3, 40),
    LC: (dict(ENV_IDS[LC], scene_options={"n_wings": 5}, episode_time=20.0,
              disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05)]), 0.1, 20),
    RC: (dict(ENV_IDS[RC], episode_time=10.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05),
                                                            DirectionStep(step=(-0.05, 0.05))],
              initial_noise={"roll_rate": 0.02, "lateral_velocity": 0.1}), 0.5, 40),
    LM: (dict(MILL, episode_time=5.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01),
                                                    DirectionStep(step=(-0.01, 0.01))],
              initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.1, 20),
    PK: (dict(ENV_IDS[PK], disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01),
                                         DirectionStep(step=(-0.01, 0.01))],
              initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.2, 30),
    PMC: (dict(ENV_IDS[PMC], episode_time=1.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05)]),
          0.3, 6),
}
IDS = list(CASES)


def case_kwargs(env_id: str, **kw) -> dict:
    """The id's small arguments of :data:`CASES`, updated with ``kw``."""
    return dict(CASES[env_id][0], **kw)


def make_single(env_id: str, **kw):
    """``gymnasium.make(env_id)`` with the small arguments (updated with ``kw``), unwrapped."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        return gym.make(env_id, **case_kwargs(env_id, **kw)).unwrapped


def make_native(env_id: str, n: int, **kw):
    """The native vector env (``vectorization_mode="vector_entry_point"``) of ``n`` copies, small arguments."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return gym.make_vec(env_id, num_envs=n, vectorization_mode="vector_entry_point", **case_kwargs(env_id, **kw))
