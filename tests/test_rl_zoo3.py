"""rl-zoo3 on our environments: short training runs through ``python -m rl_zoo3.train`` with the shipped
hyperparameter files (configs/rl_zoo3/), then the harness reading the run folders (``laddermill evaluate``,
:class:`~laddermill_gym.control.sb3_policy.SB3Controller`).

Oracles: rl-zoo3's own loading path (``rl_zoo3.utils.get_saved_hyperparams``, ``create_test_env`` with the run's
statistics, ``rl_zoo3.utils.ALGOS[algo].load``), which must give the harness's actions on the same raw observations
and, rolled out, the harness's episode return; our own training configs (configs/agents/), whose numbers the
shipped files claim to carry; for the recipe's environment arguments (issue 34 item 13: evaluation ran on the
registered defaults, not the file's env_kwargs), rl-zoo3's own command-line parser (``StoreDict``), the shell's word
splitting, and the environments rl-zoo3's ExperimentManager builds for training and for evaluation. Skipped when
rl_zoo3 is not installed (the ``zoo`` extra).
"""

from __future__ import annotations

import csv
import shutil
import subprocess
import sys

import gymnasium as gym
import numpy as np
import pytest
import yaml

pytest.importorskip("rl_zoo3", reason="rl_zoo3 is not installed (the zoo extra: pip install rl_zoo3)")

from laddermill_gym.control.sb3_policy import SB3Controller  # noqa: E402
from laddermill_gym.control.zoo_run import (  # noqa: E402
    env_kwargs_arguments,
    find_zoo_run,
    read_zoo_run,
    read_zoo_yaml,
    zoo_env_kwargs,
)
from laddermill_gym.harness import evaluate as ev  # noqa: E402
from laddermill_gym.model.configio import CONFIG_DIR  # noqa: E402

ENV_ID = "laddermill_gym/TetheredWing-v0"
NAME = "laddermill_gym-TetheredWing-v0"
#: our training config behind each (file, env id) entry of the shipped rl-zoo3 files
SOURCES = {("ppo", ENV_ID): "ppo_tethered_wing", ("ppo", "laddermill_gym/Rotorcraft-v0"): "ppo_rotorcraft",
           ("ppo", "laddermill_gym/LadderMill-v0"): "ppo_laddermill", ("sac", ENV_ID): "sac_tethered_wing"}
#: rl-zoo3 keys that are not SB3 constructor arguments
ZOO_KEYS = ("n_envs", "n_timesteps", "policy", "normalize", "env_kwargs")
CONSTANTS = {"learning_rate": 0.0, "lr_schedule": lambda _: 0.0, "clip_range": lambda _: 0.0}


def zoo_train(tmp_path_factory, algo: str, *extra: str):
    """Train ``algo`` briefly with rl-zoo3 in a subprocess; the run folder."""
    logs = tmp_path_factory.mktemp(f"zoo_{algo}")
    # the recipe (docs/rl_zoo3.md): the file's env_kwargs also on the command line, so evaluation uses them too
    cmd = [sys.executable, "-m", "rl_zoo3.train", "--algo", algo, "--env", ENV_ID, "--gym-packages", "laddermill_gym",
           "--conf-file", str(CONFIG_DIR / "rl_zoo3" / f"{algo}.yaml"), "--num-threads", "1", "--seed", "0",
           "-f", str(logs), "--env-kwargs", *env_kwargs_arguments(zoo_env_kwargs(algo, ENV_ID)), *extra]
    done = subprocess.run(cmd, cwd=logs, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return logs / algo / f"{NAME}_1"


@pytest.fixture(scope="module")
def ppo_run(tmp_path_factory):
    # one rollout (16 copies x 256 steps) and one evaluation at its end: best_model.zip and the last model
    return zoo_train(tmp_path_factory, "ppo", "-n", "4096", "--eval-freq", "4096", "--eval-episodes", "1")


@pytest.fixture(scope="module")
def sac_run(tmp_path_factory):
    return zoo_train(tmp_path_factory, "sac", "-n", "200", "--eval-freq", "-1", "-params", "learning_starts:100",
                     "buffer_size:1000")


def zoo_oracle(run, algo: str):
    """rl-zoo3's own evaluation objects for ``run``: its VecNormalize test env (registered arguments) and model."""
    from rl_zoo3.utils import ALGOS, create_test_env, get_saved_hyperparams

    hyperparams, stats = get_saved_hyperparams(str(run / NAME))
    env = create_test_env(ENV_ID, n_envs=1, stats_path=stats, seed=0, should_render=False,
                          hyperparams=hyperparams, env_kwargs={})
    return env, ALGOS[algo].load(run / f"{NAME}.zip", env=env, custom_objects=CONSTANTS)


@pytest.mark.parametrize("algo", ["ppo", "sac"])
def test_shipped_files_carry_our_training_configs(algo):
    """Every entry's numbers are those of our configs/agents file (where there is one), and every other key is an
    argument of the SB3 algorithm, so rl-zoo3 cannot fail on a typo after a long set-up."""
    import inspect

    import stable_baselines3 as sb3

    zoo = yaml.safe_load((CONFIG_DIR / "rl_zoo3" / f"{algo}.yaml").read_text())
    accepted = set(inspect.signature(getattr(sb3, algo.upper())).parameters)
    for env_id, hp in zoo.items():
        assert set(hp) - set(ZOO_KEYS) <= accepted, (env_id, set(hp) - set(ZOO_KEYS) - accepted)
        assert hp["normalize"] == {"norm_obs": True, "norm_reward": False}
        if (algo, env_id) not in SOURCES:
            continue
        ours = yaml.safe_load((CONFIG_DIR / "agents" / f"{SOURCES[algo, env_id]}.yaml").read_text())
        assert ours["env"] == env_id and ours["algorithm"] == algo.upper()
        assert hp["n_envs"] == ours["n_envs"] and ours["normalize_observations"] is True
        assert hp["policy_kwargs"] == ours["policy_kwargs"]
        for key, value in ours["hyperparameters"].items():
            assert hp[key] == value, (env_id, key)
        assert hp["env_kwargs"] == dict(ours["env_kwargs"], disturbances=ours["disturbances"])


@pytest.mark.parametrize("algo", ["ppo", "sac"])
def test_recipe_arguments_are_the_files_env_kwargs(algo):
    """What the recipe passes as ``--env-kwargs`` is, through rl-zoo3's own parser, each entry's env_kwargs; and the
    printed line survives the shell's word splitting (``$(python -m laddermill_gym.control.zoo_run FILE ID)``)."""
    import argparse

    from rl_zoo3.utils import StoreDict

    parser = argparse.ArgumentParser()
    parser.add_argument("--env-kwargs", type=str, nargs="+", action=StoreDict)
    zoo = yaml.safe_load((CONFIG_DIR / "rl_zoo3" / f"{algo}.yaml").read_text())
    for env_id, hp in zoo.items():
        args = env_kwargs_arguments(zoo_env_kwargs(algo, env_id))
        assert parser.parse_args(["--env-kwargs", *args]).env_kwargs == hp["env_kwargs"], env_id
    cmd = f'printf "%s\\n" $("{sys.executable}" -m laddermill_gym.control.zoo_run {algo} {ENV_ID})'
    done = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == env_kwargs_arguments(zoo_env_kwargs(algo, ENV_ID))


def _zoo_envs(tmp_path, env_kwargs):
    """(training env, evaluation env) tasks as rl-zoo3's ExperimentManager builds them from our PPO file, with
    ``env_kwargs`` as the command line's --env-kwargs (None: not given)."""
    import argparse

    from rl_zoo3.exp_manager import ExperimentManager
    from stable_baselines3.common.callbacks import EvalCallback

    em = ExperimentManager(argparse.Namespace(), "ppo", ENV_ID, str(tmp_path), eval_freq=1000, n_eval_episodes=1,
                           hyperparams={"n_envs": 1, "batch_size": 256}, env_kwargs=env_kwargs,
                           config=str(CONFIG_DIR / "rl_zoo3" / "ppo.yaml"), verbose=0)
    model, _ = em.setup_experiment()
    (evaluation,) = [c for c in em.callbacks if isinstance(c, EvalCallback)]
    tasks = [env.get_attr("unwrapped")[0].task for env in (model.get_env(), evaluation.eval_env)]
    for env in (model.get_env(), evaluation.eval_env):
        env.close()
    return tasks


def settings(task):
    return task.episode_time, task.disturbances, task.reward_config


def test_evaluation_uses_the_training_settings_with_the_recipe(tmp_path):
    """rl-zoo3 2.9 evaluates on the registered defaults unless the command line gives the env_kwargs (the issue:
    episodes longer than the file's 60 s); with the recipe's --env-kwargs both envs have the file's settings."""
    file_kwargs = zoo_env_kwargs("ppo", ENV_ID)
    train, evaluation = _zoo_envs(tmp_path / "recipe", dict(file_kwargs))
    assert settings(train) == settings(evaluation) and train.episode_time == file_kwargs["episode_time"] == 60.0
    assert len(train.disturbances) == len(file_kwargs["disturbances"]) == 4  # configs/agents/ppo_tethered_wing.yaml
    train, evaluation = _zoo_envs(tmp_path / "file_only", None)
    default = gym.make(ENV_ID).unwrapped.task
    assert settings(train) != settings(evaluation) and train.episode_time == 60.0
    assert settings(evaluation) == settings(default) and default.episode_time == 300.0


def test_run_folder_records_the_recipes_settings(ppo_run):
    """args.yml (what enjoy, record_video and ``laddermill evaluate`` read first) and config.yml hold the file's
    env_kwargs."""
    from laddermill_gym.control.zoo_run import read_zoo_yaml

    want = zoo_env_kwargs("ppo", ENV_ID)
    assert read_zoo_yaml(ppo_run / NAME / "args.yml")["env_kwargs"] == want
    assert read_zoo_yaml(ppo_run / NAME / "config.yml")["env_kwargs"] == want
    assert read_zoo_run(ppo_run).env_kwargs == want


@pytest.mark.parametrize("algo", ["ppo", "sac"])
def test_harness_acts_as_rl_zoo3_does(algo, request):
    """The harness loads the run's algorithm (the issue: SAC loaded as PPO) and its statistics (the issue:
    silently dropped): same actions as rl-zoo3's model behind rl-zoo3's VecNormalize, along 40 steps: the same bits
    through torch (``exact=False``, as rl-zoo3 acts), and to float32 rounding from the default float64 path of a
    linear actor (control/exact_actor.py)."""
    run = request.getfixturevalue(f"{algo}_run")
    ctrl = SB3Controller.load(run, exact=False)
    exact = SB3Controller.load(run)
    env, model = zoo_oracle(run, algo)
    assert type(ctrl.model) is type(model) and type(model).__name__ == algo.upper()
    obs = env.reset()
    for _ in range(40):
        want, _ = model.predict(obs, deterministic=True)
        raw = env.get_original_obs()
        got, _ = ctrl.predict(raw, deterministic=True)
        np.testing.assert_array_equal(got, want)
        np.testing.assert_allclose(exact.predict(raw, deterministic=True)[0], want, rtol=1e-5, atol=1e-7)
        obs, *_ = env.step(want)
    bare, _ = SB3Controller(ctrl.model).predict(raw, deterministic=True)
    assert np.abs(bare - got).max() > 1e-3  # the statistics matter: dropping them changes the actions


def test_evaluate_command_on_an_rl_zoo3_folder(ppo_run, tmp_path):
    """``laddermill evaluate`` on the run folder: the episode return equals rl-zoo3's rollout of the same
    registered episode (seed 0, 2 s)."""
    out = tmp_path / "eval"
    assert ev.main(["--env", ENV_ID, "--controllers", str(ppo_run), "--episodes", "1", "--episode-time", "2",
                    "--out", str(out)]) == 0
    rows = list(csv.DictReader(open(out / "summary.csv")))
    assert [r["controller"] for r in rows] == [ppo_run.name]
    from rl_zoo3.utils import ALGOS, create_test_env, get_saved_hyperparams

    hyperparams, stats = get_saved_hyperparams(str(ppo_run / NAME))
    env = create_test_env(ENV_ID, n_envs=1, stats_path=stats, seed=0, should_render=False, hyperparams=hyperparams,
                          env_kwargs={"episode_time": 2.0})
    model = ALGOS["ppo"].load(ppo_run / f"{NAME}.zip", env=env, custom_objects=CONSTANTS)
    obs, total, done = env.reset(), 0.0, False
    while not done:
        action, _ = model.predict(obs, deterministic=True)
        obs, reward, dones, _ = env.step(action)
        total, done = total + float(reward[0]), bool(dones[0])
    assert float(rows[0]["return"]) == pytest.approx(total, rel=1e-5)


def _copy(run, tmp_path):
    dst = tmp_path / "logs" / "ppo" / run.name
    shutil.copytree(run, dst)
    return dst


def _rewrite(path, **changes):
    from laddermill_gym.control.zoo_run import read_zoo_yaml

    data = dict(read_zoo_yaml(path), **changes)
    path.write_text(yaml.safe_dump(data))


def test_refusals_name_what_is_missing(ppo_run, tmp_path):
    run = _copy(ppo_run, tmp_path)
    assert find_zoo_run(run / "best_model.zip") == (run, run / NAME)
    assert read_zoo_run(run).model_file == run / f"{NAME}.zip"  # the last model: its statistics are on disk
    with pytest.raises(ValueError, match="best_model.zip.*statistics are lost"):
        SB3Controller.load(run / "best_model.zip")
    with pytest.raises(ValueError, match=r"an rl-zoo3 run on 'laddermill_gym/TetheredWing-v0', evaluated on "
                                         r"'laddermill_gym/Rotorcraft-v0'"):
        ev.policy_env_kwargs(str(run), "laddermill_gym/Rotorcraft-v0")
    _rewrite(run / NAME / "config.yml", frame_stack=4)
    with pytest.raises(ValueError, match="config.yml: frame_stack = 4"):
        SB3Controller.load(run)
    _rewrite(run / NAME / "config.yml", frame_stack=None)
    _rewrite(run / NAME / "args.yml", algo="ppo_lstm")
    with pytest.raises(ValueError, match="args.yml: algo = 'ppo_lstm'.*recurrent"):
        SB3Controller.load(run)
    _rewrite(run / NAME / "args.yml", algo="ppo")
    (run / NAME / "vecnormalize.pkl").unlink()
    with pytest.raises(FileNotFoundError, match="vecnormalize.pkl: missing.*normalised"):
        SB3Controller.load(run)
    (run / NAME / "args.yml").unlink()
    with pytest.raises(FileNotFoundError, match="args.yml: missing"):
        SB3Controller.load(run)


def test_unnormalised_run_loads_without_statistics(ppo_run, tmp_path):
    """A run without normalisation (config.yml normalize false, no vecnormalize.pkl): the policy sees the raw
    observations, and best_model.zip is then accepted."""
    run = _copy(ppo_run, tmp_path)
    _rewrite(run / NAME / "config.yml", normalize="dict(norm_obs=False, norm_reward=True)")
    (run / NAME / "vecnormalize.pkl").unlink()
    ctrl = SB3Controller.load(run / "best_model.zip", exact=False)
    assert ctrl.obs_mean is None
    obs = np.linspace(-1.0, 1.0, 15)
    want, _ = ctrl.model.predict(obs.astype(np.float32), deterministic=True)
    np.testing.assert_array_equal(ctrl.predict(obs, deterministic=True)[0], want)
    exact = SB3Controller.load(run / "best_model.zip")  # the linear actor in float64 (control/exact_actor.py)
    assert exact.obs_mean is None
    np.testing.assert_allclose(exact.predict(obs, deterministic=True)[0], want, rtol=1e-5, atol=1e-7)


def test_wrapper_fills_in_our_defaults(monkeypatch):
    """``laddermill zoo``: our hyperparameter file and one torch thread unless given; the user's own kept."""
    from laddermill_gym.harness.zoo import script_arguments

    monkeypatch.delenv("LADDERMILL_TORCH_THREADS", raising=False)
    conf = str(CONFIG_DIR / "rl_zoo3" / "sac.yaml")
    assert script_arguments("train", ["--algo", "sac"]) == ["--algo", "sac", "--conf-file", conf, "--num-threads", "1"]
    assert script_arguments("train", ["--algo", "sac", "-conf", "my.yml", "--num-threads", "2"]) == \
        ["--algo", "sac", "-conf", "my.yml", "--num-threads", "2"]
    monkeypatch.setenv("LADDERMILL_TORCH_THREADS", "3")
    assert script_arguments("enjoy", ["--algo", "tqc"]) == ["--algo", "tqc", "--num-threads", "3"]
    assert script_arguments("record_video", ["-n", "5"]) == ["-n", "5"]


@pytest.mark.slow  # moviepy: the video extra, not installed by CI (README, slow tests)
def test_record_video_through_the_wrapper(ppo_run):
    """``rl_zoo3.record_video`` has no --gym-packages: through ``laddermill zoo`` it finds our id and writes the
    video of the run's policy (n steps after the reset: n + 1 frames, or n where moviepy drops the last)."""
    pytest.importorskip("moviepy", reason="moviepy is not installed (the video extra)")
    import imageio_ffmpeg

    n = 5
    cmd = [sys.executable, "-m", "laddermill_gym.harness.zoo", "record_video", "--algo", "ppo", "--env", ENV_ID,
           "-f", str(ppo_run.parent.parent), "-n", str(n), "--deterministic", "-o", str(ppo_run / "videos")]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    (video,) = (ppo_run / "videos").glob("*.mp4")
    assert imageio_ffmpeg.count_frames_and_secs(str(video))[0] in (n, n + 1)


def test_run_files_read_yaml_1_2_floats(tmp_path):
    """A hand-edited ``config.yml`` with ``3e-4`` (PyYAML's own loader reads it as text) gives a float, and the
    OrderedDict tag rl-zoo3 writes is still read; any other Python tag is refused."""
    path = tmp_path / "config.yml"
    path.write_text("!!python/object/apply:collections.OrderedDict\n- - - learning_rate\n    - 3e-4\n  - - n_envs\n"
                    "    - 4\n")
    data = read_zoo_yaml(path)
    assert data == {"learning_rate": 3e-4, "n_envs": 4} and isinstance(data["n_envs"], int)
    path.write_text("!!python/object/apply:os.system ['true']\n")
    with pytest.raises(ValueError, match="not readable as an rl-zoo3 file"):
        read_zoo_yaml(path)
