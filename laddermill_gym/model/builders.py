"""Build :class:`~laddermill_gym.model.params.Assembly` objects programmatically: cable specs, chains of wings
on cable pieces between ground points, bare cables. The YAML scene loader and the tests use these."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.model.params import END_FIXED, END_NODE, END_WING, Assembly, Elements, WindParams, WingType
from laddermill_gym.model.states import wing_state_3d


@dataclass(frozen=True)
class CableSpec:
    """Cable material and size.

    diameter [m], mass_per_length [kg/m], EA axial stiffness [N], DA Voigt damping coefficient [N s],
    breaking_load [N], cn0 / ct0 cross-flow and friction coefficients [-] (Meijaard eq. 24).
    """

    diameter: float
    mass_per_length: float
    EA: float
    DA: float
    breaking_load: float = float("inf")
    cn0: float = 1.1
    ct0: float = 0.02


@dataclass
class ElementList:
    kind: list = field(default_factory=list)
    index: list = field(default_factory=list)
    attach: list = field(default_factory=list)
    l0: list = field(default_factory=list)

    def add(self, end_r, end_s, l0):
        self.kind.append((end_r[0], end_s[0]))
        self.index.append((end_r[1], end_s[1]))
        self.attach.append((end_r[2], end_s[2]))
        self.l0.append(l0)

    def build(self, cable: CableSpec) -> Elements:
        n = len(self.l0)
        return Elements(
            end_kind=np.array(self.kind, dtype=np.int64).reshape(n, 2),
            end_index=np.array(self.index, dtype=np.int64).reshape(n, 2),
            attach=np.array(self.attach, dtype=np.float64).reshape(n, 2, 3),
            l0=np.array(self.l0, dtype=np.float64),
            mu=np.full(n, cable.mass_per_length), EA=np.full(n, cable.EA), DA=np.full(n, cable.DA),
            diameter=np.full(n, cable.diameter), breaking_load=np.full(n, float(cable.breaking_load)),
        )


@dataclass(frozen=True)
class ChainLayout:
    """How a chain assembly maps onto its pieces: for piece i, the free-node indices along it
    (``piece_nodes[i]``), and which element indices it holds (``piece_elements[i]``)."""

    piece_nodes: tuple[tuple[int, ...], ...]
    piece_elements: tuple[tuple[int, ...], ...]


def build_chain(wing_types: tuple[WingType, ...], wing_type_index, piece_lengths, elements_per_piece: int,
                cable: CableSpec, fixed_points, start: int, end: int | None, wind: WindParams,
                dim: int = 3, sag: bool = True, cable_aero: bool = True, gravity: float = 9.80665,
                ) -> tuple[Assembly, ChainLayout]:
    """Wings in series on cable pieces: fixed point ``start`` - piece 0 - wing 0 - piece 1 - ... - wing n-1
    [- piece n - fixed point ``end``]. Each piece of unstretched length ``piece_lengths[i]`` [m] is split
    into ``elements_per_piece`` equal elements with point-mass nodes between them. All pieces of a wing
    attach at its wing type's attachment point."""
    wti = np.asarray(wing_type_index, dtype=np.int64)
    nw = wti.size
    n_pieces = nw + (1 if end is not None else 0)
    piece_lengths = np.broadcast_to(np.asarray(piece_lengths, dtype=float), (n_pieces,))
    m = int(elements_per_piece)
    if m < 1:
        raise ValueError(f"elements_per_piece must be >= 1, got {elements_per_piece}")
    els = ElementList()
    zero = (0.0, 0.0, 0.0)
    n_nodes = 0
    piece_nodes, piece_elements = [], []

    def wing_end(k):
        return (END_WING, k, tuple(wing_types[wti[k]].attachment))

    for i in range(n_pieces):
        a = (END_FIXED, start, zero) if i == 0 else wing_end(i - 1)
        b = wing_end(i) if i < nw else (END_FIXED, end, zero)
        ends = [a] + [(END_NODE, n_nodes + j, zero) for j in range(m - 1)] + [b]
        piece_nodes.append(tuple(range(n_nodes, n_nodes + m - 1)))
        n_nodes += m - 1
        first = len(els.l0)
        for j in range(m):
            els.add(ends[j], ends[j + 1], piece_lengths[i] / m)
        piece_elements.append(tuple(range(first, first + m)))
    elements = els.build(cable)
    node_mass = np.zeros(n_nodes)
    asm = Assembly(dim=dim, gravity=gravity, wind=wind, wing_types=tuple(wing_types), wing_type_index=wti,
                   node_mass=node_mass, fixed_points=np.asarray(fixed_points, dtype=float).reshape(-1, 3),
                   elements=elements, sag=sag, cable_aero=cable_aero, cable_cn0=cable.cn0, cable_ct0=cable.ct0)
    return asm, ChainLayout(tuple(piece_nodes), tuple(piece_elements))


def build_cable(point_a, point_b, length: float, n_elements: int, cable: CableSpec, wind: WindParams | None = None,
                sag: bool = False, cable_aero: bool = False, gravity: float = 9.80665, dim: int = 3,
                node_mass: float = 0.0) -> Assembly:
    """A bare cable of ``n_elements`` equal elements between two fixed points (no wings)."""
    asm, _ = build_chain((), np.zeros(0, dtype=np.int64), [length], n_elements, cable,
                         np.array([point_a, point_b], dtype=float), 0, 1,
                         wind or WindParams(rho0=0.0), dim=dim, sag=sag, cable_aero=cable_aero, gravity=gravity)
    if node_mass:
        import dataclasses

        asm = dataclasses.replace(asm, node_mass=np.full(asm.n_nodes, float(node_mass)))
    return asm


def chain_state(asm: Assembly, layout: ChainLayout, wing_positions, wing_euler, start_point, end_point=None,
                wing_velocities=None, wing_rates=None) -> np.ndarray:
    """A 3D state for a chain: wings at the given CG positions [m] and Euler angles [rad], body
    velocities [m/s] and rates [rad/s] (default zero); each piece's free nodes evenly spaced on the straight
    line between the attachment points."""
    from laddermill_gym.model.states import rotation_from_euler

    nw = asm.n_wings
    wp = np.asarray(wing_positions, dtype=float).reshape(nw, 3)
    we = np.asarray(wing_euler, dtype=float).reshape(nw, 3)
    wv = np.zeros((nw, 3)) if wing_velocities is None else np.asarray(wing_velocities, float).reshape(nw, 3)
    wr = np.zeros((nw, 3)) if wing_rates is None else np.asarray(wing_rates, float).reshape(nw, 3)
    att = [wp[k] + rotation_from_euler(*we[k]) @ asm.wing(k).attachment for k in range(nw)]
    parts = [wing_state_3d(wp[k], we[k], wv[k], wr[k]) for k in range(nw)]
    nodes = np.zeros((asm.n_nodes, 6))
    for i, idx in enumerate(layout.piece_nodes):
        a = np.asarray(start_point, float) if i == 0 else att[i - 1]
        b = att[i] if i < nw else np.asarray(end_point, float)
        for j, n in enumerate(idx):
            f = (j + 1) / (len(idx) + 1)
            nodes[n, :3] = a + f * (b - a)
    return np.concatenate(parts + [nodes.reshape(-1)])
