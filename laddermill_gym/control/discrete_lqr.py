"""Discrete LQR on the zero-order-hold discretisation of a continuous model (``control.c2d``, ``control.dlqr``;
from :data:`~laddermill_gym.control.riccati.DOUBLING_MIN_STATES` states the Riccati equation by doubling,
:mod:`laddermill_gym.control.riccati`), and a text table of eigenvalues (natural frequency, damping, period,
doubling or halving time)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import control
import numpy as np

from laddermill_gym.control.riccati import DOUBLING_MIN_STATES, dare_doubling


@dataclass(frozen=True)
class DiscreteLQR:
    """A discrete LQR design on the ZOH discretisation of (A, B).

    Attributes
    ----------
    A, B : continuous model;  Ad, Bd : ZOH discretisation at ``dt`` [s]
    Q, R : weights;  K : gain (u = -K x);  S : Riccati solution
    closed_loop : eigenvalues of Ad - Bd K (discrete, |z| < 1 is stable)
    open_loop : eigenvalues of A (continuous)
    """

    A: np.ndarray
    B: np.ndarray
    Ad: np.ndarray
    Bd: np.ndarray
    dt: float
    Q: np.ndarray
    R: np.ndarray
    K: np.ndarray
    S: np.ndarray
    closed_loop: np.ndarray
    open_loop: np.ndarray


def discrete_lqr(A: np.ndarray, B: np.ndarray, Q: np.ndarray, R: np.ndarray, dt: float) -> DiscreteLQR:
    """ZOH-discretise (A, B) at ``dt`` [s] (``control.c2d``) and solve the discrete LQR (``control.dlqr``; for
    n >= ``DOUBLING_MIN_STATES`` states the Riccati equation by doubling, ``riccati.dare_doubling``).

    Notes
    -----
    Minimises sum_k x_k^T Q x_k + u_k^T R u_k subject to x_{k+1} = Ad x_k + Bd u_k with
    Ad = expm(A dt), Bd = int_0^dt expm(A s) ds B; u_k = -K x_k, K = (R + Bd^T S Bd)^-1 Bd^T S Ad.
    """
    n = A.shape[0]
    sysc = control.ss(A, B, np.eye(n), np.zeros((n, B.shape[1])))
    sysd = control.c2d(sysc, dt, method="zoh")
    Ad, Bd = np.asarray(sysd.A), np.asarray(sysd.B)
    S = dare_doubling(Ad, Bd, Q, R) if n >= DOUBLING_MIN_STATES else None
    if S is None:
        K, S, E = control.dlqr(Ad, Bd, Q, R)
    else:  # the gain and closed loop as control.dlqr forms them
        K = np.linalg.solve(R + Bd.T @ S @ Bd, Bd.T @ S @ Ad)
        E = np.linalg.eigvals(Ad - Bd @ K)
    return DiscreteLQR(A=A, B=B, Ad=Ad, Bd=Bd, dt=float(dt), Q=Q, R=R, K=np.asarray(K), S=np.asarray(S),
                       closed_loop=np.asarray(E), open_loop=np.linalg.eigvals(A))


def continuous_equivalent(z: np.ndarray, dt: float) -> np.ndarray:
    """Continuous-time equivalents s = ln(z) / dt [1/s] of discrete eigenvalues z."""
    return np.log(np.asarray(z, dtype=complex)) / dt


def mode_table(eigenvalues: np.ndarray, dt: float | None = None) -> str:
    """A text table of eigenvalues (continuous; discrete if ``dt`` is given, shown with their continuous
    equivalents): real and imaginary part [1/s], natural frequency [rad/s], damping ratio, period [s],
    time to double (unstable) or halve (stable) [s]. Conjugate pairs are shown once."""
    ev = np.asarray(eigenvalues, dtype=complex)
    s = continuous_equivalent(ev, dt) if dt is not None else ev
    order = np.argsort(-s.real)
    head = ("   |z|     " if dt is not None else "") + \
        "   Re [1/s]   Im [1/s]  wn [rad/s]    zeta   period [s]  t2x/t1/2 [s]"
    lines = [head]
    for i in order:
        si = s[i]
        if si.imag < -1e-12:
            continue
        wn = abs(si)
        zeta = -si.real / wn if wn > 0 else float("nan")
        period = 2 * math.pi / si.imag if si.imag > 1e-12 else float("inf")
        t2 = math.log(2) / abs(si.real) if si.real != 0 else float("inf")
        kind = "double" if si.real > 0 else "half"
        pre = f"{abs(ev[i]):9.5f}  " if dt is not None else ""
        lines.append(f"{pre}{si.real:10.4f} {si.imag:10.4f} {wn:11.4f} {zeta:8.3f} {period:11.2f}  "
                     f"{t2:9.2f} ({kind})")
    return "\n".join(lines)
