"""The page group of docs/numerics.md (no command to run): the closed forms it quotes, worked here independently of
the package: RK4's stability limits on the imaginary and the negative real axis (where |R(z)| = 1 for R(z) = 1 + z +
z^2/2 + z^3/6 + z^4/24, by bisection), the error ratio per halving of a method of order p (2^p, for ros2's 2 and
ros34pw2's 3), and a residual acceleration's displacement a / omega^2."""

from __future__ import annotations


def _bisect(f, lo: float, hi: float) -> float:
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def rk4_gain(z: complex) -> float:
    """|R(z)| - 1 of classic RK4's stability function."""
    return abs(1 + z + z ** 2 / 2 + z ** 3 / 6 + z ** 4 / 24) - 1.0


def numerics_data() -> dict:
    """{"rk4_imag": the limit |h lambda| on the imaginary axis, "rk4_real": on the negative real axis, "ratio_ros2",
    "ratio_ros34pw2": 2^p, "node_offset": 1e-6 m/s^2 over omega^2 = 7e5 s^-2 [m]}, as the page rounds them."""
    imag = _bisect(lambda y: rk4_gain(1j * y), 1.0, 3.0)  # |R| < 1 below the limit, > 1 above
    real = _bisect(lambda x: rk4_gain(-x), 1.0, 3.0)
    return {"rk4_imag": f"{imag:.2f}", "rk4_real": f"{real:.3f}", "ratio_ros2": str(2 ** 2),
            "ratio_ros34pw2": str(2 ** 3), "node_offset": f"{1e-6 / 7e5:.1e}"}
