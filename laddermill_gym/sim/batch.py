"""Many copies of one scene stepped by one compiled kernel, parallel over copies (numba ``prange``).

Each copy has its own state, controls, time and air (a :class:`~laddermill_gym.atmosphere.field.WindField`:
the wind modulation and an optional frozen gust grid, set with :meth:`BatchSimulator.set_wind` exactly as on a
single simulator); everything else is the shared scene. Used by the batched Gymnasium vector envs and the
benchmark.
"""

from __future__ import annotations

import numbers

import numpy as np

from laddermill_gym.atmosphere.field import WindField, pack_wind_field
from laddermill_gym.kernels.batch import detach_markers, fixed_batch
from laddermill_gym.kernels.contract import GP_SIZE, LIMIT, NONFINITE, OK, SINGULAR, KAir, KWork
from laddermill_gym.kernels.dispatch import has_assemble
from laddermill_gym.kernels.rigid.kinds import WING
from laddermill_gym.model.memory import over_limit
from laddermill_gym.model.packing import make_workspace, pack_model
from laddermill_gym.model.params import Assembly
from laddermill_gym.sim.breakpoints import FIXED_STEP_METHODS, W_METHODS, breaks_mode, fixed_tableau
from laddermill_gym.sim.simulator import IntegratorSettings, limits_array

#: Status codes a smaller step may avoid: a singular matrix, a non-finite state, a speed or rate beyond the limits.
NUMERICAL_FAILURES = (SINGULAR, NONFINITE, LIMIT)
#: Divisors of the physics step tried, in order, on a copy whose control period failed numerically, before its
#: failure is reported (:meth:`BatchSimulator.advance`).
SUBSTEP_DIVISORS = (4, 16)


class BatchSimulator:
    """B copies of one built scene, advanced together with fixed-step RK4.

    Parameters
    ----------
    assembly : Assembly
        The built model shared by all copies.
    n_copies : int
        B, the number of copies (>= 1).
    settings : IntegratorSettings
        dt [s] and the speed / rate limits (the method must be "rk4").
    n_modulation : int
        Samples per copy in the wind modulation series (>= 2); shorter series are padded with their
        last value, which the kernel holds anyway.
    n_grid : int
        Floats per copy for a frozen gust grid (n_xi n_h 3 of the largest ``GustGrid`` a copy will get; 0:
        no copy has one).
    vehicle, n_controls, vehicle_sizes
        The body-loads plug-in (default ``WING``), the number of controls per copy (default 3 per wing) and
        the sizes of the vehicle's output and scratch arrays in each copy's workspace (see
        :meth:`Simulator.make_vehicle`; the rotorcraft's :class:`~laddermill_gym.rotorcraft.craft.CraftSimulator`
        gives all three).

    Attributes
    ----------
    states : ndarray (B, n_state)      controls : ndarray (B, 3 n_wings) [rad]      t : ndarray (B,) [s]
    status : ndarray (B,) int64        integrator status of the last step (0 ok; see kernels/integrate.py)
    air : KAir                         per-copy wind arrays (tmod (B, 2), mod_speed, mod_direction (B, n_mod),
                                       gust header (B, GP_SIZE), gust samples (B, n_grid); None
                                       if n_grid is 0); write with set_wind
    """

    def __init__(self, assembly: Assembly, n_copies: int, settings: IntegratorSettings, n_modulation: int = 2,
                 vehicle=WING, n_controls: int | None = None, vehicle_sizes: tuple[int, int] = (1, 1),
                 n_grid: int = 0):
        if int(n_copies) != n_copies or n_copies < 1:
            raise ValueError(f"n_copies must be a positive integer, got {n_copies!r}")
        if settings.method not in FIXED_STEP_METHODS:
            raise ValueError(f"settings.method = {settings.method!r}: the batch kernel integrates with a fixed-step "
                             f"method, one of {FIXED_STEP_METHODS}")
        if int(n_modulation) < 2:
            raise ValueError(f"n_modulation must be >= 2, got {n_modulation!r}")
        if int(n_grid) != n_grid or n_grid < 0:
            raise ValueError(f"n_grid must be an integer >= 0, got {n_grid!r}")
        self.assembly = assembly
        self.settings = settings
        self.n_copies = int(n_copies)
        nb, ns = self.n_copies, assembly.state_size
        own = assembly.wind.field  # the scene's own air: every copy starts with it, so room for it is made
        nm = max(int(n_modulation), own.speed.size)
        n_grid = max(int(n_grid), 0 if own.grid is None else own.grid.size)
        self.model = pack_model(assembly, vehicle)
        if settings.method in W_METHODS and not has_assemble(self.model.kind):
            raise ValueError(f"settings.method = {settings.method!r}: the linearly implicit methods need a 3D rigid "
                             f"model (this one is {type(self.model.kind).__name__}); use 'rk4'")
        #: the kernels' method argument: None (RK4) or the Rosenbrock-W tableau
        self.tableau = fixed_tableau(settings)
        #: the kernels' ``breaks`` argument: how the steps meet the kinks of each copy's wind (``settings.breakpoints``)
        self.breaks = breaks_mode(settings)
        #: (model without markers, kind, vehicle): the parallel kernels' form of ``model``
        self.detached = detach_markers(self.model)
        one = make_workspace(assembly, *vehicle_sizes)
        per_copy = sum(a.nbytes for a in one) + 8 * (ns + assembly.n_controls + 2 * nm + 8 + int(n_grid) + GP_SIZE)
        why = over_limit(per_copy * nb, f"{nb} copies of {per_copy / 1e3:.4g} kB")
        if why is not None:
            raise ValueError(f"n_copies = {n_copies!r}: {why}")
        self.work = KWork(*[np.zeros((nb, *a.shape), dtype=a.dtype) for a in one])
        self.states = np.zeros((nb, ns))
        self.controls = np.zeros((nb, assembly.n_controls if n_controls is None else int(n_controls)))
        self.t = np.zeros(nb)
        self.tmod = np.tile(np.array([0.0, 1.0]), (nb, 1))
        self.mod_speed = np.ones((nb, nm))
        self.mod_direction = np.zeros((nb, nm))
        gp, gv = (np.zeros((nb, GP_SIZE)), np.zeros((nb, n_grid))) if n_grid else (None, None)
        self.air = KAir(self.tmod, self.mod_speed, self.mod_direction, gp, gv)
        for b in range(nb):
            self.set_wind(b, own)
        self.active = np.ones(nb, dtype=np.int64)
        #: copies whose control period was run again at a finer step (:meth:`advance`), since construction
        self.substep_reruns = 0
        self.status = np.zeros(nb, dtype=np.int64)
        self.done = np.zeros(nb, dtype=np.int64)
        self.limits = limits_array(settings)

    @property
    def n_modulation(self) -> int:
        return self.mod_speed.shape[1]

    @property
    def n_grid(self) -> int:
        return 0 if self.air.gv is None else self.air.gv.shape[1]

    def set_wind(self, copy: int, field: WindField | float, spacing: float | None = None, speed=None,
                 direction=None) -> None:
        """Set the air of one copy: a :class:`~laddermill_gym.atmosphere.field.WindField` (modulation and gust
        grid), as :meth:`Simulator.set_wind <laddermill_gym.sim.simulator.Simulator.set_wind>` does.

        The short form ``set_wind(copy, t0, spacing, speed, direction)`` sets a modulation without a gust grid
        (samples at t0 + i spacing [s] of the speed factor [-] and the direction offset [rad]). At most
        ``n_modulation`` samples (held at the last value afterwards) and a grid of at most ``n_grid`` floats."""
        if not isinstance(field, WindField):
            if not (isinstance(spacing, numbers.Real) and spacing > 0 and np.isfinite(spacing)):
                raise ValueError(f"wind modulation of copy {copy}: spacing = {spacing!r} s must be a finite number > 0")
            try:
                field = WindField(field, spacing, speed, direction)
            except (ValueError, TypeError) as err:
                raise ValueError(f"wind modulation of copy {copy}: {err}") from None
        try:
            tmod, ms, md, gp, gv = pack_wind_field(field, self.n_modulation, self.n_grid)
        except ValueError as err:
            raise ValueError(f"wind of copy {copy}: {err}") from None
        a = self.air
        a.tmod[copy], a.ms[copy], a.md[copy] = tmod, ms, md
        self.work.wjac[copy, 0] = 0.0  # a held iteration matrix (jacobian_every > 1) was built in the former air
        if a.gv is not None:
            a.gp[copy], a.gv[copy] = gp, gv

    def step(self, n_steps: int = 1) -> np.ndarray:
        """Advance every active copy by n_steps steps of the fixed-step method (time advances by the steps each copy
        completed).
        Returns the status array (B,); a failed copy is left at its last good state."""
        fixed_batch(self.t, self.states, self.controls, self.settings.dt, int(n_steps), *self.detached, self.work,
                    self.air, self.active, self.limits, self.tableau, self.breaks, self.status, self.done)
        self.t += self.done * self.settings.dt
        return self.status

    def kernel_head(self, dt: float, nsteps: np.ndarray, dx: np.ndarray) -> tuple:
        """The leading arguments of the env step-and-observe kernels (``kernels/rigid/observe.py``, the craft's):
        times, states, controls, the step ``dt`` [s], the steps per copy ``nsteps`` (B,), the model, workspace, air,
        limits, tableau and breakpoints, and the derivative scratch ``dx`` (B, state size); each task appends its own
        observation arrays. One place for their order, which ``envs/step_callees.py`` reads."""
        return (self.t, self.states, self.controls, dt, nsteps, *self.detached, self.work, self.air, self.limits,
                self.tableau, self.breaks, dx)

    def advance(self, nsteps: np.ndarray, kernel_pass) -> int:
        """Run ``kernel_pass(dt, nsteps)`` (a step kernel over the copies: copy b advances nsteps[b] steps of dt [s],
        0 only observes, < 0 skips it) and advance the copies' times. A copy that fails numerically
        (:data:`NUMERICAL_FAILURES`) is run again from its state before the pass at dt / 4, then dt / 16
        (:data:`SUBSTEP_DIVISORS`): the envs must not end an episode for a failure a smaller step avoids (issue 13:
        the LQR after a 5x wind step failed at 1.6 s with the 0.05 s step, flew 120 s at 0.01 s). A failure that
        persists at dt / 16, or a ground contact, stands. Copies that succeed are untouched (bit for bit). Returns
        the number of copies run again (also added to ``substep_reruns``)."""
        dt = self.settings.dt
        x0, t0 = self.states.copy(), self.t.copy()
        kernel_pass(dt, nsteps)
        self.t += self.done * dt
        if not self.status.any():  # every copy OK (the common case: no np.isin over the copies)
            return 0
        retry = (nsteps > 0) & np.isin(self.status, NUMERICAL_FAILURES)
        n = int(retry.sum())
        if n == 0:
            return 0
        status, done = self.status.copy(), self.done.copy()
        for k in SUBSTEP_DIVISORS:
            self.states[retry], self.t[retry] = x0[retry], t0[retry]
            kernel_pass(dt / k, np.where(retry, nsteps * k, -1))
            self.t[retry] += self.done[retry] * (dt / k)
            status[retry], done[retry] = self.status[retry], self.done[retry] // k
            retry &= np.isin(self.status, NUMERICAL_FAILURES)
            if not retry.any():
                break
        self.status[:], self.done[:] = status, done
        self.substep_reruns += n
        return n

    def failed(self) -> np.ndarray:
        """Boolean mask (B,) of copies whose last step failed."""
        return self.status != OK
