"""harness/reselect.py (a run's saved policies flown again on a config's validation sets) and
harness/paired_survival.py (two controllers on the same drawn episodes)."""

import shutil
from pathlib import Path

import pytest
import yaml

from laddermill_gym.harness.reselect import candidates, reselect

SHIPPED = "laddermill_gym/policies/ppo_tethered_wing"
CONFIG = "configs/agents/ppo_tethered_wing_severe.yaml"


def _run_folder(tmp_path, steps):
    run = tmp_path / "run"
    (run / "checkpoints").mkdir(parents=True)
    for s in steps:
        shutil.copyfile(f"{SHIPPED}/model.zip", run / "checkpoints" / f"step_{s}.zip")
    shutil.copyfile(f"{SHIPPED}/vecnormalize.pkl", run / "vecnormalize.pkl")
    (run / "algorithm.txt").write_text("PPO\n")
    return run


def test_candidates_in_step_order_and_errors(tmp_path):
    run = _run_folder(tmp_path, [1000000, 500000, 250000])
    labels = [label for label, _m, _s in candidates(run)]
    assert labels == ["run/step_250000", "run/step_500000", "run/step_1000000"]  # numeric, not by name
    with pytest.raises(FileNotFoundError, match="no checkpoints"):
        candidates(tmp_path / "empty")
    (run / "vecnormalize.pkl").unlink()
    with pytest.raises(FileNotFoundError, match=r"vecnormalize\.pkl: missing"):
        candidates(run)


def test_reselect_matches_the_shipped_loader(tmp_path):
    """A checkpoint flown by reselect survives what the package's own loader (SB3Controller.load of the shipped
    folder) and validate() give, episode set by episode set; the reference is never the selected row."""
    from laddermill_gym.control.rl_config import load_rl_config
    from laddermill_gym.control.sb3_policy import SB3Controller
    from laddermill_gym.harness.validation import validate

    raw = yaml.safe_load(Path(CONFIG).read_text())
    raw["validation"]["episode_time"] = 3.0
    raw["validation"]["sets"] = {"ntm_ib": dict(raw["validation"]["sets"]["ntm_ib"], episodes=2),
                                 "gusts": dict(raw["validation"]["sets"]["gusts"], episodes=2)}
    cfg_file = tmp_path / "small.yaml"
    cfg_file.write_text(yaml.safe_dump(raw))
    run = _run_folder(tmp_path, [16])
    rows = reselect(cfg_file, [run], reference=["open_loop"], out=tmp_path / "rows.csv", log=lambda _s: None)
    cfg = load_rl_config(cfg_file)
    expected = validate(SB3Controller.load(SHIPPED, best=False), cfg.env_id, cfg.carried_env_kwargs(),
                        cfg.validation)
    ckpt = [r for r in rows if r["label"] == "run/step_16"][0]
    assert (ckpt["survived"], ckpt["per_set"]) == (expected["survived"], expected["per_set"])
    assert ckpt["rms_lateral_m"] == pytest.approx(expected["rms_lateral_m"], abs=1e-3)
    assert [r["selected"] for r in rows if r["reference"]] == [0]
    assert sum(r["selected"] for r in rows) == 1
    assert (tmp_path / "rows.csv").read_text().splitlines()[0].startswith("label,survived,episodes")


@pytest.mark.parametrize("first,second", [(43, 25), (0, 0), (5, 0), (3, 9), (12, 12)])
def test_sign_test_matches_scipy(first, second):
    """harness/paired_survival.sign_test against scipy's exact binomial test (an independent implementation)."""
    from scipy.stats import binomtest

    from laddermill_gym.harness.paired_survival import sign_test

    expected = 1.0 if first + second == 0 else binomtest(first, first + second, 0.5).pvalue
    assert sign_test(first, second) == pytest.approx(expected, rel=1e-12)
