"""The linear actors' fixed-order float64 evaluation (control/exact_actor.py).

Oracles: a scalar Python loop written from the formula (Python floats are IEEE doubles, each product and sum
rounded once, in the loop's order), which the vectorised evaluation must equal bit for bit; and SB3's own float32
torch evaluation of the same policy, which it must equal to float32 rounding.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.control.exact_actor import affine_fixed_order


def scalar_affine(x, w, b):
    """The oracle: out[n][m] = (...((b[m] + w[m][0] x[n][0]) + w[m][1] x[n][1]) + ...) in Python floats."""
    out = []
    for row in x.tolist():
        vals = []
        for m, wm in enumerate(w.tolist()):
            acc = float(b[m])
            for wi, xi in zip(wm, row, strict=True):
                acc = acc + wi * xi
            vals.append(acc)
        out.append(vals)
    return np.array(out, dtype=np.float64)


def test_fixed_order_equals_the_scalar_loop_bit_for_bit():
    rng = np.random.default_rng(7)
    x = rng.normal(size=(33, 21)) * np.exp(rng.uniform(-8, 8, size=(33, 21)))  # a wide spread of magnitudes
    w = rng.normal(size=(5, 21)).astype(np.float32)
    b = rng.normal(size=5).astype(np.float32)
    got = affine_fixed_order(x, w, b)
    want = scalar_affine(x, w.astype(np.float64), b.astype(np.float64))
    assert got.dtype == np.float64
    assert np.array_equal(got, want)


def test_zeros_signed_zeros_and_non_finite_weights_give_the_scalar_loops_bits():
    """The compiled loop skips a zero input's term only where it cannot change the sum: the oracle's bits with
    mostly zero inputs (as the shared policies' features are), zero and negative-zero biases and inputs, a zero
    sum reached by cancellation, and an infinite weight met by a zero input (NaN)."""
    rng = np.random.default_rng(3)
    x = rng.normal(size=(40, 30)) * (rng.uniform(size=(40, 30)) < 0.1)
    x[rng.uniform(size=x.shape) < 0.3] = -0.0
    x[0, :] = 0.0
    x[1, :] = -0.0
    x[2, :2] = (1.0, 1.0)  # with w[:, 0] = -w[:, 1] below: the sum cancels to +0 on the way
    w = rng.normal(size=(4, 30))
    w[:, 1] = -w[:, 0]
    b = np.array([0.0, -0.0, 1.5, -0.0])
    got = affine_fixed_order(x, w, b)
    want = scalar_affine(x, w, b)
    assert np.array_equal(got, want) and np.array_equal(np.signbit(got), np.signbit(want))
    w[2, 5] = np.inf
    got, want = affine_fixed_order(x, w, b), scalar_affine(x, w, b)
    assert np.isnan(got[0, 2]) and np.array_equal(got, want, equal_nan=True)
    assert np.array_equal(np.signbit(got), np.signbit(want))


def test_a_row_gives_the_same_bits_alone_and_in_any_batch():
    rng = np.random.default_rng(11)
    x = rng.normal(size=(512, 19))
    w, b = rng.normal(size=(12, 19)), rng.normal(size=12)
    batch = affine_fixed_order(x, w, b)
    for n in (0, 7, 255, 511):
        assert np.array_equal(affine_fixed_order(x[n:n + 1], w, b)[0], batch[n])
    assert np.array_equal(affine_fixed_order(x[::-1], w, b)[::-1], batch)


def test_mismatched_shapes_are_refused():
    with pytest.raises(ValueError, match="do not fit"):
        affine_fixed_order(np.zeros((3, 4)), np.zeros((2, 5)), np.zeros(2))
    with pytest.raises(ValueError, match="do not fit"):
        affine_fixed_order(np.zeros((3, 4)), np.zeros((2, 4)), np.zeros(3))


def _ppo(net_arch, seed=0):
    sb3 = pytest.importorskip("stable_baselines3")
    import gymnasium as gym

    env = gym.make("Pendulum-v1")
    return sb3.PPO("MlpPolicy", env, policy_kwargs=dict(net_arch=net_arch), seed=seed, device="cpu")


def test_sb3_linear_actor_matches_torch_to_float32_rounding_and_clips():
    from laddermill_gym.control.exact_actor import sb3_linear_actor
    from laddermill_gym.control.sb3_policy import SB3Controller

    torch = pytest.importorskip("torch")
    model = _ppo(dict(pi=[], vf=[8]))
    with torch.no_grad():
        model.policy.action_net.weight.copy_(torch.tensor([[1.5, -0.7, 0.3]]))  # some actions beyond [-2, 2]
    actor = sb3_linear_actor(model.policy)
    assert actor is not None
    obs = np.random.default_rng(3).uniform(-1, 1, size=(64, 3)) * np.array([1.0, 1.0, 8.0])
    mean, var = np.array([0.1, -0.2, 0.3]), np.array([0.5, 0.4, 9.0])
    exact = SB3Controller(model, mean, var, exact=True)
    torch_ctrl = SB3Controller(model, mean, var)
    got, _ = exact.predict(obs, deterministic=True)
    want, _ = torch_ctrl.predict(obs, deterministic=True)
    assert got.dtype == np.float64 and want.dtype == np.float32
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-5)
    assert np.any(np.abs(got) == 2.0)  # clipped to the action space as SB3's predict does
    x = np.clip((obs - mean) / np.sqrt(var + 1e-8), -10.0, 10.0)
    w = model.policy.action_net.weight.detach().numpy().astype(np.float64)
    b = model.policy.action_net.bias.detach().numpy().astype(np.float64)
    assert np.array_equal(got, np.clip(scalar_affine(x, w, b), -2.0, 2.0))
    one, _ = exact.predict(obs[5], deterministic=True)
    assert one.shape == (1,) and np.array_equal(one, got[5])
    stochastic, _ = exact.predict(obs, deterministic=False)  # sampling stays SB3's
    assert stochastic.dtype == np.float32


def test_other_policies_stay_with_torch():
    from laddermill_gym.control.exact_actor import sb3_linear_actor
    from laddermill_gym.control.sb3_policy import SB3Controller

    hidden = _ppo(dict(pi=[8], vf=[8]))
    assert sb3_linear_actor(hidden.policy) is None
    assert SB3Controller(hidden, exact=True).linear is None


def test_the_shipped_single_craft_policies_run_exact():
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.control.shipped_policies import shipped_policy_path

    for name in ("ppo_tethered_wing", "ppo_rotorcraft"):
        exact = SB3Controller.load(shipped_policy_path(name))
        assert exact.linear is not None, name
        torch_ctrl = SB3Controller.load(shipped_policy_path(name), exact=False)
        assert torch_ctrl.linear is None
        dim = exact.model.observation_space.shape[0]
        obs = exact.obs_mean + np.random.default_rng(1).normal(size=(16, dim)) * exact.obs_std
        got, want = exact.predict(obs, deterministic=True)[0], torch_ctrl.predict(obs, deterministic=True)[0]
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-5)
        alone = np.array([exact.predict(o, deterministic=True)[0] for o in obs])
        assert np.array_equal(alone, got)


def test_torch_actions_of_one_observation_against_a_batch():
    """The shipped tethered-wing policy on 512 observations drawn about its normalisation: each observation alone
    against all 512 at once. The fixed-order float64 actor gives the same bits either way; SB3's torch predict agrees
    to float32 rounding only (its last bits depend on the CPU's kernels and the batch size). Prints both
    differences and the CPU's torch kernels."""
    torch = pytest.importorskip("torch")
    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.control.shipped_policies import shipped_policy_path

    exact = SB3Controller.load(shipped_policy_path("ppo_tethered_wing"))
    torch_ctrl = SB3Controller.load(shipped_policy_path("ppo_tethered_wing"), exact=False)
    dim = exact.model.observation_space.shape[0]
    obs = exact.obs_mean + np.random.default_rng(1).normal(size=(512, dim)) * exact.obs_std
    apart = {}
    for name, ctrl in (("float64 fixed order", exact), ("torch float32", torch_ctrl)):
        batch = ctrl.predict(obs, deterministic=True)[0]
        alone = np.array([ctrl.predict(o, deterministic=True)[0] for o in obs]).reshape(batch.shape)
        apart[name] = float(np.abs(alone - batch).max())
    print(f"one observation alone against 512 at once: torch float32 up to {apart['torch float32']:.2g} apart, "
          f"float64 fixed order {apart['float64 fixed order']:.2g} (torch {torch.__version__}, CPU capability "
          f"{torch.backends.cpu.get_cpu_capability()}, MKL {torch.backends.mkl.is_available()})")
    assert apart["float64 fixed order"] == 0.0
    assert apart["torch float32"] < 1e-5
