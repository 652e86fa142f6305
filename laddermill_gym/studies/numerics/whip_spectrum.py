"""Which modes carry the apex whip, and which of them a W-method damps: ``python -m
laddermill_gym.studies.numerics.whip_spectrum SCENE --time 10 --at 3 6 8 --methods ros34pw2:0.0667 rk4:0.0222``.

Along the work-precision study's step forcing (``work_precision.forcing_setup``) the scene is run by a fine RK4
(the reference, ``--dt-ref``) to each time of ``--at``; there the full Jacobian df/dx is formed by central
differences of ``Simulator.rhs`` (``sim/stable_step.py``'s products, column by column) and decomposed (numpy's
LAPACK ``eig``). Each run of ``--methods`` (method:step) is run to the same time; its state error against the
reference, e = x_run - x_ref, is written in the eigenvector basis, e = V c, and each mode's share |c_k| ||v_k|| of
the error (restricted to the wings' lateral y positions, the quantity that binds in issue 32 point 4) is
printed with the eigenvalue and, at the method's step h, the exact one-step factor |exp(h lambda)| and the
method's |R(h lambda)| (RK4: its polynomial; a Rosenbrock-W method with the exact Jacobian: R(z) = 1 + z m^T
(I - z G)^-1 1 in the transformed form's weights, ``stability_function_w``). A mode whose |R| is well below
|exp(h lambda)| is damped by the method, not carried.
"""

from __future__ import annotations

import argparse

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_SIZE
from laddermill_gym.sim.breakpoints import W_METHODS
from laddermill_gym.sim.stable_step import stability_function
from laddermill_gym.studies.numerics.scenes import build_simulator, with_settings
from laddermill_gym.studies.numerics.work_precision import forcing_setup


def stability_function_w(tableau, z) -> np.ndarray:
    """R(z) of a Rosenbrock(-W) method with the exact Jacobian, from its transformed tableau (gamma, alpha, a, c,
    m, mhat) (Hairer & Wanner IV.7, (7.4')): with G the original gamma matrix (gamma on the diagonal) and the
    original alpha, R(z) = 1 + z b^T (I - z (alpha + G))^-1 1, b = m G (Hairer & Wanner IV.7, (7.17))."""
    gam, _, a, c, m, _ = tableau
    s = m.size
    gi = np.eye(s) / gam[0] - c  # G^-1 = diag(1/gamma) - c
    G = np.linalg.inv(gi)
    alpha = a @ G
    b = m @ G
    B = alpha + G
    z = np.atleast_1d(np.asarray(z, dtype=complex))
    one = np.ones(s)
    return np.array([1.0 + zz * (b @ np.linalg.solve(np.eye(s) - zz * B, one)) for zz in z])


def factor(method: str, z: np.ndarray) -> np.ndarray:
    """|R(z)| of ``method`` (rk4 or a fixed-step W method)."""
    if method == "rk4":
        return np.abs(stability_function("rk4", z))
    return np.abs(stability_function_w(W_METHODS[method], z))


def dense_jacobian(sim, t: float, x: np.ndarray) -> np.ndarray:
    """df/dx at (t, x) by central differences, step 1e-6 max(1, |x_i|) per column."""
    u = sim.controls
    n = x.size
    J = np.empty((n, n))
    for i in range(n):
        e = 1e-6 * max(1.0, abs(x[i]))
        xp, xm = x.copy(), x.copy()
        xp[i] += e
        xm[i] -= e
        J[:, i] = (sim.rhs(t, xp, u) - sim.rhs(t, xm, u)) / (2 * e)
    return J


def run_to(base, x0, wind, method: str, dt: float, t: float) -> np.ndarray:
    """State at time t [s] of ``method`` at step dt [s] from x0 (None if it breaks down)."""
    sim = with_settings(base, state=x0, wind=wind, method=method, dt=dt)
    n = int(round(t / dt))
    if abs(n * dt - t) > 1e-9:
        raise ValueError(f"--at {t}: not a multiple of the step {dt} s of {method}")
    try:
        sim.step(n_steps=n)
    except Exception:  # noqa: BLE001 (a breakdown is a result here)
        return None
    return sim.state.copy()


def analyse(scene: str, duration: float, times, methods, dt_ref: float, top: int) -> None:
    """Print, per time of ``times`` [s], the Jacobian's spectrum and each run's error parts (module doc)."""
    base = build_simulator(scene)
    x0, wind = forcing_setup(base, "step", duration)
    nw = base.assembly.n_wings
    lat = np.array([B3_SIZE * k + B3_POS + 1 for k in range(nw)])
    for t in times:
        xr = run_to(base, x0, wind, "rk4", dt_ref, t)
        ev = with_settings(base, state=xr, wind=wind)
        J = dense_jacobian(ev, t, xr)
        lam, V = np.linalg.eig(J)
        unstable = lam[lam.real > 1e-6]
        print(f"\n{scene} t = {t} s: {lam.size} eigenvalues, largest |lambda| {np.abs(lam).max():.1f} 1/s; "
              f"Re > 0: {unstable.size} (largest Re {lam.real.max():.3f} 1/s)")
        for spec in methods:
            method, dt = spec.split(":")
            dt = float(dt)
            xs = run_to(base, x0, wind, method, dt, t)
            if xs is None:
                print(f"  {method} at {dt} s: breaks down before {t} s")
                continue
            parts = error_parts(lam, V, xs - xr, lat, method, dt)
            share, fm, fx = parts["share"], parts["factor"], parts["exact"]
            print(f"  {method} at {dt} s: largest lateral error {parts['lateral']:.3g} m; modes by their share of it:")
            print("    lambda [1/s]          share [m]  |exp(h l)|  |R(h l)|  R/exp")
            for k in np.argsort(-share)[:top]:
                print(f"    {lam[k].real:9.3f} {lam[k].imag:+9.2f}i  {share[k]:9.3g}  {fx[k]:9.4f}  {fm[k]:8.4f}"
                      f"  {fm[k] / fx[k]:6.3f}")
            print(f"    damped below 0.9 of exact per step: {parts['n_damped']} of {lam.size} modes; the error's part "
                  f"in them: {parts['damped']:.3g} m lateral; in the {parts['n_slow']} modes with |lambda| < 1 1/s "
                  f"(all resolved): {parts['slow']:.3g} m")


def error_parts(lam: np.ndarray, V: np.ndarray, e: np.ndarray, lat: np.ndarray, method: str, h: float) -> dict:
    """A run's state error e written in the eigenvectors V (e = V c) of the Jacobian (eigenvalues lam [1/s]), read
    on the entries ``lat``: "lateral" max |e[lat]| [m]; "share" |c_k| ||V[lat, k]|| per mode [m]; "factor" |R(h
    lambda)| of ``method`` at step h [s] and "exact" |exp(h lambda)|; "damped" max |(V c)[lat]| over the modes
    with factor < 0.9 exact (oscillating: |Im lambda| > 1 1/s) and "slow" the same over |lambda| < 1 1/s [m]."""
    c = np.linalg.solve(V, e)
    z = h * lam
    fm, fx = factor(method, z), np.abs(np.exp(z))
    damped = (fm / fx < 0.9) & (np.abs(lam.imag) > 1.0)
    slow = np.abs(lam) < 1.0
    part = (V[:, damped] @ c[damped]).real  # conjugate pairs together: a real vector
    part_slow = (V[:, slow] @ c[slow]).real
    return {"lateral": float(np.abs(e[lat]).max()), "share": np.abs(c) * np.linalg.norm(V[lat, :], axis=0),
            "factor": fm, "exact": fx, "n_damped": int(damped.sum()), "n_slow": int(slow.sum()),
            "damped": float(np.abs(part[lat]).max(initial=0.0)), "slow": float(np.abs(part_slow[lat]).max(initial=0.0))}


def method_spec(text: str) -> str:
    """An argparse type for ``--methods``: ``METHOD:STEP`` with a step in seconds; the method's name is checked by
    the integrator's settings when it runs."""
    method, sep, dt = text.partition(":")
    try:
        ok = bool(sep and method) and float(dt) > 0.0
    except ValueError:
        ok = False
    if not ok:
        raise argparse.ArgumentTypeError(f"--methods {text!r}: expected METHOD:STEP with STEP > 0 in seconds, "
                                         "e.g. ros34pw2:0.0667")
    return text


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="whip_spectrum", description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("--time", type=float, default=10.0, help="the forcing's run length T [s] (step at 0.3037 T)")
    p.add_argument("--at", type=float, nargs="+", default=[6.0, 8.0], help="times of the linearisation [s]")
    p.add_argument("--methods", nargs="+", type=method_spec,
                   default=["ros34pw2:0.0666666666666667", "rk4:0.0222222222222222"])
    p.add_argument("--dt-ref", type=float, default=0.002, help="reference RK4 step [s]")
    p.add_argument("--top", type=int, default=8, help="modes listed per run")
    a = p.parse_args(argv)
    analyse(a.scene, a.time, a.at, a.methods, a.dt_ref, a.top)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
