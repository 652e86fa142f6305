"""The residual SAC policy (control/residual_sac.py): untrained, its deterministic action is the LQR's (the LQR
controller that ``make_controller`` designs, run by its own code apart from the policy, as the oracle) on
observations near and far from trim, saturated controls included, through SB3's zip format and the harness's
loader; its bound holds for any weights; the critic warm-up freezes its actor; a wrong base, a bad action space
and bad configs name what is wrong."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.policy_names import policy_class  # noqa: E402
from laddermill_gym.control.residual_sac import ResidualSACPolicy  # noqa: E402
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.warm_start import start_residual  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402
from tests.lqr_observations import lqr_observations  # noqa: E402

ENV_ID = "laddermill_gym/TetheredWing-v0"
CONFIG = "configs/agents/sac_tethered_wing_residual.yaml"
LIMIT = 0.2  # [-] the config's residual_limit


def sac_model(venv, **policy_kwargs):
    from stable_baselines3 import SAC

    return SAC(ResidualSACPolicy, venv, device="cpu", seed=0, learning_starts=0, batch_size=32, buffer_size=1000,
               policy_kwargs=dict(net_arch=[16, 16], log_std_init=-2.5, **policy_kwargs))


@pytest.fixture(scope="module")
def started():
    """(an untrained residual SAC started at the LQR, the bounded one, the LQR, raw observations of a disturbed
    LQR rollout and of states far from trim)."""
    import gymnasium as gym
    from stable_baselines3.common.vec_env import DummyVecEnv

    from laddermill_gym.control.factory import make_controller

    lqr = make_controller("lqr", ENV_ID, {})
    venv = DummyVecEnv([lambda: gym.make(ENV_ID)])
    model, bounded = sac_model(venv), sac_model(venv, residual_limit=LIMIT)
    for m in (model, bounded):
        start_residual(m, lqr, venv, 50)
    return model, bounded, lqr, lqr_observations(lqr, ENV_ID)


@pytest.mark.parametrize("which", [0, 1])
def test_untrained_action_is_the_lqr_action_through_the_zip(started, tmp_path, which):
    from stable_baselines3 import SAC

    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.sb3_policy import SB3Controller

    model, lqr, obs = started[which], started[2], started[3]
    lqr.reset_clip_count()
    expected = lqr.predict(obs)[0]
    assert lqr.n_clipped > 0 and np.abs(expected).max() == 1.0  # saturated controls are reproduced too
    got = SB3Controller(model).predict(obs, deterministic=True)[0]
    assert got.dtype == expected.dtype and np.abs(got.astype(np.float64) - expected).max() <= 1e-12
    model.save(tmp_path / "model.zip")  # SB3's zip format; the harness loads a run folder
    (tmp_path / "algorithm.txt").write_text("SAC\n")
    (tmp_path / "config.yaml").write_text(f"env: {ENV_ID}\n")
    loaded = make_controller(str(tmp_path), ENV_ID, {})
    assert isinstance(loaded.model, SAC) and isinstance(loaded.model.policy, ResidualSACPolicy)
    assert loaded.model.policy.residual_limit == model.policy.residual_limit
    assert np.abs(loaded.predict(obs, deterministic=True)[0].astype(np.float64) - expected).max() <= 1e-12


def test_stochastic_start_is_the_lqr_plus_its_noise(started):
    """Sampled actions: tanh(atanh(a_lqr) + N(0, exp(log_std_init)^2)), checked where the LQR is inside its range by
    the spread of atanh(action) - atanh(a_lqr) (standard deviation exp(-2.5) = 0.082, mean 0)."""
    import torch

    model, _, lqr, obs = started
    inside = obs[np.all(np.abs(lqr.predict(obs)[0]) < 0.9, axis=1)][:20]
    torch.manual_seed(0)
    reps = np.repeat(inside, 200, axis=0)
    sampled = model.predict(reps, deterministic=False)[0].astype(np.float64)
    d = np.arctanh(sampled) - np.arctanh(lqr.predict(reps)[0].astype(np.float64))
    assert abs(d.std() - np.exp(-2.5)) < 0.05 * np.exp(-2.5) and abs(d.mean()) < 0.005


def test_the_bound_holds_for_any_weights_and_the_warmup_freezes_the_actor(started):
    """Large random residual weights: every deterministic action within LIMIT of the LQR's (tanh is 1-Lipschitz),
    the bound reached; a small residual passes with slope 1 - a^2 (tanh's) where the LQR is inside its range."""
    import torch

    from laddermill_gym.harness.validation import freeze_actor

    _, bounded, lqr, obs = started
    actor = bounded.policy.actor
    layers = (actor.skip_net, actor.mu)
    saved = [(layer.weight.detach().clone(), layer.bias.detach().clone()) for layer in layers]
    expected = lqr.predict(obs)[0].astype(np.float64)
    gen = torch.Generator().manual_seed(3)
    try:
        with torch.no_grad():
            for layer in layers:
                layer.weight.copy_(torch.randn(layer.weight.shape, generator=gen) * 5.0)
                layer.bias.copy_(torch.randn(layer.bias.shape, generator=gen) * 5.0)
        got = bounded.predict(obs, deterministic=True)[0].astype(np.float64)
        assert np.abs(got - expected).max() <= LIMIT + 1e-6  # float32 rounding
        assert np.abs(got - expected).max() >= 0.5 * LIMIT  # the bound binds: unbounded the residual is ~1e2
        with torch.no_grad():
            for layer in layers:
                layer.weight.zero_()
                layer.bias.zero_()
            actor.skip_net.bias.copy_(torch.tensor([1e-3, -2e-3, 0.0]))
        got = bounded.predict(obs[:10], deterministic=True)[0].astype(np.float64)
        small = LIMIT * np.tanh(np.array([1e-3, -2e-3, 0.0]) / LIMIT)
        np.testing.assert_allclose(got, np.tanh(np.arctanh(expected[:10]) + small), atol=2e-7)
    finally:
        with torch.no_grad():
            for layer, (w, b) in zip(layers, saved, strict=True):
                layer.weight.copy_(w)
                layer.bias.copy_(b)
    freeze_actor(bounded, True)
    assert not any(p.requires_grad for p in bounded.policy.actor_parameters())
    assert all(p.requires_grad for p in bounded.policy.critic.parameters())
    freeze_actor(bounded, False)
    assert all(p.requires_grad for p in bounded.policy.actor_parameters())


def test_wrong_base_and_action_space_raise(started):
    from gymnasium import spaces

    from laddermill_gym.control.lqr import LQRController

    model, _, lqr, _ = started
    # an LQR of two wings (each the single wing's): the policy's base has one
    two = LQRController(*(np.concatenate([a, a]) for a in (lqr.gains, lqr.u_trim, lqr.trim_attitude, lqr.mid,
                                                           lqr.half_range)))
    with pytest.raises(ValueError, match=r"ResidualSACPolicy.set_base: needs the LQRController of 1 wing"):
        model.policy.set_base(two, np.zeros(15), np.ones(15), 100.0)
    with pytest.raises(ValueError, match="needs the LQRController"):
        model.policy.set_base(object(), np.zeros(15), np.ones(15), 100.0)
    obs_space = model.observation_space
    with pytest.raises(ValueError, match=r"action space \[-1, 1\]"):
        ResidualSACPolicy(obs_space, spaces.Box(-2.0, 2.0, (3,), np.float32), lambda _: 1e-3)
    with pytest.raises(ValueError, match="residual_limit"):
        ResidualSACPolicy(obs_space, model.action_space, lambda _: 1e-3, residual_limit=3.0)
    with pytest.raises(ValueError, match="flat Box action space"):
        ResidualSACPolicy(obs_space, spaces.Discrete(3), lambda _: 1e-3)
    with pytest.raises(ValueError, match="flat Box observation space"):
        ResidualSACPolicy(spaces.Dict({"o": obs_space}), model.action_space, lambda _: 1e-3)
    with pytest.raises(ValueError, match="4 actions is not 3 controls per wing"):
        ResidualSACPolicy(obs_space, spaces.Box(-1.0, 1.0, (4,), np.float32), lambda _: 1e-3)
    with pytest.raises(ValueError, match="use_sde"):
        ResidualSACPolicy(obs_space, model.action_space, lambda _: 1e-3, use_sde=True)
    assert policy_class("ResidualSACPolicy") is ResidualSACPolicy


def test_config_checks(tmp_path):
    cfg = load_rl_config(CONFIG)
    assert (cfg.algorithm, cfg.policy, cfg.init_from, cfg.normalize_observations) == ("SAC", "ResidualSACPolicy",
                                                                                       "lqr", False)
    assert cfg.policy_kwargs["residual_limit"] == LIMIT and cfg.validation.selection.rule == "paired"
    data = yaml.safe_load(Path(CONFIG).read_text())
    for change, field in ((dict(normalize_observations=True), "init_from"), (dict(init_from=None), "policy"),
                          (dict(algorithm="PPO", hyperparameters={}), "init_from")):
        bad = {**data, **change}
        path = tmp_path / "bad.yaml"
        path.write_text(yaml.safe_dump({k: v for k, v in bad.items() if v is not None}))
        with pytest.raises(ConfigError, match=field) as err:
            load_rl_config(path)
        assert "bad.yaml" in str(err.value)
