"""The residual SAC policy with the residual AFTER SAC's squash (control/residual_sac.py,
``residual_after_squash: true``): env action a = clip(a_lqr + L u, -1, 1), u SAC's squashed action.

Oracles: the LQR that ``make_controller`` designs, run by its own code apart from the policy (its clipped actions,
and its unclipped ones (u - mid) / half_range from its controls); the squashed Gaussian's log-density written
independently with torch.distributions (Normal through TanhTransform and AffineTransform(a_lqr, L)); SB3's replay
buffer after a short ``SAC.learn``."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.residual_sac import ResidualSACPolicy  # noqa: E402
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.warm_start import start_residual  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402
from tests.lqr_observations import lqr_observations  # noqa: E402

ENV_ID = "laddermill_gym/TetheredWing-v0"
CONFIG = "configs/agents/sac_tethered_wing_residual_after.yaml"
LIMIT = 0.2  # [-] the config's residual_limit: L


def sac_model(venv, **policy_kwargs):
    from stable_baselines3 import SAC

    return SAC(ResidualSACPolicy, venv, device="cpu", seed=0, learning_starts=0, batch_size=32, buffer_size=1000,
               gradient_steps=1, policy_kwargs=dict(net_arch=[16, 16], log_std_init=-2.5, **policy_kwargs))


@pytest.fixture(scope="module")
def started():
    """(an untrained after-squash residual SAC started at the LQR, a before-squash one of the same L, the LQR, raw
    observations of a disturbed LQR rollout and of states far from trim, the venv)."""
    import gymnasium as gym
    from stable_baselines3.common.vec_env import DummyVecEnv

    from laddermill_gym.control.factory import make_controller

    lqr = make_controller("lqr", ENV_ID, {})
    venv = DummyVecEnv([lambda: gym.make(ENV_ID)])
    after = sac_model(venv, residual_limit=LIMIT, residual_after_squash=True)
    before = sac_model(venv, residual_limit=LIMIT)
    for m in (after, before):
        start_residual(m, lqr, venv, 50)
    return after, before, lqr, lqr_observations(lqr, ENV_ID), venv


def unclipped(lqr, obs: np.ndarray) -> np.ndarray:
    """The LQR's float64 actions (N, 3) before its clip to [-1, 1], by its own code."""
    from laddermill_gym.control.base import actions_from_controls

    return actions_from_controls(lqr.controls(obs), lqr.mid, lqr.half_range).reshape(len(obs), -1)


def set_residual(actor, weight_scale: float, bias, seed: int = 3) -> None:
    """Residual layers (skip and mu) to random weights x ``weight_scale`` (seed) and skip's bias to ``bias``."""
    import torch

    gen = torch.Generator().manual_seed(seed)
    with torch.no_grad():
        for layer in (actor.skip_net, actor.mu):
            layer.weight.copy_(torch.randn(layer.weight.shape, generator=gen) * weight_scale)
            layer.bias.zero_()
        actor.skip_net.bias.copy_(torch.as_tensor(bias, dtype=torch.float32))


@pytest.fixture
def restore(started):
    """Restore both policies' residual layers after a test that changes them."""
    import copy

    saved = [copy.deepcopy(m.policy.actor.state_dict()) for m in started[:2]]
    yield
    for m, state in zip(started[:2], saved, strict=True):
        m.policy.actor.load_state_dict(state)


def test_untrained_action_is_the_lqr_action_through_the_zip(started, tmp_path):
    from stable_baselines3 import SAC

    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.sb3_policy import SB3Controller

    model, _, lqr, obs, _ = started
    lqr.reset_clip_count()
    expected = lqr.predict(obs)[0]
    assert lqr.n_clipped > 0 and np.abs(expected).max() == 1.0  # saturated controls are reproduced too
    got = SB3Controller(model).predict(obs, deterministic=True)[0]
    assert got.dtype == expected.dtype and np.array_equal(got, expected)  # bit for bit
    model.save(tmp_path / "model.zip")  # SB3's zip format; the harness loads a run folder
    (tmp_path / "algorithm.txt").write_text("SAC\n")
    (tmp_path / "config.yaml").write_text(f"env: {ENV_ID}\n")
    loaded = make_controller(str(tmp_path), ENV_ID, {})
    assert isinstance(loaded.model, SAC) and loaded.model.policy.residual_after_squash is True
    assert loaded.model.policy.residual_limit == LIMIT
    assert np.array_equal(loaded.predict(obs, deterministic=True)[0], expected)


def test_a_residual_moves_a_saturated_control(started, restore):
    """Skip's bias -2 sign(a_lqr): u = tanh(-2 sign) and a = clip(a_lqr - 0.2 tanh(2) sign, -1, 1) for every
    control, saturated ones included; the before-squash policy with the same bias leaves them at +-1."""
    after, before, lqr, obs, _ = started
    a_lqr = unclipped(lqr, obs)
    sat = np.abs(a_lqr) >= 1.0
    rows = np.flatnonzero(sat.any(axis=1) & (np.abs(a_lqr) < 1.0 + 0.5 * LIMIT).any(axis=1))
    assert len(rows) >= 3
    pick = obs[rows[:3]]
    moved = []
    for model in (after, before):
        for i, o in enumerate(pick):  # one observation at a time: the bias is per control
            set_residual(model.policy.actor, 0.0, -2.0 * np.sign(a_lqr[rows[i]]))
            moved.append(model.predict(o[None], deterministic=True)[0][0].astype(np.float64))
    ref = a_lqr[rows[:3]]
    expected = np.clip(ref - LIMIT * np.tanh(2.0) * np.sign(ref), -1.0, 1.0)
    np.testing.assert_allclose(np.array(moved[:3]), expected, atol=1e-7)
    s = sat[rows[:3]]
    inside = s & (np.abs(ref) < 1.0 + 0.5 * LIMIT)
    assert inside.any() and np.all(np.abs(np.array(moved[:3])[inside]) < 1.0 - 0.05)  # pulled back from +-1
    assert np.all(np.abs(np.array(moved[3:])[s]) == 1.0)  # before the squash: no authority there


def test_log_prob_is_the_squashed_gaussians_of_u_minus_dim_log_l(started, restore):
    """Sampled (a, log p): log p = log N(atanh u; mean, std) - sum log(1 - u^2) - 3 log L, the density of
    a = a_lqr + L tanh(x), x ~ N(mean, std^2), written with torch.distributions where the clip does not act."""
    import torch
    from torch.distributions import AffineTransform, Normal, TanhTransform, TransformedDistribution

    model, _, lqr, obs, _ = started
    actor = model.policy.actor
    a_lqr = unclipped(lqr, obs)
    inside = obs[np.all(np.abs(a_lqr) < 1.0 - 1.5 * LIMIT, axis=1)][:40]
    assert len(inside) >= 20
    set_residual(actor, 0.05, [0.3, -0.2, 0.1])
    with torch.no_grad():
        actor.log_std.weight.copy_(torch.randn(actor.log_std.weight.shape, generator=torch.Generator().manual_seed(
            5)) * 0.05)
        o = torch.as_tensor(inside)
        mean, log_std, _ = actor.get_action_dist_params(o)
        torch.manual_seed(0)
        a, log_p = actor.action_log_prob(o)
    base = torch.as_tensor(unclipped(lqr, inside))
    dist = TransformedDistribution(Normal(mean, log_std.exp()),
                                   [TanhTransform(), AffineTransform(loc=base, scale=LIMIT)])
    oracle = dist.log_prob(a.to(torch.float64)).sum(dim=1)
    assert a.dtype == torch.float32 and float((a.double() - base).abs().max()) <= LIMIT
    assert float((a.double() - base).abs().max()) > 0.02  # the residual acts
    np.testing.assert_allclose(log_p.numpy(), oracle.numpy(), rtol=0, atol=2e-3)
    assert abs(3 * math.log(LIMIT) + 4.828) < 1e-3  # the shift, -3 log 0.2 = +4.83 nats


def test_bound_for_any_weights_and_the_buffer_holds_the_env_action(started, restore):
    """Large random weights: |a - clip(a_lqr)| <= L (the clip is 1-Lipschitz), the bound reached. A short
    SAC.learn with skip's bias 0.5: the replay buffer's actions are a = clip(a_lqr + L tanh(0.5 + noise)), whose
    mean offset from the LQR's is L tanh(0.5) = 0.092 (u itself would sit at about tanh(0.5) = 0.46)."""
    import torch

    model, _, lqr, obs, _ = started
    expected = lqr.predict(obs)[0].astype(np.float64)
    set_residual(model.policy.actor, 5.0, [5.0, -5.0, 5.0])
    got = model.predict(obs, deterministic=True)[0].astype(np.float64)
    assert np.abs(got - expected).max() <= LIMIT + 1e-6 and np.abs(got - expected).max() >= 0.9 * LIMIT
    set_residual(model.policy.actor, 0.0, [0.5, 0.5, 0.5])
    torch.manual_seed(0)
    model.gradient_steps = 0  # collect only: the actions of the policy set here
    model.learn(40)
    n = model.replay_buffer.pos
    acts = model.replay_buffer.actions[:n, 0].astype(np.float64)
    raw = model.replay_buffer.observations[:n, 0]
    offset = acts - np.clip(unclipped(lqr, raw) + LIMIT * np.tanh(0.5), -1.0, 1.0)
    assert n == 40 and np.abs(offset).max() < 0.05 and abs(offset.mean()) < 0.01
    model.train(gradient_steps=2, batch_size=16)  # SAC's update through action_log_prob: the critics see a
    assert np.isfinite(model.logger.name_to_value["train/critic_loss"])


def test_bad_arguments_and_config_name_the_field(started, tmp_path):
    model = started[0]
    obs_space, act_space = model.observation_space, model.action_space
    with pytest.raises(ValueError, match="residual_after_squash needs residual_limit"):
        ResidualSACPolicy(obs_space, act_space, lambda _: 1e-3, residual_after_squash=True)
    with pytest.raises(ValueError, match="residual_after_squash 'yes' must be true or false"):
        ResidualSACPolicy(obs_space, act_space, lambda _: 1e-3, residual_limit=0.2, residual_after_squash="yes")
    cfg = load_rl_config(CONFIG)
    assert cfg.policy_kwargs["residual_after_squash"] is True and cfg.policy_kwargs["residual_limit"] == LIMIT
    previous = yaml.safe_load(Path("configs/agents/sac_tethered_wing_residual.yaml").read_text())
    data = yaml.safe_load(Path(CONFIG).read_text())
    changed = {k for k in set(data) | set(previous) if data.get(k) != previous.get(k)}
    assert changed == {"time_limit_minutes", "policy_kwargs"}  # every other setting as the previous run's
    assert {k for k in data["policy_kwargs"] if data["policy_kwargs"][k] != previous["policy_kwargs"].get(k)} == {
        "residual_after_squash"}
    for value, policy in (("yes", "ResidualSACPolicy"), (True, "ResidualPolicy")):
        bad = {**data, "policy": policy, "policy_kwargs": {**data["policy_kwargs"], "residual_after_squash": value}}
        if policy == "ResidualPolicy":
            bad = {**bad, "algorithm": "PPO", "hyperparameters": {}}
        path = tmp_path / "bad.yaml"
        path.write_text(yaml.safe_dump(bad))
        with pytest.raises(ConfigError, match="residual_after_squash") as err:
            load_rl_config(path)
        assert "bad.yaml" in str(err.value)


def test_a_clipped_base_gives_authority_beyond_1_plus_l(started, restore, tmp_path):
    """``residual_base_clipped``: a = clip(clip(a_lqr) + L u); where |a_lqr| >= 1 + L (the LQR's unclipped action by
    its own code) a residual bias -2 sign(a_lqr) gives |a| = 1 - L tanh(2); the unclipped base (the runs' form)
    leaves those controls at +-1. Untrained, both act as the LQR bit for bit."""
    after, _, lqr, obs, venv = started
    clipped = sac_model(venv, residual_limit=LIMIT, residual_after_squash=True, residual_base_clipped=True)
    start_residual(clipped, lqr, venv, 50)
    lqr.reset_clip_count()
    assert np.array_equal(clipped.predict(obs, deterministic=True)[0], lqr.predict(obs)[0])
    a_lqr = unclipped(lqr, obs)
    rows = np.flatnonzero((np.abs(a_lqr) >= 1.0 + LIMIT).any(axis=1))
    assert len(rows) >= 3
    for i in rows[:3]:
        far = np.abs(a_lqr[i]) >= 1.0 + LIMIT
        got = []
        for model in (clipped, after):
            set_residual(model.policy.actor, 0.0, -2.0 * np.sign(a_lqr[i]))
            got.append(model.predict(obs[i][None], deterministic=True)[0][0].astype(np.float64))
        np.testing.assert_allclose(np.abs(got[0][far]), 1.0 - LIMIT * np.tanh(2.0), atol=1e-7)
        assert np.all(np.abs(got[1][far]) == 1.0)  # the unclipped base: the clip absorbs the residual
    with pytest.raises(ValueError, match="residual_base_clipped True must be true or false, and true only with"):
        ResidualSACPolicy(after.observation_space, after.action_space, lambda _: 1e-3, residual_limit=0.2,
                          residual_base_clipped=True)
    data = yaml.safe_load(Path(CONFIG).read_text())
    for value, ok in ((True, True), ("yes", False)):
        path = tmp_path / "clipped.yaml"
        kwargs = {**data["policy_kwargs"], "residual_base_clipped": value}
        path.write_text(yaml.safe_dump({**data, "policy_kwargs": kwargs}))
        if ok:
            assert load_rl_config(path).policy_kwargs["residual_base_clipped"] is True
        else:
            with pytest.raises(ConfigError, match="residual_base_clipped") as err:
                load_rl_config(path)
            assert "clipped.yaml" in str(err.value)
