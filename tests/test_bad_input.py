"""Invalid scene files and exploding states are reported with the file, field and value (or the time,
body and quantity), never propagated silently."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError
from laddermill_gym.sim.simulator import SimulationError


@pytest.fixture()
def scene_copy(tmp_path):
    """A writable copy of configs/ so tests can break one field at a time."""
    dst = tmp_path / "configs"
    shutil.copytree(CONFIG_DIR, dst)

    def edit(relpath: str, dotted: str, value, delete: bool = False) -> Path:
        p = dst / relpath
        data = yaml.safe_load(p.read_text())
        node = data
        keys = dotted.split(".")
        for k in keys[:-1]:
            node = node[k]
        if delete:
            del node[keys[-1]]
        else:
            node[keys[-1]] = value
        p.write_text(yaml.safe_dump(data))
        return dst / "scenes" / "tethered_wing.yaml"

    return edit


@pytest.mark.parametrize("relpath,field,value,needle", [
    ("scenes/tethered_wing.yaml", "chain.piece_length", -5.0, "chain.piece_length"),
    ("scenes/tethered_wing.yaml", "chain.piece_length", 0.0, "must be > 0"),
    ("scenes/tethered_wing.yaml", "wind.v0", float("nan"), "wind.v0"),
    ("scenes/tethered_wing.yaml", "wind.rho0", -1.0, "wind.rho0"),
    ("scenes/tethered_wing.yaml", "chain.n_wings", 1.5, "chain.n_wings"),
    ("scenes/tethered_wing.yaml", "chain.start", "nowhere", "chain.start"),
    ("scenes/tethered_wing.yaml", "ground_points.station", [0.0, 1.0], "ground_points.station"),
    ("scenes/tethered_wing.yaml", "integrator.dt", float("inf"), "integrator.dt"),
    ("scenes/tethered_wing.yaml", "fidelity.sag", "yes", "fidelity.sag"),
    ("scenes/tethered_wing.yaml", "integrator.method", "euler", "integrator.method"),
    ("wings/meijaard_wing.yaml", "mass", 0.0, "mass"),
    ("wings/meijaard_wing.yaml", "inertia.Jxx", -3.0, "inertia.Jxx"),
    ("wings/meijaard_wing.yaml", "attachment", [1.0, 2.0], "attachment"),
    ("wings/meijaard_wing.yaml", "control_limits_deg.elevator", [10.0, -10.0], "control_limits_deg.elevator"),
    ("cables/dyneema_25mm.yaml", "EA", -1.0, "EA"),
    ("cables/dyneema_25mm.yaml", "mass_per_length", 0.0, "mass_per_length"),
])
def test_invalid_value_names_file_field_and_value(scene_copy, relpath, field, value, needle):
    path = scene_copy(relpath, field, value)
    with pytest.raises(ConfigError) as err:
        load_scene(path)
    msg = str(err.value)
    assert needle in msg
    assert Path(relpath).name in msg
    assert repr(value) in msg or str(value) in msg


def test_unknown_key_is_rejected(scene_copy):
    path = scene_copy("scenes/tethered_wing.yaml", "wind.v0_typo", 3.0)
    with pytest.raises(ConfigError, match=r"unknown field 'wind.v0_typo'"):
        load_scene(path)


def test_missing_key_is_rejected(scene_copy):
    path = scene_copy("scenes/tethered_wing.yaml", "gravity", None, delete=True)
    with pytest.raises(ConfigError, match="missing field 'gravity'"):
        load_scene(path)


def test_bad_aero_table_is_rejected(scene_copy, tmp_path):
    path = scene_copy("scenes/tethered_wing.yaml", "name", "tethered_wing")
    table = path.parent.parent / "wings" / "meijaard_wing_aero.csv"
    lines = table.read_text().splitlines()
    i = next(j for j, ln in enumerate(lines) if ln and ln[0] not in "#a")
    parts = lines[i].split(",")
    parts[3] = "nan"
    lines[i] = ",".join(parts)
    table.write_text("\n".join(lines))
    with pytest.raises(ConfigError, match="meijaard_wing_aero.csv.*must be finite"):
        load_scene(path)


def test_exploding_state_is_reported_with_time_body_and_quantity():
    """A step past the stable one on a stiff cable (25 ms; stable up to 19 ms) makes RK4 blow up: the error names the
    time and a wing or element. (A step that cannot work at all, 0.2 s, is refused at load: test_config_defects.)"""
    scene = load_scene("tethered_wing", dt=0.025)
    x0, u0 = scene.initial_state()
    sim = scene.simulator(x0, u0)
    with pytest.raises(SimulationError) as err:
        sim.step(n_steps=200)
    msg = str(err.value)
    assert "t = " in msg and ("wing" in msg or "element" in msg or "node" in msg)
    assert np.all(np.isfinite(sim.state)), "the state is left at the last good step"


def test_bad_controls_and_state_are_rejected():
    scene = load_scene("tethered_wing")
    sim = scene.simulator()
    with pytest.raises(ValueError, match="wing 0 elevator"):
        sim.step(controls=np.array([3.0, 0.0, 0.0]))
    with pytest.raises(ValueError, match="state"):
        sim.reset(state=np.zeros(3))
    bad = sim.state.copy()
    bad[2] = np.nan
    with pytest.raises(ValueError, match=r"state\[2\]"):
        sim.reset(state=bad)


def test_nan_inside_the_kernels_is_caught():
    """The kernels are compiled with fastmath flags that keep NaN/Inf semantics (no 'nnan'/'ninf'): a NaN
    written straight into the state (bypassing reset's validation) is still detected by the integrator."""
    scene = load_scene("tethered_wing")
    sim = scene.simulator()
    sim.state[9] = np.nan  # a body velocity component
    with pytest.raises(SimulationError, match="t = "):
        sim.step(n_steps=3)
