"""The moving cable's station inputs and the generator's electrical power (a review of 2026-12-07).

Oracles: the scene file's own values (a commanded station starts at its first speed, a drum's torque inside its
limits), the closed form of a generator's efficiency (electrical = eta P generating, P / eta motoring), and the
error text naming the field and value.
"""

import numpy as np
import pytest

from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.station import electrical_power

SMALL = dict(n_wings=5, dimension=2)


def test_an_elements_per_piece_override_on_a_moving_cable_is_refused():
    with pytest.raises(ConfigError, match=r"elements_per_piece = 2 \(override\).*one element per piece"):
        load_scene("laddermill", n_wings=5, elements_per_piece=2, method="ros2")


@pytest.mark.parametrize("mode, extra, control", [
    ("commanded", {"speed_time_constant": 1.0, "speed_limits": [1.0, 3.0]}, 2.0),
    ("drum", {"drum_radius": 1.0, "drum_inertia": 1000.0, "torque_limits": [1000.0, 20000.0]}, 1000.0),
    ("drum", {"drum_radius": 1.0, "drum_inertia": 1000.0, "torque_limits": [-5.0, 20000.0]}, 0.0),
])
def test_a_station_with_a_control_starts_inside_its_limits(mode, extra, control):
    st = {"mode": mode, "speed_times_s": [0.0], "speed_m_s": [2.0], **extra}
    sim = load_scene("laddermill", **SMALL, overrides={"station": st}).simulator()  # refused before: control 0
    assert sim.controls[-1] == control
    assert sim.cable_speed() == 2.0


def test_a_commanded_first_speed_outside_the_limits_and_a_schedule_without_one_are_refused():
    st = {"mode": "commanded", "speed_times_s": [0.0], "speed_m_s": [5.0], "speed_time_constant": 1.0,
          "speed_limits": [1.0, 3.0]}
    with pytest.raises(ConfigError, match=r"speed_m_s.*\[5\.0\].*within speed_limits \[1, 3\]"):
        load_scene("laddermill", **SMALL, overrides={"station": st})
    st = {"mode": "drum", "drum_radius": 1.0, "drum_inertia": 1000.0, "torque_limits": [-1e5, 1e5],
          "speed_times_s": [0.0, 30.0], "speed_m_s": [0.0, 2.0]}
    with pytest.raises(ConfigError, match=r"speed_times_s.*drum station takes only its initial speed"):
        load_scene("laddermill", **SMALL, overrides={"station": st})


def test_a_turning_wind_names_the_field_for_the_in_plane_mill():
    with pytest.raises(ConfigError, match=r"wind\.direction_inf_rad = 0\.1 \(must be 0"):
        load_scene("laddermill", **SMALL, overrides={"wind": {"direction_inf_rad": 0.1}})


def test_electrical_power_divides_by_the_efficiency_while_motoring():
    mech = np.array([-2000.0, 0.0, 3000.0])
    assert electrical_power(mech, 0.8).tolist() == [-2500.0, 0.0, 2400.0]
    assert electrical_power(-2000.0, 0.8) == -2500.0 and electrical_power(3000.0, 0.8) == 2400.0
    assert electrical_power(mech, 1.0).tolist() == mech.tolist()  # the shipped scenes' efficiency: unchanged


def test_the_simulators_generator_reading_converts_a_motoring_power():
    st = {"efficiency": 0.5, "speed_times_s": [0.0], "speed_m_s": [1.0]}  # the cable pulled at rest: motoring
    sim = load_scene("laddermill", **SMALL, overrides={"station": st}).simulator()
    sim.step(n_steps=10)
    p = sim.generator_power()
    assert p["mechanical_W"] < 0.0
    assert p["electrical_W"] == pytest.approx(p["mechanical_W"] / 0.5, rel=1e-15)
