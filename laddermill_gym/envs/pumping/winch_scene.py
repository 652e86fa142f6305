"""The pumping kite's scene: a plain one-wing scene (``configs/scenes/pumping_kite.yaml``) with its tether's ground
end on a winch (``kernels/winch.py``), read from a pumping config (``configs/pumping/*.yaml``: ``scene``, ``winch``
and ``cycle`` sections), and the simulators that run it.

:class:`WinchSimulator` is a :class:`~laddermill_gym.sim.simulator.Simulator` of the winch assembly (its packed
model has the winch kind, as has a ``BatchSimulator``'s: ``model.packing.model_kind``). The station read-outs of
the simulator (``cable_speed``, ``cable_paid_out``, ``generator_energy``) apply unchanged (no transfers: the paid-out
tether is s); :meth:`WinchSimulator.winch_power` replaces the mill's ``generator_power`` (the drum feels T_0 alone).
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.envs.pumping.reel_start import reel_state
from laddermill_gym.kernels.contract import SX_MOVED, SX_SPEED
from laddermill_gym.kernels.reel import MIN_FRACTION as REEL_MIN_FRACTION
from laddermill_gym.kernels.winch import MIN_FRACTION
from laddermill_gym.ladder.scene import Scene, load_scene
from laddermill_gym.model.configio import ConfigError, config_path, read_yaml
from laddermill_gym.model.reel import (
    ReelSpec,
    drum_rest_length,
    ground_contacts,
    is_reel,
    read_reeling,
    station_nodes_in_air,
    with_reel,
)
from laddermill_gym.model.station import StationParams
from laddermill_gym.model.winch import read_winch, with_winch
from laddermill_gym.sim.simulator import Simulator

__all__ = ["CycleSpec", "PumpingScene", "WinchSimulator", "load_pumping", "electrical_energy"]


def electrical_energy(mechanical: np.ndarray | float, efficiency: float) -> np.ndarray:
    """Electrical energy [J] of mechanical energy increments at the drum [J]: eta E when generating (E > 0),
    E / eta when the motor reels in (E < 0) (Lansdorp et al. 2008 eq. 13)."""
    e = np.asarray(mechanical, dtype=float)
    return np.where(e > 0, efficiency * e, e / efficiency)


@dataclass(frozen=True)
class CycleSpec:
    """The scripted pumping cycle (Lansdorp et al. 2008): reel out at ``reel_out_factor`` times the wind along the
    tether at the wing until ``reel_length`` has been paid out, switch the angle of attack from ``alpha_out`` to
    ``alpha_in`` and keep reeling out until the drum tension has fallen below ``depower_tension`` (or another
    ``depower_overrun`` has been paid out), reel in at ``reel_in_speed`` until the tether is back at its start
    length, switch back, repeat (``control/pumping_cycle.py``; the depower wait is ours: docs/pumping.md).

    reel_out_factor [-], reel_length [m], reel_in_speed [m/s] (> 0, the speed of the tether coming in),
    alpha_out, alpha_in [rad] the angles of attack of the two phases (their elevators: the scene's trim and the
    tethered wing's pitch balance), depower_tension [N], depower_overrun [m].
    """

    reel_out_factor: float
    reel_length: float
    reel_in_speed: float
    alpha_out: float
    alpha_in: float
    depower_tension: float
    depower_overrun: float

    def __post_init__(self):
        for name in ("reel_out_factor", "reel_length", "reel_in_speed", "depower_tension", "depower_overrun"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"cycle.{name} = {v!r}: must be a finite number > 0")
        if not self.alpha_in < self.alpha_out:
            raise ValueError(f"cycle.alpha_in_deg = {math.degrees(self.alpha_in)!r}: must be below alpha_out_deg "
                             f"({math.degrees(self.alpha_out)!r}) (reel in at low lift)")


class WinchSimulator(Simulator):
    """A :class:`Simulator` of an assembly with a winch (``model.winch.with_winch``; ``model.packing`` gives it the
    winch kind) with the winch's read-out."""

    def cable_paid_out(self) -> float:
        """Tether paid out since t = 0 [m] (``SX_MOVED``; a reeling tether's ``SX_TRANSFERS`` counts nodes, not
        pieces)."""
        return float(self.state[self.assembly.body_state_size + SX_MOVED])

    def ground_contacts(self) -> int:
        """Tether nodes on the ground now (a reeling tether, ``model.reel.ground_contacts``; 0 otherwise)."""
        return ground_contacts(self.assembly, self.state) if is_reel(self.assembly.station) else 0

    def limit_cause(self, h: float) -> str | None:
        """The winch's own limit, if the failed step of h [s] from the current state broke it (a physical end of
        reeling in, reported by the integrator's LIMIT status as a speed or rate limit would be; ``sim.reports``
        names it): :func:`winch_limit_text` of the step taken without any check (:func:`unchecked_step`); None
        where the step cannot be evaluated."""
        try:
            x = unchecked_step(self, h)
        except (ValueError, ArithmeticError):
            return None
        return winch_limit_text(self.assembly.station, self.t + h, x, self.assembly.body_state_size)

    def winch_power(self) -> dict[str, float]:
        """The winch now: tension of the tether at the drum T_0 [N], winch speed V [m/s] (> 0 reeling out),
        mechanical power at the drum [W] ((Q / r) V with a drum, T_0 V otherwise) and electrical power [W]
        (eta P generating, P / eta reeling in)."""
        st = self.assembly.station
        t0 = float(self.tensions()[0])
        v = self.cable_speed()
        mech = float(self.controls[-1]) / st.drum_radius * v if st.mode == "drum" else t0 * v
        return {"tension_N": t0, "speed_m_s": v, "mechanical_W": mech,
                "electrical_W": float(electrical_energy(mech, st.efficiency))}


def unchecked_step(sim, h: float) -> np.ndarray:
    """The state one classic RK4 step of h [s] after the simulator's, with no check at all (the right-hand side
    ``sim.rhs``): where a failed step would have gone."""
    x0, t = sim.state, sim.t
    k1 = sim.rhs(t, x0)
    k2 = sim.rhs(t + 0.5 * h, x0 + 0.5 * h * k1)
    k3 = sim.rhs(t + 0.5 * h, x0 + 0.5 * h * k2)
    k4 = sim.rhs(t + h, x0 + h * k3)
    return x0 + h / 6.0 * (k1 + 2.0 * (k2 + k3) + k4)


def winch_limit_text(winch: StationParams, t: float, x: np.ndarray, xoff: int) -> str | None:
    """The sentence on a winch element reeled in below ``MIN_FRACTION`` of its start length (``kernels/winch.py``'s
    physical limit) in the state x at time t [s] (station entries from ``xoff``), with the rest length [m] and the
    winch speed [m/s]; None when it is not. On a reeling tether (``kernels/reel.py``) its own end stop: the drum
    element, with no node left in the air to merge, under its ``MIN_FRACTION`` of the element length."""
    if is_reel(winch):
        return reel_limit_text(winch, t, x, xoff)
    start = winch.piece_length * winch.first_fraction
    rest = start + x[xoff + SX_MOVED]
    if not rest < MIN_FRACTION * winch.piece_length:
        return None
    return (f"the winch reeled the tether's first element in to a rest length of {rest:.6g} m at t = {t:.6g} s, "
            f"below {100 * MIN_FRACTION:g} % of its start length {start:.4g} m ({MIN_FRACTION * winch.piece_length:.4g}"
            f" m), winch speed {x[xoff + SX_SPEED]:.4g} m/s")


def reel_limit_text(winch, t: float, x: np.ndarray, xoff: int) -> str | None:
    """The reeling tether's end stop (``kernels/reel.relabel``'s LIMIT) in the state x at time t [s]: the drum element
    (rest length l_d = l_p + s - m l_n) under ``MIN_FRACTION`` of the element length l_n with only one node in the
    air; None when it is not."""
    ln, rest = winch.reel.element_length, drum_rest_length(winch, x, xoff)
    if station_nodes_in_air(winch, x, xoff) >= 2 or not rest < REEL_MIN_FRACTION * ln:
        return None
    return (f"the winch reeled the tether in to its last element: the drum element's rest length {rest:.6g} m at "
            f"t = {t:.6g} s is below {100 * REEL_MIN_FRACTION:g} % of the element length {ln:.4g} m "
            f"({REEL_MIN_FRACTION * ln:.4g} m), winch speed {x[xoff + SX_SPEED]:.4g} m/s")


@dataclass(frozen=True)
class PumpingScene:
    """A pumping config loaded: the plain scene (``scene``, no winch: its trim and the lateral LQR's design), the
    winch (station parameters of ``model/winch.py``), the cycle, the config's file."""

    file: Path
    scene: Scene
    winch: StationParams
    cycle: CycleSpec
    reel: ReelSpec | None = None
    base: Scene | None = None

    @property
    def assembly(self):
        """The assembly with the winch (on a reeling tether with ``reel``: ``model.reel.with_reel``)."""
        if self.reel is not None:
            return with_reel(self.scene.assembly, self.winch, self.reel, self.scene.settings.ground_height)
        return with_winch(self.scene.assembly, self.winch)

    def replace_winch(self, **changes) -> PumpingScene:
        return dataclasses.replace(self, winch=dataclasses.replace(self.winch, **changes))

    def trim(self, alpha: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(state, wing controls) of the plain scene trimmed at angle of attack ``alpha`` [rad] (default: the
        scene's), the tether held (no winch)."""
        sc = self.scene if self.base is None else self.base
        if alpha is not None:
            sc = sc.replace(initial=dataclasses.replace(sc.initial, alpha=float(alpha)))
        return sc.initial_state()

    def initial_state(self) -> tuple[np.ndarray, np.ndarray]:
        """(state, controls) with the winch: the trim at ``cycle.alpha_out``, the winch block (nothing paid out,
        the winch's initial speed, no energy) and the winch control (0 torque or the initial speed command)."""
        from laddermill_gym.model.station import station_initial

        x, u = self.trim(self.cycle.alpha_out)
        w = self.winch
        cmd = w.speed_values[0] if w.mode == "commanded" else 0.0
        tail = np.array([cmd] if w.n_controls else [])
        if self.reel is not None:  # the wing of the single-element trim, the nodes on the catenary
            return reel_state(self.assembly, x, station_initial(w)), np.concatenate([u, tail])
        return np.concatenate([x, station_initial(w)]), np.concatenate([u, tail])

    def simulator(self, initial_state=None, controls=None) -> WinchSimulator:
        if initial_state is None:
            initial_state, c0 = self.initial_state()
            controls = c0 if controls is None else controls
        return WinchSimulator(self.assembly, initial_state, self.scene.settings, controls)


def load_pumping(name_or_path: str | Path = "pumping_kite", **scene_overrides) -> PumpingScene:
    """Read a pumping config (``configs/pumping/NAME.yaml`` or a path): ``scene`` (a scene name or path, loaded by
    ``load_scene`` with ``scene_overrides``), ``winch`` (``model.winch.read_winch``) and ``cycle``."""
    path = config_path("pumping", name_or_path)
    reel_changes = scene_overrides.pop("reeling", None) or {}  # ReelSpec fields (a dict, or its JSON: options_key)
    reel_changes = json.loads(reel_changes) if isinstance(reel_changes, str) else dict(reel_changes)
    s = read_yaml(path)
    scene_ref = s.text("scene")
    try:
        sc = load_scene(config_path("scenes", scene_ref, path.parent), **scene_overrides)
    except ConfigError as err:
        raise ConfigError(f"{path}: field 'scene' = {scene_ref!r}: {err}") from None
    first = float(sc.assembly.elements.l0[0])
    winch = read_winch(s.section("winch"), first)
    reel, base = None, None
    if reel_changes and not s.has("reeling"):
        raise ConfigError(f"{path}: reeling overrides {reel_changes!r} given, but the config has no 'reeling' section")
    if s.has("reeling"):  # a reeling multi-element tether (model/reel.py): the scene in its longest chain's elements
        reel, base = read_reeling(s.section("reeling")), sc
        try:
            reel = dataclasses.replace(reel, **reel_changes)
            total = reel.layout(float(sc.assembly.elements.l0.sum()))[0]
        except (TypeError, ValueError) as err:
            raise ConfigError(f"{path}: {err}") from None
        extra = {"elements_per_piece": total, **({"dt": reel.dt} if reel.dt is not None else {})}
        sc = load_scene(config_path("scenes", scene_ref, path.parent), **{**scene_overrides, **extra})
    c = s.section("cycle")
    try:
        cycle = CycleSpec(reel_out_factor=c.number("reel_out_factor", positive=True),
                          reel_length=c.number("reel_length", positive=True),
                          reel_in_speed=c.number("reel_in_speed", positive=True),
                          alpha_out=math.radians(c.number("alpha_out_deg")),
                          alpha_in=math.radians(c.number("alpha_in_deg")),
                          depower_tension=c.number("depower_tension", positive=True),
                          depower_overrun=c.number("depower_overrun", positive=True))
    except ValueError as err:
        raise ConfigError(f"{path}: {err}") from None
    c.done()
    s.done()
    return PumpingScene(file=path, scene=sc, winch=winch, cycle=cycle, reel=reel, base=base)
