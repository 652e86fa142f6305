"""Scenes at the rigid fidelity: a scene file read into a built :class:`~laddermill_gym.model.params.Assembly`, its
chain layout, how its initial state is found and its integrator settings (:class:`Scene`), and the simulator built
from them. ``ladder/scene.py`` (``load_scene``) picks this or the point-mass fidelity by the file's ``fidelity.wing``;
the point-mass starts taken from the rigid model (``ladder/fidelity.py``, ``ladder/pointmass_mill.py``) load their
file here.
"""

from __future__ import annotations

import dataclasses
import hashlib
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.ladder.bounds import BOUNDS
from laddermill_gym.ladder.scene_files import (
    FIDELITIES,
    check_cable_length,
    open_scene,
    read_ground_points,
    read_parts,
    read_station,
    read_wind,
)
from laddermill_gym.model.builders import CableSpec, ChainLayout, build_chain
from laddermill_gym.model.configio import ConfigError, Section
from laddermill_gym.model.memory import over_limit, rigid_bytes
from laddermill_gym.model.params import END_NODE, END_WING, Assembly
from laddermill_gym.sim.breakpoints import INTEGRATOR_METHODS
from laddermill_gym.sim.simulator import IntegratorSettings, Simulator
from laddermill_gym.sim.stable_step import check_step


def read_integrator(it: Section) -> IntegratorSettings:
    """The ``integrator:`` section: method, step, tolerances, exploding-state limits and the ground (bounds:
    ``ladder/bounds.py``)."""
    if it.data.get("ground_contact") is False:  # YAML 1.1 reads a bare `off` as false
        it.data["ground_contact"] = "off"
    settings = IntegratorSettings(method=it.text("method", choices=INTEGRATOR_METHODS),
                                  dt=it.number("dt", positive=True, **BOUNDS["integrator.dt"]),
                                  rtol=it.number("rtol", 1e-8, positive=True, high=1.0),
                                  atol=it.number("atol", 1e-10, positive=True),
                                  max_speed=it.number("max_speed", positive=True, **BOUNDS["integrator.max_speed"]),
                                  max_rate=it.number("max_rate", positive=True, **BOUNDS["integrator.max_rate"]),
                                  ground_height=it.number("ground_height", 0.0, **BOUNDS["coordinate"]),
                                  ground_contact=it.text("ground_contact", "stop", choices=("stop", "flag", "off")))
    it.done()
    return settings


@dataclass(frozen=True)
class InitialSpec:
    """How the initial state is found: 'trim' (one wing at a target angle of attack alpha [rad]) or
    'static' (equilibrium at rest with the given elevator angles [rad] of ascending/descending wings).

    top_slots [-], elevator_top [rad]: the first ``top_slots`` descending slots past the loop's top (slots half ..
    half + top_slots - 1 of a closed chain, ``half = (n + 1) // 2``) fly ``elevator_top`` instead of
    ``elevator_down``; 0 (the default) changes nothing. Elevators belong to slots, not wings (the controls are per
    slot), so a wing takes the setting of each slot it passes (``ladder.initial.slot_elevators``)."""

    method: str
    alpha: float
    elevation: float
    elevator_up: float
    elevator_down: float
    top_slots: int = 0
    elevator_top: float = 0.0


#: (scene file, dt, start) already checked against RK4's stable step in this process
CHECKED_STEPS: set = set()


@dataclass(frozen=True)
class Scene:
    """A loaded scene: the built assembly plus what is needed to start it."""

    name: str
    file: Path
    description: str
    assembly: Assembly
    layout: ChainLayout
    cable: CableSpec
    ground_points: dict
    start: str
    end: str | None
    piece_length: float
    initial: InitialSpec
    settings: IntegratorSettings

    def simulator(self, initial_state: np.ndarray | None = None, controls: np.ndarray | None = None) -> Simulator:
        """A compiled simulator started from the scene's initial state (found on first use).

        With RK4, a step above the estimated stability limit at the start (the Jacobian's eigenvalues,
        ``sim/stable_step.py``) gives an :class:`~laddermill_gym.sim.stable_step.UnstableStepWarning` naming both:
        such a run can oscillate, bounded, without any error. Checked once per scene file, step and start."""
        if initial_state is None:
            initial_state, c0 = self.initial_state()
            controls = c0 if controls is None else controls
        sim = Simulator(self.assembly, initial_state, self.settings, controls)
        if self.settings.method == "rk4":
            key = (str(self.file), self.settings.dt, hashlib.sha1(sim.state.tobytes()).hexdigest())
            if key not in CHECKED_STEPS:
                CHECKED_STEPS.add(key)
                check_step(sim)
        return sim

    def initial_state(self) -> tuple[np.ndarray, np.ndarray]:
        """(state, controls) at the scene's initial equilibrium."""
        from laddermill_gym.ladder.initial import initial_state

        try:
            return initial_state(self)
        except RuntimeError as err:  # no equilibrium: say which file and which settings decide it
            w = self.assembly.wind
            raise ConfigError(
                f"{self.file}: no initial state ({err}); the wind (wind.v0 = {w.v0:g} m/s, wind.rho0 = {w.rho0:g} "
                f"kg/m^3) and initial.method = {self.initial.method!r} (alpha_deg = "
                f"{math.degrees(self.initial.alpha):g}) decide whether the wings can hold an equilibrium") from None

    def replace(self, **changes) -> Scene:
        return dataclasses.replace(self, **changes)


def _refuse_impossible_step(asm: Assembly, settings: IntegratorSettings, path: Path, given: str = "") -> None:
    """ConfigError if an RK4 step is more than twice the stability bound of the stiffest cable element's axial
    oscillation, omega^2 = (EA / l0) (1/m_r + 1/m_s), the end masses lumped (a wing's or node's own mass plus half of
    each attached element's; a fixed end infinite) and RK4's bound on the imaginary axis omega dt = 2.83. A cheap,
    geometry-only check against values that cannot work; the precise limit is ``laddermill stable-step``'s.
    ``given``: the loader's overrides in effect (named in the error, where they and not the file set the step)."""
    e = asm.elements
    if settings.method != "rk4" or e.count == 0:
        return
    mass = {END_WING: np.array([asm.wing(k).mass for k in range(asm.n_wings)], dtype=float),
            END_NODE: np.array(asm.node_mass, dtype=float)}
    half = 0.5 * e.mu * e.l0
    for end in (0, 1):
        for kind, m in mass.items():
            sel = e.end_kind[:, end] == kind
            np.add.at(m, e.end_index[sel, end], half[sel])
    inv = np.zeros(e.end_kind.shape)
    for kind, m in mass.items():
        for end in (0, 1):
            sel = e.end_kind[:, end] == kind
            inv[sel, end] = 1.0 / m[e.end_index[sel, end]]
    omega = np.sqrt(e.EA / e.l0 * inv.sum(axis=1))
    j = int(np.argmax(omega))
    bound = 2.83 / omega[j]
    if settings.dt > 2.0 * bound:
        with_given = f" with the overrides {given}" if given else ""
        raise ConfigError(f"{path}: field 'integrator.dt' = {settings.dt!r} s{with_given} cannot work with RK4: the "
                          f"stiffest cable element ({j}, EA / l0 = {e.EA[j] / e.l0[j]:.3g} N/m) oscillates at "
                          f"{omega[j]:.4g} rad/s, stable up to about {bound:.3g} s (refused above twice that; the "
                          "precise limit: laddermill stable-step SCENE)")


def _chain(s: Section):
    """The ground points {name: (3,) [m]}, the chain's start and end point names, wings, piece length [m],
    elements per piece and the ground station (None: a fixed cable)."""
    points = read_ground_points(s)
    ch = s.section("chain")
    start = ch.text("start")
    end = ch.text("end", None)
    nw = ch.number("n_wings", integer=True, positive=True)
    piece = ch.number("piece_length", positive=True)
    epp = ch.number("elements_per_piece", integer=True, positive=True)
    ch.done()
    for key, pname in (("start", start), ("end", end)):
        if pname is not None and pname not in points:
            raise ch.error(key, pname, f"is not one of the ground points {sorted(points)}")
    station = read_station(s.section("station"), piece) if s.has("station") else None
    if station is not None and (end is None or epp != 1):
        raise ch.error("elements_per_piece" if end is not None else "end", epp if end is not None else end,
                       "a moving cable (station) needs two ground points (start and end) and one element per "
                       "piece (Meijaard's boundary conditions)")
    return ch, points, start, end, nw, piece, epp, station


def _check_apparent_mass(path, wing_type, rho0: float) -> None:
    """The alpha-rate lift CLad adds rho S c / 4 CLad [kg] to the wing's mass along the lift direction (at zero
    sideslip; 1 / cos(beta) times that at sideslip beta, which the step's failure report names): a table whose
    smallest CLad makes that mass zero or negative at sea level's density ``rho0`` [kg/m^3] gives an indefinite mass
    matrix. ConfigError naming the table, its smallest CLad and the angle of attack."""
    if wing_type.aero is None:
        return
    clad = wing_type.aero.column("CLad")
    k = int(np.argmin(clad))
    added = rho0 * wing_type.area * wing_type.chord / 4.0 * clad[k]
    if wing_type.mass + added <= 0.0:
        least = -4.0 * wing_type.mass / (rho0 * wing_type.area * wing_type.chord)
        raise ConfigError(f"{path}: wing table {wing_type.aero.source}: CLad = {clad[k]:.4g} at alpha = "
                          f"{np.degrees(wing_type.aero.alpha[k]):.4g} deg adds {added:.4g} kg along the lift direction "
                          f"to the wing's {wing_type.mass:g} kg at rho = {rho0:g} kg/m^3: the mass matrix is not "
                          f"positive definite (CLad must stay above {least:.4g})")


def _check_in_plane(path, direction_inf: float, wing_type) -> None:
    """The in-plane mode (dimension 2) needs a wind whose direction does not turn and wings symmetric about their
    plane: ConfigError naming the field and value that break it."""
    bad = [f"wind.direction_inf_rad = {direction_inf:g} (must be 0: the wind direction may not turn)"] \
        if direction_inf != 0.0 else []
    bad += [f"the wing's {name} y = {v[1]:g} m (must be 0: wings symmetric about their plane)"
            for name, v in (("attachment", wing_type.attachment), ("r_ref", wing_type.r_ref)) if abs(v[1]) > 0]
    if bad:
        raise ConfigError(f"{path}: the in-plane mode (dimension 2) needs a fixed wind direction and symmetric wings: "
                          + "; ".join(bad))


def _initial(ini: Section, limits: np.ndarray) -> InitialSpec:
    """The ``initial`` section (angles in the file in degrees, here in rad; bounds ``ladder/bounds.py``, the
    elevator angles within the wing's elevator limits ``limits`` (2,) [rad])."""
    lo, hi = np.degrees(limits)
    elev = dict(low=float(lo), high=float(hi), why="deg: the wing's control_limits_deg.elevator")
    spec = InitialSpec(method=ini.text("method", choices=("trim", "static")),
                       alpha=math.radians(ini.number("alpha_deg", 8.0, **BOUNDS["initial.alpha_deg"])),
                       elevation=math.radians(ini.number("elevation_deg", 45.0, positive=True,
                                                         **BOUNDS["initial.elevation_deg"])),
                       elevator_up=math.radians(ini.number("elevator_up_deg", 0.0, **elev)),
                       elevator_down=math.radians(ini.number("elevator_down_deg", 0.0, **elev)),
                       top_slots=int(ini.number("top_slots", 0, integer=True, nonneg=True)),
                       elevator_top=math.radians(ini.number("elevator_top_deg", 0.0, **elev)))
    ini.done()
    return spec


def _field_error(ch: Section, path: Path, key: str, value, overridden: bool, why: str) -> ConfigError:
    """The error of ``chain.KEY`` = ``value``, or of the keyword override that replaced it."""
    return ConfigError(f"{path}: {key} = {value!r} (override): {why}") if overridden else ch.error(key, value, why)


def _check_sizes(ch: Section, path: Path, nw: int, epp: int, end, planar: bool, counts: dict) -> None:
    """ConfigError naming the field (or the override) that sets the number of wings or elements when the model
    and its start (solved in the plane: ``planar``) would take more memory than ``model.memory.memory_limit``;
    ``counts`` holds the keyword overrides (None: the file's)."""
    n_pieces = nw + (end is not None)
    nodes = n_pieces * (epp - 1)
    why = over_limit(rigid_bytes(nw, nodes, planar_start=planar),
                     f"{nw} wing{'s' * (nw != 1)} and {n_pieces * epp} elements ({nodes} cable nodes)")
    if why is not None:
        key = "elements_per_piece" if nodes > nw else "n_wings"
        raise _field_error(ch, path, key, nw if key == "n_wings" else epp, counts.get(key) is not None, why)


def _check_start(ch: Section, path: Path, init: InitialSpec, nw: int, end, overridden: bool) -> None:
    """ConfigError naming chain.n_wings (or its override) when initial.method 'trim' (one wing at a target angle of
    attack) has more wings than one."""
    if init.method == "trim" and nw != 1:
        raise _field_error(ch, path, "n_wings", nw, overridden,
                           "initial.method 'trim' trims exactly one wing; a chain of several wings starts at rest "
                           "with initial.method: static" + (" (the last wing carries the free upper end)"
                                                             if end is None else ""))


def _check_top_slots(path: Path, init: InitialSpec, nw: int, end) -> None:
    """ConfigError naming initial.top_slots when it is more than the descending slots (a closed chain's
    nw - (nw + 1) // 2; an open chain has none)."""
    most = nw - (nw + 1) // 2 if end is not None else 0
    if init.top_slots > most:
        raise ConfigError(f"{path}: field 'initial.top_slots' = {init.top_slots!r}: must be at most the {most} "
                          f"descending slots of {nw} wings" + ("" if end is not None else " (an open chain has none)"))


def _check_step_override(path: Path, dt: float | None) -> None:
    """ConfigError for a keyword override of the step [s] outside ``integrator.dt``'s bounds (a step that is not
    a finite number > 0 is left to ``IntegratorSettings``)."""
    b = BOUNDS["integrator.dt"]
    if dt is not None and 0.0 < dt < math.inf and not b["low"] <= dt <= b["high"]:
        raise ConfigError(f"{path}: dt = {dt!r} (override): must be between {b['low']:g} and {b['high']:g} "
                          f"({b['why']})")


def read_rigid(s: Section, path: Path, *, dimension: int | None = None, sag: bool | None = None,
               cable_aero: bool | None = None, elements_per_piece: int | None = None,
               n_wings: int | None = None, dt: float | None = None, method: str | None = None) -> Scene:
    """Build the rigid scene of a scene file already opened as ``s`` (``scene_files.open_scene``); the keyword
    overrides replace the file's values (``ladder.scene.load_scene``)."""
    name = s.text("name")
    desc = s.text("description", "")
    dim = s.number("dimension", integer=True)
    gravity = s.number("gravity", positive=True, **BOUNDS["gravity"])
    wind = read_wind(s.section("wind"))
    wing_type, cable = read_parts(s, path)
    _check_apparent_mass(path, wing_type, wind.rho0)
    ch, points, start, end, nw, piece, epp, station = _chain(s)
    fid = s.section("fidelity")
    fid.text("wing", "rigid", choices=FIDELITIES)
    fid.raw("element_length", None)  # the point-mass string's resolution, unused by the rigid model
    sag_on = fid.flag("sag")
    caero_on = fid.flag("cable_aero")
    fid.done()
    init = _initial(s.section("initial"), wing_type.control_limits[0])
    settings = read_integrator(s.section("integrator"))
    s.done()
    # overrides
    dim = dim if dimension is None else int(dimension)
    if dim not in (2, 3):
        raise ConfigError(f"{path}: field 'dimension' = {dim!r}: must be 2 or 3")
    if dim == 2:
        _check_in_plane(path, wind.direction_inf, wing_type)
    sag_on = sag_on if sag is None else bool(sag)
    caero_on = caero_on if cable_aero is None else bool(cable_aero)
    epp = epp if elements_per_piece is None else int(elements_per_piece)
    if station is not None and epp != 1:
        raise ConfigError(f"{path}: elements_per_piece = {elements_per_piece!r} (override): a moving cable (station) "
                          "needs one element per piece (Meijaard's boundary conditions)")
    nw = nw if n_wings is None else int(n_wings)
    if dt is not None or method is not None:
        settings = dataclasses.replace(settings, dt=settings.dt if dt is None else float(dt),
                                       method=settings.method if method is None else method)
    _check_sizes(ch, path, nw, epp, end, dim == 2 or wind.direction_inf == 0.0,
                 {"n_wings": n_wings, "elements_per_piece": elements_per_piece})
    _check_start(ch, path, init, nw, end, n_wings is not None)
    _check_top_slots(path, init, nw, end)
    check_cable_length(ch, piece, nw, end is not None, cable, gravity, n_wings is not None)
    names = list(points)
    fixed = np.array([points[k] for k in names])
    pieces = np.full(nw + (end is not None), piece)
    if station is not None:  # the first and last elements at their lengths right after a transfer
        pieces[0], pieces[-1] = station.first_fraction * piece, station.last_fraction * piece
    asm, layout = build_chain((wing_type,), np.zeros(nw, dtype=np.int64), pieces, epp, cable, fixed,
                              names.index(start), None if end is None else names.index(end), wind,
                              dim=dim, sag=sag_on, cable_aero=caero_on, gravity=gravity)
    if station is not None:
        asm = dataclasses.replace(asm, station=station)
    given = ", ".join(f"{k} = {v!r}" for k, v in (("dt", dt), ("method", method),
                                                   ("elements_per_piece", elements_per_piece)) if v is not None)
    _refuse_impossible_step(asm, settings, path, given)
    _check_step_override(path, dt)
    return Scene(name=name, file=path, description=desc, assembly=asm, layout=layout, cable=cable,
                 ground_points=points, start=start, end=end, piece_length=piece, initial=init, settings=settings)


def load_rigid_scene(name_or_path: str | Path, *, overrides: dict | None = None, **options) -> Scene:
    """``ladder.scene.load_scene(name_or_path, fidelity="rigid", ...)``: the scene file at the rigid fidelity
    whatever its ``fidelity.wing`` says; ``options`` are :func:`read_rigid`'s overrides."""
    path, s = open_scene(name_or_path, overrides, n_wings=options.get("n_wings"),
                         elements_per_piece=options.get("elements_per_piece"))
    return read_rigid(s, path, **options)
