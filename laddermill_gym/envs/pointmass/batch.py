"""B copies of one point-mass scene (Podgaets & Ockels 2007) for the point-mass task: the start state (the
scene's own start, optionally settled in its steady wind, memoised per process) and :class:`PointMassBatch`, the
copies' states, controls, times and air, stepped by the kernels of ``kernels/pointmass/``.

The copies are B independent strings advanced one after another, each by one call of the compiled multi-step
kernel (``explicit_advance`` or ``implicit_advance``): there is no kernel that steps all copies in one call yet
(each copy has its own wind, which the point-mass kernels read from their packed model; a batched kernel would
take per-copy air arrays as the rigid ``kernels/batch.py`` does). The per-copy cost in Python is one kernel call
per control period.
"""

from __future__ import annotations

import numba
import numpy as np

from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, N3_VEL
from laddermill_gym.kernels.pointmass.explicit import (
    explicit_advance,
    explicit_advance_serial,
    tensions,
    tensions_serial,
)
from laddermill_gym.kernels.pointmass.implicit import implicit_advance, implicit_advance_serial
from laddermill_gym.ladder.pointmass_scene import PointMassScene
from laddermill_gym.ladder.scene import load_scene
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.model.memory import over_limit, pointmass_bytes
from laddermill_gym.model.pointmass import make_work, pack
from laddermill_gym.sim.pointmass import (
    PointMassError,
    PointMassSimulator,
    check_fork_safe,
    kernel_threads,
    run_on_threads,
)

__all__ = ["PointMassBatch", "pointmass_start", "POINTMASS_FAILURES", "check_fork_safe", "freeze", "thaw"]

#: Termination causes (code -> name), the wing envs' codes (``envs/task.py`` FAILURES); 0: still flying.
POINTMASS_FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state or speed limit)",
                                      2: "ground contact", 3: "cable over its breaking load"}


class _Frozen(tuple):
    """A dict (as its sorted (key, value) pairs) or a list, hashable, equal only to a frozen value of its own kind."""

    def __eq__(self, other):
        return type(self) is type(other) and tuple.__eq__(self, other)

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((type(self).__name__, tuple(self)))


class _FrozenDict(_Frozen):
    pass


class _FrozenList(_Frozen):
    pass


def freeze(value):
    """``value`` with every dict and list in it made hashable (the memoised starts' key: ``load_scene`` options
    such as ``overrides={"wind": {"v0": 10.0}}``); :func:`thaw` gives it back."""
    if isinstance(value, dict):
        return _FrozenDict(sorted((k, freeze(v)) for k, v in value.items()))
    if isinstance(value, list):
        return _FrozenList(freeze(v) for v in value)
    return value


def thaw(value):
    """The value :func:`freeze` was given (new dicts and lists)."""
    if isinstance(value, _FrozenDict):
        return {k: thaw(v) for k, v in value}
    if isinstance(value, _FrozenList):
        return [thaw(v) for v in value]
    return value


@input_cache(maxsize=8)
def pointmass_start(scene: str, options,
                    settle_time: float) -> tuple[PointMassScene, np.ndarray, np.ndarray, np.ndarray]:
    """(scene at the point-mass fidelity, start state (6 n,), controls (3 n_k,) [rad], element tensions (n_e,) [N]
    at the start, Voigt damping included) of ``scene`` with the ``load_scene`` options ``options`` (a dict made
    hashable by :func:`freeze`): the scene's own start
    (:meth:`~laddermill_gym.ladder.pointmass_scene.PointMassScene.initial_state`), then ``settle_time`` [s] of
    its own method and step in its steady wind with the start attitude held. Memoised per process (a chain's
    start solves the rigid statics, about a second; a forked process inherits it and so builds its env without a
    kernel call); the arrays are read-only."""
    sc = load_scene(scene, fidelity="pointmass", **thaw(options))
    x0, u0 = sc.initial_state()
    x0, u0 = np.array(x0, dtype=float), np.array(u0, dtype=float)
    if settle_time > 0:
        sim = PointMassSimulator(sc.string, x0, u0, sc.dt, sc.method)
        try:
            sim.advance(settle_time, chunk=1000)
        except PointMassError as err:
            raise ValueError(f"scene {sc.name} ({sc.file}): settle_time = {settle_time!r} s: settling failed "
                             f"({err})") from None
        x0 = sim.x.copy()
    work = make_work(sc.string)
    threads = kernel_threads(sc.string.n_nodes, numba.config.NUMBA_NUM_THREADS)
    run_on_threads(threads, tensions_serial, tensions, x0, pack(sc.string), work.tension, True)
    tension = work.tension.copy()
    for a in (x0, u0, tension):
        a.setflags(write=False)
    return sc, x0, u0, tension


class PointMassBatch:
    """B copies of a point-mass scene: ``states`` (B, 6 n), ``controls`` (B, 3 n_k) [rad], ``t`` (B,) [s],
    ``status`` (B,) the last kernel status (``kernels/contract.py`` PM_*), ``tension`` (B, n_e) [N] the
    element tensions (Voigt damping included) at the current states (after :meth:`update_tensions`), and one
    packed model per copy (``models``, the scene's string with that copy's air) and workspace (``works``)."""

    def __init__(self, scene: PointMassScene, n_copies: int):
        s = scene.string
        self.scene, self.string, self.n_copies = scene, s, int(n_copies)
        self.dt, self.method = float(scene.dt), scene.method
        #: numba threads of the kernels' parallel loops: one per CHUNK nodes (sim/pointmass.py's rule); 1: the
        #: serial kernels, which start no thread pool (a forked process can run them, issue 34 item 11)
        self.threads = kernel_threads(s.n_nodes, numba.config.NUMBA_NUM_THREADS)
        serial = self.threads == 1
        if self.method == "explicit":
            self._advance = explicit_advance_serial if serial else explicit_advance
        else:
            self._advance = implicit_advance_serial if serial else implicit_advance
        self._tensions = tensions_serial if serial else tensions
        B = self.n_copies
        why = over_limit(B * pointmass_bytes(s.n_nodes), f"{B} copies of a {s.n_nodes}-node string")
        if why is not None:  # checked before anything is allocated
            raise ValueError(f"num_envs = {n_copies!r}: {why}")
        self.states = np.zeros((B, s.state_size))
        self.controls = np.zeros((B, 3 * max(1, s.n_kites)))
        self.t = np.zeros(B)
        self.status = np.zeros(B, dtype=np.int64)
        self.tension = np.zeros((B, s.n_elements))
        self.models = [pack(s) for _ in range(B)]
        self.works = [make_work(s) for _ in range(B)]

    def set_wind(self, b: int, field: WindField) -> None:
        """The air of copy ``b``: a :class:`~laddermill_gym.atmosphere.field.WindField` (modulation from t = 0,
        optional gust grid) over the scene's steady profile."""
        tmod, ms, md, gp, gv = pack_wind_field(field)
        self.models[b] = self.models[b]._replace(tmod=tmod, ms=ms, md=md, gp=gp, gv=gv)

    def step(self, nsteps: np.ndarray) -> None:
        """Advance copy b by ``nsteps[b]`` steps of dt (0 or less: untouched); its time by the steps done, its
        ``status`` to the kernel's (a failed copy stays at the state of its failed step) and its ``tension``."""
        run_on_threads(self.threads, self._step, self._step, nsteps)

    def _step(self, nsteps: np.ndarray) -> None:
        for b in np.flatnonzero(nsteps > 0):
            st, done = self._advance(float(self.t[b]), self.states[b], self.controls[b], self.dt,
                                     int(nsteps[b]), self.models[b], self.works[b])
            self.t[b] += done * self.dt
            self.status[b] = st
            self._tension(b)

    def _tension(self, b: int) -> None:
        self._tensions(self.states[b], self.models[b], self.works[b].tension, True)
        self.tension[b] = self.works[b].tension

    def update_tensions(self, mask: np.ndarray) -> None:
        """Recompute ``tension`` of the copies in ``mask`` (B,) from their states. The kernels' parallel loops run
        on at most one thread per ``CHUNK`` nodes: waking the whole thread pool for a short string costs more than
        its work (measured: 6.7 ms per call for the 101-node chain on the shared two-core machine, against
        0.05 ms for two implicit steps on one thread)."""
        run_on_threads(self.threads, self._tensions_of, self._tensions_of, mask)

    def _tensions_of(self, mask: np.ndarray) -> None:
        for b in np.flatnonzero(mask):
            self._tension(b)

    def positions(self, nodes: np.ndarray) -> np.ndarray:
        """Positions (B, len(nodes), 3) [m] of the given nodes in every copy (a copy)."""
        return self.states.reshape(self.n_copies, -1, N3_SIZE)[:, nodes, N3_POS:N3_POS + 3].copy()

    def velocities(self, nodes: np.ndarray) -> np.ndarray:
        """Velocities (B, len(nodes), 3) [m/s] of the given nodes in every copy (a copy)."""
        return self.states.reshape(self.n_copies, -1, N3_SIZE)[:, nodes, N3_VEL:N3_VEL + 3].copy()

    def kite_positions(self) -> np.ndarray:
        """Kite positions (B, n_k, 3) [m] (a copy)."""
        return self.positions(self.string.kite_nodes)

    def kite_velocities(self) -> np.ndarray:
        """Kite velocities (B, n_k, 3) [m/s] (a copy)."""
        return self.velocities(self.string.kite_nodes)

    def kite_tensions(self) -> np.ndarray:
        """Tension of the element below each kite (B, n_k) [N]."""
        return self.tension[:, self.string.kite_nodes]

    def simulator(self, b: int) -> PointMassSimulator:
        """A :class:`~laddermill_gym.sim.pointmass.PointMassSimulator` of copy ``b``: a snapshot of its state,
        controls and time, with its air (shared arrays, never written), stepped by the same kernel."""
        sim = PointMassSimulator(self.string, self.states[b], self.controls[b], self.dt, self.method,
                                 t0=float(self.t[b]))
        sim.M = self.models[b]
        return sim
