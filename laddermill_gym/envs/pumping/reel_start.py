"""The start of a pumping kite on a reeling tether (``kernels/reel.py``): the wing as in the single-element trim, the
nodes in the air on the elastic catenary of the tether between the drum and the wing's attachment, the nodes on
the drum at the ground point, all at rest.

The elastic catenary (Irvine 1981, "Cable Structures", eqs. 2.24-2.25; a tether of weight w per unstretched length
and axial stiffness EA hanging in a vertical plane): with H the horizontal tension and V the vertical one at the
lower end, the point at unstretched arc length p from it lies at

    x(p) = H p / EA + (H / w) (asinh((V + w p) / H) - asinh(V / H))
    z(p) = w p^2 / (2 EA) + V p / EA + (H / w) (sqrt(1 + ((V + w p) / H)^2) - sqrt(1 + (V / H)^2))

(x horizontal, z up). H and V follow from the two ends; the wing's tension sets them, since the single element's
trim put the wing where its tether's tension balances it.
"""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.kernels import contract as C

__all__ = ["catenary_point", "solve_catenary", "reel_state"]


def catenary_point(p, h, v, w, ea):
    """(x, z) [m] of the elastic catenary at unstretched arc length ``p`` [m] from its lower end (module docstring);
    h, v [N] the horizontal and vertical tension at the lower end, w [N/m], ea [N]."""
    p = np.asarray(p, float)
    x = h * p / ea + h / w * (np.arcsinh((v + w * p) / h) - np.arcsinh(v / h))
    z = w * p * p / (2.0 * ea) + v * p / ea + h / w * (np.sqrt(1.0 + ((v + w * p) / h) ** 2)
                                                      - np.sqrt(1.0 + (v / h) ** 2))
    return x, z


def solve_catenary(span: float, rise: float, length: float, w: float, ea: float) -> tuple[float, float]:
    """(H, V) [N] of the elastic catenary of unstretched ``length`` [m] whose upper end lies ``span`` [m] across
    and ``rise`` [m] above its lower end (w [N/m], ea [N]). Raises ValueError where no catenary fits (the ends
    farther apart than the tether stretched by its weight allows)."""
    from scipy.optimize import fsolve
    if not (span > 0 and length > 0 and w > 0 and ea > 0):
        raise ValueError(f"solve_catenary: span {span} m, length {length} m, w {w} N/m and EA {ea} N must be > 0")

    def miss(q):
        h, v = math.exp(q[0]), q[1]
        x, z = catenary_point(length, h, v, w, ea)
        return [x / span - 1.0, (z - rise) / length]

    chord = math.hypot(span, rise)
    h0 = w * length * span / max(chord, 1e-9) * 2.0
    # a sagging tether's guess first (the start's usual case, whose result it keeps), then tensions of 1 to 100 times
    # the tether's weight along the chord (a short steep tether pulled by its wing: 4 times it on a 100 m start)
    guesses = [[math.log(h0), w * length * rise / chord - 0.5 * w * length]]
    guesses += [[math.log(k * w * length * max(span, 1e-9) / chord), k * w * length * rise / chord - 0.5 * w * length]
                for k in (1.0, 3.0, 10.0, 30.0, 100.0)]
    for guess in guesses:
        q, _, ok, msg = fsolve(miss, guess, full_output=True, xtol=1e-13)
        if ok == 1 and max(abs(r) for r in miss(q)) <= 1e-9:
            return math.exp(q[0]), float(q[1])
    raise ValueError(f"solve_catenary: no catenary of {length} m spans {span} m across and {rise} m up ({msg})")


def reel_state(asm, wing_state: np.ndarray, station_block: np.ndarray) -> np.ndarray:
    """The initial state of the reeling assembly ``asm`` (``model.reel.with_reel``): the wing's 13 entries
    ``wing_state`` (its single-element trim), the nodes in the air on the elastic catenary from the ground point to
    the wing's attachment at the unstretched distances l_p, l_p + l_n, ... from the drum, the nodes on the drum at
    the ground point, every node at rest, and the winch block ``station_block`` (``SX_*``)."""
    from laddermill_gym.model.states import rotations_from_quaternions

    st, el = asm.station, asm.elements
    n, air = asm.n_nodes, st.nodes_in_air
    ground = np.asarray(asm.fixed_points[el.end_index[0, 0]], float)
    R = rotations_from_quaternions(np.asarray(wing_state[C.B3_QUAT:C.B3_QUAT + 4], float).reshape(1, 4))[0]
    top = np.asarray(wing_state[C.B3_POS:C.B3_POS + 3], float) + R @ np.asarray(el.attach[-1, 1], float)
    d = top - ground
    horiz = math.hypot(d[0], d[1])
    ex = np.array([d[0], d[1], 0.0]) / horiz
    length = st.piece_length + (air - 1) * st.reel.element_length + el.l0[-1]
    w = float(el.mu[0]) * asm.gravity
    h, v = solve_catenary(horiz, -d[2], length, w, float(el.EA[0]))
    p = st.piece_length + st.reel.element_length * np.arange(air)
    xs, zs = catenary_point(p, h, v, w, float(el.EA[0]))
    x = np.zeros(asm.body_state_size + C.SX_SIZE)
    x[:C.B3_SIZE] = wing_state[:C.B3_SIZE]
    base = C.B3_SIZE * asm.n_wings
    for j in range(n):
        o = base + C.N3_SIZE * j + C.N3_POS
        i = j - (n - air)
        x[o:o + 3] = ground if i < 0 else ground + xs[i] * ex - np.array([0.0, 0.0, zs[i]])
    x[asm.body_state_size:] = station_block
    return x
