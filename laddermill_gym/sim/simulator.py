"""The simulator object: a built scene, its compiled kernels, state, controls and named views."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.kernels.contract import (
    LIM_GROUND,
    LIM_RATE,
    LIM_SIZE,
    LIM_SPEED,
    OK,
)
from laddermill_gym.kernels.dispatch import has_assemble
from laddermill_gym.kernels.integrate import rhs_entry as _rhs_kernel
from laddermill_gym.kernels.rigid.kinds import WING
from laddermill_gym.kernels.rigid.rosenbrock import JACOBIAN_EVERY_MAX
from laddermill_gym.model.packing import make_workspace, pack_model
from laddermill_gym.model.params import CONTROL_NAMES, N_CONTROLS, Assembly
from laddermill_gym.sim.body_views import BodyViews
from laddermill_gym.sim.breakpoints import (
    ADAPTIVE_METHODS,
    BREAKPOINT_MODES,
    FIXED_STEP_METHODS,
    INTEGRATOR_METHODS,
    W_ADAPTIVE,
    W_METHODS,
    adaptive_pieces,
    fixed_pieces,
    modulation_kinks,
)
from laddermill_gym.sim.reports import GROUND_MODES, diagnose, failure_message, quaternion_problems, state_problems
from laddermill_gym.sim.station_views import (
    check_station_controls,
    station_control_labels,
)


class SimulationError(RuntimeError):
    """The integration broke down (the message names the time, the body or element and the quantity) or a wing or
    cable node reached the ground with ``ground_contact`` "stop" (the time, the body and its height)."""


#: DP5(4) step budgets: one ``step()`` (a few physics steps) and one ``advance_to`` call
STEP_MAX_STEPS, ADVANCE_MAX_STEPS = 10_000_000, 100_000_000


@dataclass(frozen=True)
class IntegratorSettings:
    """Integrator choice and safety limits.

    method : "rk4" (fixed step dt [s]), "dp54" (adaptive, rtol/atol), "ros1" / "ros2" / "ros2t" / "ros34pw2"
    (linearly implicit Rosenbrock-W of order 1 / 2 / 2 / 3, fixed step dt [s] not limited by the cable's axial
    modes; 3D rigid models; docs/numerics.md) or "ros34pw2a" (ROS34PW2 with error control, rtol/atol: the step is
    chosen by accuracy).
    max_speed [m/s], max_rate [rad/s]: a state beyond these is reported as exploding.
    ground_height [m]: height h = -z of the ground (global z points down).
    ground_contact : what a wing CG or free cable node at h <= ground_height after a step does: "stop" (the run
    stops at the last state above the ground with a SimulationError naming the time, the body and its height),
    "flag" (the run goes on; ``sim.recording.record`` flags the contact per body and sample) or "off" (no ground).
    breakpoints : step exactly onto the kinks of the wind's time modulation (``sim/breakpoints.py``): "inside"
    splits a step at a kink inside it; "all" also gives a step that ends or starts on a kink its own segment's
    modulation (fourth-order RK4 on a kink grid aligned with the steps; changes such runs slightly); "off"
    integrates across kinks (the behaviour before).
    jacobian_every : steps per iteration matrix of a fixed-step W-method (1: built every step, the default and the
    registered envs' bits; k > 1: kept for k steps, ``kernels/rigid/rosenbrock.py`` ``with_jacobian_reuse``).
    """

    method: str = "rk4"
    dt: float = 0.01
    rtol: float = 1e-8
    atol: float = 1e-10
    max_speed: float = 300.0
    max_rate: float = 100.0
    ground_height: float = 0.0
    ground_contact: str = "stop"
    breakpoints: str = "inside"
    jacobian_every: int = 1

    def __post_init__(self):
        k = self.jacobian_every
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 1 <= k <= JACOBIAN_EVERY_MAX:
            raise ValueError(f"IntegratorSettings.jacobian_every = {k!r}: must be an integer from 1 to "
                             f"{JACOBIAN_EVERY_MAX} (steps per Jacobian, an int64 in the kernels)")
        if k != 1 and self.method not in W_METHODS:
            raise ValueError(f"IntegratorSettings.jacobian_every = {k!r}: only the fixed-step W-methods reuse a "
                             f"Jacobian (method = {self.method!r})")
        if self.breakpoints not in BREAKPOINT_MODES:
            raise ValueError(f"IntegratorSettings.breakpoints = {self.breakpoints!r}: must be one of "
                             f"{', '.join(repr(m) for m in BREAKPOINT_MODES)}")
        if self.method not in INTEGRATOR_METHODS:
            raise ValueError(f"IntegratorSettings.method = {self.method!r}: must be one of "
                             f"{', '.join(repr(m) for m in INTEGRATOR_METHODS)}")
        for name, unit in (("dt", "s"), ("rtol", "-"), ("atol", "state units"), ("max_speed", "m/s"),
                           ("max_rate", "rad/s")):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float, np.number)) or not 0.0 < v < np.inf:
                raise ValueError(f"IntegratorSettings.{name} = {v!r}: must be a finite number > 0 [{unit}]")
        if self.ground_contact not in GROUND_MODES:
            raise ValueError(f"IntegratorSettings.ground_contact = {self.ground_contact!r}: must be one of "
                             f"{', '.join(repr(m) for m in GROUND_MODES)}")
        h = self.ground_height
        if isinstance(h, bool) or not isinstance(h, (int, float, np.number)) or not np.isfinite(h):
            raise ValueError(f"IntegratorSettings.ground_height = {h!r}: must be a finite number [m]")


def limits_array(settings: IntegratorSettings) -> np.ndarray:
    """The kernels' ``limits`` (slots ``LIM_*``): largest speed [m/s] and angular rate [rad/s], and the ground
    height [m] where a contact stops the run (-inf unless ``ground_contact`` is "stop")."""
    lim = np.zeros(LIM_SIZE)
    lim[LIM_SPEED], lim[LIM_RATE] = settings.max_speed, settings.max_rate
    lim[LIM_GROUND] = float(settings.ground_height) if settings.ground_contact == "stop" else -np.inf
    return lim


class Simulator(BodyViews):
    """A compiled simulator of one built scene.

    Parameters
    ----------
    assembly : Assembly
        The built model (``laddermill_gym.ladder.scene.load_scene(...).assembly``).
    initial_state : ndarray, shape (n_state,)
        State at t = 0 (layout in docs/model.md).
    settings : IntegratorSettings
    controls : ndarray, shape (3 n_wings,), optional
        Initial controls [rad] (elevator, rudder, aileron per wing).
    """

    def __init__(self, assembly: Assembly, initial_state: np.ndarray, settings: IntegratorSettings | None = None,
                 controls: np.ndarray | None = None):
        self.assembly = assembly
        self.settings = settings or IntegratorSettings()
        self.model = pack_model(assembly, self.make_vehicle())
        self.work = make_workspace(assembly, *self.vehicle_sizes())
        #: the wind's variation in time and space now in force (:meth:`set_wind`)
        self.wind_field = assembly.wind.field
        if assembly.dim == 2 and assembly.wind.gust is not None:
            raise ValueError("in-plane (dim = 2) simulation takes no gust grid (wind.gust); use dimension 3")
        if assembly.dim == 2 and (assembly.wind.direction_inf != 0.0 or np.any(assembly.wind.mod_direction != 0.0)):
            raise ValueError("in-plane (dim = 2) simulation needs a fixed wind direction: "
                             f"direction_inf = {assembly.wind.direction_inf}, "
                             f"max |mod_direction| = {np.max(np.abs(assembly.wind.mod_direction))}")
        self.limits = limits_array(self.settings)
        self._dx = np.zeros(assembly.state_size)
        self.initial_state = self._check_state(initial_state).copy()
        self.initial_controls = (np.zeros(assembly.n_controls) if controls is None
                                 else self._check_controls(controls).copy())
        self.reset()

    def make_vehicle(self):
        """The body-loads plug-in of the packed model (``kernels/dispatch.py``): ``WING`` for winged bodies;
        a simulator of another vehicle (the rotorcraft) returns its own."""
        return WING

    def vehicle_sizes(self) -> tuple[int, int]:
        """Sizes of the vehicle's output and scratch arrays in the workspace (``W.vout``, ``W.vscratch``)."""
        return 1, 1

    # ------------------------------------------------------------------ state handling
    @property
    def n_state(self) -> int:
        return self.assembly.state_size

    @property
    def n_controls(self) -> int:
        return self.assembly.n_controls

    @property
    def control_labels(self) -> list[str]:
        """One label per control entry, e.g. 'wing0_elevator'."""
        return ([f"wing{k}_{n}" for k in range(self.assembly.n_wings) for n in CONTROL_NAMES]
                + station_control_labels(self.assembly))

    def _check_state(self, x) -> np.ndarray:
        x = np.ascontiguousarray(x, dtype=np.float64)
        if x.shape != (self.n_state,):
            raise ValueError(f"state: expected shape ({self.n_state},), got {x.shape}")
        if not np.all(np.isfinite(x)):
            i = int(np.flatnonzero(~np.isfinite(x))[0])
            raise ValueError(f"state[{i}] is not finite: {x[i]}")
        return x

    def _check_controls(self, u) -> np.ndarray:
        u = np.ascontiguousarray(u, dtype=np.float64)
        if u.shape != (self.n_controls,):
            raise ValueError(f"controls: expected shape ({self.n_controls},), got {u.shape}")
        for k in range(self.assembly.n_wings):
            lim = self.assembly.wing(k).control_limits
            for j in range(N_CONTROLS):
                v = u[N_CONTROLS * k + j]
                if not np.isfinite(v) or v < lim[j, 0] - 1e-12 or v > lim[j, 1] + 1e-12:
                    raise ValueError(
                        f"controls: wing {k} {CONTROL_NAMES[j]} = {v!r} rad is outside "
                        f"[{lim[j, 0]:.4g}, {lim[j, 1]:.4g}] rad")
        check_station_controls(self.assembly, u)
        return u

    def reset(self, state: np.ndarray | None = None, t: float = 0.0, controls: np.ndarray | None = None,
              check: bool = True) -> np.ndarray:
        """Set the state (default: the initial state), time [s] and controls [rad]; returns the state.

        ValueError (naming the entry, body or quantity) for a non-finite time or state, a wing quaternion of zero
        or non-finite norm, or (``check``) a body speed or rate beyond the settings' ``max_speed`` / ``max_rate``.
        ``check=False`` takes any finite state: for read-out snapshots of where a run got to (a failed copy's)."""
        if isinstance(t, bool) or not isinstance(t, (int, float, np.number)) or not np.isfinite(t):
            raise ValueError(f"t = {t!r}: the time must be a finite number [s]")
        if state is not None:
            state = self._check_state(state)
            problems = state_problems(self, state) if check else []
            if problems:
                raise ValueError(f"state: {'; '.join(problems)}")
        self.state = (self.initial_state if state is None else state).copy()
        self.t = float(t)
        self.controls = (self.initial_controls if controls is None else self._check_controls(controls)).copy()
        #: the error-controlled methods' proposal for their next step [s], kept between calls (None: settings.dt)
        self._h_next = None
        #: steps of the error-controlled methods ("dp54", "ros34pw2a") since the reset: [accepted, rejected]
        self.adaptive_steps = [0, 0]
        self.work.wjac[0] = 0.0  # a held iteration matrix (jacobian_every > 1) belongs to the run before
        return self.state

    # ------------------------------------------------------------------ air
    def set_wind(self, field: WindField) -> None:
        """Set the wind's variation in time and space (:class:`~laddermill_gym.atmosphere.field.WindField`: the
        speed-factor and direction-offset modulation and an optional frozen gust grid) from now on; the steady
        profile, direction and density stay the scene's. The same call as ``BatchSimulator.set_wind`` on one
        copy."""
        if not isinstance(field, WindField):
            raise ValueError(f"field = {field!r}: must be a laddermill_gym.atmosphere.field.WindField")
        if self.assembly.dim == 2 and (np.any(field.direction != 0.0) or field.grid is not None):
            raise ValueError("in-plane (dim = 2) simulation needs a fixed wind direction and no gust grid: "
                             f"max |direction| = {np.max(np.abs(field.direction))} rad, grid = {field.grid!r}")
        tmod, ms, md, gp, gv = pack_wind_field(field)
        self.model = self.model._replace(tmod=tmod, ms=ms, md=md, gp=gp, gv=gv)
        self.wind_field = field
        self.work.wjac[0] = 0.0  # a held iteration matrix was built in the former air

    @property
    def breakpoint_times(self) -> np.ndarray:
        """Times [s] where the wind modulation of ``self.model`` has a kink (the steps stop on them), sorted;
        recomputed when the model's modulation arrays are replaced."""
        m = self.model
        cached = getattr(self, "_breakpoint_cache", None)
        if cached is None or any(a is not b for a, b in zip(cached[0], (m.tmod, m.ms, m.md), strict=True)):
            cached = ((m.tmod, m.ms, m.md), modulation_kinks(m.tmod, m.ms, m.md))
            self._breakpoint_cache = cached
        return cached[1]

    # ------------------------------------------------------------------ dynamics
    def rhs(self, t: float, x: np.ndarray, u: np.ndarray | None = None, params: dict | None = None) -> np.ndarray:
        """State derivative dx/dt = f(t, x, u) with python-control's ``updfcn`` signature.

        ``control.nlsys(sim.rhs, states=sim.n_state, inputs=sim.n_controls)`` works on it, but for control design
        use :func:`laddermill_gym.control.plant.plant_system` (minimal coordinates: the full state's quaternions
        give a pole at 0 per wing). ``params`` must be empty: the full-state right-hand side takes no parameters
        (ValueError otherwise; the plant takes ``wind_speed_factor``).
        """
        if params:
            raise ValueError(f"rhs: params {sorted(params)} are not taken by the full-state right-hand side; "
                             "laddermill_gym.control.plant.plant_system takes 'wind_speed_factor'")
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1)
        u = self.controls if u is None else np.ascontiguousarray(u, dtype=np.float64).reshape(-1)
        if x.shape != (self.n_state,) or u.shape != (self.n_controls,):
            raise ValueError(f"rhs: x must have {self.n_state} and u {self.n_controls} entries, "
                             f"got {x.shape} and {u.shape}")
        if not math.isfinite(t):
            raise ValueError(f"rhs: t must be finite, got {t!r}")
        if not np.all(np.isfinite(x)):
            i = int(np.flatnonzero(~np.isfinite(x))[0])
            raise SimulationError(f"t = {t:.6g} s: {self.state_name(i)} is {x[i]} (state entry {i}): "
                                  "a non-finite state")
        bad = quaternion_problems(self, x)
        if bad:
            raise SimulationError(f"t = {t:.6g} s: {bad[0]}: the state is outside what the model can evaluate")
        dx = np.zeros(self.n_state)
        if _rhs_kernel(float(t), x, u, dx, self.model, self.work) != 0:
            raise SimulationError(f"t = {t:.6g} s: the mass matrix is singular")
        if not np.all(np.isfinite(dx)):
            i = int(np.flatnonzero(~np.isfinite(dx))[0])
            raise SimulationError(f"t = {t:.6g} s: the derivative of {self.state_name(i)} is {dx[i]} (state entry {i} "
                                  f"= {x[i]!r}): the state is outside what the model can evaluate")
        return dx

    def step(self, controls: np.ndarray | None = None, n_steps: int = 1) -> np.ndarray:
        """Advance n_steps fixed RK4 steps of ``settings.dt`` (or the same time span with DP5(4)) with
        the controls held; returns the new state (a view of ``self.state``). A step that holds a kink of the
        wind modulation is split at it (``settings.breakpoints``, ``sim/breakpoints.py``)."""
        if controls is not None:
            self.controls = self._check_controls(controls).copy()
        if int(n_steps) != n_steps or n_steps < 0:
            raise ValueError(f"n_steps must be a non-negative integer, got {n_steps!r}")
        self._check_method(self.settings.method)
        if self.settings.method in FIXED_STEP_METHODS:
            status, h = fixed_pieces(self, int(n_steps))
        else:
            status, h = self._adaptive(self.t + n_steps * self.settings.dt)
        if status != OK:
            self._raise(status, h)
        return self.state

    def _check_method(self, method: str) -> None:
        """ValueError when ``method`` is a linearly implicit one and the model kind has no block assembly (checked
        when stepping, not when building: the statics and trim build in-plane simulators from a scene's settings
        that never step)."""
        if (method in W_METHODS or method in W_ADAPTIVE) and not has_assemble(self.model.kind):
            raise ValueError(f"IntegratorSettings.method = {method!r}: the linearly implicit methods need a 3D rigid "
                             f"model (this one is {type(self.model.kind).__name__}); use 'rk4' or 'dp54'")

    def _adaptive(self, t_end: float):
        """Integrate to t_end [s] with the settings' error-controlled method; (status, size of the last step tried
        [s]). On a failure the time is that of the last accepted step, where the state is left."""
        s = self.settings
        if not t_end > self.t:  # step(n_steps=0): no step, and no proposal of a zero step for the next run (its
            return OK, self._first_step()  # controller grew 0 to 0: DP5(4) spun through its budget of steps)
        status, h, t = adaptive_pieces(self, t_end, min(self._first_step(), t_end - self.t), s.rtol, s.atol,
                                       STEP_MAX_STEPS, s.method)
        self.t = t_end if status == OK else t
        self._h_next = h if status == OK and h > 0.0 else None
        return status, h

    def _first_step(self) -> float:
        """The first trial step [s] of an error-controlled run: where the previous run's controller left off (its
        proposal, not its last step cut short to land on the output time), else ``settings.dt``."""
        return self.settings.dt if self._h_next is None else self._h_next

    def advance_to(self, t_end: float, rtol: float | None = None, atol: float | None = None) -> np.ndarray:
        """Integrate to t_end [s] (finite, not before the current time) with an error-controlled method at tolerances
        ``rtol``, ``atol`` (> 0; default the settings'): the settings' method when it is one ("ros34pw2a"), else the
        Dormand-Prince 5(4). ValueError for a bad time or tolerance; SimulationError when the integration breaks down
        (at most 1e8 steps)."""
        s = self.settings
        if isinstance(t_end, bool) or not isinstance(t_end, (int, float, np.number)) or not np.isfinite(t_end):
            raise ValueError(f"t_end = {t_end!r}: must be a finite time [s]")
        if t_end < self.t:
            raise ValueError(f"t_end = {t_end!r} s is before the current time {self.t!r} s: the simulator does not "
                             "run backwards (reset to start again)")
        rtol = s.rtol if rtol is None else rtol
        atol = s.atol if atol is None else atol
        for name, v in (("rtol", rtol), ("atol", atol)):
            if isinstance(v, bool) or not isinstance(v, (int, float, np.number)) or not 0.0 < v < np.inf:
                raise ValueError(f"{name} = {v!r}: must be a finite number > 0 (an absolute tolerance of 0 stalls "
                                 "the error control on any state entry that passes through zero)")
        method = s.method if s.method in ADAPTIVE_METHODS else "dp54"
        self._check_method(method)
        h0 = self._first_step()
        status, h, t = adaptive_pieces(self, float(t_end), min(h0, float(t_end) - self.t) if t_end > self.t else h0,
                                       rtol, atol, ADVANCE_MAX_STEPS, method)
        if status != OK:
            self.t = t  # the last accepted step, where the state is left
            self._h_next = None
            self._raise(status, h)
        self.t = float(t_end)
        self._h_next = h if h > 0.0 else None
        return self.state

    def _raise(self, status: int, h: float):
        """Raise the report of a step of h [s] that failed with ``status`` (``sim/reports.py``: a ground contact
        names the time, the bodies and their heights; a breakdown the time, the body and the quantity over its
        limit in the failed step, and :meth:`diagnose` of the last good state)."""
        raise SimulationError(failure_message(self, status, h))

    def diagnose(self) -> str:
        """Name the body, node or element with the largest speed, rate or derivative in the current state."""
        return diagnose(self)
