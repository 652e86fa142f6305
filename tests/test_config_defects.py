"""Config files that load but are wrong are refused with the file, the field (or row and column) and the value
(issue 17 point 8)."""

from __future__ import annotations

import pytest

from laddermill_gym import load_scene
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, read_yaml


def test_a_key_given_twice_is_refused_with_its_line(tmp_path):
    text = (CONFIG_DIR / "scenes" / "tethered_wing.yaml").read_text()
    assert "\n  dt: " in text
    bad = tmp_path / "twice.yaml"
    bad.write_text(text.replace("\n  dt: ", "\n  dt: 0.01\n  dt: ", 1))
    with pytest.raises(ConfigError, match=r"twice.yaml: not valid YAML: duplicated key 'dt' \(first given on line"):
        read_yaml(bad)
    with pytest.raises(ConfigError, match="duplicated key 'dt'"):
        load_scene(bad)


def test_every_shipped_yaml_has_unique_keys():
    files = sorted(CONFIG_DIR.glob("*/*.yaml"))
    assert len(files) > 10
    for f in files:
        read_yaml(f)  # raises on a duplicated key


def _wing_copy(tmp_path, table_text: str | None = None, **wing_changes):
    """A copy of the shipped wing (its YAML and, optionally, a replaced aerodynamic table) in tmp_path."""
    import shutil

    src = CONFIG_DIR / "wings"
    shutil.copy2(src / "meijaard_wing_aero.csv", tmp_path / "meijaard_wing_aero.csv")
    text = (src / "meijaard_wing.yaml").read_text()
    for k, v in wing_changes.items():
        lines = [ln if not ln.startswith(f"{k}:") else f"{k}: {v}" for ln in text.splitlines()]
        text = "\n".join(lines) + "\n"
    (tmp_path / "w.yaml").write_text(text)
    if table_text is not None:
        (tmp_path / "meijaard_wing_aero.csv").write_text(table_text)
    return tmp_path / "w.yaml"


def _table_lines():
    lines = (CONFIG_DIR / "wings" / "meijaard_wing_aero.csv").read_text().splitlines()
    first = next(i for i, ln in enumerate(lines) if ln.strip() and not ln.startswith("#"))
    return lines, first  # first: the header's index


@pytest.mark.parametrize("edit, says", [
    (lambda c: c.__setitem__(3, "abc"), r"line \d+, column 'CD\w*' = 'abc': must be a number|line \d+, column '\w+' "
                                         r"= 'abc': must be a number"),
    (lambda c: c.__setitem__(2, ""), r"line \d+, column '\w+' = '': must be a number"),
    (lambda c: c.append("1.0"), r"line \d+: (\d+) entries, the header has (\d+)"),
    (lambda c: c.__setitem__(0, "-170.5"), r"line \d+, column 'alpha_deg' = -170.5: alpha must rise"),
])
def test_bad_table_cells_name_line_and_column(tmp_path, edit, says):
    from laddermill_gym.ladder.scene_files import load_wing_type

    lines, h = _table_lines()
    cells = lines[h + 5].split(",")
    edit(cells)
    lines[h + 5] = ",".join(cells)
    path = _wing_copy(tmp_path, "\n".join(lines) + "\n")
    with pytest.raises(ConfigError, match=says):
        load_wing_type(path)


def test_empty_or_comment_only_table_is_named(tmp_path):
    from laddermill_gym.ladder.scene_files import load_wing_type

    path = _wing_copy(tmp_path, "# nothing but a comment\n\n")
    with pytest.raises(ConfigError, match="no header and no rows"):
        load_wing_type(path)


def test_missing_table_names_the_wing_field(tmp_path):
    from laddermill_gym.ladder.scene_files import load_wing_type

    path = _wing_copy(tmp_path, aero_table="nowhere.csv")
    with pytest.raises(ConfigError, match=r"w.yaml: field 'aero_table' = 'nowhere.csv': no such file"):
        load_wing_type(path)


@pytest.mark.parametrize("overrides, says", [
    ({"chain": {"piece_length": 1e308}}, r"field 'chain.piece_length' = 1e\+308: must be at most 1e\+12"),
    ({"wind": {"v0": 1e308}}, r"field 'wind.v0' = 1e\+308: must be at most"),
    ({"gravity": 1e308}, r"field 'gravity' = 1e\+308: must be at most"),
    ({"wind": {"v0": 0.0}}, r"field 'wind.v0' = 0.0: must be > 0"),
    ({"wind": {"rho0": 0.0}}, r"field 'wind.rho0' = 0.0: must be > 0"),
    ({"wind": {"v00": 1.0}}, r"unknown field 'wind.v00'"),
])
def test_overrides_are_checked_like_the_file(overrides, says):
    with pytest.raises(ConfigError, match=r"tethered_wing.yaml \(with overrides\): " + says):
        load_scene("tethered_wing", overrides=overrides)


def test_overrides_change_the_model_and_bad_counts_are_refused():
    assert load_scene("tethered_wing", overrides={"wind": {"v0": 10.0}}).assembly.wind.v0 == 10.0
    assert load_scene("ladder_chain", overrides={"chain": {"n_wings": 3}}).assembly.n_wings == 3
    with pytest.raises(ConfigError, match="n_wings = 0 \\(override\\): must be a whole number >= 1"):
        load_scene("ladder_chain", n_wings=0)


def test_an_impossible_equilibrium_names_the_file_and_the_settings():
    scene = load_scene("tethered_wing", overrides={"initial": {"alpha_deg": 89.0}})
    with pytest.raises(ConfigError, match=r"(?s)tethered_wing.yaml: no initial state .*alpha_deg = 89"):
        scene.initial_state()


@pytest.mark.parametrize("scene, dt", [("tethered_wing", 10.0), ("laddermill", 0.05), ("ladder_chain", 0.1)])
def test_a_step_that_cannot_work_is_refused_at_load(scene, dt):
    """Oracle: the stiffest element's axial frequency, sqrt(EA / l0 (1/m_r + 1/m_s)), and RK4's 2.83 bound; a step
    over twice that bound is refused naming the field, while the scenes' own steps load."""
    with pytest.raises(ConfigError, match=rf"field 'integrator.dt' = {dt!r} s with the overrides dt = {dt!r} cannot "
                                          r"work with RK4"):  # the override named: the file's own step is another
        load_scene(scene, dt=dt)
    load_scene(scene)


def test_the_step_bound_is_the_spring_mass_frequency():
    """ladder_chain's piece between two wings: k = EA / l0 = 21.6e6 / 70 N/m on two 54 kg wings, each with half of
    two 21 kg pieces: omega = sqrt(k (2 / 75)) = 90.7 rad/s, bound 2.83 / omega = 0.0312 s: 0.062 s loads, 0.063 s
    does not."""
    load_scene("ladder_chain", dt=0.062)
    with pytest.raises(ConfigError, match=r"oscillates at 90.7\d rad/s"):
        load_scene("ladder_chain", dt=0.063)


@pytest.mark.parametrize("dt", [0.0, -0.005, float("nan")])
def test_a_scene_step_that_makes_no_progress_is_refused(dt):
    """dt = 0 made no progress and dt < 0 integrated backwards (issue 13): refused at load, naming the field."""
    with pytest.raises(ValueError, match=r"IntegratorSettings.dt = .*must be a finite number > 0 \[s\]"):
        load_scene("tethered_wing", dt=dt)


def test_an_env_physics_step_of_zero_is_refused():
    import gymnasium as gym

    import laddermill_gym  # noqa: F401  (registers the ids)

    with pytest.raises(ValueError, match=r"dt = 0.0: must be a finite number > 0"):
        gym.make("laddermill_gym/TetheredWing-v0", physics_dt=0.0)
