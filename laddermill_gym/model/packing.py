"""Pack an :class:`~laddermill_gym.model.params.Assembly` into the flat arrays the kernels read, and allocate
the kernels' workspace. Also finds the block elimination order (the tree the cable elements form)."""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from laddermill_gym.atmosphere.field import pack_wind_field
from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.contract import KModel, KWork
from laddermill_gym.kernels.moving_cable import MovingCable2D, MovingCable3D
from laddermill_gym.kernels.rigid.kinds import RIGID_2D, RIGID_3D, WING
from laddermill_gym.model import disk_cache
from laddermill_gym.model.params import AERO_COLUMNS, END_NODE, END_WING, Assembly
from laddermill_gym.model.reel import is_reel, reel_kind
from laddermill_gym.model.station import pack_station
from laddermill_gym.model.winch import is_winch, winch_kind


def _block(kind: int, idx: int, n_wings: int) -> int:
    if kind == END_WING:
        return idx
    if kind == END_NODE:
        return n_wings + idx
    return -1


def elimination_tree(asm: Assembly) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Order the velocity blocks children-first along the forest the elements form.

    Returns (order, parent, echild): ``parent[b]`` is the block eliminated after b that b couples to
    (-1 for a root); ``echild[e]`` is 0 if element e's r-end block is the child of its s-end block,
    1 for the reverse and -1 when the element touches a fixed point. Raises ValueError if the movable
    bodies and nodes form a closed loop (the block matrix would fill in).
    """
    nw, nn = asm.n_wings, asm.n_nodes
    nb = nw + nn
    el = asm.elements
    adj: list[set[int]] = [set() for _ in range(nb)]
    for e in range(el.count):
        a = _block(int(el.end_kind[e, 0]), int(el.end_index[e, 0]), nw)
        b = _block(int(el.end_kind[e, 1]), int(el.end_index[e, 1]), nw)
        if a >= 0 and b >= 0:
            if a == b:
                raise ValueError(f"element {e} joins block {a} to itself")
            adj[a].add(b)
            adj[b].add(a)
    parent = np.full(nb, -1, dtype=np.int64)
    seen = np.zeros(nb, dtype=bool)
    order: list[int] = []
    for root in range(nb - 1, -1, -1):
        if seen[root]:
            continue
        seen[root] = True
        bfs = [root]
        head = 0
        while head < len(bfs):
            c = bfs[head]
            head += 1
            for nbh in sorted(adj[c]):
                if nbh == parent[c]:
                    continue
                if seen[nbh]:
                    raise ValueError(
                        "cable elements form a closed loop through movable bodies "
                        f"(blocks {c} and {nbh}); close loops through a fixed ground point instead")
                seen[nbh] = True
                parent[nbh] = c
                bfs.append(nbh)
        order.extend(reversed(bfs))
    echild = np.full(el.count, -1, dtype=np.int64)
    for e in range(el.count):
        a = _block(int(el.end_kind[e, 0]), int(el.end_index[e, 0]), nw)
        b = _block(int(el.end_kind[e, 1]), int(el.end_index[e, 1]), nw)
        if a >= 0 and b >= 0:
            echild[e] = 0 if parent[a] == b else 1
    return np.asarray(order, dtype=np.int64), parent, echild


def table_spline(alpha: np.ndarray, values: np.ndarray) -> np.ndarray:
    """scipy's periodic cubic-spline coefficients of one aero table (``CubicSpline(alpha, values, bc_type=
    "periodic", axis=0).c``, shape (4, n_int, n_col)): read from the on-disk cache (``model/disk_cache.py``, folder
    ``aero_splines/``) when there, else computed and stored, so a warm start neither imports scipy.interpolate
    (about a quarter of a second) nor solves the spline. Keyed by the table's exact values, scipy's version,
    :func:`~laddermill_gym.model.disk_cache.platform_text` (numpy, the CPU) and this file's source: the same
    bits as computing it."""
    from importlib.metadata import version

    h = hashlib.sha256(f"aero_spline; format 1; scipy {version('scipy')}; {disk_cache.platform_text()}; "
                       f"source {hashlib.sha256(Path(__file__).read_bytes()).hexdigest()};".encode())
    disk_cache.feed(h, np.asarray(alpha, dtype=float))
    disk_cache.feed(h, np.asarray(values, dtype=float))
    key = h.hexdigest()
    path = disk_cache.entry_path("aero_spline", "table", key)
    data = disk_cache.read_entry(path, key)
    if data is not None and set(data) == {"c"}:
        return data["c"]
    from scipy.interpolate import CubicSpline

    c = CubicSpline(alpha, values, bc_type="periodic", axis=0).c
    disk_cache.write_entry(path, key, {"c": c})
    return c


def spline_coefficients(asm: Assembly) -> tuple[np.ndarray, float, float]:
    """Periodic cubic-spline coefficients of every wing type's table (:func:`table_spline`): array (n_types,
    n_int, 4, n_col), grid start [rad] and spacing [rad]. All types must share one uniform grid; a type without a
    table (``aero`` None) gets zeros."""
    types = asm.wing_types
    tabled = [wt for wt in types if wt.aero is not None]
    if not tabled:  # no wings, or bodies without a table (the rotorcraft): a zero table, never read
        return np.zeros((max(1, len(types)), 1, 4, len(AERO_COLUMNS))), -np.pi, 2 * np.pi
    grid = tabled[0].aero.alpha
    out = []
    for wt in types:
        if wt.aero is None:
            out.append(np.zeros((grid.size - 1, 4, len(AERO_COLUMNS))))
            continue
        a = wt.aero.alpha
        if a.shape != grid.shape or not np.allclose(a, grid, rtol=0, atol=1e-12):
            raise ValueError(f"wing type {wt.name!r}: aero table alpha grid differs from {tabled[0].name!r}")
        out.append(np.ascontiguousarray(np.transpose(table_spline(a, wt.aero.values), (1, 0, 2))))
    da = float(grid[1] - grid[0])
    return np.ascontiguousarray(np.stack(out)), float(grid[0]), da


def cable_switch(dim: int, on: bool, values: np.ndarray):
    """A cable fidelity switch as the kernels take it: in 3D always an array (``values`` when on, zeros when off; the
    kernel branches on the values at run time, so every switch setting runs one compiled kernel); in-plane
    ``values`` or None (the in-plane kernel is compiled per setting, the branch removed)."""
    if dim == 3:
        return values if on else np.zeros_like(values)
    return values if on else None


def end_mass_shapes(asm: Assembly) -> np.ndarray:
    """T^T T of every element end, shape (n_e, 2, 6, 6) (top-left nb x nb used). For a wing end it is
    [[I, -a~], [a~, -a~ a~]] in body axes (independent of the rotation); for a node end the identity;
    zero for a fixed end. The in-plane mode keeps the (u, w, q) rows and columns."""
    el = asm.elements
    out = np.zeros((el.count, 2, 6, 6))
    for e in range(el.count):
        for end in range(2):
            kind = int(el.end_kind[e, end])
            if kind == END_WING:
                ax, ay, az = el.attach[e, end]
                at = np.array([[0.0, -az, ay], [az, 0.0, -ax], [-ay, ax, 0.0]])
                full = np.block([[np.eye(3), -at], [at, -at @ at]])
                if asm.dim == 2:
                    keep = [0, 2, 4]
                    full = full[np.ix_(keep, keep)]
                n = full.shape[0]
                out[e, end, :n, :n] = full
            elif kind == END_NODE:
                n = 3 if asm.dim == 3 else 2
                out[e, end, :n, :n] = np.eye(n)
    return out


def wind_fields(w) -> np.ndarray:
    """The packed wind parameters ``wf`` (slots ``WF_*`` of kernels/contract.py) of a WindParams."""
    wf = np.zeros(C.WF_SIZE)
    wf[C.WF_V0], wf[C.WF_H0], wf[C.WF_V1], wf[C.WF_EXPONENT] = w.v0, w.h0, w.v1, w.exponent
    wf[C.WF_DIR_INF], wf[C.WF_DIR_HEIGHT], wf[C.WF_RHO0] = w.direction_inf, w.direction_height, w.rho0
    wf[C.WF_DENSITY_MODEL] = C.DENSITY_BAROMETRIC if w.density_model == "barometric" else C.DENSITY_ISA
    wf[C.WF_SCALE_HEIGHT] = w.scale_height
    return wf


def wing_type_table(asm: Assembly) -> np.ndarray:
    """The wing-type table ``tf`` (n_types, TF_SIZE) (slots ``TF_*``)."""
    tf = np.zeros((max(1, len(asm.wing_types)), C.TF_SIZE))
    for i, wt in enumerate(asm.wing_types):
        tf[i, C.TF_MASS] = wt.mass
        tf[i, C.TF_JXX:C.TF_JXZ + 1] = wt.inertia
        tf[i, C.TF_AREA], tf[i, C.TF_SPAN], tf[i, C.TF_CHORD] = wt.area, wt.span, wt.chord
        tf[i, C.TF_RREF:C.TF_RREF + 3] = wt.r_ref
        tf[i, C.TF_ATTACH:C.TF_ATTACH + 3] = wt.attachment
    return tf


def model_kind(asm: Assembly):
    """The kind marker of a built assembly: rigid 3D or in-plane, with a moving cable when it has a station."""
    if asm.station is None:
        return RIGID_3D if asm.dim == 3 else RIGID_2D
    if is_reel(asm.station):  # a winch with a reeling multi-element tether (model/reel.py, kernels/reel.py)
        return reel_kind(asm)
    if is_winch(asm.station):  # a pumping kite's winch (model/winch.py, kernels/winch.py)
        return winch_kind(asm)
    sp = pack_station(asm.station, asm.elements.count, asm.body_state_size, C.N_CONTROLS * asm.n_wings)
    return MovingCable3D(sp) if asm.dim == 3 else MovingCable2D(sp)


def pack_model(asm: Assembly, vehicle=WING) -> KModel:
    """Flat float64 / int64 arrays for the kernels (layout: kernels/contract.py).

    ``vehicle`` is the body-loads plug-in the kernels call for every rigid body (``WING``: the wing types'
    aerodynamics; the rotorcraft passes its own). The model kind follows ``asm.dim``; the fidelity switches
    ``asm.sag`` and ``asm.cable_aero`` become the ``sag`` and ``caero`` fields (:func:`cable_switch`); a station
    makes it a moving-cable kind (``kernels/moving_cable.py``)."""
    w = asm.wind
    ac, a0, da = spline_coefficients(asm)
    glob = np.zeros(C.GL_SIZE)
    glob[C.GL_GRAVITY], glob[C.GL_CN0], glob[C.GL_CT0] = asm.gravity, asm.cable_cn0, asm.cable_ct0
    glob[C.GL_ALPHA0], glob[C.GL_DALPHA] = a0, da
    el = asm.elements
    ef = np.zeros((el.count, C.EF_SIZE))
    ef[:, C.EF_L0], ef[:, C.EF_MU], ef[:, C.EF_EA] = el.l0, el.mu, el.EA
    ef[:, C.EF_DA], ef[:, C.EF_DIAMETER] = el.DA, el.diameter
    order, parent, echild = elimination_tree(asm)
    wing_dof, node_dof = (C.DOF_B3, C.DOF_N3) if asm.dim == 3 else (C.DOF_B2, C.DOF_N2)
    bsz = np.array([wing_dof] * asm.n_wings + [node_dof] * asm.n_nodes, dtype=np.int64)
    fixed = asm.fixed_points if asm.fixed_points.size else np.zeros((1, 3))
    tmod, ms, md, gp, gv = pack_wind_field(w.field)
    if asm.dim == 2 and vehicle is not WING:
        raise ValueError("the in-plane (dim = 2) model supports winged bodies only")
    return KModel(
        kind=model_kind(asm), wf=wind_fields(w), tmod=tmod, ms=ms, md=md, gp=gp, gv=gv,
        glob=glob, wtype=np.ascontiguousarray(asm.wing_type_index, dtype=np.int64), tf=wing_type_table(asm), ac=ac,
        node_mass=np.ascontiguousarray(asm.node_mass, dtype=np.float64),
        fixed=np.ascontiguousarray(fixed, dtype=np.float64),
        ek=np.ascontiguousarray(el.end_kind, dtype=np.int64).reshape(-1, 2),
        ei=np.ascontiguousarray(el.end_index, dtype=np.int64).reshape(-1, 2),
        ea=np.ascontiguousarray(el.attach, dtype=np.float64).reshape(-1, 2, 3),
        ef=ef, ekd=end_mass_shapes(asm), echild=echild, order=order, parent=parent, bsz=bsz,
        sag=cable_switch(asm.dim, asm.sag, np.ones(1)),
        caero=cable_switch(asm.dim, asm.cable_aero, np.array([asm.cable_cn0, asm.cable_ct0])),
        vehicle=vehicle,
    )


def make_workspace(asm: Assembly, n_vout: int = 1, n_vscratch: int = 1) -> KWork:
    """Every array the kernels write into, allocated once per simulator; ``n_vout`` and ``n_vscratch`` are the
    sizes of the vehicle's output and scratch arrays (1 for wings, which use neither)."""
    nb = max(1, asm.n_wings + asm.n_nodes)
    n = asm.state_size
    z = np.zeros
    return KWork(
        D=z((nb, 6, 6)), U=z((nb, 6, 6)), Y=z((nb, 6, 6)), piv=z((nb, 6), dtype=np.int64),
        bv=z((nb, 6)), Rw=z((max(1, asm.n_wings), 3, 3)), tension=z(max(1, asm.elements.count)),
        Tr=z((3, 6)), Ts=z((3, 6)), er=z(9), es=z(9), coef=z(len(AERO_COLUMNS)), aout=z(C.AO_SIZE),
        vout=z(max(1, n_vout)), vscratch=z(max(1, n_vscratch)),
        k1=z(n), k2=z(n), k3=z(n), k4=z(n), k5=z(n), k6=z(n), k7=z(n), xt=z(n), xp=z(n),
        Dm=z((nb, 6, 6)), Um=z((nb, 6, 6)), Ds=z((nb, 6, 6)), Us=z((nb, 6, 6)), Rn=z((max(1, asm.n_wings), 3, 3)),
        ke=z((max(1, asm.elements.count), C.KE_SIZE)), kb=z((max(1, asm.n_wings), 6, 3)),
        seg_tmod=z(C.TM_SIZE), seg_ms=z(4), seg_md=z(4), Yw=z((nb, 6, 6)), pivw=z((nb, 6), dtype=np.int64),
        wjac=z(1),
    )
