"""Driver of the point-mass fidelity: holds the packed string, its workspace, state and the kites' commanded
attitude, and steps it with the explicit (symplectic Euler) or the implicit (linearly implicit Euler,
block-tridiagonal along the string) kernel of ``kernels/pointmass/``.

The rigid ``sim.Simulator`` cannot carry it without changing its signatures: it is built from an ``Assembly``
(bodies with 13 states, element tables, the block-elimination tree) and allocates the seven stage vectors of
RK4 / DP5(4), which at 500,000 nodes would alone take 7 x 24 MB.
"""

from __future__ import annotations

import numba
import numpy as np
from tqdm import tqdm

from laddermill_gym.kernels import fork_state
from laddermill_gym.kernels.contract import N3_POS, N3_SIZE, N3_VEL, PM_OK, PP_DA, PP_EA, PP_L0, PP_MU
from laddermill_gym.kernels.pointmass.explicit import (
    CHUNK,
    explicit_advance,
    explicit_advance_serial,
    tensions,
    tensions_serial,
)
from laddermill_gym.kernels.pointmass.implicit import implicit_advance, implicit_advance_serial
from laddermill_gym.model.pointmass import PointMassString, held_bytes, make_work, pack

METHODS = ("explicit", "implicit")
STATUS_TEXT = {0: "ok", 2: "non-finite state", 3: "speed limit exceeded", 4: "a node at or below the ground"}


class PointMassError(RuntimeError):
    """A step failed (non-finite state, speed limit, ground); the message names the status and the time."""


def check_fork_safe() -> None:
    """RuntimeError saying what to do, in a process forked from one whose numba threads run on GNU OpenMP (where
    numba would end the process at the first parallel loop); called before the parallel point-mass kernels (the
    serial ones, which strings of at most ``CHUNK`` nodes run, need no thread pool and run in such a process)."""
    if fork_state.forked_after_gnu_openmp():
        raise RuntimeError(
            "the point-mass kernels cannot run in this process on more than one thread: it was forked "
            "(multiprocessing's 'fork' start method, AsyncVectorEnv's default on Linux) from a process whose numba "
            "threads run on GNU OpenMP, which is not fork-safe. Start the workers with 'forkserver' or 'spawn' "
            "(gymnasium.make_vec(id, n, vectorization_mode='async', vector_kwargs={'context': 'forkserver'}); SB3's "
            "SubprocVecEnv does so by default), or pick a fork-safe numba threading layer before numba starts "
            "(NUMBA_THREADING_LAYER=workqueue, or tbb with the tbb package installed)")


def kernel_threads(n_nodes: int, threads: int) -> int:
    """Threads the kernels of an ``n_nodes`` string use: at most ``threads`` and one per ``CHUNK`` nodes (waking a
    thread pool costs more than a chunk's work); 1 means the serial kernels."""
    return max(1, min(int(threads), -(-int(n_nodes) // CHUNK)))


def run_on_threads(threads: int, serial, parallel, *args):
    """``serial(*args)`` when ``threads`` is 1: no parallel loop, numba's thread pool is not started (so a process
    forked from this one can still run the kernels; issue 34 item 11); else ``parallel(*args)`` on ``threads``
    of numba's threads (at most its current count, restored after). Both give the same bits on one thread."""
    if threads <= 1:
        return serial(*args)
    check_fork_safe()
    before = numba.get_num_threads()
    numba.set_num_threads(min(threads, before))
    try:
        return parallel(*args)
    finally:
        numba.set_num_threads(before)


def explicit_stable_dt(s: PointMassString, station=None) -> float:
    """Largest stable symplectic-Euler step [s] of the string's axial dynamics (on the moving cable's ``station``:
    the smaller of this and the step its short end elements allow, :func:`_moving_stable_dt`). On its highest mode (the
    undamped chain's omega = 2c/l0, c = sqrt(EA/mu), damped at the Voigt rate g = 4 DA/(mu l0^2)) the step's
    amplification matrix is stable while (dt/t_c)^2 + dt/t_d < 1, t_c = l0/c, t_d = mu l0^2/(2 DA) (Jury's conditions on
    its trace 2 - (omega dt)^2 - dt g and determinant 1 - dt g); the limit is the positive root
    dt = t_c^2 (-1/t_d + sqrt(1/t_d^2 + 4/t_c^2))/2 = 2 / (1/t_d + sqrt(1/t_d^2 + 4/t_c^2)) (the second form without
    the cancellation), l0/c without damping. It lies below both t_c and t_d: min(t_c, t_d), returned until
    2026-12-07, overstated it by up to the golden ratio, 1.62x, at t_c = t_d."""
    c = s.cable
    l0 = s.element_length
    tc = l0 / np.sqrt(c.EA / c.mass_per_length)
    if not c.DA > 0:
        uniform = float(tc)
    else:
        inv_td = 2.0 * c.DA / (c.mass_per_length * l0 * l0)
        uniform = float(2.0 / (inv_td + np.sqrt(inv_td * inv_td + 4.0 / (tc * tc))))
    if station is None:
        return uniform
    return min(uniform, _moving_stable_dt(s, station))


def _moving_stable_dt(s: PointMassString, station) -> float:
    """The stable step [s] of a string on the moving cable's station (``model.pointmass_mill.PointMassStation``):
    its end elements run from a to a + l_e and from b down to b - l_e, and a short one raises the highest mode far
    above the uniform string's (a node between a 0.1 l_e element and an l_e one: about 4.5x the rate, so about a
    fifth of the step where damping rules; a review of 2026-12-08 saw the env's 0.9 x the uniform limit end in a
    speed limit). Voigt damping is proportional to the stiffness (DA / l against EA / l per element), so every mode
    of M^-1 K (lumped masses mu (l_j + l_(j+1)) / 2, both ends anchored) has g = beta omega^2, beta = DA / EA, and
    the step is stable while omega^2 dt^2 + 2 g dt < 4: dt = -beta + sqrt(beta^2 + 4 / lambda_max), at the two
    extreme configurations (s = 0 and s -> l_e), lambda_max from LAPACK's bisection on the symmetric tridiagonal
    M^-1/2 K M^-1/2 (O(n)). For the uniform string this is the closed form above (its infinite chain's highest
    mode bounds the finite one's)."""
    from scipy.linalg import eigvalsh_tridiagonal

    c, n, le = s.cable, int(s.n_nodes), float(station.element_length)
    a, b = float(station.first_length), float(station.last_length)
    beta = c.DA / c.EA if c.DA > 0 else 0.0
    worst = 0.0
    for first, last in ((a, b), (a + le, max(b - le, 1e-3 * le))):  # b - s > 0 for s < l_e: b >= l_e
        lengths = np.full(n + 1, float(s.element_length))
        lengths[0], lengths[-1] = first, last
        k = c.EA / lengths  # (n + 1,) element stiffness [N/m]
        m = c.mass_per_length * 0.5 * (lengths[:-1] + lengths[1:])  # (n,) node masses [kg]
        diag = (k[:-1] + k[1:]) / m
        off = -k[1:-1] / np.sqrt(m[:-1] * m[1:])
        lam = eigvalsh_tridiagonal(diag, off, select="i", select_range=(n - 1, n - 1))[0] if n > 1 else diag[0]
        worst = max(worst, float(lam))
    return float(-beta + np.sqrt(beta * beta + 4.0 / worst))


class PointMassSimulator:
    """Point-mass string and kites stepped at a fixed dt [s] by ``method`` ('explicit' or 'implicit'), the
    parallel loops on ``threads`` threads (default: all of numba's). ``copy=False`` adopts a contiguous float64
    ``x0`` as the state instead of copying it (24 MB at 500,000 nodes)."""

    def __init__(self, string: PointMassString, x0: np.ndarray, controls: np.ndarray, dt: float,
                 method: str = "implicit", t0: float = 0.0, threads: int | None = None, copy: bool = True):
        if method not in METHODS:
            raise ValueError(f"method = {method!r}: must be one of {METHODS}")
        if not dt > 0:
            raise ValueError(f"dt = {dt!r}: must be > 0")
        self.string = string
        self.M = pack(string)
        self.W = make_work(string)
        self.x = np.ascontiguousarray(x0, dtype=np.float64)
        if copy:
            self.x = self.x.copy()
        if self.x.shape != (string.state_size,):
            raise ValueError(f"initial state shape {self.x.shape}: must be ({string.state_size},)")
        self.u = np.ascontiguousarray(controls, dtype=np.float64).copy()
        if self.u.size != 3 * max(1, string.n_kites):
            raise ValueError(f"controls size {self.u.size}: must be 3 per kite ({3 * string.n_kites})")
        self.dt, self.method, self.t = float(dt), method, float(t0)
        #: Threads of the parallel loops (default: numba's, i.e. the machine's cores or NUMBA_NUM_THREADS).
        self.threads = numba.config.NUMBA_NUM_THREADS if threads is None else int(threads)
        #: the kernels' threads for this string (:func:`kernel_threads`; 1: the serial kernels)
        self.kernel_threads = kernel_threads(string.n_nodes, self.threads)
        serial = self.kernel_threads == 1
        if method == "explicit":
            self._advance = explicit_advance_serial if serial else explicit_advance
        else:
            self._advance = implicit_advance_serial if serial else implicit_advance
        self._tensions = tensions_serial if serial else tensions

    def step(self, nsteps: int = 1) -> None:
        """Advance by ``nsteps`` steps; raises PointMassError on a failed step (state at that step).
        The parallel loops run on at most one thread per ``CHUNK`` nodes (a string shorter than that runs the
        serial kernels: waking a thread pool costs more than its work)."""
        st, done = run_on_threads(self.kernel_threads, self._advance, self._advance, self.t, self.x, self.u, self.dt,
                                  int(nsteps), self.M, self.W)
        self.t += done * self.dt
        if st != PM_OK:
            raise PointMassError(f"step failed at t = {self.t:.6g} s: {STATUS_TEXT.get(st, st)}")

    def advance(self, duration: float, chunk: int = 100, progress: bool = False) -> None:
        """Advance by ``duration`` [s] (rounded to whole steps), ``chunk`` steps per kernel call."""
        n = int(round(duration / self.dt))
        bar = tqdm(total=n, desc=f"{self.method} dt={self.dt:.3g}s", disable=not progress, unit="step")
        while n > 0:
            k = min(chunk, n)
            self.step(k)
            n -= k
            bar.update(k)
        bar.close()

    @property
    def positions(self) -> np.ndarray:
        """Node positions (n, 3) [m] (a view)."""
        return self.x.reshape(-1, N3_SIZE)[:, N3_POS:N3_POS + 3]

    @property
    def velocities(self) -> np.ndarray:
        """Node velocities (n, 3) [m/s] (a view)."""
        return self.x.reshape(-1, N3_SIZE)[:, N3_VEL:N3_VEL + 3]

    def tensions(self, damped: bool = True) -> np.ndarray:
        """Element tensions (n_e,) [N] of the current state (Voigt damping included when ``damped``)."""
        run_on_threads(self.kernel_threads, self._tensions, self._tensions, self.x, self.M, self.W.tension, damped)
        return self.W.tension.copy()

    def held_bytes(self) -> dict[str, int]:
        """Bytes held by the state, controls, workspace and packed parameters."""
        return held_bytes(self.M, self.W, self.x, self.u)

    def describe(self) -> str:
        p = self.M.par
        return (f"{self.string.n_nodes} nodes, l0 = {p[PP_L0]:.4g} m, EA = {p[PP_EA]:.3g} N, DA = {p[PP_DA]:.3g} "
                f"N s, mu = {p[PP_MU]:.3g} kg/m, {self.string.n_kites} kites, {self.method} dt = {self.dt:.3g} s")
