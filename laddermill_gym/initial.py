"""Initial states of chain scenes: a quasi-static shooting layout refined by Newton on the simulator."""

from __future__ import annotations

import math

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import fsolve

from .builders import chain_state
from .params import AERO_INDEX, N_CONTROLS
from .simulator import Simulator
from .states import planar_from_3d, planar_to_3d
from .statics import pitch_trim_alpha, static_equilibrium, trim_alpha


def _rest_forces(scene, positions, alphas):
    """Aerodynamic force + weight (x, z) [N] on wings at rest in the steady wind, flying at alphas [rad]."""
    from .kernels.wind import density, wind_at

    a = scene.assembly
    wt = a.wing(0)
    sp = CubicSpline(wt.aero.alpha, wt.aero.values, bc_type="periodic", axis=0)
    wf = np.array([a.wind.v0, a.wind.h0, a.wind.v1, a.wind.exponent, 0.0, 1.0, a.wind.rho0,
                   0.0 if a.wind.density_model == "barometric" else 1.0, a.wind.scale_height, 0.0])
    out = []
    for p, al in zip(positions, alphas):
        wx, _, _ = wind_at(p[2], wf, 1.0, 0.0)
        q = 0.5 * density(-p[2], wf) * wx * wx * wt.area
        c = sp(al)
        out.append(np.array([-q * c[AERO_INDEX["CD"]], q * -c[AERO_INDEX["CL"]] + wt.mass * a.gravity]))
    return out


def _layout(scene, elevators):
    """Wing CG positions (n, 3) and pitch angles (n,) of a chain at rest: rigid massless pieces, each wing in
    force balance at its pitch-trim angle of attack (shooting on the tension at the start point)."""
    a = scene.assembly
    n = a.n_wings
    wt = a.wing(0)
    alphas = [pitch_trim_alpha(wt, el) for el in elevators]
    A = scene.ground_points[scene.start]
    L = scene.piece_length
    if scene.end is None:
        pos = []
        p = A.copy()
        for k in range(n):
            # the piece below wing k carries the forces of all wings above it
            ang = scene.initial.elevation
            for _ in range(30):
                trial = [p + L * np.array([-math.cos(ang), 0.0, -math.sin(ang)]) for _ in range(n - k)]
                F = sum(_rest_forces(scene, trial, alphas[k:]))
                ang = math.atan2(-F[1], -F[0])
            p = p + L * np.array([-math.cos(ang), 0.0, -math.sin(ang)])
            pos.append(p)
        return np.array(pos), np.array(alphas)
    B = scene.ground_points[scene.end]

    def march(T0):
        T = np.array(T0, dtype=float)
        p = A.copy()
        pos = []
        for k in range(n + 1):
            e = T / max(np.linalg.norm(T), 1e-9)
            p = p + L * np.array([e[0], 0.0, e[1]])
            if k < n:
                pos.append(p)
                F = _rest_forces(scene, [p], [alphas[k]])[0]
                T = T + F
        return np.array(pos), p

    guess_lift = sum(_rest_forces(scene, [A + np.array([-L * k * 0.5, 0, -L * k * 0.8]) for k in range(n)], alphas))
    T0 = np.array([guess_lift[0] * 0.5, guess_lift[1] * 0.5])

    def resid(T):
        return (march(T)[1] - B)[[0, 2]] / L

    T = fsolve(resid, T0, xtol=1e-12)
    return march(T)[0], np.array(alphas)


def initial_state(scene) -> tuple[np.ndarray, np.ndarray]:
    """(state, controls) at the scene's initial equilibrium (see scene.InitialSpec)."""
    a = scene.assembly
    n = a.n_wings
    ini = scene.initial
    half = (n + 1) // 2 if scene.end is not None else n
    elev = [ini.elevator_up if k < half else ini.elevator_down for k in range(n)]
    controls = np.zeros(N_CONTROLS * n)
    controls[0::N_CONTROLS] = elev
    pos, alphas = _layout(scene, elev)
    euler = np.array([[0.0, al, 0.0] for al in alphas])
    start = scene.ground_points[scene.start]
    end = None if scene.end is None else scene.ground_points[scene.end]
    # solve in the plane first (the in-plane equilibrium is also the 3D one when the wind does not turn)
    from .scene import load_scene  # noqa: F401  (documented coupling)
    import dataclasses

    asm2 = dataclasses.replace(a, dim=2) if a.dim == 3 and a.wind.direction_inf == 0.0 else a
    x3 = chain_state(a, scene.layout, pos, euler, start, end)
    x_guess = planar_from_3d(x3, n, a.n_nodes) if asm2.dim == 2 else x3
    sim = Simulator(asm2, x_guess, scene.settings, controls)
    if ini.method == "trim":
        if n != 1:
            raise ValueError(f"{scene.file}: initial.method 'trim' needs exactly one wing, the scene has {n}")
        x, controls = trim_alpha(sim, x_guess, ini.alpha)
    else:
        x = static_equilibrium(sim, x_guess, controls)
    if asm2.dim == 2 and a.dim == 3:
        x = planar_to_3d(x, n, a.n_nodes)
    return x, controls
