"""Read-outs of the moving cable's ground station for :class:`~laddermill_gym.sim.simulator.Simulator` (a mixin):
cable speed, cable moved, transfers, generator power and energy, and the wing in each slot. A simulator whose
assembly has no station returns empty views and raises on the station read-outs.

Sign convention: V_c > 0 when the cable leaves the station on the veered (first, ascending) side and returns on
the hauled (last, descending) side; the generator's mechanical power P = (T_first - T_last) V_c with a prescribed
or a commanded speed, (Q / r) V_c with a drum (Q the generator torque [N m], r the drum radius [m]); P > 0 is
power delivered to the generator; the electrical power is the station's efficiency times P while generating and
P over the efficiency while motoring (P < 0; ``model/station.electrical_power``).
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.contract import SX_ENERGY, SX_MOVED, SX_SPEED, SX_TRANSFERS
from laddermill_gym.model.station import electrical_power

_STATION_NAMES = ("station moved [m]", "station transfers [-]", "station cable_speed [m/s]",
                  "station generator_energy [J]")


def station_state_name(j: int) -> str:
    """Name of entry j of the station block."""
    return _STATION_NAMES[j]


def station_control_labels(asm) -> list[str]:
    """Labels of the station's controls (the generator torque of a drum, or the commanded cable speed)."""
    if asm.station is None or not asm.station.n_controls:
        return []
    return ["generator_torque"] if asm.station.mode == "drum" else ["cable_speed_command"]


def check_station_controls(asm, u: np.ndarray) -> None:
    """Raise ValueError naming the value if the station's control (generator torque [N m] or commanded speed [m/s])
    is outside its limits."""
    st = asm.station
    if st is None or not st.n_controls:
        return
    q = float(u[-1])
    name, field, unit = (("generator_torque", "torque_limits", "N m") if st.mode == "drum"
                         else ("cable_speed_command", "speed_limits", "m/s"))
    lo, hi = getattr(st, field)
    if not np.isfinite(q) or q < lo or q > hi:
        raise ValueError(f"controls: {name} = {q!r} {unit} is outside station.{field} [{lo}, {hi}] {unit}")


class StationViews:
    """Station read-outs of a simulator (``self.assembly``, ``self.state``, ``self.t``, ``self.controls``,
    ``self.tensions()``)."""

    def _station(self) -> np.ndarray:
        a = self.assembly
        if a.station is None:
            raise ValueError(f"this assembly has no moving cable (no station): {getattr(self, 'name', 'scene')}")
        return self.state[a.body_state_size:]

    def cable_speed(self) -> float:
        """Cable speed V_c [m/s] now (the schedule's value, or the drum's state)."""
        st = self.assembly.station
        block = self._station()
        return st.speed(self.t) if st.mode == "prescribed" else float(block[SX_SPEED])  # drum, commanded: a state

    def cable_paid_out(self) -> float:
        """Cable moved through the station since t = 0 [m]: transfers x l0 + s - s(0) (s(0) = 0)."""
        block = self._station()
        return float(block[SX_TRANSFERS] * self.assembly.station.piece_length + block[SX_MOVED])

    def transfers(self) -> int:
        """Wing transfers so far (negative when the cable ran backwards)."""
        return int(round(self._station()[SX_TRANSFERS]))

    def slot_wings(self) -> np.ndarray:
        """Identity of the wing in each slot (n_wings,): slot k holds wing (k - transfers) mod n_wings (the wing
        leaving the hauled side re-enters on the veered side)."""
        n = self.assembly.n_wings
        return (np.arange(n) - self.transfers()) % n

    def generator_energy(self) -> float:
        """Mechanical energy delivered to the generator since t = 0 [J] (integrated with the state)."""
        return float(self._station()[SX_ENERGY])

    def generator_power(self) -> dict[str, float]:
        """Generator power now: tension difference T_first - T_last [N], cable speed [m/s], mechanical power [W]
        and electrical power [W] (efficiency times mechanical)."""
        st = self.assembly.station
        self._station()
        ten = self.tensions()
        dt = float(ten[0] - ten[-1])
        v = self.cable_speed()
        mech = float(self.controls[-1]) / st.drum_radius * v if st.mode == "drum" else dt * v
        return {"tension_difference_N": dt, "cable_speed_m_s": v, "mechanical_W": mech,
                "electrical_W": electrical_power(mech, st.efficiency)}

    def station_views(self) -> dict[str, np.ndarray]:
        """Named station views for recordings (empty without a station)."""
        if self.assembly.station is None:
            return {}
        p = self.generator_power()
        return {"cable_speed_m_s": np.array(p["cable_speed_m_s"]), "cable_paid_out_m": np.array(self.cable_paid_out()),
                "generator_power_W": np.array(p["mechanical_W"]),
                "generator_electrical_power_W": np.array(p["electrical_W"]),
                "generator_energy_J": np.array(self.generator_energy()), "slot_wing": self.slot_wings()}
