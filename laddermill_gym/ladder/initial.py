"""Initial states of chain scenes: a quasi-static shooting layout (``ladder/layout.py``) refined by Newton on the
simulator (``sim/statics.py``, its residual scaled by the bodies' masses)."""

from __future__ import annotations

import dataclasses

import numpy as np

from laddermill_gym.kernels.contract import B3_POS, B3_QUAT, B3_SIZE, CTRL_ELEVATOR, N3_POS, N3_SIZE
from laddermill_gym.ladder.layout import piece_nodes, rest_layout
from laddermill_gym.model.builders import build_chain, chain_state
from laddermill_gym.model.params import N_CONTROLS
from laddermill_gym.model.states import euler_from_quaternion, planar_from_3d, planar_to_3d, rotation_from_euler
from laddermill_gym.model.station import station_initial, station_initial_controls
from laddermill_gym.sim.simulator import Simulator
from laddermill_gym.sim.statics import static_equilibrium, trim_alpha


def coarser_scene(scene):
    """The scene with half as many elements per piece (rounded down; one for three), each piece keeping its
    unstretched length: its equilibrium is the first guess of the wings' (``model/builders.build_chain`` with the
    scene's wings, cable, ground points and switches). Halving (8 -> 4 -> 2 -> 1) keeps each guess close: the
    slack apex pieces of a closed chain change shape too much from one element to eight for Newton."""
    a = scene.assembly
    names = list(scene.ground_points)
    m = len(scene.layout.piece_elements[0])
    lengths = [float(a.elements.l0[list(ix)].sum()) for ix in scene.layout.piece_elements]
    asm, lay = build_chain(a.wing_types, a.wing_type_index, lengths, max(1, m // 2), scene.cable, a.fixed_points,
                           names.index(scene.start), None if scene.end is None else names.index(scene.end), a.wind,
                           dim=a.dim, sag=a.sag, cable_aero=a.cable_aero, gravity=a.gravity)
    return scene.replace(assembly=asm, layout=lay)


def _coarse_wings(scene, pos, euler, attach, controls):
    """Wing CG positions (n, 3) [m], Euler angles (n, 3) [rad], attachment points (n, 3) [m] and controls at the
    equilibrium of :func:`coarser_scene`; the layout's (the arguments) where that has none (a plain cable without
    sag correction can be too soft or slack at one element to solve from the layout, yet fine at two)."""
    a = scene.assembly
    n = a.n_wings
    coarse = coarser_scene(scene)
    try:
        x1, controls = initial_state(coarse)
    except RuntimeError:
        return pos, euler, attach, controls
    x1 = planar_to_3d(x1, n, coarse.assembly.n_nodes) if a.dim == 2 else x1
    pos = np.array([x1[B3_SIZE * k + B3_POS: B3_SIZE * k + B3_POS + 3] for k in range(n)])
    euler = np.array([euler_from_quaternion(x1[B3_SIZE * k + B3_QUAT: B3_SIZE * k + B3_QUAT + 4]) for k in range(n)])
    attach = np.array([pos[k] + rotation_from_euler(*euler[k]) @ a.wing(k).attachment for k in range(n)])
    return pos, euler, attach, controls


def slot_elevators(ini, n: int, closed: bool) -> list[float]:
    """Elevator [rad] of each of the ``n`` slots: ``ini.elevator_up`` on the ascending half (slots below
    ``half = (n + 1) // 2``; every slot of an open chain), ``ini.elevator_top`` on the first ``ini.top_slots``
    descending slots past the top and ``ini.elevator_down`` on the rest (a closed chain: ``closed``)."""
    half = (n + 1) // 2 if closed else n
    return [ini.elevator_up if k < half else ini.elevator_top if k < half + ini.top_slots else ini.elevator_down
            for k in range(n)]


def initial_state(scene) -> tuple[np.ndarray, np.ndarray]:
    """(state, controls) at the scene's initial equilibrium (see scene.InitialSpec). A moving cable starts from
    the equilibrium at rest with its first and last elements at their lengths after a transfer (the station
    block of ``model/station.station_initial`` appended, and its controls, ``station_initial_controls``: a commanded
    station's initial speed, a drum's torque at 0 or the limit nearest it)."""
    if scene.assembly.station is not None:
        st = scene.assembly.station
        x, u = initial_state(scene.replace(assembly=dataclasses.replace(scene.assembly, station=None)))
        return np.concatenate([x, station_initial(st)]), np.concatenate([u, station_initial_controls(st)])
    a = scene.assembly
    n = a.n_wings
    ini = scene.initial
    elev = slot_elevators(ini, n, scene.end is not None)
    controls = np.zeros(N_CONTROLS * n)
    controls[CTRL_ELEVATOR::N_CONTROLS] = elev
    attach, alphas, tensions = rest_layout(scene, elev)
    euler = np.array([[0.0, al, 0.0] for al in alphas])
    # wing at rest in horizontal wind: pitch angle = angle of attack; CG = attachment - R r_att
    pos = np.array([attach[k] - rotation_from_euler(*euler[k]) @ a.wing(k).attachment for k in range(n)])
    if a.n_nodes:  # several elements per piece: the wings (and trimmed elevator) of half as many
        pos, euler, attach, controls = _coarse_wings(scene, pos, euler, attach, controls)
    start = scene.ground_points[scene.start]
    end = None if scene.end is None else scene.ground_points[scene.end]
    # solve in the plane first (the in-plane equilibrium is also the 3D one when the wind does not turn)
    asm2 = dataclasses.replace(a, dim=2) if a.dim == 3 and a.wind.direction_inf == 0.0 else a
    x3 = chain_state(a, scene.layout, pos, euler, start, end)
    if a.n_nodes:  # several elements per piece: the free nodes on each piece's discrete catenary
        nodes = piece_nodes(scene, attach, tensions)
        for j in range(a.n_nodes):
            o = B3_SIZE * n + N3_SIZE * j + N3_POS
            x3[o: o + 3] = nodes[j]
    x_guess = planar_from_3d(x3, n, a.n_nodes) if asm2.dim == 2 else x3
    sim = Simulator(asm2, x_guess, scene.settings, controls)
    # light, stiff cable nodes: Newton on forces (sim/statics.py); wings only: on the accelerations, as before
    scaled = a.n_nodes > 0
    if ini.method == "trim":
        if n != 1:
            raise ValueError(f"{scene.file}: initial.method 'trim' needs exactly one wing, the scene has {n}")
        # equilibrium at the guessed elevator first (the cable taut), then the elevator for the target alpha
        x_static = static_equilibrium(sim, x_guess, controls, scaled=scaled)
        x, controls = trim_alpha(sim, x_static, ini.alpha, scaled=scaled)
    else:
        x = static_equilibrium(sim, x_guess, controls, scaled=scaled)
    if asm2.dim == 2 and a.dim == 3:
        x = planar_to_3d(x, n, a.n_nodes)
    return x, controls
