"""The page groups of docs/work_precision.md: the explicit methods' stability limits worked here from their published
Butcher tableaux (independently of ``sim/stable_step.py``), and ``laddermill stable-step SCENE`` for the four scenes of
its table (a fresh process each, about 10-40 s of CPU each)."""

from __future__ import annotations

import numpy as np

from docsite.paper_figures import printed_match, run_command

#: Classic RK4 (Kutta 1901): (A, b).
RK4 = ([[0, 0, 0, 0], [1 / 2, 0, 0, 0], [0, 1 / 2, 0, 0], [0, 0, 1, 0]], [1 / 6, 1 / 3, 1 / 3, 1 / 6])
#: Dormand & Prince (1980), the fifth-order solution of DOPRI5 (Hairer, Norsett & Wanner, Table II.5.2): (A, b).
DP5 = ([[0] * 7, [1 / 5, 0, 0, 0, 0, 0, 0], [3 / 40, 9 / 40, 0, 0, 0, 0, 0], [44 / 45, -56 / 15, 32 / 9, 0, 0, 0, 0],
        [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0, 0, 0],
        [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0, 0],
        [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0]],
       [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0])
#: The scenes of the page's stable-step table, in its order.
SCENES = ("tethered_wing", "ladder_chain", "roberts_flying_model", "laddermill")


def stability_polynomial(a: list, b: list) -> np.ndarray:
    """Coefficients of R(z) = 1 + sum_k z^k b^T A^(k-1) 1 of an explicit Runge-Kutta method, lowest power first."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    coef, v = [1.0], np.ones(len(b))
    for _ in range(len(b)):
        coef.append(float(b @ v))
        v = a @ v
    return np.array(coef)


def first_exit(coef: np.ndarray, ray: complex) -> float:
    """The smallest h > 0 with |R(h ray)| > 1: scanned on a 1e-4 grid up to 6, refined by bisection."""
    gain = lambda h: abs(np.polynomial.polynomial.polyval(h * ray, coef)) - 1.0  # noqa: E731
    grid = np.arange(1, 60001) * 1e-4
    above = np.nonzero(np.abs(np.polynomial.polynomial.polyval(grid * ray, coef)) > 1.0 + 1e-12)[0]
    lo, hi = grid[above[0] - 1], grid[above[0]]
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gain(mid) <= 0 else (lo, mid)
    return 0.5 * (lo + hi)


def precision_data() -> dict:
    """|h lambda| limits on the negative real and the imaginary axis of RK4 and DP5(4), as the page rounds them."""
    rk4, dp5 = stability_polynomial(*RK4), stability_polynomial(*DP5)
    return {"rk4_real": f"{first_exit(rk4, -1.0):.3f}", "rk4_imag": f"{first_exit(rk4, 1j):.3f}",
            "dp5_real": f"{first_exit(dp5, -1.0):.3f}", "dp5_imag": f"{first_exit(dp5, 1j):.3f}"}


def stable_steps() -> dict:
    """Per scene, what ``laddermill stable-step SCENE`` prints: states, the scene's dt [s], RK4's and DP5(4)'s largest
    stable step [s] and RK4's limiting eigenvalue [1/s] (real part, |imaginary part|), as printed (4 digits)."""
    found = {}
    for scene in SCENES:
        argv = ["laddermill_gym.cli", "stable-step", scene]
        out, where = run_command(argv, 900), f"python -m {' '.join(argv)}"
        head = printed_match(rf"^{scene}: (\d+) states, dt ([\d.e-]+) s", out, where)
        rk4 = printed_match(r"rk4: largest stable step ([\d.e-]+) s \(set by the eigenvalue ([-\d.e]+) \+- ([\d.e]+)i",
                            out, where)
        dp5 = printed_match(r"dp54: largest stable step ([\d.e-]+) s", out, where)
        found[scene] = {"states": head.group(1), "dt": head.group(2), "rk4": rk4.group(1), "re": rk4.group(2),
                        "im": rk4.group(3), "dp5": dp5.group(1)}
    return found


#: docs/work_precision.md's groups for :data:`docsite.page_figures.GROUPS`.
PRECISION_GROUPS = {"precision_data": precision_data, "stable_steps": stable_steps}
