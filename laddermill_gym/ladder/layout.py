"""The first guess of a chain's initial state: a quasi-static shooting layout of the wings (straight pieces with a
parabolic sag shortening) and, with several elements per piece, each piece's free nodes on its discrete elastic
catenary between the wings' attachment points (``piece_nodes``). ``ladder/initial.py`` refines it by Newton."""

from __future__ import annotations

import math

import numpy as np

from laddermill_gym.kernels.contract import WF_DIR_HEIGHT, WF_DIR_INF
from laddermill_gym.model.packing import wind_fields
from laddermill_gym.model.params import AERO_INDEX
from laddermill_gym.sim.statics import pitch_trim_alpha, table_spline


def _wind_fields(a):
    """The packed wind parameters of the scene's wind without its direction turn (direction_inf 0,
    direction_height 1 m): the layout is solved in the vertical plane of the wind at the ground."""
    wf = wind_fields(a.wind)
    wf[WF_DIR_INF], wf[WF_DIR_HEIGHT] = 0.0, 1.0
    return wf


def _rest_state(scene, positions, elevators, ends):
    """Pitch-trim angles of attack (n,) [rad] and the load (n, 2) (x, z) [N] on wings at rest in the steady
    wind at the given positions (n, 3) [m] and elevator angles [rad]: wing aerodynamics and weight, plus
    half the weight and the cross-flow drag C_N0 sin^3 + C_T0 (eq. 23) of each neighbouring piece (pieces
    run between consecutive points of ``ends`` (n + 2, 3), which adds the chain's end points)."""
    from laddermill_gym.kernels.wind import density, wind_at

    a = scene.assembly
    wt = a.wing(0)
    sp = table_spline(wt.aero)
    wf = _wind_fields(a)
    m_cable = float(a.elements.mu[0]) * scene.piece_length  # half of each neighbouring piece [kg]
    dia = float(a.elements.diameter[0])
    drag = np.zeros(len(positions))
    for j in range(len(ends) - 1):  # piece j between ends[j] and ends[j + 1]
        d = ends[j + 1] - ends[j]
        mid = 0.5 * (ends[j + 1] + ends[j])
        sin_a = abs(d[2]) / max(float(np.linalg.norm(d)), 1e-9)
        wxc, _, _ = wind_at(mid[2], wf, 1.0, 0.0)
        f = 0.5 * density(-mid[2], wf) * wxc * wxc * dia * scene.piece_length * (1.1 * sin_a ** 3 + 0.02)
        for k in (j - 1, j):
            if 0 <= k < len(positions):
                drag[k] += 0.5 * f
    alphas, forces = [], []
    for p, el, dc in zip(positions, elevators, drag, strict=True):
        wx, _, _ = wind_at(p[2], wf, 1.0, 0.0)
        qd = 0.5 * density(-p[2], wf) * wx * wx
        al = pitch_trim_alpha(wt, el, qd, a.gravity)
        c = sp(al)
        cl = c[AERO_INDEX["CL"]] + c[AERO_INDEX["CLde"]] * el
        alphas.append(al)
        forces.append([-qd * wt.area * c[AERO_INDEX["CD"]] - dc, -qd * wt.area * cl + (wt.mass + m_cable) * a.gravity])
    return np.array(alphas), np.array(forces)


def _march(A, L, EA, T0, forces, w=0.0):
    """Attachment points of a chain of pieces (unstretched lengths L (n + 1,) [m], stiffness EA [N], weight w [N/m])
    from A: piece k carries the tension vector T_k (x, z) [N] and T_{k+1} = T_k - F_k at wing k. Its chord
    is L (1 + T/EA) less the parabolic sag shortening w_perp^2 L^3 / (24 T^2) (Irvine 1981), floored at L/2.
    T0 may be a batch (..., 2). Returns the wing attachment points (..., n, 3) and the end of the last
    piece (..., 3)."""
    T = np.array(T0, dtype=float)
    p = np.broadcast_to(np.asarray(A, float), T.shape[:-1] + (3,)).copy()
    pts = []
    L = np.broadcast_to(np.asarray(L, float), (len(forces) + 1,))
    for k in range(len(forces) + 1):
        Tn = np.maximum(np.hypot(T[..., 0], T[..., 1]), 1e-9)[..., None]
        e = T / Tn
        chord = L[k] * (1.0 + Tn / EA) - (w * e[..., :1]) ** 2 * L[k] ** 3 / (24.0 * Tn * Tn)
        chord = np.maximum(chord, 0.5 * L[k])
        p = p + chord * np.stack([e[..., 0], np.zeros_like(Tn[..., 0]), e[..., 1]], -1)
        if k < len(forces):
            pts.append(p)
            T = T - forces[k]
    return np.stack(pts, -2), p


def rest_layout(scene, elevators):
    """Cable attachment points (n, 3) [m] and pitch angles (n,) [rad] of the wings of a chain at rest:
    straight massless pieces stretched by T / EA, each wing in force and moment balance at rest at its
    local dynamic pressure. A free upper end: each piece points along the sum of the forces above it;
    two ground points: shooting on the tension vector at the start. Forces and positions are iterated to a
    fixed point (the forces depend on height through the wind profile). Also returns the tension
    vector (x, z) [N] at the lower end of each piece, (n_pieces, 2)."""
    from scipy.optimize import fsolve
    a = scene.assembly
    n = a.n_wings
    A = np.asarray(scene.ground_points[scene.start], float)
    L = scene.piece_length
    # unstretched length of each piece (the moving cable's first and last pieces differ from L)
    Ls = np.array([a.elements.l0[list(ix)].sum() for ix in scene.layout.piece_elements])
    EA = float(a.elements.EA[0])
    el = np.asarray(elevators, float)
    # first guess: wings on a straight line up at the guessed elevation (both legs together for a loop)
    ang = scene.initial.elevation
    up = np.array([-math.cos(ang), 0.0, -math.sin(ang)])
    m = n if scene.end is None else (n + 1) // 2
    pts = np.array([A + L * min(k + 1, n + 1 - k if scene.end is not None else k + 1) * up for k in range(n)])
    v_top = None
    w = float(a.elements.mu[0]) * a.gravity
    tail = [A] if scene.end is None else [A, np.asarray(scene.ground_points[scene.end], float)]
    for _ in range(30):
        ends = np.vstack([A, pts] + ([] if scene.end is None else [tail[1]]))
        alphas, F = _rest_state(scene, pts, el, ends)
        if scene.end is None:  # n pieces, one below each wing: the march's piece above the last wing is empty
            T0 = F.sum(axis=0)
            new, _ = _march(A, np.append(Ls, 0.0), EA, T0, F, w)
        else:
            B = np.asarray(scene.ground_points[scene.end], float)
            # unknowns: the tension of the piece after the apex (wing m - 1) in polar form (log magnitude
            # relative to the rising leg's load, angle); the miss folds over this plane, so the first start
            # is the best point of a coarse grid (all evaluated at once)
            below = F[:m].sum(axis=0)
            Ftot = float(np.hypot(*below))

            def start_tension(v):
                v = np.asarray(v, float)
                return below + np.exp(v[..., :1]) * Ftot * np.stack([np.cos(v[..., 1]), np.sin(v[..., 1])], -1)

            def miss(v):
                return (_march(A, Ls, EA, start_tension(v), F, w)[1] - B)[..., [0, 2]] / L

            if v_top is None:
                g = np.stack(np.meshgrid(np.linspace(-9.0, 0.5, 39), np.linspace(-math.pi, math.pi, 73),
                                         indexing="ij"), -1).reshape(-1, 2)
                starts = [g[np.argmin(np.linalg.norm(miss(g), axis=-1))]]
            else:
                starts = [v_top]
            best = None
            for v0 in starts:
                v, info, ok, msg = fsolve(miss, v0, xtol=1e-13, full_output=True)
                if best is None or np.linalg.norm(info["fvec"]) < best[1]:
                    best = (v, float(np.linalg.norm(info["fvec"])), msg)
            v_top, r, msg = best
            if r > 1e-8:
                raise RuntimeError(f"{scene.file}: chain layout shooting failed (miss {r * L:.3g} m): {msg}")
            T0 = start_tension(v_top)
            new, _ = _march(A, Ls, EA, T0, F, w)
        if np.max(np.abs(new - pts)) < 1e-6 * L:
            pts = new
            break
        pts = new
    T = T0 - np.concatenate([np.zeros((1, 2)), np.cumsum(F, axis=0)])  # the loads the last march used
    alphas, _ = _rest_state(scene, pts, el, ends)
    return pts, alphas, T if scene.end is not None else T[:-1]


def layout(scene, elevators):
    """Cable attachment points (n, 3) [m] and pitch angles (n,) [rad] of the wings of a chain at rest (see
    :func:`rest_layout`)."""
    pts, alphas, _ = rest_layout(scene, elevators)
    return pts, alphas


def _node_loads(P, l0, mu, g, air):
    """Loads (x, z) [N] on the free nodes (m - 1, 2) of a piece through the points P (m + 1, 3) [m] (its ends
    and free nodes) as the kernels lump them: half the weight mu l0 g of each neighbouring element, and half of
    each neighbouring element's aerodynamic load (``air``: loads per length (m, 2) [N/m] at the elements' midpoints
    (m, 3) with their unit tangents (m, 3); None without cable aerodynamics)."""
    d = np.diff(P, axis=0)
    ln = np.linalg.norm(d, axis=1)
    half = 0.5 * np.stack([np.zeros_like(l0), mu * l0 * g], -1)
    if air is not None:
        half = half + 0.5 * air(0.5 * (P[:-1] + P[1:]), d / ln[:, None]) * ln[:, None]
    return half[:-1] + half[1:]


def piece_shape(A, B, l0, EA: float, mu: float, g: float, T0, air=None, iterations: int = 4):
    """The free nodes (m - 1, 3) [m] of one cable piece of m elements (unstretched lengths l0 (m,) [m], stiffness
    EA [N], mass per length mu [kg/m]) at rest between the attachment points A and B (3,) [m]: a discrete elastic
    catenary in the vertical x-z plane. From A each element runs along its tension vector T_k (x, z) [N] with the
    chord of :func:`_march` (stretch T / EA less the parabolic sag shortening of its own weight), and at node k
    T_{k+1} = T_k - F_k with the node loads of :func:`_node_loads`; the start tension (2 unknowns, first guess T0)
    is shot (MINPACK hybrd) to end at B, and the loads (cable aerodynamics depend on the shape) are iterated
    ``iterations`` times. y runs linearly from A to B. None if the shooting misses B by more than 1e-9 of the
    piece (the caller keeps its own guess)."""
    from scipy.optimize import fsolve
    A, B = np.asarray(A, float), np.asarray(B, float)
    l0 = np.asarray(l0, float)
    m = l0.size
    f = np.arange(m + 1)[:, None] / m
    P = A + f * (B - A)  # first shape: the straight chord
    T = np.asarray(T0, float)
    span = float(l0.sum())
    for _ in range(iterations):
        F = _node_loads(P, l0, mu, g, air)

        def miss(t, F=F):
            return (_march(A, l0, EA, t, F, mu * g)[1] - B)[[0, 2]] / span

        t, info, _, _ = fsolve(miss, T, xtol=1e-13, full_output=True)
        if not np.all(np.isfinite(t)) or np.linalg.norm(info["fvec"]) > 1e-9:
            return None
        T = t
        pts, _ = _march(A, l0, EA, T, F, mu * g)
        P = np.vstack([A, pts, B])
    P[:, 1] = A[1] + f[:, 0] * (B[1] - A[1])
    return P[1:-1]


def cable_air(scene):
    """Aerodynamic load per length (k, 2) (x, z) [N/m] on cable at rest at midpoints (k, 3) [m] with unit tangents
    (k, 3), the kernels' eq. (24) (:func:`laddermill_gym.kernels.cable.aero_load`) in the scene's steady wind;
    None where the scene has no cable aerodynamics."""
    from laddermill_gym.kernels.cable import aero_load
    from laddermill_gym.kernels.wind import density, wind_at

    a = scene.assembly
    if not a.cable_aero:
        return None
    wf = _wind_fields(a)
    dia = float(a.elements.diameter[0])

    def air(mid, tan):
        out = np.zeros((len(mid), 2))
        for i, (p, e) in enumerate(zip(mid, tan, strict=True)):
            wx, wy, wz = wind_at(p[2], wf, 1.0, 0.0)
            fx, _, fz = aero_load(wx, wy, wz, e[0], e[1], e[2], density(-p[2], wf), dia, a.cable_cn0, a.cable_ct0)
            out[i] = fx, fz
        return out

    return air


def piece_nodes(scene, attach, tensions):
    """Positions (n_nodes, 3) [m] of every free cable node of a chain at rest: :func:`piece_shape` on each piece
    between its ends (the ground points and the wings' attachment points ``attach`` (n, 3) [m]) from the layout's
    tension ``tensions`` (n_pieces, 2) [N] at the piece's lower end; the straight chord where the shooting fails."""
    a = scene.assembly
    lay = scene.layout
    ends = [np.asarray(scene.ground_points[scene.start], float), *np.asarray(attach, float)]
    if scene.end is not None:
        ends.append(np.asarray(scene.ground_points[scene.end], float))
    air = cable_air(scene)
    out = np.zeros((a.n_nodes, 3))
    for i, (nodes, els) in enumerate(zip(lay.piece_nodes, lay.piece_elements, strict=True)):
        if not nodes:
            continue
        l0 = a.elements.l0[list(els)]
        P = piece_shape(ends[i], ends[i + 1], l0, float(a.elements.EA[els[0]]), float(a.elements.mu[els[0]]),
                        a.gravity, tensions[i], air)
        if P is None:
            f = np.arange(1, len(nodes) + 1)[:, None] / (len(nodes) + 1)
            P = ends[i] + f * (ends[i + 1] - ends[i])
        out[list(nodes)] = P
    return out
