"""A run folder's other model files are flown as themselves, with their own statistics and settings (issue 31
point 6; found by a review on 2026-12-06): a shared run's ``last_model.zip`` is not its exported actor, a
``laddermill train`` checkpoint gets its run's algorithm, env and observation statistics, a policy is refused on an
env whose actions mean other things, and a file that is not an SB3 model is named as such.

The oracles are SB3's own: ``VecNormalize.normalize_obs`` and ``predict`` of the model file named, loaded with
SB3 (not with the harness's loaders).
"""

import shutil
import zipfile

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.factory import make_controller  # noqa: E402
from laddermill_gym.control.shipped_policies import shipped_policy_path  # noqa: E402

TW, TW1 = "laddermill_gym/TetheredWing-v0", "laddermill_gym/TetheredWing-v1"
LC, RC = "laddermill_gym/LadderChain-v0", "laddermill_gym/Rotorcraft-v0"


@pytest.fixture(scope="module")
def wing_run(tmp_path_factory):
    """The shipped ppo_tethered_wing run folder with one checkpoint: its model with the action net's bias moved,
    so that it acts otherwise than model.zip."""
    from stable_baselines3 import PPO

    run = tmp_path_factory.mktemp("wing") / "run"
    shutil.copytree(shipped_policy_path("ppo_tethered_wing"), run)
    model = PPO.load(run / "model.zip", device="cpu")
    with __import__("torch").no_grad():
        model.policy.action_net.bias += 0.3
    (run / "checkpoints").mkdir()
    model.save(run / "checkpoints" / "step_8.zip")
    return run


def _sb3_actions(model_file, stats_file, obs):
    """SB3's own deterministic actions of raw observations: VecNormalize's statistics, then predict."""
    import pickle

    from stable_baselines3 import PPO

    with open(stats_file, "rb") as fh:
        vn = pickle.load(fh)
    return PPO.load(model_file, device="cpu").predict(vn.normalize_obs(obs).astype(np.float32), deterministic=True)[0]


def _observations(n=6):
    import gymnasium as gym

    env = gym.make(TW)
    obs = [env.reset(seed=0)[0]]
    rng = np.random.default_rng(1)
    for _ in range(n - 1):
        obs.append(env.step(rng.uniform(-0.2, 0.2, 3))[0])
    return np.array(obs, dtype=np.float64)


def test_a_checkpoint_flies_with_its_runs_env_algorithm_and_statistics(wing_run):
    ckpt = wing_run / "checkpoints" / "step_8.zip"
    obs = _observations()
    with pytest.warns(UserWarning, match=r"step_8\.zip: its observation statistics were not saved with it"):
        ctrl = make_controller(str(ckpt), TW)
    assert ctrl.trained_env == TW  # from the run's config.yaml, one folder up
    want = _sb3_actions(ckpt, wing_run / "vecnormalize.pkl", obs)
    np.testing.assert_allclose(ctrl.predict(obs, deterministic=True)[0], want, atol=1e-5)
    # statistics saved with the checkpoint (laddermill train does since 2026-12-06) are its own: no warning
    own = ckpt.with_name("step_8_vecnormalize.pkl")
    shutil.copy(wing_run / "vecnormalize.pkl", own)
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert make_controller(str(ckpt), TW).obs_mean is not None
    own.unlink()


def test_a_policy_is_refused_where_its_actions_would_mean_other_things(wing_run):
    for kw, what in (({"action_mode": "alpha"}, "action_mode = 'tail'.*has 'alpha'"),
                     ({"control_dt": 0.1}, "control_dt = 0.05.*has 0.1")):
        with pytest.raises(ValueError, match=rf"run/config\.yaml: trained with {what}"):
            make_controller(str(wing_run), TW, kw)
    assert make_controller(str(wing_run), TW1).trained_env == TW  # the same task on another physics step


def test_files_that_are_not_sb3_models_are_named(tmp_path):
    (tmp_path / "config.yaml").write_text(f"env: {TW}\n")
    not_zip = tmp_path / "notes.zip"
    not_zip.write_text("not a model\n")
    with pytest.raises(ValueError, match=r"notes\.zip: not a zip archive, so not a Stable-Baselines3 model file"):
        make_controller(str(not_zip), TW)
    other_zip = tmp_path / "other.zip"
    with zipfile.ZipFile(other_zip, "w") as z:
        z.writestr("a.txt", "hello")
    (tmp_path / "algorithm.txt").write_text("PPO\n")
    with pytest.raises(ValueError, match=r"other\.zip: does not load as PPO .*algorithm\.txt.*AssertionError"):
        make_controller(str(other_zip), TW)


def test_a_shared_runs_other_model_file_flies_itself(tmp_path):
    """A shared run's last_model.zip is not the model its linear_actor.npz was exported from: it runs through SB3
    (before, the npz ran in its place and the file named was never loaded)."""
    from stable_baselines3 import PPO

    from laddermill_gym.control.shared_controller import LinearActorController
    from laddermill_gym.control.shared_policy import SharedPolicyController

    run = tmp_path / "run"
    shutil.copytree(shipped_policy_path("ppo_chain"), run)
    model = PPO.load(run / "model.zip", device="cpu")
    with __import__("torch").no_grad():
        model.policy.action_net.weight.zero_()
        model.policy.action_net.bias.fill_(0.5)
    model.save(run / "last_model.zip")
    assert LinearActorController.available(run) and not LinearActorController.available(run / "last_model.zip")
    with pytest.raises(ValueError, match=r"last_model\.zip: .*linear_actor\.npz is the actor of .*model\.zip"):
        LinearActorController.load(run / "last_model.zip", LC)
    ctrl = make_controller(str(run / "last_model.zip"), LC)
    assert isinstance(ctrl, SharedPolicyController) and ctrl.source == run / "last_model.zip"
    import gymnasium as gym

    obs = gym.make(LC).reset(seed=0)[0]
    np.testing.assert_array_equal(ctrl.predict(obs, deterministic=True)[0], 0.5)
    assert not np.all(make_controller(str(run), LC).predict(obs, deterministic=True)[0] == 0.5)


def test_the_craft_lqr_takes_a_shipped_config_name(tmp_path):
    ctrl = make_controller("lqr:lqr_rotorcraft", RC)
    assert ctrl.predict(np.zeros(ctrl.obs_dim), deterministic=True)[0].shape == (2,)
    # a config of its own is the one designed on (a review of 2026-12-07: one that named the default passed a
    # factory that ignored the config): a tighter roll weight, another gain
    from laddermill_gym.model.configio import CONFIG_DIR

    text = (CONFIG_DIR / "agents" / "lqr_rotorcraft.yaml").read_text()
    assert "  phi_deg: 3.0 " in text and "craft: roberts_flying_model " in text
    mine = tmp_path / "lqr_tight_roll.yaml"
    mine.write_text(text.replace("  phi_deg: 3.0 ", "  phi_deg: 0.5 ", 1))
    obs = np.zeros(ctrl.obs_dim)
    obs[np.arange(ctrl.obs_dim) % 3 == 0] = 0.01  # a state off the trim, the same for both
    tight = make_controller(f"lqr:{mine}", RC)
    assert not np.allclose(tight.predict(obs, deterministic=True)[0], ctrl.predict(obs, deterministic=True)[0])
