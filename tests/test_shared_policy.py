"""The shared per-wing policy of the mill (issue 31 point 2): the actor's features against a plain-numpy oracle
written here (slot arithmetic, hat functions by their formula), the controller's mapping of the single-agent
observation against the shared-policy VecEnv's own agents (bit for bit), bad input named, the training config
checked, and a short training smoke (slow)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

pytest.importorskip("stable_baselines3", reason="the rl extra (SB3) is not installed")
import torch as th  # noqa: E402

from laddermill_gym.control.shared_policy import (  # noqa: E402
    GainScheduledExtractor,
    SharedPolicyController,
    hat_basis,
)
from laddermill_gym.envs.observation import OBS_INDEX  # noqa: E402
from tests.env_cases import LM1, case_kwargs  # noqa: E402
from tests.shared_actor_oracle import oracle_features  # noqa: E402


def test_hat_basis_interpolates_linearly_between_nodes():
    p = th.tensor([0.0, 0.25, 0.3, 1.0], dtype=th.float64)
    h = hat_basis(p, 5).numpy()  # nodes 0, 0.25, 0.5, 0.75, 1
    np.testing.assert_allclose(h.sum(axis=1), 1.0)
    np.testing.assert_allclose(h[0], [1, 0, 0, 0, 0])
    np.testing.assert_allclose(h[1], [0, 1, 0, 0, 0])
    np.testing.assert_allclose(h[2], [0, 0.8, 0.2, 0, 0], atol=1e-12)  # (0.5 - 0.3) / 0.25 on node 0.25
    np.testing.assert_allclose(hat_basis(p, 1).numpy(), 1.0)


def test_features_match_the_numpy_oracle():
    import gymnasium as gym

    n, k, block, nb = 7, 2, 15, 4
    d = block * (2 * k + 1) + 2 * k + 1 + 3
    rng = np.random.default_rng(3)
    trim = rng.uniform(-0.2, 0.2, (n, 2))
    trim[3, 1] = 3.1  # yaw near pi: the wrap matters
    scales = np.array([1.0, 1.0, 0.17, 0.17, 0.35, 0.35])
    ext = GainScheduledExtractor(gym.spaces.Box(-np.inf, np.inf, (d,)), n, k, block, nb, trim, scales)
    obs = rng.normal(size=(n, d))
    for i in range(n):  # agent i: its position and the true presence flags
        obs[i, block * 5: block * 5 + 4] = [float(0 <= i + o < n) for o in (-2, -1, 1, 2)]
        obs[i, block * 5 + 4] = i / (n - 1)
    obs[3, OBS_INDEX["psi"]] = -3.1  # 0.083 rad from trim across the wrap
    got = ext(th.as_tensor(obs, dtype=th.float64).float()).double().numpy()
    want = np.array([oracle_features(o, n, k, block, nb, trim, scales) for o in obs.astype(np.float32)])
    np.testing.assert_allclose(got, want, rtol=1e-5, atol=1e-5)
    assert ext.features_dim == nb * (6 * (2 * k + 1) + 1)


def test_gain_locality_blocks_and_band():
    from laddermill_gym.harness.gain_locality import banded, block_norms

    n = 4
    K = np.zeros((2 * n, 6 * n))
    K[2:4, 0:6] = 3.0  # slot 1's commands from slot 0's states: norm sqrt(12) * 3
    K[0:2, 18:24] = 1.0  # slot 0 from slot 3: distance 3
    W = block_norms(K)
    assert W[1, 0] == pytest.approx(np.sqrt(12) * 3) and W[0, 3] == pytest.approx(np.sqrt(12))
    assert np.count_nonzero(W) == 2
    np.testing.assert_array_equal(banded(K, 2)[0:2, 18:24], 0.0)
    np.testing.assert_array_equal(banded(K, 2)[2:4, 0:6], 3.0)
    np.testing.assert_array_equal(banded(K, 3), K)


def small_policy(tmp_path, k=1, extractor_k=None):
    """A shared-policy run folder on the 11-wing v1 mill: PPO with the gain-scheduled actor, random weights
    (``extractor_k``: the actor's own k, default ``k``, the env's and shared_policy.yaml's)."""
    from stable_baselines3 import PPO

    from laddermill_gym.multiagent import shared_policy_vec_env

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        venv = shared_policy_vec_env(LM1, 2, k=k, seed=4, **case_kwargs(LM1))
    v = venv.view
    pk = dict(features_extractor_class=GainScheduledExtractor,
              features_extractor_kwargs=dict(n_agents=v.n_agents, k=k if extractor_k is None else extractor_k,
                                             block=v.block, n_basis=3,
                                             trim=np.zeros((v.n_agents, 2)).tolist(), scales=[1.0] * 6),
              net_arch=dict(pi=[], vf=[8]), log_std_init=-3.0)
    model = PPO("MlpPolicy", venv, n_steps=8, batch_size=44, policy_kwargs=pk, seed=0, device="cpu")
    with th.no_grad():
        model.policy.action_net.weight.normal_(0.0, 0.3)
    model.save(tmp_path / "model.zip")
    import yaml

    meta = dict(env=LM1, k=k, n_agents=v.n_agents, obs_dim=v.obs_dim, algorithm="PPO")
    (tmp_path / "shared_policy.yaml").write_text(yaml.safe_dump(meta))
    return venv, model


def test_controller_maps_the_single_agent_observation_as_the_agents_see_it(tmp_path):
    venv, model = small_policy(tmp_path)
    obs = venv.reset()
    kw = {key: val for key, val in case_kwargs(LM1).items() if key != "disturbances"}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        ctrl = SharedPolicyController.load(tmp_path, LM1, kw)
    for _ in range(3):  # the controller on the task's observations = the policy on the VecEnv's agents
        joint, _ = ctrl.predict(venv.task.obs.astype(np.float32))
        np.testing.assert_array_equal(ctrl.view.local_observations(venv.task.obs).reshape(obs.shape), obs)
        a, _ = model.predict(obs, deterministic=True)
        np.testing.assert_array_equal(joint, np.clip(a, -1, 1).reshape(joint.shape))
        obs = venv.step(a)[0]
    single, _ = ctrl.predict(venv.task.obs[0])
    assert single.shape == (venv.view.n_agents * 3,)


def test_bad_policy_input_is_named(tmp_path):
    small_policy(tmp_path)
    kw = {key: val for key, val in case_kwargs(LM1).items() if key != "disturbances"}
    with pytest.raises(ValueError, match=r"model\.zip: trained on laddermill_gym/LadderMill-v1, not .*v0"):
        SharedPolicyController.load(tmp_path, "laddermill_gym/LadderMill-v0", kw)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        with pytest.raises(ValueError, match=r"model\.zip: trained with 11 agents .* the env has 9"):
            SharedPolicyController.load(tmp_path, LM1, dict(kw, scene_options={"n_wings": 9}))
        ctrl = SharedPolicyController.load(tmp_path, LM1, kw)
    with pytest.raises(ValueError, match=r"model\.zip: expects observations of"):
        ctrl.predict(np.zeros(12))
    (tmp_path / "shared_policy.yaml").write_text("env: x\n")
    with pytest.raises(ValueError, match=r"shared_policy\.yaml: missing k"):
        SharedPolicyController.load(tmp_path)


def test_training_config_is_checked(tmp_path):
    from laddermill_gym.harness.shared_config import is_shared_config, load_shared_config
    from laddermill_gym.model.configio import CONFIG_DIR, ConfigError

    cfg = load_shared_config("ppo_mill_v1")
    assert cfg.env_id == LM1 and cfg.k >= 0 and cfg.time_limit_minutes <= 120
    assert is_shared_config("ppo_mill_v1") and not is_shared_config("ppo_tethered_wing")
    text = (CONFIG_DIR / "agents" / "ppo_mill_v1.yaml").read_text()
    for old, new, needle in (("k: 4", "k: -1", "k"), ("n_copies: 4", "n_copies: 0", "n_copies"),
                             ("gamma: 0.99 ", "gama: 0.99 ", "gama"),
                             ("time_limit_minutes: 110.0", "time_limit_minutes: 300.0", "time_limit_minutes"),
                             ("episode_time: 60.0      # [s] training", "episode_tme: 60.0      # [s] training",
                              "episode_tme"),
                             # values laddermill train's configs check, each a traceback once the mill was built
                             ("learning_rate: 3.0e-5", "learning_rate: -1.0", "'ppo.hyperparameters.learning_rate'"),
                             ("episode_time: 60.0 ", "episode_time: -5.0 ", "'env_kwargs.episode_time' = -5.0"),
                             ("  - type: ", "  - type: Bogus\n    was: ", r"'disturbances\[0\]'")):
        bad = tmp_path / "bad.yaml"
        assert old in text
        bad.write_text(text.replace(old, new, 1))
        with pytest.raises(ConfigError, match=needle) as err:
            load_shared_config(bad)
        assert "bad.yaml" in str(err.value)


@pytest.mark.slow
def test_training_smoke_writes_a_policy_that_evaluate_loads(tmp_path):
    """Both phases for a few steps on LadderMill-v1 (the full mill: the LQR teacher needs its design)."""
    from laddermill_gym.control.factory import make_controller
    from laddermill_gym.harness.shared_train import main
    from laddermill_gym.model.configio import CONFIG_DIR

    src = (CONFIG_DIR / "agents" / "ppo_mill_v1.yaml").read_text()
    for old, new in (("iterations: 4 ", "iterations: 2 "), ("steps: 400 ", "steps: 10 "),
                     ("total_timesteps: 20000000", "total_timesteps: 3000"), ("every: 1000000 ", "every: 2000 "),
                     ("episode_time: 300.0     # [s] rounds", "episode_time: 2.0     # [s] rounds")):
        assert old in src
        src = src.replace(old, new)
    cfg = tmp_path / "smoke.yaml"
    cfg.write_text(src)
    assert main([str(cfg), "--out", str(tmp_path / "run")]) == 0
    for f in ("model.zip", "bc_model.zip", "training_curve.csv", "training_curve.png", "shared_policy.yaml",
              "run.yaml"):
        assert (tmp_path / "run" / f).is_file()
    import yaml

    record = yaml.safe_load((tmp_path / "run" / "run.yaml").read_text())  # how the run was made
    assert record["seed"] == yaml.safe_load(src)["seed"] and "laddermill_gym" in record["versions"]
    from laddermill_gym.control.shared_controller import LinearActorController

    ctrl = make_controller(str(tmp_path / "run"), LM1)
    # the run exports its linear actor, which the factory flies without torch (else the SB3 policy)
    assert isinstance(ctrl, LinearActorController if LinearActorController.available(tmp_path / "run")
                      else SharedPolicyController)


def test_teacher_labels_are_the_lqr_law_before_its_clip():
    """The DAgger labels clipped to [-1, 1] are the mill LQR controller's own actions (its predict)."""
    from laddermill_gym.control.mill_lqr import MillLQRController
    from laddermill_gym.harness.shared_train import teacher_labels
    from laddermill_gym.multiagent.agents import build_task

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        task = build_task(LM1, 2, {k: v for k, v in case_kwargs(LM1).items() if k != "disturbances"})
    n = task.n_wings
    rng = np.random.default_rng(1)
    ctrl = MillLQRController(rng.normal(0, 2.0, (2 * n, 6 * n)), np.zeros((n, 2)), task.actions)
    task.reset(np.ones(2, bool), [np.random.default_rng(s) for s in (0, 1)])
    obs = task.obs + rng.normal(0, 0.3, task.obs.shape)  # deviations large enough to saturate some entries
    labels = teacher_labels(ctrl, obs)
    assert np.abs(labels).max() > 1.0
    np.testing.assert_array_equal(np.clip(labels, -1, 1).astype(np.float32), ctrl.predict(obs)[0])


def test_lqr_band_projected_on_per_slot_gains_is_that_band():
    """harness.shared_fit: with one hat function per slot the actor's head reproduces the LQR's law cut to +-k
    slots (the mill LQR controller's own arithmetic, on a random gain, before its clip) exactly; with one node the
    least-squares fit is the slots' mean weight."""
    import gymnasium as gym

    from laddermill_gym.control.mill_lqr import MillLQRController
    from laddermill_gym.harness.gain_locality import banded
    from laddermill_gym.harness.shared_fit import band_weights, project_weights
    from laddermill_gym.harness.shared_train import teacher_labels
    from laddermill_gym.multiagent.agents import WingAgents, build_task

    k = 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        task = build_task(LM1, 2, {key: v for key, v in case_kwargs(LM1).items() if key != "disturbances"})
    n = task.n_wings
    rng = np.random.default_rng(5)
    K = rng.normal(0, 2.0, (2 * n, 6 * n))
    lqr = MillLQRController(banded(K, k), np.zeros((n, 2)), task.actions)
    scales = np.array([1.0, 0.5, 0.17, 0.17, 0.35, 0.35])
    task.reset(np.ones(2, bool), [np.random.default_rng(s) for s in (0, 1)])
    obs = task.obs + rng.normal(0, 0.05, task.obs.shape)
    want = teacher_labels(lqr, obs).reshape(2 * n, -1)
    view = WingAgents(task, LM1, k)
    local = view.local_observations(obs).reshape(2 * n, -1)
    w = band_weights(K, lqr.half, scales, k)  # the band cut happens inside: neighbours beyond k are not seen
    head, err = project_weights(w, n, lqr.column, view.act_dim)
    ext = GainScheduledExtractor(gym.spaces.Box(-np.inf, np.inf, (view.obs_dim,)), n, k, view.block, n,
                                 np.zeros((n, 2)), scales)
    got = ext(th.as_tensor(local, dtype=th.float32)).double().numpy() @ head.T
    assert err < 1e-12
    np.testing.assert_allclose(got, want, rtol=2e-4, atol=2e-4 * np.abs(want).max())
    head1, err1 = project_weights(w, 1, lqr.column, view.act_dim)
    f = w.shape[1]
    np.testing.assert_allclose(head1[lqr.column[0], :f], w[:, :, 0].mean(axis=0), rtol=1e-12, atol=1e-12)
    assert err1 > 0.1


def test_a_policy_of_other_surfaces_is_refused_by_name(tmp_path):
    """The actor's commands per agent against the env's (a policy of three surfaces on a mill of two loaded and
    failed in numpy's reshape; the review of 2026-12-07)."""
    small_policy(tmp_path)
    kw = {key: val for key, val in case_kwargs(LM1).items() if key != "disturbances"}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        with pytest.raises(ValueError, match=r"model\.zip: commands 3 surfaces per agent, the env's agents take 2"):
            SharedPolicyController.load(tmp_path, LM1, dict(kw, surfaces=["rudder", "aileron"]))


def test_a_run_records_and_the_check_compares_every_carried_setting(tmp_path):
    """What a shared run writes into shared_policy.yaml is what the settings check compares (surfaces, settle and
    authority were dropped or not compared: a policy flew at five times its authority unrefused)."""
    import shutil

    import yaml

    from laddermill_gym.control.rl_config import carried_settings
    from laddermill_gym.control.shipped_policies import shipped_policy_path
    from laddermill_gym.control.trained_settings import check_trained_settings

    kw = {"surfaces": ["rudder", "aileron"], "settle": {"max_time": 100.0}, "authority": 0.5, "episode_time": 60.0,
          "initial_noise": {"roll_rate": 0.02}}
    assert carried_settings(LM1, kw) == {k: kw[k] for k in ("surfaces", "settle", "authority")}
    run = tmp_path / "ppo_mill"
    shutil.copytree(shipped_policy_path("ppo_mill"), run)
    check_trained_settings(run, LM1, {})  # as trained: LadderMill-v1's registered authority 0.2
    with pytest.raises(ValueError, match=r"shared_policy\.yaml: trained with authority = 0\.2; .* has 1\.0"):
        check_trained_settings(run, LM1, {"authority": 1.0})
    meta = yaml.safe_load((run / "shared_policy.yaml").read_text())
    meta["env_kwargs"] = carried_settings(LM1, kw)
    (run / "shared_policy.yaml").write_text(yaml.safe_dump(meta))
    check_trained_settings(run, LM1, kw)  # its own settings pass
    with pytest.raises(ValueError, match=r"trained with surfaces = \['rudder', 'aileron'\]"):
        check_trained_settings(run, LM1, {k: v for k, v in kw.items() if k != "surfaces"})


def test_a_chain_run_records_its_scene_and_the_check_compares_it(tmp_path):
    """The wing family's carried settings lacked ``scene``: a LadderChain-v0 policy trained on another chain file
    of the same wing count recorded no scene and was evaluated on the registered one without a word (review of
    2026-12-08); the mill and point-mass families carried it. Oracle: the mill's refusal of the same case."""
    import shutil

    import yaml

    from laddermill_gym.control.rl_config import carried_settings
    from laddermill_gym.control.shipped_policies import shipped_policy_path
    from laddermill_gym.control.trained_settings import check_trained_settings

    chain = "laddermill_gym/LadderChain-v0"
    kw = {"scene": "my_chain.yaml", "control_dt": 0.05, "episode_time": 30.0}
    assert carried_settings(chain, kw) == carried_settings(LM1, kw) == {"scene": "my_chain.yaml", "control_dt": 0.05}
    run = tmp_path / "ppo_chain"
    shutil.copytree(shipped_policy_path("ppo_chain"), run)
    meta = yaml.safe_load((run / "shared_policy.yaml").read_text())
    meta["env_kwargs"] = dict(meta.get("env_kwargs") or {}, scene="my_chain.yaml")
    (run / "shared_policy.yaml").write_text(yaml.safe_dump(meta))
    with pytest.raises(ValueError, match=r"trained with scene = 'my_chain\.yaml'; .* has 'ladder_chain'"):
        check_trained_settings(run, chain, {})


def test_a_shared_config_for_the_point_mass_chain_is_refused_by_name(tmp_path):
    from laddermill_gym.harness.shared_config import load_shared_config
    from laddermill_gym.model.configio import CONFIG_DIR, ConfigError

    text = (CONFIG_DIR / "agents" / "ppo_chain_v0.yaml").read_text()
    bad = tmp_path / "pmc.yaml"
    bad.write_text(text.replace("env: laddermill_gym/LadderChain-v0", "env: laddermill_gym/PointMassChain-v0", 1))
    assert bad.read_text() != text
    with pytest.raises(ConfigError, match=r"pmc\.yaml.*'env'.*PointMassChain-v0"):
        load_shared_config(bad)


def test_a_model_for_other_slots_or_another_k_is_refused_by_name(tmp_path):
    """The torch path against the model's own actor: the shipped ppo_chain (an extractor of 101 slots) in a folder
    whose shared_policy.yaml says 5 agents loaded for a 5-wing chain and flew slots 0, 25, .. 100's trim and gains
    without a word (the review's t12; the linear actor refused it); an extractor of k = 1 under a yaml of k = 2."""
    import shutil

    import yaml

    from laddermill_gym.control.shipped_policies import shipped_policy_path

    chain, five = "laddermill_gym/LadderChain-v0", {"scene_options": {"n_wings": 5}}
    run = tmp_path / "ppo_chain"
    shutil.copytree(shipped_policy_path("ppo_chain"), run)
    assert SharedPolicyController.load(run, chain).view.n_agents == 101  # as shipped: loads
    meta = yaml.safe_load((run / "shared_policy.yaml").read_text())
    (run / "shared_policy.yaml").write_text(yaml.safe_dump(dict(meta, n_agents=5, env_kwargs=five)))
    with pytest.raises(ValueError, match=r"ppo_chain/model\.zip: its GainScheduledExtractor has n_agents = 101 "
                                         r"slots, the env has 5 agents"):
        SharedPolicyController.load(run, chain, five)
    small_policy(tmp_path, k=2, extractor_k=1)
    kw = {key: val for key, val in case_kwargs(LM1).items() if key != "disturbances"}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        with pytest.raises(ValueError, match=r"model\.zip: its GainScheduledExtractor has k = 1, its "
                                             r"shared_policy\.yaml says k = 2"):
            SharedPolicyController.load(tmp_path, LM1, kw)
