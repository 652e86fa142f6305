"""Small arguments for every registered environment id, shared by the tests that run each id (the skeleton's
contract, the Gymnasium conventions, the fuzz test): random winds (and start noise) so that seeds matter, an action
amplitude, and a rollout length; the malformed actions every env must refuse and a read-out of everything a step
changes. Builds nothing and computes no test answer."""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs import ENV_IDS, DirectionStep, RandomPerturbation

TW, LC, RC = "laddermill_gym/TetheredWing-v0", "laddermill_gym/LadderChain-v0", "laddermill_gym/Rotorcraft-v0"
LM, PK, PMC = "laddermill_gym/LadderMill-v0", "laddermill_gym/PumpingKite-v0", "laddermill_gym/PointMassChain-v0"
PK1, LM1 = "laddermill_gym/PumpingKite-v1", "laddermill_gym/LadderMill-v1"
LM2, LM3 = "laddermill_gym/LadderMill-v2", "laddermill_gym/LadderMill-v3"
LC1, TW1 = "laddermill_gym/LadderChain-v1", "laddermill_gym/TetheredWing-v1"
RC1 = "laddermill_gym/Rotorcraft-v1"
#: the small mill of tests/test_laddermill_env.py (11 wings, short settling) and alpha / beta ranges that never end it
MILL = dict(scene="laddermill", scene_options={"n_wings": 11}, settle={"max_time": 100.0}, control_dt=0.05,
            termination={"alpha_range_deg": (-180.0, 180.0), "max_abs_beta_deg": 90.0})
#: per id: the env's arguments with random winds (and start noise) so that seeds matter, the action amplitude and
#: the number of control periods of a rollout
CASES = {
    TW: (dict(ENV_IDS[TW], episode_time=20.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05),
                                                            DirectionStep(step=(-0.1, 0.1))]), 0.3, 40),
    # TetheredWing-v1's registered defaults (v0's with two RK4 steps of 25 ms per period)
    TW1: (dict(ENV_IDS[TW1], episode_time=20.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05),
                                                              DirectionStep(step=(-0.1, 0.1))]), 0.3, 40),
    LC: (dict(ENV_IDS[LC], scene_options={"n_wings": 5}, episode_time=20.0,
              disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05)]), 0.1, 20),
    # LadderChain-v1's registered defaults (v0's with three RK4 steps of 1/60 s per period) on LC's 5 wings
    LC1: (dict(ENV_IDS[LC1], scene_options={"n_wings": 5}, episode_time=20.0,
               disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05)]), 0.1, 20),
    RC: (dict(ENV_IDS[RC], episode_time=10.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.05),
                                                            DirectionStep(step=(-0.05, 0.05))],
              initial_noise={"roll_rate": 0.02, "lateral_velocity": 0.1}), 0.5, 40),
    # Rotorcraft-v1's registered defaults (v0's with the blade-incidence limit ending the episode)
    # (smaller actions and speed changes than v0's: the trim's tip is at 10.1 deg of the 13 deg limit, and random
    # collectives of 0.5 or speed changes of 10 % pass it within the rollout)
    RC1: (dict(ENV_IDS[RC1], episode_time=10.0, disturbances=[RandomPerturbation(speed_std=0.02, direction_std=0.05),
                                                              DirectionStep(step=(-0.05, 0.05))],
               initial_noise={"roll_rate": 0.02, "lateral_velocity": 0.1}), 0.05, 40),
    LM: (dict(MILL, episode_time=5.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01),
                                                    DirectionStep(step=(-0.01, 0.01))],
              initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.1, 20),
    # LadderMill-v1's registered defaults (scene laddermill_v1, authority 0.2) on the small mill's 11 wings
    LM1: (dict(ENV_IDS[LM1], **{k: v for k, v in MILL.items() if k != "scene"}, episode_time=5.0,
               disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01), DirectionStep(step=(-0.01, 0.01))],
               initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.5, 20),
    # LadderMill-v2's registered defaults (scene laddermill_v2, authority 0.2) on the small mill's 11 wings
    LM2: (dict(ENV_IDS[LM2], **{k: v for k, v in MILL.items() if k != "scene"}, episode_time=5.0,
               disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01), DirectionStep(step=(-0.01, 0.01))],
               initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.5, 20),
    # LadderMill-v3's registered defaults (v2's with one ROS2 step per control period) on the small mill's 11 wings
    LM3: (dict(ENV_IDS[LM3], **{k: v for k, v in MILL.items() if k != "scene"}, episode_time=5.0,
               disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01), DirectionStep(step=(-0.01, 0.01))],
               initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.5, 20),
    PK: (dict(ENV_IDS[PK], disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01),
                                         DirectionStep(step=(-0.01, 0.01))],
              initial_noise={"lateral_velocity": 0.05, "roll_rate": 0.01}), 0.2, 30),
    PK1: (dict(ENV_IDS[PK1], episode_time=20.0, disturbances=[RandomPerturbation(speed_std=0.1, direction_std=0.01)],
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


def invalid_actions(shape: tuple[int, ...]) -> list[tuple[str, object]]:
    """(name, action) pairs that are not finite real arrays of ``shape``."""
    n = shape[-1]
    nan = np.zeros(shape)
    nan.flat[1] = np.nan
    inf = np.zeros(shape)
    inf.flat[0] = -np.inf
    return [("None", None), ("scalar", 0.5), ("empty", np.zeros(0)), ("one short", np.zeros(int(np.prod(shape)) - 1)),
            ("one more", np.zeros((*shape[:-1], n + 1))), ("transposed", np.zeros(shape[::-1] + (2,))),
            ("string", "0 0 0"), ("strings", np.full(shape, "0.1")), ("complex", np.full(shape, 0.1 + 0.2j)),
            ("complex, imaginary 0", np.full(shape, 0.1 + 0j)), ("booleans", np.ones(shape, bool)),
            ("objects", np.full(shape, None, dtype=object)), ("dict", {"a": 1}), ("ragged", [[0.0], [0.0, 0.0]]),
            ("NaN", nan), ("-inf", inf)]


def env_state(env) -> list:
    """Everything a step would change: the task's snapshot, the observation, a vector env's autoreset flags and the
    generators' states (last)."""
    snap = env.task.snapshot()
    rngs = env._rngs if hasattr(env, "_rngs") else [env.np_random]
    flags = [env._autoreset.copy()] if hasattr(env, "_autoreset") else []
    return [*_arrays(snap), env.task.obs.copy(), *flags, [r.bit_generator.state for r in rngs]]


def _arrays(x) -> list:
    """The arrays in a nest of dicts, tuples and lists (None left out)."""
    if isinstance(x, dict):
        return [a for v in x.values() for a in _arrays(v)]
    if isinstance(x, (tuple, list)):
        return [a for v in x for a in _arrays(v)]
    return [] if x is None else [np.array(x, copy=True)]


def assert_same_state(a: list, b: list) -> None:
    """Two :func:`env_state` read-outs are equal."""
    assert len(a) == len(b)
    for x, y in zip(a[:-1], b[:-1], strict=True):
        np.testing.assert_array_equal(x, y)
    assert a[-1] == b[-1]
