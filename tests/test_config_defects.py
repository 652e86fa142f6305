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
