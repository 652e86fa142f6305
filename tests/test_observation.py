"""The wing observation has one implementation, the kernel ``kernels/rigid/observe.py``; these tests hold it to
an independent numpy computation written here from docs/model.md (quaternion -> rotation in the
Euler-Rodrigues form, the global velocity R v, 3-2-1 Euler angles straight from the quaternion, the wind of
Meijaard eqs. (1)-(2) with its time modulation, alpha and beta of the air velocity, the tension of the plain
numpy reference), and hold ``control.base.observe`` on a bare Simulator to the environment's own observation.
"""

from __future__ import annotations

import dataclasses

import gymnasium as gym
import numpy as np
import pytest

import laddermill_gym  # noqa: F401  (registers the env ids)
from laddermill_gym import reference as ref
from laddermill_gym.control.base import OBS_NAMES, observe
from laddermill_gym.envs.observation import N_OBS_PER_WING, OBS_FIELDS, OBS_INDEX
from laddermill_gym.envs.task import scene_trim
from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.contract import OK
from laddermill_gym.kernels.rigid.observe import (
    AUX_GROUND_END,
    AUX_GROUND_START,
    AUX_MAX_TENSION,
    AUX_MIN_ALTITUDE,
    N_AUX,
    observe_state,
)
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.states import (
    euler_from_quaternion,
    quaternion_from_euler,
    rotation_from_euler,
    rotations_from_quaternions,
)
from laddermill_gym.sim.simulator import Simulator


# ------------------------------------------------------------------------------------------- oracle
def _rotation(q: np.ndarray) -> np.ndarray:
    """R (3, 3) body -> global of a quaternion (scalar first), Euler-Rodrigues form
    R = (a^2 - |e|^2) I + 2 e e^T + 2 a [e]x of the normalised q = (a, e)."""
    q = q / np.linalg.norm(q)
    a, e = q[0], q[1:]
    cross = np.array([[0.0, -e[2], e[1]], [e[2], 0.0, -e[0]], [-e[1], e[0], 0.0]])
    return (a * a - e @ e) * np.eye(3) + 2.0 * np.outer(e, e) + 2.0 * a * cross


def _euler(q: np.ndarray) -> np.ndarray:
    """3-2-1 Euler angles (phi, theta, psi) [rad] directly from the normalised quaternion (no matrix)."""
    a, b, c, d = q / np.linalg.norm(q)
    return np.array([np.arctan2(2.0 * (a * b + c * d), 1.0 - 2.0 * (b * b + c * c)),
                     np.arcsin(np.clip(2.0 * (a * c - d * b), -1.0, 1.0)),
                     np.arctan2(2.0 * (a * d + b * c), 1.0 - 2.0 * (c * c + d * d))])


def _wind(wind, t: float, z: float) -> np.ndarray:
    """Wind velocity (3,) [m/s] at height h = -z and time t: docs/model.md, Meijaard eqs. (1)-(2) with the
    speed factor s(t) and direction offset delta(t) interpolated linearly and held outside the grid."""
    h = -z
    if h <= 0.0:
        speed = 0.0
    elif h < wind.h0:
        speed = wind.v0 * (h / wind.h0) ** wind.exponent
    else:
        speed = wind.v0 + wind.v1 * (h - wind.h0)
    turn = wind.direction_inf * (1.0 - np.exp(-h / wind.direction_height)) if h > 0.0 else 0.0
    grid = wind.mod_t0 + wind.mod_dt * np.arange(len(wind.mod_speed))
    s = np.interp(t, grid, wind.mod_speed)
    delta = np.interp(t, grid, wind.mod_direction)
    return -s * speed * np.array([np.cos(turn + delta), np.sin(turn + delta), 0.0])


def oracle(asm, t: float, x: np.ndarray, nominal: np.ndarray, below: np.ndarray, ground: np.ndarray):
    """(obs (n_wings * 15,), aux (N_AUX,)) of state x at time t, from first principles."""
    tension = ref.element_tensions(asm, t, x)
    rows = []
    for k in range(asm.n_wings):
        w = x[C.B3_SIZE * k: C.B3_SIZE * (k + 1)]
        pos, q, v, rates = w[0:3], w[3:7], w[7:10], w[10:13]  # docs/model.md: x, q, v (body), w (body)
        R = _rotation(q)
        air = v - R.T @ _wind(asm.wind, t, pos[2])
        alpha = np.arctan2(air[2], air[0])
        beta = np.arcsin(air[1] / np.linalg.norm(air))
        rows.append(np.concatenate([pos - nominal[k], R @ v, _euler(q), rates, [alpha, beta, tension[below[k]]]]))
    z = x[: C.B3_SIZE * asm.n_wings].reshape(asm.n_wings, C.B3_SIZE)[:, 2]
    aux = np.zeros(N_AUX)
    aux[AUX_MAX_TENSION] = tension.max()
    aux[AUX_GROUND_START] = tension[ground[0]] if ground[0] >= 0 else 0.0
    aux[AUX_GROUND_END] = tension[ground[1]] if ground[1] >= 0 else 0.0
    aux[AUX_MIN_ALTITUDE] = np.min(-z)
    return np.concatenate(rows), aux


# ------------------------------------------------------------------------------------------- helpers
def disturbed(scene_name: str, seed: int):
    """(assembly with a turning, modulated wind, x, u, t, nominal, below, ground, settings): the scene's trim
    state shaken (positions, attitudes, a non-unit quaternion norm, velocities, rates, node positions)."""
    sc, x_trim, u_trim = scene_trim(scene_name, ())
    asm = sc.assembly
    rng = np.random.default_rng(seed)
    tg = np.arange(8) * 0.4
    wind = dataclasses.replace(asm.wind, direction_inf=0.25, direction_height=300.0).with_modulation(
        0.1, 0.4, 1.0 + 0.15 * np.sin(tg), 0.08 * np.cos(tg))
    asm = dataclasses.replace(asm, wind=wind)
    nw = asm.n_wings
    x = np.array(x_trim)
    wings = x[: C.B3_SIZE * nw].reshape(nw, C.B3_SIZE)
    wings[:, C.B3_POS: C.B3_POS + 3] += rng.normal(scale=0.5, size=(nw, 3))
    eul = np.array([euler_from_quaternion(q) for q in wings[:, C.B3_QUAT: C.B3_QUAT + 4]])
    eul += rng.normal(scale=[0.2, 0.1, 0.3], size=(nw, 3))
    for k in range(nw):
        wings[k, C.B3_QUAT: C.B3_QUAT + 4] = quaternion_from_euler(*eul[k]) * rng.uniform(0.97, 1.03)
    wings[:, C.B3_VEL: C.B3_VEL + 3] += rng.normal(scale=2.0, size=(nw, 3))
    wings[:, C.B3_RATE: C.B3_RATE + 3] += rng.normal(scale=0.3, size=(nw, 3))
    nodes = x[C.B3_SIZE * nw:].reshape(asm.n_nodes, C.N3_SIZE)
    nodes[:, C.N3_POS: C.N3_POS + 3] += rng.normal(scale=0.2, size=(asm.n_nodes, 3))
    u = np.array(u_trim) + rng.uniform(-0.02, 0.02, size=u_trim.size)
    nominal = np.ascontiguousarray(x_trim[: C.B3_SIZE * nw].reshape(nw, C.B3_SIZE)[:, C.B3_POS: C.B3_POS + 3])
    lay = sc.layout
    below = np.array([lay.piece_elements[k][-1] for k in range(nw)], dtype=np.int64)
    ground = np.array([lay.piece_elements[0][0], lay.piece_elements[-1][-1] if sc.end is not None else -1],
                      dtype=np.int64)
    return asm, x, u, 1.37, nominal, below, ground, sc.settings


# ------------------------------------------------------------------------------------------- tests
def test_layout_is_the_kernel_contract():
    """The documented per-wing table and the kernel's OBS_* slots name the same entries."""
    assert N_OBS_PER_WING == C.OBS_SIZE == len(OBS_NAMES)
    for name, slot in [("dx", C.OBS_OFFSET), ("vx", C.OBS_VELOCITY), ("phi", C.OBS_EULER), ("p", C.OBS_RATES),
                       ("alpha", C.OBS_ALPHA), ("beta", C.OBS_BETA), ("tension", C.OBS_TENSION)]:
        assert OBS_INDEX[name] == slot
    assert [f.name for f in OBS_FIELDS] == ["dx", "dy", "dz", "vx", "vy", "vz", "phi", "theta", "psi", "p", "q",
                                            "r", "alpha", "beta", "tension"]


@pytest.mark.parametrize("scene_name,seed", [("tethered_wing", 1), ("tethered_wing", 2), ("ladder_chain", 3)])
def test_kernel_observation_equals_first_principles(scene_name, seed):
    asm, x, u, t, nominal, below, ground, settings = disturbed(scene_name, seed)
    sim = Simulator(asm, x, settings, u)
    obs, aux = np.full(asm.n_wings * N_OBS_PER_WING, np.nan), np.full(N_AUX, np.nan)
    assert observe_state(t, x, u, sim.model, sim.work, nominal, below, ground, obs, aux) == OK
    want, want_aux = oracle(asm, t, x, nominal, below, ground)
    got, exp = obs.reshape(-1, N_OBS_PER_WING), want.reshape(-1, N_OBS_PER_WING)
    ti = OBS_INDEX["tension"]
    np.testing.assert_allclose(np.delete(got, ti, axis=1), np.delete(exp, ti, axis=1), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(got[:, ti], exp[:, ti], rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(aux, want_aux, rtol=1e-10, atol=1e-9)
    # the simulator-level helper is the same kernel on the same state
    sim.reset(state=x, t=t, controls=u)
    np.testing.assert_array_equal(observe(sim, nominal, below), obs)


def test_base_observe_equals_the_env_observation():
    """control.base.observe on a bare Simulator holding the env copy's state, time, controls and wind gives the
    environment's (unclipped, float64) observation row."""
    env = gym.make("laddermill_gym/TetheredWing-v0", episode_time=5.0)
    task = env.unwrapped.task
    sc, b = task.scene, task.batch
    obs, _ = env.reset(seed=4)
    rng = np.random.default_rng(0)
    compared = 0
    for i in range(31):
        if i % 6 == 0:
            wind = sc.assembly.wind.with_modulation(b.tmod[0, 0], b.tmod[0, 1], b.mod_speed[0], b.mod_direction[0])
            sim = Simulator(dataclasses.replace(sc.assembly, wind=wind), b.states[0], sc.settings, b.controls[0])
            sim.reset(state=b.states[0], t=float(b.t[0]), controls=b.controls[0])
            row = task.obs[0]
            np.testing.assert_allclose(observe(sim, task.nominal, task.below), row, rtol=1e-12, atol=1e-12)
            np.testing.assert_array_equal(obs, row.astype(np.float32))
            compared += 1
        obs, _, terminated, truncated, _ = env.step(rng.uniform(-0.3, 0.3, size=env.action_space.shape))
        assert not (terminated or truncated)
    assert compared == 6 and b.t[0] > 1.0  # past the default direction step at 1 s
    env.close()


def test_base_observe_refuses_an_in_plane_scene():
    sc = load_scene("tethered_wing", dimension=2)
    sim = Simulator(sc.assembly, np.zeros(sc.assembly.state_size), sc.settings)
    with pytest.raises(ValueError, match="3D scene"):
        observe(sim, np.zeros((1, 3)), np.zeros(1, dtype=np.int64))


def test_base_observe_checks_its_arguments():
    sc, x, u = scene_trim("tethered_wing", ())
    sim = sc.simulator(x, u)
    with pytest.raises(ValueError, match="shape"):
        observe(sim, np.zeros((2, 3)), np.zeros(1, dtype=np.int64))
    with pytest.raises(ValueError, match="outside"):
        observe(sim, np.zeros((1, 3)), np.array([sc.assembly.elements.count]))


def test_rotations_from_quaternions():
    """Against R = Rz(psi) Ry(theta) Rx(phi) of the quaternion's Euler angles; the norm does not matter."""
    rng = np.random.default_rng(5)
    q = rng.normal(size=(6, 4)) * rng.uniform(0.5, 2.0, size=(6, 1))
    rot = rotations_from_quaternions(q)
    assert rot.shape == (6, 3, 3)
    for k in range(6):
        np.testing.assert_allclose(rot[k], rotation_from_euler(*euler_from_quaternion(q[k])), atol=1e-13)
        np.testing.assert_allclose(rot[k], _rotation(q[k]), atol=1e-14)
    with pytest.raises(ValueError, match=r"\(n, 4\)"):
        rotations_from_quaternions(np.zeros(4))
