"""The optional phases of a training config (control/rl_phases.py, harness/validation.py): the warm start's affine
map of the LQR reproduces the LQR controller's actions (the controller itself is the oracle, in float64) on sampled
observations up to large excursions; the critic-only phase leaves the actor unchanged while the critic learns; the
validation counts survivals as the gust suite's record (the LQR holds EDC_IA, open loop does not: README's
scorecard); bad phase sections are named."""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.factory import make_controller  # noqa: E402
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.rl_phases import Validation, ValidationSet  # noqa: E402
from laddermill_gym.control.warm_start import affine_map  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402
from tests.test_warm_start import small_ppo_config  # noqa: E402

TW = "laddermill_gym/TetheredWing-v0"
TW_CONFIG = "configs/agents/ppo_tethered_wing.yaml"


def test_the_warm_start_map_is_the_lqr_to_1e_9_on_sampled_observations():
    import gymnasium as gym

    lqr = make_controller("lqr", TW)
    obs0, _ = gym.make(TW).reset(seed=0)  # the trimmed start: the probe point of warm_start
    W, b = affine_map(lqr, obs0)
    exact = copy.copy(lqr)
    exact.action_dtype = np.float64  # the oracle without its float32 cast
    rng = np.random.default_rng(1)
    # excursions up to 60 m, 20 m/s, 1 rad and 2 rad/s (NTM_IB moves the wing 65 m): scales of the 15 entries
    scale = np.array([60, 60, 20, 20, 20, 20, 1, 1, 1, 2, 2, 2, 1, 1, 1000.0])
    size = 10.0 ** rng.uniform(-3, 0, (400, 1))  # from 0.1 % of those to all of them
    obs = obs0 + rng.uniform(-1, 1, (400, obs0.size)) * scale * size
    expected = exact.predict(obs, deterministic=True)[0]
    np.testing.assert_allclose(np.clip(obs @ W.T + b, -1.0, 1.0), expected, rtol=0, atol=1e-9)
    assert 0.2 < np.mean(np.abs(expected[:, 1:]) >= 1.0) < 0.9  # large ones: many saturate, many do not


def _small_config(tmp_path, **changes):
    return small_ppo_config(tmp_path, n_epochs=2, **changes)


def test_the_critic_only_phase_leaves_the_actor_and_trains_the_critic(tmp_path):
    import stable_baselines3 as sb3
    import torch
    from stable_baselines3.common.vec_env import VecMonitor, VecNormalize

    from laddermill_gym.control.warm_start import start_from
    from laddermill_gym.harness.train import training_env
    from laddermill_gym.harness.validation import freeze_actor, set_learning_rate

    cfg = load_rl_config(_small_config(tmp_path))
    venv = VecNormalize(VecMonitor(training_env(cfg)), norm_obs=True, norm_reward=False, clip_obs=10.0)
    model = sb3.PPO("MlpPolicy", venv, seed=0, policy_kwargs=cfg.policy_kwargs, device="cpu", **cfg.hyperparameters)
    start_from(cfg, model, venv)
    p = model.policy
    actor0 = [t.detach().clone() for t in (p.action_net.weight, p.action_net.bias, p.log_std)]
    critic0 = [t.detach().clone() for t in p.value_net.parameters()]
    freeze_actor(model, True)
    set_learning_rate(model, 1e-3)
    model.learn(256)
    actor = (p.action_net.weight, p.action_net.bias, p.log_std)
    assert all(torch.equal(a, b) for a, b in zip(actor0, actor, strict=True))
    assert not all(torch.equal(a, b) for a, b in zip(critic0, p.value_net.parameters(), strict=True))
    freeze_actor(model, False)
    model.learn(256)
    assert not torch.equal(actor0[0], p.action_net.weight)  # free again: PPO moves it


def test_validation_counts_the_survivors_as_the_gust_suite_does():
    from laddermill_gym.harness.validation import score, validate

    edc = {"type": "EDC", "wind_class": "IA", "wind_speed": 8.08, "hub_height": 100.5, "diameter": 20.0, "time": 5.0}
    val = Validation(every=1, seed=0, episode_time=60.0, sets=(ValidationSet("edc", 1, [edc]),))
    res = {spec: validate(make_controller(spec, TW), TW, {}, val) for spec in ("lqr", "open_loop")}
    assert res["lqr"]["per_set"] == {"edc": 1} and res["open_loop"]["per_set"] == {"edc": 0}  # gusts-v1 EDC_IA
    assert score(res["lqr"]) > score(res["open_loop"])


def test_the_shipped_config_reads_its_phases():
    cfg = load_rl_config(TW_CONFIG)
    assert cfg.critic_warmup.steps > 0 and cfg.validation.seed >= 1000  # seeds disjoint from gusts-v1's
    assert {s.name for s in cfg.validation.sets} == {"ntm_ib", "dryden_light", "gusts"}


@pytest.mark.parametrize("change, match", [
    (dict(init_from=None, critic_warmup={"steps": 10, "learning_rate": 1e-3}), r"'critic_warmup' = .*needs init_from"),
    (dict(critic_warmup={"steps": 10, "learning_rate": 1e-3, "lr": 1}), r"unknown field 'critic_warmup\.lr'"),
    (dict(critic_warmup={"steps": -5, "learning_rate": 1e-3}), r"'critic_warmup\.steps' = -5: must be > 0"),
    (dict(validation={"every": 10, "seed": 1000, "episode_time": 60.0, "sets": {}}), r"'validation\.sets' = .*mapping"),
    (dict(validation={"every": 10, "seed": 1000, "episode_time": 60.0, "sets": {"a": {"episodes": 2}}}),
     r"'validation\.sets\.a\.disturbances' = \[\]: must list at least one"),
    (dict(validation={"every": 10, "seed": 1000, "episode_time": 60.0,
                      "sets": {"a": {"episodes": 2, "disturbances": [{"type": "Nope"}]}}}), r"Nope"),
])
def test_bad_phases_are_named(tmp_path, change, match):
    data = yaml.safe_load(Path(TW_CONFIG).read_text())
    data.update(change)
    data = {k: v for k, v in data.items() if v is not None}
    p = tmp_path / "bad.yaml"
    p.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=match):
        load_rl_config(p)
