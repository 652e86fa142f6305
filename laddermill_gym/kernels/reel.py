"""The reeling multi-element tether of a pumping kite's winch as a model kind: elements are paid out into the air
from the drum and taken back onto it as the tether reels (issue 29 point 2; docs/reeling_tether.md).

``ReelWinch3D`` is the 3D winch (``kernels/winch.py``: the station's parameters ``station``, slots ``SP_*``, state
block ``SX_*``) on a chain of n free nodes with a fixed maximum count and a count in the air (the reel's slots
``RL_*`` of ``kernels/contract.py`` in ``reel``, packed by ``model/reel.py``). Element e joins node e - 1 (the ground
point for e = 0) to node e; the last element joins node n - 1 to the wing. With a nodes in the air, nodes
0 .. k - 1 (k = n - a) lie on the drum: held at the ground point at rest (their blocks of the mass matrix are the
identity, their forces and couplings zero), their elements slack and massless to the rest. Element k, from the
drum to node k, is the **drum element**: its rest length is l_d = l_p + s - m l_n with l_p its length at t = 0
(``SP_PIECE``), s the tether paid out (``SX_MOVED``, ds/dt = V) and m the nodes paid out since t = 0
(``SX_TRANSFERS``); the elements above it keep their nominal length l_n. Its mass follows (mu l_d) and its damping
acts on the material strain rate, l0 d(eps)/dt = dl/dt - (l / l0) V, as the single winch element's. The drum feels
the drum element's tension (the tension of element slot 0 is reported as it, so that read-outs of the tension at
the drum need no index).

After every step (:func:`reel3d_check`), at most one relabelling, the moving cable's rule applied to one end
(``kernels/moving_cable.py``):

* **split** when l_d >= ``RL_SPLIT`` l_n and a node is left on the drum: node k - 1 leaves the drum onto the drum
  element's chord at the unstretched distance l_d - l_n from the ground point (fraction f = (l_d - l_n) / l_d of
  the way to node k) with velocity f v_k (the element's linear velocity field, the ground end at rest). Both
  pieces keep the element's strain; the tether's mass (mu times the rest lengths) and the momentum of the
  consistent mass (mu l (v_r + v_s) / 2 per element) are unchanged.
* **merge** when l_d < ``RL_MERGE`` l_n and at least two nodes are in the air: node k goes onto the drum (to the
  ground point, at rest) and node k + 1 takes the velocity that keeps the momentum of the consistent mass,
  v' = ((l_d + l_a) v_k + (l_a + l_b) v_{k+1}) / (l_d + l_a + l_b), l_a and l_b the rest lengths of the elements
  below and above node k + 1. Mass is unchanged (the merged element's rest length is l_d + l_a); kinetic energy is
  not (a merge is inelastic).

**Ground contact of a tether node** is a contact force, not a stop: a node in the air below the ground height h_g
(``RL_GROUND``) feels a penalty spring-damper normal force F_n = max(0, m_j (omega^2 d + 2 zeta omega d'))
(d the depth below the ground, m_j = mu (l_below + l_above) / 2 the node's lumped mass, so that a node resting
under its own weight sinks g / omega^2) and a friction force mu_f F_n against its sliding velocity, viscous below
``RL_VSLIP``. The wing's CG on the ground still stops the run (GROUND), as on every kind.

The post-step check returns LIMIT when the drum element is shorter than ``MIN_FRACTION`` l_n with no node left in
the air to merge (the drum would swallow the wing's element).
"""

import math
from collections import namedtuple

from numba import njit

from laddermill_gym.kernels import contract as C
from laddermill_gym.kernels.dispatch import register_kind, register_moving_ends
from laddermill_gym.kernels.rigid.blocks import tree_solve
from laddermill_gym.kernels.rigid.kinds import check_wings3d
from laddermill_gym.kernels.rigid.rhs3d import assemble3d
from laddermill_gym.kernels.station import cable_speed, station_rates

_FM = {"contract", "nsz", "arcp"}

#: Kind marker: ``station`` the packed winch (``SP_*``), ``reel`` the packed reel (``RL_*``).
ReelWinch3D = namedtuple("ReelWinch3D", ["station", "reel"])

#: Shortest drum element with no node left to merge, as a fraction of l_n [-]: below it the step returns LIMIT.
MIN_FRACTION = 0.05


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def nodes_in_air(kind, x, M):
    """Free nodes in the air [-]: those at t = 0 plus those paid out since (``SX_TRANSFERS``)."""
    m = x[int(kind.station[C.SP_XOFF]) + C.SX_TRANSFERS]
    return int(kind.reel[C.RL_ACTIVE0] + math.floor(m + 0.5))


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def drum_element(kind, x, M):
    """Index k of the drum element (the nodes 0 .. k - 1 lie on the drum)."""
    return M.node_mass.size - nodes_in_air(kind, x, M)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def drum_rest_length(kind, x):
    """Rest length l_d [m] of the drum element: l_p + s - m l_n."""
    sp, o = kind.station, int(kind.station[C.SP_XOFF])
    return sp[C.SP_PIECE] + x[o + C.SX_MOVED] - x[o + C.SX_TRANSFERS] * kind.reel[C.RL_LNOM]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def reel_rest_length(kind, e, t, x, M):
    """Unstretched length [m] of element e: l_n on the drum (any positive value: the element is slack and
    massless to the nodes in the air), l_d for the drum element, the packed length above it."""
    k = drum_element(kind, x, M)
    if e < k:
        return kind.reel[C.RL_LNOM]
    if e == k:
        return drum_rest_length(kind, x)
    return M.ef[e, C.EF_L0]


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def reel_elongation_rate(kind, e, t, x, M, ln, l0, ld):
    """Material elongation rate [m/s]: dl/dt - (l / l0) V for the drum element, dl/dt for the others."""
    if e != drum_element(kind, x, M):
        return ld
    return ld - ln / l0 * cable_speed(kind.station, t, x)


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def hold_drum_nodes(W, nw, k):
    """Blocks of the nodes on the drum (0 .. k - 1): identity mass, no force, no coupling: zero acceleration."""
    for j in range(k):
        b = nw + j
        for i in range(3):
            W.bv[b, i] = 0.0
            for c in range(6):
                W.U[b, i, c] = 0.0
            for c in range(3):
                W.D[b, i, c] = 1.0 if i == c else 0.0


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def contact_force(rl, mass, depth, depth_rate, vx, vy):
    """Ground reaction (fx, fy, fz) [N] (global, z down) on a node of lumped mass [kg] at ``depth`` [m] below the
    ground sinking at ``depth_rate`` [m/s], sliding at (vx, vy) [m/s]: zero above the ground."""
    if not depth > 0.0:
        return 0.0, 0.0, 0.0
    w = rl[C.RL_OMEGA]
    fn = mass * (w * w * depth + 2.0 * rl[C.RL_ZETA] * w * depth_rate)
    if not fn > 0.0:
        return 0.0, 0.0, 0.0
    vt = math.sqrt(vx * vx + vy * vy)
    c = rl[C.RL_MU] * fn / max(vt, rl[C.RL_VSLIP])
    return -c * vx, -c * vy, -fn


@njit(cache=True, error_model="numpy", fastmath=_FM, inline="always")
def add_ground_contact(kind, t, x, M, W, nw, k):
    """Add the ground's reaction on every node in the air to its generalised force."""
    rl = kind.reel
    nn = M.node_mass.size
    for j in range(k, nn):
        o = C.B3_SIZE * nw + C.N3_SIZE * j
        depth = x[o + C.N3_POS + 2] + rl[C.RL_GROUND]  # z + h_g: below the ground when > 0 (z down)
        if depth > 0.0:
            mass = 0.5 * M.ef[j, C.EF_MU] * (reel_rest_length(kind, j, t, x, M) + M.ef[j + 1, C.EF_L0])
            fx, fy, fz = contact_force(rl, mass, depth, x[o + C.N3_VEL + 2], x[o + C.N3_VEL], x[o + C.N3_VEL + 1])
            W.bv[nw + j, 0] += fx
            W.bv[nw + j, 1] += fy
            W.bv[nw + j, 2] += fz


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def reel3d_rhs(kind, t, x, u, dx, M, W):
    """State derivative: the rigid 3D assembly (with this kind's rest lengths), the drum's nodes held, the
    ground's reaction on the nodes in the air, the block solve, and the winch block driven by the drum element's
    tension. Returns 0, or 1 if the mass matrix is singular."""
    assemble3d(t, x, u, dx, M, W, M.sag, M.caero, M.vehicle)
    nw = M.wtype.size
    nn = M.node_mass.size
    k = drum_element(kind, x, M)
    hold_drum_nodes(W, nw, k)
    add_ground_contact(kind, t, x, M, W, nw, k)
    W.tension[0] = W.tension[k]  # slot 0 reports the tension at the drum (the drum element's)
    station_rates(kind.station, t, x, u, dx, W.tension[k])
    if not tree_solve(W.D, W.U, W.Y, W.piv, W.bv, M.order, M.parent, M.bsz):
        return 1
    for b in range(nw):
        o = C.B3_SIZE * b + C.B3_VEL
        for i in range(6):
            dx[o + i] = W.bv[b, i]
    base = C.B3_SIZE * nw
    for j in range(nn):
        o = base + C.N3_SIZE * j + C.N3_VEL
        for i in range(3):
            dx[o + i] = W.bv[nw + j, i]
    return 0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def split_node(kind, x, M):
    """Pay node k - 1 out of the drum onto the drum element (module docstring, "split")."""
    nw = M.wtype.size
    k = drum_element(kind, x, M)
    ld = drum_rest_length(kind, x)
    f = (ld - kind.reel[C.RL_LNOM]) / ld
    g = M.ei[0, 0]
    up = C.B3_SIZE * nw + C.N3_SIZE * k
    new = up - C.N3_SIZE
    for i in range(3):
        p0 = M.fixed[g, i]
        x[new + C.N3_POS + i] = p0 + f * (x[up + C.N3_POS + i] - p0)
        x[new + C.N3_VEL + i] = f * x[up + C.N3_VEL + i]
    x[int(kind.station[C.SP_XOFF]) + C.SX_TRANSFERS] += 1.0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def merge_node(kind, x, M):
    """Take node k onto the drum, node k + 1 keeping the momentum (module docstring, "merge")."""
    nw = M.wtype.size
    k = drum_element(kind, x, M)
    ld = drum_rest_length(kind, x)
    la, lb = M.ef[k + 1, C.EF_L0], M.ef[k + 2, C.EF_L0]
    g = M.ei[0, 0]
    gone = C.B3_SIZE * nw + C.N3_SIZE * k
    up = gone + C.N3_SIZE
    wa, wb = (ld + la) / (ld + la + lb), (la + lb) / (ld + la + lb)
    for i in range(3):
        x[up + C.N3_VEL + i] = wa * x[gone + C.N3_VEL + i] + wb * x[up + C.N3_VEL + i]
        x[gone + C.N3_POS + i] = M.fixed[g, i]
        x[gone + C.N3_VEL + i] = 0.0
    x[int(kind.station[C.SP_XOFF]) + C.SX_TRANSFERS] -= 1.0


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def relabel(kind, x, M):
    """At most one split or merge after a step; LIMIT when the drum element is shorter than MIN_FRACTION l_n and
    no node can be merged, else OK."""
    ln = kind.reel[C.RL_LNOM]
    ld = drum_rest_length(kind, x)
    air = nodes_in_air(kind, x, M)
    if ld >= kind.reel[C.RL_SPLIT] * ln and air < M.node_mass.size:
        split_node(kind, x, M)
    elif ld < kind.reel[C.RL_MERGE] * ln and air >= 2:
        merge_node(kind, x, M)
    elif ld < MIN_FRACTION * ln:
        return C.LIMIT
    return C.OK


@njit(cache=True, error_model="numpy", fastmath=_FM, _nrt=False)
def reel3d_check(kind, x, M, limits):
    """Renormalise the wings' quaternions; LIMIT beyond the speed and rate limits, GROUND for a wing CG at or below
    ``limits[LIM_GROUND]`` (a tether node there is a contact, not a stop), NONFINITE; then :func:`relabel`."""
    nw, nn = M.wtype.size, M.node_mass.size
    vmax2, wmax2 = limits[C.LIM_SPEED] ** 2, limits[C.LIM_RATE] ** 2
    for i in range(x.size):
        if not math.isfinite(x[i]):
            return C.NONFINITE
    st = check_wings3d(x, nw, vmax2, wmax2, limits[C.LIM_GROUND])
    if st != C.OK:
        return st
    for j in range(nn):
        o = C.B3_SIZE * nw + C.N3_SIZE * j + C.N3_VEL
        if x[o] ** 2 + x[o + 1] ** 2 + x[o + 2] ** 2 > vmax2:
            return C.LIMIT
    return relabel(kind, x, M)


register_kind(ReelWinch3D, reel3d_rhs, reel3d_check)
register_moving_ends(ReelWinch3D, reel_rest_length, reel_elongation_rate)
