"""Where the laddermill's loop is, for sizing a frozen gust grid (turbulence) over it.

The moving loop covers, over one transfer period, every position its slots pass through, so its extent is that of

* every wing CG over the operating point's recorded period (``OperatingPoint.orbit_positions``, all slots),
* every free cable node at the operating point's state,
* the ground stations (the scene's fixed points, where the cable runs through the generator).

:func:`loop_points` collects them; the extent and the cover check are the tasks' shared ones
(``envs/gust_cover.py``, re-exported here).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.envs.gust_cover import (
    LOOP,
    START,
    LoopExtent,
    check_turbulence_cover,
    extent,
    point_positions,
    start_points,
)

__all__ = ["LoopExtent", "loop_points", "extent", "point_positions", "check_turbulence_cover", "start_points",
           "LOOP", "START"]


def loop_points(op, assembly) -> np.ndarray:
    """Points (m, 3) [m] the loop passes through over a transfer period: every slot's wing CG over the operating
    point ``op``'s recorded orbit, the free cable nodes at ``op.state`` and the ground stations
    (``assembly.fixed_points``)."""
    orbit = np.asarray(op.orbit_positions, dtype=float).reshape(-1, 3)
    at_op = point_positions(assembly, op.state)[0]
    return np.concatenate([orbit, at_op, np.asarray(assembly.fixed_points, dtype=float).reshape(-1, 3)])
