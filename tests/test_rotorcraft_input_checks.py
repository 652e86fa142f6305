"""The rotorcraft's inputs, from a review: a craft file edited during a session, the trim-power check against a fixed
reference power, the blade-limit refusal's collective and wind, the craft config's differential limits and design
pitch, the autorotation search's collective range, and the files the modules' docstrings cite.

Oracles: the edited file's own values and a trim computed here without any cache; the trim's power read from a
simulator at the trim; the blade-limited collective found here by bisection on trims (the tip incidence against the
rotor file's 13 deg); the files on disk.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import gymnasium as gym
import numpy as np
import pytest
import yaml

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym.envs.rotorcraft.trim import craft_config, craft_trim
from laddermill_gym.model import disk_cache
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.rotorcraft.config import CRAFT_CONFIG_DIR, load_craft_config
from laddermill_gym.rotorcraft.craft import CraftSimulator, load_craft

ROOT = Path(__file__).resolve().parent.parent
V1 = "laddermill_gym/Rotorcraft-v1"
ROTOR = ROOT / "configs/rotors/roberts_rotor.yaml"
LIMIT = math.radians(yaml.safe_load(ROTOR.read_text())["blade_incidence_limit_deg"])


def _craft_file(tmp_path: Path, name: str = "craft.yaml", **changes) -> Path:
    """The shipped craft, its rotor and cable as package data, with ``changes`` (``tethers__x``: a tether field)."""
    data = yaml.safe_load((CRAFT_CONFIG_DIR / "roberts_flying_model.yaml").read_text())
    data["rotor"], data["tethers"]["cable"] = "package:rotors/roberts_rotor.yaml", "package:cables/kevlar_2p5mm.yaml"
    for key, value in changes.items():
        head, _, leaf = key.rpartition("__")
        (data[head] if head else data)[leaf] = value
    p = tmp_path / name
    p.write_text(yaml.safe_dump(data))
    return p


def _tip(craft, collective: float) -> float:
    x = craft.trim(collective)
    s = CraftSimulator(craft.config, craft.assembly, craft.layout, x, np.array([collective, 0.0]))
    return float(np.max(s.rotor_outputs()["tip_incidence_rad"]))


def test_a_craft_file_edited_in_a_session_is_read_again(tmp_path, monkeypatch):
    monkeypatch.setenv(disk_cache.CACHE_VARIABLE, disk_cache.OFF)  # the in-process caches only
    p = _craft_file(tmp_path)
    assert craft_config(str(p)).fin_area == 0.15
    _, x_before, _ = craft_trim(str(p))
    _craft_file(tmp_path, fin_area=0.4, drag_area=0.6)  # the fins: lateral only; the drag moves the trim
    assert craft_config(str(p)).fin_area == 0.4 and craft_config(str(p)).drag_area == 0.6
    _, x_after, u = craft_trim(str(p))
    oracle = load_craft(p).trim(u[0])  # the edited file, no cache
    assert x_after.tobytes() == oracle.tobytes() and x_after.tobytes() != x_before.tobytes()
    assert craft_trim(str(p))[1] is x_after  # unchanged file: the cached trim


def test_a_fixed_reference_power_lets_a_trim_that_takes_power_fly():
    """5 m/s at 8 deg of collective: the trim takes power from the ground (helicopter mode); the env needs a positive
    trim power only as the reward's reference, so a fixed reference flies it."""
    c = load_craft(config=load_craft_config().with_wind_speed(5.0))
    th = math.radians(8.0)
    x = c.trim(th)
    power = CraftSimulator(c.config, c.assembly, c.layout, x, np.array([th, 0.0])).electrical_power()
    assert power < 0.0
    with pytest.raises(ValueError, match=r"no positive power \(-?[\d.]+ W\).*reference_power_W"):
        gym.make(V1, wind_speed=5.0, collective=th)
    env = gym.make(V1, wind_speed=5.0, collective=th, reward={"reference_power_W": 1600.0})
    assert env.unwrapped.task.p_ref == 1600.0
    env.reset(seed=0)
    _, reward, terminated, _, info = env.step(env.unwrapped.task.trim_action)
    assert np.isfinite(reward) and not terminated and info["power_W"] == pytest.approx(power, rel=0.05)
    env.close()


def test_the_blade_limit_refusal_names_the_limited_collective_below_the_requested_one_and_the_wind():
    """8 deg at the default 10 m/s puts the tip past 13 deg: the refusal names the wind used and the collective that
    puts the tip at the limit, found here by bisection on trims (the config's 4 deg is inside the limit)."""
    th = math.radians(8.0)
    with pytest.raises(ValueError, match=r"at wind_speed = 10\.0 m/s, collective = 0\.139\d* rad.*pass collective <= ")\
            as err:
        gym.make(V1, collective=th)
    said = float(str(err.value).split("pass collective <= ")[1].split(" rad")[0])
    craft = load_craft()
    lo, hi = math.radians(4.0), th
    assert _tip(craft, lo) < LIMIT < _tip(craft, hi)
    while hi - lo > 1e-6:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _tip(craft, mid) < LIMIT else (lo, mid)
    assert said == pytest.approx(lo, abs=2e-5) and said > math.radians(4.0) + 0.03


@pytest.mark.parametrize("changes, field, why", [
    ({"differential_limits_deg": [1.0, 5.0]}, r"differential_limits_deg' = \[1\.0, 5\.0\]", "must hold 0"),
    ({"differential_limits_deg": [-5.0, -1.0]}, r"differential_limits_deg' = \[-5\.0, -1\.0\]", "must hold 0"),
    ({"tethers__design_pitch_deg": 200.0}, r"tethers\.design_pitch_deg' = 200\.0", r"must lie in \(-90, 90\) deg"),
    ({"tethers__design_pitch_deg": -90.0}, r"tethers\.design_pitch_deg' = -90\.0", r"must lie in \(-90, 90\) deg"),
])
def test_the_craft_config_names_its_file_and_field(tmp_path, changes, field, why):
    p = _craft_file(tmp_path, **changes)
    with pytest.raises(ConfigError, match=rf"craft\.yaml: field '{field}: {why}"):
        load_craft_config(p)
    with pytest.raises(ValueError, match=rf"craft\.yaml: field '{field}"):
        gym.make("laddermill_gym/Rotorcraft-v0", craft=str(p))
    assert load_craft_config(_craft_file(tmp_path, "ok.yaml", differential_limits_deg=[0.0, 5.0],
                                         tethers__design_pitch_deg=-30.0)).tethers.design_pitch == math.radians(-30.0)


def test_the_autorotation_search_names_a_reversed_collective_range():
    from laddermill_gym.rotorcraft.rotor import load_rotor_config
    from laddermill_gym.rotorcraft.rotor_limits import min_autorotation_angle

    params = load_rotor_config(ROTOR).params
    angle, theta = min_autorotation_angle(params, 0.1)
    assert 0.0 < angle < math.pi / 2 and -0.07 < theta < 0.21
    for bad in ((0.2, -0.07), (0.1, 0.1), (0.1,)):
        with pytest.raises(ValueError, match=r"argument 'theta_range' = "):
            min_autorotation_angle(params, 0.1, bad)


def test_the_modules_cite_files_that_exist():
    """Every ``folder/file.py`` a rotorcraft module names is a file of the package (or of the repository)."""
    missing = []
    for module in sorted((ROOT / "laddermill_gym" / "rotorcraft").glob("*.py")) + sorted(
            (ROOT / "laddermill_gym" / "envs" / "rotorcraft").glob("*.py")):
        for cited in re.findall(r"\b((?:[a-z_]+/)+[a-z_]+\.py)\b", module.read_text()):
            if not any((base / cited).is_file() for base in (ROOT / "laddermill_gym", ROOT)):
                missing.append(f"{module.name}: {cited}")
    assert missing == []
