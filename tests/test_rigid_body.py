"""A free rigid wing (no cable, vacuum, no gravity) against the closed-form properties of a torque-free body.

Oracles (shared/design/oracles.md, "Rigid body and waves"; any mechanics text, e.g. Goldstein ch. 5):
- kinetic energy 1/2 w.J w and the angular momentum R J w in the global frame are constants of the motion;
  the CG moves on a straight line at the constant global velocity R v (Meijaard eq. 5);
- spin w2 about the intermediate axis of I = (1, 2, 3) is unstable with growth rate
  w2 sqrt((I2 - I1)(I3 - I2)/(I1 I3)) = 0.577 w2 (linearised Euler equations);
- 3-2-1 Euler angle rates are A(phi, theta) w (Meijaard eq. 6, written out in the test, independently of
  ``states.euler_rate_matrix``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from laddermill_gym.model.states import euler_from_quaternion, euler_rate_matrix, rotation_from_euler, wing_state_3d
from laddermill_gym.sim.simulator import IntegratorSettings, Simulator
from tests.conftest import free_body_assembly, make_wing_type


def inertia_matrix(jxx, jyy, jzz, jxz):
    """J of docs/model.md: the product of inertia Jxz enters with a minus sign off the diagonal."""
    return np.array([[jxx, 0.0, -jxz], [0.0, jyy, 0.0], [-jxz, 0.0, jzz]])


def quat_matrix(q):
    """Rotation matrix of a unit quaternion (scalar first), written out here independently."""
    a, b, c, d = np.asarray(q) / np.linalg.norm(q)
    return np.array([
        [a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
        [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
        [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d],
    ])


def free_body(inertia, euler, v_body, rates, settings, mass=2.0):
    wt = make_wing_type(mass=mass, inertia=inertia)
    asm = free_body_assembly(wt, gravity=0.0)
    x0 = wing_state_3d([1.0, -2.0, -50.0], euler, v_body, rates)
    return Simulator(asm, x0, settings)


@pytest.mark.parametrize("inertia", [(1.0, 2.0, 3.0, 0.0), (1.0, 2.0, 3.0, 0.6), (4.0, 1.5, 4.5, -1.2)],
                         ids=["principal", "Jxz", "Jxz-negative"])
def test_torque_free_invariants(inertia):
    """Energy, global angular momentum (vector) and the CG's straight-line motion over 100 s of a
    tumbling body: relative drift below 1e-9 (RK4, dt = 2 ms)."""
    J = inertia_matrix(*inertia)
    assert np.all(np.linalg.eigvalsh(J) > 0)
    euler0, v0, w0 = (0.3, -0.4, 1.0), np.array([1.0, 2.0, -3.0]), np.array([0.7, -1.1, 0.9])
    sim = free_body(inertia, euler0, v0, w0, IntegratorSettings(method="rk4", dt=2e-3))

    def invariants():
        s = sim.state
        R = quat_matrix(s[3:7])
        w = s[10:13]
        return 0.5 * w @ J @ w, R @ (J @ w), s[0:3].copy(), R @ s[7:10]

    e0, L0, x0, V0 = invariants()
    sim.step(n_steps=50_000)
    assert sim.t == pytest.approx(100.0)
    e1, L1, x1, V1 = invariants()
    assert abs(e1 / e0 - 1.0) < 1e-9
    assert np.linalg.norm(L1 - L0) / np.linalg.norm(L0) < 1e-9
    assert np.linalg.norm(V1 - V0) / np.linalg.norm(V0) < 1e-9
    assert np.linalg.norm(x1 - (x0 + V0 * 100.0)) < 1e-9 * np.linalg.norm(V0) * 100.0
    # the motion is a genuine tumble, not a steady spin about a principal axis
    assert np.linalg.norm(sim.state[10:13] - w0) > 0.1


def test_intermediate_axis_instability():
    """Spin w2 = 2 rad/s about axis 2 of I = (1, 2, 3) with 1e-8 rad/s perturbations: the transverse rates
    grow as exp(0.577 w2 t); the fitted rate over the linear phase is within 2%."""
    w2 = 2.0
    sim = free_body((1.0, 2.0, 3.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (1e-8, w2, 1e-8),
                    IntegratorSettings(method="rk4", dt=1e-3))
    ts, amp = [], []
    for _ in range(100):
        sim.step(n_steps=100)
        ts.append(sim.t)
        amp.append(math.hypot(sim.state[10], sim.state[12]))
    ts, amp = np.array(ts), np.array(amp)
    expected = w2 * math.sqrt((2.0 - 1.0) * (3.0 - 2.0) / (1.0 * 3.0))
    linear = (ts >= 3.0) & (amp < 1e-4)  # decaying mode gone, transverse rates still tiny
    assert linear.sum() > 30
    rate = np.polyfit(ts[linear], np.log(amp[linear]), 1)[0]
    assert rate == pytest.approx(expected, rel=0.02), f"rate {rate:.5f} vs {expected:.5f}"
    # and it does not stay small: by t = 10 s the perturbation has grown by > 1e4
    assert amp[-1] > 1e4 * 1e-8


def euler_rates_meijaard(phi, theta, w):
    """Meijaard eq. (6) written out: phi' = p + (q sin phi + r cos phi) tan theta,
    theta' = q cos phi - r sin phi, psi' = (q sin phi + r cos phi)/cos theta."""
    p, q, r = w
    s = q * math.sin(phi) + r * math.cos(phi)
    return np.array([p + s * math.tan(theta), q * math.cos(phi) - r * math.sin(phi), s / math.cos(theta)])


def test_euler_angle_kinematics():
    """Along a tumbling trajectory, central differences of the Euler angles from the stored quaternion
    equal A(phi, theta) w (eq. 6) to 1e-6 rad/s (difference step 1 ms: truncation ~ h^2/6 |angle'''|)."""
    h = 1e-3
    sim = free_body((1.0, 2.0, 3.0, 0.4), (0.2, 0.3, -0.5), (0.0, 0.0, 0.0), (0.5, -0.3, 0.6),
                    IntegratorSettings(method="rk4", dt=h))
    states = [sim.state.copy()]
    for _ in range(6000):
        sim.step()
        states.append(sim.state.copy())
    states = np.array(states)
    eul = np.array([euler_from_quaternion(s[3:7]) for s in states])
    assert np.max(np.abs(eul[:, 1])) < math.radians(75)  # clear of the gimbal lock
    eul_u = np.unwrap(eul, axis=0)
    fd = (eul_u[2:] - eul_u[:-2]) / (2 * h)
    mid = states[1:-1]
    ana = np.array([euler_rates_meijaard(e[0], e[1], s[10:13]) for e, s in zip(eul[1:-1], mid, strict=True)])
    assert np.max(np.abs(fd - ana)) < 1e-6
    # the package's A matrix is the same thing
    pkg = np.array([euler_rate_matrix(e[0], e[1]) @ s[10:13] for e, s in zip(eul[1:-1:50], mid[::50], strict=True)])
    np.testing.assert_allclose(pkg, ana[::50], rtol=0, atol=1e-12)
    # the state's quaternion and its Euler angles describe the same rotation
    for s, e in zip(states[::500], eul[::500], strict=True):
        np.testing.assert_allclose(rotation_from_euler(*e), quat_matrix(s[3:7]), atol=1e-12)


def test_translation_kinematics():
    """x' = R v (eq. 5): the position derivative returned by rhs is the body velocity rotated to global,
    and a central difference of the integrated CG position of a tumbling, translating body agrees with
    R v to 1e-8 m/s (step 1 ms)."""
    euler, v = (0.4, -0.2, 2.5), np.array([3.0, -1.0, 0.5])
    sim = free_body((1.0, 2.0, 3.0, 0.3), euler, v, (0.2, 0.5, -0.4), IntegratorSettings(method="rk4", dt=1e-3))
    dx = sim.rhs(0.0, sim.state)
    np.testing.assert_allclose(dx[0:3], rotation_from_euler(*euler) @ v, rtol=0, atol=1e-13)
    sim.step(n_steps=1000)
    a = sim.state.copy()
    sim.step()
    b = sim.state.copy()
    sim.step()
    c = sim.state.copy()
    np.testing.assert_allclose((c[0:3] - a[0:3]) / 2e-3, quat_matrix(b[3:7]) @ b[7:10], rtol=0, atol=1e-8)
    # the body velocity itself has changed (v' = -w x v), so this is not a trivial constant
    assert np.linalg.norm(b[7:10] - v) > 0.1
