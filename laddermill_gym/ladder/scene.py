"""Scenes: YAML files in configs/scenes/ loaded into frozen parameters and built into a simulator.

A scene file names its wing type and cable files, the wind, the ground points, a chain of wings on
cable pieces, the fidelity switches, how the initial state is found, and the integrator. See
configs/scenes/tethered_wing.yaml for a commented example and README.md ("Adding a scene").
"""

from __future__ import annotations

import dataclasses
import hashlib
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laddermill_gym.model.aero_table import load_aero_table
from laddermill_gym.model.builders import CableSpec, ChainLayout, build_chain
from laddermill_gym.model.configio import CONFIG_DIR, ConfigError, Section, config_path, read_yaml
from laddermill_gym.model.params import (
    END_NODE,
    END_WING,
    N_CONTROLS,
    Assembly,
    WindParams,
    WingType,
)
from laddermill_gym.model.station import MODES, StationParams
from laddermill_gym.sim.simulator import INTEGRATOR_METHODS, IntegratorSettings, Simulator
from laddermill_gym.sim.stable_step import check_step

SCENE_DIR = CONFIG_DIR / "scenes"


def scene_path(name_or_path: str | Path) -> Path:
    """The shipped configs/scenes/NAME.yaml for a bare name, else the path itself."""
    return config_path("scenes", name_or_path)


def available_scenes() -> list[str]:
    return sorted(p.stem for p in SCENE_DIR.glob("*.yaml"))


# ---------------------------------------------------------------------------------------- parts
def load_wing_type(path: Path) -> WingType:
    """Read a wing type YAML (mass, inertia, geometry, attachment, control limits, table file)."""
    s = read_yaml(path)
    inertia = s.section("inertia")
    J = (inertia.number("Jxx", positive=True), inertia.number("Jyy", positive=True),
         inertia.number("Jzz", positive=True), inertia.number("Jxz"))
    inertia.done()
    if J[0] * J[2] - J[3] ** 2 <= 0:
        raise ConfigError(f"{path}: field 'inertia' = {J}: Jxx Jzz - Jxz^2 must be > 0")
    lim = s.section("control_limits_deg")
    limits = np.zeros((N_CONTROLS, 2))
    for i, name in enumerate(("elevator", "rudder", "aileron")):
        lo_hi = lim.vector(name, 2)
        if not lo_hi[0] < lo_hi[1]:
            raise lim.error(name, list(lo_hi), "lower limit must be below the upper limit")
        limits[i] = np.radians(lo_hi)
    lim.done()
    table_name = s.text("aero_table")
    table_file = config_path("wings", table_name, path.parent)
    if not table_file.is_file():
        raise s.error("aero_table", table_name, f"no such file {table_file}")
    wt = WingType(
        name=s.text("name"), mass=s.number("mass", positive=True), inertia=J,
        area=s.number("area", positive=True), span=s.number("span", positive=True),
        chord=s.number("chord", positive=True), r_ref=s.vector("aero_reference", 3),
        attachment=s.vector("attachment", 3), control_limits=limits, aero=load_aero_table(table_file))
    s.done()
    return wt


def load_cable(path: Path) -> CableSpec:
    """Read a cable YAML (diameter, mass per length, EA, DA, breaking load, cn0, ct0)."""
    s = read_yaml(path)
    c = CableSpec(diameter=s.number("diameter", positive=True),
                  mass_per_length=s.number("mass_per_length", positive=True),
                  EA=s.number("EA", positive=True), DA=s.number("DA", nonneg=True),
                  breaking_load=s.number("breaking_load", positive=True), cn0=s.number("cn0", nonneg=True),
                  ct0=s.number("ct0", nonneg=True))
    s.done()
    return c


def read_wind(s: Section) -> WindParams:
    # v0 and rho0 > 0: without wind or air no wing or rotor here can hold an equilibrium (the trim would fail)
    w = WindParams(
        v0=s.number("v0", positive=True), h0=s.number("h0", positive=True), v1=s.number("v1"),
        exponent=s.number("exponent", nonneg=True), direction_inf=s.number("direction_inf_rad", 0.0),
        direction_height=s.number("direction_height", 500.0, positive=True),
        rho0=s.number("rho0", positive=True), density_model=s.text("density_model", "barometric",
                                                                 choices=("barometric", "isa")),
        scale_height=s.number("scale_height", 8400.0, positive=True))
    s.done()
    return w


def read_integrator(it: Section) -> IntegratorSettings:
    """The ``integrator:`` section: method, step, tolerances, exploding-state limits and the ground."""
    if it.data.get("ground_contact") is False:  # YAML 1.1 reads a bare `off` as false
        it.data["ground_contact"] = "off"
    settings = IntegratorSettings(method=it.text("method", choices=INTEGRATOR_METHODS),
                                  dt=it.number("dt", positive=True),
                                  rtol=it.number("rtol", 1e-8, positive=True),
                                  atol=it.number("atol", 1e-10, positive=True),
                                  max_speed=it.number("max_speed", positive=True),
                                  max_rate=it.number("max_rate", positive=True),
                                  ground_height=it.number("ground_height", 0.0),
                                  ground_contact=it.text("ground_contact", "stop", choices=("stop", "flag", "off")))
    it.done()
    return settings


def read_station(s: Section, piece: float) -> StationParams:
    """The moving cable's ground station (``station:`` section; ``model/station.py``), errors naming the field."""
    mode = s.text("mode", "prescribed", choices=MODES)
    times = s.vector("speed_times_s", default=[0.0])
    speeds = s.vector("speed_m_s", default=[0.0])
    kw = dict(piece_length=piece, first_fraction=s.number("first_fraction", 0.1, positive=True),
              last_fraction=s.number("last_fraction", 1.1, positive=True), mode=mode,
              speed_times=tuple(times), speed_values=tuple(speeds),
              efficiency=s.number("efficiency", 1.0, positive=True))
    if mode == "drum":
        kw.update(drum_radius=s.number("drum_radius", positive=True),
                  drum_inertia=s.number("drum_inertia", positive=True),
                  torque_limits=tuple(s.vector("torque_limits", 2)))
    if mode == "commanded":
        kw.update(speed_time_constant=s.number("speed_time_constant", positive=True),
                  speed_limits=tuple(s.vector("speed_limits", 2)))
    s.done()
    try:
        return StationParams(**kw)
    except ValueError as err:
        raise ConfigError(f"{s.file}: {err}") from None


# ---------------------------------------------------------------------------------------- scene
@dataclass(frozen=True)
class InitialSpec:
    """How the initial state is found: 'trim' (one wing at a target angle of attack alpha [rad]) or
    'static' (equilibrium at rest with the given elevator angles [rad] of ascending/descending wings)."""

    method: str
    alpha: float
    elevation: float
    elevator_up: float
    elevator_down: float


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


FIDELITIES = ("rigid", "pointmass")


def options_key(options: dict | None) -> tuple:
    """A hashable key of ``load_scene`` keyword overrides (sorted pairs; a nested mapping such as ``overrides`` as
    canonical JSON), for caches of loaded scenes; :func:`options_kwargs` turns it back."""
    import json

    return tuple(sorted((k, json.dumps(v, sort_keys=True) if isinstance(v, (dict, list)) else v)
                        for k, v in dict(options or {}).items()))


def options_kwargs(key: tuple) -> dict:
    """The ``load_scene`` keyword arguments of an :func:`options_key`."""
    import json

    return {k: json.loads(v) if k == "overrides" and isinstance(v, str) else v for k, v in key}


def _refuse_impossible_step(asm: Assembly, settings: IntegratorSettings, path: Path) -> None:
    """ConfigError if an RK4 step is more than twice the stability bound of the stiffest cable element's axial
    oscillation, omega^2 = (EA / l0) (1/m_r + 1/m_s), the end masses lumped (a wing's or node's own mass plus half of
    each attached element's; a fixed end infinite) and RK4's bound on the imaginary axis omega dt = 2.83. A cheap,
    geometry-only check against values that cannot work; the precise limit is ``laddermill stable-step``'s."""
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
        raise ConfigError(f"{path}: field 'integrator.dt' = {settings.dt!r} s cannot work with RK4: the stiffest cable "
                          f"element ({j}, EA / l0 = {e.EA[j] / e.l0[j]:.3g} N/m) oscillates at {omega[j]:.4g} rad/s, "
                          f"stable up to about {bound:.3g} s (refused above twice that; the precise limit: "
                          "laddermill stable-step SCENE)")


def _merged(data: dict, overrides, where: str) -> dict:
    """A copy of the YAML mapping ``data`` with the nested mapping ``overrides`` merged in (mappings merge, other
    values replace); ConfigError naming the override's path if it is not a mapping with text keys."""
    if not isinstance(overrides, dict) or not all(isinstance(k, str) for k in overrides):
        raise ConfigError(f"{where} = {overrides!r}: must be a mapping with text keys")
    out = dict(data)
    for k, v in overrides.items():
        if isinstance(v, dict) and isinstance(out.get(k), dict):
            out[k] = _merged(out[k], v, f"{where}.{k}")
        else:
            out[k] = v
    return out


def _parts(s: Section, path: Path):
    """The wing type and the cable the scene names; ConfigError naming the scene file and field (not only the
    missing file) when one is not found."""
    parts = {}
    for key, kind in (("wing_type", "wings"), ("cable", "cables")):
        value = s.text(key)
        parts[key] = config_path(kind, value, path.parent)
        if not parts[key].is_file():
            shown = parts[key] if parts[key].is_absolute() else path.parent / parts[key]
            raise s.error(key, value, f"no such file {shown} (a path is relative to the scene's folder, a bare "
                                      f"name is {CONFIG_DIR / kind}/NAME.yaml, 'package:{kind}/FILE' the shipped data)")
    return load_wing_type(parts["wing_type"]), load_cable(parts["cable"])


def _chain(s: Section):
    """The ground points {name: (3,) [m]}, the chain's start and end point names, wings, piece length [m],
    elements per piece and the ground station (None: a fixed cable)."""
    gp = s.section("ground_points")
    points = {k: gp.vector(k, 3) for k in list(gp.data)}
    gp.done()
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
    return points, start, end, nw, piece, epp, station


def _initial(ini: Section) -> InitialSpec:
    """The ``initial`` section (angles in the file in degrees, here in rad)."""
    spec = InitialSpec(method=ini.text("method", choices=("trim", "static")),
                       alpha=math.radians(ini.number("alpha_deg", 8.0)),
                       elevation=math.radians(ini.number("elevation_deg", 45.0)),
                       elevator_up=math.radians(ini.number("elevator_up_deg", 0.0)),
                       elevator_down=math.radians(ini.number("elevator_down_deg", 0.0)))
    ini.done()
    return spec


def load_scene(name_or_path: str | Path, *, dimension: int | None = None, sag: bool | None = None,
               cable_aero: bool | None = None, elements_per_piece: int | None = None,
               n_wings: int | None = None, dt: float | None = None, method: str | None = None,
               fidelity: str | None = None, element_length: float | None = None, overrides: dict | None = None):
    """Load a scene YAML; keyword overrides replace the file's values (for benchmarks and studies).

    The fidelity is the file's ``fidelity.wing`` ('rigid', the default, or 'pointmass') unless ``fidelity``
    overrides it; at 'pointmass' the result is a :class:`~laddermill_gym.ladder.pointmass_scene.PointMassScene`
    (its string at ``fidelity.element_length`` or ``element_length`` [m]; ``n_wings``, ``dt`` and ``method``
    ('explicit' or 'implicit') apply), and nothing of the rigid model is built.

    ``overrides``: a nested mapping merged into the file's fields before they are read, e.g.
    ``{"wind": {"v0": 10.0}, "chain": {"piece_length": 120.0}}`` (parameters as data); checked like the file, errors
    naming the field and "(with overrides)"."""
    path = scene_path(name_or_path)
    s = read_yaml(path)
    if overrides:
        s = Section(_merged(s.data, overrides, "overrides"), f"{path} (with overrides)")
    for key, v in (("n_wings", n_wings), ("elements_per_piece", elements_per_piece)):
        if v is not None and (isinstance(v, bool) or int(v) != v or v < 1):
            raise ConfigError(f"{path}: {key} = {v!r} (override): must be a whole number >= 1")
    fdata = s.data.get("fidelity")
    wing_fid = fidelity or (fdata.get("wing", "rigid") if isinstance(fdata, dict) else "rigid")
    if wing_fid not in FIDELITIES:
        raise ConfigError(f"{path}: fidelity.wing = {wing_fid!r}: must be one of {FIDELITIES}")
    if wing_fid == "pointmass":
        from laddermill_gym.ladder.pointmass_scene import read_pointmass

        return read_pointmass(s, s.section("fidelity"), path, element_length=element_length, n_kites=n_wings,
                              dt=dt, method=method)
    name = s.text("name")
    desc = s.text("description", "")
    dim = s.number("dimension", integer=True)
    gravity = s.number("gravity", positive=True)
    wind = read_wind(s.section("wind"))
    wing_type, cable = _parts(s, path)
    points, start, end, nw, piece, epp, station = _chain(s)
    fid = s.section("fidelity")
    fid.text("wing", "rigid", choices=FIDELITIES)
    fid.raw("element_length", None)  # the point-mass string's resolution, unused by the rigid model
    sag_on = fid.flag("sag")
    caero_on = fid.flag("cable_aero")
    fid.done()
    init = _initial(s.section("initial"))
    settings = read_integrator(s.section("integrator"))
    s.done()
    # overrides
    dim = dim if dimension is None else int(dimension)
    if dim not in (2, 3):
        raise ConfigError(f"{path}: field 'dimension' = {dim!r}: must be 2 or 3")
    if dim == 2 and (wind.direction_inf != 0.0 or abs(wing_type.attachment[1]) > 0 or abs(wing_type.r_ref[1]) > 0):
        raise ConfigError(f"{path}: the in-plane mode needs a fixed wind direction and symmetric wings")
    sag_on = sag_on if sag is None else bool(sag)
    caero_on = caero_on if cable_aero is None else bool(cable_aero)
    epp = epp if elements_per_piece is None else int(elements_per_piece)
    nw = nw if n_wings is None else int(n_wings)
    if dt is not None or method is not None:
        settings = dataclasses.replace(settings, dt=settings.dt if dt is None else float(dt),
                                       method=settings.method if method is None else method)
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
    _refuse_impossible_step(asm, settings, path)
    return Scene(name=name, file=path, description=desc, assembly=asm, layout=layout, cable=cable,
                 ground_points=points, start=start, end=end, piece_length=piece, initial=init, settings=settings)
