"""Scene values that once loaded and failed later, naming no field (issue 34 items 2, 3, 5 and 14), are refused at
load with the file, the field and the value; the physical bounds of ``ladder/bounds.py``."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import ConfigError


def test_two_wings_on_a_free_end_with_trim_are_refused_clearly():
    """Item 2: tethered_wing with n_wings: 2 gave numpy's "operands could not be broadcast together"."""
    with pytest.raises(ConfigError, match=r"tethered_wing.yaml \(with overrides\): field 'chain.n_wings' = 2: "
                                          r"initial.method 'trim' trims exactly one wing"):
        load_scene("tethered_wing", overrides={"chain": {"n_wings": 2}})
    with pytest.raises(ConfigError, match=r"n_wings = 3 \(override\): initial.method 'trim'"):
        load_scene("tethered_wing", n_wings=3)


def test_two_wings_on_a_free_end_start_at_rest():
    """Item 2, the other half: the layout of a chain with a free upper end and two wings (it broadcast the pieces
    against one piece too many) now starts; the static solve accepts only a state at rest (RMS acceleration below
    1e-6 m/s^2), and the upper wing flies above the lower one."""
    sc = load_scene("tethered_wing", n_wings=2, elements_per_piece=1, overrides={"initial": {"method": "static"}})
    x, u = sc.initial_state()
    z = x[[2, 15]]  # the two wings' z [m] (13 states each, position first)
    assert np.all(np.isfinite(x)) and u.shape == (6,)
    assert z[1] < z[0] < -50.0  # both up (z down), the second higher


@pytest.mark.parametrize("overrides, says", [
    ({"chain": {"piece_length": 1.0e12}}, r"field 'chain.piece_length' = 1000000000000.0: longer than the cable's "
                                          r"breaking length F_b / \(mu g\) = 1.785e\+05 m"),
    ({"chain": {"piece_length": 2.0e5}}, r"field 'chain.piece_length' = 200000.0: longer than the cable's breaking"),
    ({"initial": {"elevation_deg": 400}}, r"field 'initial.elevation_deg' = 400: must be at most 90"),
    ({"initial": {"elevation_deg": 0}}, r"field 'initial.elevation_deg' = 0: must be > 0"),
    ({"initial": {"alpha_deg": -120.0}}, r"field 'initial.alpha_deg' = -120.0: must be between -90 and 90"),
    ({"integrator": {"dt": 1.0e-12}}, r"field 'integrator.dt' = 1e-12: must be between 1e-09 and 1"),
    ({"wind": {"v0": 1.0e6}}, r"field 'wind.v0' = 1000000.0: must be at most 150"),
    ({"gravity": 98.0}, r"field 'gravity' = 98.0: must be at most 25"),
    ({"ground_points": {"station": [0.0, 0.0, -1.0e6]}}, r"field 'ground_points.station' = \[0.0, 0.0, -1000000.0\]"),
])
def test_out_of_range_values_are_refused_at_load(overrides, says):
    """Items 3 and 5: piece_length 1e12 loaded and failed later as "state[0] is not finite: nan"; dt 1e-12 set up
    1e12 steps; elevation_deg 400 was accepted."""
    with pytest.raises(ConfigError, match=r"tethered_wing.yaml \(with overrides\): " + says):
        load_scene("tethered_wing", overrides=overrides)


def test_a_chain_of_more_cable_than_the_atmosphere_names_n_wings():
    """Oracle: 2000 pieces of 70 m are 140 km of cable, beyond the Karman line (100 km); 1400 pieces are 98 km."""
    with pytest.raises(ConfigError, match=r"field 'chain.n_wings' = 2000: 2001 pieces of chain.piece_length = 70 m "
                                          r"are 1.401e\+05 m of cable, more than 100000 m"):
        load_scene("ladder_chain", overrides={"chain": {"n_wings": 2000}})
    with pytest.raises(ConfigError, match="dt = 1e-12 \\(override\\): must be between 1e-09 and 1"):
        load_scene("ladder_chain", dt=1e-12)


def test_an_elevator_beyond_the_wing_limits_is_refused():
    with pytest.raises(ConfigError, match=r"field 'initial.elevator_up_deg' = -40.0: must be between -15 and 15 "
                                          r"\(deg: the wing's control_limits_deg.elevator\)"):
        load_scene("ladder_chain", overrides={"initial": {"elevator_up_deg": -40.0}})


def test_physical_consistency_of_wing_and_cable(tmp_path):
    """A cable denser than osmium, stiffer than graphene; a wing whose inertia no body has; oracles: the numbers
    (0.3 kg/m on 2.5 mm: 61,000 kg/m^3; Jxx 3000 > Jyy + Jzz = 1810.9 kg m^2)."""
    import shutil

    from laddermill_gym.model.configio import CONFIG_DIR

    for kind in ("scenes", "wings", "cables"):
        shutil.copytree(CONFIG_DIR / kind, tmp_path / kind)
    cable = tmp_path / "cables" / "dyneema_25mm.yaml"
    text = cable.read_text()
    cable.write_text(text.replace("diameter: 0.025 ", "diameter: 0.0025 "))
    with pytest.raises(ConfigError, match=r"dyneema_25mm.yaml: field 'mass_per_length' = 0.3: its density .* is "
                                          r"6.112e\+04 kg/m\^3, must be between 100 and 23000"):
        load_scene(tmp_path / "scenes" / "tethered_wing.yaml")
    cable.write_text(text.replace("EA: 2.16e+7 ", "EA: 2.16e+11 "))
    with pytest.raises(ConfigError, match=r"field 'EA' = 216000000000.0: its modulus .* is 4.4e\+14 Pa"):
        load_scene(tmp_path / "scenes" / "tethered_wing.yaml")
    cable.write_text(text)
    wing = tmp_path / "wings" / "meijaard_wing.yaml"
    wing.write_text(wing.read_text().replace("Jxx: 1324.9 ", "Jxx: 3000.0 "))
    with pytest.raises(ConfigError, match=r"meijaard_wing.yaml: field 'inertia.Jzz' = 1565.6: no rigid body|"
                                          r"meijaard_wing.yaml: field 'inertia.Jxx' = 3000.0: no rigid body"):
        load_scene(tmp_path / "scenes" / "tethered_wing.yaml")


def test_shipped_configs_are_found_by_bare_name_and_outside_a_checkout(tmp_path, monkeypatch):
    """Item 14: ``laddermill train configs/agents/ppo_tethered_wing.yaml`` outside a checkout, and the bare name."""
    from laddermill_gym.model.configio import CONFIG_DIR, config_path, find_config

    monkeypatch.chdir(tmp_path)
    shipped = CONFIG_DIR / "agents" / "ppo_tethered_wing.yaml"
    for given in ("configs/agents/ppo_tethered_wing.yaml", "ppo_tethered_wing", "ppo_tethered_wing.yaml"):
        assert find_config("agents", given) == shipped
    assert config_path("scenes", "elsewhere/configs/scenes/tethered_wing.yaml").parent.name == "scenes"
    assert not config_path("scenes", "elsewhere/configs/scenes/tethered_wing.yaml").is_file()  # only configs/...
    (tmp_path / "configs" / "agents").mkdir(parents=True)
    own = tmp_path / "configs" / "agents" / "ppo_tethered_wing.yaml"
    own.write_text("algorithm: PPO\n")
    assert find_config("agents", "configs/agents/ppo_tethered_wing.yaml").resolve() == own  # a user's own first
    with pytest.raises(ConfigError, match=r"config = 'nosuch': .*nosuch.yaml: no such file \(a bare name is one of "
                                          r"the shipped agents: .*ppo_tethered_wing"):
        find_config("agents", "nosuch", "config")
