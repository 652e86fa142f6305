"""``laddermill train`` of a shared per-wing policy with ``ppo.n_copies`` != ``imitation.n_copies`` (SB3's
``set_env`` refuses another number of envs: such a run crashed after its whole DAgger phase). The oracles: the PPO
model's envs counted from the config (copies x wings), the learning rate the config sets, and ``bc_model.zip``, the
DAgger model written to disk before the PPO phase, whose every tensor the PPO phase's first model must hold."""

from __future__ import annotations

import pytest

pytest.importorskip("stable_baselines3", reason="the rl extra (SB3) is not installed")
import torch as th  # noqa: E402

#: A 5-wing chain, one DAgger round of 5 steps on 1 copy, then 200 PPO steps on 2 copies (about 7 s).
TINY = """
shared_policy: true
algorithm: PPO
env: laddermill_gym/LadderChain-v0
k: 1
n_basis: 5
seed: 0
time_limit_minutes: 5.0
env_kwargs:
  scene_options: {n_wings: 5}
  episode_time: 2.0
imitation: {iterations: 1, n_copies: 1, steps: 5, ridge: 1.0e-3, action_noise: 0.05}
ppo:
  n_copies: 2
  total_timesteps: 200
  time_limit_minutes: 1.0
  log_std_init: -3.0
  value_net: [8]
  hyperparameters: {n_steps: 8, batch_size: 10, n_epochs: 1, learning_rate: 2.5e-4}
eval: {episodes: 1, episode_time: 1.0, every: 100}
"""


def test_unequal_copies_train_and_ppo_starts_from_the_dagger_weights(tmp_path, monkeypatch):
    from stable_baselines3 import PPO

    from laddermill_gym.harness import shared_train

    cfg, out = tmp_path / "tiny.yaml", tmp_path / "run"
    cfg.write_text(TINY)
    start: dict = {}
    build = shared_train.ppo_phase_model

    def spy(*args, **kwargs):  # the PPO phase's model as it starts
        model = build(*args, **kwargs)
        start.update(n_envs=model.n_envs, lr=model.lr_schedule(1.0),
                     optimizer_lr=[g["lr"] for g in model.policy.optimizer.param_groups],
                     state={key: v.clone() for key, v in model.policy.state_dict().items()})
        return model

    monkeypatch.setattr(shared_train, "ppo_phase_model", spy)
    assert shared_train.main([str(cfg), "--out", str(out)]) == 0
    assert start["n_envs"] == 2 * 5  # ppo.n_copies x wings
    bc = PPO.load(out / "bc_model.zip", device="cpu")
    assert bc.n_envs == 1 * 5  # imitation.n_copies x wings
    dagger = bc.policy.state_dict()  # weights, log_std, the extractor's trim, scales and index buffers
    assert set(start["state"]) == set(dagger)
    for key, value in dagger.items():
        assert th.equal(start["state"][key], value), key
    assert start["lr"] == 2.5e-4 and start["optimizer_lr"] == [2.5e-4]
    last = PPO.load(out / "last_model.zip", device="cpu")
    assert last.n_envs == 2 * 5 and last.num_timesteps >= 200
    phases = (out / "training_curve.csv").read_text().splitlines()[1:]
    assert {row.split(",")[0] for row in phases} == {"imitation", "ppo"}
