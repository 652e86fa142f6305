"""The agents harness on ``laddermill_gym/Rotorcraft-v0``: training configs checked against RotorcraftEnv's
arguments, the looped vector env against single envs, a short Stable-Baselines3 PPO run through
``agents.train`` (a few hundred steps), the trained policy as a controller, and ``agents.evaluate`` on open
loop and LQR."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
import yaml

from laddermill_gym.envs import ENV_IDS
from laddermill_gym.envs.rotorcraft.env import RotorcraftEnv, RotorcraftVectorEnv
from laddermill_gym.model.configio import ConfigError

RC = "laddermill_gym/Rotorcraft-v0"
PPO_CONFIG = "configs/agents/ppo_rotorcraft.yaml"


def _small_config(tmp_path, env_kwargs=None, **changes):
    data = yaml.safe_load(Path(PPO_CONFIG).read_text())
    data.update(n_envs=2, total_timesteps=256, time_limit_minutes=2.0, checkpoint_every=128,
                eval={"every": 128, "episodes": 2})
    data["env_kwargs"]["episode_time"] = 2.0
    data["env_kwargs"].update(env_kwargs or {})
    data["hyperparameters"].update(n_steps=64, batch_size=64, n_epochs=2)
    data.update(changes)
    p = tmp_path / "ppo_small.yaml"
    p.write_text(yaml.safe_dump(data))
    return p


def test_rl_config_checks_the_craft_arguments(tmp_path):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.rl_config import load_rl_config

    cfg = load_rl_config(_small_config(tmp_path, env_kwargs={"wind_dt": 0.2, "control_dt": 0.1}))
    assert cfg.is_craft
    assert cfg.train_env_kwargs()["wind_dt"] == 0.2 and cfg.train_env_kwargs()["episode_time"] == 2.0
    ev = cfg.eval_env_kwargs()  # the registered scenario with the training's control period
    assert ev["control_dt"] == 0.1 and ev["episode_time"] == ENV_IDS[RC]["episode_time"] and "reward" not in ev
    for key in ("action_mode", "scene", "disturbances", "episode_tim"):  # wing arguments, sections, typos
        with pytest.raises(ConfigError, match=rf"env_kwargs\.{key}.*Rotorcraft-v0"):
            load_rl_config(_small_config(tmp_path, env_kwargs={key: 1.0}))
    wing = yaml.safe_load(Path("configs/agents/ppo_tethered_wing.yaml").read_text())
    wing["env_kwargs"]["craft"] = "roberts_flying_model"
    p = tmp_path / "wing.yaml"
    p.write_text(yaml.safe_dump(wing))
    with pytest.raises(ConfigError, match=r"env_kwargs\.craft.*TetheredWing-v0"):
        load_rl_config(p)


def test_vector_env_copies_behave_like_single_envs():
    kw = dict(ENV_IDS[RC], episode_time=0.25, initial_noise={"roll_rate": 0.05})
    venv = RotorcraftVectorEnv(2, **kw)
    obs, _ = venv.reset(seed=[3, 4])
    single = RotorcraftEnv(**kw)
    o1, _ = single.reset(seed=4)
    np.testing.assert_array_equal(obs[1], o1)
    a = np.array([[0.1, 0.2], [-0.3, 0.4]], np.float32)
    for _ in range(5):
        obs, r, term, trunc, info = venv.step(a)
        o1, r1, t1, tr1, i1 = single.step(a[1])
        np.testing.assert_array_equal(obs[1], o1)
        assert r[1] == r1 and info["power_W"][1] == i1["power_W"] and info["t"][1] == i1["t"]
    assert trunc.all() and not term.any() and venv.task.n_steps_max == 5
    np.testing.assert_array_equal(venv.lateral_offsets(obs)[:, 0], obs[:, 1])
    obs, r, term, trunc, info = venv.step(a)  # NextStep autoreset: fresh starts, reward 0
    assert not (term | trunc).any() and np.all(r == 0.0) and np.all(info["t"] == 0.0)
    with pytest.raises(ValueError, match="scene"):
        RotorcraftVectorEnv(1, scene="tethered_wing")


def test_ppo_smoke_run_and_policy_as_controller(tmp_path, monkeypatch):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.harness.train import train

    cfg = load_rl_config(_small_config(tmp_path))
    # evaluation episodes of 120 s would dominate a smoke test: shorten the registered scenario here
    monkeypatch.setitem(ENV_IDS, RC, dict(ENV_IDS[RC], episode_time=1.0))
    out = tmp_path / "run"
    summary = train(cfg, out)
    assert summary["steps"] >= 256
    for name in ("model.zip", "best_model.zip", "vecnormalize.pkl", "best_vecnormalize.pkl", "evaluations.csv",
                 "training_curve.png", "config.yaml", "references.csv"):
        assert (out / name).is_file(), name
    # the references ran the same 1 s evaluation episodes: 20 steps of about 1 at the trim power
    assert summary["references"]["lqr"] == pytest.approx(20.0, rel=0.02)
    assert summary["references"]["open_loop"] == pytest.approx(20.0, rel=0.02)
    assert np.isfinite(summary["best_eval_return"])
    ctrl = make_controller(str(out), RC)
    assert isinstance(ctrl, SB3Controller) and ctrl.obs_mean.shape == (19,)
    env = RotorcraftEnv(**dict(ENV_IDS[RC], episode_time=0.5))
    obs, _ = env.reset(seed=0)
    a, _ = ctrl.predict(obs, deterministic=True)
    assert a.shape == (2,) and np.all(np.abs(a) <= 1.0)
    obs, r, term, trunc, _ = env.step(a)
    assert np.isfinite(r) and not term
    a, _ = ctrl.predict(np.stack([obs, obs, obs]), deterministic=True)
    assert a.shape == (3, 2)


def test_evaluate_open_loop_and_lqr_on_the_craft(tmp_path):
    from laddermill_gym.harness.evaluate import main

    out = tmp_path / "eval"
    assert main(["--env", RC, "--controllers", "open_loop", "lqr", "--episodes", "2", "--episode-time", "5",
                 "--scenario", "step_0.1", "--out", str(out)]) == 0
    rows = list(csv.DictReader(Path(out / "summary.csv").read_text().splitlines()))
    assert [r["controller"] for r in rows] == ["open_loop", "open_loop", "lqr", "lqr"]
    assert all(float(r["length_s"]) == pytest.approx(5.0) and r["failure"] == "" for r in rows)
    assert all(float(r["return"]) == pytest.approx(100.0, rel=0.05) for r in rows)  # about 1 per step
    assert (out / "lateral.png").is_file() and (out / "lateral.csv").is_file()


def test_evaluate_names_an_argument_the_env_does_not_take():
    from laddermill_gym.harness.evaluate import check_env_kwargs

    with pytest.raises(ValueError, match="groups = 'per_wing'.*Rotorcraft-v0"):
        check_env_kwargs(RC, {"groups": "per_wing"})
    with pytest.raises(ValueError, match="craft = .roberts_flying_model.*TetheredWing-v0"):
        check_env_kwargs("laddermill_gym/TetheredWing-v0", {"craft": "roberts_flying_model"})
    check_env_kwargs(RC, {"episode_time": 5.0, "disturbances": []})
