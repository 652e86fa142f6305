"""The command line's inputs and outputs, from a review of 2026-12-07: each case here failed before its fix, after the
work (a bad ``--out`` after a two-minute demo), on a traceback, silently (a ``--time`` rounded, a failed run's exit
status 0) or not at all (an option ignored).

Oracles: the commands' own compute functions replaced by ones that fail the test when reached (so "refused before
the work" is checked, not timed), the physics step and sample interval of the scene file (the duration a run can
have), and the file system.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest

from laddermill_gym.cli import main as cli_main
from laddermill_gym.model.configio import ConfigError, config_path, read_yaml


def _never(*a, **k):
    raise AssertionError("the command's work started before its options were checked")


@pytest.fixture
def a_file(tmp_path):
    f = tmp_path / "a_file"
    f.write_text("")
    return f


def _status(argv) -> int:
    """The exit status of ``laddermill ARGV``: returned (run_guarded) or raised (argparse's error)."""
    try:
        return cli_main(argv)
    except SystemExit as err:
        return err.code


@pytest.mark.parametrize("argv, module, name", [
    (["demo", "--controllers", "open_loop", "--time", "0.05", "--no-gif", "--no-progress"],
     "laddermill_gym.studies.mill.control_demo", "run_demo"),
    (["pumping-cycle", "--cycles", "2"], "laddermill_gym.studies.pumping.pumping_cycle", "run_cycles"),
    (["tether-convergence", "--lengths", "100"], "laddermill_gym.studies.pumping.tether_convergence", "tether_run"),
    (["lqr", "--rollout", "2"], "laddermill_gym.harness.lqr_report", "design_tethered_wing"),
    (["train", "configs/agents/ppo_tethered_wing.yaml"], "laddermill_gym.harness.train", "build_model"),
])
def test_an_output_folder_that_is_a_file_is_refused_before_the_work(a_file, monkeypatch, capsys, argv, module, name):
    import importlib

    monkeypatch.setattr(importlib.import_module(module), name, _never)
    assert _status([*argv, "--out", str(a_file)]) == 2
    assert "is a file, not a folder" in capsys.readouterr().err


def test_simulate_says_when_time_is_not_whole_samples_and_refuses_none(tmp_path, capsys):
    assert cli_main(["simulate", "tethered_wing", "--time", "0.7", "--sample-dt", "0.4", "--out", str(tmp_path),
                     "--quiet", "--no-step-check"]) == 0
    err = capsys.readouterr().err
    assert "--time = 0.7 s is not a whole number of sample intervals of 0.4 s" in err and "simulating 0.8 s" in err
    import numpy as np

    assert np.load(tmp_path / "tethered_wing.npz")["t_s"][-1] == pytest.approx(0.8)  # what it says it simulated
    assert cli_main(["simulate", "tethered_wing", "--time", "0.001", "--sample-dt", "0.001",
                     "--out", str(tmp_path)]) == 2  # under half of one 5 ms physics step: nothing simulated
    assert "nothing would be simulated" in capsys.readouterr().err


def test_simulate_refuses_a_start_below_the_ground_and_periodic_on_a_fixed_cable(tmp_path, capsys):
    assert cli_main(["simulate", "tethered_wing", "--time", "0.2", "--sample-dt", "0.1", "--ground-height", "1000",
                     "--out", str(tmp_path), "--quiet"]) == 2
    assert "the start has node 0 at height 49.3 m, at or below the ground at 1000 m" in capsys.readouterr().err
    assert cli_main(["simulate", "tethered_wing", "--start", "periodic", "--out", str(tmp_path)]) == 2
    assert "laddermill simulate: error: --start periodic needs a moving-cable scene" in capsys.readouterr().err


def test_a_dotted_scene_name_keeps_its_whole_name_in_every_file(tmp_path, capsys):
    scene = tmp_path / "wing_v2.5.yaml"  # the shipped scene, its files named as shipped data
    text = config_path("scenes", "tethered_wing").read_text().replace("../", "package:")
    scene.write_text(text.replace("name: tethered_wing", "name: wing_v2.5"))  # the files are named by the scene's name
    out = tmp_path / "out"
    assert cli_main(["simulate", str(scene), "--time", "0.1", "--sample-dt", "0.05", "--csv", "--out", str(out),
                     "--quiet"]) == 0
    assert {"wing_v2.5.npz", "wing_v2.5.csv", "wing_v2.5_shape.png"} <= {p.name for p in out.iterdir()}


def test_tether_convergence_exits_1_when_a_run_fails_and_keeps_the_failure(tmp_path, monkeypatch):
    from laddermill_gym.studies.pumping import tether_convergence as tc

    def fails(length, cycles, start):
        raise RuntimeError(f"element length {length} m broke down")

    monkeypatch.setattr(tc, "tether_run", fails)
    assert cli_main(["tether-convergence", "--lengths", "100", "300", "--out", str(tmp_path)]) == 1
    rows = json.loads((tmp_path / "tether_convergence.json").read_text())
    assert [r["element_length_m"] for r in rows] == [100.0, 300.0] and "broke down" in rows[0]["failure"]


def test_site_refuses_an_unknown_turbine_before_optimising(monkeypatch, tmp_path, capsys):
    pytest.importorskip("windpowerlib")
    from laddermill_gym.quasisteady import cli as site

    monkeypatch.setattr(site, "optimise", _never)
    with pytest.raises(SystemExit) as err:
        cli_main(["site", "--wind", "cabauw", "--case", "table1", "--turbine", "nosuch", "--quiet",
                  "--out", str(tmp_path)])
    assert err.value.code == 2 and "--turbine 'nosuch': not a windpowerlib turbine type" in capsys.readouterr().err


def test_a_binary_or_wrong_kind_config_is_named_in_one_line(tmp_path):
    png = tmp_path / "figure.png"
    png.write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(64))
    with pytest.raises(ConfigError, match=r"figure.png: not a UTF-8 text YAML file"):
        read_yaml(png)
    text = tmp_path / "list.yaml"
    text.write_text("\n".join(f"- item {i}" for i in range(200)))
    with pytest.raises(ConfigError, match=r"top level must be a mapping, got list \['item 0'") as err:
        read_yaml(text)
    assert len(str(err.value).split("got list ", 1)[1]) <= 80  # the value cut short, not the whole file


@pytest.mark.parametrize("argv, says", [
    (["--table", "NOFILE"], "--table 'NOFILE': not a readable power_curve.json (FileNotFoundError"),
    (["--replay", "NOTJSON"], "not a readable power_curve.json (JSONDecodeError"),
    (["--table", "WRONG"], "not a power_curve.json of this command (no config)"),
    (["--table", "WRONG", "--replay", "WRONG"], "--table and --replay: give one"),
])
def test_power_curve_names_a_bad_earlier_run(tmp_path, capsys, argv, says):
    files = {"NOFILE": tmp_path / "nosuch.json", "NOTJSON": tmp_path / "a.txt", "WRONG": tmp_path / "w.json"}
    files["NOTJSON"].write_text("not json")
    files["WRONG"].write_text('{"rows": []}')
    argv = [str(files[a]) if a in files else a for a in argv]
    with pytest.raises(SystemExit) as err:
        cli_main(["power-curve", *argv, "--out", str(tmp_path / "out")])
    assert err.value.code == 2 and says.replace("NOFILE", str(files["NOFILE"])) in capsys.readouterr().err


@pytest.mark.parametrize("argv, says", [
    (["--full-check"], "--full-check closes a chain's loop"),
    (["--step", "0.1"], "--step is --rollout's"),
    (["--out", "somewhere"], "--out is --rollout's"),
])
def test_lqr_refuses_options_it_would_ignore(capsys, argv, says):
    with pytest.raises(SystemExit) as err:
        cli_main(["lqr", *argv])
    assert err.value.code == 2 and says in capsys.readouterr().err


def test_python_m_agents_gives_one_line_and_exit_2():
    from pathlib import Path

    run = subprocess.run([sys.executable, "-m", "agents.evaluate", "--episodes", "0"], capture_output=True,
                         text=True, timeout=120, cwd=Path(__file__).resolve().parents[1])  # agents/ is the repo's
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert "laddermill evaluate: error: --episodes = 0: must be a whole number >= 1 and <= 4096" in run.stderr


def test_work_precision_refuses_two_scenes_of_one_file_name(tmp_path, capsys):
    other = tmp_path / "tethered_wing.yaml"
    shutil.copy(config_path("scenes", "tethered_wing"), other)
    assert cli_main(["work-precision", "tethered_wing", str(other), "--out", str(tmp_path / "wp")]) == 2
    assert "the same file name" in capsys.readouterr().err


def test_stable_step_estimates_a_cable_too_fine_for_the_files_rk4_step(capsys):
    # 40 elements per piece: the file's 5 ms RK4 step is refused at load (the case the command is for), and the
    # trim's Newton stopped short of its angle-of-attack tolerance (1.1e-9 rad against 1e-9) before the polish
    assert cli_main(["stable-step", "tethered_wing", "--elements-per-piece", "40"]) == 0
    out = capsys.readouterr().out
    assert "rk4: largest stable step" in out
    limit = float(out.split("rk4: largest stable step ")[1].split(" s")[0])
    assert limit < 0.005 / 2  # the refusal's own bound: the file's step is more than twice RK4's limit


def test_a_scenes_file_name_drops_only_a_yaml_suffix():
    from laddermill_gym.studies.numerics.scenes import file_stem

    assert [file_stem(n) for n in ("wing_v2.5", "dir/wing_v2.5.yaml", "tethered_wing", "x/y.yml")] == \
        ["wing_v2.5", "wing_v2.5", "tethered_wing", "y"]


@pytest.mark.parametrize("unbuffered", [False, True])
def test_a_reader_that_leaves_the_pipe_ends_the_command_quietly(unbuffered):
    """``laddermill scenes | head -1``: the reader closes the pipe before the command writes; the command ends with
    141 (a tool ended by SIGPIPE) and nothing on stderr, where it printed a BrokenPipeError traceback. Both with
    Python's default block-buffered pipe (the output then written at the end of the command) and with
    ``PYTHONUNBUFFERED`` (each line at once); the first passed only with the second set (review of 2026-12-08)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"} | ({"PYTHONUNBUFFERED": "1"} if unbuffered
                                                                             else {})
    proc = subprocess.Popen([sys.executable, "-m", "laddermill_gym", "scenes"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env)
    proc.stdout.close()  # before the command's first line
    err = proc.stderr.read()
    assert proc.wait(timeout=120) == 141 and err == b""


def test_a_broken_pipe_that_is_not_the_output_keeps_its_traceback():
    """A BrokenPipeError from a pipe of the command's own while its standard output is fine is a failure with its
    traceback (exit status 1), not the quiet 141 of a reader that left the output (review of 2026-12-08)."""
    script = ("import sys\nfrom laddermill_gym.studies.commands import run_guarded\n"
              "def run():\n    raise BrokenPipeError('a worker pipe closed')\n"
              "sys.exit(run_guarded('demo', run))\n")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert out.returncode == 1 and "BrokenPipeError: a worker pipe closed" in out.stderr, out
