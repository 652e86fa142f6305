"""The lateral LQR of the moving-cable mill (``control/mill_lqr.py``, issue 12 point 4).

Oracles: the plain-numpy reference right-hand side (``reference``) for the lateral model; the mirror
symmetry of an in-plane state (lateral and longitudinal blocks decouple exactly); the paper's transfer rule for the
transfer's Jacobian (slots shift by one unchanged, the new wing takes its neighbour's attitude and no rates); the
gain itself for the controller's action layout; and, in the slow test, the nonlinear mill after the paper's
direction step (the open loop leaves the aerodynamic range within 10 s: README).
"""

from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import numpy as np
import pytest

from laddermill_gym import Simulator, load_scene
from laddermill_gym.control.linearize import coupling_norms, full_from_minimal, linearize, minimal_from_full
from laddermill_gym.control.lqr_config import load_lqr_config
from laddermill_gym.control.mill_lqr import design_mill_lqr, mill_lateral_model, transfer_jacobian
from laddermill_gym.envs.laddermill.observation import OBS_INDEX
from laddermill_gym.envs.laddermill.task import MillTask
from laddermill_gym.kernels.contract import SX_MOVED, SX_SIZE
from laddermill_gym.model.configio import CONFIG_DIR
from laddermill_gym.reference import reference_rhs
from tests.conftest import SMALL_MILL, small_mill_task

SMALL = SMALL_MILL
N = SMALL["scene_options"]["n_wings"]
CONFIG = CONFIG_DIR / "agents" / "lqr_laddermill.yaml"


@pytest.fixture(scope="module")
def task():
    return small_mill_task()


def _at_rest(task):
    """A simulator of the small mill's start with the cable held still (the reference has fixed lengths)."""
    asm = task.batch.assembly
    st = dataclasses.replace(asm.station, speed_times=(0.0,), speed_values=(0.0,))
    asm0 = dataclasses.replace(asm, station=st)
    x = np.array(task.op.state)
    return Simulator(asm0, x, task.scene.settings, np.array(task.u_op)), x


def test_station_tail_is_required_and_kept(task):
    sim, x = _at_rest(task)
    z = minimal_from_full(sim.assembly, x)
    with pytest.raises(ValueError, match="tail"):
        full_from_minimal(sim.assembly, z)
    back = full_from_minimal(sim.assembly, z, x[sim.assembly.body_state_size:])
    np.testing.assert_allclose(back, x, rtol=0, atol=1e-12)


def test_lateral_model_equals_the_reference_rhs(task):
    """A, B of the compiled mill = those of the numpy reference with the station's element lengths (V_c = 0)."""
    sim, x = _at_rest(task)
    asm = sim.assembly
    nb, s, st = asm.body_state_size, x[asm.body_state_size + SX_MOVED], asm.station
    l0 = asm.elements.l0.copy()
    l0[0] = st.first_fraction * st.piece_length + s
    l0[-1] = st.last_fraction * st.piece_length - s
    fixed = dataclasses.replace(asm, station=None, elements=dataclasses.replace(asm.elements, l0=l0))

    def ref(t, xf, u):
        return np.concatenate([reference_rhs(t, xf[:nb], u, fixed), np.zeros(SX_SIZE)])

    A, B = mill_lateral_model(sim, x, task.u_op)
    Ar, Br = mill_lateral_model(sim, x, task.u_op, rhs=ref)
    assert A.shape == (6 * N, 6 * N) and B.shape == (6 * N, 2 * N)
    assert np.max(np.abs(A - Ar)) < 1e-5 * np.max(np.abs(Ar))
    assert np.max(np.abs(B - Br)) < 1e-5 * np.max(np.abs(Br))


def test_in_plane_state_decouples_lateral_from_longitudinal(task):
    """Mirror symmetry of the in-plane mill: the coupling blocks vanish (to finite-difference noise)."""
    sim = task.simulator(0)
    lin = linearize(sim, np.array(task.op.state), np.array(task.u_op))
    norms = coupling_norms(lin)
    assert max(norms.values()) < 1e-6, norms


def test_transfer_jacobian_is_the_slot_shift(task):
    """Slots 1..n-1 take the lateral states of slots 0..n-2 unchanged; the new wing in slot 0 has its neighbour's
    roll and yaw, no rates, and the lateral offset a fraction f = f_first / (1 + f_first) of the neighbour's (the
    first element, f_first l0 + l0 long at the transfer, split one piece from its top)."""
    sim = task.simulator(0)
    x = np.array(task.op.state)
    st = sim.assembly.station
    x[sim.assembly.body_state_size + SX_MOVED] = st.piece_length  # the cable has just moved a whole piece
    S = transfer_jacobian(sim, x)
    blk = S.reshape(N, 6, N, 6)
    for k in range(1, N):
        for j in range(N):
            np.testing.assert_allclose(blk[k, :, j, :], np.eye(6) if j == k - 1 else 0.0, atol=1e-8)
    new = blk[0]  # rows y, vy, phi, psi, p, r of the new wing
    assert np.all(np.abs(new[:, 1:, :]) < 1e-8)  # only the neighbour (old slot 0) matters
    np.testing.assert_allclose(new[[2, 3], 0, :][:, [2, 3]], np.eye(2), atol=1e-8)  # phi, psi copied
    np.testing.assert_allclose(new[[4, 5], 0, :], 0.0, atol=1e-8)  # rates zero
    f = st.first_fraction / (1.0 + st.first_fraction)
    assert new[0, 0, 0] == pytest.approx(f, rel=1e-7)  # y from the neighbour's y
    assert new[1, 0, 1] == pytest.approx(f, rel=1e-7)  # vy from the neighbour's vy


def test_controller_applies_the_gain_in_the_env_layout(task):
    """u - u_op of the controller's actions = -K dz for a small lateral deviation, elevators untouched."""
    design = design_mill_lqr(load_lqr_config(CONFIG), task)
    assert design.gains.shape == (2 * N, 6 * N)
    assert np.all(np.isfinite(design.frozen_radius)) and design.phases.size == 8
    ctrl = design.controller(task)
    rng = np.random.default_rng(3)
    dz = rng.normal(size=(N, 6)) * np.array([0.01, 0.01, 1e-3, 1e-3, 1e-3, 1e-3])
    obs = np.zeros(ctrl.obs_dim)
    o = obs[: 15 * N].reshape(N, 15)
    for c, name in enumerate(("dy", "vy", "phi", "psi", "p", "r")):
        o[:, OBS_INDEX[name]] = dz[:, c] + (design.trim_attitude[:, 0] if name == "phi" else 0.0) \
            + (design.trim_attitude[:, 1] if name == "psi" else 0.0)
    a, _ = ctrl.predict(obs.astype(np.float64))
    assert ctrl.n_clipped == 0
    u = task.actions.controls(a[None].astype(float))[0]
    du = (u - task.u_op)[: 3 * N].reshape(N, 3)
    expect = -(design.gains @ dz.reshape(-1)).reshape(N, 2)
    np.testing.assert_allclose(du[:, 1:], expect, rtol=1e-5, atol=1e-9)  # float32 actions
    np.testing.assert_array_equal(du[:, 0], 0.0)


def test_layouts_the_lqr_cannot_drive_are_refused(task):
    design = design_mill_lqr(load_lqr_config(CONFIG), task, n_phases=2)
    halves = MillTask(1, **dict(SMALL, groups="halves"), operating_point=task.op)
    with pytest.raises(ValueError, match="per_slot"):
        design.controller(halves)
    with pytest.raises(ValueError, match="elements_per_piece"):  # the scene loader refuses a moving cable's nodes
        load_scene("laddermill", n_wings=N, elements_per_piece=2, dt=0.001)
    with pytest.raises(ValueError, match="elements_per_piece"):  # and so does the lateral model, for a model with them
        mill_lateral_model(SimpleNamespace(assembly=SimpleNamespace(n_nodes=N + 1)), np.zeros(1), np.zeros(3 * N))


@pytest.mark.slow
def test_lqr_holds_the_default_mill_after_the_paper_step():
    """The 101-wing mill from its periodic operating point, 0.01 rad direction step at 1 s: the LQR keeps every slot
    within 0.5 m for 80 s (two transfers); the open loop leaves the aerodynamic range before 15 s."""
    import gymnasium as gym

    import laddermill_gym  # noqa: F401
    from laddermill_gym.control.factory import make_controller

    results = {}
    for spec in ("open_loop", "lqr"):
        env = gym.make("laddermill_gym/LadderMill-v0", episode_time=80.0)
        ctrl = make_controller(spec, "laddermill_gym/LadderMill-v0", {"episode_time": 80.0})
        obs, _ = env.reset(seed=0)
        worst, t = 0.0, 0.0
        while True:
            a, _ = ctrl.predict(obs)
            obs, _, term, trunc, info = env.step(a)
            dy = np.asarray(obs[: 15 * 101]).reshape(101, 15)[:, OBS_INDEX["dy"]]
            worst = max(worst, float(np.max(np.abs(dy))))
            t = info["t"]
            if term or trunc:
                break
        results[spec] = (t, worst, term)
    assert results["open_loop"][2] and results["open_loop"][0] < 15.0
    assert not results["lqr"][2] and results["lqr"][0] >= 80.0 - 1e-6 and results["lqr"][1] < 0.5
