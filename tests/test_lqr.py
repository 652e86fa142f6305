"""Lateral LQR: the linearised model (against central differences of the nonlinear right-hand side), the gain
(against an independent discretisation and Riccati solution in scipy), closed-loop stability on the linear
model, and the nonlinear wing in the environment after the paper's 0.01 rad direction step."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from laddermill_gym.control.base import control_ranges
from laddermill_gym.control.factory import make_controller
from laddermill_gym.control.linearize import full_from_minimal, minimal_derivative, minimal_from_full
from laddermill_gym.control.lqr import (
    LQRController,
    bryson_weights,
    design_ladder_chain,
    design_tethered_wing,
    full_gain,
    load_lqr_config,
)
from laddermill_gym.envs import ENV_IDS, WingVectorEnv
from laddermill_gym.envs.observation import OBS_INDEX
from laddermill_gym.model.configio import ConfigError

TW = "laddermill_gym/TetheredWing-v0"


@pytest.fixture(scope="module")
def design():
    return design_tethered_wing()


def test_open_loop_unstable_closed_loop_stable(design):
    """The towed-glider lateral instability (Meijaard et al. 1999) and its cure on the linear model."""
    assert design.lqr.open_loop.real.max() > 0.05  # doubling in under 14 s
    assert np.abs(design.lqr.closed_loop).max() < 1.0


def test_linearisation_against_central_differences(design):
    """A_lat columns against central differences of the nonlinear rhs in minimal coordinates, computed here
    with a different step (1e-5 instead of the library's 1e-6)."""
    sc = design.scene
    x0, u0 = design.x_trim, design.u_trim
    sim = sc.simulator(x0, u0)
    asm = sc.assembly
    z0 = minimal_from_full(asm, x0)
    lin = design.linearization
    for j in range(0, z0.size, 3):
        h = 1e-5 * max(1.0, abs(z0[j]))
        zp, zm = z0.copy(), z0.copy()
        zp[j] += h
        zm[j] -= h
        fp = minimal_derivative(asm, full_from_minimal(asm, zp), sim.rhs(0.0, full_from_minimal(asm, zp), u0))
        fm = minimal_derivative(asm, full_from_minimal(asm, zm), sim.rhs(0.0, full_from_minimal(asm, zm), u0))
        col = (fp - fm) / (2 * h)
        np.testing.assert_allclose(lin.A[:, j], col, rtol=1e-4, atol=1e-5 * (1 + np.abs(col).max()))


def test_gain_matches_independent_riccati(design):
    """ZOH by the matrix exponential of [[A, B], [0, 0]] and the DARE from scipy (python-control not used)."""
    A, B, dt = design.A_lat, design.B_lat, design.config.control_period
    n, m = B.shape
    M = np.zeros((n + m, n + m))
    M[:n, :n], M[:n, n:] = A, B
    E = sla.expm(M * dt)
    Ad, Bd = E[:n, :n], E[:n, n:]
    Q, R = bryson_weights(design.config.max_state, design.config.max_input)
    P = sla.solve_discrete_are(Ad, Bd, Q, R)
    K = np.linalg.solve(R + Bd.T @ P @ Bd, Bd.T @ P @ Ad)
    np.testing.assert_allclose(design.lqr.K, K, rtol=1e-6, atol=1e-9)


def _fly(controller, seconds: float, n: int = 1):
    env = WingVectorEnv(n, **dict(ENV_IDS[TW], episode_time=seconds))
    obs, _ = env.reset(seed=0)
    peak, ended = 0.0, False
    for _ in range(int(round(seconds / env.task.control_dt))):
        a, _ = controller.predict(obs, deterministic=True)
        obs, _, term, trunc, _ = env.step(a)
        peak = max(peak, float(np.abs(obs[:, OBS_INDEX["dy"]]).max()))
        ended = bool(term.any())
        if ended:
            break
    return peak, ended


def test_lqr_holds_the_nonlinear_wing_open_loop_drifts():
    """TetheredWing-v0, 0.01 rad direction step at 1 s: LQR keeps the CG within 0.1 m for the whole 300 s
    episode; open loop oscillates with growing amplitude (doubling time about 6 s) far beyond that in 60 s."""
    lqr_peak, lqr_ended = _fly(make_controller("lqr", TW), 300.0)
    ol_peak, _ = _fly(make_controller("open_loop", TW), 60.0)
    assert not lqr_ended and lqr_peak < 0.1
    assert ol_peak > 10 * lqr_peak and ol_peak > 0.5


def test_block_and_full_gains_act_identically(design):
    """Per-wing gains (einsum path) and the same gains as one block-diagonal matrix (matmul path)."""
    sc = design.scene
    rng = np.random.default_rng(0)
    gains = rng.normal(size=(1, 2, 6))
    mid, half = control_ranges(sc.assembly)
    att = np.zeros((1, 2))
    c_block = LQRController(gains, design.u_trim, att, mid, half)
    c_full = LQRController(full_gain(gains), design.u_trim, att, mid, half)
    obs = rng.normal(scale=0.1, size=(5, 15))
    np.testing.assert_allclose(c_block.controls(obs), c_full.controls(obs), rtol=1e-12, atol=1e-15)


def test_chain_decentralised_blocks_stable():
    d = design_ladder_chain()
    assert d.gains.shape == (101, 2, 6)
    assert np.abs(d.closed_loop).max() < 1.0
    ol = np.array([np.linalg.eigvals(A) for A in d.A_blocks])
    assert (ol.real.max(axis=1) > 0).all()  # every wing on its own cable pieces is laterally unstable


@pytest.mark.parametrize("change, field", [
    ({"structure": "ring"}, "structure"),
    ({"design_model": "average"}, "design_model"),
    ({"max_state": {"y": -1.0}}, "max_state.y"),
    ({"control_period": 0}, "control_period"),
    ({"gain_scale": 2.0}, "gain_scale"),
])
def test_bad_lqr_config_names_the_field(tmp_path, change, field):
    import yaml

    from laddermill_gym.control.lqr import DEFAULT_CONFIG

    data = yaml.safe_load(DEFAULT_CONFIG.read_text())
    for key, value in change.items():
        if isinstance(value, dict):
            data[key].update(value)
        else:
            data[key] = value
    p = tmp_path / "bad.yaml"
    p.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=field):
        load_lqr_config(p)
