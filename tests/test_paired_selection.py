"""The paired selection rule (``validation.selection``: control/rl_phases.py, harness/validation.py,
harness/reselect.py) against hand-built per-episode tables whose scores are worked out by hand below, in the
training loop's order (TrainingPhases.validate) and in reselect's; the default rule keeps the original choice; bad
selection sections are named (file, field, value)."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
import yaml

pytest.importorskip("stable_baselines3")

from laddermill_gym.control.rl_config import load_rl_config  # noqa: E402
from laddermill_gym.control.rl_phases import Selection, Validation, ValidationSet  # noqa: E402
from laddermill_gym.harness import validation as hv  # noqa: E402
from laddermill_gym.model.configio import ConfigError  # noqa: E402

CONFIG = "configs/agents/ppo_tethered_wing_residual_paired.yaml"
PAIRED = Selection("paired", 2.0, "lqr")


def _result(a, b, rms):
    """A validate() result from per-episode outcomes (1 survived) of two sets of 5 and 3 episodes."""
    return dict(survived=sum(a) + sum(b), episodes=8, rms_lateral_m=rms, per_set=dict(a=sum(a), b=sum(b)),
                outcomes=dict(a=tuple(a), b=tuple(b)))


# The table. Reference (the LQR): a 1 1 0 0 1, b 1 0 1: 5 survived.
REF = _result((1, 1, 0, 0, 1), (1, 0, 1), 3.0)
# START: the reference's outcomes (an untrained residual is the LQR): 5 survived, 0 lost -> paired 5 - 2 x 0 = 5.
START = _result((1, 1, 0, 0, 1), (1, 0, 1), 3.0)
# GAIN: a 0 1 1 1 1, b 0 1 1: 6 survived; loses a[0] and b[0], which the reference holds: 2 lost ->
# paired 6 - 2 x 2 = 2; with penalty 0.4: 6 - 0.8 = 5.2.
GAIN = _result((0, 1, 1, 1, 1), (0, 1, 1), 2.0)
# CALM: a 1 1 0 1 0, b 1 0 1: 5 survived; loses a[4]: 1 lost -> paired 5 - 2 = 3; with penalty 0.4: 4.6.
CALM = _result((1, 1, 0, 1, 0), (1, 0, 1), 1.0)
# TWIN: START's outcomes with a smaller RMS: paired 5 as START, wins the tie on RMS.
TWIN = _result((1, 1, 0, 0, 1), (1, 0, 1), 2.5)


def test_lost_to_reference_and_scores_by_hand():
    assert [hv.lost_to_reference(r, REF) for r in (START, GAIN, CALM, TWIN)] == [0, 2, 1, 0]
    start, gain, calm, twin = (dict(r, lost_to_reference=hv.lost_to_reference(r, REF))
                               for r in (START, GAIN, CALM, TWIN))
    assert [hv.score(r, PAIRED)[0] for r in (start, gain, calm, twin)] == [5, 2, 3, 5]
    assert hv.score(gain, Selection("paired", 0.4, "lqr"))[0] == pytest.approx(5.2)
    assert hv.score(twin, PAIRED) > hv.score(start, PAIRED)  # tie on the count: the smaller RMS
    assert hv.score(GAIN) == (6, -2.0) and hv.score(GAIN, Selection()) == (6, -2.0)  # the original order
    with pytest.raises(ValueError, match="unpaired"):
        hv.lost_to_reference(START, _result((1, 1, 0, 0), (1, 0, 1), 3.0))


class _Bar:
    def __init__(self):
        self.lines = []

    def write(self, s):
        self.lines.append(s)


def _phases(tmp_path, monkeypatch, selection, sequence):
    """TrainingPhases.validate over ``sequence`` (results in the order of the validations) with ``selection``;
    returns the selected flags of validation.csv and how often the reference was flown."""
    import laddermill_gym.control.factory as factory
    import laddermill_gym.control.sb3_policy as sb3_policy

    flown = []
    queue = list(sequence)
    monkeypatch.setattr(sb3_policy, "SB3Controller", lambda *_a: "policy")
    monkeypatch.setattr(factory, "make_controller", lambda spec, *_a: flown.append(spec) or "reference")
    monkeypatch.setattr(hv, "validate", lambda ctrl, *_a: dict(REF if ctrl == "reference" else queue.pop(0)))
    val = Validation(1, 1000, 60.0, (ValidationSet("a", 5, [{}]), ValidationSet("b", 3, [{}])), selection)
    cfg = type("Cfg", (), dict(validation=val, env_id="x", carried_env_kwargs=lambda self: {}))()
    saved = []
    phases = hv.TrainingPhases()
    phases.cfg, phases.out, phases.pbar, phases.t0, phases.num_timesteps = cfg, tmp_path, _Bar(), 0.0, 0
    phases.model = None
    phases._vecnorm = lambda: None
    phases._save_best = lambda _vn: saved.append(phases.num_timesteps)
    phases._save_checkpoint = lambda force=False: None  # the training's callback saves the validated policy
    for step in range(len(sequence)):
        phases.num_timesteps = step
        phases.validate()
    rows = list(csv.DictReader(Path(tmp_path / "validation.csv").read_text().splitlines()))
    return [int(r["selected"]) for r in rows], flown, saved, rows


def test_training_keeps_the_paired_best_and_flies_the_reference_once(tmp_path, monkeypatch):
    # by hand, penalty 2: START 5 (kept: the first), GAIN 2, CALM 3, TWIN 5 with a smaller RMS (kept)
    flags, flown, saved, rows = _phases(tmp_path, monkeypatch, PAIRED, [START, GAIN, CALM, TWIN])
    assert flags == [1, 0, 0, 1] and saved == [0, 3] and flown == ["lqr"]
    assert [r["lost_to_reference"] for r in rows] == ["0", "2", "1", "0"]
    assert [float(r["score"]) for r in rows] == [5, 2, 3, 5]
    # penalty 0.4: START 5, GAIN 5.2 (kept), CALM 4.6, TWIN 5
    flags, *_ = _phases(tmp_path, monkeypatch, Selection("paired", 0.4, "lqr"), [START, GAIN, CALM, TWIN])
    assert flags == [1, 1, 0, 0]


def test_the_default_rule_keeps_the_original_choice(tmp_path, monkeypatch):
    # the most survived, then the smaller RMS: START 5, GAIN 6 (kept), CALM 5, TWIN 5; no reference flown
    flags, flown, saved, rows = _phases(tmp_path, monkeypatch, Selection(), [START, GAIN, CALM, TWIN])
    assert flags == [1, 1, 0, 0] and saved == [0, 1] and flown == []
    assert [r["lost_to_reference"] for r in rows] == ["", "", "", ""]


def test_reselect_ranks_by_the_paired_rule(tmp_path, monkeypatch):
    """reselect over a run folder whose four checkpoints fly the table's rows (START at step 1 ... TWIN at step 4),
    with the config's paired rule: the reference is flown although not named, TWIN is selected; the same run with
    the default rule selects GAIN."""
    import laddermill_gym.control.factory as factory
    from laddermill_gym.harness import reselect as rs

    run = tmp_path / "run"
    (run / "checkpoints").mkdir(parents=True)
    table = dict(zip(("step_1", "step_2", "step_3", "step_4"), (START, GAIN, CALM, TWIN), strict=True))
    for name in table:
        (run / "checkpoints" / f"{name}.zip").write_bytes(b"")
    (run / "vecnormalize.pkl").write_bytes(b"")
    monkeypatch.setattr(factory, "make_controller", lambda spec, *_a: spec)
    monkeypatch.setattr(rs, "load_candidate", lambda model_file, *_a: model_file.stem)
    monkeypatch.setattr(hv, "validate", lambda ctrl, *_a: dict(table[ctrl] if ctrl in table else REF))
    for sel, best in ((None, "run/step_2"), ({"rule": "paired", "penalty": 2.0}, "run/step_4")):
        raw = yaml.safe_load(Path(CONFIG).read_text())
        raw["validation"].pop("selection")
        if sel is not None:
            raw["validation"]["selection"] = sel
        cfg = tmp_path / "cfg.yaml"
        cfg.write_text(yaml.safe_dump(raw))
        rows = rs.reselect(cfg, [run], log=lambda _s: None)
        assert [r["label"] for r in rows if r["selected"]] == [best]
        assert [r["label"] for r in rows if r["reference"]] == (["lqr"] if sel else [])
    assert [r["lost_to_reference"] for r in rows if not r["reference"]] == [0, 2, 1, 0]


@pytest.mark.parametrize("selection, match", [
    ({"rule": "best"}, r"bad\.yaml: field 'validation\.selection\.rule' = 'best': must be one of"),
    ({"rule": "paired"}, r"bad\.yaml: missing field 'validation\.selection\.penalty'"),
    ({"rule": "paired", "penalty": -1.0}, r"'validation\.selection\.penalty' = -1\.0: must be > 0"),
    ({"rule": "paired", "penalty": 2.0, "reference": "ppo"}, r"'validation\.selection\.reference' = 'ppo'"),
    ({"rule": "survived", "penalty": 2.0}, r"'validation\.selection\.penalty' = 2\.0: applies only to rule: paired"),
    ({"rule": "paired", "penalty": 2.0, "weight": 1}, r"unknown field 'validation\.selection\.weight'"),
    ("paired", r"validation\.selection must be a mapping"),
])
def test_bad_selection_is_named(tmp_path, selection, match):
    raw = yaml.safe_load(Path(CONFIG).read_text())
    raw["validation"]["selection"] = selection
    p = tmp_path / "bad.yaml"
    p.write_text(yaml.safe_dump(raw))
    with pytest.raises(ConfigError, match=match):
        load_rl_config(p)


def test_configs_read_their_rule():
    assert load_rl_config(CONFIG).validation.selection == Selection("paired", 2.0, "lqr")
    assert load_rl_config(CONFIG.replace("paired", "bounded")).validation.selection == Selection()
