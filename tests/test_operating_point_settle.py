"""How long the operating point's search runs the in-plane mill of LadderMill-v0, v1 and v2 (docs/benchmarks.md, "The
operating point on disk"): the simulated time ``OperatingPoint.t_settle_s``, printed (``pytest -s``). Oracle: the
generator holds the scene's piecewise-linear cable speed, so the cable has moved int_0^t V_c dt (the trapezoid rule,
exact for a piecewise-linear schedule) at the end; the point is taken just after a wing transfer, so that distance
less the point's own s moved since the transfer is a whole number of pieces, and s is below one step's travel."""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.envs import ENV_IDS
from laddermill_gym.envs.laddermill.operating_point import SettleConfig, mill_scene, operating_point
from laddermill_gym.kernels.contract import SX_MOVED, SX_SIZE

MILLS = {"laddermill_gym/LadderMill-v0": "laddermill", "laddermill_gym/LadderMill-v1": "laddermill_v1",
         "laddermill_gym/LadderMill-v2": "laddermill_v2"}


def cable_moved(times, speeds, t: float) -> float:
    """int_0^t V_c dt [m] of a piecewise-linear schedule held after its last point (trapezoids)."""
    tt = np.append(np.asarray(times, float), max(t, times[-1]))
    vv = np.append(np.asarray(speeds, float), speeds[-1])
    keep = tt <= t
    tt, vv = np.append(tt[keep], t), np.append(vv[keep], np.interp(t, tt, vv))
    return float(np.sum(0.5 * (vv[1:] + vv[:-1]) * np.diff(tt)))


def test_cable_moved_is_the_trapezoid_rule():
    assert cable_moved((0.0, 30.0), (0.0, 2.0), 130.0) == pytest.approx(2.0 * (130.0 - 15.0), rel=1e-15)
    assert cable_moved((0.0, 30.0), (0.0, 2.0), 15.0) == pytest.approx(0.5 * 15.0 * 1.0, rel=1e-15)


@pytest.mark.slow
@pytest.mark.parametrize("env_id", sorted(MILLS))
def test_the_search_ends_just_after_a_transfer(env_id):
    """The registered mill's point (the env's scene, no scene options, the default settle) converged, at a
    simulated time whose cable travel is whole pieces plus the point's s moved since its last transfer."""
    kwargs = ENV_IDS[env_id]
    scene = MILLS[env_id]
    assert kwargs["scene"] == scene and "scene_options" not in kwargs and "settle" not in kwargs
    op = operating_point(scene, (), SettleConfig())
    sc = mill_scene(scene, (), 2)
    st, dt = sc.assembly.station, sc.settings.dt
    moved = cable_moved(st.speed_times, st.speed_values, op.t_settle_s)
    s = float(op.state[op.state.size - SX_SIZE + SX_MOVED])  # the station block ends the state
    pieces = (moved - s) / st.piece_length
    print(f"{env_id} ({scene}): search ran {op.t_settle_s:.2f} simulated seconds (converged {op.converged}); cable "
          f"moved {moved:.4f} m = {pieces:.6f} pieces of {st.piece_length:g} m + s {s:.4f} m since the transfer")
    assert op.converged
    assert abs(pieces - round(pieces)) * st.piece_length < 1e-6
    assert 0.0 <= s < st.speed_values[-1] * dt * (1 + 1e-9)
