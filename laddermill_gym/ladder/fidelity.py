"""Between fidelities: a point-mass start from the rigid model's static equilibrium of the same scene file (the
same trim), and the comparison of the two static solutions (shape and tension along the cable).

The point-mass kite sits at the rigid wing's CG with the wing's attitude (3-2-1 Euler angles) as its commanded
attitude; the string's nodes start evenly spaced on the straight line between consecutive kites (or ground
points), at rest. The rigid model is read from the same file with the point-mass scene's overrides (without its
``integrator`` section). ``docs/pointmass.md`` ("Between fidelities") discusses the differences.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, PU_SIZE
from laddermill_gym.ladder.rigid_scene import load_rigid_scene
from laddermill_gym.model.configio import ConfigError


def rigid_overrides(overrides: dict | None) -> dict | None:
    """A point-mass scene's nested ``overrides`` as the rigid reader takes them: without the ``integrator`` section
    (the point-mass step, method and limits are not the rigid model's; its start runs at the file's own)."""
    if not overrides:
        return None
    return {k: v for k, v in overrides.items() if k != "integrator"} or None


def load_rigid_of(file, n_wings: int, overrides: dict | None):
    """The scene ``file`` at the rigid fidelity with ``n_wings`` and the point-mass scene's ``overrides``
    (:func:`rigid_overrides`); a ConfigError says that the point-mass start reads the file so."""
    try:
        return load_rigid_scene(file, n_wings=n_wings, overrides=rigid_overrides(overrides))
    except ConfigError as err:
        raise ConfigError(f"{err} (the point-mass start is the rigid model's of the same file with the same "
                          "overrides, read at the rigid fidelity)") from None


def rigid_static(pm_scene):
    """(rigid simulator at the static equilibrium, rigid scene) of the file behind a point-mass scene, with its
    overrides (``PointMassScene.overrides``)."""
    rigid = load_rigid_of(pm_scene.file, pm_scene.string.n_kites, pm_scene.overrides)
    x, u = rigid.initial_state()
    return rigid.simulator(x, u), rigid


def _string_through(string, points: np.ndarray) -> np.ndarray:
    """State (6 n,) of the string at rest with its kites at ``points`` (n_k, 3) [m], nodes evenly on the
    straight lines between consecutive kites and the anchors."""
    x = np.zeros(string.state_size)
    xs = x.reshape(-1, N3_SIZE)
    corners = [string.anchor, *points] + ([string.end] if string.end is not None else [])
    ends = [*string.kite_nodes] + ([string.n_nodes] if string.end is not None else [])
    j0 = 0
    for k, jk in enumerate(ends):
        m = jk - j0 + 1  # elements of this piece
        f = np.arange(1, m + (0 if jk == string.n_nodes else 1)) / m
        xs[j0:j0 + f.size, N3_POS:N3_POS + 3] = corners[k] + np.outer(f, corners[k + 1] - corners[k])
        j0 = jk + 1
    return x


def pointmass_from_rigid(pm_scene) -> tuple[np.ndarray, np.ndarray]:
    """(state, controls) of a point-mass scene at the rigid model's static equilibrium of the same file."""
    sim, _ = rigid_static(pm_scene)
    u = np.ascontiguousarray(sim.wing_euler().reshape(-1, PU_SIZE).ravel())
    return _string_through(pm_scene.string, sim.wing_positions()), u
