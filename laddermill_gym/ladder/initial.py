"""Initial states of chain scenes: a quasi-static shooting layout refined by Newton on the simulator."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import fsolve

from laddermill_gym.kernels.contract import CTRL_ELEVATOR, WF_DIR_HEIGHT, WF_DIR_INF
from laddermill_gym.model.builders import chain_state
from laddermill_gym.model.packing import wind_fields
from laddermill_gym.model.params import AERO_INDEX, N_CONTROLS
from laddermill_gym.model.states import planar_from_3d, planar_to_3d, rotation_from_euler
from laddermill_gym.model.station import station_initial
from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.sim.statics import pitch_trim_alpha, static_equilibrium, table_spline, trim_alpha


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
    from laddermill_gym.atmosphere.wind_kernels import density, wind_at

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


def layout(scene, elevators):
    """Cable attachment points (n, 3) [m] and pitch angles (n,) [rad] of the wings of a chain at rest:
    straight massless pieces stretched by T / EA, each wing in force and moment balance at rest at its
    local dynamic pressure. A free upper end: each piece points along the sum of the forces above it;
    two ground points: shooting on the tension vector at the start. Forces and positions are iterated to a
    fixed point (the forces depend on height through the wind profile)."""
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
        if scene.end is None:
            T0 = F.sum(axis=0)
            new, _ = _march(A, Ls, EA, T0, F, w)
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
    alphas, _ = _rest_state(scene, pts, el, ends)
    return pts, alphas


def initial_state(scene) -> tuple[np.ndarray, np.ndarray]:
    """(state, controls) at the scene's initial equilibrium (see scene.InitialSpec). A moving cable starts from
    the equilibrium at rest with its first and last elements at their lengths after a transfer (the station
    block of ``model/station.station_initial`` appended; its generator torque control, if any, 0)."""
    if scene.assembly.station is not None:
        st = scene.assembly.station
        x, u = initial_state(scene.replace(assembly=dataclasses.replace(scene.assembly, station=None)))
        return np.concatenate([x, station_initial(st)]), np.concatenate([u, np.zeros(st.n_controls)])
    a = scene.assembly
    n = a.n_wings
    ini = scene.initial
    half = (n + 1) // 2 if scene.end is not None else n
    elev = [ini.elevator_up if k < half else ini.elevator_down for k in range(n)]
    controls = np.zeros(N_CONTROLS * n)
    controls[CTRL_ELEVATOR::N_CONTROLS] = elev
    attach, alphas = layout(scene, elev)
    euler = np.array([[0.0, al, 0.0] for al in alphas])
    # wing at rest in horizontal wind: pitch angle = angle of attack; CG = attachment - R r_att
    pos = np.array([attach[k] - rotation_from_euler(*euler[k]) @ a.wing(k).attachment for k in range(n)])
    start = scene.ground_points[scene.start]
    end = None if scene.end is None else scene.ground_points[scene.end]
    # solve in the plane first (the in-plane equilibrium is also the 3D one when the wind does not turn)
    asm2 = dataclasses.replace(a, dim=2) if a.dim == 3 and a.wind.direction_inf == 0.0 else a
    x3 = chain_state(a, scene.layout, pos, euler, start, end)
    x_guess = planar_from_3d(x3, n, a.n_nodes) if asm2.dim == 2 else x3
    sim = Simulator(asm2, x_guess, scene.settings, controls)
    if ini.method == "trim":
        if n != 1:
            raise ValueError(f"{scene.file}: initial.method 'trim' needs exactly one wing, the scene has {n}")
        # equilibrium at the guessed elevator first (the cable taut), then the elevator for the target alpha
        x_static = static_equilibrium(sim, x_guess, controls)
        x, controls = trim_alpha(sim, x_static, ini.alpha)
    else:
        x = static_equilibrium(sim, x_guess, controls)
    if asm2.dim == 2 and a.dim == 3:
        x = planar_to_3d(x, n, a.n_nodes)
    return x, controls
