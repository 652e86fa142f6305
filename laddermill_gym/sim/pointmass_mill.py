"""Driver of the moving cable at the point-mass fidelity: the point-mass string between the two ground points of the
station, stepped with the station (``kernels/pointmass/mill.py``, docs/pointmass.md "The moving cable")."""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import (
    PP_L0,
    PP_L_FIRST,
    PP_L_LAST,
    PP_MU,
    PP_N,
    SX_ENERGY,
    SX_MOVED,
    SX_SPEED,
    SX_TRANSFERS,
)
from laddermill_gym.kernels.pointmass.implicit import mill_implicit_step, mill_implicit_step_serial
from laddermill_gym.kernels.pointmass.mill import (
    MX_KITE_TRANSFERS,
    MX_SIZE,
    end_tensions,
    mill_after,
    mill_before,
    node_masses,
    set_ends,
)
from laddermill_gym.model.pointmass import PointMassString
from laddermill_gym.model.pointmass_mill import PointMassStation, pack_pm_station, station_state
from laddermill_gym.model.station import electrical_power
from laddermill_gym.sim.pointmass import PointMassSimulator


def check_pay_out_step(station: PointMassStation, dt: float) -> None:
    """ValueError when the schedule pays out an element or more in one step, max |V_c| dt >= l_e: a step transfers
    at most one node (``kernels/pointmass/mill._transfer``)."""
    vmax = float(np.max(np.abs(station.speed_values)))
    if vmax * dt >= station.element_length:
        raise ValueError(f"the moving cable pays out max |V_c| dt = {vmax:g} m/s x {dt:g} s = {vmax * dt:g} m "
                         f"per step, not below element_length = {station.element_length:g} m (station.speed_values "
                         f"up to {vmax:g} m/s, dt = {dt:g} s): a step transfers at most one node; take dt < "
                         f"{station.element_length / vmax:g} s or longer elements")


class PointMassMillSimulator(PointMassSimulator):
    """A :class:`~laddermill_gym.sim.pointmass.PointMassSimulator` whose string moves through the ground station.

    ``station_x`` (``MX_SIZE``,): the station state (default: nothing moved, V_c(t0), no energy). Controls are per
    slot (row k: the k-th kite from the veered end), as the rigid mill's. The packed model's kite nodes and flags
    change at the transfers: ``kite_nodes`` holds their current indices.

    ``slot_attitudes`` (n_k, 3) [rad], optional: the attitude (roll, pitch, yaw) of the kite at each slot's place
    just after a kite transfer; then every step commands each kite the attitude interpolated linearly between its
    slot's and the next slot's (slot n_k - 1 to slot 0 round the station) by the cable phase, the cable moved since
    the last kite transfer over the piece length (angle differences taken in (-pi, pi]). A kite travels from one
    slot's place to the next in a period, so this follows the rigid mill's wings, whose attitude changes with the
    place on the loop; the controls are then overwritten every step."""

    def __init__(self, string: PointMassString, station: PointMassStation, x0: np.ndarray, controls: np.ndarray,
                 dt: float, method: str = "implicit", t0: float = 0.0, threads: int | None = None,
                 copy: bool = True, station_x: np.ndarray | None = None, slot_attitudes: np.ndarray | None = None):
        if string.end is None:
            raise ValueError("a moving cable needs two ground points (the string's end anchor)")
        if abs(station.element_length - string.element_length) > 1e-12 * string.element_length:
            raise ValueError(f"station.element_length = {station.element_length} m differs from the string's "
                             f"{string.element_length} m")
        check_pay_out_step(station, dt)
        super().__init__(string, x0, controls, dt, method, t0, threads, copy)
        # the transfers rewrite the kite nodes and flags in place: never the string's own array
        self.M = self.M._replace(knode=self.M.knode.copy(), kflag=self.M.kflag.copy())
        self.station = station
        self.sp = pack_pm_station(station)
        self.sx = station_state(station, t0) if station_x is None else np.array(station_x, dtype=float)
        if self.sx.shape != (MX_SIZE,):
            raise ValueError(f"station_x shape {self.sx.shape}: must be ({MX_SIZE},)")
        if not 0.0 <= self.sx[SX_MOVED] < station.element_length:
            raise ValueError(f"station_x moved = {self.sx[SX_MOVED]!r} m: must be in [0, l_e)")
        set_ends(self.M.par, self.sp, self.sx[SX_MOVED], station.speed(t0))
        self._string_advance = self._advance
        self._mill_step = mill_implicit_step_serial if self.kernel_threads == 1 else mill_implicit_step
        self._advance = self._mill_advance
        self.slot_attitudes = None
        self._first_node = int(string.kite_nodes[0]) if string.n_kites else 0
        self._per = int(np.diff(string.kite_nodes)[0]) if string.n_kites > 1 else string.n_nodes
        if slot_attitudes is not None:
            a = np.asarray(slot_attitudes, dtype=float)
            if a.shape != (string.n_kites, 3):
                raise ValueError(f"slot_attitudes shape {a.shape}: must be ({string.n_kites}, 3)")
            self.slot_attitudes = a
            d = np.roll(a, -1, axis=0) - a
            self._attitude_step = (d + np.pi) % (2.0 * np.pi) - np.pi

    def cable_phase(self) -> float:
        """Cable moved since the last kite transfer over the piece length [-], in [0, 1)."""
        m = (int(self.M.knode[0]) - self._first_node) % self._per
        return (m * self.station.element_length + self.moved()) / (self._per * self.station.element_length)

    def _command_attitudes(self) -> None:
        if self.slot_attitudes is not None:
            u = self.slot_attitudes + self.cable_phase() * self._attitude_step
            if int(self.M.knode[0]) < self._first_node:  # a kite has come round, the phase not yet restarted:
                u = np.roll(u, 1, axis=0)  # slot k holds the kite that the attitudes' slot k - 1 names
            self.u[:] = u.ravel()

    def _mill_advance(self, t, x, u, dt, nsteps, M, W):
        """Steps of the moving string: per step the station before, one step of the string (explicit: the string's
        own kernel; implicit: ``implicit.mill_implicit_step``, the string's step with the pay-out term on its
        right-hand side), the station after (``kernels/pointmass/mill.py``; the string kernels' parallel loops are
        called from Python: numba cannot cache a compiled caller of them). Returns (status, steps done)."""
        implicit = self.method == "implicit"
        for k in range(nsteps):
            tk = t + k * dt
            self._command_attitudes()
            t0, tn, v = mill_before(tk, x, M, self.sp, self.sx)
            if implicit:
                st = self._mill_step(tk, x, u, dt, M, W)
            else:
                st, _ = self._string_advance(tk, x, u, dt, 1, M, W)
            st = mill_after(tk, x, M, self.sp, self.sx, dt, t0, tn, v, st)
            if st != 0:
                return st, k + 1
        return 0, nsteps

    # ------------------------------------------------------------------ station read-outs
    def moved(self) -> float:
        """Cable moved since the last node transfer s [m]."""
        return float(self.sx[SX_MOVED])

    def transfers(self) -> int:
        """Node transfers so far (signed)."""
        return int(round(self.sx[SX_TRANSFERS]))

    def kite_transfers(self) -> int:
        """Kites gone round the station so far (signed): slot k holds kite (k - this) mod n_k."""
        return int(round(self.sx[MX_KITE_TRANSFERS]))

    def cable_speed(self) -> float:
        """V_c [m/s] at the current time."""
        return float(self.sx[SX_SPEED])

    def generator_energy(self) -> float:
        """Mechanical energy delivered to the generator so far [J]."""
        return float(self.sx[SX_ENERGY])

    def generator_power(self) -> dict[str, float]:
        """Tensions of the first and last elements [N], V_c [m/s], mechanical (T_first - T_last) V_c and electrical
        power [W] of the current state."""
        t0, tn = end_tensions(self.x, self.M)
        v = self.cable_speed()
        p = (t0 - tn) * v
        return {"tension_first_N": float(t0), "tension_last_N": float(tn), "cable_speed_m_s": v,
                "mechanical_W": float(p), "electrical_W": float(electrical_power(float(p), self.station.efficiency))}

    @property
    def kite_nodes(self) -> np.ndarray:
        """Current node index of each slot's kite (n_k,) (a view of the packed model)."""
        return self.M.knode

    def kite_positions(self) -> np.ndarray:
        """Kite positions per slot (n_k, 3) [m]."""
        return self.positions[self.M.knode].copy()

    def slot_kites(self) -> np.ndarray:
        """Which kite (its slot at the start) is in each slot (n_k,)."""
        nk = self.string.n_kites
        return (np.arange(nk) - self.kite_transfers()) % nk

    def rest_lengths(self) -> tuple[float, float]:
        """Unstretched lengths of the first and last elements [m]."""
        return float(self.M.par[PP_L_FIRST]), float(self.M.par[PP_L_LAST])

    def cable_length(self) -> float:
        """Unstretched cable between the two ground points [m]: first + last + (n - 1) l_e."""
        p = self.M.par
        return float(p[PP_L_FIRST] + p[PP_L_LAST] + (int(p[PP_N]) - 1) * p[PP_L0])

    def node_masses(self) -> np.ndarray:
        """Lumped node masses (n,) [kg] as the kernels use them (cable share plus kite)."""
        out = np.zeros(self.string.n_nodes)
        node_masses(self.M, out)
        return out

    def cable_mass(self) -> float:
        """Cable mass between the ground points [kg]: mu times :meth:`cable_length`."""
        return float(self.M.par[PP_MU]) * self.cable_length()
