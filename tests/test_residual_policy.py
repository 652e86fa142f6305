"""The residual PPO policy (control/residual_policy.py): untrained, its deterministic action is the LQR's (the
LQR controller that ``make_controller`` designs, computed apart from the policy, as the oracle) on observations
far from trim, through SB3's zip format and the harness's loader; the critic warm-up freezes its residual; bad
configs and a wrong base name what is wrong."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.policy_names import policy_class  # noqa: E402
from laddermill_gym.control.residual_policy import ResidualPolicy  # noqa: E402
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.warm_start import start_residual  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402
from tests.lqr_observations import lqr_observations  # noqa: E402

ENV_ID = "laddermill_gym/TetheredWing-v0"
CONFIG = "configs/agents/ppo_tethered_wing_residual.yaml"


@pytest.fixture(scope="module")
def started():
    """(an untrained residual PPO started at the LQR, the LQR, raw observations of a disturbed LQR rollout)."""
    import gymnasium as gym
    from stable_baselines3 import PPO
    from stable_baselines3.common.vec_env import DummyVecEnv

    from laddermill_gym.control.factory import make_controller

    lqr = make_controller("lqr", ENV_ID, {})
    venv = DummyVecEnv([lambda: gym.make(ENV_ID)])
    model = PPO(ResidualPolicy, venv, n_steps=64, batch_size=64, device="cpu", seed=0,
                policy_kwargs=dict(net_arch=dict(pi=[16, 16], vf=[16]), log_std_init=-2.5))
    start_residual(model, lqr, venv, 50)
    return model, lqr, lqr_observations(lqr, ENV_ID)


def test_untrained_action_is_the_lqr_action(started, tmp_path):
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.sb3_policy import SB3Controller

    model, lqr, obs = started
    expected = lqr.predict(obs)[0]
    assert lqr.n_clipped > 0  # some actions at the clip: the residual is added before SB3's clip, as the LQR clips
    got = SB3Controller(model).predict(obs, deterministic=True)[0]
    assert np.abs(got.astype(np.float64) - expected).max() <= 1e-12
    model.save(tmp_path / "model.zip")  # SB3's zip format; the harness loads a run folder
    (tmp_path / "algorithm.txt").write_text("PPO\n")
    (tmp_path / "config.yaml").write_text(f"env: {ENV_ID}\n")
    loaded = make_controller(str(tmp_path), ENV_ID, {})
    assert isinstance(loaded.model.policy, ResidualPolicy)
    assert np.abs(loaded.predict(obs, deterministic=True)[0].astype(np.float64) - expected).max() <= 1e-12


def test_residual_changes_the_action_and_warmup_freezes_it(started):
    import torch

    from laddermill_gym.harness.validation import freeze_actor

    model, lqr, obs = started
    policy = model.policy
    freeze_actor(model, True)
    assert not any(p.requires_grad for p in policy.actor_parameters())
    assert all(p.requires_grad for p in policy.value_net.parameters())
    freeze_actor(model, False)
    saved = policy.skip_net.bias.detach().clone()
    try:
        with torch.no_grad():
            policy.skip_net.bias.copy_(torch.tensor([0.01, -0.02, 0.0]))
        got = model.predict(obs[:10], deterministic=True)[0].astype(np.float64)
        ref = np.clip(lqr.predict(obs[:10])[0].astype(np.float64) + [0.01, -0.02, 0.0], -1, 1)
        np.testing.assert_allclose(got, ref, atol=2e-7)  # float32 rounding of the sum
    finally:
        with torch.no_grad():
            policy.skip_net.bias.copy_(saved)


def test_set_base_refuses_another_controller(started):
    model = started[0]
    with pytest.raises(ValueError, match="needs the LQRController"):
        model.policy.set_base(object(), np.zeros(15), np.ones(15), 100.0)
    with pytest.raises(ValueError, match="policy 'Residual'"):
        policy_class("Residual")


def test_config_checks(tmp_path):
    cfg = load_rl_config(CONFIG)
    assert cfg.policy == "ResidualPolicy" and cfg.init_from == "lqr" and not cfg.normalize_observations
    data = yaml.safe_load(Path(CONFIG).read_text())
    for change, field in ((dict(normalize_observations=True), "init_from"), (dict(init_from=None), "policy"),
                          (dict(policy="CnnPolicy"), "policy")):
        bad = {**data, **change}
        path = tmp_path / "bad.yaml"
        path.write_text(yaml.safe_dump({k: v for k, v in bad.items() if v is not None}))
        with pytest.raises(ConfigError, match=field) as err:
            load_rl_config(path)
        assert "bad.yaml" in str(err.value)


LIMIT = 0.2  # [-] the bounded config's residual_limit (a fraction of each control's half range)


@pytest.fixture(scope="module")
def bounded(started):
    """An untrained residual PPO with ``residual_limit`` LIMIT, started at the same LQR as ``started``."""
    import gymnasium as gym
    from stable_baselines3 import PPO
    from stable_baselines3.common.vec_env import DummyVecEnv

    lqr = started[1]
    venv = DummyVecEnv([lambda: gym.make(ENV_ID)])
    model = PPO(ResidualPolicy, venv, n_steps=64, batch_size=64, device="cpu", seed=0,
                policy_kwargs=dict(net_arch=dict(pi=[16, 16], vf=[16]), log_std_init=-2.5, residual_limit=LIMIT))
    start_residual(model, lqr, venv, 50)
    return model


def test_bounded_untrained_is_the_lqr_and_keeps_its_bound_through_the_zip(started, bounded, tmp_path):
    from laddermill_gym.control.factory import make_controller

    _, lqr, obs = started
    expected = lqr.predict(obs)[0]
    assert np.abs(bounded.predict(obs, deterministic=True)[0].astype(np.float64) - expected).max() == 0.0
    bounded.save(tmp_path / "model.zip")
    (tmp_path / "algorithm.txt").write_text("PPO\n")
    (tmp_path / "config.yaml").write_text(f"env: {ENV_ID}\n")
    loaded = make_controller(str(tmp_path), ENV_ID, {})
    assert loaded.model.policy.residual_limit == LIMIT
    assert np.abs(loaded.predict(obs, deterministic=True)[0].astype(np.float64) - expected).max() == 0.0


def test_the_bound_holds_for_any_weights(started, bounded):
    """Large random residual weights: every deterministic action within LIMIT of the LQR's (both clipped to the
    action space, a 1-Lipschitz map: lqr.predict clips), the bound reached (so it is what holds the action), and a
    small residual passed with slope 1 (tanh(x) = x - x^3 / 3 + ...)."""
    import torch

    _, lqr, obs = started
    policy = bounded.policy
    layers = (policy.skip_net, policy.action_net)
    saved = [(layer.weight.detach().clone(), layer.bias.detach().clone()) for layer in layers]
    expected = lqr.predict(obs)[0].astype(np.float64)
    gen = torch.Generator().manual_seed(3)
    try:
        with torch.no_grad():
            for layer in layers:
                layer.weight.copy_(torch.randn(layer.weight.shape, generator=gen) * 5.0)
                layer.bias.copy_(torch.randn(layer.bias.shape, generator=gen) * 5.0)
        got = bounded.predict(obs, deterministic=True)[0].astype(np.float64)
        assert np.abs(got - expected).max() <= LIMIT + 1e-6  # float32 rounding of the sum
        assert np.abs(got - expected).max() >= 0.99 * LIMIT  # the bound binds: without it the residual is ~1e2
        with torch.no_grad():
            for layer in layers:
                layer.weight.zero_()
                layer.bias.zero_()
            policy.skip_net.bias.copy_(torch.tensor([1e-3, -2e-3, 0.0]))
        got = bounded.predict(obs[:10], deterministic=True)[0].astype(np.float64)
        small = LIMIT * np.tanh(np.array([1e-3, -2e-3, 0.0]) / LIMIT)  # 1e-3 (1 - 8e-6): slope 1 to 1e-8
        np.testing.assert_allclose(got, np.clip(expected[:10] + small, -1, 1), atol=2e-7)
    finally:
        with torch.no_grad():
            for layer, (w, b) in zip(layers, saved, strict=True):
                layer.weight.copy_(w)
                layer.bias.copy_(b)


@pytest.mark.parametrize("value", [0.0, -0.1, 2.5, "tight", True, float("nan")])
def test_bad_residual_limit_names_field_and_value(tmp_path, value):
    data = yaml.safe_load(Path(CONFIG).read_text())
    data["policy_kwargs"]["residual_limit"] = value
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="residual_limit") as err:
        load_rl_config(path)
    assert "bad.yaml" in str(err.value) and str(value)[:4] in str(err.value)
    with pytest.raises(ValueError, match="residual_limit"):
        ResidualPolicy.__init__(object.__new__(ResidualPolicy), residual_limit=value)


def test_residual_limit_needs_the_residual_policy(tmp_path):
    data = yaml.safe_load(Path("configs/agents/ppo_tethered_wing.yaml").read_text())
    data.setdefault("policy_kwargs", {})["residual_limit"] = 0.2
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="residual_limit") as err:
        load_rl_config(path)
    assert "bad.yaml" in str(err.value)
