"""Every ``laddermill`` subcommand tried with a missing file, an unknown name and an out-of-range number (issue 34
item 6 and its closing check): each gives one line on stderr, ``laddermill NAME: error: ...`` naming the option or
field and the value, exit status 2, no traceback, before any long work. Where a command has no such argument the
case is left out (``N/A`` below)."""

from __future__ import annotations

import pytest

from laddermill_gym.cli import FORWARDED, build_parser
from laddermill_gym.cli import main as cli_main

MISSING, UNKNOWN, RANGE = "missing file", "unknown name", "out-of-range number"
NOFILE = "/nonexistent/laddermill_sweep.yaml"

#: (command, kind, arguments, text the message names); scenes and workers take no names or numbers,
#: zoo's numbers are rl-zoo3's own
CASES = [
    ("simulate", MISSING, [NOFILE], "laddermill_sweep.yaml: no such file"),
    ("simulate", UNKNOWN, ["nosuch_scene"], "nosuch_scene.yaml: no such file"),
    ("simulate", RANGE, ["tethered_wing", "--time", "-1"], "--time = -1.0"),
    ("simulate", RANGE, ["tethered_wing", "--dt", "1e-9", "--time", "5"], "would take 5e+09 steps"),
    ("simulate", UNKNOWN, ["podgaets_5km"], "is a point-mass scene"),
    ("bench", MISSING, ["--scenes", NOFILE], "laddermill_sweep.yaml: no such file"),
    ("bench", UNKNOWN, ["--scenes", "nosuch_scene"], "nosuch_scene"),
    ("bench", MISSING, ["--json", "/nonexistent/x.json"], "--json = '/nonexistent/x.json': no such folder"),
    ("bench-envs", MISSING, ["--json", "/nonexistent/x.json"], "no such folder"),
    ("bench-envs", RANGE, ["--copies", "0"], "--copies = 0: must be a positive integer"),
    ("bench-envs", UNKNOWN, ["--envs", "NoSuch-v0"], "--envs = 'NoSuch-v0': not one of"),
    ("scenes", UNKNOWN, ["nosuch_argument"], "unrecognized arguments: nosuch_argument"),
    ("train", MISSING, [NOFILE], "laddermill_sweep.yaml: no such file"),
    ("train", UNKNOWN, ["ppo_nosuch"], "config = 'ppo_nosuch'"),
    ("train", RANGE, ["ppo_tethered_wing", "--n-envs", "0"], "--n-envs = 0"),
    ("evaluate", MISSING, ["--controllers", f"lqr:{NOFILE}"], "laddermill_sweep.yaml: no such file"),
    ("evaluate", UNKNOWN, ["--env", "laddermill_gym/TetheredWing-v0", "--controllers", "nosuch"], "'nosuch'"),
    ("evaluate", RANGE, ["--episodes", "0"], "--episodes = 0"),
    ("zoo", MISSING, ["enjoy", "--folder", "/nonexistent"], "--folder = '/nonexistent': no such folder"),
    ("zoo", UNKNOWN, ["nosuch_script"], "invalid choice: 'nosuch_script'"),
    ("lqr", MISSING, ["--config", NOFILE], "laddermill_sweep.yaml: no such file"),
    ("lqr", UNKNOWN, ["--config", "lqr_nosuch"], "config = 'lqr_nosuch'"),
    ("lqr", RANGE, ["--rollout", "-1"], "--rollout = -1.0"),
    ("site", MISSING, ["--wind", NOFILE], "laddermill_sweep.yaml"),
    ("site", UNKNOWN, ["--case", "nosuch"], "'nosuch'"),
    ("site", RANGE, ["--power-mw", "-1"], "--power-mw"),
    ("work-precision", MISSING, [NOFILE], "laddermill_sweep.yaml: no such file"),
    ("work-precision", UNKNOWN, ["nosuch_scene"], "nosuch_scene.yaml: no such file"),
    ("work-precision", RANGE, ["tethered_wing", "--time", "-1"], "--time = -1.0"),
    ("stable-step", MISSING, [NOFILE], "laddermill_sweep.yaml: no such file"),
    ("stable-step", UNKNOWN, ["nosuch_scene"], "nosuch_scene.yaml: no such file"),
    ("stable-step", RANGE, ["tethered_wing", "--elements-per-piece", "0"], "--elements-per-piece = 0"),
    ("stress", MISSING, [NOFILE, "--quick"], "laddermill_sweep.yaml: no such file"),
    ("stress", UNKNOWN, ["tethered_wing", "nosuch_scene", "--quick"], "nosuch_scene.yaml: no such file"),
    ("stress", RANGE, ["tethered_wing", "--hours", "-1", "--quick"], "--hours = -1.0"),
    ("stress", UNKNOWN, ["tethered_wing", "--envs", "nosuch/Env-v0"], "--envs 'nosuch/Env-v0'"),
    ("train-seeds", MISSING, [NOFILE, "--seeds", "1"], "laddermill_sweep.yaml: no such file"),
    ("train-seeds", UNKNOWN, ["ppo_nosuch", "--seeds", "1"], "config = 'ppo_nosuch'"),
    ("train-seeds", RANGE, ["ppo_tethered_wing", "--seeds", "-1"], "--seeds [-1]"),
    ("workers", UNKNOWN, ["nosuch_action"], "invalid choice: 'nosuch_action'"),
    ("pumping-cycle", MISSING, ["--config", NOFILE], "laddermill_sweep.yaml: no such file"),
    ("pumping-cycle", UNKNOWN, ["--config", "nosuch"], "--config = 'nosuch'"),
    ("pumping-cycle", RANGE, ["--cycles", "1"], "--cycles = 1"),
    ("tether-convergence", RANGE, ["--lengths", "300", "1"], "--lengths = 1.0"),
    ("tether-convergence", RANGE, ["--start-length", "50"], "--start-length = 50.0"),
    ("gust-bench", MISSING, ["--suite", NOFILE], "laddermill_sweep.yaml: no such file"),
    ("gust-bench", UNKNOWN, ["--controllers", "nosuch"], "'nosuch'"),
    ("gust-bench", UNKNOWN, ["--env", "nosuch/Env-v0"], "--env 'nosuch/Env-v0'"),
    ("gust-bench", RANGE, ["--workers", "-1"], "--workers -1"),
    ("demo", MISSING, ["--controllers", NOFILE], "laddermill_sweep.yaml"),
    ("demo", UNKNOWN, ["--env", "laddermill_gym/TetheredWing-v0"], "not a mill id"),
    ("demo", RANGE, ["--time", "-1"], "--time = -1.0"),
    ("power-curve", RANGE, ["--workers", "-1"], "--workers -1"),
]
def test_the_sweep_covers_every_command_and_kind(capsys):
    """The commands: those ``laddermill`` lists for an unknown one (argparse's "choose from ...")."""
    import re

    with pytest.raises(SystemExit):
        build_parser().parse_args(["nosuch_command"])
    listed = re.search(r"choose from (.*)\)", capsys.readouterr().err).group(1)
    commands = set(re.findall(r"'([\w-]+)'", listed))
    assert set(FORWARDED) < commands and {"simulate", "scenes"} < commands
    assert {c for c, *_ in CASES} == commands
    n = len(CASES)
    print(f"{n} invocations over {len(commands)} commands: {sum(k == MISSING for _, k, *_ in CASES)} missing files, "
          f"{sum(k == UNKNOWN for _, k, *_ in CASES)} unknown names, {sum(k == RANGE for _, k, *_ in CASES)} numbers")


@pytest.mark.parametrize("command, kind, args, names", [
    pytest.param(*c, id=f"{c[0]}-{c[1].split()[0]}-{i}") for i, c in enumerate(CASES)])
def test_bad_input_is_one_line_and_exit_2(command, kind, args, names, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # nothing is written into the checkout
    if command in ("train", "train-seeds") and kind == RANGE:
        pytest.importorskip("stable_baselines3")  # the config is read first (its hyperparameters' check needs SB3)
    if command == "zoo":
        pytest.importorskip("rl_zoo3")
    try:
        code = cli_main([command, *args])
    except SystemExit as stop:  # argparse's own errors
        code = stop.code
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert code == 2, err
    assert "Traceback" not in err
    # the top-level parser reports arguments no command takes ("laddermill: error: unrecognized arguments")
    prefix = "laddermill:" if "unrecognized arguments" in err else f"laddermill {command}"
    assert len(lines) == 1 and lines[0].startswith(prefix) and "error:" in lines[0], err
    assert names in lines[0], err


@pytest.mark.parametrize("given", ["configs/agents/ppo_tethered_wing.yaml", "ppo_tethered_wing"])
def test_train_finds_the_shipped_config_outside_a_checkout(given, tmp_path, monkeypatch, capsys):
    """Item 14: from a folder without configs/ the path and the bare name are the shipped config (read: the
    command goes on to its next check, ``--replot`` without a run folder)."""
    pytest.importorskip("stable_baselines3")
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:  # the parser's own error
        cli_main(["train", given, "--replot"])
    assert stop.value.code == 2
    assert capsys.readouterr().err.startswith("laddermill train: error: --replot needs --out RUN_FOLDER")
