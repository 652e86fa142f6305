"""The linear stability functions of the shipped Rosenbrock-W tableaux and of two methods the docs compare them with.

docs/work_precision.md ("Keeping the unresolved oscillations does not help") quotes |R(inf)| of ROS3Pw and ROS34PW3
(Rang & Angermann 2005), not in the package, and |R(4i)| of those two against the shipped ROS34PW2. Each figure is
evaluated here from a tableau, independently of the integrator's kernels:

* for a Rosenbrock method with the exact Jacobian, y' = lambda y gives y1 = R(h lambda) y0 with
  R(z) = 1 + z b^T (I - z B)^-1 1, B = alpha + Gamma (strictly lower alpha_ij and gamma_ij, gamma on the diagonal;
  Hairer & Wanner, Solving ODEs II, sect. IV.7);
* the shipped methods are stored in the transformed form (7.4'); their published (alpha, Gamma, b) is recovered from
  it (G = (I / gamma - c)^-1, alpha = a G, b = m G) and, as a second route, one transformed-form step of
  y' = lambda y is taken by hand.

Oracles: closed forms (ROS2 at gamma: (1 + (1 - 2 gamma) z + (gamma^2 - 2 gamma + 1/2) z^2) / (1 - gamma z)^2,
worked by hand from its two stages; ros2t's ((1 + z/4) / (1 - z/4))^2), L-stability of ROS2 and ROS34PW2 (R(inf) =
0, published), the methods' classical orders (R(z) - exp(z) = O(z^(p+1)): a typo in a coefficient breaks it), and
the page's figures.
"""

import numpy as np
import pytest

from laddermill_gym.kernels.rigid.rosenbrock import ROS2, ROS2T, ROS34PW2

# Rang & Angermann (2005), BIT Numer. Math. 45, tables of ROS3Pw (3 stages, order 3) and ROS34PW3 (4 stages, order
# 4 with the exact Jacobian): gamma, alpha_ij, gamma_ij (strictly lower), b
_G3 = 7.8867513459481287e-1  # 1/2 + sqrt(3)/6
ROS3PW = (np.array([[0.0, 0, 0], [1.5773502691896257, 0, 0], [0.5, 0, 0]]),
          np.array([[_G3, 0, 0], [-1.5773502691896257, _G3, 0], [-6.7075317547305480e-1, -1.7075317547305482e-1,
                                                                    _G3]]),
          np.array([1.0566243270259355e-1, 4.9038105676657971e-2, 8.4529946162074843e-1]))
_G4 = 1.0685790213016289
ROS34PW3 = (np.array([[0.0, 0, 0, 0], [2.5155456020628817, 0, 0, 0], [5.0777280103144085e-1, 0.75, 0, 0],
                      [1.3959081404277204e-1, -3.3111001065419338e-1, 8.2040559712714178e-1, 0]]),
            np.array([[_G4, 0, 0, 0], [-2.5155456020628817, _G4, 0, 0],
                      [-8.7991339217106512e-1, -9.6014187766190695e-1, _G4, 0],
                      [-4.1731389379448741e-1, 4.1091047035857703e-1, -1.3558873204765276, _G4]]),
            np.array([2.2047681286931747e-1, 2.7828278331185935e-3, 7.1844787635140066e-3, 7.6955588053404989e-1]))


def published_form(transformed):
    """(alpha (s, s), Gamma (s, s) with gamma on its diagonal, b (s,)) from a shipped transformed tableau."""
    gamma, _, a, c, m, _ = transformed
    G = np.linalg.inv(np.eye(m.size) / gamma[0] - c)
    return a @ G, G, m @ G


SHIPPED = {"ros2": ROS2, "ros2t": ROS2T, "ros34pw2": ROS34PW2}
ORDER = {"ros2": 2, "ros2t": 2, "ros34pw2": 3, "ros3pw": 3, "ros34pw3": 4}
TABLEAUX = {**{k: published_form(v) for k, v in SHIPPED.items()}, "ros3pw": ROS3PW, "ros34pw3": ROS34PW3}


def stability(tableau, z: complex) -> complex:
    """R(z) = 1 + z b^T (I - z (alpha + Gamma))^-1 1 (z = h lambda, dimensionless)."""
    alpha, G, b = tableau
    s = b.size
    return complex(1.0 + z * b @ np.linalg.solve(np.eye(s) - z * (np.tril(alpha, -1) + G), np.ones(s)))


def transformed_step(transformed, z: complex) -> complex:
    """y1 of one step of the transformed form from y0 = 1 on y' = lambda y with J = lambda (h = 1, so z = lambda):
    (1 - gamma z) U_i = gamma [z (1 + sum_j a_ij U_j) + sum_j c_ij U_j], y1 = 1 + sum_i m_i U_i."""
    gamma, _, a, c, m, _ = transformed
    g = gamma[0]
    U = np.zeros(m.size, dtype=complex)
    for i in range(m.size):
        U[i] = g * (z * (1.0 + a[i, :i] @ U[:i]) + c[i, :i] @ U[:i]) / (1.0 - g * z)
    return complex(1.0 + m @ U)


@pytest.mark.parametrize("name", sorted(SHIPPED))
def test_the_two_routes_agree_on_the_shipped_tableaux(name):
    for z in (-0.3, 1.281, 4j, -50 + 20j, -1e4):
        assert abs(stability(TABLEAUX[name], z) - transformed_step(SHIPPED[name], z)) < 1e-12 * max(
            1.0, abs(stability(TABLEAUX[name], z)))


def test_closed_forms_of_ros2_and_ros2t():
    for name, g in (("ros2", 1.0 + 1.0 / np.sqrt(2.0)), ("ros2t", 0.25)):
        for z in (-0.7, 2j, -30 + 5j):
            closed = (1 + (1 - 2 * g) * z + (g * g - 2 * g + 0.5) * z * z) / (1 - g * z) ** 2
            assert stability(TABLEAUX[name], z) == pytest.approx(closed, rel=1e-13)
    assert stability(TABLEAUX["ros2t"], 3j) == pytest.approx(((1 + 0.75j) / (1 - 0.75j)) ** 2, rel=1e-13)


@pytest.mark.parametrize("name", sorted(TABLEAUX))
def test_each_stability_function_has_its_methods_order(name):
    """|R(z) - exp(z)| ~ C z^(p+1): halving z divides it by 2^(p+1) (within 10 %)."""
    err = [abs(stability(TABLEAUX[name], z) - np.exp(z)) for z in (0.02, 0.01)]
    assert err[0] / err[1] == pytest.approx(2.0 ** (ORDER[name] + 1), rel=0.1)


def test_the_pages_damping_figures():
    """work_precision.md: "ROS3Pw and ROS34PW3 (Rang & Angermann 2005, |R(inf)| = 0.73, 0.63) damp more (|R(4i)|
    0.79, 0.70 against 0.61)"; ROS2 and ROS34PW2 are L-stable (R(inf) = 0), ros2t keeps |R(inf)| = 1."""
    big = -1e12
    r_inf = {k: stability(v, big).real for k, v in TABLEAUX.items()}
    r_4i = {k: abs(stability(v, 4j)) for k, v in TABLEAUX.items()}
    print(f"\nRang & Angermann 2005's R(inf): ROS3Pw {r_inf['ros3pw']:.3f}, ROS34PW3 {r_inf['ros34pw3']:.3f} (|R(inf)| "
          f"{abs(r_inf['ros3pw']):.3f}, {abs(r_inf['ros34pw3']):.3f}); |R(4i)|: ROS3Pw {r_4i['ros3pw']:.3f}, "
          f"ROS34PW3 {r_4i['ros34pw3']:.3f}, ROS34PW2 {r_4i['ros34pw2']:.3f}")
    print("shipped: R(inf) " + ", ".join(f"{k} {r_inf[k]:.2g}" for k in sorted(SHIPPED))
          + "; |R(4i)| " + ", ".join(f"{k} {r_4i[k]:.3f}" for k in sorted(SHIPPED)))
    assert abs(r_inf["ros2"]) < 1e-9 and abs(r_inf["ros34pw2"]) < 1e-9
    assert r_inf["ros2t"] == pytest.approx(1.0, abs=1e-9)
    assert -r_inf["ros3pw"] == pytest.approx(np.sqrt(3.0) - 1.0, abs=1e-9)  # 0.732 = sqrt 3 - 1
    assert round(abs(r_inf["ros3pw"]), 2) == 0.73 and round(abs(r_inf["ros34pw3"]), 2) == 0.63
    assert [round(r_4i[k], 2) for k in ("ros3pw", "ros34pw3", "ros34pw2")] == [0.79, 0.70, 0.61]
    assert r_4i["ros2t"] == pytest.approx(1.0, abs=1e-12)


def test_the_whip_modes_damping_figure():
    """work_precision.md: the mill's fastest unstable mode at 7.6 s, 6.405 +- 7.82i 1/s as ``python -m
    laddermill_gym.studies.numerics.whip_spectrum laddermill --at 7.6 --top 2000 --methods ros34pw2:0.2`` prints it
    (with R/exp 0.850; 2026-11-30), gets 0.85 of |exp(z)| from ROS34PW2 at 0.2 s; 0.70 (the page until 2026-11-30)
    is its real part's alone, z = 1.281. The study's own evaluation (W_METHODS, stability_function_w) agrees."""
    from laddermill_gym.studies.numerics.whip_spectrum import W_METHODS, stability_function_w

    lam, h = 6.405 + 7.82j, 0.2  # 1/s, s
    share = abs(stability(TABLEAUX["ros34pw2"], h * lam)) / abs(np.exp(h * lam))
    real = abs(stability(TABLEAUX["ros34pw2"], h * lam.real)) / np.exp(h * lam.real)
    print(f"\nthe mill's mode at 7.6 s growing at {lam.real:.1f} 1/s, lambda = {lam.real} +- {lam.imag}i 1/s; "
          f"ROS34PW2 at {h} s: |R(z)| / |exp(z)| {share:.3f} (its real part alone, z = {h * lam.real:.3f}: {real:.3f})")
    study = float(np.abs(stability_function_w(W_METHODS["ros34pw2"], np.array([h * lam])))[0])
    assert study == pytest.approx(abs(stability(TABLEAUX["ros34pw2"], h * lam)), rel=1e-12)
    assert round(share, 2) == 0.85 and round(real, 2) == 0.70
