"""Scenes at the point-mass fidelity (Podgaets & Ockels 2007): a YAML file with ``fidelity: {wing: pointmass}``
read into a :class:`~laddermill_gym.model.pointmass.PointMassString`, the kites' commanded attitude, the
integrator settings and a quasi-static start. The wind, wing-type and cable sections are those of the rigid
scenes (``ladder/scene.py``); see configs/scenes/podgaets_5km.yaml for a commented example."""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.kernels.contract import N3_POS, N3_SIZE
from laddermill_gym.kernels.pointmass.forces import kite_force
from laddermill_gym.kernels.wind import density, wind_point
from laddermill_gym.ladder.bounds import BOUNDS
from laddermill_gym.ladder.scene_files import (
    check_cable_length,
    open_scene,
    read_ground_points,
    read_parts,
    read_station,
    read_wind,
)
from laddermill_gym.model.configio import ConfigError, Section
from laddermill_gym.model.memory import over_limit, pointmass_bytes
from laddermill_gym.model.pointmass import PointMassKite, PointMassString, attitude_controls, pack
from laddermill_gym.model.pointmass_mill import PointMassStation, mill_layout, station_from_rigid
from laddermill_gym.sim.breakpoints import INTEGRATOR_METHODS
from laddermill_gym.sim.pointmass import METHODS, PointMassSimulator
from laddermill_gym.sim.pointmass_mill import PointMassMillSimulator, check_pay_out_step


@dataclass(frozen=True)
class PointMassScene:
    """A loaded point-mass scene: the string, the kites' attitude (n_k * 3,) [rad], the method and step."""

    name: str
    file: Path
    description: str
    string: PointMassString
    controls: np.ndarray
    method: str
    dt: float
    piece_length: float
    #: The moving cable's station (a scene with ``station:``, docs/pointmass.md "The moving cable"), else None.
    station: PointMassStation | None = None
    #: ``load_scene``'s nested ``overrides`` merged into the file (None: none): the starts taken from the rigid
    #: model read the file with them (``ladder/fidelity.py``, ``ladder/pointmass_mill.py``).
    overrides: dict | None = None

    @property
    def n_wings(self) -> int:
        return self.string.n_kites

    def initial_state(self) -> tuple[np.ndarray, np.ndarray]:
        """(state, controls): a free upper end starts quasi-static at the file's attitude; a chain between two
        ground points starts from the rigid fidelity's static equilibrium of the same file (its wings' CG
        positions and attitudes, ``ladder/fidelity.py``); a moving cable from the same equilibrium with the kites
        at the rigid wings' cable attachment points (``ladder/pointmass_mill.py``). A moving cable's
        :meth:`simulator` starts from the rigid mill's periodic operating point instead."""
        if self.station is not None:
            from laddermill_gym.ladder.pointmass_mill import mill_start

            return mill_start(self)  # the simulator's default start is the periodic one (mill_simulator)
        if self.string.end is None:
            return quasi_static_state(self.string, self.controls), self.controls
        from laddermill_gym.ladder.fidelity import pointmass_from_rigid

        return pointmass_from_rigid(self)

    def simulator(self, x0: np.ndarray | None = None, controls: np.ndarray | None = None,
                  method: str | None = None, dt: float | None = None) -> PointMassSimulator:
        fresh = x0 is None
        if fresh and self.station is not None:  # the rigid mill's periodic operating point (ladder/pointmass_mill)
            from laddermill_gym.ladder.pointmass_mill import mill_simulator

            return mill_simulator(self, "periodic", dt, method)
        if fresh:
            x0, c0 = self.initial_state()
            controls = c0 if controls is None else controls
        if self.station is not None:
            return PointMassMillSimulator(self.string, self.station, x0, self.controls if controls is None else
                                          controls, self.dt if dt is None else dt,
                                          self.method if method is None else method, copy=not fresh)
        return PointMassSimulator(self.string, x0, self.controls if controls is None else controls,
                                  self.dt if dt is None else dt, self.method if method is None else method,
                                  copy=not fresh)


def read_pointmass(s: Section, fid: Section, path: Path, *, element_length: float | None = None,
                   n_kites: int | None = None, dt: float | None = None, method: str | None = None,
                   cable_aero: bool | None = None, overrides: dict | None = None) -> PointMassScene:
    """Build a point-mass scene from a scene file already opened as ``s`` (with ``overrides`` merged in, kept on the
    scene for the starts taken from the rigid model) whose ``fidelity`` section ``fid`` says ``wing: pointmass``
    (the caller has read ``name``-independent keys it owns)."""
    name, desc = s.text("name"), s.text("description", "")
    if s.number("dimension", 3, integer=True) != 3:
        raise s.error("dimension", s.data.get("dimension"), "the point-mass fidelity is 3D only")
    gravity = s.number("gravity", positive=True, **BOUNDS["gravity"])
    wind = read_wind(s.section("wind"))
    wing, cable = read_parts(s, path)
    points = read_ground_points(s)
    ch = s.section("chain")
    start, end = ch.text("start"), ch.text("end", None)
    nk = ch.number("n_wings", integer=True, positive=True)
    piece = ch.number("piece_length", positive=True)
    ch.raw("elements_per_piece", None)  # the rigid fidelity's subdivision; element_length replaces it
    ch.done()
    for key, pname in (("start", start), ("end", end)):
        if pname is not None and pname not in points:
            raise ch.error(key, pname, f"is not one of the ground points {sorted(points)}")
    # a station without ``insertion`` keeps the point-mass mill's own rule: the node moves with the cable it joins
    rigid_station = read_station(s.section("station"), piece, "cable") if s.has("station") else None
    if rigid_station is not None and end is None:
        raise ch.error("end", end, "a moving cable (station) needs two ground points (start and end)")
    el, caero = _read_fidelity(fid, path, element_length, cable_aero)
    if not caero:  # the rigid fidelity's switch of the cable's aerodynamics: no drag on the string
        cable = dataclasses.replace(cable, cn0=0.0, ct0=0.0)
    ini = s.section("initial")
    pitch0 = ini.number("alpha_deg", 0.0, **BOUNDS["initial.alpha_deg"])  # a rigid scene's trim alpha: the pitch
    att = [math.radians(ini.number(k, d, **BOUNDS["attitude_deg"]))
           for k, d in (("roll_deg", 0.0), ("pitch_deg", pitch0), ("yaw_deg", 0.0))]
    for key in ("method", "elevation_deg", "elevator_up_deg", "elevator_down_deg", "top_slots", "elevator_top_deg"):
        ini.raw(key, None)  # the rigid fidelity's start: the point-mass start is quasi-static
    ini.done()
    meth, step, vmax, hg = _read_integrator(s.section("integrator"), path, method, dt)
    s.done()
    nk = nk if n_kites is None else int(n_kites)
    check_cable_length(ch, piece, nk, end is not None, cable, gravity, n_kites is not None)
    per = piece / el
    if abs(per - round(per)) > 1e-6 * per or round(per) < 1:
        raise fid.error("element_length", el, f"must divide the piece length {piece} m into whole elements")
    per = int(round(per))
    _check_nodes(fid, ch, path, per * (nk + 1), el, nk, element_length is not None, n_kites is not None)
    n_nodes = per * nk + (per - 1 if end is not None else 0)
    kite_nodes = np.arange(1, nk + 1, dtype=np.int64) * per - 1
    station = None
    if rigid_station is not None:  # the moving cable: the layout that holds the rigid mill's cable
        lay = mill_layout(nk, piece, el, rigid_station.first_fraction, rigid_station.last_fraction)
        n_nodes, kite_nodes = lay.n_nodes, lay.kite_nodes
        try:
            station = station_from_rigid(rigid_station, lay, el)
            check_pay_out_step(station, step)
        except ValueError as err:
            raise ConfigError(f"{path}: {err}") from None
    string = PointMassString(wind=wind, gravity=gravity, cable=cable, element_length=el, n_nodes=n_nodes,
                             anchor=points[start], end=None if end is None else points[end],
                             kite=PointMassKite.from_wing(wing), kite_nodes=kite_nodes, ground_height=hg,
                             max_speed=vmax)
    return PointMassScene(name=name, file=path, description=desc, string=string,
                          controls=attitude_controls(nk, *att), method=meth, dt=step, piece_length=piece,
                          station=station, overrides=_with_cable_aero(overrides, cable_aero))


def _with_cable_aero(overrides: dict | None, cable_aero: bool | None) -> dict | None:
    """The nested overrides a point-mass scene keeps for its rigid start, with the ``cable_aero`` keyword folded in
    as ``fidelity.cable_aero``: the rigid start read the file's drag while the string had none (review of
    2026-12-08)."""
    if cable_aero is None:
        return overrides or None
    merged = dict(overrides or {})
    merged["fidelity"] = {**(merged.get("fidelity") or {}), "cable_aero": cable_aero}
    return merged


def _override(path: Path, key: str, value) -> float:
    """The keyword override ``key`` = ``value`` as a float; ConfigError naming the file, the override and the value
    unless it is a finite number > 0 (a step below the file's bound of 1 ns stays allowed: the explicit step of a
    1 cm string is 0.69 ns)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not (math.isfinite(value) and value > 0):
        raise ConfigError(f"{path}: {key} = {value!r} (override): must be a finite number > 0")
    return float(value)


def _read_fidelity(fid: Section, path: Path, element_length, cable_aero) -> tuple[float, bool]:
    """(element length [m], cable aerodynamics on) from the ``fidelity`` section or their keyword overrides."""
    fid.raw("wing", None)
    if element_length is None:
        el = fid.number("element_length", positive=True)
    else:
        fid.raw("element_length", None)
        el = _override(path, "element_length", element_length)
    fid.flag("sag", True)  # the rigid fidelity's sag correction: the string resolves its own sag
    caero = fid.flag("cable_aero", True)
    if cable_aero is not None:
        if not isinstance(cable_aero, bool):
            raise ConfigError(f"{path}: cable_aero = {cable_aero!r} (override): must be True or False")
        caero = cable_aero
    fid.done()
    return el, caero


def _read_integrator(it: Section, path: Path, method, dt) -> tuple[str, float, float, float]:
    """(method, dt [s], max_speed [m/s], ground height [m]: -inf with ground_contact 'off') from the ``integrator``
    section or the ``method`` and ``dt`` overrides."""
    meth = it.text("method", choices=METHODS + INTEGRATOR_METHODS)
    meth = "implicit" if meth not in METHODS else meth  # a rigid scene's integrator: the implicit method
    if method is not None and method not in METHODS:
        raise ConfigError(f"{path}: method override {method!r}: the point-mass fidelity has {METHODS}")
    step = it.number("dt", positive=True, **BOUNDS["integrator.dt"])
    if dt is not None:
        step = _override(path, "dt", dt)
    vmax = it.number("max_speed", 1000.0, positive=True, **BOUNDS["integrator.max_speed"])
    hg = it.number("ground_height", 0.0, **BOUNDS["coordinate"])
    contact = it.text("ground_contact", "stop", choices=("stop", "flag", "off"))
    if contact == "flag":
        raise it.error("ground_contact", contact, "the point-mass fidelity has 'stop' (a node at or below the ground "
                                                  "stops the run) and 'off'; 'flag' (go on and report) is the rigid "
                                                  "fidelity's")
    for key in ("max_rate", "rtol", "atol"):
        it.raw(key, None)
    it.done()
    return meth if method is None else method, step, vmax, hg if contact == "stop" else -math.inf


def _check_nodes(fid: Section, ch: Section, path: Path, n_nodes: int, el: float, nk: int, el_override: bool,
                 nk_override: bool) -> None:
    """ConfigError naming fidelity.element_length (or chain.n_wings when the kites make the string long, or the
    override that set either) when a string of about ``n_nodes`` nodes would take more memory than
    ``model.memory.memory_limit``."""
    why = over_limit(pointmass_bytes(n_nodes), f"a string of {n_nodes} nodes")
    if why is None:
        return
    if nk_override or el_override:
        key, value = ("n_wings", nk) if nk_override else ("element_length", el)
        raise ConfigError(f"{path}: {key} = {value!r} (override): {why}")
    raise fid.error("element_length", el, f"{why} (with chain.n_wings = {nk})")


def load_pointmass_scene(path: str | Path, *, element_length: float | None = None, n_kites: int | None = None,
                         dt: float | None = None, method: str | None = None, cable_aero: bool | None = None,
                         overrides: dict | None = None) -> PointMassScene:
    """Load any scene file at the point-mass fidelity (``ladder.scene.load_scene(..., fidelity='pointmass')``).
    A rigid scene needs ``fidelity.element_length`` in its file or the ``element_length`` override [m]."""
    file, s = open_scene(path, overrides, n_wings=n_kites)
    return read_pointmass(s, s.section("fidelity"), file, element_length=element_length, n_kites=n_kites, dt=dt,
                          method=method, cable_aero=cable_aero, overrides=overrides)


def _kite_net_force(string: PointMassString, M, p: np.ndarray, u: np.ndarray, k: int) -> np.ndarray:
    """Aerodynamic force plus weight [N] of kite k at rest at p (cable weight added by the caller)."""
    w = np.array(wind_point(p[0], p[1], p[2], 0.0, M.wf, M.ms[0], M.md[0], M.gp, M.gv))
    f = np.array(kite_force(k, -w[0], -w[1], -w[2], density(-p[2], M.wf), u, M))
    f[2] += string.kite.mass * string.gravity
    return f


def quasi_static_state(string: PointMassString, u: np.ndarray, iterations: int = 20) -> np.ndarray:
    """A start near equilibrium for a chain of kites with a free upper end: kites at rest in the wind, each
    piece straight along its tension (tension accumulated from the top kite down: kite lift, drag and
    weight and the pieces' weight), stretched by T/EA; nodes spaced evenly along each piece, at rest.
    Iterated because the kites' forces depend on their heights. A fixed upper end is not supported here."""
    if string.end is not None or string.n_kites == 0 or string.kite_nodes[-1] != string.n_nodes - 1:
        raise ValueError("quasi_static_state needs a free upper end carried by the last kite")
    M = pack(string)
    kn = string.kite_nodes
    nk = kn.size
    lens = np.diff(np.concatenate([[-1], kn])) * string.element_length  # unstretched piece lengths [m]
    wpiece = lens * string.cable.mass_per_length * string.gravity
    pos = string.anchor + np.outer(np.cumsum(lens), [-math.sqrt(0.5), 0.0, -math.sqrt(0.5)])
    for _ in range(iterations):
        tens = np.zeros((nk, 3))
        above = np.zeros(3)
        for k in range(nk - 1, -1, -1):
            f = _kite_net_force(string, M, pos[k], u, k)
            f[2] += 0.5 * wpiece[k] + (0.5 * wpiece[k + 1] if k + 1 < nk else 0.0)
            above = above - f  # tension vector of the piece below kite k, pointing down the cable
            tens[k] = above
        prev = string.anchor.copy()
        for k in range(nk):
            t = np.linalg.norm(tens[k])
            prev = prev - tens[k] / t * lens[k] * (1.0 + t / string.cable.EA)
            pos[k] = prev
    x = np.zeros(string.state_size)
    xs = x.reshape(-1, N3_SIZE)
    lo = string.anchor
    j0 = 0
    for k in range(nk):
        m = kn[k] - j0 + 1
        f = np.arange(1, m + 1) / m
        xs[j0:kn[k] + 1, N3_POS:N3_POS + 3] = lo + np.outer(f, pos[k] - lo)
        lo, j0 = pos[k], kn[k] + 1
    return x
