"""Raw observations on which a policy started at the LQR must act as the LQR, shared by the residual PPO and SAC
tests: a rollout of the LQR itself and states far from its trim."""

from __future__ import annotations

import numpy as np


def lqr_observations(lqr, env_id: str) -> np.ndarray:
    """(175, obs_dim) float32: 100 observations of ``lqr`` flying env ``env_id`` from seed 0 (asserted to stay in
    the air), then every fourth of them moved by 3, 30 and 300 of the rollout's standard deviations (seed 1), where
    the controls clip."""
    import gymnasium as gym

    env = gym.make(env_id)
    obs, _ = env.reset(seed=0)
    rng = np.random.default_rng(1)
    rows = []
    for _ in range(100):
        rows.append(obs)
        obs, _, term, trunc, _ = env.step(lqr.predict(obs)[0])
        assert not (term or trunc)
    rows = np.array(rows)
    far = [rows[::4] + rng.normal(size=rows[::4].shape) * k * rows.std(axis=0) for k in (3.0, 30.0, 300.0)]
    return np.concatenate([rows, *far]).astype(np.float32)
