"""The starting point of ``laddermill_gym/LadderMill-v0``: the mill's periodic stationary motion.

:func:`compute_operating_point` runs the in-plane (2D) mill from the scene's equilibrium at rest through the
scene's cable-speed ramp to its periodic motion (:func:`laddermill_gym.ladder.periodic.run_to_periodic`), records
one more period (wing positions per slot against the cable moved, the reference orbit the observations' offsets
are taken from), and maps the state at the end of that period (just after a transfer) to 3D
(:func:`laddermill_gym.model.states.planar_to_3d` on the body block, the station block appended with no
transfers and no energy yet). The 3D mill from that in-plane start stays in plane to round-off without a
disturbance (docs/moving_cable.md), so the 2D run is the cheap way to the 3D operating point.

It costs 30-100 s of CPU for the 101-wing mills (periodic at t ~ 1,000-1,400 s), so :func:`operating_point`
memoises it once per process per (scene, scene options, settle settings) and keeps it on disk for later processes
(``envs/laddermill/op_cache.py``: ``~/.cache/laddermill_gym``, or ``$LADDERMILL_CACHE_DIR``; keyed by the scene,
the settings and the code; the exact float64 arrays, so a start read back is bit for bit a recomputed one); a user
may pass a precomputed :class:`OperatingPoint` to the environment instead (it pickles).

Small mills (11 or 21 wings) do not reach a periodic motion (docs/moving_cable.md, "Small mills wander"): then
the state after the settling time ``max_time`` is used, ``converged`` is False, a warning says so and every reset's
``info`` carries the note. The reference power is the mean electrical power of the last period when it is
positive; otherwise (a small mill that makes no net power) it is efficiency x V_c x the mean tension of the
first element, stated in the note.
"""

from __future__ import annotations

import dataclasses
import hashlib
import math
import numbers
import warnings
from dataclasses import dataclass

import numpy as np

from laddermill_gym.envs.laddermill import op_cache
from laddermill_gym.kernels.contract import N_CONTROLS, SX_ENERGY, SX_MOVED, SX_SIZE, SX_SPEED, SX_TRANSFERS
from laddermill_gym.ladder.periodic import run_to_periodic
from laddermill_gym.ladder.scene import Scene, load_scene, options_kwargs
from laddermill_gym.model.configio import ConfigError
from laddermill_gym.model.disk_cache import feed
from laddermill_gym.model.input_cache import input_cache
from laddermill_gym.model.states import planar_to_3d
from laddermill_gym.model.station import electrical_power
from laddermill_gym.sim.reports import lowest_body
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["OperatingPoint", "SettleConfig", "compute_operating_point", "operating_point", "cached_operating_point",
           "mill_scene", "scene_digest", "nominal_positions", "operating_point_pending", "SEARCH_HOOK"]

#: a function (scene, options) that :func:`compute_operating_point` calls first, or None: LadderMill's kernel warm-up
#: (``envs/laddermill/kernel_warmup.py``) compiles the search's kernels there while its second process compiles the
#: static equilibrium's; it computes nothing the operating point depends on
SEARCH_HOOK: list = [None]


@dataclass(frozen=True)
class SettleConfig:
    """How the operating point is found (:func:`run_to_periodic`'s criteria).

    max_time [s]: the longest periodic search after the ramp (the settling time of the fallback);
    shape_tol [-], power_tol [-]: the periodicity criteria (shape change / l0, relative power change);
    orbit_dt [s]: sample spacing of the recorded reference orbit (a whole number of physics steps, rounded).
    """

    max_time: float = 3000.0
    shape_tol: float = 1e-3
    power_tol: float = 1e-3
    orbit_dt: float = 0.25

    def __post_init__(self):
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
                raise ValueError(f"settle.{f.name} = {v!r}: must be a finite number > 0")


@dataclass(frozen=True, eq=False)
class OperatingPoint:
    """The mill's periodic stationary operating point, in 3D.

    state : (n_state,) 3D state just after a transfer; station block: s [m], 0 transfers, V_c [m/s], 0 J.
    controls : (3 n_wings,) tail controls [rad] per slot (elevator, rudder, aileron).
    cable_speed : V_c [m/s].  period_s : l0 / V_c [s].
    power_W : mean electrical generator power over the last period [W] (may be <= 0 for a small mill).
    mechanical_power_W : the same before the station's efficiency [W].
    reference_power_W : P_ref > 0 [W], the reward's normalisation (power_W when positive, see the module doc).
    tension_first_N, tension_last_N : mean tensions of the first and last elements over the last period [N].
    converged : the periodic criteria held.  t_settle_s : simulated time of the 2D run [s].
    orbit_moved : (m,) cable moved s since the transfer [m], increasing, of the recorded period.
    orbit_positions : (m, n_wings, 3) CG positions per slot at those s [m] (y = 0: in plane).
    alpha_range_rad : (2,) smallest and largest angle of attack of any wing over the recorded period [rad].
    note : a sentence on how the point was found (convergence, settling time, reference power).
    scene_digest : :func:`scene_digest` of the 3D scene it was found for ("" when the scene cannot be fingerprinted):
    an env refuses a point of another scene, wing type, wind or station.
    """

    state: np.ndarray
    controls: np.ndarray
    cable_speed: float
    period_s: float
    power_W: float
    mechanical_power_W: float
    reference_power_W: float
    tension_first_N: float
    tension_last_N: float
    converged: bool
    t_settle_s: float
    orbit_moved: np.ndarray
    orbit_positions: np.ndarray
    alpha_range_rad: np.ndarray
    note: str
    scene_digest: str

    @property
    def n_wings(self) -> int:
        return int(self.orbit_positions.shape[1])


@input_cache(maxsize=16)
def mill_scene(scene: str, options: tuple, dimension: int = 3) -> Scene:
    """The scene ``scene`` with ``load_scene`` overrides ``options`` (sorted (key, value) pairs) in ``dimension``
    (cached); ValueError unless it has a moving cable."""
    try:
        sc = load_scene(scene, dimension=dimension, **options_kwargs(options))
    except ConfigError as err:
        if dimension != 2:
            raise
        raise ConfigError(f"LadderMill finds its operating point on the in-plane mill: {err}") from None
    if sc.assembly.station is None:
        raise ValueError(f"scene {sc.name!r}: LadderMill needs a scene with a moving cable (a 'station:' section)")
    return sc


def scene_digest(sc: Scene) -> str:
    """Hex SHA-256 of a scene as loaded (every field but its file's path: wings, cable, station, wind, initial
    settings, integrator; ``model/disk_cache.feed``), or "" when a field cannot be fingerprinted."""
    h = hashlib.sha256(b"laddermill operating point scene;")
    try:
        feed(h, sc, ("file",))
    except TypeError:
        return ""
    return h.hexdigest()


def _search_failure(sc2: Scene, options: tuple, what: str) -> ValueError:
    """The error of an operating-point search that cannot give a start: the scene, its options and wind, and
    ``what`` happened."""
    a = sc2.assembly
    opts = f", options {dict(options)}" if options else ""
    return ValueError(f"LadderMill operating point of scene {sc2.name!r} ({a.n_wings} wings, wind v0 = {a.wind.v0:g} "
                      f"m/s{opts}): {what}; no periodic start exists at these settings")


def _check_rest_above_ground(sim, sc2: Scene, options: tuple) -> None:
    """ValueError when a wing of the equilibrium at rest, the search's start, is at or below the ground (a wind
    too weak to hold the chain up: the search would stop at its first step)."""
    if sim.settings.ground_contact == "off":
        return
    name, height = lowest_body(sim.assembly, sim.state)
    if not height > sim.settings.ground_height:
        raise _search_failure(sc2, options, f"its equilibrium at rest has {name} at height {height:.4g} m, "
                                            f"at or below the ground ({sim.settings.ground_height:g} m)")


def _record_period(sim, orbit_dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Step ``sim`` (just after a transfer) to the next transfer; returns (s (m,), positions (m, n, 3), alpha
    range (2,)) sampled every ``orbit_dt`` (rounded to physics steps). The body is 2D: y = 0."""
    n_every = max(1, int(round(orbit_dt / sim.settings.dt)))
    st = sim.assembly.station
    n_max = int(math.ceil(2.0 * st.piece_length / max(sim.cable_speed(), 1e-9) / sim.settings.dt))
    moved, pos = [], []
    alo, ahi = math.inf, -math.inf
    n0 = sim.transfers()
    off = sim.assembly.body_state_size
    for i in range(n_max):
        if i % n_every == 0:
            moved.append(float(sim.state[off + SX_MOVED]))
            pos.append(sim.wing_positions().copy())
            alpha = sim.wing_alpha_beta()[:, 0]
            alo, ahi = min(alo, float(alpha.min())), max(ahi, float(alpha.max()))
        sim.step()
        if sim.transfers() != n0:
            return np.array(moved), np.array(pos), np.array([alo, ahi])
    raise RuntimeError(f"t = {sim.t:.2f} s: no transfer within two periods while recording the reference orbit")


def compute_operating_point(scene: str = "laddermill", options: tuple = (), settle: SettleConfig | None = None,
                            warn: bool = True) -> OperatingPoint:
    """Run the in-plane mill to its periodic motion and return the 3D :class:`OperatingPoint` (not cached: see
    :func:`operating_point`). ``options``: sorted (key, value) ``load_scene`` overrides (no ``dimension``)."""
    settle = settle or SettleConfig()
    sc2 = mill_scene(scene, options, 2)
    if SEARCH_HOOK[0] is not None:  # LadderMill's kernel warm-up: the in-plane kernels compiled on two cores
        SEARCH_HOOK[0](scene, options)
    sim = sc2.simulator()
    _check_rest_above_ground(sim, sc2, options)
    controls = sim.controls[: N_CONTROLS * sc2.assembly.n_wings].copy()  # the tails' (not a drum's or commanded)
    try:  # the tensions of the last period only (its mean tensions below; the same bits, a fifth less work per step)
        res = run_to_periodic(sim, shape_tol=settle.shape_tol, power_tol=settle.power_tol, max_time=settle.max_time,
                              progress=False, watch_every_period=False)
    except RuntimeError as err:  # a breakdown (SimulationError) in the ramp, or no transfer: the cable not moving on
        raise _search_failure(sc2, options, f"the in-plane mill found no periodic motion: {err}") from None
    if res.breakdown is not None:
        raise _search_failure(sc2, options, f"the in-plane mill broke down while looking for its periodic motion: "
                                            f"{res.breakdown}")
    st = sc2.assembly.station
    e0 = sim.generator_energy()
    t0 = sim.t
    try:
        moved, positions, alpha_range = _record_period(sim, settle.orbit_dt)
    except RuntimeError as err:
        raise _search_failure(sc2, options, f"the in-plane mill failed recording its period: {err}") from None
    mech = (sim.generator_energy() - e0) / (sim.t - t0)  # the recorded period's mean (energy integral, exact)
    v = sim.cable_speed()
    t_first, t_last = float(res.tension_mean_N[0]), float(res.tension_mean_N[-1])
    power = electrical_power(mech, st.efficiency)
    how = (f"periodic motion reached at t = {sim.t:.0f} s" if res.converged else
           f"NO periodic motion within the settling time ({settle.max_time:g} s after the ramp; last shape change "
           f"{res.history[-1]['shape_change']:.2g} l0, power change {res.history[-1]['power_change']:.2g}): the "
           f"start is the state reached at t = {sim.t:.0f} s")
    if power > 0:
        p_ref, ref = power, f"reference power = the period's mean electrical power {power / 1e3:.4g} kW"
    else:
        p_ref = st.efficiency * v * max(t_first, 1.0)
        ref = (f"the period's mean electrical power is {power / 1e3:.3g} kW (not positive), so the reference power "
               f"is efficiency x V_c x mean first-element tension = {p_ref / 1e3:.4g} kW")
    note = f"{sc2.name} ({sc2.assembly.n_wings} wings, V_c = {v:.3g} m/s): {how}; {ref}"
    nb2 = sc2.assembly.body_state_size
    station = np.zeros(SX_SIZE)
    station[SX_MOVED] = sim.state[nb2 + SX_MOVED]
    station[SX_TRANSFERS] = 0.0
    station[SX_SPEED] = v
    station[SX_ENERGY] = 0.0
    x3 = np.concatenate([planar_to_3d(sim.state[:nb2], sc2.assembly.n_wings, sc2.assembly.n_nodes), station])
    pos3 = np.zeros_like(positions)
    pos3[:, :, 0], pos3[:, :, 2] = positions[:, :, 0], positions[:, :, 2]
    for a in (x3, controls, moved, pos3, alpha_range):
        a.setflags(write=False)
    op = OperatingPoint(state=x3, controls=controls, cable_speed=float(v), period_s=st.piece_length / v,
                        power_W=float(power), mechanical_power_W=float(mech), reference_power_W=float(p_ref),
                        tension_first_N=t_first, tension_last_N=t_last, converged=bool(res.converged),
                        t_settle_s=float(sim.t), orbit_moved=moved, orbit_positions=pos3,
                        alpha_range_rad=alpha_range, note=note,
                        scene_digest=scene_digest(mill_scene(scene, options, 3)))
    if warn and not op.converged:
        warnings.warn(f"LadderMill operating point: {note}", RuntimeWarning, stacklevel=user_stacklevel())
    return op


#: the fields of an :class:`OperatingPoint` stored as arrays in its cache entry (the others are scalars)
_ARRAY_FIELDS = ("state", "controls", "orbit_moved", "orbit_positions", "alpha_range_rad")


def _from_entry(data: dict) -> OperatingPoint | None:
    """The operating point of a cache entry's arrays (``envs/laddermill/op_cache.py``), read-only as computed;
    None when a field is missing."""
    names = [f.name for f in dataclasses.fields(OperatingPoint)]
    if set(data) != set(names):
        return None
    values = {}
    for name in names:
        a = data[name]
        if name in _ARRAY_FIELDS:
            a = np.array(a)
            a.setflags(write=False)
            values[name] = a
        else:
            values[name] = a.item()  # a 0-d array: the same float's bits, bool or str
    return OperatingPoint(**values)


def cached_operating_point(scene: str, options: tuple, settle: SettleConfig) -> tuple[OperatingPoint, bool]:
    """(operating point, whether it was read from the on-disk cache): the entry of the in-plane scene, ``settle``
    and the code (``op_cache.entry_key``) when one is there and whole, else :func:`compute_operating_point`,
    stored for the next process. The same bits either way."""
    sc2 = mill_scene(scene, options, 2)
    try:
        key = op_cache.entry_key("operating_point", sc2, settle)
    except TypeError:  # a scene field the fingerprint does not know: not cached
        return compute_operating_point(scene, options, settle, warn=False), False
    path = op_cache.entry_path("operating_point", f"{sc2.name}-{sc2.assembly.n_wings}", key)
    data = op_cache.read_entry(path, key)
    op = None if data is None else _from_entry(data)
    if op is not None:
        return op, True
    op = compute_operating_point(scene, options, settle, warn=False)
    op_cache.write_entry(path, key, {f.name: getattr(op, f.name) for f in dataclasses.fields(op)})
    return op, False


#: the (scene, options, settle) that :func:`operating_point` has returned in this process
_RETURNED: set = set()


def operating_point_pending(scene: str, options: tuple, settle: SettleConfig) -> bool:
    """Whether :func:`operating_point` of these arguments would compute the point: not returned before in this
    process and no entry file for it on disk (a present file is not read here: a broken one is recomputed then)."""
    if (scene, options, settle) in _RETURNED:
        return False
    sc2 = mill_scene(scene, options, 2)
    try:
        key = op_cache.entry_key("operating_point", sc2, settle)
    except TypeError:
        return True
    path = op_cache.entry_path("operating_point", f"{sc2.name}-{sc2.assembly.n_wings}", key)
    return path is None or not path.exists()


@input_cache(maxsize=8)
def operating_point(scene: str, options: tuple, settle: SettleConfig) -> OperatingPoint:
    """:func:`compute_operating_point`, memoised per process on (scene, options, settle) and on disk across
    processes (:func:`cached_operating_point`); the warning of a non-converged point is given once per process."""
    op, _ = cached_operating_point(scene, options, settle)
    _RETURNED.add((scene, options, settle))
    if not op.converged:
        warnings.warn(f"LadderMill operating point: {op.note}", RuntimeWarning, stacklevel=user_stacklevel())
    return op


def nominal_positions(op: OperatingPoint, moved: np.ndarray) -> np.ndarray:
    """Reference CG positions per slot (B, n_wings, 3) [m] at the cable moved ``moved`` (B,) [m] since the last
    transfer: linear interpolation of the recorded orbit in s (held at its ends).

    The orbit is sampled every ``SettleConfig.orbit_dt`` up to the last sample before the transfer, so over the last
    sample's stretch of cable (0.5 m at 2 m/s and 0.25 s) the reference is held while the wings move on: there the
    undisturbed mill's in-plane offsets reach 0.40 m on LadderMill-v0 and 0.51 m on v1 (median over the period 0.027
    and 0.023 m; one period, zero action, 2026-12-07). At reset they are 0.049 and 0.044 m, since the start is the
    recorded period's end and the orbit's first sample its start (the largest |dx|, |dz| of the slots' observations
    over 700 zero-action steps of ``gymnasium.make(ID, disturbances=[])``). Kept, because the registered ids'
    observations are built on it."""
    s = np.asarray(moved, dtype=float)
    grid = op.orbit_moved
    j = np.clip(np.searchsorted(grid, s, side="right") - 1, 0, grid.size - 2)
    w = np.clip((s - grid[j]) / (grid[j + 1] - grid[j]), 0.0, 1.0)[:, None, None]
    return (1.0 - w) * op.orbit_positions[j] + w * op.orbit_positions[j + 1]
