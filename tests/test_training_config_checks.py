"""Training configs and commands that would fail after the envs are built are refused first, and a run folder
records how it was made (found by a review): hyperparameters a config may not set (private names, Python classes
and objects, unknown buffer arguments, a squashed PPO without gSDE), a critic warm-up that never ends, a config that
fails at model build leaving its --out free, ``run.yaml``, and ``laddermill train-seeds`` checking its options as
``laddermill train`` does.

Oracles: Stable-Baselines3 itself (what it builds and what it refuses on a stand-in env), the packages' installed
versions (``importlib.metadata``), and ``laddermill train``'s own messages for the same options.
"""

from __future__ import annotations

import platform
import sys
from importlib.metadata import version
from pathlib import Path

import gymnasium as gym
import numpy as np
import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.envs import ENV_IDS  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402

TW = "laddermill_gym/TetheredWing-v0"
PPO_CONFIG, SAC_CONFIG = "configs/agents/ppo_tethered_wing.yaml", "configs/agents/sac_tethered_wing.yaml"


class _Spaces(gym.Env):
    observation_space = gym.spaces.Box(-1.0, 1.0, (4,), np.float32)
    action_space = gym.spaces.Box(-1.0, 1.0, (2,), np.float32)


def _config(tmp_path, source=PPO_CONFIG, hyper=None, name="cfg.yaml", **top):
    """``source`` with ``hyper`` merged into its hyperparameters and ``top`` replacing top-level fields; its path."""
    data = yaml.safe_load(Path(source).read_text())
    data["hyperparameters"].update(hyper or {})
    data.update(top)
    path = tmp_path / name
    path.write_text(yaml.safe_dump(data))
    return path


def _tiny(tmp_path):
    """ppo_tethered_wing.yaml cut to one rollout of 2 x 32 steps (no warm-up, no validation)."""
    data = yaml.safe_load(Path(PPO_CONFIG).read_text())
    data.pop("critic_warmup")
    data.pop("validation")
    data.update(n_envs=2, total_timesteps=64, time_limit_minutes=2.0, checkpoint_every=64,
                eval={"every": 64, "episodes": 1})
    data["env_kwargs"]["episode_time"] = 2.0
    data["hyperparameters"].update(n_steps=32, batch_size=64, n_epochs=1)
    path = tmp_path / "tiny.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


@pytest.mark.parametrize("source, hyper, field, why", [
    (PPO_CONFIG, {"_init_setup_model": False}, "hyperparameters._init_setup_model", "not an argument of PPO"),
    (PPO_CONFIG, {"rollout_buffer_class": "foo"}, "hyperparameters.rollout_buffer_class", "a Python object"),
    (SAC_CONFIG, {"replay_buffer_class": "foo"}, "hyperparameters.replay_buffer_class", "a Python object"),
    (SAC_CONFIG, {"action_noise": "normal"}, "hyperparameters.action_noise", "a Python object"),
    (PPO_CONFIG, {"rollout_buffer_kwargs": {"foo": 1}}, "hyperparameters.rollout_buffer_kwargs.foo",
     "not an argument of RolloutBuffer"),
    (SAC_CONFIG, {"replay_buffer_kwargs": {"n_envs": 2}}, "hyperparameters.replay_buffer_kwargs.n_envs",
     "not an argument of ReplayBuffer a config may set"),
    (SAC_CONFIG, {"replay_buffer_kwargs": {"handle_timeout_termination": "no"}},
     "hyperparameters.replay_buffer_kwargs.handle_timeout_termination", "true or false"),
    (SAC_CONFIG, {"optimize_memory_usage": True}, "hyperparameters.optimize_memory_usage",
     "handle_timeout_termination: false"),
])
def test_hyperparameters_a_config_may_not_set_are_named(tmp_path, source, hyper, field, why):
    with pytest.raises(ConfigError, match=rf"cfg\.yaml: field '{field}' = .*{why}"):
        load_rl_config(_config(tmp_path, source, hyper))


def test_what_the_config_takes_sb3_builds_and_what_it_refuses_sb3_refuses(tmp_path):
    from stable_baselines3 import PPO, SAC

    env = _Spaces()
    ok = {"replay_buffer_kwargs": {"handle_timeout_termination": False}, "optimize_memory_usage": True}
    assert load_rl_config(_config(tmp_path, SAC_CONFIG, ok)).hyperparameters["replay_buffer_kwargs"] == \
        ok["replay_buffer_kwargs"]
    SAC("MlpPolicy", env, buffer_size=10, device="cpu", **ok)
    with pytest.raises(ValueError):  # SB3's ReplayBuffer: not both (the config check above names it)
        SAC("MlpPolicy", env, buffer_size=10, device="cpu", optimize_memory_usage=True)
    with pytest.raises(TypeError):  # SB3 gives n_envs itself
        SAC("MlpPolicy", env, buffer_size=10, device="cpu", replay_buffer_kwargs={"n_envs": 2})
    with pytest.raises(TypeError):
        PPO("MlpPolicy", env, n_steps=8, batch_size=8, device="cpu", rollout_buffer_kwargs={"foo": 1})
    with pytest.raises(AssertionError):  # SB3 asserts squash_output only with gSDE
        PPO("MlpPolicy", env, n_steps=8, batch_size=8, device="cpu", policy_kwargs={"squash_output": True})
    PPO("MlpPolicy", env, n_steps=8, batch_size=8, device="cpu", use_sde=True, policy_kwargs={"squash_output": True})
    data = yaml.safe_load(Path(PPO_CONFIG).read_text())
    squash = dict(data["policy_kwargs"], squash_output=True)
    with pytest.raises(ConfigError, match=r"field 'policy_kwargs\.squash_output' = True: needs "
                                          r"hyperparameters\.use_sde: true"):
        load_rl_config(_config(tmp_path, policy_kwargs=squash))
    assert load_rl_config(_config(tmp_path, hyper={"use_sde": True}, policy_kwargs=squash)).policy_kwargs[
        "squash_output"] is True


def test_a_critic_warmup_at_or_beyond_the_run_is_refused_naming_both(tmp_path):
    for total in (400000, 300000):  # the config's warm-up is 400,000 steps
        with pytest.raises(ConfigError, match=rf"field 'critic_warmup\.steps' = 400000: must be below "
                                              rf"total_timesteps = {total}"):
            load_rl_config(_config(tmp_path, total_timesteps=total))
    assert load_rl_config(_config(tmp_path, total_timesteps=400001)).critic_warmup.steps == 400000


def test_a_config_failing_at_model_build_leaves_its_out_free(tmp_path):
    """SB3 refuses the model (here a buffer class given as text, which the config check now refuses first); the
    folder gets nothing, so the same --out can be given again (before: config.yaml was written and the second run
    was refused as 'holds a training run already')."""
    import dataclasses

    from laddermill_gym.harness.train import train

    cfg = load_rl_config(_tiny(tmp_path))
    bad = dataclasses.replace(cfg, hyperparameters=dict(cfg.hyperparameters, rollout_buffer_class="foo"))
    out = tmp_path / "run"
    for _ in range(2):
        with pytest.raises(TypeError, match="not callable"):
            train(bad, out, threads=1)
        assert not out.exists() or not any(out.iterdir())


def test_the_run_folder_records_command_versions_threads_and_seed(tmp_path, monkeypatch):
    import torch

    import laddermill_gym
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.harness.reselect import candidates
    from laddermill_gym.harness.train import main

    monkeypatch.setitem(ENV_IDS, TW, dict(ENV_IDS[TW], episode_time=2.0))  # short evaluation episodes
    out = tmp_path / "run"
    argv = ["laddermill", "train", str(_tiny(tmp_path)), "--out", str(out), "--seed", "3", "--torch-threads", "2"]
    monkeypatch.setattr(sys, "argv", argv)
    threads = torch.get_num_threads()
    try:
        assert main(argv[2:]) == 0
    finally:
        torch.set_num_threads(threads)
    record = yaml.safe_load((out / "run.yaml").read_text())
    assert record["command"] == argv and record["seed"] == 3 and record["torch_threads"] == 2
    want = {name: version(name) for name in ("stable_baselines3", "torch", "numpy", "gymnasium")}
    want.update(laddermill_gym=laddermill_gym.__version__, python=platform.python_version())
    assert record["versions"] == want
    # the readers of run folders take it as before: the policy loads, reselect lists its models
    assert make_controller(str(out), TW).trained_env == TW
    assert [label for label, _m, _s in candidates(out)][-1] == "run/model"


def _message(err: str) -> str:
    """The message of a ``PROG: error: MESSAGE (see PROG --help)`` line."""
    line = err.strip().splitlines()[-1]
    return line.split(": error: ", 1)[1].split(" (see ", 1)[0]


@pytest.mark.parametrize("options, text", [
    (["--n-envs", "5000"], "--n-envs = 5000: must be a whole number > 0 and <= 4096"),
    (["--n-envs", "1"], "'hyperparameters.batch_size' = 1024: must be at most 256"),  # n_steps 256 x 1 copy
    (["--timesteps", "1000"], "'critic_warmup.steps' = 400000 must be below total_timesteps = 1000"),
])
def test_train_seeds_checks_its_options_as_train_does(tmp_path, monkeypatch, capsys, options, text):
    from laddermill_gym.harness import train as train_mod
    from laddermill_gym.harness import train_seeds

    def trained(*_a, **_k):
        raise AssertionError("the options were not refused: it trained")

    monkeypatch.setattr(train_seeds, "train_seeds", trained)
    monkeypatch.setattr(train_mod, "train", trained)
    with pytest.raises(SystemExit) as err:
        train_mod.main([PPO_CONFIG, "--out", str(tmp_path / "one"), *options])
    assert err.value.code == 2
    expected = _message(capsys.readouterr().err)
    assert text in expected
    with pytest.raises(SystemExit) as err:
        train_seeds.main([PPO_CONFIG, "--seeds", "0", "--out-root", str(tmp_path), *options])
    assert err.value.code == 2
    assert capsys.readouterr().err.strip() == f"laddermill train-seeds: error: {expected}"


def test_gradient_steps_zero_is_refused_and_minus_one_or_more_taken(tmp_path):
    """SB3's off-policy algorithms skip the update when gradient_steps is 0 (``if gradient_steps > 0: train``), so a
    run would train nothing: refused, naming the field; -1 (as many as env steps) and 1 are taken."""
    with pytest.raises(ConfigError, match=r"cfg\.yaml: field 'hyperparameters\.gradient_steps' = 0: must be -1"):
        load_rl_config(_config(tmp_path, SAC_CONFIG, {"gradient_steps": 0}))
    for ok in (-1, 1):
        assert load_rl_config(_config(tmp_path, SAC_CONFIG, {"gradient_steps": ok})).hyperparameters[
            "gradient_steps"] == ok


@pytest.mark.parametrize("key, value, ok", [
    ("ent_coef", "auto", True), ("ent_coef", "auto_0.1", True), ("target_entropy", "auto", True),
    # accepted by the check and refused by SB3 when it built the model (review of 2026-12-08): SB3 takes
    # target_entropy 'auto' or a number, and logs an initial ent_coef, which must be above 0
    ("target_entropy", "auto_0.5", False), ("ent_coef", "auto_0", False), ("ent_coef", "auto_", False),
    ("ent_coef", "auto_-1", False)])
def test_sac_auto_texts_are_those_sb3_takes(tmp_path, key, value, ok):
    from stable_baselines3 import SAC

    try:  # the oracle: SB3 itself, on a small env
        SAC("MlpPolicy", "Pendulum-v1", buffer_size=10, device="cpu", **{key: value})
        builds = True
    except (ValueError, AssertionError):
        builds = False
    assert builds == ok
    path = _config(tmp_path, SAC_CONFIG, {key: value})
    if ok:
        assert load_rl_config(path).hyperparameters[key] == value
    else:
        with pytest.raises(ConfigError, match=rf"cfg\.yaml: field 'hyperparameters\.{key}' = '{value}': 'auto'"):
            load_rl_config(path)


def test_a_sac_critic_warmup_needs_a_fixed_entropy_coefficient(tmp_path):
    """With SAC's learned entropy coefficient (``ent_coef: auto``, its default) the warm-up's frozen actor keeps the
    entropy's gradient of one sign, so log(alpha) drifts by about the learning rate per gradient step: refused,
    naming the field and the value; the shipped residual configs' fixed 0.001 is taken."""
    source = "configs/agents/sac_tethered_wing_residual_after_warmup.yaml"
    data = yaml.safe_load(Path(source).read_text())
    assert data["hyperparameters"]["ent_coef"] == 0.001 and "critic_warmup" in data
    assert load_rl_config(source).critic_warmup is not None
    for auto in ("auto", "auto_0.1", None):
        hyper = dict(data["hyperparameters"])
        if auto is None:
            hyper.pop("ent_coef")
        else:
            hyper["ent_coef"] = auto
        path = tmp_path / "cfg.yaml"
        path.write_text(yaml.safe_dump(dict(data, hyperparameters=hyper)))
        with pytest.raises(ConfigError, match=rf"cfg\.yaml: field 'critic_warmup' = .*fixed hyperparameters\.ent_coef "
                                              rf"\(got '{auto or 'auto'}'\)"):
            load_rl_config(path)
