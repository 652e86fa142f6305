"""In-process caches notice an edited input file (a review of 2026-12-07: the scene's trim, the mill's and the
point-mass starts and the craft's rotor file were cached on the file's name, so an edit was ignored for the session).

Oracles: a fresh ``load_scene`` / ``load_craft_config`` of the edited file (no cache), and the number of calls the
cached function makes.
"""

import re
import shutil
from pathlib import Path

import pytest

from laddermill_gym.envs.rotorcraft.trim import craft_config
from laddermill_gym.envs.task import scene_trim
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import read_yaml
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.rotorcraft.config import load_craft_config

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


@pytest.fixture
def configs(tmp_path):
    """A copy of the shipped configs (scenes, wings, cables, rotors, rotorcraft), relative references intact."""
    for part in ("scenes", "wings", "cables", "rotors", "rotorcraft"):
        shutil.copytree(CONFIGS / part, tmp_path / part)
    return tmp_path


def test_a_cached_call_is_made_again_when_a_file_it_read_changes_and_not_otherwise(tmp_path):
    inner_file, outer_file = tmp_path / "inner.yaml", tmp_path / "outer.yaml"
    inner_file.write_text("a: 1\n")
    outer_file.write_text("b: 2\n")
    calls = []

    @input_cache(maxsize=2)
    def inner(path):
        calls.append("inner")
        return read_yaml(path).data["a"]

    @input_cache(maxsize=2)
    def outer(path):
        calls.append("outer")
        return inner(str(inner_file)) + read_yaml(path).data["b"]

    assert outer(str(outer_file)) == 3 and outer(str(outer_file)) == 3
    assert calls == ["outer", "inner"]
    inner_file.write_text("a: 10\n")  # read by the nested call only: the outer result depends on it too
    assert outer(str(outer_file)) == 12
    assert calls == ["outer", "inner", "outer", "inner"]
    outer_file.write_text("b: 20\n")
    assert outer(str(outer_file)) == 30
    assert calls[-1] == "outer" and calls.count("inner") == 2  # the inner hit (its file unchanged) is not re-run


def test_an_edited_scene_file_reaches_the_next_env_in_the_session(configs):
    path = configs / "scenes" / "tethered_wing.yaml"
    text = path.read_text()
    first, _, _ = scene_trim(str(path), ())
    assert scene_trim(str(path), ())[0] is first  # unchanged: the cached trim
    path.write_text(re.sub(r"(\n\s*v0:\s*)8\.0", r"\g<1>10.0", text, count=1))
    edited, _, _ = scene_trim(str(path), ())
    assert edited.assembly.wind.v0 == load_scene(str(path)).assembly.wind.v0 == 10.0 != first.assembly.wind.v0


def test_an_edited_rotor_file_reaches_the_craft_config(configs):
    craft = str(configs / "rotorcraft" / "roberts_flying_model.yaml")
    rotor = configs / "rotors" / "roberts_rotor.yaml"
    first = craft_config(craft)
    text = rotor.read_text()
    sigma = re.search(r"\n\s*sigma:\s*([\d.]+)", text).group(1)
    rotor.write_text(text.replace(f"sigma: {sigma}", "sigma: 0.06", 1))
    edited = craft_config(craft)
    assert edited is not first and edited.rotor.sigma == load_craft_config(craft).rotor.sigma == 0.06


def test_a_relative_path_after_a_chdir_names_the_other_folder_s_file(tmp_path, monkeypatch):
    """The same relative craft path in two folders with different masses: after ``chdir`` the cache answered with
    the first folder's craft, trim and env (a review of 2026-12-08; the key was the path's text, and the files the
    first call read were unchanged). Oracle: a fresh ``load_craft_config`` in each folder."""
    rel = "rotorcraft/roberts_flying_model.yaml"
    for name, mass in (("a", 20.0), ("b", 25.0)):
        for part in ("rotorcraft", "rotors", "cables"):
            shutil.copytree(CONFIGS / part, tmp_path / name / part)
        craft = tmp_path / name / rel
        text, n = re.subn(r"\nmass: [\d.]+", f"\nmass: {mass}", craft.read_text(), count=1)
        assert n == 1
        craft.write_text(text)
    masses = []
    for name in ("a", "b", "a"):
        monkeypatch.chdir(tmp_path / name)
        masses.append((craft_config(rel).mass, load_craft_config(rel).mass))
    assert masses == [(20.0, 20.0), (25.0, 25.0), (20.0, 20.0)]


def test_the_spline_caches_hold_the_tables_used_last_only():
    """Keyed on the table object, they kept every table ever splined: a sweep of freshly loaded scenes grew by about
    160 kB a scene (a review of 2026-12-07). Oracle: the copies still alive once the test drops its own references."""
    import dataclasses
    import gc
    import weakref

    from laddermill_gym.reference.wing import aero_coefficients
    from laddermill_gym.sim.statics import SPLINES_KEPT, table_spline

    table = load_scene("tethered_wing").assembly.wing(0).aero
    alive = []
    for _ in range(40):
        copy = dataclasses.replace(table, values=table.values.copy())
        table_spline(copy)
        aero_coefficients(copy, 0.1)
        alive.append(weakref.ref(copy))
    del copy
    gc.collect()
    assert 0 < sum(r() is not None for r in alive) <= SPLINES_KEPT + 16  # the last ones, not all 40
