"""Policy files that do not belong together are refused when loaded, naming the file (found by a review):
observation statistics of another env or not statistics at all (``laddermill train`` run folders, rl-zoo3 run folders
and ``harness/reselect.py``'s candidates), an ``algorithm.txt`` naming no algorithm class, a ``shared_policy.yaml``
whose ``obs_dim`` was edited; and the shipped policies are all named where the docs list them.

Oracles: the files' own contents read with pickle and SB3 (the statistics' shape, the model's observation space),
rl-zoo3's documented algorithm names (``rl_zoo3.utils.ALGOS``), and the package's registry of shipped policies.
"""

import importlib.util
import pickle
import shutil

import numpy as np
import pytest

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.factory import make_controller  # noqa: E402
from laddermill_gym.control.shipped_policies import SHIPPED_POLICIES, shipped_policy_path  # noqa: E402

TW, RC = "laddermill_gym/TetheredWing-v0", "laddermill_gym/Rotorcraft-v0"
ZOO_NAME = "laddermill_gym-TetheredWing-v0"  # rl-zoo3's <env name>: the id with "/" replaced by "-"


def _stats_shape(path):
    with open(path, "rb") as fh:
        return tuple(pickle.load(fh).obs_rms.mean.shape)


def _model_obs_shape(path):
    from stable_baselines3 import PPO

    return tuple(PPO.load(path, device="cpu").observation_space.shape)


def _wing_run(tmp_path, stats_from: str | None = "ppo_rotorcraft"):
    """The shipped wing policy's run folder with the statistics of ``stats_from`` (None: its own)."""
    run = tmp_path / "wing"
    shutil.copytree(shipped_policy_path("ppo_tethered_wing"), run)
    if stats_from is not None:
        shutil.copy(shipped_policy_path(stats_from) / "vecnormalize.pkl", run / "vecnormalize.pkl")
    return run


def _zoo_run(tmp_path, stats: bytes):
    """An rl-zoo3 run folder as rl-zoo3 2.x lays it out (zoo_run.py's docstring) holding the shipped wing policy,
    with ``stats`` as its vecnormalize.pkl."""
    run = tmp_path / "logs" / "ppo" / f"{ZOO_NAME}_1"
    (run / ZOO_NAME).mkdir(parents=True)
    shutil.copy(shipped_policy_path("ppo_tethered_wing") / "model.zip", run / f"{ZOO_NAME}.zip")
    (run / ZOO_NAME / "args.yml").write_text(f"algo: ppo\nenv: {TW}\n")
    (run / ZOO_NAME / "config.yml").write_text("normalize: true\n")
    (run / ZOO_NAME / "vecnormalize.pkl").write_bytes(stats)
    return run


def test_statistics_of_another_env_are_refused_at_load_naming_file_and_shapes(tmp_path):
    own = make_controller(str(shipped_policy_path("ppo_tethered_wing")), TW)  # its own statistics: taken
    run = _wing_run(tmp_path)
    assert own.obs_mean.shape == _model_obs_shape(run / "model.zip")
    theirs, mine = _stats_shape(run / "vecnormalize.pkl"), _model_obs_shape(run / "model.zip")
    assert theirs != mine
    with pytest.raises(ValueError) as err:
        make_controller(str(run), TW)
    text = str(err.value)
    assert text.startswith(f"{run / 'vecnormalize.pkl'}: ")
    assert str(theirs) in text and str(mine) in text
    zoo = _zoo_run(tmp_path, (shipped_policy_path("ppo_rotorcraft") / "vecnormalize.pkl").read_bytes())
    with pytest.raises(ValueError, match=rf"{ZOO_NAME}/vecnormalize\.pkl: .*{theirs}.*{mine}".replace("(", r"\(")
                       .replace(")", r"\)")):
        make_controller(str(zoo), TW)


def test_statistics_that_are_not_a_vecnormalize_are_named(tmp_path):
    run = _wing_run(tmp_path, None)
    (run / "vecnormalize.pkl").write_text("mean: [0, 0, 0]\nvar: [1, 1, 1]\n")
    with pytest.raises(ValueError, match=rf"{run / 'vecnormalize.pkl'}: not readable as pickled observation"):
        make_controller(str(run), TW)
    (run / "vecnormalize.pkl").write_bytes(pickle.dumps({"mean": np.zeros(15)}))
    with pytest.raises(ValueError, match=r"vecnormalize\.pkl: holds a builtins\.dict, not SB3's VecNormalize"):
        make_controller(str(run), TW)
    zoo = _zoo_run(tmp_path, b"12 not a pickle\n")
    with pytest.raises(ValueError, match=rf"{ZOO_NAME}/vecnormalize\.pkl: not readable as pickled"):
        make_controller(str(zoo), TW)


def test_reselect_refuses_a_policy_of_another_env_and_foreign_statistics(tmp_path):
    """reselect loads its candidates as make_controller does: before, the rotorcraft's policy loaded and failed
    in the flight, and foreign statistics on the first step, each on a bare numpy or env error."""
    from laddermill_gym.harness.reselect import reselect

    config = "configs/agents/ppo_tethered_wing_severe.yaml"
    craft = tmp_path / "craft"
    shutil.copytree(shipped_policy_path("ppo_rotorcraft"), craft)
    with pytest.raises(ValueError, match=rf"craft/model\.zip: trained on {RC}, not {TW}"):
        reselect(config, [craft], log=lambda _s: None)
    run = _wing_run(tmp_path)
    with pytest.raises(ValueError, match=r"wing/vecnormalize\.pkl: observation statistics of shape"):
        reselect(config, [run], log=lambda _s: None)
    shutil.copy(shipped_policy_path("ppo_tethered_wing") / "vecnormalize.pkl", run / "vecnormalize.pkl")
    text = (run / "config.yaml").read_text().replace("env_kwargs:\n", "env_kwargs:\n  action_mode: alpha\n", 1)
    (run / "config.yaml").write_text(text)
    with pytest.raises(ValueError, match=r"wing/config\.yaml: trained with action_mode = 'alpha'.* has 'tail'"):
        reselect(config, [run], log=lambda _s: None)


#: rl-zoo3's algorithm names and classes (rl_zoo3/utils.py, ALGOS, rl-zoo3 2.x), without its recurrent ppo_lstm
ZOO_ALGOS = {"a2c": "A2C", "ddpg": "DDPG", "dqn": "DQN", "ppo": "PPO", "sac": "SAC", "td3": "TD3", "ars": "ARS",
             "crossq": "CrossQ", "qrdqn": "QRDQN", "tqc": "TQC", "trpo": "TRPO"}


def test_algorithm_txt_takes_class_names_and_rl_zoo3_names(tmp_path):
    from laddermill_gym.control.sb3_policy import SB3Controller, algorithm_class

    run = _wing_run(tmp_path, None)
    (run / "algorithm.txt").write_text("ppo\n")  # before: "module 'stable_baselines3.ppo' has no attribute 'load'"
    assert type(SB3Controller.load(run).model).__name__ == "PPO"
    contrib = importlib.util.find_spec("sb3_contrib") is not None
    for zoo, name in ZOO_ALGOS.items():
        module = "sb3_contrib" if name in ("ARS", "CrossQ", "QRDQN", "TQC", "TRPO") else "stable_baselines3"
        if module == "sb3_contrib" and not contrib:
            continue
        cls = algorithm_class(zoo, run / "algorithm.txt")
        assert (cls.__name__, cls.__module__.split(".")[0]) == (name, module)
    for bad, why in (("HerReplayBuffer", "unknown algorithm 'HerReplayBuffer'"),  # a class, but no algorithm
                     ("common", "unknown algorithm 'common'"),  # a module of stable_baselines3
                     ("recurrentppo", "unknown algorithm 'recurrentppo'"),  # not an rl-zoo3 name
                     ("ppo_lstm", "'ppo_lstm' .*is recurrent")):
        (run / "algorithm.txt").write_text(bad + "\n")
        with pytest.raises(ValueError, match=rf"wing/algorithm\.txt: .*{why}") as err:
            SB3Controller.load(run)
        if bad != "ppo_lstm":
            assert "PPO" in str(err.value) and "ppo" in str(err.value)  # the known names


def test_an_edited_obs_dim_is_named_against_the_models(tmp_path):
    """shared_policy.yaml's obs_dim against the model's own input size (before: the model's size against the
    env's, two equal numbers)."""
    from laddermill_gym.control.shared_policy import SharedPolicyController

    run = tmp_path / "chain"
    shutil.copytree(shipped_policy_path("ppo_chain"), run)
    (run / "linear_actor.npz").unlink()  # the SB3 model runs
    model_dim = _model_obs_shape(run / "model.zip")[0]
    meta = (run / "shared_policy.yaml").read_text()
    assert f"obs_dim: {model_dim}" in meta
    (run / "shared_policy.yaml").write_text(meta.replace(f"obs_dim: {model_dim}", f"obs_dim: {model_dim + 7}"))
    with pytest.raises(ValueError, match=rf"takes local observations of {model_dim} entries, but its "
                                         rf"shared_policy\.yaml says obs_dim = {model_dim + 7}"):
        SharedPolicyController.load(run, SHIPPED_POLICIES["ppo_chain"])


def test_every_shipped_policy_is_listed_where_the_docs_list_them():
    from pathlib import Path

    import laddermill_gym.control.factory as factory

    page = Path("laddermill_gym/docs/controllers.md").read_text()
    section = page.split("## Shipped policies", 1)[1].strip().split("\n\n", 1)[0]
    words = {4: "Four", 5: "Five", 6: "Six", 7: "Seven"}
    assert section.lstrip().startswith(f"{words[len(SHIPPED_POLICIES)]} trained policies")
    for name in SHIPPED_POLICIES:
        assert f"`{name}`" in section or f'"{name}"' in section, name
        assert f"``{name}``" in factory.__doc__, name
