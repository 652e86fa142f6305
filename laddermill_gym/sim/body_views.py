"""Named read-outs of a simulator's state: names of state entries, wing positions, attitudes, velocities, rates,
air velocities, angles of attack and sideslip, heights, node positions, element tensions, and the station's views
(a mixin of :class:`~laddermill_gym.sim.simulator.Simulator`, which provides ``assembly``, ``state``, ``t``,
``controls``, ``model`` and ``work``)."""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.wind import modulation, wind_point
from laddermill_gym.model.states import euler_from_quaternion
from laddermill_gym.sim.overload import BREAKING_FRACTION, Overload, overload_events, tension_limits
from laddermill_gym.sim.reports import body_heights
from laddermill_gym.sim.station_views import StationViews, station_state_name


def _slot_names(size: int, *groups) -> tuple[str, ...]:
    """Names of the entries of one body's or node's state block from (offset, names) pairs."""
    names = [""] * size
    for offset, group in groups:
        names[offset: offset + len(group)] = group
    return tuple(names)


_WING_NAMES_3D = _slot_names(C.B3_SIZE, (C.B3_POS, ("x [m]", "y [m]", "z [m]")), (C.B3_QUAT, ("q0", "q1", "q2", "q3")),
                             (C.B3_VEL, ("u [m/s]", "v [m/s]", "w [m/s]")),
                             (C.B3_RATE, ("p [rad/s]", "q [rad/s]", "r [rad/s]")))
_WING_NAMES_2D = _slot_names(C.B2_SIZE, (C.B2_X, ("x [m]",)), (C.B2_Z, ("z [m]",)), (C.B2_THETA, ("theta [rad]",)),
                             (C.B2_U, ("u [m/s]",)), (C.B2_W, ("w [m/s]",)), (C.B2_Q, ("q [rad/s]",)))
_NODE_NAMES_3D = _slot_names(C.N3_SIZE, (C.N3_POS, ("x [m]", "y [m]", "z [m]")),
                             (C.N3_VEL, ("vx [m/s]", "vy [m/s]", "vz [m/s]")))
_NODE_NAMES_2D = _slot_names(C.N2_SIZE, (C.N2_POS, ("x [m]", "z [m]")), (C.N2_VEL, ("vx [m/s]", "vz [m/s]")))



class BodyViews(StationViews):
    """State names and views of a simulator (see the module doc)."""

    def state_name(self, i: int) -> str:
        """Human-readable name of state entry i (e.g. 'wing 3 v_body[1] [m/s]')."""
        a = self.assembly
        ws, ns = a.wing_state_size, a.node_state_size
        if i < a.n_wings * ws:
            k, j = divmod(i, ws)
            names = _WING_NAMES_3D if a.dim == 3 else _WING_NAMES_2D
            return f"wing {k} {names[j]}"
        if i >= a.body_state_size:
            return station_state_name(i - a.body_state_size)
        k, j = divmod(i - a.n_wings * ws, ns)
        names = _NODE_NAMES_3D if a.dim == 3 else _NODE_NAMES_2D
        return f"node {k} {names[j]}"

    def _wing_block(self) -> np.ndarray:
        a = self.assembly
        return self.state[: a.n_wings * a.wing_state_size].reshape(a.n_wings, a.wing_state_size)

    def _node_block(self) -> np.ndarray:
        a = self.assembly
        return self.state[a.n_wings * a.wing_state_size: a.body_state_size].reshape(a.n_nodes, a.node_state_size)

    def _wing_vectors(self, slot3: int, slots2: tuple) -> np.ndarray:
        """A 3-vector of every wing, shape (n_wings, 3): the three slots from ``slot3`` of a 3D wing, or the in-plane
        wing's slots ``slots2`` (None: a component the plane does not have, 0)."""
        w = self._wing_block()
        if self.assembly.dim == 3:
            return w[:, slot3: slot3 + 3].copy()
        return np.stack([np.zeros(len(w)) if s is None else w[:, s] for s in slots2], axis=1)

    def wing_positions(self) -> np.ndarray:
        """CG positions, shape (n_wings, 3), global frame [m] (y = 0 in the in-plane mode)."""
        return self._wing_vectors(C.B3_POS, (C.B2_X, None, C.B2_Z))

    def wing_euler(self) -> np.ndarray:
        """3-2-1 Euler angles (roll phi, pitch theta, yaw psi), shape (n_wings, 3) [rad]."""
        if self.assembly.dim == 3:
            q = self._wing_block()[:, C.B3_QUAT: C.B3_QUAT + 4]
            return np.array([euler_from_quaternion(qq) for qq in q]).reshape(-1, 3)
        return self._wing_vectors(C.B3_QUAT, (None, C.B2_THETA, None))

    def wing_velocities(self) -> np.ndarray:
        """Body-frame CG velocities (u, v, w), shape (n_wings, 3) [m/s]."""
        return self._wing_vectors(C.B3_VEL, (C.B2_U, None, C.B2_W))

    def wing_rates(self) -> np.ndarray:
        """Body rates (p, q, r), shape (n_wings, 3) [rad/s]."""
        return self._wing_vectors(C.B3_RATE, (None, C.B2_Q, None))

    def wing_rotations(self) -> np.ndarray:
        """Rotation matrices body -> global, shape (n_wings, 3, 3)."""
        from laddermill_gym.model.states import rotation_from_euler

        return np.array([rotation_from_euler(*e) for e in self.wing_euler()]).reshape(-1, 3, 3)

    def air_velocity_body(self) -> np.ndarray:
        """Air-relative CG velocity in body axes, shape (n_wings, 3) [m/s] (from the kernels' wind)."""
        m = self.model
        s, d, _, _ = modulation(self.t, m.tmod[C.TM_T0], m.tmod[C.TM_DT], m.ms, m.md)
        pos = self.wing_positions()
        Rs = self.wing_rotations()
        out = np.zeros((len(pos), 3))
        for k in range(len(pos)):
            w = np.array(wind_point(pos[k, 0], pos[k, 1], pos[k, 2], self.t, m.wf, s, d, m.gp, m.gv))
            out[k] = self.wing_velocities()[k] - Rs[k].T @ w
        return out

    def wing_alpha_beta(self) -> np.ndarray:
        """Angle of attack and sideslip, shape (n_wings, 2) [rad]."""
        va = self.air_velocity_body()
        V = np.maximum(np.linalg.norm(va, axis=1), 1e-300)
        return np.stack([np.arctan2(va[:, 2], va[:, 0]), np.arcsin(np.clip(va[:, 1] / V, -1, 1))], axis=1)

    def body_heights(self) -> tuple[np.ndarray, np.ndarray]:
        """Heights h = -z [m] of the wing CGs (n_wings,) and of the free cable nodes (n_nodes,)."""
        return body_heights(self.assembly, self.state)

    def node_positions(self) -> np.ndarray:
        """Free cable node positions, shape (n_nodes, 3) [m]."""
        n = self._node_block()
        if self.assembly.dim == 3:
            return n[:, C.N3_POS: C.N3_POS + 3].copy()
        return np.stack([n[:, C.N2_POS], np.zeros(len(n)), n[:, C.N2_POS + 1]], axis=1)

    def tensions(self) -> np.ndarray:
        """Element tensions, shape (n_elements,) [N], evaluated at the current state."""
        self.rhs(self.t, self.state, self.controls)
        return self.work.tension[: self.assembly.elements.count].copy()

    def overloads(self, breaking_fraction: float = BREAKING_FRACTION) -> list[Overload]:
        """Elements whose tension now exceeds ``breaking_fraction`` [-] times their cable's breaking load (time,
        element, tension, limit; ``sim/overload.py``); empty if none. One right-hand side, O(n_elements)."""
        return overload_events(np.array([self.t]), self.tensions()[None, :],
                               tension_limits(self.assembly, breaking_fraction))[1]

    def views(self) -> dict[str, np.ndarray]:
        """All named views at once (for saving): name -> array, units in the names."""
        ab = self.wing_alpha_beta()
        return {
            "wing_position_m": self.wing_positions(),
            "wing_velocity_body_m_s": self.wing_velocities(),
            "wing_euler_rad": self.wing_euler(),
            "wing_rates_rad_s": self.wing_rates(),
            "wing_alpha_rad": ab[:, 0],
            "wing_beta_rad": ab[:, 1],
            "node_position_m": self.node_positions(),
            "element_tension_N": self.tensions(),
            **self.station_views(),
        }
