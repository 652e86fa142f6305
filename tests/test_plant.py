"""The python-control plant (``control/plant.py``, issue 17 point 5): minimal coordinates (no pole at the quaternion
norm), the environments' observation as output, wind disturbance inputs and a parameter that changes the model.

Oracles: the TetheredWing-v0 env's own first observation (its batched kernel path) for the output; the simulator's
``set_wind`` path (a packed WindField) for the disturbance input and the parameter; the quaternion-norm pole of the
full-state linearisation, which the minimal plant must not have."""

from __future__ import annotations

import control
import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401
from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.control.plant import DISTURBANCE_NAMES, plant_system
from laddermill_gym.envs.task import scene_trim

TW = "laddermill_gym/TetheredWing-v0"


@pytest.fixture(scope="module")
def trimmed():
    sc, x, u = scene_trim("tethered_wing", (("elements_per_piece", 1),))
    return sc, np.array(x), np.array(u)


def test_output_is_the_envs_observation(trimmed):
    sc, x, u = trimmed
    plant = plant_system(sc, x, u)
    env = gym.make(TW, disturbances=[])
    obs, _ = env.reset(seed=0)
    y = plant.output(0.0, plant.z0, plant.u0)
    np.testing.assert_allclose(y, obs, rtol=2e-6, atol=2e-6)  # the env's observation is float32
    assert plant.noutputs == obs.size and plant.ninputs == u.size + len(DISTURBANCE_NAMES)


def test_linear_plant_has_no_quaternion_pole(trimmed):
    sc, x, u = trimmed
    plant = plant_system(sc, x, u)
    lin = control.linearize(plant, plant.z0, plant.u0)
    n = plant.nstates
    assert lin.A.shape == (n, n) and lin.B.shape == (n, u.size + 2) and lin.C.shape == (15, n)
    assert lin.D.shape == (15, u.size + 2)
    assert np.min(np.abs(np.linalg.eigvals(lin.A))) > 1e-3  # a tethered wing has no free mode
    full = control.linearize(control.nlsys(sc.simulator(x, u).rhs, None, states=x.size, inputs=u.size), x, u)
    assert np.min(np.abs(np.linalg.eigvals(full.A))) < 1e-6  # the trap the plant avoids
    d_dir = lin.B[:, u.size + 1]
    assert np.max(np.abs(d_dir)) > 0 and np.max(np.abs(lin.D[:, u.size + 1])) > 0  # wind moves states, alpha, beta


def test_disturbance_and_parameter_equal_a_packed_wind_field(trimmed):
    sc, x, u = trimmed
    plant = plant_system(sc, x, u, outputs="states")
    ud = plant.u0.copy()
    ud[-2], ud[-1] = 0.2, 0.03
    f_input = plant.dynamics(0.0, plant.z0, ud)
    f_param = plant.dynamics(0.0, plant.z0, np.concatenate([u, [0.0, 0.03]]), params={"wind_speed_factor": 1.2})
    ref = sc.simulator(x, u)
    ref.set_wind(WindField(speed=np.array([1.2]), direction=np.array([0.03])))
    from laddermill_gym.control.linearize import minimal_derivative

    f_ref = minimal_derivative(sc.assembly, x, ref.rhs(0.0, x, u))
    np.testing.assert_allclose(f_input, f_ref, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(f_param, f_ref, rtol=1e-12, atol=1e-9)
    assert not np.allclose(plant.dynamics(0.0, plant.z0, plant.u0), f_ref)
    with pytest.raises(ValueError, match="unknown \\['v0'\\]"):
        plant.dynamics(0.0, plant.z0, plant.u0, params={"v0": 10.0})


def test_full_state_rhs_refuses_parameters(trimmed):
    sc, x, u = trimmed
    sim = sc.simulator(x, u)
    sim.rhs(0.0, x, u, {})  # python-control passes an empty mapping
    with pytest.raises(ValueError, match=r"params \['v0'\] are not taken"):
        sim.rhs(0.0, x, u, {"v0": 10.0})
