"""Roberts' tethered twin-rotor craft in the core simulator: build, simulate, trim, read out power.

The craft is one rigid body (the core's 13-entry body state: position, quaternion, body velocity, body
rates) held by three tethers made of the core's truss elements (sag correction, Voigt damping, cable
aerodynamics and sub-element nodes as for the laddermill). Its loads come from ``rotorcraft/craft_kernels.py``: two
contra-rotating Gessow & Myers rotors side by side, fins and frame drag. The generators hold the rotor
speed. Controls: collective pitch theta0 and differential collective dtheta [rad] (right rotor
theta0 + dtheta, left theta0 - dtheta). Model and choices: ``laddermill_gym/docs/rotorcraft.md``.

Examples
--------
>>> from laddermill_gym.rotorcraft.craft import load_craft
>>> craft = load_craft("roberts_flying_model")
>>> sim = craft.simulator()                  # trimmed in the config's wind
>>> sim.step(n_steps=20)                     # 1 s at the config's 50 ms step (ROS34PW2)
>>> round(sim.electrical_power() / 1e3, 2)   # kW   # doctest: +SKIP
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels.contract import DOF_B3, DOF_N3, N3_POS, N3_SIZE
from laddermill_gym.model.builders import ElementList
from laddermill_gym.model.params import END_FIXED, END_NODE, END_WING, Assembly, WingType
from laddermill_gym.model.states import rotation_from_euler, wing_state_3d
from laddermill_gym.rotorcraft import craft_kernels as _kc
from laddermill_gym.rotorcraft import rotor_kernels as _kr
from laddermill_gym.rotorcraft.config import CraftConfig, load_craft_config
from laddermill_gym.rotorcraft.rotor import INFLOW_MAX_ITER, INFLOW_TOL
from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.sim.statics import accelerations, pack_unknowns, static_equilibrium, unpack_unknowns

#: Names of the craft's controls, in order.
CRAFT_CONTROL_NAMES = ("collective", "differential")
#: Names of the tethers, in element-block order.
TETHER_NAMES = ("rear right", "rear left", "front")


@dataclass(frozen=True)
class CraftLayout:
    """Tether geometry of a built craft.

    anchors : (3, 3) ground points [m]; attach : (3, 3) body attachment points [m]; lengths : (3,)
    unstretched tether lengths [m]; tether_elements : element indices of each tether, anchor end first;
    tether_nodes : free-node indices of each tether; design_position : (3,) CG at the design pose [m].
    """

    anchors: np.ndarray
    attach: np.ndarray
    lengths: np.ndarray
    tether_elements: tuple[tuple[int, ...], ...]
    tether_nodes: tuple[tuple[int, ...], ...]
    design_position: np.ndarray


def tether_layout(cfg: CraftConfig) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Anchors, attachment points, lengths and design CG position for parallel tethers.

    At the design pose (pitch ``design_pitch``, no roll or yaw) every tether runs from its attachment point in
    the direction e = (cos beta, 0, sin beta) (upwind and down) to the ground z = 0. The rear tethers have
    length L_c and their anchors lie at x = 0, y = +-(attachment y); the forward tether gets the length that
    puts its anchor on the ground too (Roberts' Fig. 2: all three at the angle beta).
    Returns anchors (3, 3), body attachments (3, 3), lengths (3,) [m] and the design CG position (3,) [m].
    """
    t = cfg.tethers
    attach = np.array([t.attach_rear, t.attach_rear * np.array([1.0, -1.0, 1.0]), t.attach_front])
    R = rotation_from_euler(0.0, t.design_pitch, 0.0)
    e = np.array([math.cos(t.elevation), 0.0, math.sin(t.elevation)])
    ra = attach @ R.T
    pos = np.array([0.0, ra[0, 1], 0.0]) - ra[0] - t.length * e
    front = pos + ra[2]
    lf = -front[2] / e[2]
    if not lf > 0.0:
        raise ValueError(f"{cfg.file}: the forward tether would need length {lf:.4g} m: check tethers.attach_front")
    lengths = np.array([t.length, t.length, lf])
    anchors = pos + ra + lengths[:, None] * e
    return anchors, attach, lengths, pos


def build_craft_assembly(cfg: CraftConfig) -> tuple[Assembly, CraftLayout]:
    """The craft as a one-body 3D assembly with three tethers of ``tethers.elements`` elements each."""
    anchors, attach, lengths, pos = tether_layout(cfg)
    n = cfg.tethers.elements
    els = ElementList()
    zero = (0.0, 0.0, 0.0)
    tether_elements, tether_nodes = [], []
    n_nodes = 0
    for i in range(3):
        ends = ([(END_FIXED, i, zero)] + [(END_NODE, n_nodes + j, zero) for j in range(n - 1)]
                + [(END_WING, 0, tuple(attach[i]))])
        first = len(els.l0)
        for j in range(n):
            els.add(ends[j], ends[j + 1], lengths[i] / n)
        tether_elements.append(tuple(range(first, first + n)))
        tether_nodes.append(tuple(range(n_nodes, n_nodes + n - 1)))
        n_nodes += n - 1
    span = cfg.hub_spacing + 2.0 * cfg.rotor_radius
    limits = np.zeros((3, 2))
    limits[0], limits[1] = cfg.collective_limits, cfg.differential_limits
    body = WingType(name=cfg.name, mass=cfg.mass, inertia=cfg.inertia,
                    area=2.0 * math.pi * cfg.rotor_radius ** 2, span=span, chord=2.0 * cfg.rotor_radius,
                    r_ref=np.zeros(3), attachment=np.asarray(cfg.tethers.attach_rear, float),
                    control_limits=limits, aero=None)
    cable = cfg.tethers.cable
    asm = Assembly(dim=3, gravity=cfg.gravity, wind=cfg.wind, wing_types=(body,),
                   wing_type_index=np.zeros(1, dtype=np.int64), node_mass=np.zeros(n_nodes),
                   fixed_points=anchors, elements=els.build(cable), sag=cfg.sag, cable_aero=cfg.cable_aero,
                   cable_cn0=cable.cn0, cable_ct0=cable.ct0)
    layout = CraftLayout(anchors=anchors, attach=attach, lengths=lengths,
                         tether_elements=tuple(tether_elements), tether_nodes=tuple(tether_nodes),
                         design_position=pos)
    return asm, layout


def craft_parameters(cfg: CraftConfig) -> np.ndarray:
    """The packed craft parameters ``cp`` of rotorcraft/craft_kernels.py, shape (N_CP,)."""
    cp = np.zeros(_kc.N_CP)
    cp[_kc.C_RADIUS], cp[_kc.C_OMEGA] = cfg.rotor_radius, cfg.rotor_speed
    cp[_kc.C_HUB_X], cp[_kc.C_HUB_Y], cp[_kc.C_HUB_Z] = cfg.hub_x, 0.5 * cfg.hub_spacing, -cfg.hub_height
    cp[_kc.C_FIN_AREA], cp[_kc.C_FIN_SLOPE] = cfg.fin_area, cfg.fin_lift_slope
    cp[_kc.C_FIN_X], cp[_kc.C_FIN_Z], cp[_kc.C_DRAG_AREA] = cfg.fin_x, cfg.fin_z, cfg.drag_area
    cp[_kc.C_ETA], cp[_kc.C_TOL], cp[_kc.C_MAX_ITER] = cfg.electrical_efficiency, INFLOW_TOL, INFLOW_MAX_ITER
    return cp


def craft_vehicle(cfg: CraftConfig) -> _kc.CraftVehicle:
    """The packed model's vehicle for a craft config (``kernels/dispatch.py``)."""
    return _kc.CraftVehicle(craft_parameters(cfg), np.array(cfg.rotor.packed(), dtype=np.float64))


class CraftSimulator(Simulator):
    """The core :class:`~laddermill_gym.sim.simulator.Simulator` with Roberts' craft as body 0.

    Controls are ``(collective, differential)`` [rad], shape (2,), inside the config's limits. Everything
    else (step, advance_to, rhs with python-control's signature, views, diagnostics) is the core's; the
    ``wing_*`` views describe the craft. Extra read-outs: :meth:`rotor_outputs`, :meth:`electrical_power`.
    """

    def __init__(self, config: CraftConfig, assembly: Assembly, layout: CraftLayout, initial_state: np.ndarray,
                 controls: np.ndarray):
        self.config = config
        self.layout = layout
        super().__init__(assembly, initial_state, config.settings, controls)

    def make_vehicle(self):
        """The craft's body-loads plug-in: its parameters and the rotor's blade parameters."""
        return craft_vehicle(self.config)

    def vehicle_sizes(self) -> tuple[int, int]:
        """The rotor outputs (``craft_kernels.N_COUT``) and the inflow solver's scratch."""
        return _kc.N_COUT, _kr.N_OUT

    @property
    def n_controls(self) -> int:
        return 2

    @property
    def control_labels(self) -> list[str]:
        return list(CRAFT_CONTROL_NAMES)

    def _check_controls(self, u) -> np.ndarray:
        u = np.ascontiguousarray(u, dtype=np.float64).reshape(-1)
        if u.shape != (2,):
            raise ValueError(f"controls: expected (collective, differential) of shape (2,), got {u.shape}")
        for j, lim in enumerate((self.config.collective_limits, self.config.differential_limits)):
            if not np.isfinite(u[j]) or u[j] < lim[0] - 1e-12 or u[j] > lim[1] + 1e-12:
                raise ValueError(f"controls: {CRAFT_CONTROL_NAMES[j]} = {u[j]!r} rad is outside "
                                 f"[{lim[0]:.4g}, {lim[1]:.4g}] rad")
        return u

    def rotor_outputs(self) -> dict[str, np.ndarray]:
        """Per-rotor values at the current state, each shape (2,) (right, left): thrust [N], H-force [N],
        shaft torque Q [N m] (> 0 supplied), mechanical power -Q Omega [W], mu, lambda, C_T [-], retreating-tip
        incidence [rad], blade pitch [rad]; plus ``force_body`` (3,) [N] and ``moment_body`` (3,) [N m]."""
        self.rhs(self.t, self.state, self.controls)
        out = self.work.vout
        blocks = out[_kc.V_ROTOR:].reshape(2, _kc.N_RO)
        names = {"thrust_N": _kc.R_THRUST, "hforce_N": _kc.R_HFORCE, "torque_Nm": _kc.R_TORQUE,
                 "power_W": _kc.R_POWER, "mu": _kc.R_MU, "lambda": _kc.R_LAMBDA, "ct": _kc.R_CT,
                 "tip_incidence_rad": _kc.R_TIP_AOA, "pitch_rad": _kc.R_THETA}
        res = {k: blocks[:, j].copy() for k, j in names.items()}
        res["force_body"] = out[_kc.V_FORCE: _kc.V_FORCE + 3].copy()
        res["moment_body"] = out[_kc.V_MOMENT: _kc.V_MOMENT + 3].copy()
        return res

    def electrical_power(self) -> float:
        """Net electrical power at the ground [W]: efficiency x generated mechanical power (or drawn power
        / efficiency when the rotors are driven), Roberts' 95 %."""
        p = float(np.sum(self.rotor_outputs()["power_W"]))
        eta = self.config.electrical_efficiency
        return eta * p if p >= 0.0 else p / eta

    def tether_tensions(self) -> np.ndarray:
        """Tension at the craft end of each tether, shape (3,) [N] (rear right, rear left, front)."""
        ten = self.tensions()
        return np.array([ten[els[-1]] for els in self.layout.tether_elements])

    def views(self) -> dict[str, np.ndarray]:
        v = super().views()
        ro = self.rotor_outputs()
        v.update({"rotor_thrust_N": ro["thrust_N"], "rotor_power_W": ro["power_W"],
                  "electrical_power_W": np.array([self.electrical_power()])})
        return v


def _mirror_expansion(layout: CraftLayout, n_unknowns: int) -> tuple[np.ndarray, np.ndarray]:
    """The trim unknowns of a craft that is mirror-symmetric about its x-z plane, in terms of the independent
    ones. Returns (E, free): E (n_unknowns, n_free) of 0 / +-1 maps the independent unknowns w to the full
    z = E w (craft x, z, pitch; the right rear tether's nodes; the front tether's nodes in x and z; the left
    rear tether mirrors the right); ``free`` (n_free,) indexes the entries of z (and of the residual) that w
    stands for."""
    cols: list[dict[int, float]] = []
    for i in (0, 2, 4):  # the craft's x, z and pitch: its velocity-block dofs v_x, v_z, q (body 0)
        cols.append({i: 1.0})
    right, left, front = layout.tether_nodes
    for kr, kl in zip(right, left, strict=True):
        for c, sign in ((0, 1.0), (1, -1.0), (2, 1.0)):
            cols.append({DOF_B3 + DOF_N3 * kr + c: 1.0, DOF_B3 + DOF_N3 * kl + c: sign})
    for k in front:
        for c in (0, 2):
            cols.append({DOF_B3 + DOF_N3 * k + c: 1.0})
    E = np.zeros((n_unknowns, len(cols)))
    for j, col in enumerate(cols):
        for i, v in col.items():
            E[i, j] = v
    free = np.array([min(col) for col in cols])
    return E, free


def _symmetric_equilibrium(sim, u, x0) -> tuple[np.ndarray, float]:
    """Equilibrium restricted to mirror-symmetric poses (no sideslip, roll or yaw; the rear tethers mirror
    images). Without differential collective or cross wind the trim is one of these, and the restriction
    removes the nearly free sideways drift of craft and tethers that makes the full Jacobian ill-conditioned
    (condition number ~1e7). Returns (z, |full residual|): the caller checks that the full residual vanishes,
    which also catches a scene that is not symmetric."""
    from scipy.optimize import root
    z0 = pack_unknowns(sim, x0)
    E, free = _mirror_expansion(sim.layout, z0.size)

    def full(w):
        return accelerations(sim, sim.rhs(0.0, unpack_unknowns(sim, E @ w), u))

    sol = root(lambda w: full(w)[free], z0[free], method="hybr", options={"xtol": 1e-12})
    z = E @ sol.x
    r = full(sol.x)
    return z, float(np.linalg.norm(r)) if np.all(np.isfinite(r)) else math.inf


def _damped_newton(sim, u, z, iterations: int = 60):
    """Equilibrium unknowns z by damped Newton with a central-difference Jacobian (hybrd can stall on the soft
    yaw direction). Returns (z, |residual|)."""
    def resid(zz):
        return accelerations(sim, sim.rhs(0.0, unpack_unknowns(sim, zz), u))

    r = resid(z)
    for _ in range(iterations):
        J = np.empty((r.size, z.size))
        for i in range(z.size):
            h = 1e-6 * max(1.0, abs(z[i]))
            e = np.zeros(z.size)
            e[i] = h
            J[:, i] = (resid(z + e) - resid(z - e)) / (2.0 * h)
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        lam = 1.0
        r_new = r
        while lam > 1e-4:
            r_new = resid(z + lam * step)
            if np.all(np.isfinite(r_new)) and np.linalg.norm(r_new) < np.linalg.norm(r):
                break
            lam *= 0.5
        if not np.linalg.norm(r_new) < np.linalg.norm(r):
            break
        z, r = z + lam * step, r_new
        if np.linalg.norm(r) < 1e-9 * math.sqrt(z.size):
            break
    return z, float(np.linalg.norm(r))


@dataclass(frozen=True)
class Craft:
    """A loaded craft: config, built assembly and tether layout. :meth:`simulator` trims and compiles."""

    config: CraftConfig
    assembly: Assembly
    layout: CraftLayout

    def design_state(self) -> np.ndarray:
        """The design pose (pitch = design pitch, at rest) with straight tethers: a first guess for trim."""
        t = self.config.tethers
        pos = self.layout.design_position
        euler = np.array([0.0, t.design_pitch, 0.0])
        R = rotation_from_euler(*euler)
        nodes = np.zeros((self.assembly.n_nodes, N3_SIZE))
        for i, idx in enumerate(self.layout.tether_nodes):
            a, b = self.layout.anchors[i], pos + R @ self.layout.attach[i]
            for j, k in enumerate(idx):
                nodes[k, N3_POS: N3_POS + 3] = a + (j + 1) / (len(idx) + 1) * (b - a)
        return np.concatenate([wing_state_3d(pos, euler, np.zeros(3), np.zeros(3)), nodes.reshape(-1)])

    def trim(self, collective: float | None = None, x_guess: np.ndarray | None = None) -> np.ndarray:
        """Static equilibrium in the config's steady wind at the given collective [rad] (default: the
        config's initial collective), no differential. Returns the state (velocities zero).

        Starts from ``x_guess`` (e.g. the trim at a nearby wind speed) and, if that fails, from the design pose.
        From each start it first solves for a mirror-symmetric pose (well conditioned), then, if the full
        residual does not vanish there, for a general one. Raises RuntimeError (naming collective, wind and
        residual) when neither converges."""
        th = self.config.initial_collective if collective is None else float(collective)
        u = np.array([th, 0.0])
        sim = CraftSimulator(self.config, self.assembly, self.layout, self.design_state(), u)
        guesses = [self.design_state()] if x_guess is None else [np.asarray(x_guess, float), self.design_state()]
        residual = math.inf
        for x0 in guesses:
            z, r = _symmetric_equilibrium(sim, u, x0)
            if r < 1e-6 * math.sqrt(z.size):
                return unpack_unknowns(sim, z)
            try:
                return static_equilibrium(sim, x0, controls=u)
            except RuntimeError:
                pass
            z, r = _damped_newton(sim, u, pack_unknowns(sim, x0))
            if r < 1e-6 * math.sqrt(z.size):
                return unpack_unknowns(sim, z)
            residual = min(residual, r)
        raise RuntimeError(f"craft trim at collective {math.degrees(th):.3g} deg, wind v0 = "
                           f"{self.config.wind.v0:.4g} m/s: no equilibrium found (|residual| = "
                           f"{residual:.3g} m/s^2); the rotors may not carry the craft")

    def operating_collective(self, x_guess: np.ndarray | None = None, step: float = math.radians(0.5),
                             start: float | None = None) -> tuple[float, np.ndarray]:
        """Collective [rad] of the blade-limited operating schedule and its trim state: ``start`` (None: the config's
        collective), or, where that drives a retreating blade tip past the blade-incidence limit (Roberts: 13 deg),
        the collective that puts the worse tip exactly at the limit (stepped down from ``start`` by ``step``, then
        Brent's method). Raises RuntimeError if the craft cannot be trimmed within the collective limits."""
        from scipy.optimize import brentq
        lim = self.config.blade_incidence_limit
        cache: dict[float, np.ndarray] = {}

        last = [x_guess]

        def excess(th):
            x = self.trim(th, x_guess=last[0])
            cache[th] = last[0] = x
            s = CraftSimulator(self.config, self.assembly, self.layout, x, np.array([th, 0.0]))
            return float(np.max(s.rotor_outputs()["tip_incidence_rad"])) - lim

        th = self.config.initial_collective if start is None else float(start)
        if excess(th) <= 0.0:
            return th, cache[th]
        lo = th
        while True:
            lo -= step
            if lo < self.config.collective_limits[0]:
                lim_deg = math.degrees(self.config.collective_limits[0])
                raise RuntimeError(f"wind v0 = {self.config.wind.v0:.4g} m/s: the blade-incidence limit needs a "
                                   f"collective below its lower limit {lim_deg:.4g} deg")
            if excess(lo) <= 0.0:
                break
        th = float(brentq(excess, lo, lo + step, xtol=1e-5))
        return th, self.trim(th, x_guess=cache[lo])

    def simulator(self, collective: float | None = None, state: np.ndarray | None = None) -> CraftSimulator:
        """A craft simulator started at ``state`` (default: trimmed at ``collective``)."""
        th = self.config.initial_collective if collective is None else float(collective)
        x = self.trim(th) if state is None else state
        return CraftSimulator(self.config, self.assembly, self.layout, x, np.array([th, 0.0]))


def load_craft(name_or_path="roberts_flying_model", config: CraftConfig | None = None) -> Craft:
    """Load a craft config (a name in configs/rotorcraft/ or a path) and build it; or build ``config``."""
    cfg = load_craft_config(name_or_path) if config is None else config
    asm, layout = build_craft_assembly(cfg)
    return Craft(cfg, asm, layout)
