"""The evaluation commands' checks before any episode (harness/evaluate.py, harness/paired_survival.py): the output
folder, an episode that is not a whole number of control periods, the episode count and seeds, both controllers
built before either flies, and no evaluation's tables replaced unasked.

Oracles: the commands' exit status and one-line errors, with the builders and episode runners replaced by ones that
fail if called (nothing ran); the folders on disk; hand-counted control periods (0.07 s at 0.05 s: 1.4 periods).
"""

from __future__ import annotations

from pathlib import Path

import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.cli import main as cli_main
from laddermill_gym.harness import evaluate as ev

TW = "laddermill_gym/TetheredWing-v0"
SEVERE = "configs/agents/ppo_tethered_wing_severe.yaml"


def _nothing(*args, **kwargs):
    raise AssertionError("a controller was built or an episode ran")


def _one_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    return lines[0]


def test_evaluate_refuses_a_file_as_out_before_building(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(ev, "build_controllers", _nothing)
    (tmp_path / "afile").write_text("")
    assert cli_main(["evaluate", "--controllers", "open_loop", "--out", str(tmp_path / "afile")]) == 2
    assert _one_line(capsys.readouterr().err) == (f"laddermill evaluate: error: --out = '{tmp_path / 'afile'}': is a "
                                                  "file, not a folder")


def test_evaluate_refuses_an_episode_of_part_periods(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(ev, "run_episodes", _nothing)
    monkeypatch.setattr(ev, "build_controllers", lambda specs, env, kw, **k: {s: (None, dict(kw)) for s in specs})
    out = tmp_path / "eval"
    assert cli_main(["evaluate", "--controllers", "open_loop", "--episode-time", "0.07", "--out", str(out)]) == 2
    line = _one_line(capsys.readouterr().err)
    assert line.startswith("laddermill evaluate: error: --episode-time = 0.07: episode_time = 0.07 s is not a whole "
                           "number of control periods (control_dt = 0.05 s: 1.4 periods)")
    assert not out.exists()


def test_evaluate_keeps_an_earlier_evaluations_tables(tmp_path, monkeypatch, capsys):
    """An --out holding them is refused (before any build) unless --force; the default folder moves on to _2, _3."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(ev, "build_controllers", _nothing)
    held = tmp_path / "held"
    held.mkdir()
    (held / "summary.csv").write_text("controller\n")
    assert cli_main(["evaluate", "--controllers", "open_loop", "--out", str(held)]) == 2
    line = _one_line(capsys.readouterr().err)
    assert "holds an evaluation's tables already (summary.csv)" in line and "--force" in line
    assert ev.output_folder(held, TW, force=True) == held
    default = tmp_path / "results" / "TetheredWing-v0"
    assert ev.output_folder(None, TW) == Path("results/TetheredWing-v0")  # none there yet
    default.mkdir(parents=True)
    (default / "lateral.png").write_bytes(b"")
    assert ev.output_folder(None, TW) == Path("results/TetheredWing-v0_2")
    (tmp_path / "results" / "TetheredWing-v0_2").mkdir()
    (tmp_path / "results" / "TetheredWing-v0_2" / "summary.csv").write_text("")
    assert ev.output_folder(None, TW) == Path("results/TetheredWing-v0_3")
    assert ev.output_folder(None, TW, force=True) == Path("results/TetheredWing-v0")


@pytest.mark.parametrize("args, text", [
    (["--episodes", "0"], "--episodes = 0: must be a whole number >= 1"),
    (["--episodes", "-3"], "--episodes = -3: must be a whole number >= 1"),
    (["--seed", "-1"], "--seed = -1: must be a whole number >= 0"),
    (["--controllers", "lqr", "lqr"], "--controllers ['lqr', 'lqr']: the same controller twice"),
])
def test_paired_survival_checks_its_options_before_any_controller(monkeypatch, capsys, args, text):
    from laddermill_gym.control import factory
    from laddermill_gym.harness.paired_survival import main
    from laddermill_gym.studies.gusts import gust_bench

    monkeypatch.setattr(factory, "make_controller", _nothing)
    monkeypatch.setattr(gust_bench, "run_episodes", _nothing)
    argv = ["--config", SEVERE, "--set", "ntm_ib", "--controllers", "lqr", "open_loop", *args]
    with pytest.raises(SystemExit) as err:
        main(argv)
    assert err.value.code == 2
    line = _one_line(capsys.readouterr().err)
    assert line.startswith("python -m laddermill_gym.harness.paired_survival: error: " + text), line


def test_paired_survival_builds_both_controllers_before_either_flies(monkeypatch):
    from laddermill_gym.control import factory
    from laddermill_gym.harness.paired_survival import paired_survival
    from laddermill_gym.studies.gusts import gust_bench

    def make(spec, env_id, kw=None):
        if spec == "bad":
            raise ValueError("controller = 'bad': not a controller")
        return object()

    monkeypatch.setattr(factory, "make_controller", make)
    monkeypatch.setattr(gust_bench, "run_episodes", _nothing)
    with pytest.raises(ValueError, match="'bad': not a controller"):
        paired_survival(SEVERE, "ntm_ib", 2, 5000, ["open_loop", "bad"])
    with pytest.raises(ValueError, match="episodes = 0"):
        paired_survival(SEVERE, "ntm_ib", 0, 5000, ["open_loop", "lqr"])


@pytest.mark.parametrize("argv, says", [
    (["--env-config", '{"nosuch": 1}'], "nosuch = 1: not arguments of the wing env"),
    (["--minibatch", "128", "--train-batch", "64"], "--minibatch 128: must not exceed --train-batch 64"),
    (["--seed", "-1"], "--seed -1: must be >= 0"),
])
def test_rllib_train_refuses_bad_settings_before_ray_starts(capsys, argv, says):
    """These reached RLlib: a 133-line log with the cause buried in a runner's traceback (a review of 2026-12-07)."""
    from laddermill_gym.harness import rllib_train

    with pytest.raises(SystemExit) as err:
        rllib_train.main(argv)
    assert err.value.code == 2 and says in capsys.readouterr().err
