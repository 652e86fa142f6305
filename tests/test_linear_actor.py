"""The torch-free evaluator of a shared per-wing policy (control/shared_controller.py): its features against the
loop-by-loop oracle, its actions against the SB3 model it was exported from (torch, an independent implementation),
the shipped ppo_mill's export current, no torch imported on its path, and stale or broken files refused by name."""

from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

from laddermill_gym.control.shared_controller import (
    LINEAR_ACTOR_FILE,
    LinearActor,
    LinearActorController,
    file_digest,
)
from laddermill_gym.control.shipped_policies import POLICY_DIR
from laddermill_gym.envs.observation import OBS_INDEX
from tests.env_cases import LM1, case_kwargs
from tests.shared_actor_oracle import oracle_features

MILL = POLICY_DIR / "ppo_mill"


def local_observations(n: int, k: int, block: int, rows: int, seed: int) -> np.ndarray:
    """Random local observations (rows, d) float32 with consistent positions and presence flags (agent i mod n)."""
    rng = np.random.default_rng(seed)
    d = block * (2 * k + 1) + 2 * k + 1 + 3
    obs = rng.normal(scale=0.3, size=(rows, d))
    for r in range(rows):
        i = r % n
        obs[r, block * (2 * k + 1): block * (2 * k + 1) + 2 * k] = [
            float(0 <= i + o < n) for o in [o for o in range(-k, k + 1) if o != 0]]
        obs[r, block * (2 * k + 1) + 2 * k] = i / (n - 1)
    return obs.astype(np.float32)


def small_actor(n=7, k=2, block=15, nb=4, seed=3) -> LinearActor:
    rng = np.random.default_rng(seed)
    n_lat = 6 * (2 * k + 1) + 1
    trim = rng.uniform(-0.2, 0.2, (n, 2))
    trim[3, 1] = 3.1  # yaw near pi: the wrap matters
    from laddermill_gym.control.shared_controller import lateral_columns

    arrays = dict(weight=rng.normal(size=(3, nb * n_lat)), bias=rng.normal(size=3), trim=trim,
                  scales=np.array([1.0, 1.0, 0.17, 0.17, 0.35, 0.35]),
                  offsets=np.array([0] + [d for d in range(-k, k + 1) if d != 0]),
                  cols=np.array(lateral_columns(k, block)), n_agents=n, k=k, block=block, n_basis=nb,
                  model_sha256="")
    return LinearActor(arrays, MILL / "test")


def test_features_and_actions_match_the_loop_oracle():
    actor = small_actor()
    obs = local_observations(actor.n, actor.k, actor.block, 21, seed=5)
    obs[3, OBS_INDEX["psi"]] = -3.1  # across the wrap from slot 3's trim
    want = np.array([oracle_features(o, actor.n, actor.k, actor.block, actor.n_basis, actor.trim.astype(float),
                                     actor.scales.astype(float)) for o in obs])
    np.testing.assert_allclose(actor.features(obs), want, rtol=1e-5, atol=1e-5)
    np.testing.assert_allclose(actor.mean(obs), want @ actor.weight.T.astype(float) + actor.bias, rtol=1e-4,
                               atol=1e-4)


def test_the_shipped_export_is_of_the_shipped_model():
    with np.load(MILL / LINEAR_ACTOR_FILE) as f:
        assert str(f["model_sha256"]) == file_digest(MILL / "model.zip")
    actor = LinearActor.load(MILL / LINEAR_ACTOR_FILE, MILL / "model.zip")
    assert (actor.n, actor.k, actor.n_basis) == (101, 4, 101)


def test_the_shipped_actor_gives_the_sb3_models_actions():
    pytest.importorskip("stable_baselines3")
    from stable_baselines3 import PPO

    actor = LinearActor.load(MILL / LINEAR_ACTOR_FILE, MILL / "model.zip")
    model = PPO.load(MILL / "model.zip", device="cpu")
    obs = local_observations(actor.n, actor.k, actor.block, 303, seed=11)
    obs[:, :-12] *= 0.1  # lateral deviations of a few cm and tenths of a degree: actions mostly inside [-1, 1]
    want, _ = model.predict(obs, deterministic=True)
    got = np.clip(actor.mean(obs), -1.0, 1.0)
    assert np.mean(np.abs(want) < 0.99) > 0.5 and np.abs(want).max() > 0.05  # the observations excite the actor
    # float32 both: sums of 5555 products in another order, and torch's float32 linspace puts some nodes an ulp
    # off i / 100, so its hat functions leak ~1e-5 of a neighbour slot's gains (numpy's nodes are i / 100 rounded)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-4)
    assert np.median(np.abs(got - want)) < 1e-6


def test_the_controller_flies_as_the_sb3_controller(tmp_path):
    pytest.importorskip("stable_baselines3")
    from laddermill_gym.control.shared_policy import SharedPolicyController, export_linear_actor
    from tests.test_shared_policy import small_policy

    venv, _ = small_policy(tmp_path, k=2)
    export_linear_actor(tmp_path / "model.zip")
    kw = {key: val for key, val in case_kwargs(LM1).items() if key != "disturbances"}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the small mill's fallback start
        sb3 = SharedPolicyController.load(tmp_path, LM1, kw)
        mine = LinearActorController.load(tmp_path, LM1, kw)
    venv.reset()
    for _ in range(3):
        obs = venv.task.obs.astype(np.float32)
        a, _ = mine.predict(obs)
        np.testing.assert_allclose(a, sb3.predict(obs)[0], rtol=0, atol=2e-6)
        venv.step(a.reshape(-1, 3))
    with pytest.raises(ValueError, match=r"linear_actor\.npz: trained on laddermill_gym/LadderMill-v1, not .*v0"):
        LinearActorController.load(tmp_path, "laddermill_gym/LadderMill-v0", kw)
    (tmp_path / "model.zip").write_bytes(b"another model")
    with pytest.raises(ValueError, match=r"linear_actor\.npz: exported from another model than .*model\.zip"):
        LinearActorController.load(tmp_path, LM1, kw)


def test_broken_files_are_named(tmp_path):
    np.savez(tmp_path / LINEAR_ACTOR_FILE, weight=np.zeros((3, 4)))
    with pytest.raises(ValueError, match=r"linear_actor\.npz: missing bias, trim"):
        LinearActor.load(tmp_path / LINEAR_ACTOR_FILE)
    actor = small_actor()
    arrays = {key: getattr(actor, key) for key in ("weight", "bias", "trim", "scales", "offsets", "cols")}
    arrays.update(n_agents=actor.n, k=actor.k, block=actor.block, n_basis=actor.n_basis + 1, model_sha256="")
    with pytest.raises(ValueError, match=r"test: weight \(3, 124\).* n_basis 5"):
        LinearActor(arrays, MILL / "test")
    (tmp_path / LINEAR_ACTOR_FILE).unlink()
    (tmp_path / "shared_policy.yaml").write_text("env: x\nk: 1\nn_agents: 3\nobs_dim: 4\nalgorithm: PPO\n")
    with pytest.raises(FileNotFoundError, match=r"linear_actor\.npz: no such file"):
        LinearActorController.load(tmp_path / "model.zip")


def test_the_numpy_path_imports_no_torch():
    code = ("import sys, numpy as np; from laddermill_gym.control.shared_controller import LinearActor; "
            f"a = LinearActor.load(__import__('pathlib').Path({str(MILL / LINEAR_ACTOR_FILE)!r})); "
            "a.mean(np.zeros((2, 147), np.float32)); assert 'torch' not in sys.modules, 'torch imported'")
    subprocess.run([sys.executable, "-c", code], check=True)
