"""The slower actor of the residual SAC policy (control/residual_sac.py, ``policy_kwargs.optimizer_kwargs.
actor_lr_scale: s``): the actor's optimiser steps at s times SB3's learning rate, the critics' at the rate itself.

Oracle: Adam's update written out independently in numpy (Kingma and Ba 2015, Algorithm 1: m and v moving
averages with bias correction, step lr m_hat / (sqrt(v_hat) + eps)), fed the same gradients as the policy's
optimisers; its first step is the closed form -lr g / (|g| + eps)."""

from __future__ import annotations

import numpy as np
import pytest
import torch

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.residual_sac import ResidualSACPolicy, scale_steps  # noqa: E402
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402

ENV_ID = "laddermill_gym/TetheredWing-v0"
CONFIG = "configs/agents/sac_tethered_wing_residual_slow_actor.yaml"
RATE, SCALE = 3.0e-5, 0.1  # [-] the config's learning rate and actor_lr_scale


def sac_model(**optimizer_kwargs):
    import gymnasium as gym
    from stable_baselines3 import SAC
    from stable_baselines3.common.vec_env import DummyVecEnv

    venv = DummyVecEnv([lambda: gym.make(ENV_ID)])
    kwargs = dict(optimizer_kwargs=optimizer_kwargs) if optimizer_kwargs else {}
    return SAC(ResidualSACPolicy, venv, device="cpu", seed=0, learning_rate=RATE, learning_starts=0, batch_size=32,
               buffer_size=1000, policy_kwargs=dict(net_arch=[16, 16], log_std_init=-1.6, residual_limit=0.2,
                                                    residual_after_squash=True, residual_base_clipped=True, **kwargs))


def adam_oracle(p0: np.ndarray, grads: list[np.ndarray], lr: float, b1=0.9, b2=0.999, eps=1e-8) -> np.ndarray:
    """Adam's iterates (float64) from ``p0`` under ``grads``, one step each, at rate ``lr``."""
    p, m, v = p0.astype(np.float64), np.zeros_like(p0, dtype=np.float64), np.zeros_like(p0, dtype=np.float64)
    for t, g in enumerate(grads, start=1):
        m = b1 * m + (1 - b1) * g
        v = b2 * v + (1 - b2) * g * g
        p = p - lr * (m / (1 - b1 ** t)) / (np.sqrt(v / (1 - b2 ** t)) + eps)
    return p


def step_both(model, n_steps: int) -> dict:
    """Feed both optimisers ``n_steps`` seeded gradients (as SAC.train does: the rate set first, then steps); the
    parameters before and after and the gradients, by name."""
    from stable_baselines3.common.utils import update_learning_rate

    for opt in (model.actor.optimizer, model.critic.optimizer):  # as SAC._update_learning_rate, without its logger
        update_learning_rate(opt, model.lr_schedule(1.0))
    rng = np.random.default_rng(7)
    out = {}
    for opt_name, opt in (("actor", model.actor.optimizer), ("critic", model.critic.optimizer)):
        params = [p for g in opt.param_groups for p in g["params"]]
        before = [p.detach().double().numpy().copy() for p in params]
        grads = [[rng.normal(0.0, 10.0 ** rng.uniform(-4, 0), p.shape) for p in params] for _ in range(n_steps)]
        for k in range(n_steps):
            opt.zero_grad()
            for p, g in zip(params, grads[k], strict=True):
                p.grad = torch.as_tensor(g, dtype=p.dtype)
            opt.step()
        after = [p.detach().double().numpy() for p in params]
        out[opt_name] = (before, after, [[gs[i] for gs in grads] for i in range(len(params))], opt)
    return out


@pytest.mark.parametrize("n_steps", [1, 3])
def test_actor_steps_at_the_scaled_rate(n_steps):
    """Every actor parameter follows Adam at SCALE x RATE, every critic parameter Adam at RATE (to float32
    rounding of the parameters, 1e-6 of a step); the groups' rate is RATE again after the steps."""
    out = step_both(sac_model(actor_lr_scale=SCALE), n_steps)
    for name, lr in (("actor", SCALE * RATE), ("critic", RATE)):
        before, after, grads, opt = out[name]
        for p0, p1, g in zip(before, after, grads, strict=True):
            ulp = float(np.spacing(np.float32(np.max(np.abs(p0)))))  # [-] the float32 parameters' rounding
            assert np.max(np.abs(p1 - adam_oracle(p0, g, lr))) <= 1e-5 * n_steps * lr + n_steps * ulp, name
        assert all(group["lr"] == RATE for group in opt.param_groups)
    before, after, grads, _ = out["actor"]
    zero = [i for i, p0 in enumerate(before) if not p0.any()]  # the zero-started residual layers: no rounding floor
    assert zero
    if n_steps == 1:  # the closed form of Adam's first step: -lr g / (|g| + eps), about -lr sign(g)
        for i in zero:
            g = grads[i][0]
            np.testing.assert_allclose(after[i], -SCALE * RATE * g / (np.abs(g) + 1e-8), rtol=1e-5, atol=0.0)


def test_default_is_unchanged_and_the_scale_is_saved(tmp_path):
    """Without the key the optimisers have no step hooks and the constructor's optimizer_kwargs are SB3's; with
    it, SAC.save / SAC.load rebuild the slower actor (its rate scaled, the critics' not)."""
    from stable_baselines3 import SAC

    plain = sac_model()
    assert plain.policy.actor_lr_scale is None
    for opt in (plain.actor.optimizer, plain.critic.optimizer):
        assert not opt._optimizer_step_pre_hooks and not opt._optimizer_step_post_hooks
    assert plain.policy._get_constructor_parameters()["optimizer_kwargs"] == {}
    slow = sac_model(actor_lr_scale=SCALE)
    assert slow.actor.optimizer.defaults == plain.actor.optimizer.defaults  # the key never reaches Adam
    slow.save(tmp_path / "slow.zip")
    loaded = SAC.load(tmp_path / "slow.zip", device="cpu")
    assert loaded.policy.actor_lr_scale == SCALE
    out = step_both(loaded, 1)
    for name, lr in (("actor", SCALE * RATE), ("critic", RATE)):
        before, after, grads, _ = out[name]
        for p0, p1, g in zip(before, after, grads, strict=True):
            ulp = float(np.spacing(np.float32(np.max(np.abs(p0)))))
            assert np.max(np.abs(p1 - adam_oracle(p0, g, lr))) <= 1e-5 * lr + ulp, name


def test_scale_steps_on_a_plain_optimiser():
    """scale_steps on SGD (step -lr g, the simplest oracle): the step is scale x lr x g, the rate restored."""
    w = torch.nn.Parameter(torch.tensor([1.0, -2.0], dtype=torch.float64))
    opt = torch.optim.SGD([w], lr=0.5)
    scale_steps(opt, 0.25)
    w.grad = torch.tensor([2.0, 4.0], dtype=torch.float64)
    opt.step()
    assert w.detach().tolist() == [1.0 - 0.125 * 2.0, -2.0 - 0.125 * 4.0] and opt.param_groups[0]["lr"] == 0.5


@pytest.mark.parametrize("bad", [0.0, -0.1, 1.5, "slow", True])
def test_bad_scale(bad):
    with pytest.raises(ValueError, match=f"actor_lr_scale {bad!r} must be a number in"):
        sac_model(actor_lr_scale=bad)


def test_config_carries_the_scale():
    cfg = load_rl_config(CONFIG)
    assert cfg.policy_kwargs["optimizer_kwargs"] == {"actor_lr_scale": SCALE}
    assert cfg.hyperparameters["learning_rate"] == RATE
