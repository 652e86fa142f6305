"""A stable explicit step found automatically: the fastest eigenvalues of the Jacobian of ``Simulator.rhs`` at a
state, and the largest step h for which every h lambda lies in the method's region of absolute stability.

Eigenvalues: the Jacobian is applied as central finite differences of the compiled right-hand side,
J v = (f(x + e v) - f(x - e v)) / (2 e). Up to ``DENSE_MAX`` states it is formed column by column and all its
eigenvalues are taken (numpy's LAPACK); above that scipy's ARPACK (``scipy.sparse.linalg.eigs`` on a
``LinearOperator``, the largest-magnitude few) needs only Jacobian-vector products. Both are maintained
libraries; nothing iterative is written here.

Stability region: R(z) = 1 + z b^T (I - z A)^-1 1 from the Butcher tableau (``kernels/integrate.py``'s
coefficients for DP5(4), the classic one for RK4). Along the ray through each eigenvalue the first |R(z)| > 1
is found (a scan then a bracketing root), so complex eigenvalues get their own bound (RK4: 2.785 on the
negative real axis, 2 sqrt 2 = 2.828 on the imaginary axis). A mode with Re lambda >= 0 (a physical
instability, such as the mill's slow lateral divergence) has no stable step; it is held to the imaginary-axis
bound |h lambda| <= the method's imaginary limit.

``check_step(sim)`` compares the simulator's dt with the estimate and warns (or raises) naming both: the
detection of a run past its stable step (``ladder_chain`` at 0.025 s oscillates without any error). A scene's
``simulator()`` runs it once per scene, step and initial state (``ladder/scene.py``); ``laddermill simulate`` too.
The command ``laddermill stable-step SCENE`` is in ``studies/numerics/stable_step.py``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from laddermill_gym.kernels import integrate as KI

#: the dense Jacobian is formed up to this many states; above it ARPACK works on products
DENSE_MAX = 200
#: a run whose dt exceeds ``SAFETY`` x the estimate is flagged (the estimate is for the linearisation at one state)
SAFETY = 1.0

_RK4 = (np.array([[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 1.0, 0]]),
        np.array([1 / 6, 1 / 3, 1 / 3, 1 / 6]))
_DP5 = (np.array([[0, 0, 0, 0, 0, 0],
                  [KI.A21, 0, 0, 0, 0, 0],
                  [KI.A31, KI.A32, 0, 0, 0, 0],
                  [KI.A41, KI.A42, KI.A43, 0, 0, 0],
                  [KI.A51, KI.A52, KI.A53, KI.A54, 0, 0],
                  [KI.A61, KI.A62, KI.A63, KI.A64, KI.A65, 0]]),
        np.array([KI.B1, 0.0, KI.B3, KI.B4, KI.B5, KI.B6]))
#: Butcher tableaux (A, b) of the explicit methods a Simulator runs
TABLEAUX = {"rk4": _RK4, "dp54": _DP5}


class UnstableStepWarning(UserWarning):
    """The simulator's step exceeds the estimated stability limit of its explicit method."""


def stability_function(method: str, z: complex | np.ndarray) -> np.ndarray:
    """R(z) = 1 + z b^T (I - z A)^-1 1 of ``method`` ("rk4" or "dp54"); one step of y' = lambda y multiplies y
    by R(h lambda). For an explicit method (A strictly lower triangular) this is the polynomial
    1 + sum_k z^k b^T A^(k-1) 1, evaluated here."""
    A, b = TABLEAUX[method]
    coef, v = [1.0], np.ones(len(b))
    for _ in range(len(b)):
        coef.append(float(b @ v))
        v = A @ v
    return np.polyval(coef[::-1], np.atleast_1d(np.asarray(z, dtype=complex)))


def ray_limit(method: str, angle: float) -> float:
    """Largest r with |R(r e^{i angle})| <= 1 on [0, r] (angle in (pi/2, 3 pi/2): the left half-plane; for angles
    towards the right half-plane the imaginary-axis limit, see the module text)."""
    from scipy.optimize import brentq
    angle = math.atan2(math.sin(angle), math.cos(angle))
    if abs(angle) <= math.pi / 2:
        angle = math.copysign(math.pi / 2, angle if angle != 0 else 1.0)
    d = complex(math.cos(angle), math.sin(angle))

    def excess(r):
        return abs(stability_function(method, r * d)[0]) - 1.0

    rs = np.linspace(0.001, 8.0, 8000)
    # on the imaginary axis RK4's |R| - 1 is about -r^6/72 near 0: use a tolerance below that, above roundoff
    vals = np.abs(stability_function(method, rs * d)) - 1.0
    bad = np.flatnonzero(vals > 1e-12)
    if bad.size == 0:
        return float(rs[-1])
    i = int(bad[0])
    if i == 0:
        return 0.0
    return float(brentq(lambda r: excess(r) - 1e-12, rs[i - 1], rs[i], xtol=1e-12))


def jacobian_eigenvalues(sim, x: np.ndarray | None = None, t: float | None = None, k: int = 20) -> np.ndarray:
    """Eigenvalues [1/s] of df/dx of ``sim.rhs`` at state x (default the current state) and time t: all of them
    (n <= DENSE_MAX) or the k largest in magnitude (ARPACK), sorted by decreasing magnitude."""
    x = np.array(sim.state if x is None else x, dtype=float)
    t = sim.t if t is None else float(t)
    u = sim.controls
    scale = np.maximum(np.abs(x), 1.0)

    def jv(v):
        v = np.asarray(v, dtype=float).reshape(-1)
        nv = np.linalg.norm(v / scale)
        if nv == 0.0:
            return np.zeros_like(v)
        e = 1e-6 / nv
        return (sim.rhs(t, x + e * v, u) - sim.rhs(t, x - e * v, u)) / (2 * e)

    n = x.size
    if n <= DENSE_MAX:
        J = np.empty((n, n))
        for i in range(n):
            v = np.zeros(n)
            v[i] = 1.0
            J[:, i] = jv(v)
        lam = np.linalg.eigvals(J)
    else:
        from scipy.sparse.linalg import LinearOperator, eigs

        op = LinearOperator((n, n), matvec=jv, dtype=float)
        lam = eigs(op, k=k, which="LM", return_eigenvectors=False, tol=1e-6, maxiter=50 * n,
                   v0=np.random.default_rng(0).standard_normal(n))
    return lam[np.argsort(-np.abs(lam))]


@dataclass(frozen=True)
class StableStep:
    """The estimate: largest stable step [s] of ``method``, the eigenvalue that sets it [1/s], and the limits of
    the few fastest eigenvalues."""

    method: str
    dt_max: float
    eigenvalue: complex
    fastest: tuple[complex, ...]

    def __str__(self) -> str:
        lam = self.eigenvalue
        return (f"{self.method}: largest stable step {self.dt_max:.4g} s (set by the eigenvalue "
                f"{lam.real:.4g} {'+-' if lam.imag else '+'} {abs(lam.imag):.4g}i 1/s)")


def estimate_stable_step(sim, method: str | None = None, x: np.ndarray | None = None, t: float | None = None,
                         eigenvalues: np.ndarray | None = None) -> StableStep:
    """Largest step [s] of ``method`` (default the simulator's) for which every Jacobian eigenvalue at x is in
    the stability region (slow modes with Re lambda >= 0 are physical instabilities and bound nothing here
    unless fast)."""
    method = method or sim.settings.method
    if method not in TABLEAUX:
        raise ValueError(f"method = {method!r}: must be one of {sorted(TABLEAUX)}")
    lam = jacobian_eigenvalues(sim, x, t) if eigenvalues is None else np.asarray(eigenvalues)
    lam = lam[np.abs(lam) > 1e-9]
    best, which = math.inf, 0j
    for ll in lam:
        h = ray_limit(method, math.atan2(ll.imag, ll.real)) / abs(ll)
        if h < best:
            best, which = h, complex(ll)
    return StableStep(method, best, which, tuple(complex(v) for v in lam[:6]))


def check_step(sim, action: str = "warn", safety: float = SAFETY) -> StableStep:
    """Compare ``sim.settings.dt`` (RK4) with the estimate at the current state; if dt > safety x estimate, warn
    (:class:`UnstableStepWarning`) or raise ValueError (``action`` "error") naming both. Returns the estimate."""
    est = estimate_stable_step(sim, "rk4")
    if sim.settings.method == "rk4" and sim.settings.dt > safety * est.dt_max:
        msg = (f"dt = {sim.settings.dt:g} s is above the estimated stability limit of RK4 at this state, "
               f"{est.dt_max:.4g} s (eigenvalue {est.eigenvalue:.4g} 1/s): the run may oscillate without failing")
        if action == "error":
            raise ValueError(msg)
        warnings.warn(msg, UnstableStepWarning, stacklevel=2)
    return est
