"""Bad policy files are refused naming the file and what does not match (issue 31 point 6).

A policy is a small PPO built on a stand-in env with a 7-value observation (no simulation: only the spaces
matter here); its run folder says it was trained on TetheredWing-v0, as ``laddermill train`` writes it.
"""

import gymnasium as gym
import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.factory import make_controller  # noqa: E402

TW, RC = "laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"


class _Spaces(gym.Env):
    observation_space = gym.spaces.Box(-1.0, 1.0, (7,), np.float32)
    action_space = gym.spaces.Box(-1.0, 1.0, (3,), np.float32)


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory):
    from stable_baselines3 import PPO

    folder = tmp_path_factory.mktemp("run")
    PPO("MlpPolicy", _Spaces(), n_steps=8, batch_size=8, device="cpu", seed=0).save(folder / "model.zip")
    (folder / "algorithm.txt").write_text("PPO\n")
    (folder / "config.yaml").write_text(f"algorithm: PPO\nenv: {TW}\n")
    return folder


def test_a_policy_for_another_env_is_refused_naming_both(run_folder):
    with pytest.raises(ValueError, match=rf"model\.zip: trained on {TW}, not {RC}"):
        make_controller(str(run_folder), RC)


def test_a_policy_of_another_observation_size_is_refused_at_load_naming_the_file(run_folder):
    # TetheredWing-v0 observes 15 values (N_OBS_PER_WING = 15 for its one wing) and takes 3 actions
    with pytest.raises(ValueError, match=r"model\.zip: observations of shape \(7,\).*TetheredWing-v0.*\(15,\)"):
        make_controller(str(run_folder), TW)


def test_an_observation_of_another_size_is_refused_naming_the_file(run_folder):
    from laddermill_gym.control.sb3_policy import SB3Controller

    ctrl = SB3Controller.load(run_folder)
    action, _ = ctrl.predict(np.zeros(7), deterministic=True)
    assert action.shape == (3,)
    with pytest.raises(ValueError, match=r"model\.zip: expects observations of shape \(7,\).*got \(9,\)"):
        ctrl.predict(np.zeros(9))
    with pytest.raises(ValueError, match=r"got \(4, 9\)"):
        ctrl.predict(np.zeros((4, 9)))


def test_an_unknown_algorithm_and_an_unreadable_config_are_named(run_folder, tmp_path):
    import shutil

    bad = tmp_path / "bad"
    shutil.copytree(run_folder, bad)
    (bad / "algorithm.txt").write_text("NOPE\n")
    with pytest.raises(ValueError, match=r"algorithm\.txt: unknown algorithm 'NOPE'"):
        make_controller(str(bad), TW)
    (bad / "algorithm.txt").write_text("PPO\n")
    (bad / "config.yaml").write_text("env: [unclosed\n")
    with pytest.raises(ValueError, match=r"config\.yaml: not valid YAML"):
        make_controller(str(bad), TW)


def test_a_run_s_settings_are_read_as_training_read_them(run_folder, tmp_path):
    """YAML 1.2, as the package's loader: ``control_dt: 5e-2`` trains at 0.05 s, and the run's own setting was read
    back by YAML 1.1 as the text '5e-2' and refused as another control period (review of 2026-12-08). Oracle: the
    training config loader's value, and the same run refused at another period."""
    import shutil

    from laddermill_gym.control.trained_settings import check_trained_settings
    from laddermill_gym.model.configio import load_yaml_text

    run = tmp_path / "run"
    shutil.copytree(run_folder, run)
    (run / "config.yaml").write_text(f"algorithm: PPO\nenv: {TW}\nenv_kwargs:\n  control_dt: 5e-2\n")
    assert load_yaml_text((run / "config.yaml").read_text(), "x")["env_kwargs"]["control_dt"] == 0.05
    check_trained_settings(run, TW, {"control_dt": 0.05})
    with pytest.raises(ValueError, match=r"trained with control_dt = 0\.05; .* has 0\.1"):
        check_trained_settings(run, TW, {"control_dt": 0.1})


def test_a_model_without_its_algorithm_file_is_named(run_folder, tmp_path):
    from stable_baselines3 import SAC

    from laddermill_gym.control.sb3_policy import SB3Controller

    bare = tmp_path / "bare"
    bare.mkdir()
    (bare / "model.zip").write_bytes((run_folder / "model.zip").read_bytes())
    assert SB3Controller.load(bare).model.__class__.__name__ == "PPO"  # no algorithm.txt: PPO, as before
    SAC("MlpPolicy", _Spaces(), buffer_size=10, device="cpu", seed=0).save(bare / "model.zip")
    with pytest.raises(ValueError, match=r"model\.zip: does not load as PPO.*algorithm\.txt is missing"):
        SB3Controller.load(bare)
    (bare / "algorithm.txt").write_text("SAC\n")
    assert SB3Controller.load(bare).model.__class__.__name__ == "SAC"


def test_shipped_policy_names():
    from laddermill_gym.control.shipped_policies import SHIPPED_POLICIES, shipped_policy_path
    from laddermill_gym.studies.commands import UsageError, check_controllers

    with pytest.raises(ValueError, match=r"'ppo_nothing': not a shipped policy \(shipped: ppo_chain, ppo_mill, "
                                         r"ppo_mill_v3, ppo_rotorcraft"):
        shipped_policy_path("ppo_nothing")
    with pytest.raises(ValueError, match=r"'ppo_nothing': not 'open_loop'.*shipped policy \(ppo_chain, ppo_mill, "
                                         r"ppo_mill_v3, ppo_rotorcraft"):
        make_controller("ppo_nothing", TW)
    check_controllers(list(SHIPPED_POLICIES))
    with pytest.raises(UsageError, match=r"'ppo_nothing'.*a shipped policy"):
        check_controllers(["ppo_nothing"])
