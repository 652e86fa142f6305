"""``kernels/integrate.rhs_entry``, the right-hand side Python calls (``Simulator.rhs``: the static equilibria and
trims): the rigid kinds reach rhs3d / rhs2d through their compiled addresses (``kernels/far_call.py``) so the entry
links neither, and the derivative is bit for bit the one of ``integrate.rhs``, which links them (the oracle: the
same kernels compiled into their caller, the path every step kernel takes); a kind without an address entry (the
winch) is linked as before."""

import dataclasses

import numpy as np
import pytest
from numba import njit

from laddermill_gym import load_scene
from laddermill_gym.kernels.integrate import rhs, rhs_entry
from laddermill_gym.kernels.rigid.rhs2d import rhs2d
from laddermill_gym.kernels.rigid.rhs3d import rhs3d
from laddermill_gym.sim.simulator import Simulator


def _simulator(dim: int) -> Simulator:
    """The tethered wing scene's simulator at its start, in 3D or in the plane (the trim's model)."""
    sc = load_scene("tethered_wing")
    sim = sc.simulator()
    if dim == 3:
        return sim
    a = dataclasses.replace(sc.assembly, dim=2)
    from laddermill_gym.model.states import planar_from_3d

    x2 = planar_from_3d(sim.state, a.n_wings, a.n_nodes)
    return Simulator(a, x2, sc.settings, sim.controls)


def _states(sim: Simulator, n: int = 12) -> list[np.ndarray]:
    """The start and ``n - 1`` states around it: every entry moved by a seeded relative 1e-3 (quaternions, where
    there are any, are renormalised by the kernels' callers only, so small moves keep them near unit length)."""
    rng = np.random.default_rng(5)
    x0 = np.asarray(sim.state, dtype=np.float64)
    return [x0] + [x0 * (1.0 + 1e-3 * rng.standard_normal(x0.size)) for _ in range(n - 1)]


@pytest.mark.parametrize("dim", [3, 2])
def test_entry_derivative_equals_the_linked_one(dim):
    sim = _simulator(dim)
    u = np.asarray(sim.controls, dtype=np.float64)
    for i, x in enumerate(_states(sim)):
        d_entry, d_linked = np.zeros_like(x), np.zeros_like(x)
        s_entry = rhs_entry(0.1 * i, x, u, d_entry, sim.model, sim.work)
        t_entry = sim.work.tension.copy()
        s_linked = rhs(0.1 * i, x, u, d_linked, sim.model, sim.work)
        assert s_entry == s_linked == 0
        assert d_entry.tobytes() == d_linked.tobytes(), (dim, i, np.max(np.abs(d_entry - d_linked)))
        assert t_entry.tobytes() == sim.work.tension.tobytes()  # what an observation reads, too


@pytest.mark.parametrize("dim", [3, 2])
def test_entry_does_not_link_the_right_hand_side(dim):
    # fresh, uncached compiles of the two entries (a library loaded from numba's cache lists no linked libraries)
    flags = {"error_model": "numpy", "fastmath": {"contract", "nsz", "arcp"}, "_nrt": False}
    entry, linked = njit(**flags)(rhs_entry.py_func), njit(**flags)(rhs.py_func)
    sim = _simulator(dim)
    x, u = np.asarray(sim.state, dtype=np.float64), np.asarray(sim.controls, dtype=np.float64)
    entry(0.0, x, u, np.zeros_like(x), sim.model, sim.work)
    linked(0.0, x, u, np.zeros_like(x), sim.model, sim.work)
    callee = {id(c.library) for c in (rhs3d if dim == 3 else rhs2d).overloads.values()}
    assert callee, "the entry's call resolved the callee: it is compiled or loaded in this process"

    def links(disp):
        return any({id(lib) for lib in c.library._linking_libraries} & callee for c in disp.overloads.values())

    assert links(linked)  # the control: a plain call links the kind's right-hand side
    assert not links(entry)


def test_a_kind_without_an_address_entry_is_linked():
    # the pumping kite's winch kind registers no far right-hand side: the entry links the kind's own, and
    # Simulator.rhs (the entry) equals integrate.rhs there too
    from laddermill_gym.envs.pumping.winch_scene import load_pumping

    scene = load_pumping()
    sim = scene.simulator(*scene.initial_state())
    assert type(sim.model.kind).__name__ == "Winch3D"
    x = np.asarray(sim.state, dtype=np.float64)
    u = np.asarray(sim.controls, dtype=np.float64)
    d_linked = np.zeros_like(x)
    assert rhs(0.0, x, u, d_linked, sim.model, sim.work) == 0
    assert sim.rhs(0.0, x, u).tobytes() == d_linked.tobytes()
