"""The python-control plant of every vehicle and station (``control/plant.py``, issue 34 item 16): Roberts'
rotorcraft (``plant_system(craft, ...)`` failed), the moving-cable mill (its station block as states, the generator
as outputs) and the pumping kite's winch, with named states, inputs (wind disturbances included) and outputs.

Oracles:

* dynamics: the rate of the plant's states along the simulator's own trajectory, a central difference of states
  mapped by ``minimal_from_full`` from two RK4 steps (+h and -h, written here) of the full-state right-hand side,
  with the disturbance set through the simulator's own ``set_wind`` path (a packed WindField); the plant instead
  converts the full derivative with the closed-form kinematics of ``minimal_derivative``;
* the craft's outputs: the Rotorcraft-v0 environment's first observation (its compiled observation kernel; the plant
  reads the same quantities in Python from the minimal coordinates, ``rotor_outputs`` and ``tether_tensions``);
* the mill's and the winch's station outputs: closed forms, the speed schedule's V_c(t) = 2 m/s t / 30 s (the
  laddermill scene's ramp), eta (T_first - T_last) V_c and eta T_0 V with the tensions read at the state;
* the names: python-control's ``linearize`` with ``copy_names=True`` keeps them, without it they are ``x[i]``.
"""

from __future__ import annotations

import control
import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the ids)
from laddermill_gym import load_scene
from laddermill_gym.atmosphere.field import WindField
from laddermill_gym.control.linearize import minimal_from_full
from laddermill_gym.control.plant import (
    CRAFT_OUTPUT_NAMES,
    DISTURBANCE_NAMES,
    MILL_OUTPUT_NAMES,
    STATION_STATE_NAMES,
    WINCH_OUTPUT_NAMES,
    plant_system,
)
from laddermill_gym.envs.pumping.winch_scene import load_pumping
from laddermill_gym.kernels.contract import B3_RATE, B3_VEL, SX_MOVED

DIST = (0.05, 0.02)  # speed factor deviation [-], direction offset [rad] for the disturbed checks


def rk4(f, t, x, h):
    k1 = f(t, x)
    k2 = f(t + h / 2, x + h / 2 * k1)
    k3 = f(t + h / 2, x + h / 2 * k2)
    k4 = f(t + h, x + h * k3)
    return x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)


def trajectory_rate(sim, x, u, t, h=1e-5):
    """d/dt of the plant's states (minimal coordinates, then the station block) along the simulator's trajectory
    through (t, x) under the controls u and the simulator's wind: central differences of RK4 steps (+-h, +-h/2),
    Richardson-extrapolated: the tethers' stiff modes make the O(h^2) term 5e-5 at h = 1e-5, extrapolated 6e-8)."""
    asm = sim.assembly

    def states(xx):
        return np.concatenate([minimal_from_full(asm, xx), xx[asm.body_state_size:]])

    def f(tt, xx):
        return sim.rhs(tt, xx, u)

    def central(step):
        return (states(rk4(f, t, x, step)) - states(rk4(f, t, x, -step))) / (2 * step)

    return (4 * central(h / 2) - central(h)) / 3


def check_dynamics(plant, sim, x, u, t=0.0):
    """The plant's dz/dt at (x, u + DIST) against the simulator's trajectory with the same wind."""
    z = np.concatenate([minimal_from_full(sim.assembly, x), x[sim.assembly.body_state_size:]])
    got = plant.dynamics(t, z, np.concatenate([u, DIST]))
    sim.set_wind(WindField(speed=np.array([1.0 + DIST[0]]), direction=np.array([DIST[1]])))
    want = trajectory_rate(sim, x, u, t)
    scale = np.maximum(np.abs(want), 1e-3 * np.max(np.abs(want)))
    assert np.max(np.abs(got - want) / scale) < 1e-6, np.argmax(np.abs(got - want) / scale)
    return got


# ---------------------------------------------------------------- the rotorcraft
@pytest.fixture(scope="module")
def craft_env():
    env = gym.make("laddermill_gym/Rotorcraft-v0", disturbances=[])
    obs, _ = env.reset(seed=0)
    return env, obs


def test_craft_plant_outputs_are_the_envs_observation(craft_env):
    """The reproducer, ``plant_system(craft, x, u)``, with the craft the env flies: its outputs at the trim are the
    env's first observation, named by the env's fields."""
    env, obs = craft_env
    task = env.unwrapped.task
    plant = plant_system(task.craft, task.x_trim, task.u_trim)
    assert plant.output_labels == list(CRAFT_OUTPUT_NAMES) and len(CRAFT_OUTPUT_NAMES) == obs.size
    assert plant.input_labels == ["collective", "differential", *DISTURBANCE_NAMES]
    assert plant.state_labels[:4] == ["wing0_x", "wing0_y", "wing0_z", "wing0_phi"] and plant.nstates == \
        12 + 6 * task.craft.assembly.n_nodes
    y = plant.output(0.0, plant.z0, plant.u0)
    np.testing.assert_allclose(y, obs, rtol=2e-6, atol=2e-6)  # the env's observation is float32
    assert abs(y[CRAFT_OUTPUT_NAMES.index("craft_pitch_right")] - task.u_trim[0]) < 1e-12  # no differential


def test_craft_plant_dynamics_follow_the_simulator(craft_env):
    env, _ = craft_env
    task = env.unwrapped.task
    rng = np.random.default_rng(1)
    x = np.array(task.x_trim)
    x[B3_VEL: B3_VEL + 3] += 0.3 * rng.standard_normal(3)
    x[B3_RATE: B3_RATE + 3] += 0.05 * rng.standard_normal(3)
    u = np.array(task.u_trim) + np.array([0.0, 0.01])
    plant = plant_system(task.craft, task.x_trim, task.u_trim, outputs="states")
    check_dynamics(plant, task.simulator(0), x, u)
    # the differential collective and the wind direction move the lateral states (the LQR's inputs)
    lin = control.linearize(plant, plant.z0, plant.u0, copy_names=True)
    assert lin.state_labels == plant.state_labels and lin.input_labels == plant.input_labels
    i_vy, i_p = plant.state_labels.index("wing0_vy"), plant.state_labels.index("wing0_p")
    assert abs(lin.B[i_p, 1]) > 0 and abs(lin.B[i_vy, 3]) > 0


# ---------------------------------------------------------------- the mill
@pytest.fixture(scope="module")
def mill():
    return load_scene("laddermill", n_wings=4, dt=0.0125)


def test_mill_plant_has_the_station_as_states_and_outputs(mill):
    sim = mill.simulator()
    t, x, u = 6.0, sim.state.copy(), sim.controls.copy()
    x[mill.assembly.body_state_size + SX_MOVED] = 0.5  # cable moved since the last transfer [m]
    plant = plant_system(mill, x, u)
    assert plant.state_labels[-4:] == list(STATION_STATE_NAMES) and plant.output_labels[-4:] == list(MILL_OUTPUT_NAMES)
    assert plant.noutputs == 15 * 4 + 4 and plant.name == "laddermill"
    y = plant.output(t, plant.z0, plant.u0)
    v = 2.0 * t / 30.0  # the scene's prescribed ramp: 0 to 2 m/s over 30 s
    ref = mill.simulator(x, u)
    ref.t = t
    ten = ref.tensions()
    eta = mill.assembly.station.efficiency
    np.testing.assert_allclose(y[-4:], [v, 0.5 / 70.0, ten[0] - ten[-1], eta * (ten[0] - ten[-1]) * v],
                               rtol=1e-12, atol=1e-9)
    dz = check_dynamics(plant_system(mill, x, u, outputs="states"), mill.simulator(x, u), x, u, t)
    assert dz[-4] == pytest.approx(v, rel=1e-12)  # d(moved)/dt = V_c


def test_plant_names_survive_linearize_only_with_copy_names(mill):
    plant = plant_system(mill)
    lin = control.linearize(plant, plant.z0, plant.u0, copy_names=True)
    assert (lin.state_labels, lin.input_labels, lin.output_labels) == \
        (plant.state_labels, plant.input_labels, plant.output_labels)
    bare = control.linearize(plant, plant.z0, plant.u0)
    assert bare.state_labels[0] == "x[0]"  # python-control's default drops them (hence copy_names=True)


# ---------------------------------------------------------------- the pumping kite's winch
def test_winch_plant_outputs_and_dynamics():
    pk = load_pumping()
    sim = pk.simulator()
    x, u = sim.state.copy(), sim.controls.copy()
    plant = plant_system(pk, x, u)
    assert plant.output_labels[-3:] == list(WINCH_OUTPUT_NAMES) and plant.name == "pumping_kite"
    assert plant.state_labels[-4:] == list(STATION_STATE_NAMES)
    y = plant.output(0.0, plant.z0, plant.u0)
    t0, v = sim.tensions()[0], sim.cable_speed()
    eta = pk.winch.efficiency
    assert y[-3:-1] == pytest.approx([t0, v], rel=1e-12)
    assert y[-1] == pytest.approx(eta * t0 * v if t0 * v >= 0 else t0 * v / eta, rel=1e-12)
    check_dynamics(plant_system(pk, x, u, outputs="states"), pk.simulator(x, u), x, u)


def test_unknown_system_is_refused():
    with pytest.raises(TypeError, match="not a wing scene.*craft.*pumping"):
        plant_system(object())
