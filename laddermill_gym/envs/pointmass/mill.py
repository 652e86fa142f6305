"""The moving cable (a scene with a ``station``, docs/pointmass.md "The moving cable") in the point-mass task: its
start, the rigid mill's periodic operating point mapped to the point-mass mill (``ladder/pointmass_mill.py``,
memoised per process), and :class:`PointMassMillBatch`, B copies of the
:class:`~laddermill_gym.sim.pointmass_mill.PointMassMillSimulator` with the interface of
:class:`~laddermill_gym.envs.pointmass.batch.PointMassBatch`.

Kites are relabelled as the cable moves through the station: everything here is per slot (slot k: the k-th kite
from the veered ground point), as the simulator's controls and the rigid ``LadderMill-v0``'s.
"""

from __future__ import annotations

import copy
import dataclasses

import numba
import numpy as np

from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.envs.pointmass.batch import check_fork_safe, thaw
from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, N3_VEL, PU_SIZE, SX_SPEED
from laddermill_gym.kernels.pointmass.explicit import CHUNK
from laddermill_gym.ladder.pointmass_scene import PointMassScene
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.sim.pointmass import PointMassError
from laddermill_gym.sim.pointmass_mill import PointMassMillSimulator

__all__ = ["MillStart", "mill_task_start", "PointMassMillBatch"]


@dataclasses.dataclass(frozen=True, eq=False)
class MillStart:
    """The moving cable's start: ``x0`` (6 n,) state, ``sx0`` (MX_SIZE,) station state, ``t0`` [s] its time on the
    station's speed schedule, ``attitudes`` (n_k, 3) [rad] the slots' attitude schedule (roll, pitch, yaw at each
    slot's place), ``mean_power_W`` the point-mass mill's mean mechanical generator power over the first period
    from this start [W] (its generator energy over the period's time), ``period_s`` l_piece / V_c [s]."""

    x0: np.ndarray
    sx0: np.ndarray
    t0: float
    attitudes: np.ndarray
    mean_power_W: float
    period_s: float


@input_cache(maxsize=4)
def mill_task_start(scene: str, options) -> tuple[PointMassScene, MillStart]:
    """(scene at the point-mass fidelity, :class:`MillStart`) of a moving-cable ``scene`` with ``load_scene``
    options ``options`` (a dict made hashable by ``batch.freeze``): the rigid mill's periodic operating point mapped
    to the point-mass mill (``ladder.pointmass_mill.periodic_mill_start``; the rigid run costs about 30 s, once per
    process), then one period of the point-mass mill from it for the mean power. Memoised per process; the arrays
    are read-only."""
    from laddermill_gym.ladder.pointmass_mill import periodic_mill_start

    sc = load_scene(scene, fidelity="pointmass", **thaw(options))
    x0, sx0, t0, att, _ = periodic_mill_start(sc)
    att = np.array(att, dtype=float).reshape(-1, PU_SIZE)
    sim = PointMassMillSimulator(sc.string, sc.station, x0, att.ravel(), sc.dt, sc.method, t0=t0, station_x=sx0,
                                 slot_attitudes=att)
    v = sim.cable_speed()
    if not v > 0:
        raise ValueError(f"scene {sc.name} ({sc.file}): V_c = {v!r} m/s at the periodic start (t = {t0} s): the "
                         "point-mass env needs a moving cable")
    nk = sc.string.n_kites
    per = int(np.diff(sc.string.kite_nodes)[0]) if nk > 1 else sc.string.n_nodes
    period = per * sc.station.element_length / v
    try:
        sim.advance(period, chunk=max(1, int(round(period / sc.dt))))
    except PointMassError as err:
        raise ValueError(f"scene {sc.name} ({sc.file}): the point-mass mill's first period from its operating point "
                         f"failed at the {sc.method} step of {sc.dt:g} s ({err}); pass a finer step, scene_options="
                         "{'dt': 0.01} (docs/pointmass_mill.md: the implicit step holds the first period's power "
                         "within 0.2 % from 10 ms to 50 ms at 70 m elements and fails at 0.1 s)") from None
    mean_power = sim.generator_energy() / (sim.t - t0)
    arrays = (np.array(x0, dtype=float), np.array(sx0, dtype=float), att)
    for a in arrays:
        a.setflags(write=False)
    return sc, MillStart(*arrays[:2], float(t0), arrays[2], float(mean_power), float(period))


class _EnvMillSimulator(PointMassMillSimulator):
    """The mill simulator whose commanded attitude is its slots' schedule plus ``offsets`` (n_k, 3) [rad] per slot
    (the actions' pitch and roll offsets)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.offsets = np.zeros((self.string.n_kites, PU_SIZE))

    def _command_attitudes(self) -> None:
        super()._command_attitudes()
        self.u += self.offsets.ravel()


class PointMassMillBatch:
    """B copies of a moving-cable point-mass scene, each a mill simulator started at ``start``
    (:class:`MillStart`): ``states`` (B, 6 n) (each copy's simulator state is a view of its row), ``offsets``
    (B, n_k, 3) [rad] the attitude offsets per slot, ``t`` (B,) [s] (absolute, on the station's speed schedule),
    ``status`` (B,) the last kernel status (PM_*), ``tension`` (B, n_e) [N] the damped element tensions,
    ``cable_speed`` (B,) V_c [m/s] from the station states, ``kite_nodes`` (B, n_k) each slot's current node."""

    def __init__(self, scene: PointMassScene, n_copies: int, start: MillStart):
        s = scene.string
        self.scene, self.string, self.start, self.n_copies = scene, s, start, int(n_copies)
        B = self.n_copies
        self.states = np.zeros((B, s.state_size))
        self.offsets = np.zeros((B, s.n_kites, PU_SIZE))
        self.t = np.zeros(B)
        self.status = np.zeros(B, dtype=np.int64)
        self.tension = np.zeros((B, s.n_elements))
        self.cable_speed = np.zeros(B)
        self.kite_nodes = np.zeros((B, s.n_kites), dtype=np.int64)
        self.sims: list[_EnvMillSimulator] = [None] * B  # type: ignore[list-item]
        self.threads = max(1, -(-s.n_nodes // CHUNK))
        for b in range(B):
            self.restart(b, None)

    def restart(self, b: int, field: WindField | None) -> None:
        """Copy ``b`` back at the start, offsets zero, with the air of ``field`` (its modulation shifted to start at
        the start time t0; None: the steady profile). A gust grid is refused: the kernels sample it at the absolute
        time, which starts at t0 here, past its fade-in."""
        check_fork_safe()
        st, sc = self.start, self.scene
        self.states[b] = st.x0
        sim = _EnvMillSimulator(self.string, sc.station, self.states[b], st.attitudes.ravel(), sc.dt, sc.method,
                                t0=st.t0, copy=False, station_x=st.sx0, slot_attitudes=st.attitudes)
        if field is not None:
            if field.grid is not None:
                raise ValueError(f"scene {sc.name} ({sc.file}): a gust grid in the disturbances; the moving cable "
                                 "starts at its operating point's time, and its env takes modulation disturbances only")
            tmod, ms, md, _, _ = pack_wind_field(dataclasses.replace(field, t0=field.t0 + st.t0))
            sim.M = sim.M._replace(tmod=tmod, ms=ms, md=md)
        self.sims[b] = sim
        self.offsets[b] = 0.0
        self.t[b] = st.t0
        self.status[b] = 0
        self._read(b)

    def _read(self, b: int) -> None:
        sim = self.sims[b]
        self.tension[b] = sim.tensions(True)
        self.cable_speed[b] = sim.sx[SX_SPEED]
        self.kite_nodes[b] = sim.kite_nodes

    def step(self, nsteps: np.ndarray) -> None:
        """Advance copy b by ``nsteps[b]`` steps of dt (0 or less: untouched) with its ``offsets``; its time by the
        steps done, its ``status`` to the kernel's (a failed copy stays at its failed step), tensions and slots."""
        check_fork_safe()
        before = numba.get_num_threads()
        numba.set_num_threads(min(self.threads, before))
        try:
            for b in np.flatnonzero(nsteps > 0):
                sim = self.sims[b]
                sim.offsets[:] = self.offsets[b]
                st, done = sim._advance(sim.t, sim.x, sim.u, sim.dt, int(nsteps[b]), sim.M, sim.W)
                sim.t += done * sim.dt
                self.t[b], self.status[b] = sim.t, st
                self._read(b)
        finally:
            numba.set_num_threads(before)

    def update_tensions(self, mask: np.ndarray) -> None:
        """Re-read tensions, speeds and slots of the copies in ``mask`` (B,) from their simulators."""
        for b in np.flatnonzero(mask):
            self._read(b)

    def _nodes(self, k: int) -> np.ndarray:
        return self.states.reshape(self.n_copies, -1, N3_SIZE)[np.arange(self.n_copies)[:, None], self.kite_nodes,
                                                                k:k + 3]

    def kite_positions(self) -> np.ndarray:
        """Kite positions per slot (B, n_k, 3) [m] (a copy)."""
        return self._nodes(N3_POS)

    def kite_velocities(self) -> np.ndarray:
        """Kite velocities per slot (B, n_k, 3) [m/s] (a copy)."""
        return self._nodes(N3_VEL)

    def kite_tensions(self) -> np.ndarray:
        """Tension of the element below each slot's kite (B, n_k) [N]."""
        return np.take_along_axis(self.tension, self.kite_nodes, axis=1)

    def simulator(self, b: int) -> PointMassMillSimulator:
        """An independent copy of copy ``b``'s mill simulator (state, station state, slots, air, offsets)."""
        return copy.deepcopy(self.sims[b])
