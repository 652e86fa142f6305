"""A PPO policy's linear actor started at the LQR (``init_from: lqr``, control/warm_start.py): the affine map of a
known affine controller is recovered (closed form), the started policy's deterministic action is the LQR's on the
observations of an LQR rollout (the LQR controller itself as the oracle), and bad configs name the field."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.warm_start import affine_map  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402

RC_CONFIG = "configs/agents/ppo_rotorcraft.yaml"


class _Affine:
    def __init__(self, W, b):
        self.W, self.b = W, b

    def predict(self, obs, deterministic=True):
        return np.clip(np.asarray(obs) @ self.W.T + self.b, -1.0, 1.0), None


def test_affine_map_recovers_a_known_affine_controller():
    rng = np.random.default_rng(0)
    scales = np.array([1, 10, 100, 1e3, 1, 0.1, 5])  # observations of mixed units, as the envs' (m, N, rad)
    W, b = rng.normal(size=(3, 7)) * 0.05 / scales, rng.normal(size=3) * 0.1
    obs0 = rng.normal(size=7) * scales
    W_est, b_est = affine_map(_Affine(W, b), obs0)
    np.testing.assert_allclose(W_est, W, rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(b_est, b, rtol=1e-6, atol=1e-9)
    with pytest.raises(ValueError, match="reaches the clip"):
        affine_map(_Affine(W, b + 5.0), obs0)


def small_ppo_config(tmp_path, n_epochs: int = 1, **changes):
    """ppo_rotorcraft.yaml cut to a few hundred steps on 2 copies (``changes`` replace top-level fields); its path."""
    data = yaml.safe_load(Path(RC_CONFIG).read_text())
    data.update(n_envs=2, total_timesteps=512, time_limit_minutes=1.0, checkpoint_every=256,
                eval={"every": 256, "episodes": 1})
    data["hyperparameters"].update(n_steps=64, batch_size=64, n_epochs=n_epochs)
    data.update(changes)
    p = tmp_path / "ppo_small.yaml"
    p.write_text(yaml.safe_dump(data))
    return p


def test_the_started_policy_acts_as_the_lqr(tmp_path):
    import stable_baselines3 as sb3
    from stable_baselines3.common.vec_env import VecMonitor, VecNormalize

    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.control.warm_start import start_from
    from laddermill_gym.harness.train import training_env

    cfg = load_rl_config(small_ppo_config(tmp_path))
    assert cfg.init_from == "lqr"
    venv = VecNormalize(VecMonitor(training_env(cfg)), norm_obs=True, norm_reward=False, clip_obs=10.0)
    model = sb3.PPO("MlpPolicy", venv, seed=0, policy_kwargs=cfg.policy_kwargs, device="cpu", **cfg.hyperparameters)
    start_from(cfg, model, venv)
    assert not venv.training  # the statistics are held fixed: the actor's gains depend on them
    policy = SB3Controller(model, venv.obs_rms.mean, venv.obs_rms.var, venv.clip_obs, venv.epsilon)
    lqr = make_controller("lqr", cfg.env_id, cfg.carried_env_kwargs())
    raw = venv.venv
    obs = raw.reset()
    for _ in range(200):  # 10 s of the training disturbances
        a_lqr = lqr.predict(obs, deterministic=True)[0]
        np.testing.assert_allclose(policy.predict(obs, deterministic=True)[0], a_lqr, atol=1e-3)
        obs = raw.step(a_lqr)[0]


@pytest.mark.parametrize("changes, match", [
    (dict(init_from="pid"), r"init_from' = 'pid': must be 'lqr'"),
    (dict(policy_kwargs={"net_arch": [64, 64]}), r"init_from' = 'lqr': needs .*net_arch\.pi: \[\]"),
    (dict(normalize_observations=False), r"init_from' = 'lqr': needs .*normalize_observations: true \(got False\)"),
])
def test_bad_init_from_is_named(tmp_path, changes, match):
    with pytest.raises(ConfigError, match=match):
        load_rl_config(small_ppo_config(tmp_path, **changes))
