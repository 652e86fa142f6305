"""Non-finite inputs never become table or grid indices (a NaN index crashed the process with a segfault).

Oracle: with a NaN or infinite angle of attack the table lookup falls back to the first interval at its start,
whose value is the spline's constant coefficient there (closed form); a simulator stepped into a NaN state
reports the failure instead of crashing.
"""

from __future__ import annotations

import numpy as np
import pytest

from laddermill_gym.kernels.rigid.aero import N_COLUMNS, spline_eval
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.packing import pack_model
from laddermill_gym.sim.simulator import SimulationError


@pytest.mark.parametrize("alpha", [np.nan, np.inf, -np.inf])
def test_table_lookup_with_non_finite_alpha(alpha):
    scene = load_scene("tethered_wing")
    m = pack_model(scene.assembly)
    from laddermill_gym.kernels.contract import GL_ALPHA0, GL_DALPHA

    out = np.zeros(N_COLUMNS)
    spline_eval(m.ac, 0, alpha, m.glob[GL_ALPHA0], m.glob[GL_DALPHA], out)
    np.testing.assert_array_equal(out, m.ac[0, 0, 3, :N_COLUMNS])


def test_nan_state_is_reported_not_crashed():
    sim = load_scene("tethered_wing").simulator()
    x = sim.state.copy()
    x[7] = np.nan  # body velocity of the wing
    sim.state = x  # reset() refuses a non-finite state; set it behind its back, as a diverged step would
    with pytest.raises(SimulationError):
        sim.step(None, n_steps=3)
