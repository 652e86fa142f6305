"""Training's validations and checkpoints (harness/train.py, harness/validation.py), reselect's ranking
(harness/reselect.py) and a validation set's own seeds (control/rl_phases.py).

Oracles: SB3's callback protocol driven by hand (``num_timesteps`` advancing by ``n_envs`` per call, as SB3 calls it),
with the validation's episodes replaced by a record of which policy was on disk when it flew: every validated step is
a checkpoint saved before its validation, at the steps the training validated before (``n_envs`` + k ``every``: the
shipped policies' selection does not move); two checkpoints whose RMS rounds alike, ranked as the training's own
``score`` ranks them; the seeds each set flies, counted by hand; the warnings raised.
"""

from __future__ import annotations

import warnings
from pathlib import Path
from types import SimpleNamespace as NS

import pytest
import yaml

pytest.importorskip("stable_baselines3")

import laddermill_gym  # noqa: E402, F401  (registers the ids)
from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.rl_phases import Selection, Validation, ValidationSet  # noqa: E402
from laddermill_gym.harness import validation as V  # noqa: E402

SEVERE = "configs/agents/ppo_tethered_wing_severe.yaml"
SAC = "configs/agents/sac_tethered_wing_residual.yaml"


class _Bar:
    n = 0

    def update(self, k):
        self.n += k

    def set_postfix(self, **k):
        pass

    def write(self, s):
        pass


def test_every_validated_policy_is_the_checkpoint_of_its_step(tmp_path, monkeypatch):
    from laddermill_gym.control import sb3_policy
    from laddermill_gym.harness.train import make_callback

    raw = yaml.safe_load(Path(SAC).read_text())
    n_envs, every, ckpt = raw["n_envs"], raw["validation"]["every"], raw["checkpoint_every"]
    val = Validation(every=every, seed=1000, episode_time=60.0, sets=(ValidationSet("a", 1, [{}]),))
    cfg = NS(n_envs=n_envs, checkpoint_every=ckpt, eval_every=10 ** 12, time_limit_minutes=1e9, critic_warmup=None,
             validation=val, env_id="laddermill_gym/TetheredWing-v0", carried_env_kwargs=lambda: {},
             file=Path(SAC))
    on_disk, validated, version = {}, [], [0]

    class Model:
        def save(self, path):
            on_disk[Path(path).name] = version[0]

        def get_env(self):
            return None

    def fly(ctrl, env_id, kw, validation):
        validated.append((h.num_timesteps, on_disk.get(f"step_{h.num_timesteps}.zip"), version[0]))
        return dict(survived=1, episodes=1, rms_lateral_m=0.5, per_set={"a": 1}, outcomes={"a": (1,)})

    monkeypatch.setattr(V, "validate", fly)
    monkeypatch.setattr(sb3_policy, "SB3Controller", lambda *a, **k: None)
    (tmp_path / "checkpoints").mkdir()
    h = make_callback(cfg, tmp_path, None, _Bar())
    h.model = Model()
    h.evaluate = lambda: None
    for k in range(1, 150001 // n_envs + 1):  # SB3 calls the callback after every env step of n_envs transitions
        h.num_timesteps = k * n_envs
        version[0] = k  # the policy changes between calls (SAC trains every step)
        h._on_step()
    assert (n_envs, every, ckpt) == (8, 50000, 50000)
    assert [s for s, _, _ in validated] == [8, 50008, 100008]  # as trained before: the first call, then every 50000
    assert all(saved == now for _, saved, now in validated)  # the file of its step is the policy validated
    assert {f"step_{i * ckpt}.zip" for i in range(1, 150000 // ckpt + 1)} <= set(on_disk)  # the grid still saved


def test_reselect_ranks_on_the_unrounded_rms_as_the_training(monkeypatch):
    """Two checkpoints with the same survivals, RMS 0.61049 and 0.61001 m (both 0.610 rounded): the later one is
    better by score(), as the training keeps it; reselect selects it too."""
    import laddermill_gym.harness.reselect as R

    res = {"run/step_50000": dict(survived=60, episodes=96, rms_lateral_m=0.61049, per_set={}, outcomes={}),
           "run/step_100000": dict(survived=60, episodes=96, rms_lateral_m=0.61001, per_set={}, outcomes={})}
    monkeypatch.setattr(R, "candidates", lambda run, name=None: [(k, Path(k + ".zip"), Path("s.pkl")) for k in res])
    monkeypatch.setattr(R, "load_candidate", lambda m, s, e, kw: m.stem)
    monkeypatch.setattr(V, "validate", lambda ctrl, env, kw, val: res["run/" + ctrl])
    with pytest.warns(UserWarning, match="ntm_ib and ntm_ia"):
        rows = R.reselect(SEVERE, ["run"], log=lambda s: None)
    assert [r["label"] for r in rows if r["selected"]] == ["run/step_100000"]
    assert V.score(res["run/step_100000"]) > V.score(res["run/step_50000"])
    assert {r["rms_lateral_m"] for r in rows} == {0.61}  # the table still shows it rounded


def test_a_set_flies_its_own_seeds(monkeypatch):
    from laddermill_gym.studies.gusts import gust_bench

    flown = {}

    def run(ctrl, env_id, kw, seeds, t, dist):
        flown[dist[0]["model"]] = list(seeds)
        n = len(seeds)
        return {"failure": [0] * n, "lateral_sq": [0.0] * n, "steps": [1] * n}

    monkeypatch.setattr(gust_bench, "run_episodes", run)
    sets = (ValidationSet("ib", 3, [{"type": "Turbulence", "model": "NTM"}]),
            ValidationSet("light", 2, [{"type": "Turbulence", "model": "Dryden"}], seed=7000))
    V.validate(None, "laddermill_gym/TetheredWing-v0", {}, Validation(1, 1000, 60.0, sets, Selection()))
    assert flown == {"NTM": [1000, 1001, 1002], "Dryden": [7000, 7001]}


def test_sets_of_one_turbulence_model_on_shared_seeds_are_warned_of(tmp_path):
    """ppo_tethered_wing_severe's NTM IB and NTM IA sets share seeds 1000-1047 (the same fields, scaled): warned of
    with the file and the sets; a seed of its own for NTM IA parts them; the shipped configs read no set seed."""
    cfg = load_rl_config(SEVERE)
    assert V.shared_fields(cfg.validation) == [("ntm_ib", "ntm_ia", "NTM")]
    with pytest.warns(UserWarning, match=rf"{SEVERE}: validation sets ntm_ib and ntm_ia \(NTM\) draw"):
        V.warn_shared_fields(cfg)
    raw = yaml.safe_load(Path(SEVERE).read_text())
    raw["validation"]["sets"]["ntm_ia"]["seed"] = 1096  # after ntm_ib's 96 episodes
    path = tmp_path / "parted.yaml"
    path.write_text(yaml.safe_dump(raw))
    parted = load_rl_config(path)
    ia = next(s for s in parted.validation.sets if s.name == "ntm_ia")
    assert V.set_seeds(parted.validation, ia) == list(range(1096, 1144))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        V.warn_shared_fields(parted)
    for config in Path("configs/agents").glob("*.yaml"):
        data = yaml.safe_load(config.read_text())
        if isinstance(data, dict) and "validation" in data:
            assert all(s.seed is None for s in load_rl_config(config).validation.sets), config
