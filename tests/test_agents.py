"""The agents harness: training configs (strict reading), a short Stable-Baselines3 PPO run through
``agents.train`` (a few hundred steps), loading the trained policy as a controller, the SB3 VecEnv adapter's
episode ends against the native vector env, and ``agents.evaluate`` on open loop and LQR."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
import yaml

from laddermill_gym.envs import ENV_IDS, WingVectorEnv
from laddermill_gym.model.configio import ConfigError

TW = "laddermill_gym/TetheredWing-v0"
PPO_CONFIG = "configs/agents/ppo_tethered_wing.yaml"


def _small_config(tmp_path, **changes):
    data = yaml.safe_load(Path(PPO_CONFIG).read_text())
    data.update(n_envs=4, total_timesteps=512, time_limit_minutes=2.0, checkpoint_every=256,
                eval={"every": 256, "episodes": 2})
    data["env_kwargs"]["episode_time"] = 5.0
    data["hyperparameters"].update(n_steps=64, batch_size=64, n_epochs=2)
    data["critic_warmup"]["steps"] = 256  # below total_timesteps (the actor trains after it)
    data.update(changes)
    p = tmp_path / "ppo_small.yaml"
    p.write_text(yaml.safe_dump(data))
    return p


def test_sb3_smoke_training_and_policy_as_controller(tmp_path, monkeypatch):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import train

    cfg = load_rl_config(_small_config(tmp_path))
    # evaluation episodes of 300 s would dominate a smoke test: shorten the registered scenario here
    monkeypatch.setitem(ENV_IDS, TW, dict(ENV_IDS[TW], episode_time=2.0))
    out = tmp_path / "run"
    summary = train(cfg, out)
    assert summary["steps"] >= 512
    for name in ("model.zip", "best_model.zip", "vecnormalize.pkl", "evaluations.csv", "training_curve.png",
                 "config.yaml", "references.csv"):
        assert (out / name).is_file(), name
    assert any((out / "checkpoints").iterdir())
    assert any((out / "tb").rglob("events.out.tfevents*"))
    ctrl = make_controller(str(out), TW)
    obs = np.zeros((3, 15), np.float32)
    a, _ = ctrl.predict(obs, deterministic=True)
    assert a.shape == (3, 3) and np.all(np.abs(a) <= 1.0)


def test_an_evaluation_on_the_last_step_is_of_the_saved_model(tmp_path, monkeypatch):
    """An evaluation that fell on the final step (4 + 508 = 512 = total_timesteps) was taken as the final model's,
    but SB3 updates the model once more after the last step's callback: evaluations.csv's last row was of a policy
    never saved (review of 2026-12-08). Oracle: the saved model.zip flown on the same evaluation episodes."""
    pytest.importorskip("stable_baselines3")
    import csv

    import gymnasium as gym
    from stable_baselines3.common.vec_env import DummyVecEnv

    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.evaluate import run_episodes
    from laddermill_gym.harness.train import evaluation_env, train

    cfg = load_rl_config(_small_config(tmp_path, eval={"every": 508, "episodes": 2}))
    monkeypatch.setitem(ENV_IDS, TW, dict(ENV_IDS[TW], episode_time=2.0))
    out = tmp_path / "run"
    train(cfg, out)
    with open(out / "evaluations.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [int(r["steps"]) for r in rows] == [4, 512]  # one row per step count: the final model's replaced it
    from stable_baselines3 import PPO
    from stable_baselines3.common.vec_env import VecNormalize

    from laddermill_gym.control.sb3_policy import SB3Controller

    env = evaluation_env(cfg)
    stats = VecNormalize.load(str(out / "vecnormalize.pkl"), DummyVecEnv([lambda: gym.make(TW)]))
    saved = SB3Controller(PPO.load(out / "model.zip", device="cpu"), stats.obs_rms.mean, stats.obs_rms.var,
                          stats.clip_obs, stats.epsilon)  # through torch, as the harness evaluates
    returns = run_episodes(saved, env, 2, record=False).returns  # the harness's evaluation, seeds 0 and 1
    assert float(rows[-1]["mean_return"]) == float(np.mean(returns))


def test_sac_config_trains_a_few_hundred_steps(tmp_path, monkeypatch):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import train

    data = yaml.safe_load(Path("configs/agents/sac_tethered_wing.yaml").read_text())
    data.update(n_envs=2, total_timesteps=300, checkpoint_every=200, eval={"every": 200, "episodes": 1})
    data["hyperparameters"].update(learning_starts=100, batch_size=32, gradient_steps=1)
    data["env_kwargs"]["episode_time"] = 3.0
    p = tmp_path / "sac_small.yaml"
    p.write_text(yaml.safe_dump(data))
    monkeypatch.setitem(ENV_IDS, TW, dict(ENV_IDS[TW], episode_time=2.0))
    summary = train(load_rl_config(p), tmp_path / "run")
    assert summary["steps"] >= 300
    assert (tmp_path / "run" / "algorithm.txt").read_text().strip() == "SAC"
    assert np.isfinite(summary["best_eval_return"])


def test_rl_config_errors_name_the_field(tmp_path):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.rl_config import load_rl_config

    for changes, field in (({"algorithm": "DQN"}, "algorithm"),
                           ({"hyperparameters": {"learning_rat": 1e-3}}, "hyperparameters.learning_rat"),
                           ({"env_kwargs": {"episode_tim": 5.0}}, "env_kwargs.episode_tim"),
                           ({"n_envs": 0}, "n_envs"),
                           ({"disturbances": [{"type": "Tornado"}]}, "disturbances"),
                           # SAC's only (PPO crashed at its first update); a typo'd part SB3 ignored (no critic)
                           ({"hyperparameters": {"ent_coef": "auto"}}, "hyperparameters.ent_coef"),
                           ({"policy_kwargs": {"net_arch": {"pi": [64], "qf": [64]}}}, "net_arch.qf"),
                           # SB3's PPO asserts it; a validation episode of a fraction of periods failed at the first
                           ({"hyperparameters": {"batch_size": 1}}, "hyperparameters.batch_size"),
                           ({"validation": {**yaml.safe_load(Path(PPO_CONFIG).read_text())["validation"],
                                            "episode_time": 5.03}}, "validation.episode_time"),
                           # each a traceback in torch, SB3 or load_scene before
                           ({"policy_kwargs": {"optimizer_kwargs": {"epss": 1e-5}}}, "optimizer_kwargs.epss"),
                           ({"policy_kwargs": {"features_extractor_kwargs": {"x": 1}}},
                            "features_extractor_kwargs.x"),
                           ({"env_kwargs": {"scene_options": {"bogus": 1}}}, "env_kwargs.scene_options.bogus"),
                           ({"env_kwargs": {"physics_dt": 0.03}}, "env_kwargs.physics_dt")):
        with pytest.raises(ConfigError, match=field.replace(".", r"\.")):
            load_rl_config(_small_config(tmp_path, **changes))


def test_sb3_adapter_episode_ends_match_native_vector_env():
    """SB3 resets in the same step and keeps the last observation in ``terminal_observation``; Gymnasium's
    SameStep autoreset keeps it in ``final_obs``: both must hold the same numbers, and both must come back
    with the same fresh start."""
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.envs.sb3 import WingSB3VecEnv

    kw = dict(ENV_IDS[TW], episode_time=0.5)
    sb3_env = WingSB3VecEnv(2, **kw)
    sb3_env.seed(5)
    obs_sb3 = sb3_env.reset()
    gym_env = WingVectorEnv(2, autoreset_mode="SameStep", **kw)
    obs_gym, _ = gym_env.reset(seed=5)
    np.testing.assert_array_equal(obs_sb3, obs_gym)
    a = np.full((2, 3), 0.2, np.float32)
    for _ in range(10):
        obs_sb3, r_sb3, done, infos = sb3_env.step(a)
        obs_gym, r_gym, term, trunc, info = gym_env.step(a)
        np.testing.assert_allclose(r_sb3, r_gym, rtol=1e-6)
    assert done.all() and trunc.all()
    for i in range(2):
        np.testing.assert_array_equal(infos[i]["terminal_observation"], info["final_obs"][i])
        assert infos[i]["TimeLimit.truncated"]
    np.testing.assert_array_equal(obs_sb3, obs_gym)


def test_evaluate_writes_tables_and_figure(tmp_path):
    from laddermill_gym.harness.evaluate import main

    out = tmp_path / "eval"
    assert main(["--env", TW, "--controllers", "open_loop", "lqr", "--episodes", "2", "--episode-time", "30",
                 "--direction-step", "0.05", "--out", str(out)]) == 0
    rows = list(csv.DictReader(Path(out / "summary.csv").read_text().splitlines()))
    assert [r["controller"] for r in rows] == ["open_loop", "open_loop", "lqr", "lqr"]
    lat = {r["controller"]: float(r["max_lateral_m"]) for r in rows}
    assert lat["lqr"] < 0.2 * lat["open_loop"]
    assert (out / "lateral.png").is_file() and (out / "lateral.csv").is_file()


def test_run_episodes_records_until_each_copy_ends():
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.harness.evaluate import run_episodes

    env = WingVectorEnv(2, **dict(ENV_IDS[TW], episode_time=3.0))
    res = run_episodes(make_controller("lqr", TW), env)
    assert res.lateral_m.shape == (2, 61, 1)
    np.testing.assert_allclose(res.lengths_s, 3.0, atol=1e-9)
    assert res.returns == pytest.approx(np.full(2, 60.0), rel=0.01)  # about 1 per step at trim power


def test_laddermill_ppo_config_trains_a_few_steps(tmp_path, monkeypatch):
    """configs/agents/ppo_laddermill.yaml is read strictly and trains through agents.train (an 11-wing mill with a
    short settle, a few hundred steps): the policy's action space is the config's 8 bands x 2 surfaces."""
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.rl_config import env_family, load_rl_config
    from laddermill_gym.harness.train import train

    mill = "laddermill_gym/LadderMill-v0"
    data = yaml.safe_load(Path("configs/agents/ppo_laddermill.yaml").read_text())
    data.update(n_envs=2, total_timesteps=128, checkpoint_every=64, eval={"every": 64, "episodes": 1})
    data["env_kwargs"].update(episode_time=1.0, scene_options={"n_wings": 11}, settle={"max_time": 100.0},
                              termination={"alpha_range_deg": [-180.0, 180.0], "max_abs_beta_deg": 90.0})
    data["hyperparameters"].update(n_steps=32, batch_size=32, n_epochs=1)
    p = tmp_path / "ppo_mill.yaml"
    p.write_text(yaml.safe_dump(data))
    cfg = load_rl_config(p)
    assert env_family(mill) == "mill"
    assert set(cfg.carried_env_kwargs()) >= {"groups", "n_bands", "surfaces", "scene_options", "settle"}
    monkeypatch.setitem(ENV_IDS, mill, dict(ENV_IDS[mill], episode_time=0.5))
    summary = train(cfg, tmp_path / "run")
    assert summary["steps"] >= 128
    from stable_baselines3 import PPO

    model = PPO.load(tmp_path / "run" / "model.zip")
    assert model.action_space.shape == (16,)
    # the evaluation harness builds the policy's env layout from the run's config (11 wings, bands x 2 surfaces)
    from laddermill_gym.harness.evaluate import evaluate

    res = evaluate(mill, [str(tmp_path / "run")], 1, {"episode_time": 0.5}, tmp_path / "eval", progress=False)
    assert len(res) == 1 and (tmp_path / "eval" / "summary.csv").is_file()
    with pytest.raises(ConfigError, match="env_kwargs.action_mode"):
        bad = dict(data, env_kwargs=dict(data["env_kwargs"], action_mode="tail"))
        p.write_text(yaml.safe_dump(bad))
        load_rl_config(p)


def test_pointmass_env_has_its_own_config_family():
    """A training config for PointMassChain-v0 takes the point-mass task's arguments (attitude ranges), not the
    rigid wing task's (action_mode, physics_dt), and carries its control layout to the evaluation."""
    from laddermill_gym.control.rl_config import CARRIED_KWARGS, env_family, env_kwargs_known
    from laddermill_gym.envs import env_arguments

    pm = "laddermill_gym/PointMassChain-v0"
    assert env_family(pm) == "pointmass"
    known = env_kwargs_known(pm)
    assert "pitch_range_deg" in known and "action_mode" not in known
    assert set(CARRIED_KWARGS["pointmass"]) <= set(env_arguments(pm))


def test_a_run_folder_holds_one_run_with_the_config_it_trained(tmp_path, capsys):
    """The saved config.yaml carries the command line's overrides (read back, it is the config trained), and a
    folder that holds a run already is refused before anything trains (a second run mixed its files with the
    first's, statistics included)."""
    pytest.importorskip("stable_baselines3")
    import dataclasses

    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.harness.train import main, saved_config

    cfg = dataclasses.replace(load_rl_config(_small_config(tmp_path)), seed=7, n_envs=2, time_limit_minutes=0.5)
    saved = tmp_path / "saved.yaml"
    saved.write_text(saved_config(cfg))
    back = load_rl_config(saved)
    assert (back.seed, back.n_envs, back.time_limit_minutes, back.total_timesteps) == (7, 2, 0.5, 512)
    with pytest.raises(SystemExit) as exc:  # n_envs 1 makes a rollout of 64 steps, below the minibatch of 64 x 2
        main([str(_small_config(tmp_path, hyperparameters={"n_steps": 64, "batch_size": 128})), "--n-envs", "1",
              "--out", str(tmp_path / "other")])
    err = capsys.readouterr().err
    assert exc.value.code == 2 and "--n-envs 1" in err
    assert "'hyperparameters.batch_size' = 128: must be at most 64" in err
    run = tmp_path / "run"
    run.mkdir()
    (run / "config.yaml").write_text("from an earlier run\n")
    with pytest.raises(SystemExit) as exc:
        main([str(_small_config(tmp_path)), "--out", str(run)])
    assert exc.value.code == 2 and "holds a training run already (config.yaml)" in capsys.readouterr().err


def test_run_episodes_metrics_are_the_recorded_series():
    """``laddermill evaluate``'s headline columns against a loop written here on the same env and controller (a
    review of 2026-12-07: keeping the last offset instead of the largest, or dividing the power by one step too many,
    passed every test): the largest |dy| over the episode, start included, and the mean of the per-step power."""
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.envs.observation import OBS_INDEX
    from laddermill_gym.harness.evaluate import run_episodes

    ctrl = make_controller("lqr", TW)
    res = run_episodes(ctrl, WingVectorEnv(2, **dict(ENV_IDS[TW], episode_time=40.0)))
    env = WingVectorEnv(2, **dict(ENV_IDS[TW], episode_time=40.0))
    obs, _ = env.reset(seed=[0, 1])
    dys, powers = [obs[:, OBS_INDEX["dy"]].astype(float)], []
    for _ in range(800):  # 40 s of 0.05 s periods: both copies run to the time limit
        obs, _, term, trunc, info = env.step(ctrl.predict(obs, deterministic=True)[0])
        dys.append(obs[:, OBS_INDEX["dy"]].astype(float))
        powers.append(info["power_W"])
    assert trunc.all() and not term.any()
    dys = np.array(dys)
    assert np.argmax(np.abs(dys[:, 0])) < len(dys) - 1  # the largest offset is not the last one: the max is tested
    np.testing.assert_array_equal(res.max_lateral_m[:, 0], np.abs(dys).max(axis=0))
    np.testing.assert_allclose(res.mean_power_W, np.mean(powers, axis=0), rtol=1e-12)
