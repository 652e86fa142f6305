"""The laddermill at the point-mass fidelity: its start and its periodic motion (docs/pointmass.md, "The moving
cable").

Start (:func:`mill_start`): the rigid mill's static equilibrium at rest of the same file (``ladder/fidelity.py``),
the kites at the wings' CG positions with their attitudes commanded, the string's nodes on the straight lines
between kites and ground points at their material positions, everything at rest, t = 0; the file's speed
schedule then ramps the cable up (as the rigid mill's own start). :func:`run_pointmass_periodic` runs it period
by period to its periodic motion with the rigid :func:`~laddermill_gym.ladder.periodic.run_to_periodic`'s
criteria.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, N3_VEL, PU_SIZE
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.sim.pointmass import PointMassError


def string_along_material(string, station, kite_positions: np.ndarray, moved: float = 0.0,
                          end_values=None) -> np.ndarray:
    """State (6 n,) at rest with the kites at ``kite_positions`` (n_k, 3) [m] and every node on the straight line
    between its neighbouring kites (or ground points) at its share of the unstretched cable (node j at
    a + s + j l_e from the veered ground point): the pieces next to the ground points have ends of other lengths.
    ``end_values`` (two 3-vectors) replaces the ground points' positions (to interpolate velocities the same way)."""
    le = string.element_length
    sig = station.first_length + moved + le * np.arange(string.n_nodes)
    kn = string.kite_nodes
    g0, g1 = (string.anchor, string.end) if end_values is None else end_values
    corners = np.vstack([g0, kite_positions, g1])
    sc = np.concatenate([[0.0], sig[kn], [sig[-1] + station.last_length - moved]])
    x = np.zeros(string.state_size)
    xs = x.reshape(-1, N3_SIZE)
    for i in range(3):
        xs[:, N3_POS + i] = np.interp(sig, sc, corners[:, i])
    return x


def mill_start(pm_scene) -> tuple[np.ndarray, np.ndarray]:
    """(state, controls): the rigid mill's static equilibrium at rest mapped to the point-mass mill (module doc),
    the kites at the wings' cable attachment points (not their CG as ``ladder/fidelity.py`` does for fixed scenes:
    at one element per piece the first element is 7 m long, and the 1.5 m from CG to attachment would stretch it
    by 20 %)."""
    from laddermill_gym.ladder.fidelity import rigid_static

    sim, _ = rigid_static(pm_scene)
    u = np.ascontiguousarray(sim.wing_euler().reshape(-1, PU_SIZE).ravel())
    att = np.array([sim.assembly.wing(k).attachment for k in range(sim.assembly.n_wings)])
    points = sim.wing_positions() + np.einsum("kij,kj->ki", sim.wing_rotations(), att)
    return string_along_material(pm_scene.string, pm_scene.station, points), u


@dataclass
class PointMassPeriodic:
    """What :func:`run_pointmass_periodic` found (the rigid ``PeriodicResult``'s quantities).

    converged : shape and power repeated for ``confirm`` periods.  period_s : l0 / V_c [s].  t_s : end time [s].
    mean_power_W : mean mechanical generator power over the last period [W] (its energy / its time).
    tension_first_N, tension_last_N : mean tensions of the first and last element over the last period [N].
    tension_kites_N : (n_k,) mean tension of the element below each slot's kite over the last period [N].
    shape_m : kite positions per slot at the last kite transfer (n_k, 3) [m].
    history : per period: time [s], mean power [W], shape change [-], power change [-].
    breakdown : the step's error when the motion broke down, else None.
    """

    converged: bool
    period_s: float
    t_s: float
    mean_power_W: float
    tension_first_N: float
    tension_last_N: float
    tension_kites_N: np.ndarray
    shape_m: np.ndarray
    history: list[dict] = field(default_factory=list)
    breakdown: str | None = None

    def summary(self) -> str:
        state = "converged" if self.converged else f"NOT converged ({self.breakdown or 'time limit'})"
        k = int(np.argmin(self.tension_kites_N))
        return (f"point-mass periodic motion {state} at t = {self.t_s:.1f} s (period {self.period_s:.2f} s): mean "
                f"power {self.mean_power_W / 1e3:.1f} kW, first element {self.tension_first_N / 1e3:.1f} kN, last "
                f"{self.tension_last_N / 1e3:.1f} kN, smallest mean tension {self.tension_kites_N[k] / 1e3:.1f} kN "
                f"(below slot {k})")


def _to_kite_transfer(sim, max_steps: int, record=None) -> None:
    n0 = sim.kite_transfers()
    for _ in range(max_steps):
        sim.step()
        if record is not None:
            record(sim)
        if sim.kite_transfers() != n0:
            return
    raise RuntimeError(f"t = {sim.t:.3f} s: no kite transfer within {max_steps} steps (V_c = {sim.cable_speed()} m/s)")


def run_pointmass_periodic(sim, shape_tol: float = 1e-3, power_tol: float = 1e-3, confirm: int = 2,
                           max_time: float = 3000.0) -> PointMassPeriodic:
    """Run a :class:`~laddermill_gym.sim.pointmass_mill.PointMassMillSimulator` past its speed ramp, then period by
    period (kite transfer to kite transfer) until the kite positions per slot change by less than ``shape_tol``
    piece lengths and the period's mean power by less than ``power_tol`` relative, ``confirm`` times in a row."""
    st = sim.station
    if sim.t < st.speed_times[-1]:
        sim.advance(st.speed_times[-1] - sim.t)
    v = sim.cable_speed()
    if not v > 0:
        raise ValueError(f"V_c = {v!r} m/s at t = {sim.t} s: the periodic motion needs V_c > 0")
    piece = st.element_length * (np.diff(sim.kite_nodes)[0] if sim.string.n_kites > 1 else sim.string.n_nodes)
    period = float(piece / v)
    steps = int(np.ceil(2 * period / sim.dt))
    _to_kite_transfer(sim, steps)
    t_start, shape, energy, t_prev = sim.t, sim.kite_positions(), sim.generator_energy(), sim.t
    history, hits, p_prev, breakdown = [], 0, np.nan, None
    sums = {}

    def record(s):
        te = s.tensions()
        sums["first"] = sums.get("first", 0.0) + te[0]
        sums["last"] = sums.get("last", 0.0) + te[-1]
        sums["kites"] = sums.get("kites", 0.0) + te[s.kite_nodes]
        sums["n"] = sums.get("n", 0) + 1

    last = dict(sums)
    while sim.t - t_start < max_time:
        sums.clear()
        try:
            _to_kite_transfer(sim, steps, record)
        except PointMassError as err:
            breakdown = str(err)
            break
        last = dict(sums)
        new_shape, e = sim.kite_positions(), sim.generator_energy()
        p = (e - energy) / (sim.t - t_prev)
        d_shape = float(np.max(np.linalg.norm(new_shape - shape, axis=1)) / piece)
        d_power = abs(p - p_prev) / max(abs(p), 1e-12)
        history.append({"t_s": sim.t, "mean_power_W": p, "shape_change": d_shape, "power_change": d_power})
        hits = hits + 1 if (d_shape < shape_tol and d_power < power_tol) else 0
        shape, energy, t_prev, p_prev = new_shape, e, sim.t, p
        if hits >= confirm:
            break
    n = max(last.get("n", 0), 1)
    nk = sim.string.n_kites
    return PointMassPeriodic(
        converged=breakdown is None and hits >= confirm, period_s=period, t_s=sim.t,
        mean_power_W=history[-1]["mean_power_W"] if history else float("nan"),
        tension_first_N=last.get("first", np.nan) / n, tension_last_N=last.get("last", np.nan) / n,
        tension_kites_N=np.asarray(last.get("kites", np.full(nk, np.nan))) / n, shape_m=shape, history=history,
        breakdown=breakdown)


def rigid_periodic(file: str, n_wings: int, overrides: str = "null"):
    """The rigid mill's periodic start of a scene file with the nested overrides ``overrides`` (canonical JSON:
    :func:`overrides_key`; read by ``ladder.fidelity.load_rigid_of``) (``ladder/periodic.periodic_start``; about 30
    s, once per process and key): (rigid simulator at that state, its time [s], PeriodicResult)."""
    return _rigid_periodic(str(file), int(n_wings), overrides)


@input_cache(maxsize=4)
def _rigid_periodic(file: str, n_wings: int, overrides: str):
    from laddermill_gym.ladder.fidelity import load_rigid_of
    from laddermill_gym.ladder.periodic import periodic_start

    rigid = load_rigid_of(file, n_wings, json.loads(overrides))
    x, u, t, res = periodic_start(rigid, progress=False)
    return rigid.simulator(x, u), t, res


def overrides_key(pm_scene) -> str:
    """A point-mass scene's overrides as canonical JSON (sorted keys), :func:`rigid_periodic`'s cache key."""
    return json.dumps(pm_scene.overrides, sort_keys=True)


def periodic_mill_start(pm_scene):
    """The rigid mill's periodic operating point mapped to the point-mass mill: kites at the wings' cable
    attachment points with the attachments' velocities, nodes along the material between them with velocities
    interpolated the same way (the ground points' as the cable's pay-out V_c along the end elements), the cable
    moved and the time of the rigid state, the slots' attitudes for the simulator's attitude schedule.
    Returns (state, station state, time [s], slot attitudes (n_k, 3) [rad], rigid PeriodicResult)."""
    from laddermill_gym.kernels.contract import SX_MOVED
    from laddermill_gym.model.pointmass_mill import station_state

    sim, t0, res = rigid_periodic(str(pm_scene.file), pm_scene.string.n_kites, overrides_key(pm_scene))
    a = sim.assembly
    att = np.array([a.wing(k).attachment for k in range(a.n_wings)])
    rot = sim.wing_rotations()
    vb = sim.wing_velocities() + np.cross(sim.wing_rates(), att)
    points = sim.wing_positions() + np.einsum("kij,kj->ki", rot, att)
    vel = np.einsum("kij,kj->ki", rot, vb)
    moved = float(sim.state[a.body_state_size + SX_MOVED])
    string, st = pm_scene.string, pm_scene.station
    if not 0.0 <= moved < st.element_length:
        raise ValueError(f"the rigid periodic state has moved the cable {moved} m: not below l_e = {st.element_length}")
    x = string_along_material(string, st, points, moved)
    v = st.speed(t0)
    up, down = points[0] - string.anchor, string.end - points[-1]  # the pay-out's directions at the ground points
    gv = (v * up / np.linalg.norm(up), v * down / np.linalg.norm(down))
    vx = string_along_material(string, st, vel, moved, end_values=gv)
    xs, vs = x.reshape(-1, N3_SIZE), vx.reshape(-1, N3_SIZE)
    xs[:, N3_VEL:N3_VEL + 3] = vs[:, N3_POS:N3_POS + 3]
    return x, station_state(st, t0, moved), t0, sim.wing_euler(), res


def mill_simulator(pm_scene, start: str = "periodic", dt: float | None = None, method: str | None = None):
    """A :class:`~laddermill_gym.sim.pointmass_mill.PointMassMillSimulator` of a point-mass mill scene.

    start 'periodic' (the default): the rigid mill's periodic operating point (:func:`periodic_mill_start`, the
    rigid run costs about 30 s once per process), the kites' attitudes following the rigid wings' along the loop
    (the simulator's slot attitudes). 'static': the rigid static equilibrium at rest at t = 0 (:func:`mill_start`),
    the file's speed ramp ahead, every kite holding its slot's attitude at rest (a point-mass kite does not
    weathercock: moving with the cable its angle of attack changes by atan(V_c / wind), docs/pointmass.md)."""
    from laddermill_gym.sim.pointmass_mill import PointMassMillSimulator

    dt = pm_scene.dt if dt is None else dt
    method = pm_scene.method if method is None else method
    if start == "static":
        x, u = mill_start(pm_scene)
        return PointMassMillSimulator(pm_scene.string, pm_scene.station, x, u, dt, method, copy=False)
    if start != "periodic":
        raise ValueError(f"start = {start!r}: must be 'periodic' or 'static'")
    x, sx, t0, att, _ = periodic_mill_start(pm_scene)
    return PointMassMillSimulator(pm_scene.string, pm_scene.station, x, att.ravel(), dt, method, t0=t0, copy=False,
                                  station_x=sx, slot_attitudes=att)
