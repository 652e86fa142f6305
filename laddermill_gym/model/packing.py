"""Pack an :class:`~laddermill_gym.model.params.Assembly` into the flat arrays the kernels read, and allocate
the kernels' workspace. Also finds the block elimination order (the tree the cable elements form)."""

from __future__ import annotations

from collections import namedtuple

import numpy as np
from scipy.interpolate import CubicSpline

from laddermill_gym.model.params import AERO_COLUMNS, END_NODE, END_WING, Assembly

KModel = namedtuple(
    "KModel",
    ["wf", "tmod", "ms", "md", "glob", "wtype", "tf", "ac", "node_mass", "fixed",
     "ek", "ei", "ea", "ef", "ekd", "echild", "order", "parent", "bsz"],
)
KWork = namedtuple(
    "KWork",
    ["D", "U", "Y", "piv", "bv", "Rw", "tension", "Tr", "Ts", "er", "es", "coef", "aout",
     "k1", "k2", "k3", "k4", "k5", "k6", "k7", "xt", "xp"],
)


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


def spline_coefficients(asm: Assembly) -> tuple[np.ndarray, float, float]:
    """Periodic cubic-spline coefficients of every wing type's table: array (n_types, n_int, 4, n_col),
    grid start [rad] and spacing [rad]. All types must share one uniform grid; a type without a table
    (``aero`` None) gets zeros."""
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
        sp = CubicSpline(a, wt.aero.values, bc_type="periodic", axis=0)
        out.append(np.ascontiguousarray(np.transpose(sp.c, (1, 0, 2))))
    da = float(grid[1] - grid[0])
    return np.ascontiguousarray(np.stack(out)), float(grid[0]), da


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


def pack_model(asm: Assembly) -> KModel:
    """Flat float64 / int64 arrays for the kernels (see the kernel module docstrings for layouts)."""
    w = asm.wind
    wf = np.array([w.v0, w.h0, w.v1, w.exponent, w.direction_inf, w.direction_height, w.rho0,
                   0.0 if w.density_model == "barometric" else 1.0, w.scale_height, 0.0])
    ac, a0, da = spline_coefficients(asm)
    tf = np.zeros((max(1, len(asm.wing_types)), 16))
    for i, wt in enumerate(asm.wing_types):
        tf[i, :5] = (wt.mass, *wt.inertia)
        tf[i, 5:8] = (wt.area, wt.span, wt.chord)
        tf[i, 8:11] = wt.r_ref
        tf[i, 11:14] = wt.attachment
    el = asm.elements
    ef = np.ascontiguousarray(np.stack([el.l0, el.mu, el.EA, el.DA, el.diameter], axis=1).reshape(-1, 5))
    order, parent, echild = elimination_tree(asm)
    wing_dof, node_dof = (6, 3) if asm.dim == 3 else (3, 2)
    bsz = np.array([wing_dof] * asm.n_wings + [node_dof] * asm.n_nodes, dtype=np.int64)
    fixed = asm.fixed_points if asm.fixed_points.size else np.zeros((1, 3))
    return KModel(
        wf=wf, tmod=np.array([w.mod_t0, w.mod_dt]),
        ms=np.ascontiguousarray(w.mod_speed, dtype=np.float64),
        md=np.ascontiguousarray(w.mod_direction, dtype=np.float64),
        glob=np.array([asm.gravity, asm.cable_cn0, asm.cable_ct0, a0, da, 0.0, 0.0, 0.0]),
        wtype=np.ascontiguousarray(asm.wing_type_index, dtype=np.int64), tf=tf, ac=ac,
        node_mass=np.ascontiguousarray(asm.node_mass, dtype=np.float64),
        fixed=np.ascontiguousarray(fixed, dtype=np.float64),
        ek=np.ascontiguousarray(el.end_kind, dtype=np.int64).reshape(-1, 2),
        ei=np.ascontiguousarray(el.end_index, dtype=np.int64).reshape(-1, 2),
        ea=np.ascontiguousarray(el.attach, dtype=np.float64).reshape(-1, 2, 3),
        ef=ef, ekd=end_mass_shapes(asm), echild=echild, order=order, parent=parent, bsz=bsz,
    )


def make_workspace(asm: Assembly) -> KWork:
    """Every array the kernels write into, allocated once per simulator."""
    nb = max(1, asm.n_wings + asm.n_nodes)
    n = asm.state_size
    z = np.zeros
    return KWork(
        D=z((nb, 6, 6)), U=z((nb, 6, 6)), Y=z((nb, 6, 6)), piv=z((nb, 6), dtype=np.int64),
        bv=z((nb, 6)), Rw=z((max(1, asm.n_wings), 3, 3)), tension=z(max(1, asm.elements.count)),
        Tr=z((3, 6)), Ts=z((3, 6)), er=z(9), es=z(9), coef=z(len(AERO_COLUMNS)), aout=z(15),
        k1=z(n), k2=z(n), k3=z(n), k4=z(n), k5=z(n), k6=z(n), k7=z(n), xt=z(n), xp=z(n),
    )
