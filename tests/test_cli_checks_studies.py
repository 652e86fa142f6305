"""The study and benchmark commands refuse bad input before any work, with one line naming the option and the value
and exit status 2, whether run as ``laddermill NAME`` or as ``python -m MODULE`` (their ``main``): an output path
that cannot be written (it failed after the whole run), a selection that is empty or names a thing twice, a scene
or thread count the command cannot measure, a hand-over time or an elevator that is not a number, an option that
would be ignored. Each case here ran before the fix and failed only after its work, on a traceback, or not at all."""

from __future__ import annotations

import pytest

from laddermill_gym.cli import main as cli_main


@pytest.fixture
def a_file(tmp_path):
    f = tmp_path / "a_file"
    f.write_text("")
    return f


def _one_line(capsys, prog: str, says: str) -> None:
    err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
    assert len(err) == 1 and err[0].startswith(f"{prog}: error: ") and says in err[0], err


def test_python_m_entry_points_give_one_line_and_exit_2(capsys):
    """``python -m laddermill_gym.studies.numerics.work_precision nosuch`` printed a UsageError traceback, exit 1."""
    from laddermill_gym.studies.numerics import work_precision

    assert work_precision.main(["nosuch"]) == 2
    _one_line(capsys, "laddermill work-precision", "nosuch")


@pytest.mark.parametrize("argv, says", [
    (["gust-bench", "--env", "laddermill_gym/TetheredWing-v0", "--controllers", "open_loop", "--out", "FILE"],
     "is a file, not a folder"),
    (["stress", "tethered_wing", "--quick", "--envs", "laddermill_gym/TetheredWing-v0", "--out", "FILE"],
     "is a file, not a folder"),
    (["bench", "--startup", "--quick", "--json", "DIR"], "--json = 'DIR': is a folder, not a file"),
])
def test_output_paths_are_refused_before_the_work(tmp_path, a_file, capsys, argv, says):
    argv = [str(a_file) if a == "FILE" else str(tmp_path) if a == "DIR" else a for a in argv]
    assert cli_main(argv) == 2
    _one_line(capsys, f"laddermill {argv[0]}", says.replace("'DIR'", repr(str(tmp_path))))


@pytest.mark.parametrize("argv, says", [
    # random_perturbation is a gusts-v1 scenario of other envs: an empty selection, an IndexError after the setup
    (["gust-bench", "--env", "laddermill_gym/TetheredWing-v0", "--scenarios", "random_perturbation"],
     "--scenarios ['random_perturbation']: not scenarios of laddermill_gym/TetheredWing-v0"),
    # a controller named twice counted its seeds twice in the summary (n: 2 for one seed)
    (["gust-bench", "--env", "laddermill_gym/TetheredWing-v0", "--controllers", "open_loop", "lqr", "open_loop"],
     "--controllers ['open_loop']: named twice"),
    (["bench", "--startup", "--quick", "--scenes", "ladder_chain"], "--scenes would be ignored"),
    (["bench", "--quick", "--scenes", "podgaets_5km", "--no-mill", "--no-pointmass"], "a point-mass scene"),
    (["bench", "--quick", "--scenes", "laddermill", "--no-mill", "--no-pointmass"], "a moving-cable scene"),
    (["stable-step", "podgaets_5km"], "a point-mass scene"),
    (["bench", "--quick", "--scenes", "tethered_wing", "tethered_wing", "--no-mill", "--no-pointmass"],
     "--scenes ['tethered_wing']: named twice"),
    (["work-precision", "tethered_wing", "tethered_wing"], "scene ['tethered_wing']: named twice"),
    (["simulate", "tethered_wing", "--time", "2", "--direction-step", "0.01", "--step-time", "50", "--quiet"],
     "--step-time = 50 s: the direction step would come at or after the end of the run"),
    (["bench-envs", "--threads", "4096", "--envs", "TetheredWing-v0", "--copies", "8", "--quick"],
     "every count is above the pool's"),
])
def test_selections_the_command_cannot_run_are_refused(tmp_path, capsys, argv, says):
    if argv[0] in ("gust-bench", "simulate"):
        argv = [*argv, "--out", str(tmp_path / "out")]
    assert cli_main(argv) == 2
    _one_line(capsys, f"laddermill {argv[0]}", says)


def test_module_programs_refuse_numbers_that_are_not(capsys):
    from laddermill_gym.studies.gusts import switch_controllers
    from laddermill_gym.studies.mill import trim_slope
    from laddermill_gym.studies.pointmass import pointmass_benchmark

    with pytest.raises(SystemExit) as e:
        switch_controllers.main(["--scenario", "NTM_IB", "--controllers", "lqr", "open_loop", "--times", "nan"])
    assert e.value.code == 2 and "--times nan" in capsys.readouterr().err
    # a hand-over after the episode's end printed "survives" for a hand-over that never happened; an unknown scenario
    # ended in a traceback (review of 2026-12-08); gusts-v1's NTM_IB episodes are 60 s (configs/benchmarks/gusts-v1)
    for argv, says in ((["--scenario", "NTM_IB", "--times", "0", "1000"], "--times 1000.0: at or after the end of "
                        "NTM_IB's episode (60 s): no hand-over"),
                       (["--scenario", "nosuch", "--times", "1"], "--scenario 'nosuch': ")):
        with pytest.raises(SystemExit) as e:
            switch_controllers.main([*argv, "--controllers", "lqr", "open_loop"])
        err = capsys.readouterr().err
        assert e.value.code == 2 and says in err and "Traceback" not in err, err
    with pytest.raises(SystemExit) as e:
        trim_slope.main(["--elevators", "nan", "1000"])
    assert e.value.code == 2 and "--elevators = [nan, 1000.0]" in capsys.readouterr().err
    assert pointmass_benchmark.main(["--scaling", "0"]) == 2
    _one_line(capsys, "laddermill bench-pointmass", "--scaling 0: must be a thread count from 1")


def test_meijaard_refuses_a_scene_without_a_moving_cable(tmp_path, capsys):
    """``--scene tethered_wing`` gave ``TypeError: replace() should be called on dataclass instances``."""
    from laddermill_gym.studies.mill import meijaard

    for scene in ("tethered_wing", "podgaets_5km"):
        with pytest.raises(SystemExit) as e:
            meijaard.main(["--scene", scene, "--quick", "--out", str(tmp_path / "m")])
        assert e.value.code == 2 and "no moving cable through a station" in capsys.readouterr().err
    assert not (tmp_path / "m").exists()


def test_step_convergence_refuses_a_step_that_would_not_finish(capsys):
    from laddermill_gym.studies.gusts import step_convergence

    with pytest.raises(SystemExit) as e:
        step_convergence.main(["--steps", "rk4:1e-9"])
    assert e.value.code == 2 and "--steps rk4:1e-9: the step = 1e-09 s" in capsys.readouterr().err


def test_mill_power_curve_sends_its_cases_to_ray_when_asked(monkeypatch, tmp_path):
    """``laddermill power-curve --ray ADDRESS`` ran its cases locally: the address never reached the task runner."""
    pytest.importorskip("ray")  # the option is refused without Ray (an extra)
    from laddermill_gym.studies import parallel
    from laddermill_gym.studies.mill import power_curve

    seen = {}

    def fake(tasks, **kw):
        seen.update(kw)
        raise KeyboardInterrupt  # stop before any case

    monkeypatch.setattr(parallel, "run_tasks", fake)
    with pytest.raises(KeyboardInterrupt):
        power_curve.main(["--quick", "--ray", "local", "--out", str(tmp_path)])
    assert seen["ray"] == "local"


@pytest.mark.parametrize("module, argv, says", [
    ("rotorcraft.rotor_chart", ["--out", "{tmp}/chart.txt"], "the file must end in one of .png, .pdf, .svg"),
    ("rotorcraft.rotor_chart", ["--out", "{file}/chart.png"], "its folder '{file}' is a file"),
    ("rotorcraft.rotor_chart", ["--out", "{tmp}/c.png", "--csv", "{file}/c.csv"], "--csv = '{file}/c.csv'"),
    ("lateral.lateral_study", ["--out", "{tmp}"], "the file must end in one of"),
    ("rotorcraft.craft_stability", ["--out", "{file}"], "is a file, not a folder"),
    ("pumping.power_curve", ["--winds", "8", "--out", "{file}"], "is a file, not a folder"),
])
def test_figure_studies_refuse_an_output_path_before_their_work(module, argv, says, tmp_path, a_file, monkeypatch):
    """A review of 2026-12-07: these ended in a traceback (exit 1), the pumping power curve after flying every wind.
    Run as ``python -m``: one line, exit 2, and no flight (its curve_point replaced by a recorder)."""
    import importlib
    import subprocess
    import sys

    fill = {"tmp": str(tmp_path), "file": str(a_file)}
    argv = [a.format(**fill) for a in argv]
    done = subprocess.run([sys.executable, "-m", f"laddermill_gym.studies.{module}", *argv], capture_output=True,
                          text=True, timeout=300)
    err = [line for line in done.stderr.splitlines() if line.strip()]
    assert done.returncode == 2 and len(err) == 1 and says.format(**fill) in err[0], done.stderr[-2000:]
    mod = importlib.import_module(f"laddermill_gym.studies.{module}")
    if hasattr(mod, "curve_point"):
        flown = []
        monkeypatch.setattr(mod, "curve_point", lambda *a: flown.append(a))
        with pytest.raises(Exception, match="is a file"):
            mod.main(argv)
        assert flown == []


def test_figure_studies_do_not_write_into_the_package_by_default():
    """rotor_chart and lateral_study wrote their figure over laddermill_gym/docs/figures/ relative to any working
    folder (the docs' figures are drawn with an explicit --out: docsite/pictures.py)."""
    from laddermill_gym.studies.lateral import lateral_study
    from laddermill_gym.studies.rotorcraft import rotor_chart

    for default in (rotor_chart.DEFAULT_OUT, lateral_study.DEFAULT_OUT):
        assert "docs" not in default.parts and default.parts[0] == "results"
