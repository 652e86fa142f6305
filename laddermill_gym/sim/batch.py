"""Many copies of one scene stepped by one compiled kernel, parallel over copies (numba ``prange``).

Each copy has its own state, controls, time and wind modulation (speed factor and direction offset sampled
on a uniform time grid, the same representation as :meth:`WindParams.with_modulation`); everything else is
the shared scene. Used by the batched Gymnasium vector envs and the benchmark.
"""

from __future__ import annotations

import numpy as np

from laddermill_gym.kernels.batch import detach_markers, rk4_batch
from laddermill_gym.kernels.contract import KWork
from laddermill_gym.kernels.integrate import OK
from laddermill_gym.kernels.rigid.kinds import WING
from laddermill_gym.model.packing import make_workspace, pack_model
from laddermill_gym.model.params import N_CONTROLS, Assembly
from laddermill_gym.sim.simulator import IntegratorSettings, limits_array


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
    vehicle, n_controls, vehicle_sizes
        The body-loads plug-in (default ``WING``), the number of controls per copy (default 3 per wing) and
        the sizes of the vehicle's output and scratch arrays in each copy's workspace (see
        :meth:`Simulator.make_vehicle`; the rotorcraft's :class:`~laddermill_gym.rotorcraft.craft.CraftSimulator`
        gives all three).

    Attributes
    ----------
    states : ndarray (B, n_state)      controls : ndarray (B, 3 n_wings) [rad]      t : ndarray (B,) [s]
    status : ndarray (B,) int64        integrator status of the last step (0 ok; see kernels/integrate.py)
    """

    def __init__(self, assembly: Assembly, n_copies: int, settings: IntegratorSettings, n_modulation: int = 2,
                 vehicle=WING, n_controls: int | None = None, vehicle_sizes: tuple[int, int] = (1, 1)):
        if int(n_copies) != n_copies or n_copies < 1:
            raise ValueError(f"n_copies must be a positive integer, got {n_copies!r}")
        if settings.method != "rk4":
            raise ValueError(f"settings.method = {settings.method!r}: the batch kernel integrates with 'rk4'")
        if int(n_modulation) < 2:
            raise ValueError(f"n_modulation must be >= 2, got {n_modulation!r}")
        self.assembly = assembly
        self.settings = settings
        self.n_copies = int(n_copies)
        nb, ns, nm = self.n_copies, assembly.state_size, int(n_modulation)
        self.model = pack_model(assembly, vehicle)
        #: (model without markers, kind, vehicle): the parallel kernels' form of ``model``
        self.detached = detach_markers(self.model)
        one = make_workspace(assembly, *vehicle_sizes)
        self.work = KWork(*[np.zeros((nb, *a.shape), dtype=a.dtype) for a in one])
        self.states = np.zeros((nb, ns))
        self.controls = np.zeros((nb, N_CONTROLS * assembly.n_wings if n_controls is None else int(n_controls)))
        self.t = np.zeros(nb)
        self.tmod = np.tile(np.array([0.0, 1.0]), (nb, 1))
        self.mod_speed = np.ones((nb, nm))
        self.mod_direction = np.zeros((nb, nm))
        self.active = np.ones(nb, dtype=np.int64)
        self.status = np.zeros(nb, dtype=np.int64)
        self.done = np.zeros(nb, dtype=np.int64)
        self.limits = limits_array(settings)

    @property
    def n_modulation(self) -> int:
        return self.mod_speed.shape[1]

    def set_wind(self, copy: int, t0: float, spacing: float, speed: np.ndarray, direction: np.ndarray) -> None:
        """Wind modulation of one copy: samples at t0 + i spacing [s] of the speed factor [-] and the
        direction offset [rad] (at most n_modulation samples; held at the last value afterwards)."""
        speed = np.asarray(speed, float).reshape(-1)
        direction = np.asarray(direction, float).reshape(-1)
        n = speed.size
        if direction.size != n or n < 1 or n > self.n_modulation:
            raise ValueError(f"wind modulation of copy {copy}: speed and direction need the same length "
                             f"1..{self.n_modulation}, got {speed.size} and {direction.size}")
        if not (spacing > 0 and np.isfinite(spacing) and np.isfinite(t0)):
            raise ValueError(f"wind modulation of copy {copy}: t0 = {t0!r}, spacing = {spacing!r} s")
        if not (np.all(np.isfinite(speed)) and np.all(np.isfinite(direction)) and np.all(speed >= 0)):
            raise ValueError(f"wind modulation of copy {copy}: non-finite samples or a negative speed factor")
        self.tmod[copy] = (t0, spacing)
        self.mod_speed[copy, :n] = speed
        self.mod_speed[copy, n:] = speed[-1]
        self.mod_direction[copy, :n] = direction
        self.mod_direction[copy, n:] = direction[-1]

    def step(self, n_steps: int = 1) -> np.ndarray:
        """Advance every active copy by n_steps RK4 steps (time advances by the steps each copy completed).
        Returns the status array (B,); a failed copy is left at its last good state."""
        rk4_batch(self.t, self.states, self.controls, self.settings.dt, int(n_steps), *self.detached, self.work,
                  self.tmod, self.mod_speed, self.mod_direction, self.active, self.limits, self.status, self.done)
        self.t += self.done * self.settings.dt
        return self.status

    def failed(self) -> np.ndarray:
        """Boolean mask (B,) of copies whose last step failed."""
        return self.status != OK
